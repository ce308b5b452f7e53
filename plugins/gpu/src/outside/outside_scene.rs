//! What the outside view draws, placed at the stage on the CPU by the pipeline's own
//! [`StageMorph`]: the model's triangles (each corner with its clip coordinates, for the
//! per-fragment inside test), the lines (the view volume's edges, the window's outline on the
//! near plane, the camera's u, v, n axes and their letters) and the translucent near and far
//! planes. The buffers are kept and refilled, so a frame allocates nothing once they are big
//! enough.

use bytemuck::{Pod, Zeroable};
use close2gl_core::{Appearance, Camera, FateKind, Fates, Mesh, Overlay};
use close2gl_pipeline::frustum::{EDGES, world_corners};
use close2gl_pipeline::morph::{OutsideFraming, Placed, StageMorph, has_image};
use glam::Vec3;

use close2gl_core::parity::to_rgb8;

/// One vertex of outside.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct OutsideVertex {
    position: [f32; 3],
    /// Clip coordinates times `weight_warn[0]`.
    clip: [f32; 4],
    weight_warn: [f32; 2],
    color: [u8; 4],
}

/// The colours of the volume and the gizmo.
const EDGE: [u8; 4] = [220, 220, 230, 255];
const WINDOW: [u8; 4] = [255, 210, 60, 255];
const NEAR_FACE: [u8; 4] = [255, 210, 60, 60];
const FAR_FACE: [u8; 4] = [110, 150, 255, 45];
/// The far face when it lies far beyond the model: a faint mark of where the volume ends.
const FAR_FACE_FADED: [u8; 4] = [110, 150, 255, 12];
const AXES: [[u8; 4]; 3] = [[240, 80, 70, 255], [90, 220, 90, 255], [90, 140, 255, 255]];

/// The letters u, v, n as strokes in a unit box (x right, y up), drawn by the axes' tips.
const LETTERS: [&[[f32; 2]]; 3] = [
    &[[0.0, 1.0], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0]],
    &[[0.0, 1.0], [0.5, 0.0], [1.0, 1.0]],
    &[[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]],
];

impl OutsideVertex {
    /// A vertex the inside test passes (its clip coordinates are the cube's centre).
    fn plain(position: Vec3, warn: bool, color: [u8; 4]) -> Self {
        Self {
            position: position.to_array(),
            clip: [0.0, 0.0, 0.0, 1.0],
            weight_warn: [1.0, f32::from(u8::from(warn))],
            color,
        }
    }

    /// A model vertex: its clip coordinates weighted for the stage's interpolation.
    fn of(placed: &Placed, stage: f32, color: [u8; 4]) -> Self {
        let w = placed.clip.w;
        // Towards the NDC stop the drawn space is the divided one: interpolating clip/w and 1/w
        // across it and dividing gives each fragment its own clip coordinates again.
        let weight = if stage > 1.0 && w > 0.0 {
            1.0 + (1.0 / w - 1.0) * (stage - 1.0)
        } else {
            1.0
        };
        Self {
            position: placed.position.to_array(),
            clip: (placed.clip * weight).to_array(),
            weight_warn: [weight, f32::from(u8::from(placed.behind_eye))],
            color,
        }
    }
}

/// The outside camera's right and up directions, for the letters that face it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Billboard {
    pub right: Vec3,
    pub up: Vec3,
}

/// The three vertex lists of one frame, and the frame they were placed in.
#[derive(Default)]
pub(crate) struct OutsideScene {
    pub mesh: Vec<OutsideVertex>,
    pub lines: Vec<OutsideVertex>,
    pub faces: Vec<OutsideVertex>,
    placed: Vec<Placed>,
}

/// What one scene is built from.
pub(crate) struct SceneInput<'a> {
    pub camera: &'a Camera,
    pub mesh: &'a Mesh,
    pub look: &'a Appearance,
    pub overlay: Overlay,
    pub fates: &'a Fates,
    pub frame: &'a OutsideFraming,
    pub stage: f32,
    pub billboard: Billboard,
}

