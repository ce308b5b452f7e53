//! Clues for a difference no mistake explains: what a found number is to the expected one (a
//! ratio, named when it is a value a program plausibly multiplied by: cos 25°, 3/4, the
//! window's aspect), and how big and where the triangles that differ are. Pure functions: the
//! stages call them where they state expected and found values (docs/checking.md, "Clues").

mod camera_moves;
mod matrix_ratio;
mod triangle_sizes;

use close2gl_pipeline::program::{Program, ProgramCamera};
use close2gl_trace_format::Trace;
use glam::DMat4;

use crate::compare::matrices::{ALL_ROWS, V_ROWS};
use crate::vocabulary::{Stage, StageResult, Status};
use crate::words::number;
pub use camera_moves::{axes_after_move, travel};
pub use matrix_ratio::matrix;
pub use triangle_sizes::{Seen, on_screen, seen, triangles};

/// A ratio matches a value within this fraction of the value.
const MATCH: f64 = 1e-4;
/// Two names whose values are this close name the same number (cos 60° and 1/2).
const SAME: f64 = 1e-9;
/// A name is given only when the next distinct value that matches is this many times farther
/// off: otherwise the data cannot tell the two apart.
const CLEARER: f64 = 10.0;

/// Where a name comes from; the first family is preferred when names coincide, and the whole
/// degrees name a number only when nothing more telling does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Family {
    Fraction,
    Camera,
    Window,
    Ratio,
    Degrees,
}

/// The values a clue may name, for one camera and window.
pub struct Values(Vec<(f64, Family, String)>);

/// What a ratio is, in words.
#[derive(Clone, Debug, PartialEq)]
pub enum Named {
    /// One value matches: its names ("4/3 = 640/480, the window's aspect").
    Is(String),
    /// Several distinct values match about as well: none is named.
    Ambiguous,
    Unknown,
}

impl Values {
    /// cos and sin of whole degrees and of the camera's angles (half of each field of view; the
    /// pitch, yaw and roll of its axes against the world's), 1/2, 2, 3/4, 4/3, the window's
    /// aspect both ways, the fields of view's tangent ratio and angle ratio both ways, π/180 and
    /// 180/π.
    pub fn new(camera: &ProgramCamera, window: (u32, u32)) -> Self {
        let mut values: Vec<(f64, Family, String)> = [(0.5, "1/2"), (2.0, "2"), (0.75, "3/4")]
            .into_iter()
            .chain([(4.0 / 3.0, "4/3"), (1.0, "1")])
            .map(|(v, name)| (v, Family::Fraction, name.to_string()))
            .collect();
        for (degrees, what) in camera_angles(camera) {
            let shown = whole_or(degrees);
            let (sin, cos) = degrees.to_radians().sin_cos();
            values.push((cos, Family::Camera, format!("cos {shown}°, {what}")));
            values.push((sin, Family::Camera, format!("sin {shown}°, {what}")));
        }
        let (w, h) = (f64::from(window.0), f64::from(window.1));
        values.push((
            w / h,
            Family::Window,
            format!("{w}/{h}, the window's aspect"),
        ));
        values.push((
            h / w,
            Family::Window,
            format!("{h}/{w}, the window's height/width"),
        ));
        let half_tan = |fov: f64| (fov / 2.0).to_radians().tan();
        let tangents = half_tan(camera.hfov) / half_tan(camera.vfov);
        values.push((tangents, Family::Ratio, "tan(hfov/2)/tan(vfov/2)".into()));
        values.push((
            1.0 / tangents,
            Family::Ratio,
            "tan(vfov/2)/tan(hfov/2)".into(),
        ));
        let angles = camera.hfov / camera.vfov;
        values.push((angles, Family::Ratio, "hfov/vfov".into()));
        values.push((1.0 / angles, Family::Ratio, "vfov/hfov".into()));
        let radian = std::f64::consts::PI / 180.0;
        values.push((radian, Family::Ratio, "π/180".into()));
        values.push((1.0 / radian, Family::Ratio, "180/π".into()));
        for d in 1..=89 {
            let name = match d <= 45 {
                true => format!("cos {d}°"),
                false => format!("sin {}°", 90 - d),
            };
            values.push((f64::from(d).to_radians().cos(), Family::Degrees, name));
        }
        // A ratio of equal fields of view is 1, which the fraction names alone.
        values.retain(|(v, family, _)| {
            let one = *family != Family::Fraction && (v.abs() - 1.0).abs() <= SAME;
            v.is_finite() && v.abs() > 1e-6 && !one
        });
        Self(values)
    }

