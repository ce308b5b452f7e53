//! Close2GL's own rasterizer. This crate owns the software path from the pipeline's clipped,
//! culled primitives to pixels: triangle setup in fixed point with the top-left fill rule, lines
//! and points as the reference's GPU draws them, a depth buffer with the reference's test, the
//! four shadings lit exactly as the reference's shader lights them, and perspective-correct
//! interpolation; tiled (64×64 bins, each triangle binned once) and drawn in parallel. Its
//! `RasterPlugin` owns the `SoftwareFrame` image and writes it, in the `Close2gl` set after the
//! pipeline, when `PipelineSettings::close2gl_raster` is `software`; it reads `Close2glFrame`
//! (the Close2GL plugin's), `Camera`, `PipelineSettings` (who rasterizes), `Appearance` (colour,
//! shading, background, texture and filter) and `Lighting` (the settings plugin's),
//! and the model's `Texture` when there is one. Textures are sampled by its own code, from its
//! own mipmap chain (nearest, bilinear, trilinear). While `Fates::record` is set it also writes
//! the `Fates` resource (the pipeline's): the drawn triangles that covered no pixel centre or
//! won none become `no_pixels` and `hidden`, and it keeps who drew each pixel
//! ([`SoftwareRasterizer::owner`]) for the inspector's probe. Like the pipeline, it knows no
//! GPU, window or UI.
//!
//! Read [`textbook`] first: the rasterizer as the textbook writes it, in one file that stands
//! alone, each triangle and each pixel of its bounding box one at a time (edge functions with the
//! top-left rule, the depth test, then the shading and the texture). The fast rasterizer, to read
//! next, covers exactly its pixels, with depth and colour equal but for rounding (`tests/golden.rs`
//! holds it to them, and docs/rasterizer.md states the tolerances). What it adds, to get those
//! pixels faster, is fixed-point setup once per vertex and triangle, with planes evaluated in f32,
//! and how the work is shared out and batched: every primitive set up and binned into 64×64 tiles
//! in one parallel pass (those that cover no pixel centre dropped before their planes are built),
//! the tiles drawn by the threads, each triangle's covered rows solved rather than tested pixel by
//! pixel, eight pixels at a time in SIMD lanes, small triangles listed as their fragments, Phong's
//! attenuation skipped when it is 1 everywhere, and Phong shaded once per pixel after the depth
//! test where a tile's triangles are small, their partial blocks queued where they are not.
//!
//! Its files follow one frame, in the order `rasterizer` runs them: `vertex` (each vertex's
//! varyings, lit by `lighting` for Gouraud) → `bin` (setup and binning in one parallel pass, in
//! submission order: each primitive to triangles by `primitives` and `setup`, with `edge`'s
//! fixed-point edge functions and `varyings`' planes, those that cover no pixel centre dropped
//! before their planes are built, the rest listed in the 64×64 tiles they touch, a small one
//! as its fragments, each pixel with its depth and, for Phong, its values there) → the tiles
//! shared out between the threads by `tile_runs` → `tile` (a narrow triangle's rows found pixel
//! by pixel, a wide one's solved; or `deferred`, a tile of small Phong-shaded triangles
//! depth-tested first and shaded once per pixel after) → `row` → `lanes`, the hierarchy tile →
//! rows → blocks of eight lanes (llvmpipe's is tile → block → quad): each block depth-tested,
//! then coloured by `shading` (with `sampling`'s level of detail and filters) into `target`'s
//! buffers, or, for Phong, a small triangle's partial blocks left in `queue` and shaded eight
//! pixels together when the triangle is done in the tile. The tiles are then copied out as the
//! image. `pixel_fates` and `coverage_probe` read what a frame left.

mod bin;
pub mod coverage_probe;
mod deferred;
mod edge;
mod lanes;
mod lighting;
mod pixel_fates;
mod primitives;
mod queue;
mod rasterizer;
mod row;
mod sampling;
mod setup;
mod shading;
mod target;
pub mod textbook;
mod tile;
mod tile_runs;
mod varyings;
mod vertex;

use web_time::Instant;

use bevy_ecs::prelude::*;
use close2gl_core::Owner;
use close2gl_core::{
    App, Appearance, Camera, Close2glFrame, Close2glStep, Fates, Lighting, PipelineSettings,
    Plugin, RasterMistake, RasterMistakes, Rasterizer, SoftwareFrame, Texture, Update,
};

pub use rasterizer::SoftwareRasterizer;

/// Runs the software rasterizer in `FrameSet::Close2gl`, after the Close2GL pipeline.
pub struct RasterPlugin;

impl Plugin for RasterPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<SoftwareRasterizer>()
            .init_resource::<SoftwareFrame>()
            .requires::<Close2glFrame>(Owner::Close2gl)
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<Appearance>(Owner::Settings)
            .requires::<Lighting>(Owner::Settings)
            .requires::<Fates>(Owner::Close2gl)
            .add_systems(Update, raster_system.in_set(Close2glStep::Raster));
    }
}

/// Draws a new image (and, while recording, the rasterizer's fates) when the pipeline's output
/// or the lighting changed (and the software rasterizer is the one asked for).
pub fn raster_system(
    camera: Single<&Camera>,
    frame: Res<Close2glFrame>,
    (pipeline, look): (Res<PipelineSettings>, Res<Appearance>),
    lighting: Res<Lighting>,
    texture: Option<Res<Texture>>,
    mut rasterizer: ResMut<SoftwareRasterizer>,
    (mut image, mut fates): (ResMut<SoftwareFrame>, ResMut<Fates>),
) {
    let wanted = pipeline.close2gl_raster == Rasterizer::Software;
    // Set even while the GPU draws the view, so that switching to software finds it ready.
    let new_texture = texture
        .as_ref()
        .map_or(rasterizer.has_texture(), |t| t.is_changed());
    if new_texture {
        rasterizer.set_texture(texture.as_deref());
    }
    // A change of the pipeline's switches changes the frame too; the look only the pixels.
    let stale = frame.is_changed() || lighting.is_changed() || look.is_changed() || new_texture;
    if !wanted || !stale {
        return;
    }
    let start = Instant::now();
    // Fates are written only while recorded; otherwise nobody needs telling.
    let fates = match fates.record {
        true => fates.into_inner(),
        false => fates.bypass_change_detection(),
    };
    match look.raster_mistake {
        RasterMistake::None => {
            rasterizer.draw(&frame, &camera, &look, &lighting, &mut image, fates)
        }
        // The mistakes live in the textbook rasterizer only (one place to read each): it draws
        // the view while one is made, without the fast one's fates.
        mistake => {
            let mistakes = RasterMistakes::one(mistake);
            let texture = texture.as_deref();
            let drawn =
                textbook::draw_mistaken(&frame, &camera, &look, &lighting, texture, mistakes);
            image.image = drawn.image;
        }
    }
    image.raster_ms = start.elapsed().as_secs_f64() * 1e3;
}
