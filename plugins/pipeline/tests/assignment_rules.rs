//! Close2GL's stage counts against an independent, float64 reading of the assignment's rules
//! (001): transform by P·M, clip (simple: drop a triangle with a corner outside |x|, |y|, |z| <= w;
//! full: Sutherland–Hodgman against the six planes, a triangle is clipped when nothing is left),
//! divide, cull on the sign of the area. Random models from 1 cm to 10 km across, up to 1,000
//! units from the origin, seen from random cameras. Written from the seed, not from the pipeline's
//! code, and in f64, so that the two agree only if both follow the rules.

use close2gl_core::glam::{DVec3, DVec4, Vec3};
use close2gl_core::limits::ZERO_AREA;
use close2gl_core::{
    Camera, Clipping, Close2glFrame, FrontFace, Mesh, PipelineSettings, StageCounts, Viewport,
};
use close2gl_pipeline::FastPipeline;

/// A small deterministic generator (SplitMix64): the same cases on every run and machine.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    fn point(&mut self, centre: DVec3, half: f64) -> DVec3 {
        centre
            + DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            ) * half
    }
}

/// The counts by the rules, in f64, for a camera given by its own u, v, n and position.
fn counts_by_the_rules(
    triangles: &[[DVec3; 3]],
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
) -> StageCounts {
    let to_clip = clip_transform(camera);
    let inside = |p: DVec4| p.w > 0.0 && PLANES.iter().all(|plane| plane(p) >= 0.0);
    let mut counts = StageCounts::default();
    for triangle in triangles {
        counts.triangles_in += 1;
        let corners = triangle.map(&to_clip);
        let polygon = match (corners.iter().all(|&p| inside(p)), settings.clipping) {
            (true, _) => corners.to_vec(),
            (false, Clipping::Simple) => Vec::new(),
            (false, Clipping::Full) => clip(corners.to_vec()),
        };
        if polygon.len() < 3 {
            counts.clipped += 1;
        } else if settings.backface_culling && is_back_face(&polygon, settings, viewport) {
            counts.culled += 1;
        } else {
            counts.drawn += 1;
        }
    }
    counts
}

/// P·M for the camera: eye coordinates from u, v, n and the position, then the perspective
/// projection of the two fields of view.
fn clip_transform(camera: &Camera) -> impl Fn(DVec3) -> DVec4 {
    let (u, v, n, c) = (
        camera.u.as_dvec3(),
        camera.v.as_dvec3(),
        camera.n.as_dvec3(),
        camera.position.as_dvec3(),
    );
    let (near, far) = (camera.near as f64, camera.far as f64);
    let right = near * ((camera.hfov as f64).to_radians() * 0.5).tan();
    let top = near * ((camera.vfov as f64).to_radians() * 0.5).tan();
    move |p: DVec3| {
        let d = p - c;
        let (x, y, z) = (d.dot(u), d.dot(v), d.dot(n));
        DVec4::new(
            near / right * x,
            near / top * y,
            -(far + near) / (far - near) * z - 2.0 * far * near / (far - near),
            -z,
        )
    }
}

/// The view volume's six planes as signed distances, >= 0 inside.
const PLANES: [fn(DVec4) -> f64; 6] = [
    |p| p.w + p.x,
    |p| p.w - p.x,
    |p| p.w + p.y,
    |p| p.w - p.y,
    |p| p.w + p.z,
    |p| p.w - p.z,
];

/// Sutherland–Hodgman against every plane; fewer than 3 corners left means nothing is.
fn clip(mut polygon: Vec<DVec4>) -> Vec<DVec4> {
    for plane in PLANES {
        let mut cut = Vec::new();
        for i in 0..polygon.len() {
            let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
            let (da, db) = (plane(a), plane(b));
            if da >= 0.0 {
                cut.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                cut.push(a + (b - a) * (da / (da - db)));
            }
        }
        polygon = cut;
        if polygon.len() < 3 {
            break;
        }
    }
    polygon
}

