//! The motion lines: where the final camera is after the scene's `move`, `orbit` or `rotate`,
//! against what close2gl expects ([`Pose`]), with the accepted variants (an arc for an orbit,
//! the other way round for a rotation, consistently).

use close2gl_trace_format::{Axis, Motion};
use glam::DVec3;

use super::{AXIS, Judge, POSITION, Verdict, stages_agree, vec3};
use crate::clues::{self, Values};
use crate::rubric::expected_motion::Pose;
use crate::rubric::scenes::default_lookat;
use crate::vocabulary::Stage;
use crate::words::number;

/// "About the asked amount": an orbit may land this fraction of its length from a straight
/// move or an arc.
const ABOUT: f64 = 0.03;

/// Which way a program's rotations turn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    RightHand,
    OtherWay,
}

/// A program's convention is the way most of its rotations turn (the right-hand rule on a
/// tie); a rotation that passed the other way round from it fails: the rule must hold for
/// every axis and sign.
pub(crate) fn settle_rotations(verdicts: &mut [&mut Verdict]) {
    let count = |turn| verdicts.iter().filter(|v| v.turn == Some(turn)).count();
    let convention = match count(Turn::OtherWay) > count(Turn::RightHand) {
        true => Turn::OtherWay,
        false => Turn::RightHand,
    };
    for verdict in verdicts.iter_mut() {
        if verdict.turn.is_some_and(|turn| turn != convention) {
            **verdict = Verdict::fail(match convention {
                Turn::RightHand => "it turns the other way round from its other rotations",
                Turn::OtherWay => {
                    "it turns by the right-hand rule, its other rotations the other way round"
                }
            });
        }
    }
}

impl Judge<'_> {
    pub(super) fn translation(&self) -> Verdict {
        let start = Pose::of(&self.start);
        let expected = self
            .scene
            .motions
            .iter()
            .fold(start, |pose, motion| match *motion {
                Motion::Move(axis, d) => pose.moved(axis, d),
                _ => pose,
            });
        let found = Pose::of(&self.trace.camera);
        let travel: f64 = self.scene.motions.iter().map(motion_amount).sum();
        let tolerance = POSITION * (expected.position.length() + travel + 1.0);
        if expected.position.distance(found.position) > tolerance {
            let mut why = format!(
                "the camera expected at {}, found at {}",
                vec3(expected.position),
                vec3(found.position)
            );
            let (asked, moved) = (
                expected.position - start.position,
                found.position - start.position,
            );
            let hint = along_world_axis(
                &self.scene.motions,
                start.position,
                found.position,
                tolerance,
            )
            .or_else(|| clues::travel(asked, moved, tolerance, &self.values()));
            if let Some(hint) = hint {
                why.push_str(&format!(" ({hint})"));
            }
            return Verdict::fail(why);
        }
        let axes = |pose: &Pose| [pose.u, pose.v, pose.n];
        if let Some(why) =
            clues::axes_after_move(axes(&expected), axes(&found), AXIS, &self.values())
        {
            return Verdict::fail(why);
        }
        stages_agree(&self.report.comparison, &[Stage::M])
    }

    /// The values a clue may name for this trace's camera and window.
    fn values(&self) -> Values {
        Values::new(&self.trace.camera, self.trace.window)
    }

    pub(super) fn orbit(&self) -> Verdict {
        let Some(&Motion::Orbit(axis, d)) = self.scene.motions.first() else {
            return Verdict::fail("the scene has no orbit");
        };
        let lookat = (self.scene.lookat).unwrap_or_else(|| default_lookat(self.mesh));
        let camera = &self.trace.camera;
        let axes = stages_agree(&self.report.comparison, &[Stage::Camera]);
        if !axes.passed {
            return axes;
        }
        let toward = (camera.position - lookat).normalize();
        if camera.n.distance(toward) > 1e-3 {
            return Verdict::fail(format!(
                "n does not point from the look-at point {} to the camera: expected {}, found {}",
                vec3(lookat),
                vec3(toward),
                vec3(camera.n)
            ));
        }
        let start = Pose::of(&self.start);
        let straight = start.orbited_straight(axis, d);
        let arc = start.orbited_arc(axis, d, lookat);
        let tolerance = ABOUT * d.abs();
        if camera.position.distance(straight) <= tolerance {
            Verdict::pass("a straight move, then turned back to the look-at point")
        } else if camera.position.distance(arc) <= tolerance {
            Verdict::pass("an arc around the look-at point")
        } else {
            Verdict::fail(format!(
                "orbit {} {}: the camera expected near {} (a straight move) or {} (an arc \
                 around the look-at point), found at {}",
                axis_name(axis),
                number(d),
                vec3(straight),
                vec3(arc),
                vec3(camera.position)
            ))
        }
    }

    pub(super) fn rotation(&self) -> Verdict {
        let Some(&Motion::Rotate(axis, degrees)) = self.scene.motions.first() else {
            return Verdict::fail("the scene has no rotation");
        };
        let axes = stages_agree(&self.report.comparison, &[Stage::Camera]);
        if !axes.passed {
            return axes;
        }
        let start = Pose::of(&self.start);
        let found = Pose::of(&self.trace.camera);
        let tolerance = POSITION * (start.position.length() + 1.0);
        if start.position.distance(found.position) > tolerance {
            return Verdict::fail(format!(
                "a rotation moved the camera from {} to {}",
                vec3(start.position),
                vec3(found.position)
            ));
        }
        let right_hand = start.rotated(axis, degrees);
        let other_way = start.rotated(axis, -degrees);
        if same_axes(&right_hand, &found) {
            return Verdict {
                turn: Some(Turn::RightHand),
                ..Verdict::pass("")
            };
        }
        if same_axes(&other_way, &found) {
            return Verdict {
                turn: Some(Turn::OtherWay),
                ..Verdict::pass("the other way round from the right-hand rule")
            };
        }
        if axis == Axis::N && start.n.distance(found.n) > AXIS {
            return Verdict::fail(format!(
                "the roll changed the view direction: n expected {}, found {}",
                vec3(start.n),
                vec3(found.n)
            ));
        }
        let (name, want, other, got) = [
            ("u", right_hand.u, other_way.u, found.u),
            ("v", right_hand.v, other_way.v, found.v),
            ("n", right_hand.n, other_way.n, found.n),
        ]
        .into_iter()
        .max_by(|a, b| a.1.distance(a.3).total_cmp(&b.1.distance(b.3)))
        .unwrap_or(("u", right_hand.u, other_way.u, found.u));
        Verdict::fail(format!(
            "rotate {} {}: {name} expected {} by the right-hand rule (or {} the other way \
             round), found {}",
            axis_name(axis),
            number(degrees),
            vec3(want),
            vec3(other),
            vec3(got)
        ))
    }
}

