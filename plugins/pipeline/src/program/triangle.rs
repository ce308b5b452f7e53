//! One mesh triangle down a program's stages, in the textbook's order: transform, clip (by the
//! program's rule), divide, map by V, cull (by the program's rule, where it tests the winding),
//! and what float32 rounding could do to each number the program writes.

use close2gl_core::{FateKind, FrontFace, Mesh, Topology, TriangleFate};
use glam::{DMat3, DMat4, DVec2, DVec3, DVec4};

use super::{ClipRule, CullRule, Program, WindingSpace, planes_mask};
use crate::clip::{NEAR, Polygon, clip_polygon, outcode};
use crate::stage::face;
use crate::{emit, rounding};

impl Program {
    /// Mesh triangle `index` down the stages: its clip coordinates, its fate, and what it drew.
    /// None when the mesh has no such triangle.
    pub fn triangle(&self, mesh: &Mesh, index: usize) -> Option<TriangleOutcome> {
        let corners = *mesh.triangles.get(index)?;
        let world = corners.map(|i| self.world(mesh, i));
        let clip = world.map(|p| self.clip_matrix * p.extend(1.0));
        let terms = rounding::clip_terms(self.clip_matrix, self.camera.position, &world);
        let mut outcome = TriangleOutcome {
            clip,
            fate: TriangleFate::default(),
            polygon: Vec::new(),
            depths: Vec::new(),
            edges: Vec::new(),
            weights: Vec::new(),
            inv_w: Vec::new(),
            near_a_plane: rounding::near_a_plane(&clip, terms),
            near_edge_on: false,
            terms,
            errors: Vec::new(),
            depth_errors: Vec::new(),
        };
        if let Some(piece) = self.clipped(&clip, &mut outcome) {
            self.divide_map_cull(mesh, index, &world, &piece, &mut outcome);
        }
        Some(outcome)
    }

    /// The clipped piece divided by w, mapped by V and culled, into `outcome`: its fate and,
    /// when drawn, its polygon with each vertex's depth and what rounding could do to both.
    fn divide_map_cull(
        &self,
        mesh: &Mesh,
        index: usize,
        world: &[DVec3; 3],
        piece: &[DVec4],
        outcome: &mut TriangleOutcome,
    ) {
        let ndc: Vec<DVec3> = piece.iter().map(|p| p.truncate() / p.w).collect();
        let system: Vec<DVec2> = ndc.iter().map(|&p| self.in_system(p)).collect();
        if system.iter().any(|p| !p.is_finite()) {
            outcome.fate.kind = FateKind::Clipped;
            return;
        }
        let (pixels, tested) = self.windings(&ndc, &system);
        outcome.errors = piece
            .iter()
            .zip(&system)
            .map(|(&c, &p)| rounding::window_error(self.v, outcome.terms, c, p))
            .collect();
        let (area, culled) = self.cull(mesh, index, world, [&pixels, &tested], outcome);
        let uncertain = rounding::twice_area_error(&system, &outcome.errors);
        outcome.near_edge_on |= rounding::twice_area(&system).abs() <= uncertain;
        outcome.fate.signed_area = area;
        if let Some(kind) = culled {
            outcome.fate.kind = kind;
            return;
        }
        outcome.fate.kind = match outcome.fate.planes {
            0 => FateKind::Drawn,
            _ => FateKind::Cut,
        };
        outcome.depths = ndc.iter().map(|p| p.z).collect();
        outcome.depth_errors = piece
            .iter()
            .map(|&c| rounding::depth_error(outcome.terms, c))
            .collect();
        outcome.inv_w = piece.iter().map(|p| 1.0 / p.w).collect();
        outcome.polygon = system;
    }

    /// An NDC point mapped by V into the declared 2D system.
    fn in_system(&self, ndc: DVec3) -> DVec2 {
        (self.v * ndc.extend(1.0)).truncate().truncate()
    }

