//! The classic mistakes of the assignment, as data beside the textbook's stages. A [`Program`]
//! is what a student's Close2GL computes: its camera, its M, P and V, how it clips and how it
//! culls, each chosen by the mistakes it makes (none: close2gl's own choices). [`Program::triangle`]
//! then sends one mesh triangle down the textbook's stages with those choices, in double
//! precision, into any 2D system (`gluOrtho2D`'s L R B T), reusing the pipeline's own clipping
//! and culling. The fast path never sees a mistake; a frame with one runs this, triangle by
//! triangle (teaching models are small). `close2gl check` runs it to recompute a student's
//! frame, and with each mistake to name the one that reproduces it.
//!
//! Where a mistake's one-line meaning leaves a choice open, `trace-format.md` pins it; the
//! comments below quote those choices.

use close2gl_core::{
    Camera, Clipping, FateKind, FrontFace, Mesh, Mistake, RenderMode, RenderSettings, TriangleFate,
    Viewport,
};
use glam::{DMat3, DMat4, DVec2, DVec3, DVec4};

use crate::clip::{FAR, NEAR, Outcode, Polygon, clip_polygon, outcode};
use crate::rounding;
use crate::stage::face;

/// A set of mistakes (at most a few at once: diagnosis tries each one and each pair).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Mistakes(u32);

impl Mistakes {
    pub const NONE: Mistakes = Mistakes(0);

    pub fn one(mistake: Mistake) -> Self {
        Self::NONE.with(mistake)
    }

    /// This set and `mistake` (`Mistake::None` adds nothing).
    pub fn with(self, mistake: Mistake) -> Self {
        match mistake {
            Mistake::None => self,
            m => Mistakes(self.0 | 1 << m as u32),
        }
    }

    pub fn has(self, mistake: Mistake) -> bool {
        mistake != Mistake::None && self.0 & (1 << mistake as u32) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The mistakes in the set, in the catalogue's order.
    pub fn iter(self) -> impl Iterator<Item = Mistake> {
        Mistake::ALL.iter().copied().filter(move |&m| self.has(m))
    }

    /// The catalogue's ids, joined with " + " ("none" for the empty set).
    pub fn names(self) -> String {
        let names: Vec<&str> = self.iter().map(Mistake::name).collect();
        match names.is_empty() {
            true => "none".into(),
            false => names.join(" + "),
        }
    }

    /// Every mistake alone, then every pair that can be made at once (two culling rules that
    /// each replace the winding test, or two clipping rules, cannot).
    pub fn singles_and_pairs() -> Vec<Mistakes> {
        let all = &Mistake::ALL[1..];
        let mut sets: Vec<Mistakes> = all.iter().map(|&m| Mistakes::one(m)).collect();
        for (i, &a) in all.iter().enumerate() {
            for &b in &all[i + 1..] {
                if !excludes(a, b) {
                    sets.push(Mistakes::one(a).with(b));
                }
            }
        }
        sets
    }
}

/// Two mistakes that each replace the same decision, so that no program makes both: the test
/// that decides a back face, the front winding, or the clipping rule. A program that never
/// culls makes no other culling mistake.
fn excludes(a: Mistake, b: Mistake) -> bool {
    use Mistake::{
        CullingByFileNormals, CullingByViewAxis, CullingIgnoresFrontFace, CullingInverted,
        DivideBeforeClip, NeverCulls, NoClipping,
    };
    let replaces = |m: Mistake| match m {
        CullingByFileNormals | CullingByViewAxis => 1,
        DivideBeforeClip | NoClipping => 2,
        CullingInverted | CullingIgnoresFrontFace => 3,
        _ => 0,
    };
    let culling = |m: Mistake| replaces(m) == 1 || replaces(m) == 3;
    (replaces(a) != 0 && replaces(a) == replaces(b))
        || (a == NeverCulls && culling(b))
        || (b == NeverCulls && culling(a))
}

/// The 2D system the program draws in: the arguments it gave `gluOrtho2D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct System2d {
    pub left: f64,
    pub right: f64,
    pub bottom: f64,
    pub top: f64,
}

