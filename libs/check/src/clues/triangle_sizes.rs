//! The triangles clue: how big the triangles that differ are on screen (area in px², longest
//! edge) and where they are (distance in front of the eye in units of near, touching a plane of
//! the view volume). A rule of the program's own that decides small or border triangles
//! differently shows as sizes or places they share.

use close2gl_core::Mesh;
use close2gl_pipeline::program::{Program, TriangleOutcome};
use glam::DVec2;

/// One triangle that differs, as the clue sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct Seen {
    /// Its shape on screen, in pixels: what close2gl drew of it, or the whole triangle when
    /// close2gl drew nothing; None when a corner is at or behind the eye (it has no size there).
    pub pixels: Option<Vec<DVec2>>,
    /// Its corners' distances in front of the eye (negative: behind it).
    pub distances: [f64; 3],
    /// It touches a plane of the view volume.
    pub touches: bool,
}

/// Mesh triangle `t` as `program` sees it (`outcome`: what the program did with it); touching
/// the border is being cut or removed by a plane of the view volume.
pub fn seen(program: &Program, mesh: &Mesh, t: usize, outcome: &TriangleOutcome) -> Seen {
    let eye = |i: u32| -(program.m * mesh.positions[i as usize].as_dvec3().extend(1.0)).z;
    Seen {
        pixels: on_screen(program, outcome),
        distances: mesh.triangles[t].map(eye),
        touches: outcome.fate.planes != 0,
    }
}

/// `outcome`'s shape on screen in window pixels (see [`Seen::pixels`]).
pub fn on_screen(program: &Program, outcome: &TriangleOutcome) -> Option<Vec<DVec2>> {
    let (width, height) = program.declared.window;
    let polygon: Vec<DVec2> = match outcome.drawn() {
        true => outcome.polygon.clone(),
        false if outcome.clip.iter().all(|c| c.w > 0.0) => outcome
            .clip
            .iter()
            .map(|c| {
                (program.v * (c.truncate() / c.w).extend(1.0))
                    .truncate()
                    .truncate()
            })
            .collect(),
        false => return None,
    };
    let pixels: Vec<DVec2> = polygon
        .iter()
        .map(|&p| program.declared.system.to_pixels(p, width, height))
        .collect();
    pixels.iter().all(|p| p.is_finite()).then_some(pixels)
}

/// "areas 0.020 to 1.6 px² (median 0.40 px²), longest edge at most 2.1 px; 1.6·near to
/// 3.0·near in front of the eye (near = 2.4581); none touch the view volume's border".
pub fn triangles(seen: &[Seen], near: f64) -> String {
    format!(
        "{}; {}; {}",
        sizes(seen),
        distances(seen, near),
        border(seen)
    )
}

fn sizes(seen: &[Seen]) -> String {
    let shapes: Vec<&Vec<DVec2>> = seen.iter().filter_map(|s| s.pixels.as_ref()).collect();
    let mut areas: Vec<f64> = shapes.iter().map(|p| area(p)).collect();
    areas.sort_by(f64::total_cmp);
    let longest = shapes.iter().map(|p| longest_edge(p)).fold(0.0, f64::max);
    let behind = match seen.len() - shapes.len() {
        0 => String::new(),
        k if k == seen.len() => return "each with a corner at or behind the eye".into(),
        k => format!(", and {k} with a corner at or behind the eye"),
    };
    match areas.as_slice() {
        [one] => format!(
            "area {} px², longest edge {} px{behind}",
            short(*one),
            short(longest)
        ),
        _ => format!(
            "areas {} to {} px² (median {} px²), longest edge at most {} px{behind}",
            short(areas[0]),
            short(areas[areas.len() - 1]),
            short(areas[areas.len() / 2]),
            short(longest)
        ),
    }
}