    /// The corners `topology` draws of what `outcome` drew, each with what the rasterizer
    /// needs: its polygon's, or in point mode, of a triangle clipping cut, [`emit::points`] of
    /// its corners (f32 clip coordinates, as its clipping), divided and mapped as the polygon.
    /// Empty when it drew nothing.
    pub fn drawn_corners(&self, outcome: &TriangleOutcome, topology: Topology) -> Vec<DrawnCorner> {
        if topology == Topology::Points && outcome.fate.kind == FateKind::Cut {
            let single = outcome.clip.map(|c| c.as_vec4());
            let triangle = Polygon::triangle(single[0], single[1], single[2]);
            let points = emit::points(
                &triangle,
                outcome.fate.planes,
                planes_mask(self.declared.planes),
            );
            return (points.vertices().iter().zip(points.weights))
                .map(|(p, weights)| {
                    let clip = p.as_dvec4();
                    let ndc = clip.truncate() / clip.w;
                    DrawnCorner {
                        at: self.in_system(ndc),
                        depth: ndc.z,
                        inv_w: 1.0 / clip.w,
                        weights: weights.to_array(),
                        own: true,
                    }
                })
                .collect();
        }
        (0..outcome.polygon.len())
            .map(|i| DrawnCorner {
                at: outcome.polygon[i],
                depth: outcome.depths[i],
                inv_w: outcome.inv_w[i],
                weights: outcome.weights[i],
                own: outcome.edges[i],
            })
            .collect()
    }

    /// The piece's corners on screen (window pixels, y down) and where the program tests the
    /// winding (y down too: the pipeline's facing test reads it so, and y up is negated).
    fn windings(&self, ndc: &[DVec3], system: &[DVec2]) -> (Vec<[f32; 2]>, Vec<[f32; 2]>) {
        let (w, h) = self.declared.window;
        let pixels: Vec<[f32; 2]> = system
            .iter()
            .map(|&p| {
                let px = self.declared.system.to_pixels(p, w, h);
                [px.x as f32, px.y as f32]
            })
            .collect();
        let tested: Vec<[f32; 2]> = match self.declared.winding {
            WindingSpace::Screen => pixels.clone(),
            WindingSpace::Ndc => ndc.iter().map(|p| [p.x as f32, -p.y as f32]).collect(),
            WindingSpace::Window => system.iter().map(|p| [p.x as f32, -p.y as f32]).collect(),
        };
        (pixels, tested)
    }

    /// The clip rule: the polygon to divide (clip coordinates) and, in `outcome`, which planes
    /// cut it and which of its edges are the triangle's own; None when the triangle is removed
    /// whole (its fate then says why).
    fn clipped(&self, clip: &[DVec4; 3], outcome: &mut TriangleOutcome) -> Option<Vec<DVec4>> {
        let single = clip.map(|c| c.as_vec4());
        let mask = planes_mask(self.declared.planes);
        let codes = single.map(|c| outcode(c) & mask);
        let (any, all) = (
            codes[0] | codes[1] | codes[2],
            codes[0] & codes[1] & codes[2],
        );
        let whole = |outcome: &mut TriangleOutcome| {
            outcome.edges = vec![true; 3];
            outcome.weights = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
            Some(clip.to_vec())
        };
        let removed = |outcome: &mut TriangleOutcome, planes: u8| {
            outcome.fate.kind = FateKind::Clipped;
            outcome.fate.planes = planes;
            outcome.fate.behind_eye = clip.iter().all(|c| c.w <= 0.0);
            None
        };
        if self.divides_first {
            let outside =
                |c: &DVec4| c.w == 0.0 || (c.x / c.w).abs() > 1.0 || (c.y / c.w).abs() > 1.0;
            return match clip.iter().any(outside) {
                true => removed(outcome, any),
                false => whole(outcome),
            };
        }
        match self.clip {
            ClipRule::Nothing if clip.iter().any(|c| c.w == 0.0) => removed(outcome, NEAR),
            ClipRule::Nothing => whole(outcome),
            _ if any == 0 => whole(outcome),
            ClipRule::Simple => removed(outcome, any),
            _ if all != 0 => removed(outcome, all),
            ClipRule::Full => {
                let piece = clip_polygon(&Polygon::triangle(single[0], single[1], single[2]), any);
                if piece.len < 3 {
                    return removed(outcome, any);
                }
                outcome.fate.planes = any;
                outcome.edges = piece.original[..piece.len].to_vec();
                outcome.weights = piece.weights[..piece.len]
                    .iter()
                    .map(|w| w.to_array())
                    .collect();
                Some(piece.vertices().iter().map(|p| p.as_dvec4()).collect())
            }
        }
    }

