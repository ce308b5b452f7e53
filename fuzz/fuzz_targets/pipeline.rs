//! The Close2GL stage and the software rasterizer after it, on arbitrary meshes (positions,
//! normals and texture coordinates including NaN, infinities, 1e38, 1e-38, zero; degenerate and
//! huge triangles), arbitrary cameras (looked at from a point, or a raw u, v, n that may be NaN
//! or zero; any fields of view and clipping distances) and every mode and setting, in viewports
//! of 1..=64 pixels a side, for up to three frames reusing the same buffers as the app does.
//! Never a panic or a hang; the fast path's output equals the textbook path's bit for bit; the
//! counts and the rasterizer's indices add up; and for a sane scene every vertex is finite.
#![no_main]

use arbitrary::Arbitrary;
use close2gl_core::glam::{Vec2, Vec3};
use close2gl_core::limits::FOV_RANGE;
use close2gl_core::{
    Appearance, Camera, Clipping, Close2glFrame, FateCounts, Fates, FrontFace, Image, Lighting,
    Mesh, Overlay, PipelineSettings, Rasterizer, RenderMode, Shading, SoftwareFrame, Texture,
    TextureFilter, Topology, Viewport,
};
use close2gl_fuzz::{Num, vec3};
use close2gl_pipeline::{FastPipeline, textbook};
use close2gl_raster::SoftwareRasterizer;
use libfuzzer_sys::fuzz_target;

const MAX_VERTICES: usize = 64;
const MAX_TRIANGLES: usize = 256;

#[derive(Arbitrary, Debug)]
struct VertexIn {
    position: [Num; 3],
    normal: [Num; 3],
    uv: [Num; 2],
}

#[derive(Arbitrary, Debug)]
struct Lens {
    hfov: Num,
    vfov: Num,
    near: Num,
    far: Num,
}

#[derive(Arbitrary, Debug)]
enum CameraIn {
    /// As the camera plugin builds it (when the pose is not degenerate).
    LookAt {
        position: [Num; 3],
        target: [Num; 3],
        up: [Num; 3],
        lens: Lens,
    },
    /// Any basis at all.
    Raw {
        position: [Num; 3],
        u: [Num; 3],
        v: [Num; 3],
        n: [Num; 3],
        lens: Lens,
    },
}

#[derive(Arbitrary, Debug)]
struct SettingsIn {
    mode: u8,
    cw: bool,
    culling: bool,
    simple_clipping: bool,
    shading: u8,
    software: bool,
    texture: bool,
    filter: u8,
    overlay: u8,
    color: [Num; 3],
    background: [Num; 3],
}

#[derive(Arbitrary, Debug)]
struct LightingIn {
    light_position: [Num; 3],
    ia: [Num; 3],
    il: [Num; 3],
    k: [Num; 3],
    shininess: Num,
    attenuation: [Num; 3],
}

#[derive(Arbitrary, Debug)]
struct TextureIn {
    width: u8,
    height: u8,
    seed: u32,
}

#[derive(Arbitrary, Debug)]
struct Input {
    vertices: Vec<VertexIn>,
    textured: bool,
    triangles: Vec<[u16; 3]>,
    camera: CameraIn,
    lighting: LightingIn,
    texture: Option<TextureIn>,
    width: u8,
    height: u8,
    /// One to three frames through the same buffers.
    frames: [SettingsIn; 3],
    frame_count: u8,
}

fn pick<T: Copy>(all: &[T], i: u8) -> T {
    all[usize::from(i) % all.len()]
}

/// The pipeline's switches (the textbook, no mistake), the look and the overlay of one frame.
fn settings(s: &SettingsIn) -> (PipelineSettings, Appearance, Overlay) {
    let pipeline = PipelineSettings {
        mode: pick(RenderMode::ALL, s.mode),
        front_face: if s.cw { FrontFace::Cw } else { FrontFace::Ccw },
        backface_culling: s.culling,
        clipping: if s.simple_clipping {
            Clipping::Simple
        } else {
            Clipping::Full
        },
        close2gl_raster: if s.software {
            Rasterizer::Software
        } else {
            Rasterizer::Gpu
        },
        ..PipelineSettings::default()
    };
    let look = Appearance {
        color: vec3(s.color),
        shading: pick(Shading::ALL, s.shading),
        background: vec3(s.background),
        texture: s.texture,
        texture_filter: pick(TextureFilter::ALL, s.filter),
    };
    (pipeline, look, pick(Overlay::ALL, s.overlay))
}