impl System2d {
    /// OpenGL's window coordinates, `0 W 0 H`: the origin bottom-left, y up.
    pub fn gl_window(width: u32, height: u32) -> Self {
        Self {
            left: 0.0,
            right: f64::from(width),
            bottom: 0.0,
            top: f64::from(height),
        }
    }

    /// Window pixels as close2gl's 2D buffer holds them, `0 W H 0`: the origin top-left, y down.
    pub fn pixels(width: u32, height: u32) -> Self {
        Self {
            left: 0.0,
            right: f64::from(width),
            bottom: f64::from(height),
            top: 0.0,
        }
    }

    /// A point of this system in window pixels (origin top-left, y down) of a `width` ×
    /// `height` window: where it shows on screen, whichever way the system's axes run.
    pub fn to_pixels(&self, p: DVec2, width: u32, height: u32) -> DVec2 {
        DVec2::new(
            (p.x - self.left) / (self.right - self.left) * f64::from(width),
            (self.top - p.y) / (self.top - self.bottom) * f64::from(height),
        )
    }
}

/// The camera as the program holds it, in double precision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProgramCamera {
    pub position: DVec3,
    pub u: DVec3,
    pub v: DVec3,
    pub n: DVec3,
    pub hfov: f64,
    pub vfov: f64,
    pub near: f64,
    pub far: f64,
}

impl From<&Camera> for ProgramCamera {
    fn from(c: &Camera) -> Self {
        Self {
            position: c.position.as_dvec3(),
            u: c.u.as_dvec3(),
            v: c.v.as_dvec3(),
            n: c.n.as_dvec3(),
            hfov: f64::from(c.hfov),
            vfov: f64::from(c.vfov),
            near: f64::from(c.near),
            far: f64::from(c.far),
        }
    }
}

/// How the program clips.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClipRule {
    /// The assignment's: drop a triangle with any corner outside the view volume.
    Simple,
    /// Cut against the six planes, as a GPU does.
    Full,
    /// Nothing clipped, but a corner at w = 0 exactly (no division is possible).
    Nothing,
    /// `divide_before_clip`: divide first, then drop a triangle with a corner at w = 0 or
    /// |x/w| > 1 or |y/w| > 1; z is not tested, and what is kept is drawn whole.
    DivideFirst,
}

/// How the program culls, and which winding (or side) is front.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CullRule {
    Off,
    /// By the winding of its 2D output as seen on screen (close2gl's rule).
    Winding(FrontFace),
    /// `culling_by_file_normals`: back when N_T · (c − p0) < 0 (reversed for cw).
    FileNormals(FrontFace),
    /// `culling_by_view_axis`: back when ((p1 − p0) × (p2 − p0)) · n < 0 (reversed for cw).
    ViewAxis(FrontFace),
}

/// Where a program tests a triangle's winding (`trace-format.md`, culling's space).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WindingSpace {
    /// As seen on screen (version 1's `culling ccw`): the 2D output mapped to the window.
    Screen,
    /// NDC x, y, y up, before V: a mistake in V does not change it.
    Ndc,
    /// The 2D output's own numbers (x right, y growing upward in the numbers): with a y-down
    /// system, the mirror of the screen.
    Window,
}

impl WindingSpace {
    pub const ALL: [WindingSpace; 3] = [Self::Screen, Self::Ndc, Self::Window];
}

/// Which planes the program clips against itself.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ClipPlanes {
    /// All six.
    #[default]
    All,
    /// Near and far only: x and y are left to the 2D rasteriser, which cuts at the window.
    NearFar,
}

impl ClipPlanes {
    fn mask(self) -> Outcode {
        match self {
            ClipPlanes::All => 0x3f,
            ClipPlanes::NearFar => NEAR | FAR,
        }
    }
}

/// What the program is told to do, or says it did: the settings a scene or a trace declares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Declared {
    pub window: (u32, u32),
    pub system: System2d,
    /// None: culling off.
    pub culling: Option<FrontFace>,
    /// Where the winding is tested.
    pub winding: WindingSpace,
    pub clip: ClipRule,
    pub planes: ClipPlanes,
    pub mode: RenderMode,
    /// The model matrix the program applies before M: world = model·p.
    pub model: DMat4,
}