/// Whether u, v and n are each where expected.
fn same_axes(expected: &Pose, found: &Pose) -> bool {
    [
        (expected.u, found.u),
        (expected.v, found.v),
        (expected.n, found.n),
    ]
    .iter()
    .all(|(want, got)| want.distance(*got) <= AXIS)
}

/// When a move went along the world's axis instead of the camera's: says so.
fn along_world_axis(
    motions: &[Motion],
    start: DVec3,
    found: DVec3,
    tolerance: f64,
) -> Option<String> {
    let world = motions.iter().fold(start, |p, motion| match *motion {
        Motion::Move(axis, d) => p + d * world_axis(axis),
        _ => p,
    });
    (world.distance(found) <= tolerance)
        .then(|| "it moved along the world's x, y, z axes, not the camera's u, v, n".to_string())
}

fn world_axis(axis: Axis) -> DVec3 {
    match axis {
        Axis::U => DVec3::X,
        Axis::V => DVec3::Y,
        Axis::N => DVec3::Z,
    }
}

fn motion_amount(motion: &Motion) -> f64 {
    match *motion {
        Motion::Move(_, d) | Motion::Orbit(_, d) => d.abs(),
        Motion::Rotate(..) => 0.0,
    }
}

fn axis_name(axis: Axis) -> &'static str {
    close2gl_core::NamedEnum::name(axis)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turned(turn: Turn) -> Verdict {
        Verdict {
            turn: Some(turn),
            ..Verdict::pass("")
        }
    }

    #[test]
    fn the_way_most_rotations_turn_is_the_convention_and_the_others_fail() {
        let mut verdicts = [
            turned(Turn::OtherWay),
            turned(Turn::OtherWay),
            turned(Turn::RightHand),
            Verdict::fail("no"),
        ];
        settle_rotations(&mut verdicts.iter_mut().collect::<Vec<_>>());
        let passed: Vec<bool> = verdicts.iter().map(|v| v.passed).collect();
        assert_eq!(passed, [true, true, false, false]);
        let mut tie = [turned(Turn::OtherWay), turned(Turn::RightHand)];
        settle_rotations(&mut tie.iter_mut().collect::<Vec<_>>());
        assert_eq!(
            tie.map(|v| v.passed),
            [false, true],
            "a tie goes to the right-hand rule"
        );
    }
}
