//! Clipping in homogeneous clip space, before the division by w: a point is inside the view
//! volume when |x|, |y|, |z| <= w (which forces w >= 0). Working before the division is what
//! keeps points behind the camera (w < 0) from wrapping around onto the screen.

use glam::Vec4;

/// One bit per plane of the view volume that a point lies outside of.
pub type Outcode = u8;

/// The six planes as signed distances: >= 0 inside, < 0 outside. Bit i of an outcode is plane i.
const PLANES: [fn(Vec4) -> f32; 6] = [
    |p| p.w + p.x, // left:   x >= -w
    |p| p.w - p.x, // right:  x <=  w
    |p| p.w + p.y, // bottom: y >= -w
    |p| p.w - p.y, // top:    y <=  w
    |p| p.w + p.z, // near:   z >= -w
    |p| p.w - p.z, // far:    z <=  w
];

/// Which planes `p` is outside of; 0 means inside the view volume. A point with w <= 0 is
/// always outside (it is at or behind the centre of projection), even where every plane test
/// would pass for w = 0. Written out plane by plane (rather than looping over [`PLANES`]) because
/// it runs once per vertex of every frame.
pub fn outcode(p: Vec4) -> Outcode {
    (p.w + p.x < 0.0) as Outcode
        | ((p.w - p.x < 0.0) as Outcode) << 1
        | ((p.w + p.y < 0.0) as Outcode) << 2
        | ((p.w - p.y < 0.0) as Outcode) << 3
        | ((p.w + p.z < 0.0 || p.w <= 0.0) as Outcode) << 4
        | ((p.w - p.z < 0.0) as Outcode) << 5
}

/// The most vertices a triangle can have after cutting by six planes (3 + 6).
pub const MAX_POLYGON: usize = 9;

/// A convex polygon in clip space, kept on the stack: clipping allocates nothing.
#[derive(Clone, Copy, Debug)]
pub struct Polygon {
    pub points: [Vec4; MAX_POLYGON],
    pub len: usize,
}

impl Polygon {
    pub fn triangle(a: Vec4, b: Vec4, c: Vec4) -> Self {
        let mut points = [Vec4::ZERO; MAX_POLYGON];
        points[..3].copy_from_slice(&[a, b, c]);
        Self { points, len: 3 }
    }

    pub fn vertices(&self) -> &[Vec4] {
        &self.points[..self.len]
    }

    fn push(&mut self, p: Vec4) {
        self.points[self.len] = p;
        self.len += 1;
    }
}

/// Sutherland–Hodgman: cuts the polygon by every plane named in `planes`, in turn. The result
/// may be empty (fewer than 3 vertices) when the polygon lies outside.
pub fn clip_polygon(polygon: &Polygon, planes: Outcode) -> Polygon {
    let mut current = *polygon;
    for (bit, plane) in PLANES.iter().enumerate() {
        if planes & (1 << bit) == 0 || current.len < 3 {
            continue;
        }
        let input = current;
        current.len = 0;
        let points = input.vertices();
        for (i, &a) in points.iter().enumerate() {
            let b = points[(i + 1) % points.len()];
            let (da, db) = (plane(a), plane(b));
            if da >= 0.0 {
                current.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                current.push(a + (b - a) * (da / (da - db)));
            }
        }
    }
    if current.len < 3 {
        current.len = 0;
    }
    current
}

/// Liang–Barsky in clip space: the part of segment a→b inside the view volume, or `None`.
/// Wireframes clip each edge as a line, as a GPU clips the edges of a polygon drawn as lines.
pub fn clip_segment(a: Vec4, b: Vec4) -> Option<(Vec4, Vec4)> {
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for plane in PLANES {
        let (da, db) = (plane(a), plane(b));
        if da < 0.0 && db < 0.0 {
            return None;
        }
        if da < 0.0 {
            t0 = t0.max(da / (da - db));
        } else if db < 0.0 {
            t1 = t1.min(da / (da - db));
        }
    }
    (t0 <= t1).then(|| (a + (b - a) * t0, a + (b - a) * t1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outcodes_name_the_planes() {
        assert_eq!(outcode(Vec4::new(0.0, 0.0, 0.0, 1.0)), 0);
        assert_eq!(
            outcode(Vec4::new(1.0, -1.0, 1.0, 1.0)),
            0,
            "the border is inside"
        );
        assert_eq!(outcode(Vec4::new(2.0, 0.0, 0.0, 1.0)), 0b10);
        assert_eq!(outcode(Vec4::new(0.0, 0.0, -2.0, 1.0)), 0b1_0000);
        assert_ne!(
            outcode(Vec4::new(0.0, 0.0, 0.0, -1.0)) & 0b1_0000,
            0,
            "behind the camera"
        );
        assert_ne!(outcode(Vec4::ZERO), 0, "the centre of projection itself");
    }

    #[test]
    fn a_triangle_through_the_near_plane_becomes_a_quad() {
        // Two corners in front (z = 0), one far behind the near plane (z < -w).
        let t = Polygon::triangle(
            Vec4::new(-0.5, 0.0, 0.0, 1.0),
            Vec4::new(0.5, 0.0, 0.0, 1.0),
            Vec4::new(0.0, 0.5, -3.0, 1.0),
        );
        let clipped = clip_polygon(&t, outcode(t.points[2]));
        assert_eq!(clipped.len, 4);
        for p in clipped.vertices() {
            assert_eq!(outcode(*p) & !0b1_0000, 0);
            assert!(p.z >= -p.w - 1e-6, "{p:?} is behind the near plane");
        }
    }

    #[test]
    fn a_triangle_outside_clips_to_nothing() {
        let t = Polygon::triangle(
            Vec4::new(2.0, 0.0, 0.0, 1.0),
            Vec4::new(3.0, 0.0, 0.0, 1.0),
            Vec4::new(2.0, 1.0, 0.0, 1.0),
        );
        assert_eq!(clip_polygon(&t, 0b10).len, 0);
    }

    #[test]
    fn segments_are_cut_at_the_planes() {
        let (a, b) = clip_segment(
            Vec4::new(-3.0, 0.0, 0.0, 1.0),
            Vec4::new(3.0, 0.0, 0.0, 1.0),
        )
        .expect("crosses the volume");
        assert!((a.x + 1.0).abs() < 1e-6 && (b.x - 1.0).abs() < 1e-6);
        assert!(
            clip_segment(Vec4::new(2.0, 0.0, 0.0, 1.0), Vec4::new(3.0, 2.0, 0.0, 1.0)).is_none()
        );
    }
}
