//! The control panel driven the way a user drives it, without a window: egui runs headless over
//! a real App (the settings, the Close2GL pipeline, the panel and the camera plugin's edit step; a
//! triangle and a camera), widgets
//! are found by their accessibility labels and clicked or set through AccessKit action requests.

use close2gl_core::bevy_ecs::prelude::*;
use close2gl_core::glam::Vec3;
use close2gl_core::{
    App, Camera, CameraActions, CameraRequest, CameraSpeeds, FrameSet, Mesh, ModelRequest,
    ModelSource, ModelStatus, SettingsPlugin, TextureRequest, ToolRequests, Update, Viewport,
};
use close2gl_ui::{PanelInput, PanelOutput};
use egui::accesskit::{Action, ActionData, ActionRequest, Node, NodeId, Role, TreeId};

/// Re-exported for the tests that name widgets' roles and send events.
pub use egui;

pub struct Harness {
    pub ctx: egui::Context,
    pub app: App,
    nodes: Vec<(NodeId, Node)>,
}

impl Harness {
    /// The window the panel is shown in, in points.
    pub const SCREEN: egui::Rect =
        egui::Rect::from_min_max(egui::Pos2::ZERO, egui::pos2(1280.0, 2400.0));

    /// One triangle 5 units in front of the default camera, wound clockwise as seen from it: a
    /// back face, culled while backface culling is on.
    pub fn new() -> Self {
        let mut app = App::new();
        app.add_plugins(SettingsPlugin)
            .add_plugins(close2gl_pipeline::Close2glPlugin)
            .add_plugins(close2gl_raster::RasterPlugin)
            .add_plugins(close2gl_ui::UiPlugin)
            // The camera plugin's edit step alone: the panel's camera edits land in the frame,
            // and the actions it asks for stay in `CameraActions` for a test to read.
            .init_resource::<CameraActions>()
            .init_resource::<CameraRequest>()
            .add_systems(
                Update,
                close2gl_camera::apply_camera_edit.in_set(FrameSet::Camera),
            )
            .init_resource::<CameraSpeeds>()
            .init_resource::<ModelRequest>()
            .init_resource::<TextureRequest>()
            .init_resource::<ToolRequests>()
            .insert_resource(ModelStatus {
                source: Some(ModelSource::File("models/tri.in".into())),
                generation: 1,
                ..ModelStatus::default()
            })
            .insert_resource(Viewport {
                width: 200,
                height: 100,
            });
        app.world_mut().spawn(Camera::default());
        app.world_mut().spawn(Mesh {
            face_normals: Vec::new(),
            name: "tri".into(),
            positions: vec![
                Vec3::new(-1.0, -1.0, -5.0),
                Vec3::new(0.0, 1.0, -5.0),
                Vec3::new(1.0, -1.0, -5.0),
            ],
            normals: vec![Vec3::Z; 3],
            uvs: Vec::new(),
            triangles: vec![[0, 1, 2]],
        });
        app.update();
        let ctx = egui::Context::default();
        ctx.enable_accesskit();
        let mut harness = Self {
            ctx,
            app,
            nodes: Vec::new(),
        };
        harness.frame(Vec::new());
        harness
    }

    /// One app frame with `events` for the panel, which runs in it as in the viewer's (the split
    /// layout's, both views beside the panel).
    pub fn frame(&mut self, events: Vec<egui::Event>) {
        let input = egui::RawInput {
            screen_rect: Some(Self::SCREEN),
            events,
            ..Default::default()
        };
        self.app.insert_resource(PanelInput {
            ctx: self.ctx.clone(),
            raw: Some(input),
            both_views: true,
        });
        self.app.update();
        let Some(PanelOutput(mut output)) = self.app.world_mut().remove_resource::<PanelOutput>()
        else {
            panic!("the panel did not run in the app's frame");
        };
        // No renderer here to upload the font atlas to.
        output.textures_delta.clear();
        self.nodes = output
            .platform_output
            .accesskit_update
            .map(|update| update.nodes)
            .unwrap_or_default();
    }

    /// A node's own label, or else the text of the label beside it (`labelled_by`, as sliders).
    fn name(&self, node: &Node) -> Option<String> {
        node.label().map(str::to_string).or_else(|| {
            let by = node.labelled_by().first()?;
            let (_, label) = self.nodes.iter().find(|(id, _)| id == by)?;
            label.label().or(label.value()).map(str::to_string)
        })
    }

    pub fn node(&self, role: Role, label: &str) -> NodeId {
        self.nodes
            .iter()
            .find(|(_, node)| node.role() == role && self.name(node).as_deref() == Some(label))
            .map(|(id, _)| *id)
            .unwrap_or_else(|| {
                let known: Vec<_> = self
                    .nodes
                    .iter()
                    .filter_map(|(_, n)| self.name(n).map(|l| format!("{:?} {l:?}", n.role())))
                    .collect();
                panic!("no {role:?} labelled {label:?}; the panel has {known:?}")
            })
    }

    /// Whether any widget of the panel is labelled `text` (a node's own label or value).
    pub fn shows(&self, text: &str) -> bool {
        self.nodes
            .iter()
            .any(|(_, node)| node.label() == Some(text) || node.value() == Some(text))
    }

    /// Every text shown (a node's label or value, its padding trimmed) with its rectangle, in
    /// points: where a test reads whether something fits.
    pub fn texts(&self) -> Vec<(String, egui::Rect)> {
        let mut texts: Vec<(String, egui::Rect)> = Vec::new();
        let all = self.nodes.iter().filter_map(|(_, node)| {
            let text = node.label().or(node.value())?.trim().to_string();
            let b = node.bounds()?;
            let rect = egui::Rect::from_min_max(
                egui::pos2(b.x0 as f32, b.y0 as f32),
                egui::pos2(b.x1 as f32, b.y1 as f32),
            );
            Some((text, rect))
        });
        // A label and the run of text in it are two nodes with the same text and place.
        for text in all {
            if !texts.contains(&text) {
                texts.push(text);
            }
        }
        texts
    }

    pub fn act(&mut self, role: Role, label: &str, action: Action, data: Option<ActionData>) {
        let target_node = self.node(role, label);
        self.frame(vec![egui::Event::AccessKitActionRequest(ActionRequest {
            action,
            target_tree: TreeId::ROOT,
            target_node,
            data,
        })]);
    }

    pub fn click(&mut self, role: Role, label: &str) {
        self.act(role, label, Action::Click, None);
    }

    pub fn set_value(&mut self, role: Role, label: &str, value: f64) {
        self.act(
            role,
            label,
            Action::SetValue,
            Some(ActionData::NumericValue(value)),
        );
    }

    pub fn world(&mut self) -> &mut World {
        self.app.world_mut()
    }

    pub fn camera(&mut self) -> Camera {
        *self
            .world()
            .query::<&Camera>()
            .single(self.app.world())
            .expect("the harness has one camera")
    }
}

impl Default for Harness {
    fn default() -> Self {
        Self::new()
    }
}
