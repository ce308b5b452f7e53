//! The triangles of a `.in` file as both of its readers build them (`in_format` line by line,
//! `in_parallel` in blocks on all cores): what a vertex record holds, one triangle as the file
//! gives it, its normals oriented by its face, and the body of triangles it is added to.

use glam::{Vec2, Vec3};

use crate::mesh_builder::{Corner, MeshBuilder};

/// The tags of a triangle's three vertex records.
pub(crate) const VERTEX_TAGS: [&str; 3] = ["v0", "v1", "v2"];

/// The triangles read so far: the mesh being built and what orienting them corrected.
pub(crate) struct Body {
    pub(crate) builder: MeshBuilder,
    pub(crate) orientation: Orientation,
    pub(crate) triangles: u64,
}

impl Body {
    pub(crate) fn new(builder: MeshBuilder) -> Self {
        Self {
            builder,
            orientation: Orientation::default(),
            triangles: 0,
        }
    }

    /// Adds a triangle as the file gives it.
    pub(crate) fn add(&mut self, triangle: FileTriangle) -> Result<(), String> {
        let face_normal = triangle.face_normal();
        let corners = self.orientation.orient(triangle).corners();
        self.add_corners(&corners, face_normal)
    }

    /// Adds the corners of a triangle [`Orientation::orient`] has seen (whose counts the caller
    /// keeps), with the file's face normal.
    pub(crate) fn add_corners(
        &mut self,
        corners: &[Corner; 3],
        face_normal: Vec3,
    ) -> Result<(), String> {
        let mut indices = [0; 3];
        for (index, corner) in indices.iter_mut().zip(corners) {
            *index = self.builder.corner(corner)?;
        }
        self.builder.triangle(indices);
        self.builder.face_normal(face_normal);
        self.triangles += 1;
        Ok(())
    }
}

/// What each vertex record holds after its position and normal.
pub(crate) struct VertexLayout {
    /// How many numbers a vertex record has: 9 when `<s> <t>` follow (`Texture = YES`), 7 when
    /// not; either when the file has no `Texture =` line.
    pub(crate) counts: &'static [usize],
    /// The expected form of the v0, v1 and v2 records, for errors.
    pub(crate) forms: [String; 3],
    pub(crate) material_count: u64,
}

impl VertexLayout {
    pub(crate) fn new(texture: Option<bool>, material_count: u64) -> Self {
        let (counts, st): (&'static [usize], &str) = match texture {
            Some(true) => (&[9], " s t"),
            Some(false) => (&[7], ""),
            None => (&[7, 9], ""),
        };
        Self {
            counts,
            forms: VERTEX_TAGS.map(|tag| format!("{tag} x y z nx ny nz material{st}")),
            material_count,
        }
    }

    /// Whether `material` (a finite number) indexes one of the file's material blocks.
    pub(crate) fn is_material(&self, material: f32) -> bool {
        material.fract() == 0.0
            && material >= 0.0
            && f64::from(material) < self.material_count as f64
    }
}

/// One triangle as the file gives it: corners in file winding, their texture coordinates when
/// the records carry `s t`, and the face normal.
#[derive(Default)]
pub(crate) struct FileTriangle {
    positions: [Vec3; 3],
    normals: [Vec3; 3],
    uvs: [Option<Vec2>; 3],
    face_normal: Vec3,
}

impl FileTriangle {
    /// Corner `k` from the numbers of its record (`x y z nx ny nz material [s t]`).
    pub(crate) fn set_corner(&mut self, k: usize, v: &[f32]) {
        self.positions[k] = Vec3::new(v[0], v[1], v[2]);
        self.normals[k] = Vec3::new(v[3], v[4], v[5]);
        self.uvs[k] = (v.len() == 9).then(|| Vec2::new(v[7], v[8]));
    }

    pub(crate) fn set_face_normal(&mut self, n: &[f32]) {
        self.face_normal = Vec3::new(n[0], n[1], n[2]);
    }

    /// The face normal as the file gives it.
    pub(crate) fn face_normal(&self) -> Vec3 {
        self.face_normal
    }

    /// The corners as the mesh builder takes them.
    pub(crate) fn corners(&self) -> [Corner; 3] {
        [0, 1, 2].map(|k| Corner::new(self.positions[k], self.normals[k], self.uvs[k]))
    }
}

/// Orients vertex normals by the face normal and the winding, which the spec makes the ground
/// truth, and counts what it had to correct.
#[derive(Default)]
pub(crate) struct Orientation {
    flipped: usize,
    face_against_winding: usize,
}

impl Orientation {
    /// The triangle with each vertex normal unit length and on its face's side.
    pub(crate) fn orient(&mut self, mut t: FileTriangle) -> FileTriangle {
        let [a, b, c] = t.positions;
        let geometric = (b - a).cross(c - a).try_normalize();
        let face = t.face_normal.try_normalize();
        if let (Some(f), Some(g)) = (face, geometric)
            && f.dot(g) < 0.0
        {
            self.face_against_winding += 1;
        }
        let reference = face.or(geometric);
        for normal in &mut t.normals {
            let mut unit = normal.try_normalize().or(reference);
            if let (Some(n), Some(r)) = (unit, reference)
                && n.dot(r) < 0.0
            {
                unit = Some(-n);
                self.flipped += 1;
            }
            // Only a zero-area triangle with no usable normal gets here: it has no side to
            // show, so any unit vector will do.
            *normal = unit.unwrap_or(Vec3::Z);
        }
        t
    }

    /// Adds what `other` counted (on another part of the file).
    pub(crate) fn absorb(&mut self, other: &Orientation) {
        self.flipped += other.flipped;
        self.face_against_winding += other.face_against_winding;
    }

    pub(crate) fn warnings(&self, label: &str) -> impl Iterator<Item = String> {
        let flipped = (self.flipped > 0).then(|| {
            format!(
                "{label}: {} vertex normals pointed against their face normal and were flipped",
                self.flipped
            )
        });
        let against = (self.face_against_winding > 0).then(|| {
            format!(
                "{label}: {} face normals point against their triangle's winding",
                self.face_against_winding
            )
        });
        flipped.into_iter().chain(against)
    }
}
