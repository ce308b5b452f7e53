//! The rasterizer's output pinned to hashes: scenes covering every path (each shading, each texture
//! filter, wireframe, points, both clippings, culling, many tiles, fates recorded), drawn on one
//! thread and on two, each image and depth buffer (and, while fates are recorded, the owner of each
//! pixel and the fate counts) hashed with FNV-1a and compared with the hash the rasterizer gave
//! when the constants were taken. A restructuring that changes no pixel keeps them all; any change
//! of output, however small, fails here and names the scene. A change meant to alter the output (a
//! fix for parity with the reference, say) takes the new hashes this test prints, in the same
//! commit, saying why. The same scenes are also drawn by the textbook rasterizer
//! (`src/textbook/`): the same pixels covered, and depth and colour within the tolerances below.

use TextureFilter::Nearest;
use close2gl_core::glam::{Vec2, Vec3};
use close2gl_core::{
    Appearance, Clipping, Mesh, PipelineSettings, Rasterizer, RenderMode, Shading, SoftwareFrame,
    Texture, TextureFilter, Viewport,
};
use close2gl_raster::textbook;

mod common;
use common::{Drawing, Scene};

/// 64-bit FNV-1a.
struct Fnv(u64);

impl Fnv {
    fn new() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= b as u64;
            self.0 = self.0.wrapping_mul(0x0100_0000_01b3);
        }
    }
}

/// A wavy ground from beside the eye to far ahead (so the near and side planes cut it), with
/// normals that vary (so the shadings differ) and texture coordinates that repeat (so the far
/// part is minified), and a sphere standing on it (so the depth test has work).
fn scene_mesh() -> Mesh {
    let mut mesh = Mesh {
        face_normals: Vec::new(),
        name: "golden".into(),
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        triangles: Vec::new(),
    };
    ground(&mut mesh, 90);
    sphere(&mut mesh, Vec3::new(0.3, -0.2, -3.0), 0.8, 24);
    mesh
}

fn ground(mesh: &mut Mesh, n: u32) {
    let first = mesh.positions.len() as u32;
    for i in 0..=n {
        for j in 0..=n {
            let (a, b) = (i as f32 / n as f32, j as f32 / n as f32);
            let (x, z) = (a * 4.0 - 2.0, b * -9.0 + 1.0);
            let y = -0.6 + 0.15 * (3.0 * x).sin() * (2.0 * z).cos();
            let slope = Vec2::new(
                0.45 * (3.0 * x).cos() * (2.0 * z).cos(),
                -0.3 * (3.0 * x).sin() * (2.0 * z).sin(),
            );
            mesh.positions.push(Vec3::new(x, y, z));
            mesh.normals
                .push(Vec3::new(-slope.x, 1.0, -slope.y).normalize());
            mesh.uvs.push(Vec2::new(a * 3.0, b * 7.0));
        }
    }
    grid_triangles(mesh, first, n, n);
}

fn sphere(mesh: &mut Mesh, centre: Vec3, radius: f32, n: u32) {
    let first = mesh.positions.len() as u32;
    for i in 0..=n {
        for j in 0..=n {
            let (a, b) = (i as f32 / n as f32, j as f32 / n as f32);
            let (theta, phi) = (b * std::f32::consts::PI, a * std::f32::consts::TAU);
            let normal = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            mesh.positions.push(centre + normal * radius);
            mesh.normals.push(normal);
            mesh.uvs.push(Vec2::new(a * 2.0, 1.0 - b));
        }
    }
    grid_triangles(mesh, first, n, n);
}