impl Declared {
    /// What a program is told when only these are said: winding as seen on screen, all six
    /// planes clipped, no model matrix.
    pub fn new(
        window: (u32, u32),
        system: System2d,
        culling: Option<FrontFace>,
        clip: ClipRule,
        mode: RenderMode,
    ) -> Self {
        Self {
            window,
            system,
            culling,
            winding: WindingSpace::Screen,
            clip,
            planes: ClipPlanes::All,
            mode,
            model: DMat4::IDENTITY,
        }
    }
}

/// A program's Close2GL: what it computes from a camera, with its mistakes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Program {
    pub mistakes: Mistakes,
    /// The camera it uses (`left_handed` makes u = n × v).
    pub camera: ProgramCamera,
    pub m: DMat4,
    pub p: DMat4,
    /// V into the declared 2D system (its third row maps depth to 0..1).
    pub v: DMat4,
    /// What takes a world point to clip coordinates: P·M (or M·P, with `product_order`).
    pub clip_matrix: DMat4,
    pub clip: ClipRule,
    pub cull: CullRule,
    pub declared: Declared,
}

/// A matrix from its rows, so the code reads like the printed matrices.
pub fn from_rows(rows: [[f64; 4]; 4]) -> DMat4 {
    DMat4::from_cols_array_2d(&rows).transpose()
}

impl Program {
    pub fn new(camera: &ProgramCamera, declared: Declared, mistakes: Mistakes) -> Self {
        use Mistake::{
            CullingByFileNormals, CullingByViewAxis, CullingIgnoresFrontFace, CullingInverted,
            DivideBeforeClip, LeftHanded, NeverCulls, NoClipping, ProductOrder,
        };
        let mut camera = *camera;
        if mistakes.has(LeftHanded) {
            camera.u = camera.n.cross(camera.v);
        }
        let m = modelview(&camera, mistakes);
        let p = projection(&camera, mistakes);
        let v = viewport(&declared.system, mistakes);
        let clip_matrix = match mistakes.has(ProductOrder) {
            true => m * p,
            false => p * m,
        };
        let clip = match () {
            _ if mistakes.has(DivideBeforeClip) => ClipRule::DivideFirst,
            _ if mistakes.has(NoClipping) => ClipRule::Nothing,
            _ => declared.clip,
        };
        let cull = match declared.culling {
            None => CullRule::Off,
            Some(_) if mistakes.has(NeverCulls) => CullRule::Off,
            Some(front) => {
                let front = match () {
                    _ if mistakes.has(CullingInverted) => opposite(front),
                    _ if mistakes.has(CullingIgnoresFrontFace) => FrontFace::Ccw,
                    _ => front,
                };
                match () {
                    _ if mistakes.has(CullingByFileNormals) => CullRule::FileNormals(front),
                    _ if mistakes.has(CullingByViewAxis) => CullRule::ViewAxis(front),
                    _ => CullRule::Winding(front),
                }
            }
        };
        Self {
            mistakes,
            camera,
            m,
            p,
            v,
            clip_matrix,
            clip,
            cull,
            declared,
        }
    }

    /// The program that draws close2gl's own view with `mistakes`: this camera and these
    /// settings, into the view's pixels (close2gl's 2D buffer: the origin top-left, y down).
    pub fn for_view(
        camera: &Camera,
        settings: &RenderSettings,
        viewport: Viewport,
        mistakes: Mistakes,
    ) -> Self {
        let declared = Declared::new(
            (viewport.width, viewport.height),
            System2d::pixels(viewport.width, viewport.height),
            settings.backface_culling.then_some(settings.front_face),
            match settings.clipping {
                Clipping::Simple => ClipRule::Simple,
                Clipping::Full => ClipRule::Full,
            },
            settings.mode,
        );
        Program::new(&ProgramCamera::from(camera), declared, mistakes)
    }

