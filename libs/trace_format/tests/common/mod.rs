//! What the format's test files (and check's `clues.rs`) share: small valid files to break one line of, and
//! proptest strategies for every value the readers can produce.

// Each test file that includes this module uses a part of it.
#![allow(dead_code)]

use std::collections::HashSet;

use close2gl_core::declaration::{ClipPlanes, ClipRule, WindingSpace};
use close2gl_core::{NamedEnum, RenderMode};
use close2gl_trace_format::{
    Axis, CLIPPINGS, CULLINGS, CameraLines, ClipLine, Motion, Piece, SceneCamera, SceneFile,
    System2d, Trace, parse_scene, parse_trace,
};
use glam::{DMat4, DVec2, DVec3, DVec4};
use proptest::prelude::*;

/// The smallest whole trace: the magic, the window and the eight camera lines (lines 1 to 10).
pub const TRACE: &str = "close2gl-trace 1
window 640 480
camera position 0 0 5
camera u 1 0 0
camera v 0 1 0
camera n 0 0 1
camera hfov 60
camera vfov 45
camera near 1
camera far 100
";

/// The smallest whole scene (lines 1 to 4).
pub const SCENE: &str = "close2gl-scene 1
model cow.in
window 640 480
camera framed
";

/// [`TRACE`] or [`SCENE`] with line `n` (1-based) replaced by `with`, which may be several lines
/// or none.
pub fn replaced(text: &str, n: usize, with: &str) -> String {
    let mut lines: Vec<&str> = text.lines().collect();
    lines.splice(n - 1..n, with.lines());
    lines.join("\n") + "\n"
}

/// The error `text` gives as a trace named `t.trace`, as a user reads it.
pub fn trace_error(text: &str) -> String {
    match parse_trace(text, "t.trace") {
        Ok(trace) => panic!("expected an error, read {trace:?}"),
        Err(e) => e.to_string(),
    }
}

/// The error `text` gives as a scene named `s.scene`.
pub fn scene_error(text: &str) -> String {
    match parse_scene(text, "s.scene") {
        Ok(scene) => panic!("expected an error, read {scene:?}"),
        Err(e) => e.to_string(),
    }
}

/// `trace` with every `line` field 0: what stays the same when it is written and read back.
pub fn without_lines(mut trace: Trace) -> Trace {
    trace.triangles = trace.triangles.map(|(n, _)| (n, 0));
    trace.drawn = trace.drawn.map(|(n, _)| (n, 0));
    trace.clip.iter_mut().for_each(|c| c.line = 0);
    trace.pieces.iter_mut().for_each(|p| p.line = 0);
    trace
}

/// Any finite number, often a plain one a C program would print. Boxed, as are the bigger
/// strategies built of it: a trace's value tree held inline overflows a test thread's stack in
/// a debug build.
pub fn number() -> BoxedStrategy<f64> {
    prop_oneof![
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
        (-1000i32..1000).prop_map(f64::from),
        -1e3..1e3f64,
        Just(-0.0),
    ]
    .boxed()
}

fn vec3() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(number()).prop_map(DVec3::from_array)
}

fn fov() -> impl Strategy<Value = f64> {
    prop_oneof![1e-6..179.999f64, Just(90.0)]
}

/// A near plane and a far one beyond it.
fn near_far() -> impl Strategy<Value = (f64, f64)> {
    (1e-6..1e3f64, 1e-6..1e6f64).prop_map(|(near, gap)| (near, near + gap))
}

fn camera() -> BoxedStrategy<CameraLines> {
    (vec3(), vec3(), vec3(), vec3(), fov(), fov(), near_far())
        .prop_map(|(position, u, v, n, hfov, vfov, (near, far))| CameraLines {
            position,
            u,
            v,
            n,
            hfov,
            vfov,
            near,
            far,
        })
        .boxed()
}

fn one_of<T: NamedEnum + std::fmt::Debug>() -> impl Strategy<Value = T> {
    prop::sample::select(T::ALL)
}

fn window() -> impl Strategy<Value = (u32, u32)> {
    (1..=16384u32, 1..=16384u32)
}

fn name() -> impl Strategy<Value = String> {
    "[A-Za-z0-9_./-]{1,24}"
}

fn ortho2d() -> BoxedStrategy<System2d> {
    prop::array::uniform4(number())
        .prop_filter("a system of some size", |[l, r, b, t]| l != r && b != t)
        .prop_map(|[left, right, bottom, top]| System2d {
            left,
            right,
            bottom,
            top,
        })
        .boxed()
}

fn matrix() -> BoxedStrategy<Option<DMat4>> {
    prop::option::of(prop::array::uniform16(number()).prop_map(|a| DMat4::from_cols_array(&a)))
        .boxed()
}

