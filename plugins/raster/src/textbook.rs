//! The rasterizer as the textbook writes it: the place to start reading. One file, no threads,
//! no tiles, no SIMD lanes, nothing shared with the fast rasterizer ([`crate::SoftwareRasterizer`])
//! but the pipeline's output it reads. Each vertex gets its varyings (lit, for Gouraud); each
//! primitive becomes triangles (a line's and a point's rectangle are two); and for each triangle
//! every pixel of its bounding box, one at a time, is inside when its centre is inside all three
//! edges (the top-left rule settles a centre exactly on one), drawn when nearer than the depth
//! buffer, and coloured by the shading (none, Gouraud's interpolated intensity, or Phong lit at
//! the pixel) times the texel the filter finds.
//!
//! `tests/golden.rs` holds the fast rasterizer to it on every golden scene: the same pixels
//! covered, exactly (both snap the corners to 1/256 pixel and decide coverage in integers); the
//! same triangle seen wherever the depth test is not a near tie; depth within 1e-6 and each
//! colour channel within one step of 255, the rounding of f32 planes against f64 here (and a
//! nearest texel may differ where (s, t) falls exactly on a texel's edge).

use close2gl_core::{
    Appearance, Camera, Close2glFrame, Image, Lighting, RasterGeometry, Shading, Texture,
    TextureFilter, Topology,
};
use close2gl_pipeline::matrices::ClipTransform;
use glam::{Vec2, Vec3};

/// The colour, depth and owner buffers the textbook rasterizer drew, row after row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Buffers {
    pub image: Image,
    /// The depth buffer (1, the far plane, where nothing drew).
    pub depth: Vec<f32>,
    /// The mesh triangle that drew each pixel (the depth test's winner): None where none drew,
    /// and everywhere when the pipeline did not record which triangle each primitive came from.
    pub owners: Vec<Option<u32>>,
}

/// What a vertex carries to the pixels: Gouraud's intensity, Phong's eye position and normal,
/// the texture coordinates.
const INTENSITY: usize = 0;
const EYE: usize = 3;
const NORMAL: usize = 6;
const UV: usize = 9;
const VARYINGS: usize = 11;

/// A vertex: x, y in window pixels, depth and 1/w; x, y snapped (see [`snap`]); its varyings.
#[derive(Clone, Copy, Debug)]
struct Vertex {
    window: [f32; 4],
    snapped: Option<[i64; 2]>,
    varyings: [f32; VARYINGS],
}

/// Draws the pipeline's output `geometry` (made with the software rasterizer on, for `camera`)
/// as [`crate::SoftwareRasterizer::draw`] does, `texture` sampled when there is one, the
/// settings ask for it and the mesh has texture coordinates.
pub fn draw(
    geometry: &Close2glFrame,
    camera: &Camera,
    settings: &Appearance,
    lighting: &Lighting,
    texture: Option<&Texture>,
) -> Buffers {
    let raster = &geometry.raster;
    let textured = settings.texture && raster.textured;
    let shader = Shader {
        shading: settings.shading,
        color: settings.color,
        lighting: *lighting,
        light: ClipTransform::new(camera).eye(lighting.light_position),
        texture: texture
            .filter(|_| textured)
            .map(|t| Mips(t.image.mip_chain())),
        filter: settings.texture_filter,
    };
    let (width, height) = (geometry.viewport.width, geometry.viewport.height);
    let pixels = (width * height) as usize;
    let mut buffers = Buffers {
        image: Image::filled(width, height, background(settings.background)),
        depth: vec![1.0; pixels],
        owners: vec![None; pixels],
    };
    let vertices = vertex_stage(raster, &shader);
    let per_primitive = match geometry.topology {
        Topology::Triangles => 3,
        Topology::Lines => 2,
        Topology::Points => 1,
    };
    for (i, primitive) in raster.primitives.chunks_exact(per_primitive).enumerate() {
        let corners = primitive.iter().map(|&k| vertices[k as usize]);
        let owner = raster.triangles.get(i).copied();
        for triangle in triangles(&corners.collect::<Vec<_>>()) {
            draw_triangle(triangle, owner, &shader, &mut buffers);
        }
    }
    buffers
}