    /// Mesh triangle `index` down the stages: its clip coordinates, its fate, and what it drew.
    /// None when the mesh has no such triangle.
    pub fn triangle(&self, mesh: &Mesh, index: usize) -> Option<Outcome> {
        let corners = *mesh.triangles.get(index)?;
        let world = corners.map(|i| self.world(mesh, i));
        let clip = world.map(|p| self.clip_matrix * p.extend(1.0));
        let terms = rounding::clip_terms(self.clip_matrix, self.camera.position, &world);
        let mut outcome = Outcome {
            clip,
            fate: TriangleFate::default(),
            polygon: Vec::new(),
            depths: Vec::new(),
            edges: Vec::new(),
            weights: Vec::new(),
            inv_w: Vec::new(),
            near_a_plane: rounding::near_a_plane(&clip, terms),
            near_edge_on: false,
            terms,
            errors: Vec::new(),
            depth_errors: Vec::new(),
        };
        let Some(piece) = self.clipped(&clip, &mut outcome) else {
            return Some(outcome);
        };
        let ndc: Vec<DVec3> = piece.iter().map(|p| p.truncate() / p.w).collect();
        let system: Vec<DVec2> = ndc
            .iter()
            .map(|p| (self.v * p.extend(1.0)).truncate().truncate())
            .collect();
        if system.iter().any(|p| !p.is_finite()) {
            outcome.fate.kind = FateKind::Clipped;
            return Some(outcome);
        }
        let (w, h) = self.declared.window;
        let pixels: Vec<[f32; 2]> = system
            .iter()
            .map(|&p| {
                let px = self.declared.system.to_pixels(p, w, h);
                [px.x as f32, px.y as f32]
            })
            .collect();
        let tested: Vec<[f32; 2]> = match self.declared.winding {
            WindingSpace::Screen => pixels.clone(),
            // The facing test reads y down, as the window's pixels: y up is negated for it.
            WindingSpace::Ndc => ndc.iter().map(|p| [p.x as f32, -p.y as f32]).collect(),
            WindingSpace::Window => system.iter().map(|p| [p.x as f32, -p.y as f32]).collect(),
        };
        outcome.errors = piece
            .iter()
            .zip(&system)
            .map(|(&c, &p)| rounding::window_error(self.v, terms, c, p))
            .collect();
        let (area, culled) = self.cull(mesh, index, &world, [&pixels, &tested], &mut outcome);
        let uncertain = rounding::twice_area_error(&system, &outcome.errors);
        outcome.near_edge_on |= rounding::twice_area(&system).abs() <= uncertain;
        outcome.fate.signed_area = area;
        if let Some(kind) = culled {
            outcome.fate.kind = kind;
            return Some(outcome);
        }
        outcome.fate.kind = match outcome.fate.planes {
            0 => FateKind::Drawn,
            _ => FateKind::Cut,
        };
        outcome.depths = ndc.iter().map(|p| p.z).collect();
        outcome.depth_errors = piece
            .iter()
            .map(|&c| rounding::depth_error(terms, c))
            .collect();
        outcome.inv_w = piece.iter().map(|p| 1.0 / p.w).collect();
        outcome.polygon = system;
        Some(outcome)
    }

    /// Mesh vertex `i` in world coordinates: the model matrix applied to the file's position.
    pub fn world(&self, mesh: &Mesh, i: u32) -> DVec3 {
        let p = mesh.positions[i as usize].as_dvec3();
        match self.declared.model == DMat4::IDENTITY {
            true => p,
            false => self.declared.model.transform_point3(p),
        }
    }

    /// Every triangle of `mesh`, in order.
    pub fn frame(&self, mesh: &Mesh) -> Vec<Outcome> {
        (0..mesh.triangles.len())
            .filter_map(|t| self.triangle(mesh, t))
            .collect()
    }

