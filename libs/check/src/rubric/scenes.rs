//! The rubric's scenes on one model, each made for the line it is about. Every camera is given
//! (the eight camera lines), never `camera framed`, so that a scene shows the same frame to
//! every program; poses are placed from the model's bounding box (its centre, and the radius of
//! the sphere around it), so the same scenes work on any course model.
//!
//! Only the motion scenes (translation, look-at translation, rotation) start from a turned
//! camera; every other camera looks along -z with u = +x, v = +y, as the assignment's framed
//! camera does. Only the fov scenes have unequal fields of view, only the culling scenes turn
//! culling on, and only the clipping and culling-from-inside scenes put part of the model outside
//! the view volume: so a mistake in one stage shows in the scenes of the line about that stage
//! (and in the whole frame, which `synchronized` judges) and nowhere else it need not.

use close2gl_core::{FrontFace, Mesh, NamedEnum, RenderMode};
use close2gl_pipeline::program::ClipRule;
use close2gl_trace_format::{Axis, CameraLines, Motion, SceneCamera, SceneFile, culling_name};
use glam::DVec3;

use super::expected_motion::Pose;
use super::lines::LineId;

/// One scene of the rubric: its id (`cube/translation-move-u+`), the lines it counts for
/// (`synchronized` is every scene's), and the scene file's values.
#[derive(Clone, Debug, PartialEq)]
pub struct RubricScene {
    pub id: String,
    pub lines: Vec<LineId>,
    pub scene: SceneFile,
}

/// The fraction of the narrower field of view the model's bounding sphere fills in the scenes
/// that show it whole: room for a program whose horizontal scale is off by a fifth to still
/// draw all of it (so that a fov mistake does not become a clipping one).
const FILL: f64 = 0.6;
/// How far a motion goes, in bounding-sphere radii; large enough that a straight orbit and an
/// arc differ by more than the judge's tolerance.
const STEP: f64 = 0.5;
/// How far a rotation turns, degrees: small enough that the turned view still holds the whole
/// model (so that a rotation scene never tests clipping).
const TURN: f64 = 10.0;
/// The turned camera of the motion scenes: seen from up and to the right, degrees.
const YAW: f64 = 35.0;
const PITCH: f64 = 25.0;

/// The look-at point a scene without a `lookat` line means: the model's bounding-box centre.
pub fn default_lookat(mesh: &Mesh) -> DVec3 {
    Bounds::of(mesh).centre
}

/// The model's bounding box centre and the radius of the sphere around the box.
#[derive(Clone, Copy, Debug)]
struct Bounds {
    centre: DVec3,
    radius: f64,
}

impl Bounds {
    fn of(mesh: &Mesh) -> Self {
        let (low, high) = mesh.positions.iter().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(low, high), p| (low.min(p.as_dvec3()), high.max(p.as_dvec3())),
        );
        let radius = 0.5 * low.distance(high);
        Self {
            centre: 0.5 * (low + high),
            // A model that is one point still needs a size to stand back from.
            radius: if radius > 0.0 { radius } else { 1.0 },
        }
    }

    /// The distance at which the bounding sphere fills [`FILL`] of a field of view.
    fn distance(&self, fov: f64) -> f64 {
        self.radius / (FILL * fov.to_radians() / 2.0).sin()
    }

    /// A camera `distance` from the centre in direction `toward`, looking at the centre.
    fn looking_from(&self, toward: DVec3, distance: f64) -> Pose {
        let n = toward.normalize();
        let u = DVec3::Y.cross(n).normalize();
        Pose {
            position: self.centre + distance * n,
            u,
            v: n.cross(u),
            n,
        }
    }

    /// The camera in front of the model along +z, looking along -z, for these fovs.
    fn front(&self, hfov: f64, vfov: f64) -> CameraLines {
        let distance = self.distance(hfov.min(vfov));
        let pose = self.looking_from(DVec3::Z, distance);
        self.volume(pose, hfov, vfov, 0.5 * (distance - self.radius))
    }

    /// The turned camera of the motion scenes, looking at the centre.
    fn turned(&self) -> CameraLines {
        let (yaw, pitch) = (YAW.to_radians(), PITCH.to_radians());
        let toward = DVec3::new(
            yaw.sin() * pitch.cos(),
            pitch.sin(),
            yaw.cos() * pitch.cos(),
        );
        let distance = self.distance(60.0);
        let pose = self.looking_from(toward, distance);
        self.volume(pose, 60.0, 60.0, 0.5 * (distance - self.radius))
    }

    /// The eight camera lines: `far` leaves room for the model behind the centre and a move.
    fn volume(&self, pose: Pose, hfov: f64, vfov: f64, near: f64) -> CameraLines {
        let far = pose.position.distance(self.centre) + 3.0 * self.radius;
        CameraLines {
            position: pose.position,
            u: pose.u,
            v: pose.v,
            n: pose.n,
            hfov,
            vfov,
            near,
            far,
        }
    }
}

