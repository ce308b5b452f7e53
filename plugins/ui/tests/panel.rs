//! The panel driven the way a user drives it, without a window: egui runs headless over a real
//! App, widgets are found by their accessibility labels and clicked or set through AccessKit
//! action requests, and the tests check the change lands in the resources the render systems
//! read: through the real Close2GL system into the 2D frame, and through the real GPU views
//! (offscreen, on whatever adapter wgpu finds: Mesa's lavapipe without a GPU) into both images.

use close2gl_core::bevy_ecs::prelude::*;
use close2gl_core::glam::Vec3;
use close2gl_core::{
    App, Camera, CameraAction, CameraActions, Close2glFrame, Mesh, ModelRequest, ModelSource,
    ModelStatus, PrimitiveKind, RenderMode, RenderSettings, Topology, Viewport,
};
use egui::accesskit::{Action, ActionData, ActionRequest, Node, NodeId, Role, TreeId};

struct Harness {
    ctx: egui::Context,
    app: App,
    nodes: Vec<(NodeId, Node)>,
    views: egui::Rect,
}

impl Harness {
    /// One triangle 5 units in front of the default camera, wound clockwise as seen from it: a
    /// back face, culled while backface culling is on.
    fn new() -> Self {
        let mut app = App::new();
        app.add_plugins(close2gl_pipeline::Close2glPlugin)
            .add_plugins(close2gl_ui::UiPlugin)
            .init_resource::<CameraActions>()
            .init_resource::<ModelRequest>()
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
            name: "tri".into(),
            positions: vec![
                Vec3::new(-1.0, -1.0, -5.0),
                Vec3::new(0.0, 1.0, -5.0),
                Vec3::new(1.0, -1.0, -5.0),
            ],
            normals: vec![Vec3::Z; 3],
            triangles: vec![[0, 1, 2]],
        });
        app.update();
        let ctx = egui::Context::default();
        ctx.enable_accesskit();
        let mut harness = Self {
            ctx,
            app,
            nodes: Vec::new(),
            views: egui::Rect::NOTHING,
        };
        harness.frame(Vec::new());
        harness
    }

    /// One panel frame with `events`, then one app frame, as the viewer does.
    fn frame(&mut self, events: Vec<egui::Event>) {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 2400.0),
            )),
            events,
            ..Default::default()
        };
        let world = self.app.world_mut();
        let mut views = egui::Rect::NOTHING;
        let mut output = self
            .ctx
            .run_ui(input, |ui| views = close2gl_ui::show(ui, world));
        // No renderer here to upload the font atlas to.
        output.textures_delta.clear();
        self.views = views;
        self.nodes = output
            .platform_output
            .accesskit_update
            .map(|update| update.nodes)
            .unwrap_or_default();
        self.app.update();
    }

    /// A node's own label, or else the text of the label beside it (`labelled_by`, as sliders).
    fn name(&self, node: &Node) -> Option<String> {
        node.label().map(str::to_string).or_else(|| {
            let by = node.labelled_by().first()?;
            let (_, label) = self.nodes.iter().find(|(id, _)| id == by)?;
            label.label().or(label.value()).map(str::to_string)
        })
    }

    fn node(&self, role: Role, label: &str) -> NodeId {
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

    fn act(&mut self, role: Role, label: &str, action: Action, data: Option<ActionData>) {
        let target_node = self.node(role, label);
        self.frame(vec![egui::Event::AccessKitActionRequest(ActionRequest {
            action,
            target_tree: TreeId::ROOT,
            target_node,
            data,
        })]);
    }

    fn click(&mut self, role: Role, label: &str) {
        self.act(role, label, Action::Click, None);
    }

    fn set_value(&mut self, role: Role, label: &str, value: f64) {
        self.act(
            role,
            label,
            Action::SetValue,
            Some(ActionData::NumericValue(value)),
        );
    }

    fn world(&mut self) -> &mut World {
        self.app.world_mut()
    }

    fn camera(&mut self) -> Camera {
        *self
            .world()
            .query::<&Camera>()
            .single(self.app.world())
            .unwrap()
    }
}

#[test]
fn unticking_backface_culling_reaches_the_settings_and_the_close2gl_frame() {
    let mut h = Harness::new();
    let before = h.world().resource::<Close2glFrame>().counts;
    assert_eq!(
        (before.culled, before.drawn),
        (1, 0),
        "the back face starts culled"
    );

    h.click(Role::CheckBox, "Backface culling");

    assert!(!h.world().resource::<RenderSettings>().backface_culling);
    let after = h.world().resource::<Close2glFrame>().counts;
    assert_eq!(
        (after.culled, after.drawn),
        (0, 1),
        "the back face is drawn now"
    );
}

