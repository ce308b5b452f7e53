//! What the raster crate's tests share: a scene drawn as the app draws it, the Close2GL
//! pipeline then (when the settings ask for it) the software rasterizer, with every buffer kept
//! from frame to frame as the app keeps them.

use close2gl_core::{
    Appearance, Camera, Close2glFrame, Fates, Lighting, Mesh, PipelineSettings, Rasterizer,
    SoftwareFrame, Texture, Viewport,
};
use close2gl_pipeline::FastPipeline;
use close2gl_raster::SoftwareRasterizer;

/// What stays the same from frame to frame.
pub struct Scene<'a> {
    pub mesh: &'a Mesh,
    pub camera: Camera,
    pub viewport: Viewport,
    pub lighting: Lighting,
    pub texture: Option<&'a Texture>,
}

impl<'a> Scene<'a> {
    /// `mesh` seen from the assignment's initial camera (at the origin, looking down −z), its
    /// near plane moved to 0.3 and its far plane to 20, under the default lighting.
    pub fn new(mesh: &'a Mesh, viewport: Viewport, texture: Option<&'a Texture>) -> Self {
        Scene {
            mesh,
            camera: Camera {
                near: 0.3,
                far: 20.0,
                ..Camera::default()
            },
            viewport,
            lighting: Lighting::default(),
            texture,
        }
    }
}

/// The pipeline's and the rasterizer's state and output, reused from frame to frame.
#[derive(Default)]
pub struct Drawing {
    pub pipeline: FastPipeline,
    pub rasterizer: SoftwareRasterizer,
    pub frame: Close2glFrame,
    pub image: SoftwareFrame,
    pub fates: Fates,
    /// The texture last set, so that a scene's texture is set once, as the app sets it.
    pub texture: Option<Texture>,
}

impl Drawing {
    /// One frame of `scene` with the pipeline's switches `pipeline` and the look `look`,
    /// recording fates when `record`.
    pub fn draw(
        &mut self,
        scene: &Scene<'_>,
        pipeline: &PipelineSettings,
        look: &Appearance,
        record: bool,
    ) {
        self.fates.record = record;
        self.pipeline.run(
            scene.mesh,
            &scene.camera,
            pipeline,
            scene.viewport,
            &mut self.frame,
            &mut self.fates,
        );
        if self.texture.as_ref() != scene.texture {
            self.texture = scene.texture.cloned();
            self.rasterizer.set_texture(scene.texture);
        }
        if pipeline.close2gl_raster == Rasterizer::Software {
            self.rasterizer.draw(
                &self.frame,
                &scene.camera,
                look,
                &scene.lighting,
                &mut self.image,
                &mut self.fates,
            );
        }
    }
}
