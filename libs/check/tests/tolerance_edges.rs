//! The line between rounding and a rule: check's tolerances accept what float32 rounding does to
//! a right frame, and refuse a program that leaves out triangles of 0.05 px² or more (a rule of
//! its own about small triangles, not rounding) or draws nothing at all.

use close2gl_check::{self as check, Kind, Report};
use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::TriangleOutcome;
use close2gl_pipeline::rounding::twice_area;
use close2gl_testkit::student::asset;
use close2gl_trace_format::parse_trace;

/// The knot seen from 12 units, in window pixels y up (so that areas are in px²).
const HEAD: &str = "close2gl-trace 1
window 640 480
camera position 0.3 -0.2 12
camera u 1 0 0
camera v 0 1 0
camera n 0 0 1
camera hfov 60
camera vfov 45
camera near 1
camera far 100
culling ccw
clipping full
";

fn knot() -> Mesh {
    let source = ModelSource::File(asset("knot.obj"));
    close2gl_model::load(&source, &PrimitiveParams::default())
        .expect("the bundled knot")
        .mesh
}

/// close2gl's own frame of the knot from [`HEAD`]'s camera.
fn frame(mesh: &Mesh) -> Vec<TriangleOutcome> {
    let trace = parse_trace(&format!("{HEAD}drawn 0\n"), "head.trace").expect("head");
    check::program_for(&trace, Mistakes::NONE).frame(mesh)
}

/// A trace of `frame` with `corner` applied to each 2D corner, leaving out the triangles
/// `drop` says.
fn trace_of(
    frame: &[TriangleOutcome],
    corner: impl Fn(f64) -> f64,
    drop: impl Fn(&TriangleOutcome) -> bool,
) -> String {
    let mut text = String::from(HEAD);
    let mut drawn = 0;
    for (t, outcome) in frame.iter().enumerate() {
        if !outcome.drawn() || drop(outcome) {
            continue;
        }
        let numbers: Vec<String> = outcome
            .polygon
            .iter()
            .flat_map(|p| [corner(p.x), corner(p.y)])
            .map(|x| format!("{x:?}"))
            .collect();
        text += &format!("poly {t} {} {}\n", outcome.polygon.len(), numbers.join(" "));
        drawn += 1;
    }
    text + &format!("drawn {drawn}\nend\n")
}

fn checked(mesh: &Mesh, text: &str) -> Report {
    let trace = parse_trace(text, "edges.trace").expect("a valid trace");
    check::check(mesh, &trace).expect("the trace fits the knot")
}

fn area(outcome: &TriangleOutcome) -> f64 {
    twice_area(&outcome.polygon).abs() / 2.0
}

#[test]
fn float32_rounding_of_every_corner_agrees() {
    let mesh = knot();
    let frame = frame(&mesh);
    // Rounded to float32 and one float32 step further, as a float32 program may land.
    let float32 = |x: f64| {
        let x = x as f32;
        f64::from(f32::from_bits(x.to_bits() + 1))
    };
    let report = checked(&mesh, &trace_of(&frame, float32, |_| false));
    assert!(report.agrees(), "{}", check::report::text(&report, "f32"));
}

#[test]
fn leaving_out_triangles_of_a_twentieth_of_a_pixel_is_caught() {
    let mesh = knot();
    let frame = frame(&mesh);
    let small = |o: &TriangleOutcome| (0.05..0.25).contains(&area(o));
    let left_out = frame.iter().filter(|o| o.drawn() && small(o)).count();
    assert!(
        left_out > 0,
        "the knot has triangles of 0.05 to 0.25 px² from here"
    );
    let report = checked(&mesh, &trace_of(&frame, |x| x, small));
    assert!(
        !report.agrees(),
        "{}",
        check::report::text(&report, "small")
    );
    let missing = report.comparison.of_kind(Kind::FrontCulled).len()
        + report.comparison.of_kind(Kind::NotDrawn).len();
    assert_eq!(
        missing,
        left_out,
        "{}",
        check::report::text(&report, "small")
    );
}

#[test]
fn a_trace_that_draws_nothing_never_agrees() {
    let mesh = knot();
    let frame = frame(&mesh);
    let report = checked(&mesh, &trace_of(&frame, |x| x, |_| true));
    assert!(
        !report.agrees(),
        "{}",
        check::report::text(&report, "nothing")
    );
}