/// Every vertex of `raster` with its varyings: the mesh's (lit, for Gouraud), then those clipping
/// made, whose varyings are their triangle's corners' blended by their weights, as a GPU's
/// clipper blends them (a Gouraud intensity is not lit again).
fn vertex_stage(raster: &RasterGeometry, shader: &Shader) -> Vec<Vertex> {
    let gouraud = shader.shading.per_vertex();
    let mut vertices: Vec<Vertex> = (raster.vertices.iter())
        .map(|v| {
            let (eye, normal) = (Vec3::from(v.eye), Vec3::from(v.normal));
            let intensity = gouraud.then(|| shader.illumination(eye, normal));
            let mut varyings = [0.0; VARYINGS];
            varyings[INTENSITY..EYE].copy_from_slice(&intensity.unwrap_or_default().to_array());
            varyings[EYE..NORMAL].copy_from_slice(&v.eye);
            varyings[NORMAL..UV].copy_from_slice(&v.normal);
            varyings[UV..].copy_from_slice(&v.uv);
            Vertex::new(v.window, varyings)
        })
        .collect();
    for cut in &raster.cuts {
        let corner = |i: usize| &vertices[cut.corners[i] as usize].varyings;
        let varyings = std::array::from_fn(|k| (0..3).map(|i| cut.weights[i] * corner(i)[k]).sum());
        vertices.push(Vertex::new(cut.window, varyings));
    }
    vertices
}

/// Sub-pixel steps per pixel: corners are snapped to 1/256 pixel.
const STEPS: f32 = 256.0;

/// A window position snapped to 1/256 pixel, moved by half a pixel so that the centre of pixel
/// (x, y) is the integer point (256x, 256y): None when it is not finite or so far off screen
/// (beyond 2^21 pixels) that the edge functions' products would overflow i64. This decides
/// which pixel centres a triangle covers, so it is the fast rasterizer's snapping to the bit
/// (f32, rounded to nearest even): coverage on the snapped corners is then exact, in integers,
/// and the two rasterizers cover the same pixels.
fn snap(window: [f32; 4]) -> Option<[i64; 2]> {
    let far = window[..2].iter().any(|x| x.abs() > (1 << 21) as f32);
    let snap = |x: f32| ((x - 0.5) * STEPS).round_ties_even() as i64;
    (!far && window.iter().all(|x| x.is_finite())).then(|| [snap(window[0]), snap(window[1])])
}

impl Vertex {
    fn new(window: [f32; 4], varyings: [f32; VARYINGS]) -> Vertex {
        let snapped = snap(window);
        Vertex {
            window,
            snapped,
            varyings,
        }
    }

    /// The same vertex moved to the snapped position `to` (a corner of a line's or a point's
    /// rectangle), keeping its depth, 1/w and varyings.
    fn moved(&self, to: [i64; 2]) -> Vertex {
        let mut moved = *self;
        moved.window[0] = to[0] as f32 / STEPS + 0.5;
        moved.window[1] = to[1] as f32 / STEPS + 0.5;
        moved.snapped = Some(to);
        moved
    }

    /// Where it was snapped to (the origin for a vertex that could not be, never drawn).
    fn at(&self) -> [i64; 2] {
        self.snapped.unwrap_or_default()
    }
}

/// A primitive's triangles. A line is the rectangle one pixel wide around it (long sides half a
/// pixel either side, short sides through its ends) and a point the one-pixel square centred on
/// it, the shapes Vulkan's rasterizer (the reference view's) gives them; either as two triangles
/// sharing a diagonal, which the top-left rule draws each pixel of once. A primitive with a
/// corner that cannot be snapped is not drawn.
fn triangles(corners: &[Vertex]) -> Vec<[Vertex; 3]> {
    if corners.iter().any(|v| v.snapped.is_none()) {
        return Vec::new();
    }
    match *corners {
        [a, b, c] => vec![[a, b, c]],
        [a, b] => line(&a, &b),
        [v] => {
            let [x, y] = v.at().map(|p| p - 128);
            rectangle([[x, y], [x + 256, y], [x + 256, y + 256], [x, y + 256]].map(|c| v.moved(c)))
        }
        _ => Vec::new(),
    }
}

