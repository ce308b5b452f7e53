//! The pipeline seen from outside: a third view, drawn by wgpu, with its own orbit camera, of
//! the model, the Close2GL camera's view volume (from the real matrices) and the camera as a
//! gizmo, at a stage between world, eye and normalised device coordinates. It is an
//! illustration, not one of the two pipelines compared.

mod outside_camera;
mod outside_scene;
mod render_outside;
mod renderer;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Appearance, Camera, Fates, FrameSet, Mesh, OutsideOrbit, OutsideView, Overlay, Owner,
    Plugin, Update, Viewport,
};
use close2gl_pipeline::morph::{OutsideFraming, StageMorph};

pub use outside_camera::OutsideCamera;
use outside_scene::SceneInput;
pub use render_outside::render_outside;
pub use renderer::OutsideRenderer;

use crate::gpu::Gpu;

/// Adds the outside view's system: in `FrameSet::Output`, placing the scene at the stage (in the fate
/// colours while the fate view, which has the pipeline record them, is on) and uploading it
/// into [`OutsideRenderer`] (inserted by whoever owns the target). Nothing runs while
/// `OutsideView::show` is off (or missing: it and `OutsideOrbit` are the settings plugin's, and
/// an app without them, a test of the two compared views, say, never shows this one). It reads
/// `Fates` (the pipeline's), `Camera`, `Mesh`, `Appearance`, `Overlay` and `Viewport` too.
pub struct OutsidePlugin;

impl Plugin for OutsidePlugin {
    fn build(&self, app: &mut App) {
        app.requires::<Fates>(Owner::Close2gl).add_systems(
            Update,
            upload_outside.in_set(FrameSet::Output).run_if(
                outside_shown
                    .and_then(resource_exists::<OutsideOrbit>)
                    .and_then(resource_exists::<Gpu>)
                    .and_then(resource_exists::<OutsideRenderer>),
            ),
        );
    }
}

/// Shown, when the settings plugin's `OutsideView` says so (an app without it never shows it).
fn outside_shown(outside: Option<Res<OutsideView>>) -> bool {
    outside.is_some_and(|o| o.show)
}

/// Places the model, the volume and the gizmo at the stage and uploads them, every frame the
/// view shows (the viewer draws only frames in which something changed).
#[allow(clippy::too_many_arguments)]
fn upload_outside(
    gpu: Res<Gpu>,
    camera: Single<&Camera>,
    mesh: Single<&Mesh>,
    (look, overlay): (Res<Appearance>, Res<Overlay>),
    viewport: Res<Viewport>,
    outside: Res<OutsideView>,
    orbit: Res<OutsideOrbit>,
    fates: Res<Fates>,
    mut renderer: ResMut<OutsideRenderer>,
) {
    if mesh.validate().is_err() {
        return;
    }
    let frame = match orbit.whole_volume {
        true => OutsideFraming::whole_volume(&camera, mesh.bounds()),
        false => OutsideFraming::new(&camera, mesh.bounds()),
    };
    let morph = StageMorph::new(&camera, &frame, outside.stage);
    let aspect = viewport.width.max(1) as f32 / viewport.height.max(1) as f32;
    let view = OutsideCamera::new(&orbit, &frame, morph.blend(frame.centres), aspect);
    renderer.scene.build(&SceneInput {
        camera: &camera,
        mesh: &mesh,
        look: &look,
        overlay: *overlay,
        fates: &fates,
        frame: &frame,
        stage: outside.stage,
        billboard: OutsideCamera::billboard(&orbit),
    });
    renderer.upload(&gpu, view);
}
