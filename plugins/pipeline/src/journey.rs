//! One mesh triangle's journey through the Close2GL pipeline, with every number the course
//! names: world (the file's coordinates), eye = M·p, clip = P·M·p, the Sutherland–Hodgman
//! steps, NDC (÷ w), window (V·ndc), the signed area, the culling decision and the fate. Each
//! number comes from the pipeline's own functions (the same [`clip_step`], division and cull),
//! so what the inspector shows is what the frame did.

use close2gl_core::{
    Camera, ClipPlane, Clipping, FateKind, Mesh, PipelineSettings, TriangleFate, Viewport,
};
use glam::{Vec3, Vec4};

use crate::clip::{Polygon, clip_step, outcode};
use crate::matrices::ClipTransform;
use crate::stage::{FrameConstants, corner, face, process, to_window_depth};

/// The polygon after clipping by one plane.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipStep {
    pub plane: ClipPlane,
    /// Clip coordinates (x, y, z, w) of each vertex.
    pub polygon: Vec<Vec4>,
    /// Where each vertex lies in the triangle: the weights of its three corners (a corner is
    /// (1, 0, 0), ...; a vertex the plane made, its edge's ends' weights interpolated).
    pub weights: Vec<Vec3>,
}

/// Everything that happened to one triangle.
#[derive(Clone, Debug, PartialEq)]
pub struct Journey {
    pub triangle: usize,
    pub world: [Vec3; 3],
    /// M·p.
    pub eye: [Vec3; 3],
    /// P·M·p.
    pub clip: [Vec4; 3],
    /// Outcode of each corner (bit i is [`ClipPlane`] i).
    pub outcodes: [u8; 3],
    /// One step per plane the triangle straddles, in the pipeline's order; none when it lies
    /// inside, or is removed whole (outside one plane, or any with simple clipping).
    pub clip_steps: Vec<ClipStep>,
    /// The polygon the pipeline divides by w (the corners, or the last clip step's polygon) in
    /// normalized device coordinates; empty when clipping removed the triangle.
    pub ndc: Vec<Vec3>,
    /// The same polygon in the window: x, y in pixels (y down from the top-left), depth 0..1.
    pub window: Vec<Vec3>,
    /// Twice the signed window area of `window` (y down: counter-clockwise on screen is
    /// negative); NaN when there is no polygon.
    pub signed_area: f32,
    /// What backface culling decided: `Culled`, `ZeroArea`, or None (kept, or culling off).
    pub culling: Option<FateKind>,
    pub fate: TriangleFate,
}

/// The journey of mesh triangle `index`, or None when the mesh has no such triangle.
pub fn journey(
    mesh: &Mesh,
    index: usize,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
) -> Option<Journey> {
    let corners = *mesh.triangles.get(index)?;
    let world = corners.map(|i| mesh.positions[i as usize]);
    let transform = ClipTransform::new(camera);
    let constants = FrameConstants::new(settings, viewport);
    let clip = world.map(|p| transform.apply(p));
    let outcodes = clip.map(outcode);
    // The fate is the pipeline's own decision, from the frame's constants.
    let seen = clip.map(|c| corner(c, &constants));
    let (codes, window) = (seen.map(|(code, _)| code), seen.map(|(_, window)| window));
    let fate = process::<true>(corners, codes, window, || clip, &constants, &mut Vec::new()).fate;
    let clip_steps = clip_steps(clip, outcodes, &constants);
    let divided = match (&clip_steps.last(), fate.kind) {
        (_, FateKind::Clipped) => Vec::new(),
        (Some(last), _) => last.polygon.clone(),
        (None, _) => clip.to_vec(),
    };
    let ndc: Vec<Vec3> = divided.iter().map(|p| p.truncate() / p.w).collect();
    let window: Vec<Vec3> = divided
        .iter()
        .map(|p| Vec3::from_slice(&to_window_depth(*p, &constants.viewport)[..3]))
        .collect();
    let (signed_area, culling) = match window.is_empty() {
        true => (f32::NAN, None),
        false => face::<true>(
            &window.iter().map(|w| [w.x, w.y]).collect::<Vec<_>>(),
            constants.culling,
        ),
    };
    Some(Journey {
        triangle: index,
        world,
        eye: world.map(|p| transform.eye(p)),
        clip,
        outcodes,
        clip_steps,
        ndc,
        window,
        signed_area,
        culling,
        fate,
    })
}

