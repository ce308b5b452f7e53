//! The outside view's settings and its own orbit camera: small data the config, the panel, the
//! keys and the renderer share.

use bevy_ecs::prelude::*;

/// The three spaces the outside view's stage slider passes through, by their stop on it.
pub const STAGE_NAMES: [(&str, f32); 3] = [("world", 0.0), ("eye", 1.0), ("ndc", 2.0)];

/// Whether the outside view is shown, and at which stage of the pipeline: 0 = world
/// coordinates, 1 = eye coordinates (M applied), 2 = normalised device coordinates (P applied and
/// divided); between two stops the positions are interpolated.
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct OutsideView {
    pub show: bool,
    pub stage: f32,
}

impl Default for OutsideView {
    fn default() -> Self {
        Self {
            show: false,
            stage: 0.0,
        }
    }
}

impl OutsideView {
    /// The last stage.
    pub const MAX_STAGE: f32 = 2.0;

    /// A stage by its name (`world`, `eye`, `ndc`).
    pub fn stage_named(name: &str) -> Option<f32> {
        STAGE_NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, stage)| *stage)
    }
}

/// The outside view's own orbit camera, independent of the Close2GL camera: it turns about the
/// centre of what it frames (the model, the eye and the near plane; or the whole view volume
/// with them). Angles in radians; `zoom` scales the framed distance (below 1 is closer).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct OutsideOrbit {
    pub yaw: f32,
    pub pitch: f32,
    pub zoom: f32,
    /// Frame the whole view volume, far plane included, rather than the model and the near part.
    pub whole_volume: bool,
}

impl Default for OutsideOrbit {
    /// A three-quarter view from the right, above: the camera's side and the volume's depth
    /// both show.
    fn default() -> Self {
        Self {
            yaw: 0.9,
            pitch: 0.45,
            zoom: 1.0,
            whole_volume: false,
        }
    }
}

impl OutsideOrbit {
    /// How far the pitch may go: just short of straight up or down, where the orbit's up
    /// direction would be undefined.
    pub const MAX_PITCH: f32 = 1.55;
    pub const ZOOM_RANGE: std::ops::RangeInclusive<f32> = 0.05..=20.0;

    /// Turns by a mouse drag of `dx`, `dy` pixels.
    pub fn drag(&mut self, dx: f32, dy: f32) {
        const RADIANS_PER_PIXEL: f32 = 0.01;
        self.yaw -= dx * RADIANS_PER_PIXEL;
        self.pitch = (self.pitch + dy * RADIANS_PER_PIXEL).clamp(-Self::MAX_PITCH, Self::MAX_PITCH);
    }

    /// Moves closer by `lines` of scroll (negative: away).
    pub fn scroll(&mut self, lines: f32) {
        let zoom = self.zoom * 0.9f32.powf(lines);
        self.zoom = zoom.clamp(*Self::ZOOM_RANGE.start(), *Self::ZOOM_RANGE.end());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_orbit_keeps_its_pitch_and_zoom_in_range() {
        let mut orbit = OutsideOrbit::default();
        orbit.drag(0.0, 1e6);
        assert_eq!(orbit.pitch, OutsideOrbit::MAX_PITCH);
        orbit.scroll(1e4);
        assert_eq!(orbit.zoom, *OutsideOrbit::ZOOM_RANGE.start());
        orbit.scroll(-2.0);
        assert!(orbit.zoom > *OutsideOrbit::ZOOM_RANGE.start());
    }

    #[test]
    fn the_stage_names_are_the_slider_stops() {
        assert_eq!(OutsideView::stage_named("eye"), Some(1.0));
        assert_eq!(
            OutsideView::stage_named("ndc"),
            Some(OutsideView::MAX_STAGE)
        );
        assert_eq!(OutsideView::stage_named("clip"), None);
    }
}