    /// The value `ratio` is, if one distinct value matches clearly better than any other; a
    /// negative ratio is named as the negative of a value ("−1", "−cos 25°").
    pub fn name(&self, ratio: f64) -> Named {
        let mut matches: Vec<(f64, f64, Family, String)> = Vec::new();
        for (value, family, name) in &self.0 {
            for (value, name) in [(*value, name.clone()), (-value, format!("−{name}"))] {
                let off = (ratio - value).abs() / value.abs();
                if off <= MATCH {
                    matches.push((off, value, *family, name));
                }
            }
        }
        matches.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.2.cmp(&b.2)));
        let Some(&(best_off, best, _, _)) = matches.first() else {
            return Named::Unknown;
        };
        let same = |v: f64| (v - best).abs() <= SAME * best.abs();
        let rival = matches.iter().find(|m| !same(m.1));
        if rival.is_some_and(|r| r.0 < CLEARER * best_off.max(SAME)) {
            return Named::Ambiguous;
        }
        let mut names: Vec<&(f64, f64, Family, String)> =
            matches.iter().filter(|m| same(m.1)).collect();
        names.sort_by_key(|m| m.2);
        if names.len() > 1 {
            names.retain(|m| m.2 != Family::Degrees);
        }
        let names: Vec<&str> = names.iter().map(|m| m.3.as_str()).collect();
        Named::Is(names.join(" = "))
    }

    /// "0.9063 (= cos 25°)", "≈ 0.7500" when several values match, "0.8123" when none does.
    pub fn ratio(&self, ratio: f64) -> String {
        self.then(ratio, "")
    }

    /// "0.9063 of `what` (= cos 25°)", "≈ 0.7500 of `what`", "0.8123 of `what`".
    pub fn of(&self, ratio: f64, what: &str) -> String {
        self.then(ratio, &format!(" of {what}"))
    }

    /// The ratio, then `words`, then its name: "0.9063 long (= cos 25°)".
    pub fn then(&self, ratio: f64, words: &str) -> String {
        match self.name(ratio) {
            Named::Is(name) => format!("{}{words} (= {name})", number(ratio)),
            Named::Ambiguous => format!("≈ {}{words}", number(ratio)),
            Named::Unknown => format!("{}{words}", number(ratio)),
        }
    }
}

/// The matrix clue of each matrix stage among `stages` (`program`'s matrices against the
/// trace's).
pub fn add_matrix_clues(stages: &mut [StageResult], program: &Program, trace: &Trace) {
    for result in stages {
        let (expected, rows) = match result.stage {
            Stage::M => (program.m, ALL_ROWS),
            Stage::P => (program.p, ALL_ROWS),
            Stage::V => (program.v, V_ROWS),
            _ => continue,
        };
        add_matrix_clue(result, expected, trace, rows);
    }
}

/// Puts the matrix clue first in `result`'s details when it differs: `result` compares
/// `expected` with the trace's matrix of its stage over `rows`. The first detail is what a
/// one-line summary quotes, and the clue says more than any one entry.
pub fn add_matrix_clue(result: &mut StageResult, expected: DMat4, trace: &Trace, rows: &[usize]) {
    let found = match result.stage {
        Stage::M => trace.m,
        Stage::P => trace.p,
        Stage::V => trace.v,
        _ => None,
    };
    let Some(found) = found.filter(|_| result.status == Status::Differs) else {
        return;
    };
    let values = Values::new(&trace.camera, trace.window);
    if let Some(clue) = matrix(result.stage.name(), expected, found, rows, &values) {
        result.details.insert(0, clue);
    }
}

/// The camera's own angles in degrees, each with what it is: half of each field of view, and
/// the pitch, yaw and roll of its axes against the world's (those of a turned camera only).
fn camera_angles(camera: &ProgramCamera) -> Vec<(f64, &'static str)> {
    let (u, v, n) = (
        camera.u.normalize_or_zero(),
        camera.v.normalize_or_zero(),
        camera.n.normalize_or_zero(),
    );
    let turned = [
        (n.y.clamp(-1.0, 1.0).asin(), "the pitch"),
        (n.x.atan2(n.z), "the yaw"),
        (u.y.atan2(v.y), "the roll"),
    ];
    let mut angles = vec![
        (camera.hfov / 2.0, "half the hfov"),
        (camera.vfov / 2.0, "half the vfov"),
    ];
    angles.extend(
        turned
            .into_iter()
            .map(|(a, what)| (a.to_degrees().abs(), what))
            .filter(|(a, _)| a.is_finite() && *a > 0.5),
    );
    angles
}

