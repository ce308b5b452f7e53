//! Clipping in homogeneous clip space, before the division by w: a point is inside the view
//! volume when |x|, |y|, |z| <= w (which forces w >= 0). Working before the division is what
//! keeps points behind the camera (w < 0) from wrapping around onto the screen.

use glam::{Vec3, Vec4};

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

/// The near plane's bit: the one plane a GPU must cut geometrically, since dividing by w needs
/// w > 0 (the others it may apply per pixel: the viewport's edges and the depth range).
pub const NEAR: Outcode = 1 << 4;

/// The far plane's bit.
pub const FAR: Outcode = 1 << 5;

/// Which planes `p` is outside of; 0 means inside the view volume. A point with w <= 0 is
/// always outside (it is at or behind the centre of projection), even where every plane test
/// would pass for w = 0. Written out plane by plane (rather than looping over `PLANES`) because
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

/// A convex polygon in clip space, kept on the stack: clipping allocates nothing. `original[i]`
/// says whether the edge from vertex i to vertex i + 1 is part of one of the triangle's own edges
/// (OpenGL's edge flag) rather than an edge the clipping planes added: a GPU draws only those in
/// line mode, and only their starting vertices in point mode. `weights[i]` says where vertex i
/// lies in the triangle (the weights of its three corners), for interpolating what the corners
/// carry.
#[derive(Clone, Copy, Debug)]
pub struct Polygon {
    pub points: [Vec4; MAX_POLYGON],
    pub original: [bool; MAX_POLYGON],
    pub weights: [Vec3; MAX_POLYGON],
    pub len: usize,
}

impl Polygon {
    pub fn triangle(a: Vec4, b: Vec4, c: Vec4) -> Self {
        let mut points = [Vec4::ZERO; MAX_POLYGON];
        points[..3].copy_from_slice(&[a, b, c]);
        let mut weights = [Vec3::ZERO; MAX_POLYGON];
        weights[..3].copy_from_slice(&[Vec3::X, Vec3::Y, Vec3::Z]);
        Self {
            points,
            original: [true; MAX_POLYGON],
            weights,
            len: 3,
        }
    }

    pub fn vertices(&self) -> &[Vec4] {
        &self.points[..self.len]
    }

    /// Appends a vertex; false when the polygon is already [`MAX_POLYGON`] long.
    #[must_use]
    fn push(&mut self, p: Vec4, original: bool, weights: Vec3) -> bool {
        if self.len == MAX_POLYGON {
            return false;
        }
        self.points[self.len] = p;
        self.original[self.len] = original;
        self.weights[self.len] = weights;
        self.len += 1;
        true
    }
}

/// Sutherland–Hodgman: cuts the polygon by every plane named in `planes`, in turn (each by
/// [`clip_step`]). The result may be empty (fewer than 3 vertices) when the polygon lies
/// outside, or when a step would pass [`MAX_POLYGON`] vertices.
pub fn clip_polygon(polygon: &Polygon, planes: Outcode) -> Polygon {
    let mut current = *polygon;
    for bit in 0..PLANES.len() {
        if planes & (1 << bit) == 0 || current.len < 3 {
            continue;
        }
        match clip_step(&current, bit) {
            Some(next) => current = next,
            None => return Polygon { len: 0, ..current },
        }
    }
    if current.len < 3 {
        current.len = 0;
    }
    current
}

/// One step of Sutherland–Hodgman: the polygon cut by plane `bit` (its bit in an outcode).
/// Where an edge leaves the volume, the new vertex starts an edge along the plane (not
/// original); where an edge comes back in, the new vertex starts what remains of the outside
/// vertex's edge. Each new vertex's weights are its edge's ends' weights, interpolated.
///
/// None when the cut would pass [`MAX_POLYGON`] vertices. A convex polygon gains at most one
/// vertex per plane, but with coordinates near f32's limits the distances to the planes
/// overflow or round into a polygon that is no longer convex, and a plane may then add several:
/// such a piece is rounding noise, dropped as clipped rather than overrunning the arrays.
pub fn clip_step(input: &Polygon, bit: usize) -> Option<Polygon> {
    let plane = PLANES[bit];
    let mut output = Polygon { len: 0, ..*input };
    for i in 0..input.len {
        let j = (i + 1) % input.len;
        let (a, b) = (input.points[i], input.points[j]);
        let (da, db) = (plane(a), plane(b));
        if da >= 0.0 && !output.push(a, input.original[i], input.weights[i]) {
            return None;
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            let cut = a + (b - a) * t;
            let weights = input.weights[i] + (input.weights[j] - input.weights[i]) * t;
            let leaving = da >= 0.0;
            if !output.push(cut, !leaving && input.original[i], weights) {
                return None;
            }
        }
    }
    Some(output)
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
    fn edges_added_by_clipping_are_not_original() {
        // Corner 2 is behind the near plane: the edge between the two cut points lies on the
        // plane, every other edge is what is left of the triangle's own edges.
        let t = Polygon::triangle(
            Vec4::new(-0.5, 0.0, 0.0, 1.0),
            Vec4::new(0.5, 0.0, 0.0, 1.0),
            Vec4::new(0.0, 0.5, -3.0, 1.0),
        );
        let clipped = clip_polygon(&t, outcode(t.points[2]));
        assert_eq!(&clipped.original[..4], &[true, true, false, true]);
    }
}
