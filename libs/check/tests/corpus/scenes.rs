//! The scenes the corpus runs on: the bundled models from several poses, a camera inside the
//! cube, and a 1,200-unit model 10⁴ units from the origin (the knot, scaled and moved, written
//! into the test's folder), each written as a scene file next to nothing but itself.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_testkit::student::asset;

/// A scene file and the mesh its model loads into (what check compares with).
pub struct SceneFile {
    pub path: PathBuf,
    pub mesh: Mesh,
}

/// Where the far model's centre goes, and its size (its bounding box's diagonal).
const FAR_OFFSET: [f64; 3] = [12_000.0, -9_000.0, 7_000.0];
const FAR_SIZE: f64 = 1_200.0;

fn load(path: &Path) -> Mesh {
    close2gl_model::load(
        &ModelSource::File(path.to_path_buf()),
        &PrimitiveParams::default(),
    )
    .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    .mesh
}

/// Half the bounding box's diagonal: the radius the programs frame by.
fn radius(mesh: &Mesh) -> f64 {
    let (lo, hi) = mesh.bounds();
    f64::from((hi - lo).length()) / 2.0
}

/// The knot scaled to FAR_SIZE and centred at FAR_OFFSET, as an .obj in `dir` (its normals and
/// faces unchanged, so that triangle T is the knot's triangle T).
fn write_far_model(dir: &Path) -> PathBuf {
    let knot = std::fs::read_to_string(asset("knot.obj")).expect("read knot.obj");
    let vertices: Vec<[f64; 3]> = knot
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let mut x = l
                .split_whitespace()
                .map(|f| f.parse::<f64>().expect("a number"));
            [0; 3].map(|_| x.next().expect("x y z"))
        })
        .collect();
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for v in &vertices {
        for k in 0..3 {
            lo[k] = lo[k].min(v[k]);
            hi[k] = hi[k].max(v[k]);
        }
    }
    let diagonal = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    let scale = FAR_SIZE / diagonal;
    let mut text = String::from("# the knot, 1,200 units across, 10^4 units from the origin\n");
    for v in &vertices {
        let p: Vec<String> = (0..3)
            .map(|k| {
                format!(
                    "{:.4}",
                    (v[k] - (lo[k] + hi[k]) / 2.0) * scale + FAR_OFFSET[k]
                )
            })
            .collect();
        text += &format!("v {}\n", p.join(" "));
    }
    for line in knot
        .lines()
        .filter(|l| l.starts_with("vn ") || l.starts_with("f "))
    {
        text += line;
        text.push('\n');
    }
    let path = dir.join("far_offset.obj");
    std::fs::write(&path, text).expect("write the far model");
    path
}

/// A first-person pose: up, turn left, look down 25° (back at the model), step forward. Yaw
/// before pitch, as a first-person camera turns.
fn fps(r: f64) -> String {
    format!(
        "camera framed\nculling ccw\nmove v {}\nrotate v 10\nrotate u -25\nmove n {}\n",
        2.0 * r * 25f64.to_radians().tan(),
        -0.2 * r
    )
}

/// Every scene by name, written into `dir`.
pub fn write_all(dir: &Path) -> BTreeMap<&'static str, SceneFile> {
    let far = write_far_model(dir);
    let models = [
        ("cube", asset("cube.in")),
        ("knot", asset("knot.obj")),
        ("far_away", asset("far_away.in")),
        ("far_offset", far),
    ];
    let meshes: BTreeMap<&str, (PathBuf, Mesh)> = models
        .into_iter()
        .map(|(name, path)| (name, (path.clone(), load(&path))))
        .collect();
    let r = |model: &str| radius(&meshes[model].1);
    let scenes: [(&'static str, &str, String); 12] = [
        ("cube_front", "cube", format!("camera framed\nculling ccw\norbit u {}\norbit v {}\n", 0.6 * r("cube"), 0.4 * r("cube"))),
        ("knot_turned", "knot", format!("camera framed\nculling ccw\norbit u {}\nrotate n 15\nmove n {}\n", 0.5 * r("knot"), -0.2 * r("knot"))),
        ("knot_cw", "knot", format!("camera framed\nculling cw\nclipping full\norbit v {}\n", -0.4 * r("knot"))),
        ("knot_small", "knot", format!("camera framed\ncamera near {}\ncamera far {}\nculling ccw\nmove n {}\n", r("knot"), 12.0 * r("knot"), 4.0 * r("knot"))),
        ("knot_aside", "knot", format!("camera framed\nculling ccw\nmove u {}\n", 0.8 * r("knot"))),
        ("knot_through", "knot", format!("camera framed\nculling ccw\nclipping full\nmove n {}\n", -1.3 * r("knot"))),
        ("far_away_turned", "far_away", format!("camera framed\nculling ccw\norbit u {}\n", 0.4 * r("far_away"))),
        ("inside_cube", "cube", "camera position 0.2 -0.1 -2.8\ncamera u 1 0 0\ncamera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\ncamera near 0.1\ncamera far 10\nculling off\nrotate v 20\n".to_string()),
        ("knot_fps", "knot", fps(r("knot"))),
        ("far_away_fps", "far_away", fps(r("far_away"))),
        ("far_offset_fps", "far_offset", fps(r("far_offset"))),
        ("far_offset_turned", "far_offset", format!("camera framed\nculling ccw\norbit u {}\n", 0.5 * r("far_offset"))),
    ];
    scenes
        .into_iter()
        .map(|(name, model, lines)| {
            let (model_path, mesh) = &meshes[model];
            let text = format!(
                "close2gl-scene 1\nmodel {}\nwindow 640 480\n{lines}",
                model_path.display()
            );
            let path = dir.join(format!("{name}.scene"));
            std::fs::write(&path, text).expect("write a scene");
            (
                name,
                SceneFile {
                    path,
                    mesh: mesh.clone(),
                },
            )
        })
        .collect()
}