/// Every scene of the rubric on one model. `stem` names the model in the scene ids,
/// `model_file` is the model's file name as the scene's `model` line gives it (the grader puts
/// the model beside the scene).
pub fn scenes(stem: &str, model_file: &str, mesh: &Mesh) -> Vec<RubricScene> {
    let bounds = Bounds::of(mesh);
    let make = |name: &str, lines: &[LineId], window: (u32, u32), camera: CameraLines| {
        let mut lines = lines.to_vec();
        lines.push(LineId::Synchronized);
        let id = format!("{stem}/{name}");
        RubricScene {
            scene: SceneFile {
                file: id.clone(),
                model: model_file.to_string(),
                window,
                camera: SceneCamera::Given(camera),
                culling: None,
                clipping: ClipRule::Simple,
                mode: None,
                lookat: None,
                motions: Vec::new(),
                look: Default::default(),
            },
            id,
            lines,
        }
    };
    let mut all = Vec::new();
    all.extend(mode_scenes(&bounds, &make));
    all.extend(motion_scenes(&bounds, &make));
    all.extend(culling_scenes(&bounds, &make));
    all.extend(fov_scenes(&bounds, &make));
    all.extend(clipping_scenes(&bounds, &make));
    all.extend(resize_scenes(&bounds, &make));
    all
}

type Make<'a> = dyn Fn(&str, &[LineId], (u32, u32), CameraLines) -> RubricScene + 'a;

const WINDOW: (u32, u32) = (640, 480);

/// Points, wireframe and solid: the framed view, in each mode.
fn mode_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    let modes = [
        (LineId::Points, RenderMode::Points),
        (LineId::Wireframe, RenderMode::Wireframe),
        (LineId::Solid, RenderMode::Solid),
    ];
    modes
        .into_iter()
        .map(|(line, mode)| {
            let mut scene = make(line.id(), &[line], WINDOW, bounds.front(60.0, 60.0));
            scene.scene.mode = Some(mode);
            scene
        })
        .collect()
}

/// Translation (`move` along u, v, n, both signs), the look-at translation (`orbit` along u and
/// v, both signs, about the model's centre) and rotation (`rotate` about u, v, n, both signs),
/// all from the turned camera: a program that moves along the world's axes is caught.
fn motion_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    let step = STEP * bounds.radius;
    let mut scenes = Vec::new();
    let mut add = |line: LineId, verb: &str, motion: Motion, axis: Axis, sign: f64| {
        let name = format!(
            "{}-{verb}-{}{}",
            line.id(),
            axis.name(),
            if sign > 0.0 { "+" } else { "-" }
        );
        let mut scene = make(&name, &[line], WINDOW, bounds.turned());
        scene.scene.motions.push(motion);
        if line == LineId::LookatTranslation {
            scene.scene.lookat = Some(bounds.centre);
        }
        scenes.push(scene);
    };
    for axis in [Axis::U, Axis::V, Axis::N] {
        for sign in [1.0, -1.0] {
            let motion = Motion::Move(axis, sign * step);
            add(LineId::Translation, "move", motion, axis, sign);
        }
    }
    for axis in [Axis::U, Axis::V] {
        for sign in [1.0, -1.0] {
            let motion = Motion::Orbit(axis, sign * step);
            add(LineId::LookatTranslation, "orbit", motion, axis, sign);
        }
    }
    for axis in [Axis::U, Axis::V, Axis::N] {
        for sign in [1.0, -1.0] {
            let motion = Motion::Rotate(axis, sign * TURN);
            add(LineId::Rotation, "rotate", motion, axis, sign);
        }
    }
    scenes
}

/// Culling ccw, cw and off, with the model seen from outside (framed) and from inside (the
/// camera at its centre, a wide view, near close to the eye; 100 degrees, not 90, so that a
/// cube's far side is not exactly on the window's border, where rounding decides).
fn culling_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    let inside = {
        let pose = bounds.looking_from(DVec3::Z, 0.0);
        bounds.volume(pose, 100.0, 100.0, 0.01 * bounds.radius)
    };
    let mut scenes = Vec::new();
    for (place, camera) in [("outside", bounds.front(60.0, 60.0)), ("inside", inside)] {
        for culling in [Some(FrontFace::Ccw), Some(FrontFace::Cw), None] {
            let name = format!("culling-{}-{place}", culling_name(culling));
            let mut scene = make(&name, &[LineId::Culling], WINDOW, camera);
            scene.scene.culling = culling;
            scenes.push(scene);
        }
    }
    scenes
}