    /// The cull rule: twice the signed window area (y down, as the pipeline's) and, when the
    /// triangle is culled, why. `tested`: the piece's corners where the program tests the
    /// winding (y down), `pixels` on screen.
    fn cull(
        &self,
        mesh: &Mesh,
        index: usize,
        world: &[DVec3; 3],
        [pixels, tested]: [&[[f32; 2]]; 2],
        outcome: &mut TriangleOutcome,
    ) -> (f32, Option<FateKind>) {
        let (_, winding) = face::<true>(
            tested,
            match self.cull {
                CullRule::Winding(front) => Some(front),
                _ => None,
            },
        );
        let area = face::<true>(pixels, None).0;
        let mut side = |normal: DVec3, towards: DVec3, front: FrontFace| {
            let dot = normal.dot(towards);
            outcome.near_edge_on = dot.abs() <= rounding::dot_error(normal, towards);
            let back = match front {
                FrontFace::Ccw => dot < 0.0,
                FrontFace::Cw => dot > 0.0,
            };
            back.then_some(FateKind::Culled)
        };
        let culled = match self.cull {
            CullRule::Off => None,
            CullRule::Winding(_) => winding,
            CullRule::FileNormals(front) => {
                let normal = file_normal(mesh, index, self.declared.model);
                side(normal, self.camera.position - world[0], front)
            }
            CullRule::ViewAxis(front) => {
                let normal = (world[1] - world[0]).cross(world[2] - world[0]);
                side(normal, self.camera.n, front)
            }
        };
        (area, culled)
    }
}

/// What one mesh triangle became in a program's Close2GL.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleOutcome {
    /// Its corners' clip coordinates, before clipping.
    pub clip: [DVec4; 3],
    /// Drawn, cut, clipped, culled or zero_area, with the planes and the signed area (the
    /// pipeline's record; never no_pixels or hidden, which only a rasterizer knows).
    pub fate: TriangleFate,
    /// What it drew, in the declared 2D system: the triangle, or the polygon clipping left of
    /// it; empty when it drew nothing.
    pub polygon: Vec<DVec2>,
    /// The NDC depth (z/w) of each vertex of `polygon`.
    pub depths: Vec<f64>,
    /// Whether the edge from vertex i to i + 1 is part of one of the triangle's own edges
    /// (wireframe draws only those); one per vertex of `polygon`.
    pub edges: Vec<bool>,
    /// Where each vertex of `polygon` lies in the triangle: its corners' weights.
    pub weights: Vec<[f32; 3]>,
    /// 1/w of each vertex of `polygon`, for perspective-correct interpolation.
    pub inv_w: Vec<f64>,
    /// A corner lies on a plane of the view volume to rounding: whether it is inside is for the
    /// program's rounding to say, and either clipping decision is right.
    pub near_a_plane: bool,
    /// The facing test's value is rounding (seen edge-on): either culling decision is right.
    pub near_edge_on: bool,
    /// The magnitude of the terms each row of its clip coordinates sums
    /// ([`rounding::clip_terms`]): what a float32 program's rounding scales with.
    pub terms: DVec4,
    /// How far a float32 program may put each vertex of `polygon`, in the 2D system's units
    /// ([`rounding::window_error`]).
    pub errors: Vec<f64>,
    /// How far its NDC depth at each vertex of `polygon` may be off.
    pub depth_errors: Vec<f64>,
}

impl TriangleOutcome {
    /// Whether it drew anything.
    pub fn drawn(&self) -> bool {
        !self.polygon.is_empty()
    }
}

/// A corner of what a program drew, as its mode draws it ([`Program::drawn_corners`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnCorner {
    /// Where, in the declared 2D system.
    pub at: DVec2,
    /// Its NDC depth (z/w).
    pub depth: f64,
    /// 1/w, for perspective-correct interpolation.
    pub inv_w: f64,
    /// Where it lies in the triangle: its corners' weights.
    pub weights: [f32; 3],
    /// Whether the edge it starts is part of one of the triangle's own edges.
    pub own: bool,
}

/// The file's face normal of triangle `index`; for a model without them (an OBJ), the mean of
/// its three corner normals, as `trace-format.md` pins it. A model matrix turns it by its
/// inverse transpose, as normals turn.
fn file_normal(mesh: &Mesh, index: usize, model: DMat4) -> DVec3 {
    let normal = file_normal_as_read(mesh, index);
    match model == DMat4::IDENTITY {
        true => normal,
        false => DMat3::from_mat4(model).inverse().transpose() * normal,
    }
}

fn file_normal_as_read(mesh: &Mesh, index: usize) -> DVec3 {
    match mesh.face_normals.get(index) {
        Some(normal) => normal.as_dvec3(),
        None => {
            mesh.triangles[index]
                .iter()
                .map(|&i| mesh.normals[i as usize].as_dvec3())
                .sum::<DVec3>()
                / 3.0
        }
    }
}
