//! `check` against a real student program: `examples/trace/pipeline.c`, compiled with the
//! system's C compiler once correct (in double and in float32, writing polygons or fans) and once
//! per catalogue mistake, run as a process on the bundled models from five camera poses in the
//! three 2D systems. Every correct trace agrees; every mistaken trace that differs is named
//! exactly its mistake, and nothing else.

use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_check::{self as check, Report};
use close2gl_core::{Mesh, Mistake, ModelSource, PrimitiveParams};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_pipeline, mistake_flag};
use rayon::prelude::*;

const MODELS: [&str; 4] = ["cube.in", "textured_cube.in", "far_away.in", "knot.obj"];

/// The radius of the sphere around the model's bounding box, which the program frames by.
fn radius(mesh: &Mesh) -> f32 {
    let (lo, hi) = mesh.bounds();
    (hi - lo).length() / 2.0
}

/// The poses, from the program's own framed one (model centred, as close as the fields of view
/// allow, near at half the way to the model): (name, 2D systems, scene lines).
fn poses(r: f32) -> Vec<(&'static str, Vec<&'static str>, String)> {
    vec![
        (
            "inside",
            vec!["yup", "ydown", "unit"],
            format!(
                "culling ccw\nclipping simple\nrotate n 20\nmove u {}\n",
                0.1 * r
            ),
        ),
        (
            "near_through",
            vec!["ydown"],
            format!("culling ccw\nclipping full\nmove n {}\n", -1.3 * r),
        ),
        (
            "behind_eye",
            vec!["unit"],
            format!(
                "culling ccw\nclipping full\nmove n {}\nrotate v 25\n",
                -2.0 * r
            ),
        ),
        (
            "behind_eye_simple",
            vec!["yup"],
            format!("culling ccw\nclipping simple\nmove n {}\n", -2.0 * r),
        ),
        (
            "unequal_fov",
            vec!["yup"],
            format!(
                "camera hfov 90\ncamera vfov 40\nculling ccw\norbit u {}\n",
                0.5 * r
            ),
        ),
        (
            "cw",
            vec!["ydown"],
            format!(
                "culling cw\nclipping full\nrotate u 15\nmove v {}\n",
                0.3 * r
            ),
        ),
    ]
}

struct Case {
    model: &'static str,
    mesh: Mesh,
    scene: PathBuf,
    pose: &'static str,
    system: &'static str,
}

fn cases(dir: &Path) -> Vec<Case> {
    let mut cases = Vec::new();
    for model in MODELS {
        let path = asset(model);
        let loaded = close2gl_model::load(
            &ModelSource::File(path.clone()),
            &PrimitiveParams::default(),
        );
        let mesh = loaded.expect("a bundled model").mesh;
        for (pose, systems, lines) in poses(radius(&mesh)) {
            let text = format!(
                "close2gl-scene 1\nmodel {}\nwindow 640 480\ncamera framed\n{lines}",
                path.display()
            );
            let scene = dir.join(format!("{model}-{pose}.scene"));
            std::fs::write(&scene, text).expect("write scene");
            for system in systems {
                cases.push(Case {
                    model,
                    mesh: mesh.clone(),
                    scene: scene.clone(),
                    pose,
                    system,
                });
            }
        }
    }
    cases
}

/// Runs `program` on the case and checks its trace.
fn run(program: &Path, case: &Case, dir: &Path, build: &str) -> Report {
    let trace = dir.join(format!(
        "{}-{}-{}-{build}.trace",
        case.model, case.pose, case.system
    ));
    let status = Command::new(program)
        .arg(&case.scene)
        .arg(&trace)
        .arg(case.system)
        .status()
        .expect("run the program");
    assert!(status.success(), "{build} on {}", case.scene.display());
    let trace =
        close2gl_trace_format::read_trace(&trace).expect("the program writes a valid trace");
    check::check(&case.mesh, &trace).expect("the trace fits the model")
}

#[test]
fn correct_programs_agree_in_double_and_float32_as_polygons_or_fans() {
    let dir = TempDir::new("check_correct");
    let cases = cases(&dir);
    for (build, flags) in [
        ("correct", vec![]),
        ("float", vec!["-DCLOSE2GL_FLOAT"]),
        ("fan", vec!["-DFAN"]),
    ] {
        let program = compile_pipeline(&dir, build, &flags);
        cases.par_iter().for_each(|case| {
            let report = run(&program, case, &dir, build);
            assert!(
                report.agrees(),
                "{build} on {} {} {}:\n{}",
                case.model,
                case.pose,
                case.system,
                check::report::text(&report, "trace")
            );
        });
    }
}

#[test]
fn each_mistake_is_named_exactly_and_nothing_else_is() {
    let dir = TempDir::new("check_mistakes");
    let cases = cases(&dir);
    Mistake::ALL[1..].par_iter().for_each(|&mistake| {
        let id = mistake.name();
        let program = compile_pipeline(&dir, id, &[&mistake_flag(id)]);
        let (mut differing, mut exactly) = (0, 0);
        for case in &cases {
            let report = run(&program, case, &dir, id);
            if report.agrees() {
                continue;
            }
            differing += 1;
            // Named, and when other sets reproduce this frame too, named with them and with
            // what would tell them apart.
            let named = report.diagnoses.contains(&Mistakes::one(mistake));
            let alone_or_told = report.diagnoses.len() == 1 || !report.apart.is_empty();
            assert!(
                named && alone_or_told,
                "{id} on {} {} {}:\n{}",
                case.model,
                case.pose,
                case.system,
                check::report::text(&report, "trace")
            );
            exactly += usize::from(report.diagnoses.len() == 1);
        }
        assert!(differing > 0, "no pose shows {id}");
        // Every mistake has a frame that shows it alone, but one: ignoring the declared front
        // face shows only with `culling cw`, where it culls as culling_inverted does.
        let twin = mistake == Mistake::CullingIgnoresFrontFace;
        assert!(
            exactly > 0 || twin,
            "no pose tells {id} from every other set"
        );
    });
}