/// An angle as the report shows it: whole degrees when it is one, else two decimals.
fn whole_or(degrees: f64) -> String {
    match (degrees - degrees.round()).abs() < 1e-6 {
        true => format!("{}", degrees.round()),
        false => format!("{degrees:.2}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A camera pitched 25°, 56° by 40°, in an 800 × 500 window.
    pub(super) fn pitched() -> (ProgramCamera, (u32, u32)) {
        let (s, c) = 25f64.to_radians().sin_cos();
        let camera = ProgramCamera {
            position: DVec3::new(1.0, 2.0, 5.0),
            u: DVec3::X,
            v: DVec3::new(0.0, c, s),
            n: DVec3::new(0.0, -s, c),
            hfov: 56.0,
            vfov: 40.0,
            near: 1.0,
            far: 100.0,
        };
        (camera, (800, 500))
    }

    fn named(ratio: f64) -> Named {
        let (camera, window) = pitched();
        Values::new(&camera, window).name(ratio)
    }

    fn is(name: &str) -> Named {
        Named::Is(name.into())
    }

    #[test]
    fn the_cameras_own_angles_are_named_before_whole_degrees() {
        let c25 = 25f64.to_radians().cos();
        assert_eq!(named(c25), is("cos 25°, the pitch"));
        assert_eq!(
            named(c25 * (1.0 + 3e-5)),
            is("cos 25°, the pitch"),
            "float32"
        );
        assert_eq!(named(25f64.to_radians().sin()), is("sin 25°, the pitch"));
        assert_eq!(named(25f64.to_radians().tan().recip()), Named::Unknown);
        assert_eq!(
            named(20f64.to_radians().sin()),
            is("sin 20°, half the vfov")
        );
        assert_eq!(named(-c25), is("−cos 25°, the pitch"));
        assert_eq!(
            named(28f64.to_radians().cos()),
            is("cos 28°, half the hfov")
        );
    }

    #[test]
    fn whole_degrees_are_named_by_the_smaller_angle() {
        assert_eq!(named(37f64.to_radians().cos()), is("cos 37°"));
        assert_eq!(named(10f64.to_radians().sin()), is("sin 10°"));
        assert_eq!(named(-(37f64.to_radians().cos())), is("−cos 37°"));
    }

    #[test]
    fn fractions_window_and_field_of_view_ratios() {
        assert_eq!(named(0.75), is("3/4"));
        assert_eq!(named(4.0 / 3.0), is("4/3"));
        assert_eq!(named(2.0), is("2"));
        assert_eq!(named(0.5), is("1/2"), "cos 60° and sin 30° are dropped");
        assert_eq!(named(-1.0), is("−1"));
        assert_eq!(named(1.6), is("800/500, the window's aspect"));
        assert_eq!(named(0.625), is("500/800, the window's height/width"));
        let tangents = 28f64.to_radians().tan() / 20f64.to_radians().tan();
        assert_eq!(named(tangents), is("tan(hfov/2)/tan(vfov/2)"));
        assert_eq!(named(1.0 / tangents), is("tan(vfov/2)/tan(hfov/2)"));
        assert_eq!(named(1.4), is("hfov/vfov"));
        assert_eq!(named(40.0 / 56.0), is("vfov/hfov"));
        assert_eq!(named(std::f64::consts::PI / 180.0), is("π/180"));
        assert_eq!(named(180.0 / std::f64::consts::PI), is("180/π"));
    }

    #[test]
    fn one_number_with_several_names_gives_them_all() {
        let (camera, _) = pitched();
        let values = Values::new(&camera, (640, 480));
        assert_eq!(
            values.name(4.0 / 3.0),
            is("4/3 = 640/480, the window's aspect")
        );
    }

    #[test]
    fn two_values_that_match_about_as_well_are_not_named() {
        // 12000/16001 is 6.2e-5 from 3/4: a ratio between them could be either.
        let (camera, _) = pitched();
        let values = Values::new(&camera, (12000, 16001));
        let between = (0.75 + 12000.0 / 16001.0) / 2.0;
        assert_eq!(values.name(between), Named::Ambiguous);
        assert_eq!(values.ratio(between), "≈ 0.7500");
        assert_eq!(values.name(0.75), is("3/4"), "exactly 3/4 is clearly 3/4");
    }

    #[test]
    fn a_ratio_that_matches_nothing_is_only_a_number() {
        assert_eq!(named(0.8123), Named::Unknown);
        assert_eq!(named(1.0 + 5e-4), Named::Unknown, "outside 1e-4 of 1");
        let (camera, window) = pitched();
        assert_eq!(Values::new(&camera, window).ratio(0.8123), "0.8123");
        let c25 = 25f64.to_radians().cos();
        assert_eq!(
            Values::new(&camera, window).ratio(c25),
            "0.9063 (= cos 25°, the pitch)"
        );
    }

    #[test]
    fn equal_fields_of_view_do_not_name_1() {
        let (mut camera, window) = pitched();
        camera.vfov = camera.hfov;
        assert_eq!(Values::new(&camera, window).name(-1.0), is("−1"));
    }

    #[test]
    fn a_camera_of_zero_axes_names_no_angle_of_them() {
        let (mut camera, window) = pitched();
        (camera.u, camera.v, camera.n) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
        let values = Values::new(&camera, window);
        assert!(values.0.iter().all(|(v, _, _)| v.is_finite()));
        assert_eq!(values.name(25f64.to_radians().cos()), is("cos 25°"));
    }
}
