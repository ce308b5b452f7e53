//! The move clue: how far and which way a camera went against the move a scene asked for
//! ("it moved 0.9063 of the asked distance (= cos 25°, the pitch)"), and what happened to its
//! axes when they are not the scene's after a move: shortened, left-handed, or turned.

use glam::DVec3;

use super::{Named, Values};
use crate::words::number;

const NAMES: [&str; 3] = ["u", "v", "n"];

/// How `moved` (the camera's displacement) compares with `asked` (the scene's moves'), both
/// from the start; None when nothing was asked.
pub fn travel(asked: DVec3, moved: DVec3, tolerance: f64, values: &Values) -> Option<String> {
    let length = asked.length();
    if length <= tolerance {
        return None;
    }
    if moved.length() <= tolerance {
        return Some("it did not move".into());
    }
    let along = moved.dot(asked) / (length * length);
    let aside = (moved - along * asked).length();
    if aside > tolerance {
        return Some(format!(
            "it moved {} of the asked distance, {}° off the asked direction",
            number(moved.length() / length),
            number(moved.angle_between(asked).to_degrees())
        ));
    }
    Some(match along < 0.0 {
        true if values.name(along) == Named::Is("−1".into()) => {
            "it moved the asked distance the other way".into()
        }
        true => format!(
            "it moved the other way, {}",
            values.of(-along, "the asked distance")
        ),
        false => format!("it moved {}", values.of(along, "the asked distance")),
    })
}

/// What happened to the axes when `found` (u, v, n) are not `expected` after a move: an axis
/// that only changed length is "not unit", a u pointing the other way with the axes
/// left-handed was so from the start (a move does not mirror), and anything else turned.
/// None when each is within `tolerance`.
pub fn axes_after_move(
    expected: [DVec3; 3],
    found: [DVec3; 3],
    tolerance: f64,
    values: &Values,
) -> Option<String> {
    let off: Vec<usize> = (0..3)
        .filter(|&i| expected[i].distance(found[i]) > tolerance)
        .collect();
    let angle = |i: usize| expected[i].angle_between(found[i]);
    let left_handed = found[0].cross(found[1]).dot(found[2]) < 0.0;
    let mirrored = |i: usize| i == 0 && left_handed && angle(0) >= std::f64::consts::PI - tolerance;
    if let Some(&i) = off.iter().find(|&&i| angle(i) > tolerance && !mirrored(i)) {
        return Some(format!(
            "a move turned the camera: {} expected {}, found {} ({}° apart)",
            NAMES[i],
            vec3(expected[i]),
            vec3(found[i]),
            number(angle(i).to_degrees())
        ));
    }
    let said: Vec<String> = off
        .iter()
        .map(|&i| match mirrored(i) {
            true => format!(
                "the axes are left-handed from the scene's start: u = n × v = {}, where the \
                 scene's u is {}; the move did not turn the camera",
                vec3(found[0]),
                vec3(expected[0])
            ),
            false => format!(
                "{} is {}, not unit; the move did not turn it",
                NAMES[i],
                values.then(found[i].length() / expected[i].length(), " long")
            ),
        })
        .collect();
    (!said.is_empty()).then(|| said.join("; "))
}

/// A vector as the report shows it; adding 0 makes a −0 a 0.
fn vec3(p: DVec3) -> String {
    let p = p + DVec3::ZERO;
    format!("({}, {}, {})", number(p.x), number(p.y), number(p.z))
}

#[cfg(test)]
mod tests {
    use super::super::tests::pitched;
    use super::*;

    fn values() -> Values {
        let (camera, window) = pitched();
        Values::new(&camera, window)
    }

    fn travel_of(moved: DVec3) -> Option<String> {
        travel(DVec3::new(0.0, 0.0, -2.0), moved, 1e-5, &values())
    }

    #[test]
    fn how_far_and_which_way() {
        let c = 25f64.to_radians().cos();
        assert_eq!(
            travel_of(DVec3::new(0.0, 0.0, -2.0 * c)).as_deref(),
            Some("it moved 0.9063 of the asked distance (= cos 25°, the pitch)")
        );
        assert_eq!(
            travel_of(DVec3::new(0.0, 0.0, 2.0)).as_deref(),
            Some("it moved the asked distance the other way")
        );
        assert_eq!(
            travel_of(DVec3::new(0.0, 0.0, 1.0)).as_deref(),
            Some("it moved the other way, 0.5000 of the asked distance (= 1/2)")
        );
        assert_eq!(travel_of(DVec3::ZERO).as_deref(), Some("it did not move"));
        assert_eq!(
            travel_of(DVec3::new(2.0, 0.0, 0.0)).as_deref(),
            Some("it moved 1.0000 of the asked distance, 90.0000° off the asked direction")
        );
        assert_eq!(travel(DVec3::ZERO, DVec3::X, 1e-5, &values()), None);
    }

    const START: [DVec3; 3] = [DVec3::X, DVec3::Y, DVec3::Z];

    #[test]
    fn a_shorter_u_is_not_a_turn() {
        let c = 25f64.to_radians().cos();
        let found = [DVec3::X * c, DVec3::Y, DVec3::Z];
        assert_eq!(
            axes_after_move(START, found, 1e-4, &values()).as_deref(),
            Some("u is 0.9063 long (= cos 25°, the pitch), not unit; the move did not turn it")
        );
        assert_eq!(axes_after_move(START, START, 1e-4, &values()), None);
    }

    #[test]
    fn a_left_handed_u_was_so_from_the_start() {
        let found = [DVec3::new(-1.0, 0.0, 0.0), DVec3::Y, DVec3::Z];
        assert_eq!(
            axes_after_move(START, found, 1e-4, &values()).as_deref(),
            Some(
                "the axes are left-handed from the scene's start: u = n × v = (-1.0000, 0.0000, \
                 0.0000), where the scene's u is (1.0000, 0.0000, 0.0000); the move did not turn \
                 the camera"
            )
        );
    }

    #[test]
    fn a_real_turn_is_a_turn() {
        let (s, c) = 10f64.to_radians().sin_cos();
        let found = [DVec3::new(c, 0.0, -s), DVec3::Y, DVec3::new(s, 0.0, c)];
        let said = axes_after_move(START, found, 1e-4, &values()).unwrap_or_default();
        assert!(
            said.starts_with("a move turned the camera: u expected (1.0000, 0.0000, 0.0000)")
                && said.ends_with("(10.0000° apart)"),
            "{said}"
        );
    }
}
