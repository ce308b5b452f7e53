//! A student's Close2GL as data. A [`Program`] is what a program computes: its camera, its M, P
//! and V, how it clips and how it culls, as it declares them ([`Declared`]) and as its mistakes
//! change them ([`crate::mistakes`]; none: close2gl's own choices). [`Program::triangle`] then
//! sends one mesh triangle down the textbook's stages with those choices into any 2D system
//! (`gluOrtho2D`'s L R B T): its matrices, the division and V in double precision, the
//! clipping and the winding test in float32 as the pipeline's own (whose code they reuse), with
//! what float32 rounding could make of each number ([`crate::rounding`]). The fast path
//! never sees a mistake; a frame with one runs this, triangle by triangle (teaching models are
//! small). `close2gl check` runs it to recompute a student's frame, and with each mistake to name
//! the one that reproduces it.

use close2gl_core::{
    Camera, Clipping, FrontFace, Mesh, Mistake, PipelineSettings, RenderMode, Viewport,
};
use glam::{DMat4, DVec3};

use crate::mistakes::Mistakes;

pub mod given;
mod triangle;
pub mod view;

pub use close2gl_core::declaration::{ClipPlanes, ClipRule, ProgramCamera, System2d, WindingSpace};
pub use given::planes_mask;
pub use triangle::{DrawnCorner, TriangleOutcome};

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

    /// What close2gl's own view declares with `settings` in `viewport`: its pixels (origin
    /// top-left, y down), its culling, clipping and mode. [`Declared::onto`] goes back.
    pub fn of_view(settings: &PipelineSettings, viewport: Viewport) -> Self {
        Self::new(
            (viewport.width, viewport.height),
            System2d::pixels(viewport.width, viewport.height),
            settings.backface_culling.then_some(settings.front_face),
            match settings.clipping {
                Clipping::Simple => ClipRule::Simple,
                Clipping::Full => ClipRule::Full,
            },
            settings.mode,
        )
    }

    /// `settings` switched to this declaration's culling, clipping and mode: what close2gl's
    /// view shows of a program that declares it (one that clips nothing is shown with full
    /// clipping, the nearest close2gl draws).
    pub fn onto(&self, settings: PipelineSettings) -> PipelineSettings {
        PipelineSettings {
            mode: self.mode,
            backface_culling: self.culling.is_some(),
            front_face: self.culling.unwrap_or(FrontFace::Ccw),
            clipping: match self.clip {
                ClipRule::Simple => Clipping::Simple,
                ClipRule::Full | ClipRule::Nothing => Clipping::Full,
            },
            ..settings
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
    /// The declared rule, or `Nothing` with `no_clipping`.
    pub clip: ClipRule,
    /// `divide_before_clip`: it divides first, then drops a triangle with a corner at w = 0 or
    /// |x/w| > 1 or |y/w| > 1 (z is not tested) and draws what it keeps whole, whatever `clip`.
    pub divides_first: bool,
    pub cull: CullRule,
    pub declared: Declared,
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
        let m = given::modelview(&camera, mistakes);
        let p = given::projection(&camera, mistakes);
        let v = given::viewport(&declared.system, mistakes);
        let clip_matrix = match mistakes.has(ProductOrder) {
            true => m * p,
            false => p * m,
        };
        let clip = match mistakes.has(NoClipping) {
            true => ClipRule::Nothing,
            false => declared.clip,
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
            divides_first: mistakes.has(DivideBeforeClip),
            cull,
            declared,
        }
    }

    /// The program that draws close2gl's own view with `mistakes`: this camera and these
    /// settings, into the view's pixels (close2gl's 2D buffer: the origin top-left, y down).
    pub fn for_view(
        camera: &Camera,
        settings: &PipelineSettings,
        viewport: Viewport,
        mistakes: Mistakes,
    ) -> Self {
        let declared = Declared::of_view(settings, viewport);
        Program::new(&ProgramCamera::from(camera), declared, mistakes)
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
    pub fn frame(&self, mesh: &Mesh) -> Vec<TriangleOutcome> {
        (0..mesh.triangles.len())
            .filter_map(|t| self.triangle(mesh, t))
            .collect()
    }
}

fn opposite(front: FrontFace) -> FrontFace {
    match front {
        FrontFace::Ccw => FrontFace::Cw,
        FrontFace::Cw => FrontFace::Ccw,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The view's switches become a declaration and come back unchanged, whichever they are.
    #[test]
    fn the_views_switches_go_to_a_declaration_and_back() {
        let viewport = Viewport {
            width: 64,
            height: 48,
        };
        for i in 0..24 {
            let settings = PipelineSettings {
                backface_culling: i % 2 == 0,
                front_face: [FrontFace::Ccw, FrontFace::Cw][i / 2 % 2],
                clipping: [Clipping::Simple, Clipping::Full][i / 4 % 2],
                mode: [RenderMode::Solid, RenderMode::Wireframe, RenderMode::Points][i / 8],
                ..PipelineSettings::default()
            };
            let back = Declared::of_view(&settings, viewport).onto(PipelineSettings::default());
            let front = |s: &PipelineSettings| s.backface_culling.then_some(s.front_face);
            assert_eq!(
                (front(&back), back.clipping, back.mode),
                (front(&settings), settings.clipping, settings.mode),
                "{i}"
            );
        }
    }
}
