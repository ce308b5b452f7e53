//! Close2GL: the geometry half of the OpenGL pipeline, in software. This crate owns the
//! hand-written matrices (modelview M, projection P, viewport V), clipping in homogeneous space,
//! the perspective division, backface culling, and the `Close2glPlugin` whose system reads the
//! `Camera` and `Mesh` components and the `PipelineSettings` and `Viewport` resources (owned by the
//! core's `SettingsPlugin`), and writes the `Close2glFrame` resource, which it owns: the 2D vertex
//! buffer in window pixels (which the GPU only draws) and the stage counts. It also owns the
//! core's `Fates` resource: every frame it writes each fate's count, and, while `RecordFates`
//! asks, each mesh triangle's fate (the software rasterizer then adds `no_pixels` and
//! `hidden`). [`journey`] follows one triangle through every stage with its numbers, for the
//! inspector. For the outside view it gives the view volume's world corners from the real
//! matrices ([`frustum`]) and the stage morph from world to eye to NDC coordinates ([`morph`]),
//! as pure functions. It depends on no GPU, window or UI crate; glam only holds the numbers.

pub mod clip;
pub mod emit;
pub mod fast;
pub mod frustum;
pub mod journey;
pub mod matrices;
pub mod mistakes;
pub mod morph;
pub mod program;
#[cfg(test)]
mod random_triangles;
pub mod rounding;
pub mod stage;
pub mod textbook;

use web_time::Instant;

use bevy_ecs::prelude::*;
use close2gl_core::Owner;
use close2gl_core::{
    App, Camera, Close2glFrame, Close2glStep, FateCounts, FateKind, Fates, Mesh, Mistake,
    PipelineSettings, Plugin, RecordFates, StageCounts, Update, Viewport,
};

pub use fast::FastPipeline;
use stage::Fate;

/// Runs the Close2GL pipeline in `FrameSet::Close2gl`, after the camera has moved.
/// It owns `FastPipeline`, `Close2glFrame` and `Fates`; the core's `SettingsPlugin` provides the
/// rest.
pub struct Close2glPlugin;

impl Plugin for Close2glPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<FastPipeline>()
            .init_resource::<Close2glFrame>()
            .init_resource::<Fates>()
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<Viewport>(Owner::Settings)
            .requires::<RecordFates>(Owner::Settings)
            .add_systems(Update, close2gl_system.in_set(Close2glStep::Geometry));
    }
}

/// Recomputes the 2D buffer and the fates when the camera, the mesh, the settings or the
/// viewport changed, or when someone started or stopped recording fates.
pub fn close2gl_system(
    camera: Single<Ref<Camera>>,
    mesh: Single<Ref<Mesh>>,
    settings: Res<PipelineSettings>,
    viewport: Res<Viewport>,
    mut pipeline: ResMut<FastPipeline>,
    mut frame: ResMut<Close2glFrame>,
    (mut fates, request): (ResMut<Fates>, Res<RecordFates>),
) {
    if fates.record != request.0 {
        fates.record = request.0;
    }
    let changed =
        camera.is_changed() || mesh.is_changed() || settings.is_changed() || viewport.is_changed();
    let recorded = match fates.record {
        true => fates.triangles.len() == mesh.triangles.len(),
        false => fates.triangles.is_empty(),
    };
    if !changed && recorded {
        return;
    }
    let start = Instant::now();
    if let ViewPath::Program(mistakes) = ViewPath::of(&settings) {
        let (mistaken, all) = program::view::run(&mesh, &camera, &settings, *viewport, mistakes);
        *frame = mistaken;
        let record = fates.record;
        *fates = all;
        fates.record = record;
        if !record {
            // The rasterizer adds its fates only to a recorded frame.
            fates.triangles.clear();
            frame.raster.triangles.clear();
        }
    } else {
        pipeline.run(&mesh, &camera, &settings, *viewport, &mut frame, &mut fates);
    }
    frame.geometry_ms = start.elapsed().as_secs_f64() * 1e3;
}

/// Which path draws Close2GL's view with some settings, said once: the fast path, which never
/// sees a mistake, or, for a frame with one, a program that makes it ([`program::view`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewPath {
    Fast,
    Program(mistakes::Mistakes),
}

impl ViewPath {
    pub fn of(settings: &PipelineSettings) -> Self {
        match settings.mistake {
            Mistake::None => ViewPath::Fast,
            mistake => ViewPath::Program(mistakes::Mistakes::one(mistake)),
        }
    }

    /// The frame this path draws and every triangle's fate, recorded. The fast path's are the
    /// textbook path's (tests hold them equal), worked out here by the textbook, which needs no
    /// buffers kept between frames.
    pub fn run_recording(
        self,
        mesh: &Mesh,
        camera: &Camera,
        settings: &PipelineSettings,
        viewport: Viewport,
    ) -> (Close2glFrame, Fates) {
        match self {
            ViewPath::Fast => textbook::run_recording(mesh, camera, settings, viewport),
            ViewPath::Program(mistakes) => {
                program::view::run(mesh, camera, settings, viewport, mistakes)
            }
        }
    }
}

/// How many of some triangles met each fate, and how many primitives they were drawn as. The
/// fates are counted in an array indexed by the kind: one add per triangle, no branch.
#[derive(Clone, Copy, Debug, Default)]
struct Tally {
    fates: [usize; FateKind::ALL.len()],
    primitives: usize,
}

impl Tally {
    /// Adds one triangle's fate.
    #[inline(always)]
    fn add(&mut self, fate: &Fate) {
        self.fates[fate.fate.kind as usize] += 1;
        self.primitives += fate.primitives;
    }

    /// Adds another tally (a parallel chunk's).
    fn merge(&mut self, other: &Tally) {
        for (count, more) in self.fates.iter_mut().zip(other.fates) {
            *count += more;
        }
        self.primitives += other.primitives;
    }

    /// The fate counts. Exact only for a recorded frame: without recording, a back face with no
    /// area counts as culled, and no_pixels and hidden are the rasterizer's to add.
    fn fate_counts(&self) -> FateCounts {
        FateCounts::from_fn(|kind| self.fates[kind as usize])
    }

    /// The stage counts, which recording or not does not change.
    fn stage_counts(&self) -> StageCounts {
        let fates = self.fate_counts();
        StageCounts {
            triangles_in: self.fates.iter().sum(),
            clipped: fates.clipped,
            culled: fates.culled + fates.zero_area,
            drawn: fates.drawn + fates.cut,
            output_primitives: self.primitives,
        }
    }
}
