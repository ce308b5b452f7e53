//! Close2GL: the geometry half of the OpenGL pipeline, in software. This crate owns the
//! hand-written matrices (modelview M, projection P, viewport V), clipping in homogeneous space,
//! the perspective division, backface culling, and the `Close2glPlugin` whose system reads the
//! `Camera` and `Mesh` components and the `RenderSettings` and `Viewport` resources (owned by the
//! core's `SettingsPlugin`), and writes the `Close2glFrame` resource, which it owns: the 2D vertex
//! buffer in window pixels (which the GPU only draws) and the stage counts. For the outside view
//! it gives the view volume's world corners from the real matrices ([`frustum`]) and the stage
//! morph from world to eye to NDC coordinates ([`morph`]), as pure functions. It depends on no GPU,
//! window or UI crate; glam only holds the numbers.

pub mod clip;
pub mod fast;
pub mod frustum;
pub mod matrices;
pub mod morph;
pub mod stage;
pub mod textbook;

use std::time::Instant;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Camera, Close2glFrame, FrameSet, Mesh, Plugin, PostUpdate, RenderSettings, StageCounts,
    Viewport,
};

pub use fast::FastPipeline;
use stage::Fate;

/// Runs the Close2GL pipeline in `PostUpdate` (`FrameSet::Close2gl`), after the camera has moved.
/// It owns `FastPipeline` and `Close2glFrame`; the core's `SettingsPlugin` provides the rest.
pub struct Close2glPlugin;

impl Plugin for Close2glPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<FastPipeline>()
            .init_resource::<Close2glFrame>()
            .requires::<RenderSettings>("Close2glPlugin", "SettingsPlugin")
            .requires::<Viewport>("Close2glPlugin", "SettingsPlugin")
            .add_systems(PostUpdate, close2gl_system.in_set(FrameSet::Close2gl));
    }
}

/// Recomputes the 2D buffer when the camera, the mesh, the settings or the viewport changed.
pub fn close2gl_system(
    camera: Single<Ref<Camera>>,
    mesh: Single<Ref<Mesh>>,
    settings: Res<RenderSettings>,
    viewport: Res<Viewport>,
    mut pipeline: ResMut<FastPipeline>,
    mut frame: ResMut<Close2glFrame>,
) {
    let changed =
        camera.is_changed() || mesh.is_changed() || settings.is_changed() || viewport.is_changed();
    if !changed {
        return;
    }
    let start = Instant::now();
    pipeline.run(&mesh, &camera, &settings, *viewport, &mut frame);
    frame.stage_ms = start.elapsed().as_secs_f64() * 1e3;
}

/// Adds one triangle's fate to the counts.
fn tally(counts: &mut StageCounts, fate: Fate) {
    counts.triangles_in += 1;
    match fate {
        Fate::Clipped => counts.clipped += 1,
        Fate::Culled => counts.culled += 1,
        Fate::Drawn(primitives) => {
            counts.drawn += 1;
            counts.output_primitives += primitives;
        }
    }
}