/// The rectangle one pixel wide around the line from `a` to `b`.
fn line(a: &Vertex, b: &Vertex) -> Vec<[Vertex; 3]> {
    let (dx, dy) = (a.window[0] - b.window[0], a.window[1] - b.window[1]);
    let length_squared = dx * dx + dy * dy;
    if length_squared == 0.0 || !length_squared.is_finite() {
        return Vec::new();
    }
    // Half a pixel across the line, snapped: the fast one's f32 operations, in its order, since
    // the corners decide coverage.
    let scale = 0.5 / length_squared.sqrt();
    let across = [-dy * scale * STEPS, dx * scale * STEPS].map(|d| d.round_ties_even() as i64);
    let side = |v: &Vertex, sign: i64| v.moved([0, 1].map(|k| v.at()[k] + sign * across[k]));
    rectangle([side(a, -1), side(b, -1), side(b, 1), side(a, 1)])
}

/// A rectangle as two triangles sharing the diagonal from its first corner to its third.
fn rectangle(c: [Vertex; 4]) -> Vec<[Vertex; 3]> {
    vec![[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
}

/// Twice the signed area of triangle (a, b, p): positive when p lies to the left of a → b as y
/// grows downwards. At a pixel centre p it is the edge function of a → b; divided by the
/// triangle's own, it is p's barycentric weight of the corner opposite the edge.
fn edge<T: Copy + std::ops::Sub<Output = T> + std::ops::Mul<Output = T>>(
    a: [T; 2],
    b: [T; 2],
    p: [T; 2],
) -> T {
    (b[1] - a[1]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[1] - a[1])
}

/// The top-left rule: a centre exactly on an edge is inside when the edge is a left edge (it
/// goes down, with the triangle wound as [`draw_triangle`] winds it) or a horizontal top edge
/// (it goes left), so that of two triangles sharing the edge exactly one draws the pixel.
fn top_left(a: [i64; 2], b: [i64; 2]) -> bool {
    a[1] < b[1] || (a[1] == b[1] && a[0] > b[0])
}

/// One triangle, pixel by pixel over its bounding box (within the viewport).
fn draw_triangle(mut v: [Vertex; 3], owner: Option<u32>, shader: &Shader, buffers: &mut Buffers) {
    let area = edge(v[0].at(), v[1].at(), v[2].at());
    if area == 0 {
        return;
    }
    if area < 0 {
        v.swap(1, 2); // wound so that the inside is to the left of every edge
    }
    let p = v.map(|v| v.at());
    let (width, height) = (buffers.image.width as i64, buffers.image.height as i64);
    let low = |axis: usize| (p.iter().map(|p| p[axis]).min().unwrap_or(0) / 256 - 1).max(0);
    let high = |axis: usize, size: i64| {
        (p.iter().map(|p| p[axis]).max().unwrap_or(0) / 256 + 1).min(size - 1)
    };
    for y in low(1)..=high(1, height) {
        for x in low(0)..=high(0, width) {
            if !covers(p, [x * 256, y * 256]) {
                continue;
            }
            let (at, x, y) = ((y * width + x) as usize, x as i32, y as i32);
            // Depth is affine on screen (it is z/w): the corners' depths blended; the test: less.
            let weights = barycentrics(&v, x, y);
            let z = (0..3)
                .map(|i| weights[i] * v[i].window[2] as f64)
                .sum::<f64>() as f32;
            if z < buffers.depth[at] {
                buffers.depth[at] = z;
                buffers.image.pixels[at] = shader.colour(&v, x, y);
                buffers.owners[at] = owner;
            }
        }
    }
}

/// Whether the triangle with snapped corners `p` (wound as [`draw_triangle`] winds them) covers
/// the pixel centre `centre`: inside every edge, or exactly on one the top-left rule gives it.
fn covers(p: [[i64; 2]; 3], centre: [i64; 2]) -> bool {
    (0..3).all(|i| {
        let (a, b) = (p[i], p[(i + 1) % 3]);
        let f = edge(a, b, centre);
        f > 0 || (f == 0 && top_left(a, b))
    })
}

/// The barycentric weights of the centre of pixel (x, y) (outside the triangle too), from the
/// corners where they are, unsnapped, as the fast one's planes take them; in f64, so that the
/// differences from it are its rounding, not ours.
fn barycentrics(v: &[Vertex; 3], x: i32, y: i32) -> [f64; 3] {
    let [a, b, c] = v.map(|v| [v.window[0] as f64, v.window[1] as f64]);
    let p = [x as f64 + 0.5, y as f64 + 0.5];
    let area = edge(a, b, c);
    [
        edge(b, c, p) / area,
        edge(c, a, p) / area,
        edge(a, b, p) / area,
    ]
}

/// The varyings at the centre of pixel (x, y), perspective-correct: a varying is not affine on
/// screen, but it times 1/w is, and so is 1/w; blend both, then divide.
fn varyings(v: &[Vertex; 3], x: i32, y: i32) -> [f32; VARYINGS] {
    let weights = barycentrics(v, x, y);
    let over_w = |i: usize| weights[i] * v[i].window[3] as f64;
    let sum_over_w: f64 = (0..3).map(over_w).sum();
    std::array::from_fn(|k| {
        let blend: f64 = (0..3).map(|i| over_w(i) * v[i].varyings[k] as f64).sum();
        (blend / sum_over_w) as f32
    })
}

/// The frame's shading and texture.
struct Shader {
    shading: Shading,
    color: Vec3,
    lighting: Lighting,
    /// The light's position in eye space.
    light: Vec3,
    texture: Option<Mips>,
    filter: TextureFilter,
}

impl Shader {
    /// The colour of pixel (x, y) of triangle `v`, as the target stores it.
    fn colour(&self, v: &[Vertex; 3], x: i32, y: i32) -> [u8; 4] {
        let here = varyings(v, x, y);
        let vec3 = |k: usize| Vec3::from_slice(&here[k..k + 3]);
        let colour = match self.shading {
            Shading::None => self.color,
            Shading::GouraudAd | Shading::GouraudAds => self.color * vec3(INTENSITY),
            Shading::Phong => self.color * self.illumination(vec3(EYE), vec3(NORMAL)),
        };
        let Some(mips) = &self.texture else {
            return pack(colour);
        };
        let st = |x: i32, y: i32| Vec2::from_slice(&varyings(v, x, y)[UV..]);
        let texel = match self.filter {
            TextureFilter::Nearest => mips.nearest(st(x, y)),
            TextureFilter::Bilinear => mips.bilinear(0, st(x, y)),
            TextureFilter::Trilinear => mips.trilinear(st(x, y), mips.level_of_detail(st, x, y)),
        };
        pack(colour * texel)
    }

    /// I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n), f_att = min(1 / (c0 + c1 d +
    /// c2 d²), 1), in eye space (the eye at the origin): the reference shader's formula, term
    /// for term; without the specular term for Gouraud AD.
    fn illumination(&self, eye: Vec3, normal: Vec3) -> Vec3 {
        let k = &self.lighting;
        let ks = if self.shading.specular() { k.ks } else { 0.0 };
        // Normalised without a NaN for a zero vector, as the shader's safe_normalize.
        let unit = |v: Vec3| v / v.dot(v).max(1e-30).sqrt();
        let (n, to_light) = (unit(normal), self.light - eye);
        let (l, v) = (unit(to_light), unit(-eye));
        let r = 2.0 * n.dot(l) * n - l;
        let diffuse = k.kd * n.dot(l).max(0.0);
        let specular = ks * v.dot(r).max(0.0).powf(k.shininess);
        let ([c0, c1, c2], d) = (k.attenuation, to_light.length());
        let f_att = (1.0 / (c0 + c1 * d + c2 * d * d)).min(1.0);
        k.ia * k.ka + k.il * f_att * (diffuse + specular)
    }
}

/// The background: its colour with alpha 0, which says that nothing was drawn there (the
/// views' coverage is their alpha, never their colour).
fn background(rgb: Vec3) -> [u8; 4] {
    let [r, g, b, _] = pack(rgb);
    [r, g, b, 0]
}

/// A colour in 0..1 as the RGBA8 a UNORM target stores: clamped, rounded to nearest.
fn pack(rgb: Vec3) -> [u8; 4] {
    let byte = |c: f32| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    [byte(rgb.x), byte(rgb.y), byte(rgb.z), 255]
}

/// The texture's mipmap chain, level 0 first, each level half the one before. Wrap mode:
/// repeat; t grows upwards, and an image's rows run from the top.
struct Mips(Vec<Image>);

impl Mips {
    /// The texel in column x, row y of `level`, wrapped, as 0..1 per channel.
    fn texel(&self, level: usize, x: f32, y: f32) -> Vec3 {
        let image = &self.0[level];
        // Clamped first, so that far-off (or NaN) coordinates wrap without overflow.
        let wrap = |i: f32, n: u32| (i.clamp(-1e9, 1e9) as i64).rem_euclid(n as i64) as usize;
        let [r, g, b, _] =
            image.pixels[wrap(y, image.height) * image.width as usize + wrap(x, image.width)];
        Vec3::new(r as f32, g as f32, b as f32) / 255.0
    }

    /// Where (s, t) falls in `level`, in texels from its top-left corner.
    fn position(&self, level: usize, st: Vec2) -> Vec2 {
        let size = Vec2::new(self.0[level].width as f32, self.0[level].height as f32);
        Vec2::new(st.x, 1.0 - st.y) * size
    }

    /// The texel (s, t) falls in, at level 0.
    fn nearest(&self, st: Vec2) -> Vec3 {
        let p = self.position(0, st).floor();
        self.texel(0, p.x, p.y)
    }

    /// The four texels of `level` whose centres surround (s, t), weighted by nearness.
    fn bilinear(&self, level: usize, st: Vec2) -> Vec3 {
        let p = self.position(level, st) - 0.5;
        let (corner, f) = (p.floor(), p - p.floor());
        let texel = |dx: f32, dy: f32| self.texel(level, corner.x + dx, corner.y + dy);
        let upper = texel(0.0, 0.0).lerp(texel(1.0, 0.0), f.x);
        let lower = texel(0.0, 1.0).lerp(texel(1.0, 1.0), f.x);
        upper.lerp(lower, f.y)
    }

    /// Bilinear in the two levels around `lod`, blended by its fraction: level 0 when magnified
    /// (or when the footprint is not a number), the last level beyond it.
    fn trilinear(&self, st: Vec2, lod: f32) -> Vec3 {
        let top = (self.0.len() - 1) as f32;
        let lod = lod.max(0.0).min(top);
        let below = lod.floor();
        let near = self.bilinear(below as usize, st);
        let far = self.bilinear((below + 1.0).min(top) as usize, st);
        near.lerp(far, lod - below)
    }

    /// log2 of the pixel's footprint in level-0 texels: the longer of the steps of (s, t) across
    /// and down the 2×2 quad of pixels it is in (from an even column and row), as GPUs take it,
    /// whether or not the triangle covers the quad's other pixels.
    fn level_of_detail(&self, st: impl Fn(i32, i32) -> Vec2, x: i32, y: i32) -> f32 {
        let size = Vec2::new(self.0[0].width as f32, self.0[0].height as f32);
        let (left, top) = (x & !1, y & !1);
        let corner = st(left, top);
        let across = (st(left + 1, top) - corner) * size;
        let down = (st(left, top + 1) - corner) * size;
        across.length().max(down.length()).log2()
    }
}