impl OutsideScene {
    pub(crate) fn build(&mut self, input: &SceneInput) {
        let morph = StageMorph::new(input.camera, input.frame, input.stage);
        self.build_mesh(input, &morph);
        self.build_volume(input, &morph);
        self.build_gizmo(input, &morph);
    }

    /// Each triangle's corners, in its fate's colour when the fate view is on and the last
    /// frame recorded every triangle's fate, else in the model's colour.
    fn build_mesh(&mut self, input: &SceneInput, morph: &StageMorph) {
        let mesh = input.mesh;
        self.placed.clear();
        self.placed
            .extend(mesh.positions.iter().map(|p| morph.place(*p)));
        let fates = Some(input.fates).filter(|f| {
            input.overlay == Overlay::FateView && f.triangles.len() == mesh.triangles.len()
        });
        let model = rgba(input.look.color);
        self.mesh.clear();
        for (t, corners) in mesh.triangles.iter().enumerate() {
            let corners = corners.map(|i| self.placed[i as usize]);
            if !has_image(&corners) {
                continue;
            }
            let color = fates.map_or(model, |f| fate_color(f.triangles[t].kind));
            for placed in &corners {
                self.mesh
                    .push(OutsideVertex::of(placed, input.stage, color));
            }
        }
    }

    /// The twelve edges (the near face's four, the window's outline, in their own colour) and
    /// the near and far faces as two translucent quads (the far one fainter when it lies far
    /// beyond the model).
    fn build_volume(&mut self, input: &SceneInput, morph: &StageMorph) {
        let corners = world_corners(input.camera).map(|c| morph.place(c));
        self.lines.clear();
        for (e, [a, b]) in EDGES.iter().enumerate() {
            let color = if e < 4 { WINDOW } else { EDGE };
            self.segment(&[corners[*a], corners[*b]], color);
        }
        self.faces.clear();
        let far = match input.frame.far_faded {
            true => FAR_FACE_FADED,
            false => FAR_FACE,
        };
        for (face, color) in [([0, 1, 3, 2], NEAR_FACE), ([4, 5, 7, 6], far)] {
            for i in [0, 1, 2, 0, 2, 3] {
                let c = &corners[face[i]];
                self.faces
                    .push(OutsideVertex::plain(c.position, c.behind_eye, color));
            }
        }
    }

    /// The camera's axes from its centre of projection, each as long as a tenth of the frame,
    /// with its letter by the tip, facing the outside camera.
    fn build_gizmo(&mut self, input: &SceneInput, morph: &StageMorph) {
        let camera = input.camera;
        let length = input.frame.radius * 0.1;
        let origin = morph.place(camera.position);
        let size = length * 0.3;
        let Billboard { right, up } = input.billboard;
        for ((axis, color), letter) in [camera.u, camera.v, camera.n]
            .into_iter()
            .zip(AXES)
            .zip(LETTERS)
        {
            let tip = morph.place(camera.position + axis * length);
            if !self.segment(&[origin, tip], color) {
                continue;
            }
            let at = tip.position + (right + up) * (size * 0.4);
            for pair in letter.windows(2) {
                for [x, y] in pair {
                    let p = at + (right * *x + up * *y) * size;
                    self.lines
                        .push(OutsideVertex::plain(p, tip.behind_eye, color));
                }
            }
        }
    }
}

impl OutsideScene {
    /// A line from `ends[0]` to `ends[1]` when it has an image at the stage; returns whether.
    fn segment(&mut self, ends: &[Placed; 2], color: [u8; 4]) -> bool {
        let shown = has_image(ends);
        if shown {
            for p in ends {
                self.lines
                    .push(OutsideVertex::plain(p.position, p.behind_eye, color));
            }
        }
        shown
    }
}

fn rgba(color: Vec3) -> [u8; 4] {
    let [r, g, b] = to_rgb8(color);
    [r, g, b, 255]
}

fn fate_color(kind: FateKind) -> [u8; 4] {
    let [r, g, b] = kind.color();
    [r, g, b, 255]
}