/// Whether the clipped polygon faces away on screen, or has no area to speak of (a back face,
/// as in OpenGL).
fn is_back_face(polygon: &[DVec4], settings: &PipelineSettings, viewport: Viewport) -> bool {
    // Window pixels, y down as the window counts them: counter-clockwise on screen is a
    // negative area here.
    let (w, h) = (viewport.width as f64, viewport.height as f64);
    let window: Vec<[f64; 2]> = polygon
        .iter()
        .map(|p| [(p.x / p.w + 1.0) * w / 2.0, (1.0 - p.y / p.w) * h / 2.0])
        .collect();
    let edges = (0..window.len()).map(|i| (window[i], window[(i + 1) % window.len()]));
    let area: f64 = edges.clone().map(|(a, b)| a[0] * b[1] - b[0] * a[1]).sum();
    let longest = edges
        .map(|(a, b)| (b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2))
        .fold(0.0, f64::max);
    let front = match settings.front_face {
        FrontFace::Ccw => area < 0.0,
        FrontFace::Cw => area > 0.0,
    };
    !front || area.abs() <= ZERO_AREA as f64 * longest
}

/// A random model: `count` triangles about `size` across around `centre`, stored as the loaders
/// store them (f32).
fn random_mesh(random: &mut Random, centre: DVec3, size: f64, count: usize) -> Mesh {
    let mut mesh = Mesh::default();
    for _ in 0..count {
        let a = random.point(centre, size);
        let corners = [a, random.point(a, 0.4 * size), random.point(a, 0.4 * size)];
        let first = mesh.positions.len() as u32;
        mesh.positions.extend(corners.map(|p| p.as_vec3()));
        mesh.normals.extend([Vec3::Z; 3]);
        mesh.triangles.push([first, first + 1, first + 2]);
    }
    mesh
}

/// A random camera near the model, looking into it; `None` for a degenerate pose.
fn random_camera(random: &mut Random, centre: DVec3, size: f64) -> Option<Camera> {
    let position = random.point(centre, 3.0 * size).as_vec3();
    let target = random.point(centre, 0.5 * size).as_vec3();
    let distance = position.distance(target);
    Camera {
        hfov: random.range(20.0, 120.0) as f32,
        vfov: random.range(20.0, 120.0) as f32,
        near: distance * random.range(0.05, 1.0) as f32,
        far: distance * random.range(1.2, 4.0) as f32,
        ..Camera::default()
    }
    .looking_at(position, target, Vec3::Y)
}

fn random_settings(random: &mut Random) -> PipelineSettings {
    PipelineSettings {
        clipping: if random.next() < 0.5 {
            Clipping::Simple
        } else {
            Clipping::Full
        },
        front_face: if random.next() < 0.5 {
            FrontFace::Ccw
        } else {
            FrontFace::Cw
        },
        backface_culling: random.next() < 0.8,
        ..PipelineSettings::default()
    }
}

#[test]
fn the_counts_follow_the_assignments_rules_on_random_models_and_cameras() {
    let mut random = Random(2026);
    let mut pipeline = FastPipeline::default();
    let mut frame = Close2glFrame::default();
    let viewports = [
        Viewport {
            width: 640,
            height: 480,
        },
        Viewport {
            width: 300,
            height: 700,
        },
    ];
    for case in 0..300 {
        let size = 10f64.powf(random.range(-2.0, 4.0));
        let centre = random.point(DVec3::ZERO, 1000.0);
        let count = 1 + (random.next() * 300.0) as usize;
        let mesh = random_mesh(&mut random, centre, size, count);
        // The rules work on the stored f32 values, in f64.
        let stored: Vec<[DVec3; 3]> = mesh
            .triangles
            .iter()
            .map(|t| t.map(|i| mesh.positions[i as usize].as_dvec3()))
            .collect();
        let Some(camera) = random_camera(&mut random, centre, size) else {
            continue;
        };
        let settings = random_settings(&mut random);
        let viewport = viewports[case % 2];

        pipeline.run(
            &mesh,
            &camera,
            &settings,
            viewport,
            &mut frame,
            &mut Default::default(),
        );
        let mut got = frame.counts;
        got.output_primitives = 0;
        let expected = counts_by_the_rules(&stored, &camera, &settings, viewport);
        assert_eq!(
            got, expected,
            "case {case}: {count} triangles {size} across at {centre}, camera {camera:?}, {settings:?}"
        );
    }
}