fn mesh(input: &Input) -> Mesh {
    let vertices = &input.vertices[..input.vertices.len().min(MAX_VERTICES)];
    let count = vertices.len();
    let triangles = if count == 0 {
        Vec::new()
    } else {
        input
            .triangles
            .iter()
            .take(MAX_TRIANGLES)
            .map(|t| t.map(|i| (usize::from(i) % count) as u32))
            .collect()
    };
    Mesh {
        face_normals: Vec::new(),
        name: "fuzz".into(),
        positions: vertices.iter().map(|v| vec3(v.position)).collect(),
        normals: vertices.iter().map(|v| vec3(v.normal)).collect(),
        uvs: if input.textured {
            vertices
                .iter()
                .map(|v| Vec2::new(v.uv[0].get(), v.uv[1].get()))
                .collect()
        } else {
            Vec::new()
        },
        triangles,
    }
}

/// A camera with the lens `l`, at the default pose.
fn lens(l: &Lens) -> Camera {
    Camera {
        hfov: l.hfov.get(),
        vfov: l.vfov.get(),
        near: l.near.get(),
        far: l.far.get(),
        ..Camera::default()
    }
}

/// Fields of view in range and 1e-4 <= near < far <= 1e6.
fn sane_lens(c: &Camera) -> bool {
    FOV_RANGE.contains(&c.hfov)
        && FOV_RANGE.contains(&c.vfov)
        && (1e-4..=1e6).contains(&c.near)
        && (1e-4..=1e6).contains(&c.far)
        && c.near < c.far
}

/// Finite, and no farther than 1e4 along any axis.
fn moderate(v: Vec3) -> bool {
    v.is_finite() && v.abs().max_element() <= 1e4
}

/// The camera, and whether it is one the app could hold: built by `looking_at` from finite,
/// moderate points, with a sane lens.
fn camera(input: &CameraIn) -> (Camera, bool) {
    match input {
        CameraIn::LookAt {
            position,
            target,
            up,
            lens: l,
        } => {
            let (position, target, up) = (vec3(*position), vec3(*target), vec3(*up));
            let base = lens(l);
            match base.looking_at(position, target, up) {
                Some(c) => {
                    let sane = sane_lens(&c) && moderate(position) && moderate(target);
                    (c, sane)
                }
                None => (
                    Camera {
                        position,
                        target,
                        ..base
                    },
                    false,
                ),
            }
        }
        CameraIn::Raw {
            position,
            u,
            v,
            n,
            lens: l,
        } => (
            Camera {
                position: vec3(*position),
                u: vec3(*u),
                v: vec3(*v),
                n: vec3(*n),
                ..lens(l)
            },
            false,
        ),
    }
}

fn lighting(l: &LightingIn) -> Lighting {
    Lighting {
        light_position: vec3(l.light_position),
        ia: vec3(l.ia),
        il: vec3(l.il),
        ka: l.k[0].get(),
        kd: l.k[1].get(),
        ks: l.k[2].get(),
        shininess: l.shininess.get(),
        attenuation: l.attenuation.map(Num::get),
    }
}

fn texture(t: &TextureIn) -> Texture {
    let (width, height) = (u32::from(t.width % 8) + 1, u32::from(t.height % 8) + 1);
    let pixels = (0..width * height)
        .map(|i| (t.seed.rotate_left(i) ^ i.wrapping_mul(0x9e37_79b9)).to_le_bytes())
        .collect();
    Texture {
        source: None,
        image: Image {
            width,
            height,
            pixels,
        },
    }
}

fn bits(vertices: &[[f32; 2]]) -> Vec<[u32; 2]> {
    vertices.iter().map(|v| v.map(f32::to_bits)).collect()
}