#[test]
fn choosing_wireframe_changes_the_mode_and_the_topology() {
    let mut h = Harness::new();
    h.click(Role::CheckBox, "Backface culling");
    h.click(Role::Button, "wireframe");
    assert_eq!(
        h.world().resource::<RenderSettings>().mode,
        RenderMode::Wireframe
    );
    let frame = h.world().resource::<Close2glFrame>();
    assert_eq!(frame.topology, Topology::Lines);
    assert_eq!(frame.vertices.len(), 6, "three edges of the one triangle");
}

#[test]
fn a_primitive_button_requests_that_primitive() {
    let mut h = Harness::new();
    h.click(Role::Button, "torus");
    // Nothing here takes the request (no model plugin), so it is still waiting.
    assert_eq!(
        h.world().resource::<ModelRequest>().0,
        Some(ModelSource::Primitive(PrimitiveKind::Torus))
    );
}

#[test]
fn reload_requests_the_current_model_again() {
    let mut h = Harness::new();
    h.click(Role::Button, "Reload");
    assert_eq!(
        h.world().resource::<ModelRequest>().0,
        Some(ModelSource::File("models/tri.in".into()))
    );
}

#[test]
fn reset_pushes_a_reset_action() {
    let mut h = Harness::new();
    h.world().resource_mut::<CameraActions>().0.clear();
    h.click(Role::Button, "Reset");
    // No camera plugin drains the actions here, so the reset is still queued.
    assert_eq!(
        h.world().resource::<CameraActions>().0,
        vec![CameraAction::Reset]
    );
}

#[test]
fn fields_of_view_change_alone_or_together() {
    let mut h = Harness::new();
    h.set_value(Role::Slider, "hfov", 90.0);
    let camera = h.camera();
    assert_eq!(
        (camera.hfov, camera.vfov),
        (90.0, 60.0),
        "unlocked: vfov stays"
    );
    let frame = h.world().resource::<Close2glFrame>().clone();

    h.click(Role::CheckBox, "Lock hfov and vfov");
    h.set_value(Role::Slider, "vfov", 70.0);
    let camera = h.camera();
    assert_eq!(
        (camera.hfov, camera.vfov),
        (100.0, 70.0),
        "locked: both move by 10°"
    );
    h.click(Role::CheckBox, "Backface culling");
    assert_ne!(
        h.world().resource::<Close2glFrame>().vertices,
        frame.vertices,
        "the wider lens shrinks the triangle on screen"
    );
}

#[test]
fn the_views_get_the_window_beside_the_panel_whatever_it_shows() {
    let mut h = Harness::new();
    let views = h.views;
    assert_eq!(views.min, egui::Pos2::ZERO);
    assert_eq!(views.height(), 2400.0);
    assert!(
        views.width() < 1280.0 - 200.0 && views.width() > 1280.0 - close2gl_ui::PANEL_WIDTH - 50.0,
        "views {views:?}"
    );
    h.world().resource_mut::<ModelStatus>().error = Some(format!(
        "models/tri.in:12: expected three vertex indices {}",
        "and then some more words ".repeat(20)
    ));
    h.frame(Vec::new());
    h.frame(Vec::new());
    assert_eq!(h.views, views, "a long error wraps inside the panel");
}

#[test]
fn panel_changes_reach_both_gpu_views() {
    let gpu = close2gl_gpu::Gpu::headless(wgpu::Backends::all()).unwrap_or_else(|e| panic!("{e}"));
    let mut h = Harness::new();
    h.app.add_plugins(close2gl_gpu::OffscreenPlugin(gpu));
    let covered = |h: &mut Harness| {
        let shot = close2gl_gpu::render_offscreen(&mut h.app).unwrap_or_else(|e| panic!("{e}"));
        let count = |image| {
            close2gl_gpu::parity::coverage(image, shot.background)
                .into_iter()
                .filter(|&c| c)
                .count()
        };
        (count(&shot.reference), count(&shot.close2gl))
    };
    assert_eq!(
        covered(&mut h),
        (0, 0),
        "the back face is culled in both views"
    );

    h.click(Role::CheckBox, "Backface culling");
    let solid = covered(&mut h);
    assert!(solid.0 > 1000 && solid.1 > 1000, "solid: {solid:?} pixels");

    h.click(Role::Button, "wireframe");
    let wire = covered(&mut h);
    assert!(
        wire.0 > 0 && wire.1 > 0 && wire.0 * 4 < solid.0 && wire.1 * 4 < solid.1,
        "wireframe {wire:?} against solid {solid:?} pixels"
    );
}
