//! The pixel probe's one home: both views' answers for one pixel of the frame the world holds,
//! asked by the viewer's Ctrl+click and by `close2gl inspect --pixel` alike. The reference's
//! comes from the GPU's ID pass ([`crate::id_pass`]), Close2GL's (winner and every candidate)
//! from the raster crate's probe, on the fates this frame's pipeline recorded, or, while nothing
//! records them (the fate view is off), on this frame's worked out once.

use bevy_ecs::prelude::*;
use bevy_ecs::system::SystemParam;
use close2gl_core::{Camera, Fates, Mesh, PipelineSettings, Scene, SoftwareFrame, Viewport};
use close2gl_pipeline::ViewPath;
use close2gl_raster::SoftwareRasterizer;
use close2gl_raster::coverage_probe::{Drawn, PixelProbe, probe};

use crate::gpu::Gpu;
use crate::id_pass::{ReferenceProbe, start_probe};

/// The frame a probe asks about, as the world holds it after the frame's systems: the mesh, the
/// camera, the settings, the recorded fates and, when it drew the view, the software
/// rasterizer's last frame.
#[derive(SystemParam)]
pub struct ProbedFrame<'w, 's> {
    meshes: Query<'w, 's, &'static Mesh>,
    cameras: Query<'w, 's, &'static Camera>,
    settings: Res<'w, PipelineSettings>,
    fates: Res<'w, Fates>,
    rasterizer: Option<Res<'w, SoftwareRasterizer>>,
    image: Option<Res<'w, SoftwareFrame>>,
}

/// Both views' answers for one pixel.
pub struct PixelAnswer {
    /// The camera the answer is for: once it moves, the pixel shows something else.
    pub camera: Camera,
    /// The reference's, on its way back from the GPU ([`ReferenceProbe::wait`] or, in a
    /// browser, [`ReferenceProbe::finish`]), or why its ID pass could not be drawn.
    pub reference: Result<ReferenceProbe, String>,
    /// Close2GL's winner, depth, colour and every candidate with why it lost.
    pub close2gl: PixelProbe,
}

impl ProbedFrame<'_, '_> {
    /// Both views' answers for `pixel` of a `viewport`-sized view; None without a model or a
    /// camera.
    pub fn answer(&self, gpu: &Gpu, viewport: Viewport, pixel: (u32, u32)) -> Option<PixelAnswer> {
        let (mesh, camera) = (self.meshes.single().ok()?, self.cameras.single().ok()?);
        let settings = &*self.settings;
        let scene = Scene {
            mesh,
            camera,
            pipeline: settings,
            viewport,
        };
        let drawn = Drawn::last_frame(settings, self.rasterizer.as_deref(), self.image.as_deref());
        let close2gl = match &*self.fates {
            fates if fates.triangles.len() == mesh.triangles.len() => {
                probe(scene, fates, pixel, drawn)
            }
            _ => probe(scene, &recorded_fates(scene), pixel, drawn),
        };
        Some(PixelAnswer {
            camera: *camera,
            reference: start_probe(gpu, scene, pixel),
            close2gl,
        })
    }
}

/// Every triangle's fate in `scene`, as the path Close2GL's view takes with its settings (with
/// its mistake, if one is set) records them.
fn recorded_fates(scene: Scene<'_>) -> Fates {
    let Scene {
        mesh,
        camera,
        pipeline: settings,
        viewport,
    } = scene;
    ViewPath::of(settings)
        .run_recording(mesh, camera, settings, viewport)
        .1
}