/// Two triangles for each cell of a (rows + 1) × (columns + 1) grid of vertices from `first`.
fn grid_triangles(mesh: &mut Mesh, first: u32, rows: u32, columns: u32) {
    let at = |i: u32, j: u32| first + i * (columns + 1) + j;
    for i in 0..rows {
        for j in 0..columns {
            mesh.triangles
                .push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            mesh.triangles
                .push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
}

/// One pinned scene: its name, settings, whether fates are recorded, and its hash.
struct Pinned {
    name: &'static str,
    pipeline: PipelineSettings,
    look: Appearance,
    record: bool,
    hash: u64,
}

fn scene(
    name: &'static str,
    hash: u64,
    change: impl FnOnce(&mut PipelineSettings, &mut Appearance),
) -> Pinned {
    let mut pipeline = PipelineSettings {
        backface_culling: false,
        close2gl_raster: Rasterizer::Software,
        ..PipelineSettings::default()
    };
    let mut look = Appearance {
        texture: false,
        ..Appearance::default()
    };
    change(&mut pipeline, &mut look);
    Pinned {
        name,
        pipeline,
        look,
        record: false,
        hash,
    }
}

fn pinned() -> Vec<Pinned> {
    use Shading::*;
    use TextureFilter::{Bilinear, Trilinear};
    let textured = |filter, shading| {
        move |_: &mut PipelineSettings, a: &mut Appearance| {
            (a.texture, a.texture_filter, a.shading) = (true, filter, shading);
        }
    };
    vec![
        scene("flat", 0xd8e00aecbfd29fec, |_, a| a.shading = None),
        scene("gouraud_ad", 0x83c0bcd0767a71ca, |_, a| {
            a.shading = GouraudAd
        }),
        scene("gouraud_ads", 0xee6d31d5217f4073, |_, a| {
            a.shading = GouraudAds
        }),
        scene("phong", 0xf5541036dd9fc8aa, |_, a| a.shading = Phong),
        scene("nearest_flat", 0x66ecde7546c4c498, textured(Nearest, None)),
        scene(
            "bilinear_gouraud",
            0xf5aa4abd8a57fed4,
            textured(Bilinear, GouraudAds),
        ),
        scene(
            "trilinear_phong",
            0xd6811f4f16b36d90,
            textured(Trilinear, Phong),
        ),
        scene(
            "trilinear_flat",
            0xcd715d8494b20ab5,
            textured(Trilinear, None),
        ),
        scene("wireframe_phong", 0xee515db2d113d56f, |p, a| {
            (p.mode, a.shading) = (RenderMode::Wireframe, Phong)
        }),
        scene("points_gouraud", 0x511497eb377956ea, |p, a| {
            (p.mode, a.shading) = (RenderMode::Points, GouraudAd)
        }),
        scene("simple_clipping_culled", 0xb8520e7fa636e859, |p, a| {
            (p.clipping, p.backface_culling, a.shading) = (Clipping::Simple, true, Phong)
        }),
        Pinned {
            record: true,
            ..scene(
                "recorded_trilinear_phong",
                0xf01e34943bd2b765,
                textured(Trilinear, Phong),
            )
        },
        Pinned {
            record: true,
            ..scene("recorded_wireframe", 0xc6d8d5d9c3d680dd, |p, _| {
                p.mode = RenderMode::Wireframe
            })
        },
    ]
}

/// The scenes' fixed part: the mesh, the camera, the lighting and the checkerboard, in a
/// viewport that is not a whole number of 64-pixel tiles either way (the edge tiles are
/// partial).
fn with_scene(draw: impl FnOnce(&Scene<'_>)) {
    let mesh = scene_mesh();
    let texture = Texture::default();
    let viewport = Viewport {
        width: 301,
        height: 203,
    };
    draw(&Scene::new(&mesh, viewport, Some(&texture)));
}

/// Draws every pinned scene with one rasterizer (its buffers reused from scene to scene, as
/// the app reuses them from frame to frame) and hashes what each drew.
fn draw_pinned(scene: &Scene<'_>, pinned: &[Pinned]) -> Vec<u64> {
    let mut drawing = Drawing::default();
    let mut hashes = Vec::new();
    for p in pinned {
        drawing.draw(scene, &p.pipeline, &p.look, p.record);
        assert!(drawing.frame.counts.drawn > 0, "{}: nothing drawn", p.name);
        hashes.push(hash(&drawing, scene.viewport, p.record));
    }
    hashes
}

/// The image and the depth buffer; while fates are recorded, each pixel's owner and the counts.
fn hash(drawing: &Drawing, viewport: Viewport, record: bool) -> u64 {
    let (image, rasterizer) = (&drawing.image.image, &drawing.rasterizer);
    let mut hash = Fnv::new();
    hash.bytes(&image.width.to_le_bytes());
    hash.bytes(&image.height.to_le_bytes());
    hash.bytes(image.pixels.as_flattened());
    for (x, y) in (0..viewport.height).flat_map(|y| (0..viewport.width).map(move |x| (x, y))) {
        let depth = rasterizer.depth(x, y).unwrap_or(f32::NAN);
        hash.bytes(&depth.to_bits().to_le_bytes());
        if record {
            let owner = rasterizer.owner(x, y).unwrap_or(u32::MAX);
            hash.bytes(&owner.to_le_bytes());
        }
    }
    if record {
        hash.bytes(format!("{:?}", drawing.fates.counts).as_bytes());
    }
    hash.0
}

/// A pool of `threads` threads for the frames to be drawn on.
fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

/// Whether the images show something: the background alone would hash the same every time.
fn distinct_colours(frame: &SoftwareFrame) -> usize {
    let mut colours: Vec<[u8; 4]> = frame.image.pixels.clone();
    colours.sort_unstable();
    colours.dedup();
    colours.len()
}

#[test]
fn every_path_draws_the_pixels_it_drew_when_the_hashes_were_taken() {
    let pinned = pinned();
    for threads in [1, 2] {
        let pool = pool(threads);
        let mut hashes = Vec::new();
        with_scene(|scene| hashes = pool.install(|| draw_pinned(scene, &pinned)));
        let wrong: Vec<String> = pinned
            .iter()
            .zip(&hashes)
            .filter(|(p, hash)| p.hash != **hash)
            .map(|(p, hash)| format!("{}: {hash:#018x} (pinned {:#018x})", p.name, p.hash))
            .collect();
        assert!(
            wrong.is_empty(),
            "on {threads} thread(s), scenes drew other pixels:\n{}",
            wrong.join("\n")
        );
    }
}

/// How far the textbook rasterizer's depth may be from the fast one's: its f64 barycentrics
/// against the fast one's f32 planes, a few units in the last place of a depth near 1.
const DEPTH_TOLERANCE: f32 = 1e-6;
/// How many of the 255 steps a colour channel may differ by where both show the same triangle:
/// one, a rounding on either side of a step's middle.
const COLOUR_TOLERANCE: u8 = 1;
/// With the nearest filter, the share of the covered pixels whose colours may differ by more:
/// where (s, t) falls exactly on a texel's edge, and either texel is right.
const TEXEL_EDGES: f64 = 1.0 / 2000.0;

/// Every pinned scene drawn by the textbook rasterizer (`src/textbook/`) and by the fast one
/// (recording fates, so that each pixel's owner is known): the same pixels covered, exactly;
/// every depth within `DEPTH_TOLERANCE`; where both show the same mesh triangle, every colour
/// channel within `COLOUR_TOLERANCE` (but at texel edges, see `TEXEL_EDGES`). Where they show
/// different ones, the depth test met a near tie (a shared edge of the wireframe drawn twice,
/// say): each took its own winner to be nearer by less than the other's rounding, which the
/// depths agreeing within `DEPTH_TOLERANCE` bears out, and the colours are not compared.
#[test]
fn the_textbook_covers_the_fast_rasterizers_pixels_and_agrees_within_rounding() {
    let mut wrong = Vec::new();
    with_scene(|scene| {
        let mut drawing = Drawing::default();
        for p in &pinned() {
            drawing.draw(scene, &p.pipeline, &p.look, true);
            let textbook = textbook::draw(
                &drawing.frame,
                &scene.camera,
                &p.look,
                &scene.lighting,
                scene.texture,
            );
            let d = differences(&drawing, &textbook);
            let nearest = p.look.texture && p.look.texture_filter == Nearest;
            wrong.extend(d.wrong(nearest).map(|why| format!("{}: {why}", p.name)));
        }
    });
    assert!(
        wrong.is_empty(),
        "the textbook and the fast rasterizer differ:\n{}",
        wrong.join("\n")
    );
}

/// How two drawings of one scene differ, pixel by pixel.
#[derive(Debug, Default)]
struct Differences {
    covered: usize,
    /// Pixels one covered and the other did not.
    coverage: Vec<(u32, u32)>,
    /// Pixels whose owners differ (near ties).
    ties: usize,
    /// The largest depth difference, and where.
    depth: (f32, (u32, u32)),
    /// Where the owners agree: the largest channel difference, where, and how many pixels
    /// differ by more than `COLOUR_TOLERANCE`.
    channel: (u8, (u32, u32)),
    beyond: usize,
}

impl Differences {
    /// What is beyond the tolerances, for a scene drawn with the `nearest` filter or not.
    fn wrong(&self, nearest: bool) -> Option<String> {
        let texel_edges = if nearest { TEXEL_EDGES } else { 0.0 };
        let bad = !self.coverage.is_empty()
            || self.depth.0.is_nan()
            || self.depth.0 > DEPTH_TOLERANCE
            || self.beyond as f64 > texel_edges * self.covered as f64;
        bad.then(|| format!("{self:?}"))
    }
}

/// How the fast rasterizer's `drawing` differs from the `textbook`'s.
fn differences(drawing: &Drawing, textbook: &textbook::Buffers) -> Differences {
    let image = &drawing.image.image;
    assert_eq!(
        (image.width, image.height),
        (textbook.image.width, textbook.image.height)
    );
    let mut d = Differences::default();
    for (i, (fast, slow)) in image.pixels.iter().zip(&textbook.image.pixels).enumerate() {
        let at = (i as u32 % image.width, i as u32 / image.width);
        let owner = drawing.rasterizer.owner(at.0, at.1);
        d.covered += owner.is_some() as usize;
        if owner.is_some() != textbook.owners[i].is_some() {
            d.coverage.push(at);
        }
        let z = drawing.rasterizer.depth(at.0, at.1).unwrap_or(f32::NAN);
        let depth = (z - textbook.depth[i]).abs();
        if depth.is_nan() || depth > d.depth.0 {
            d.depth = (depth, at);
        }
        if owner != textbook.owners[i] {
            d.ties += 1;
            continue;
        }
        let channel = (0..4).map(|k| fast[k].abs_diff(slow[k])).max().unwrap_or(0);
        d.beyond += (channel > COLOUR_TOLERANCE) as usize;
        if channel > d.channel.0 {
            d.channel = (channel, at);
        }
    }
    d
}

/// The scenes hashed above are real pictures: two colours at least (model and background) in
/// the flat ones, many in the shaded and textured ones.
#[test]
fn the_pinned_scenes_are_not_blank() {
    with_scene(|scene| {
        for p in pinned() {
            let mut drawing = Drawing::default();
            drawing.draw(scene, &p.pipeline, &p.look, p.record);
            let colours = distinct_colours(&drawing.image);
            let s = &p.look;
            // Flat colour: the model's and the background (and a checker's two squares,
            // unfiltered).
            let flat = s.shading == Shading::None && (!s.texture || s.texture_filter == Nearest);
            let least = if flat { 2 } else { 50 };
            assert!(colours >= least, "{}: {colours} colours", p.name);
        }
    });
}