/// Unequal fields of view, narrow and wide, each way round; each scene counts for hfov and
/// vfov, which judge its horizontal and its vertical side.
fn fov_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    [(30.0, 50.0), (50.0, 30.0), (100.0, 70.0), (70.0, 100.0)]
        .into_iter()
        .map(|(hfov, vfov)| {
            let name = format!("fov-h{hfov}-v{vfov}");
            let lines = [LineId::Hfov, LineId::Vfov];
            make(&name, &lines, WINDOW, bounds.front(hfov, vfov))
        })
        .collect()
}

/// The near plane through the model's centre, the model's centre on each window border, and
/// the eye inside the model with part of it behind.
fn clipping_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    let line = [LineId::SimpleClipping];
    let front = bounds.front(60.0, 60.0);
    let distance = front.position.distance(bounds.centre);
    let mut near = front;
    near.near = distance;
    let mut scenes = vec![make("clipping-near", &line, WINDOW, near)];
    // Moving the camera by distance·tan(fov/2) puts the centre on the opposite border.
    let shift = distance * (30.0f64).to_radians().tan();
    let borders = [
        ("left", front.u * shift),
        ("right", -front.u * shift),
        ("bottom", front.v * shift),
        ("top", -front.v * shift),
    ];
    for (border, offset) in borders {
        let mut camera = front;
        camera.position += offset;
        scenes.push(make(&format!("clipping-{border}"), &line, WINDOW, camera));
    }
    // The eye a quarter radius behind the centre, looking on: what lies behind it is far
    // enough back that dividing it by its negative w would land it in the window, mirrored.
    let behind = {
        let pose = bounds.looking_from(DVec3::Z, -0.25 * bounds.radius);
        bounds.volume(pose, 130.0, 130.0, 0.01 * bounds.radius)
    };
    scenes.push(make("clipping-behind-eye", &line, WINDOW, behind));
    scenes
}

/// Windows of several aspect ratios: tall, wide, tiny, odd sizes.
fn resize_scenes(bounds: &Bounds, make: &Make) -> Vec<RubricScene> {
    [
        ("tall", (240, 640)),
        ("wide", (900, 220)),
        ("tiny", (7, 5)),
        ("odd", (333, 211)),
    ]
    .into_iter()
    .map(|(name, window)| {
        let name = format!("resize-{name}-{}x{}", window.0, window.1);
        make(&name, &[LineId::Resize], window, bounds.front(60.0, 60.0))
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use close2gl_trace_format::parse_scene;

    fn cube() -> Mesh {
        let mut mesh = Mesh::default();
        for x in [-1.0f32, 1.0] {
            for y in [-1.0f32, 1.0] {
                mesh.positions.push(glam::Vec3::new(x, y, -3.0 + x * y));
            }
        }
        mesh.triangles = vec![[0, 1, 2], [1, 3, 2]];
        mesh
    }

    #[test]
    fn every_scene_file_reads_back_the_same_and_ids_are_unique() {
        let scenes = scenes("cube", "cube.in", &cube());
        let mut ids: Vec<&str> = scenes.iter().map(|s| s.id.as_str()).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), scenes.len());
        for s in &scenes {
            let read = parse_scene(&s.scene.to_text(), &s.id).expect("reads back");
            assert_eq!(read, s.scene);
            assert_eq!(s.lines.last(), Some(&LineId::Synchronized));
        }
    }

    #[test]
    fn every_line_but_synchronized_has_its_scenes() {
        let scenes = scenes("cube", "cube.in", &cube());
        let count = |line| scenes.iter().filter(|s| s.lines.contains(&line)).count();
        let counts: Vec<usize> = LineId::ALL.iter().map(|&l| count(l)).collect();
        assert_eq!(counts, [1, 1, 1, 6, 4, 6, 6, 4, 4, 6, 4, scenes.len()]);
    }

    #[test]
    fn the_front_camera_is_the_assignments_axes_and_fits_the_model() {
        let bounds = Bounds::of(&cube());
        let camera = bounds.front(60.0, 60.0);
        assert_eq!(
            (camera.u, camera.v, camera.n),
            (DVec3::X, DVec3::Y, DVec3::Z)
        );
        let distance = camera.position.distance(bounds.centre);
        assert!(camera.near < distance - bounds.radius && camera.far > distance + bounds.radius);
    }
}