/// A triangle index: small ones as meshes have, and any.
fn triangle() -> impl Strategy<Value = usize> {
    prop_oneof![0..100usize, any::<usize>()]
}

/// Clip lines for distinct triangles (a trace gives each triangle's at most once), in any order.
fn clip_lines() -> BoxedStrategy<Vec<ClipLine>> {
    let clip = (triangle(), prop::array::uniform12(number())).prop_map(|(triangle, c)| {
        let corner = |i: usize| DVec4::from_slice(&c[4 * i..]);
        ClipLine {
            triangle,
            corners: [corner(0), corner(1), corner(2)],
            line: 0,
        }
    });
    prop::collection::vec(clip, 0..4)
        .prop_map(|mut lines| {
            let mut seen = HashSet::new();
            lines.retain(|c| seen.insert(c.triangle));
            lines
        })
        .boxed()
}

fn piece() -> BoxedStrategy<Piece> {
    (triangle(), 3..=64usize)
        .prop_flat_map(|(triangle, k)| {
            let corner = (number(), number()).prop_map(|(x, y)| DVec2::new(x, y));
            let depths = prop::option::of(prop::collection::vec(number(), k));
            (prop::collection::vec(corner, k), depths).prop_map(move |(corners, depths)| Piece {
                triangle,
                corners,
                depths,
                line: 0,
            })
        })
        .boxed()
}

/// Any trace the reader can produce, its `line` fields 0.
pub fn trace() -> impl Strategy<Value = Trace> {
    let head = (
        prop::option::of(name()),
        prop::option::of(any::<usize>().prop_map(|n| (n, 0))),
        window(),
        ortho2d(),
        camera(),
        prop::sample::select(&CULLINGS[..]),
        prop::sample::select(&CLIPPINGS[..]),
        prop::option::of(one_of::<RenderMode>()),
    );
    let work = (
        (matrix(), matrix(), matrix(), matrix()),
        clip_lines(),
        prop::collection::vec(piece(), 0..5),
        any::<bool>(),
    );
    // The additions within version 1: a culling space, near_far, `drawn`.
    let additions = (0..3u8, any::<bool>(), any::<bool>());
    (head, work, additions).prop_map(
        |(
            (model, triangles, window, ortho2d, camera, culling, clipping, mode),
            ((m, p, v, model_matrix), clip, pieces, ended),
            (space, near_far, drawn),
        )| Trace {
            winding: match (culling, space) {
                (None, _) | (_, 0) => None,
                (_, 1) => Some(WindingSpace::Ndc),
                _ => Some(WindingSpace::Window),
            },
            planes: match (clipping, near_far) {
                (ClipRule::Nothing, _) | (_, false) => ClipPlanes::All,
                _ => ClipPlanes::NearFar,
            },
            model_matrix,
            drawn: drawn.then_some((pieces.len(), 0)),
            file: "random.trace".to_string(),
            model,
            triangles,
            window,
            ortho2d,
            camera,
            culling,
            clipping,
            mode,
            m,
            p,
            v,
            clip,
            pieces,
            ended,
        },
    )
}

fn scene_camera() -> impl Strategy<Value = SceneCamera> {
    let framed = (
        prop::option::of(fov()),
        prop::option::of(fov()),
        prop::option::of(near_far()),
        any::<(bool, bool)>(),
    )
        .prop_map(|(hfov, vfov, volume, (near, far))| SceneCamera::Framed {
            hfov,
            vfov,
            near: volume.filter(|_| near).map(|(n, _)| n),
            far: volume.filter(|_| far).map(|(_, f)| f),
        });
    prop_oneof![framed, camera().prop_map(SceneCamera::Given)]
}

fn motion() -> impl Strategy<Value = Motion> {
    (0..3u8, one_of::<Axis>(), number()).prop_map(|(kind, axis, x)| match kind {
        0 => Motion::Move(axis, x),
        1 => Motion::Rotate(axis, x),
        _ if axis == Axis::N => Motion::Orbit(Axis::U, x),
        _ => Motion::Orbit(axis, x),
    })
}

/// Any scene the reader can produce.
pub fn scene() -> impl Strategy<Value = SceneFile> {
    (
        name(),
        window(),
        scene_camera(),
        prop::sample::select(&CULLINGS[..]),
        prop::sample::select(&CLIPPINGS[..]),
        prop::option::of(one_of::<RenderMode>()),
        prop::option::of(vec3()),
        prop::collection::vec(motion(), 0..8),
    )
        .prop_map(
            |(model, window, camera, culling, clipping, mode, lookat, motions)| SceneFile {
                file: "random.scene".to_string(),
                model,
                window,
                camera,
                culling,
                clipping,
                mode,
                lookat,
                motions,
                look: Default::default(),
            },
        )
}