fn check_frame(frame: &Close2glFrame, mesh: &Mesh, settings: &PipelineSettings, sane: bool) {
    let counts = frame.counts;
    assert_eq!(counts.triangles_in, mesh.triangles.len(), "{counts:?}");
    assert_eq!(
        counts.clipped + counts.culled + counts.drawn,
        counts.triangles_in,
        "{counts:?}"
    );
    let per_primitive = match frame.topology {
        Topology::Points => 1,
        Topology::Lines => 2,
        Topology::Triangles => 3,
    };
    assert_eq!(
        frame.vertices.len(),
        per_primitive * counts.output_primitives,
        "{counts:?}"
    );
    if settings.close2gl_raster == Rasterizer::Software {
        let raster = &frame.raster;
        assert_eq!(raster.primitives.len(), frame.vertices.len());
        assert_eq!(raster.vertices.len(), mesh.positions.len());
        let all = raster.vertices.len() + raster.cuts.len();
        for &i in &raster.primitives {
            assert!((i as usize) < all, "index {i} of {all} vertices");
        }
        for cut in &raster.cuts {
            for &c in &cut.corners {
                assert!((c as usize) < mesh.positions.len(), "cut corner {c}");
            }
        }
    }
    let sane_mesh = mesh
        .positions
        .iter()
        .all(|p| p.is_finite() && p.abs().max_element() <= 1e4);
    if sane && sane_mesh {
        for v in &frame.vertices {
            assert!(v[0].is_finite() && v[1].is_finite(), "vertex {v:?}");
        }
    }
}

fuzz_target!(|input: Input| {
    let mesh = mesh(&input);
    let (camera, sane) = camera(&input.camera);
    let lighting = lighting(&input.lighting);
    let texture = input.texture.as_ref().map(texture);
    let viewport = Viewport {
        width: u32::from(input.width % 64) + 1,
        height: u32::from(input.height % 64) + 1,
    };
    let mut pipeline = FastPipeline::default();
    let mut rasterizer = SoftwareRasterizer::default();
    let mut frame = Close2glFrame::default();
    let mut fates = Fates::default();
    let mut image = SoftwareFrame::default();
    let frames = usize::from(input.frame_count % 3) + 1;
    for s in &input.frames[..frames] {
        let (settings, look, overlay) = settings(s);
        // The inspector records fates while one of its overlays is shown.
        fates.record = overlay != Overlay::Off;
        pipeline.run(&mesh, &camera, &settings, viewport, &mut frame, &mut fates);
        let (expected, expected_fates) =
            textbook::run_recording(&mesh, &camera, &settings, viewport);
        assert_eq!(frame.counts, expected.counts);
        // Unrecorded, a frame asks none of the inspector's questions: no fates, no counts.
        if fates.record {
            assert_eq!(fates.counts, expected_fates.counts);
            assert_eq!(
                format!("{:?}", fates.triangles),
                format!("{:?}", expected_fates.triangles),
                "the fast path's fates differ from the textbook path's"
            );
        } else {
            assert!(fates.triangles.is_empty());
            assert_eq!(fates.counts, FateCounts::default());
        }
        assert_eq!(frame.topology, expected.topology);
        assert_eq!(
            bits(&frame.vertices),
            bits(&expected.vertices),
            "the fast path differs from the textbook path"
        );
        check_frame(&frame, &mesh, &settings, sane);
        if settings.close2gl_raster == Rasterizer::Software {
            rasterizer.set_texture(texture.as_ref());
            rasterizer.draw(
                &frame, &camera, &look, &lighting, &mut image, &mut fates,
            );
            let image = &image.image;
            assert_eq!(
                (image.width, image.height),
                (viewport.width, viewport.height)
            );
            // The rasterizer moves drawn triangles to no_pixels or hidden, never others.
            let (c, e) = (fates.counts, expected_fates.counts);
            if fates.record {
                assert_eq!(c.drawn + c.cut + c.no_pixels + c.hidden, e.drawn + e.cut);
                assert_eq!(
                    (c.clipped, c.culled, c.zero_area),
                    (e.clipped, e.culled, e.zero_area)
                );
            } else {
                assert_eq!(c, FateCounts::default());
            }
            assert_eq!(
                image.pixels.len(),
                (viewport.width * viewport.height) as usize
            );
        }
    }
});