    /// The clip rule: the polygon to divide (clip coordinates) and, in `outcome`, which planes
    /// cut it and which of its edges are the triangle's own; None when the triangle is removed
    /// whole (its fate then says why).
    fn clipped(&self, clip: &[DVec4; 3], outcome: &mut Outcome) -> Option<Vec<DVec4>> {
        let single = clip.map(|c| c.as_vec4());
        let mask = self.declared.planes.mask();
        let codes = single.map(|c| outcode(c) & mask);
        let (any, all) = (
            codes[0] | codes[1] | codes[2],
            codes[0] & codes[1] & codes[2],
        );
        let whole = |outcome: &mut Outcome| {
            outcome.edges = vec![true; 3];
            outcome.weights = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
            Some(clip.to_vec())
        };
        let removed = |outcome: &mut Outcome, planes: u8| {
            outcome.fate.kind = FateKind::Clipped;
            outcome.fate.planes = planes;
            outcome.fate.behind_eye = clip.iter().all(|c| c.w <= 0.0);
            None
        };
        match self.clip {
            ClipRule::Nothing if clip.iter().any(|c| c.w == 0.0) => removed(outcome, NEAR),
            ClipRule::Nothing => whole(outcome),
            ClipRule::DivideFirst => {
                let outside =
                    |c: &DVec4| c.w == 0.0 || (c.x / c.w).abs() > 1.0 || (c.y / c.w).abs() > 1.0;
                match clip.iter().any(outside) {
                    true => removed(outcome, any),
                    false => whole(outcome),
                }
            }
            _ if any == 0 => whole(outcome),
            ClipRule::Simple => removed(outcome, any),
            _ if all != 0 => removed(outcome, all),
            ClipRule::Full => {
                let piece = clip_polygon(&Polygon::triangle(single[0], single[1], single[2]), any);
                if piece.len < 3 {
                    return removed(outcome, any);
                }
                outcome.fate.planes = any;
                outcome.edges = piece.original[..piece.len].to_vec();
                outcome.weights = piece.weights[..piece.len]
                    .iter()
                    .map(|w| w.to_array())
                    .collect();
                Some(piece.vertices().iter().map(|p| p.as_dvec4()).collect())
            }
        }
    }

    /// The cull rule: twice the signed window area (y down, as the pipeline's) and, when the
    /// triangle is culled, why. `tested`: the piece's corners where the program tests the
    /// winding (y down), `pixels` on screen.
    fn cull(
        &self,
        mesh: &Mesh,
        index: usize,
        world: &[DVec3; 3],
        [pixels, tested]: [&[[f32; 2]]; 2],
        outcome: &mut Outcome,
    ) -> (f32, Option<FateKind>) {
        let (_, winding) = face::<true>(
            tested,
            match self.cull {
                CullRule::Winding(front) => Some(front),
                _ => None,
            },
        );
        let area = face::<true>(pixels, None).0;
        let mut side = |normal: DVec3, towards: DVec3, front: FrontFace| {
            let dot = normal.dot(towards);
            outcome.near_edge_on = dot.abs() <= rounding::dot_error(normal, towards);
            let back = match front {
                FrontFace::Ccw => dot < 0.0,
                FrontFace::Cw => dot > 0.0,
            };
            back.then_some(FateKind::Culled)
        };
        let culled = match self.cull {
            CullRule::Off => None,
            CullRule::Winding(_) => winding,
            CullRule::FileNormals(front) => {
                let normal = file_normal(mesh, index, self.declared.model);
                side(normal, self.camera.position - world[0], front)
            }
            CullRule::ViewAxis(front) => {
                let normal = (world[1] - world[0]).cross(world[2] - world[0]);
                side(normal, self.camera.n, front)
            }
        };
        (area, culled)
    }
}

/// What one mesh triangle became in a program's Close2GL.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Its corners' clip coordinates, before clipping.
    pub clip: [DVec4; 3],
    /// Drawn, cut, clipped, culled or zero_area, with the planes and the signed area (the
    /// pipeline's record; never no_pixels or hidden, which only a rasterizer knows).
    pub fate: TriangleFate,
    /// What it drew, in the declared 2D system: the triangle, or the polygon clipping left of
    /// it; empty when it drew nothing.
    pub polygon: Vec<DVec2>,
    /// The NDC depth (z/w) of each vertex of `polygon`.
    pub depths: Vec<f64>,
    /// Whether the edge from vertex i to i + 1 is part of one of the triangle's own edges
    /// (wireframe draws only those); one per vertex of `polygon`.
    pub edges: Vec<bool>,
    /// Where each vertex of `polygon` lies in the triangle: its corners' weights.
    pub weights: Vec<[f32; 3]>,
    /// 1/w of each vertex of `polygon`, for perspective-correct interpolation.
    pub inv_w: Vec<f64>,
    /// A corner lies on a plane of the view volume to rounding: whether it is inside is for the
    /// program's rounding to say, and either clipping decision is right.
    pub near_a_plane: bool,
    /// The facing test's value is rounding (seen edge-on): either culling decision is right.
    pub near_edge_on: bool,
    /// The magnitude of the terms each row of its clip coordinates sums
    /// ([`rounding::clip_terms`]): what a float32 program's rounding scales with.
    pub terms: DVec4,
    /// How far a float32 program may put each vertex of `polygon`, in the 2D system's units
    /// ([`rounding::window_error`]).
    pub errors: Vec<f64>,
    /// How far its NDC depth at each vertex of `polygon` may be off.
    pub depth_errors: Vec<f64>,
}