/// The Sutherland–Hodgman steps the pipeline takes for a triangle that straddles the view
/// volume: one per plane some corner lies outside of, stopping when the polygon vanishes.
fn clip_steps(clip: [Vec4; 3], outcodes: [u8; 3], constants: &FrameConstants) -> Vec<ClipStep> {
    let outside_any = outcodes[0] | outcodes[1] | outcodes[2];
    let outside_all = outcodes[0] & outcodes[1] & outcodes[2];
    let mut steps = Vec::new();
    if outside_all != 0 || constants.clipping == Clipping::Simple {
        return steps;
    }
    let mut polygon = Polygon::triangle(clip[0], clip[1], clip[2]);
    let planes = ClipPlane::ALL.iter().enumerate();
    for (bit, &plane) in planes.filter(|(bit, _)| outside_any & (1 << bit) != 0) {
        if polygon.len < 3 {
            break;
        }
        polygon = clip_step(&polygon, bit).unwrap_or(Polygon { len: 0, ..polygon });
        steps.push(ClipStep {
            plane,
            polygon: polygon.vertices().to_vec(),
            weights: polygon.weights[..polygon.len].to_vec(),
        });
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::clip::clip_polygon;
    use crate::random_triangles;
    use crate::textbook;

    /// For random triangles around a camera (many straddle the near and side planes), the
    /// journey's fate, area and final polygon are the textbook path's, bit for bit, and its
    /// last clip step is the polygon `clip_polygon` gives the pipeline.
    #[test]
    fn the_journey_retraces_the_textbook_path() {
        let camera = random_triangles::camera(Vec3::new(0.0, 0.0, 6.0));
        let viewport = random_triangles::VIEWPORT;
        let mut seen = close2gl_core::FateCounts::default();
        for (i, mesh) in random_triangles::triangles(0x9e37_79b9_7f4a_7c15, 3000).enumerate() {
            let settings = PipelineSettings {
                backface_culling: i % 2 == 0,
                clipping: if i % 7 == 0 {
                    Clipping::Simple
                } else {
                    Clipping::Full
                },
                ..PipelineSettings::default()
            };
            let (frame, fates) = textbook::run_recording(&mesh, &camera, &settings, viewport);
            let j = journey(&mesh, 0, &camera, &settings, viewport).expect("triangle 0");
            let expected = fates.triangles[0];
            seen.add(expected.kind);
            assert_eq!(format!("{:?}", j.fate), format!("{expected:?}"), "{i}");
            if j.fate.kind != FateKind::Clipped {
                assert_eq!(
                    j.signed_area.to_bits(),
                    expected.signed_area.to_bits(),
                    "{i}"
                );
            }
            if matches!(j.fate.kind, FateKind::Drawn | FateKind::Cut) {
                let n = j.window.len();
                let fan: Vec<[f32; 2]> = (1..n - 1)
                    .flat_map(|k| [0, k, k + 1])
                    .map(|k| [j.window[k].x, j.window[k].y])
                    .collect();
                assert_eq!(fan, frame.vertices, "{i}");
            }
            if let Some(last) = j.clip_steps.last() {
                let outside_any = j.outcodes.iter().fold(0, |a, b| a | b);
                let triangle = Polygon::triangle(j.clip[0], j.clip[1], j.clip[2]);
                let piece = clip_polygon(&triangle, outside_any);
                if piece.len > 0 {
                    assert_eq!(last.polygon, piece.vertices(), "{i}");
                }
            }
        }
        for kind in [
            FateKind::Drawn,
            FateKind::Cut,
            FateKind::Clipped,
            FateKind::Culled,
        ] {
            assert!(seen.get(kind) > 10, "too few {kind:?}: {seen:?}");
        }
    }
}