fn distances(seen: &[Seen], near: f64) -> String {
    let (low, high) = seen
        .iter()
        .flat_map(|s| s.distances)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), d| {
            (l.min(d), h.max(d))
        });
    let at = |d: f64| format!("{}·near", short(d.abs() / near));
    let near = short(near);
    match (low > 0.0, high > 0.0) {
        (true, _) => format!(
            "{} to {} in front of the eye (near = {near})",
            at(low),
            at(high)
        ),
        (false, true) => format!(
            "from {} behind the eye to {} in front of it (near = {near})",
            at(low),
            at(high)
        ),
        (false, false) => format!("{} to {} behind the eye (near = {near})", at(high), at(low)),
    }
}

fn border(seen: &[Seen]) -> String {
    let touching = seen.iter().filter(|s| s.touches).count();
    let what = "the view volume's border";
    match (touching, seen.len()) {
        (0, 1) => format!("it does not touch {what}"),
        (1, 1) => format!("it touches {what}"),
        (0, _) => format!("none touch {what}"),
        (k, n) if k == n => format!("all touch {what}"),
        (k, _) => format!("{k} of them touch {what}"),
    }
}

/// The area of a simple polygon.
fn area(polygon: &[DVec2]) -> f64 {
    let twice: f64 = (0..polygon.len())
        .map(|i| polygon[i].perp_dot(polygon[(i + 1) % polygon.len()]))
        .sum();
    twice.abs() / 2.0
}

fn longest_edge(polygon: &[DVec2]) -> f64 {
    (0..polygon.len())
        .map(|i| polygon[i].distance(polygon[(i + 1) % polygon.len()]))
        .fold(0.0, f64::max)
}

/// Two significant digits: sizes and distances are clues, not measurements.
fn short(x: f64) -> String {
    match x.abs() {
        0.0 => "0".into(),
        a if a < 1e-3 => format!("{x:.1e}"),
        a => {
            let decimals = (1.0 - a.log10().floor()).max(0.0) as usize;
            format!("{x:.decimals$}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A right triangle with legs `a` px, at `distance` from the eye.
    fn seen(a: f64, distance: f64, touches: bool) -> Seen {
        Seen {
            pixels: Some(vec![
                DVec2::new(10.0, 10.0),
                DVec2::new(10.0 + a, 10.0),
                DVec2::new(10.0, 10.0 + a),
            ]),
            distances: [distance; 3],
            touches,
        }
    }

    #[test]
    fn sizes_distances_and_border_of_several() {
        let seen = [
            seen(1.0, 3.2, false),
            seen(2.0, 4.0, false),
            seen(0.5, 6.0, false),
        ];
        assert_eq!(
            triangles(&seen, 2.0),
            "areas 0.12 to 2.0 px² (median 0.50 px²), longest edge at most 2.8 px; 1.6·near to \
             3.0·near in front of the eye (near = 2.0); none touch the view volume's border"
        );
    }

    #[test]
    fn one_triangle_and_one_touching() {
        assert_eq!(
            triangles(&[seen(4.0, 0.5, true)], 1.0),
            "area 8.0 px², longest edge 5.7 px; 0.50·near to 0.50·near in front of the eye \
             (near = 1.0); it touches the view volume's border"
        );
        let two = [seen(1.0, 1.0, true), seen(1.0, 1.0, false)];
        assert!(triangles(&two, 1.0).ends_with("; 1 of them touch the view volume's border"));
    }

    #[test]
    fn a_corner_behind_the_eye_has_no_size() {
        let behind = Seen {
            pixels: None,
            distances: [-1.0, 2.0, 3.0],
            touches: true,
        };
        assert_eq!(
            triangles(&[behind.clone(), seen(1.0, 2.0, true)], 1.0),
            "area 0.50 px², longest edge 1.4 px, and 1 with a corner at or behind the eye; \
             from 1.0·near behind the eye to 3.0·near in front of it (near = 1.0); all touch \
             the view volume's border"
        );
        assert!(triangles(&[behind], 1.0).starts_with("each with a corner at or behind the eye;"));
    }

    #[test]
    fn two_significant_digits() {
        assert_eq!(short(1.5966), "1.6");
        assert_eq!(short(0.4), "0.40");
        assert_eq!(short(1234.4), "1234");
        assert_eq!(short(2e-5), "2.0e-5");
        assert_eq!(short(0.0), "0");
    }
}