impl Outcome {
    /// Whether it drew anything.
    pub fn drawn(&self) -> bool {
        !self.polygon.is_empty()
    }
}

/// The file's face normal of triangle `index`; for a model without them (an OBJ), the mean of
/// its three corner normals, as `trace-format.md` pins it. A model matrix turns it by its
/// inverse transpose, as normals turn.
fn file_normal(mesh: &Mesh, index: usize, model: DMat4) -> DVec3 {
    let normal = file_normal_as_read(mesh, index);
    match model == DMat4::IDENTITY {
        true => normal,
        false => DMat3::from_mat4(model).inverse().transpose() * normal,
    }
}

fn file_normal_as_read(mesh: &Mesh, index: usize) -> DVec3 {
    match mesh.face_normals.get(index) {
        Some(normal) => normal.as_dvec3(),
        None => {
            mesh.triangles[index]
                .iter()
                .map(|&i| mesh.normals[i as usize].as_dvec3())
                .sum::<DVec3>()
                / 3.0
        }
    }
}

fn opposite(front: FrontFace) -> FrontFace {
    match front {
        FrontFace::Ccw => FrontFace::Cw,
        FrontFace::Cw => FrontFace::Ccw,
    }
}

/// M: rows u, v, n and the translation −c·(u, v, n); or what the mistakes make of it.
pub fn modelview(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    let (u, v, n, c) = (camera.u, camera.v, camera.n, camera.position);
    let mut t = match mistakes.has(Mistake::TranslationUnrotated) {
        true => -c,
        false => DVec3::new(-c.dot(u), -c.dot(v), -c.dot(n)),
    };
    if mistakes.has(Mistake::TranslationSign) {
        t = -t;
    }
    let m = from_rows([
        [u.x, u.y, u.z, t.x],
        [v.x, v.y, v.z, t.y],
        [n.x, n.y, n.z, t.z],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    match mistakes.has(Mistake::ModelviewTransposed) {
        true => m.transpose(),
        false => m,
    }
}

/// P: glFrustum for right = near·tan(hfov/2), top = near·tan(vfov/2); or what the mistakes
/// make of those extents and of the depth row.
pub fn projection(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    use Mistake::{AspectFromAngles, DepthRowSign, FovInDegrees, FovNotHalved, FovsSwapped};
    let (h, v) = match mistakes.has(FovsSwapped) {
        true => (camera.vfov, camera.hfov),
        false => (camera.hfov, camera.vfov),
    };
    let angle = |degrees: f64| {
        let radians = match mistakes.has(FovInDegrees) {
            true => degrees,
            false => degrees.to_radians(),
        };
        match mistakes.has(FovNotHalved) {
            true => radians,
            false => radians * 0.5,
        }
    };
    let (near, far) = (camera.near, camera.far);
    let top = near * angle(v).tan();
    let right = match mistakes.has(AspectFromAngles) {
        true => top * h / v,
        false => near * angle(h).tan(),
    };
    let depth = match mistakes.has(DepthRowSign) {
        true => -1.0,
        false => 1.0,
    };
    from_rows([
        [near / right, 0.0, 0.0, 0.0],
        [0.0, near / top, 0.0, 0.0],
        [
            0.0,
            0.0,
            depth * -(far + near) / (far - near),
            depth * -2.0 * far * near / (far - near),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// V: NDC onto the 2D system, x' = x·(R−L)/2 + (R+L)/2, y' = y·(T−B)/2 + (T+B)/2, and depth
/// onto 0..1; or what the mistakes make of the scales.
pub fn viewport(system: &System2d, mistakes: Mistakes) -> DMat4 {
    let half = match mistakes.has(Mistake::ViewportFullScale) {
        true => 1.0,
        false => 0.5,
    };
    let flip = match mistakes.has(Mistake::ViewportYFlipped) {
        true => -1.0,
        false => 1.0,
    };
    let System2d {
        left,
        right,
        bottom,
        top,
    } = *system;
    from_rows([
        [(right - left) * half, 0.0, 0.0, (right + left) / 2.0],
        [0.0, flip * (top - bottom) * half, 0.0, (top + bottom) / 2.0],
        [0.0, 0.0, 0.5, 0.5],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{random_triangles, textbook};
    use close2gl_core::Clipping;
    use glam::Vec3;

    /// Without mistakes, the program is close2gl's pipeline: for random triangles around a
    /// camera (many cut by the near and side planes), the same fate as the textbook path, and
    /// the same polygon to a hundredth of a pixel (the textbook path rounds P·M to float32),
    /// wherever rounding cannot tell.
    #[test]
    fn without_mistakes_it_draws_what_the_textbook_path_draws() {
        let camera = random_triangles::camera(Vec3::new(0.5, 0.2, 6.0));
        let viewport = random_triangles::VIEWPORT;
        for (i, mesh) in random_triangles::triangles(0x2545_f491_4f6c_dd1d, 3000).enumerate() {
            let settings = RenderSettings {
                backface_culling: i % 2 == 0,
                clipping: if i % 3 == 0 {
                    Clipping::Simple
                } else {
                    Clipping::Full
                },
                ..RenderSettings::default()
            };
            let (frame, fates) = textbook::run_recording(&mesh, &camera, &settings, viewport);
            let program = Program::for_view(&camera, &settings, viewport, Mistakes::NONE);
            let outcome = program.triangle(&mesh, 0).expect("triangle 0");
            if outcome.near_a_plane || outcome.near_edge_on {
                continue;
            }
            assert_eq!(outcome.fate.kind, fates.triangles[0].kind, "{i}");
            let fan: Vec<[f32; 2]> = emitted_fan(&outcome);
            assert_eq!(fan.len(), frame.vertices.len(), "{i}");
            for (a, b) in fan.iter().zip(&frame.vertices) {
                let close = |x: f32, y: f32| (x - y).abs() < 1e-2 + 1e-5 * y.abs();
                assert!(close(a[0], b[0]) && close(a[1], b[1]), "{i}: {a:?} {b:?}");
            }
        }
    }

    fn emitted_fan(outcome: &Outcome) -> Vec<[f32; 2]> {
        let p = &outcome.polygon;
        (1..p.len().saturating_sub(1))
            .flat_map(|i| [p[0], p[i], p[i + 1]])
            .map(|q| [q.x as f32, q.y as f32])
            .collect()
    }

    #[test]
    fn pairs_leave_out_two_rules_for_one_decision() {
        let sets = Mistakes::singles_and_pairs();
        let singles = Mistake::ALL.len() - 1;
        let both = |a, b| Mistakes::one(a).with(b);
        assert!(!sets.contains(&both(Mistake::DivideBeforeClip, Mistake::NoClipping)));
        assert!(!sets.contains(&both(
            Mistake::CullingByFileNormals,
            Mistake::CullingByViewAxis
        )));
        assert!(!sets.contains(&both(Mistake::NeverCulls, Mistake::CullingInverted)));
        assert!(sets.contains(&both(Mistake::FovNotHalved, Mistake::CullingInverted)));
        assert!(sets.contains(&both(Mistake::NeverCulls, Mistake::LeftHanded)));
        // Three pairs of rules for one decision, and never culling with four culling rules.
        assert_eq!(sets.len(), singles + singles * (singles - 1) / 2 - 3 - 4);
    }
}
