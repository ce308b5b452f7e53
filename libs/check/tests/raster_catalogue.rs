//! Every rasterizer mistake of the catalogue, made by close2gl's textbook rasterizer on frames
//! built to show it, is named by check; the right drawing agrees with nothing named; a legal tie
//! rule or truncation is reported as the rule it is. The frames: a textured floor receding in
//! perspective (repeating, minified far away and magnified near), a wall standing in it drawn
//! first (the depth test decides where they meet), and a square of two triangles whose corners
//! are pixel centres apart (every edge runs through pixel centres: the tie rule decides them).

use close2gl_check::raster::input::Redraw;
use close2gl_check::raster::{check_raster, corners};
use close2gl_core::{
    ByteConversion, Image, Lighting, RasterMistake as M, RasterMistakes, RasterRules, Shading,
    TextureFilter, TieRule,
};
use close2gl_raster::textbook::Light;
use close2gl_trace_format::raster::{Attribute, LightingLine, Lit};
use close2gl_trace_format::{RasterCorner, RasterFrame, RasterTrace, RasterTriangle};
use glam::DVec3;

const WIDTH: u32 = 96;
const HEIGHT: u32 = 72;
/// The camera's centre: M is a translation by its opposite.
const CAMERA: DVec3 = DVec3::new(0.0, 1.0, 0.0);
/// The model's colour.
const COLOR: DVec3 = DVec3::new(1.0, 0.95, 0.9);

/// A 16×16 texture whose four quarters differ in hue and whose texels all differ: flipping t,
/// swapping channels or shifting half a texel all change what is sampled.
fn texture() -> Image {
    let pixels = (0..256u32)
        .map(|i| {
            let (x, y) = (i % 16, i / 16);
            let quarter = (x / 8) + 2 * (y / 8);
            let base: [u8; 3] =
                [[230, 40, 40], [40, 220, 60], [50, 70, 240], [240, 220, 50]][quarter as usize];
            let shade = ((x * 7 + y * 13) % 16) as u8 * 6;
            [
                base[0].saturating_sub(shade / 2),
                base[1].saturating_sub(shade / 3),
                base[2].saturating_sub(shade / 4),
                255,
            ]
        })
        .collect();
    Image {
        width: 16,
        height: 16,
        pixels,
    }
}

/// A point of the world as a corner: projected with a 60° vertical field of view (near 0.5, far
/// 20) into window coordinates with y up, lit for Gouraud.
fn corner(world: DVec3, normal: DVec3, uv: [f64; 2], light: &Light) -> RasterCorner {
    let eye = world - CAMERA;
    let (near, far) = (0.5, 20.0);
    let f = 1.0 / (30f64.to_radians()).tan();
    let aspect = f64::from(WIDTH) / f64::from(HEIGHT);
    let w = -eye.z;
    let ndc = [
        f / aspect * eye.x / w,
        f * eye.y / w,
        (-(far + near) / (far - near) * eye.z - 2.0 * far * near / (far - near)) / w,
    ];
    let window = [
        (ndc[0] + 1.0) / 2.0 * f64::from(WIDTH),
        (ndc[1] + 1.0) / 2.0 * f64::from(HEIGHT),
        (ndc[2] + 1.0) / 2.0,
        1.0 / w,
    ];
    let rgb = COLOR.as_vec3() * light.illuminate(eye.as_vec3(), normal.as_vec3());
    RasterCorner {
        window,
        rgb: rgb.as_dvec3().to_array(),
        eye: eye.to_array(),
        normal: normal.to_array(),
        uv,
    }
}

/// A corner given in window coordinates directly (the square on pixel centres), lit as a point
/// one unit in front of the eye facing it.
fn flat_corner(x: f64, y: f64, light: &Light) -> RasterCorner {
    let (eye, normal) = (glam::Vec3::NEG_Z, glam::Vec3::Z);
    RasterCorner {
        window: [x, y, 0.05, 1.0],
        rgb: (COLOR.as_vec3() * light.illuminate(eye, normal))
            .as_dvec3()
            .to_array(),
        eye: eye.as_dvec3().to_array(),
        normal: normal.as_dvec3().to_array(),
        uv: [0.3, 0.3],
    }
}

/// The lecture's constants, but for a light just above the camera (so that some reflections
/// point away from the eye: V·R < 0), an attenuation that shows at these distances, and
/// brighter terms (so that some colours pass 1 and clamping shows).
fn lighting() -> Lighting {
    Lighting {
        light_position: glam::Vec3::new(0.6, 1.8, 0.3),
        attenuation: [0.4, 0.15, 0.04],
        ka: 1.0,
        kd: 1.0,
        ks: 0.8,
        ..Lighting::default()
    }
}

/// The light the frames are lit with, making `mistakes`.
fn light(shading: Shading, mistakes: RasterMistakes) -> Light {
    let world = lighting().light_position;
    let eye = world - CAMERA.as_vec3();
    Light::new(&lighting(), eye, world, shading, mistakes)
}

/// The triangles: the wall first, then the floor, then the square.
fn triangles(light: &Light) -> Vec<RasterTriangle> {
    let mut all = Vec::new();
    let mut quad = |p: [DVec3; 4], normals: [DVec3; 4], uv: [[f64; 2]; 4]| {
        let c = |i: usize| corner(p[i], normals[i], uv[i], light);
        for corners in [[c(0), c(1), c(2)], [c(0), c(2), c(3)]] {
            let mesh = all.len();
            all.push(RasterTriangle {
                mesh,
                corners,
                line: 0,
            });
        }
    };
    // A wall standing in the floor, leaning back: it and the floor cross.
    let wall = [
        (-0.8, -0.3, -2.2),
        (0.9, -0.3, -2.2),
        (0.9, 1.1, -3.4),
        (-0.8, 1.1, -3.4),
    ];
    quad(
        wall.map(DVec3::from),
        [DVec3::new(0.0, 0.65, 0.76).normalize(); 4],
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
    );
    // The floor, in four strips from near to far, its texture repeated beyond [0, 1].
    for k in 0..4 {
        let (z0, z1) = (-0.8 - 2.0 * k as f64, -2.8 - 2.0 * k as f64);
        let (t0, t1) = (k as f64 * 1.5 - 1.0, (k + 1) as f64 * 1.5 - 1.0);
        quad(
            [
                (-2.5, 0.0, z0),
                (2.5, 0.0, z0),
                (2.5, 0.0, z1),
                (-2.5, 0.0, z1),
            ]
            .map(DVec3::from),
            // Bent normals: a smooth surface's, some turned from the light (N·L < 0).
            [(-1.5, 0.2), (1.2, 0.1), (0.8, -0.6), (-0.4, 0.9)]
                .map(|(x, z)| DVec3::new(x, 1.0, z).normalize()),
            [[-0.5, t0], [2.5, t0], [2.5, t1], [-0.5, t1]],
        );
    }
    // The square: corners 8 pixel centres apart, edges through centres.
    let s =
        [(4.5, 4.5), (20.5, 4.5), (20.5, 20.5), (4.5, 20.5)].map(|(x, y)| flat_corner(x, y, light));
    for corners in [[s[0], s[1], s[2]], [s[0], s[2], s[3]]] {
        let mesh = all.len();
        all.push(RasterTriangle {
            mesh,
            corners,
            line: 0,
        });
    }
    all
}

/// A frame drawn with `shading` and `filter`: its trace, and the buffers the textbook rasterizer
/// draws making `mistakes` with `rules` (corners lit by Gouraud with `lit_mistakes`).
fn frame(
    shading: Shading,
    filter: Option<TextureFilter>,
    rules: RasterRules,
    mistakes: RasterMistakes,
    lit_mistakes: RasterMistakes,
) -> RasterFrame {
    let lighting = lighting();
    let triangles = triangles(&light(shading, lit_mistakes));
    let [ia, il] = [lighting.ia, lighting.il].map(|v| v.as_dvec3().to_array());
    let mut modelview = [0.0; 16];
    for k in 0..4 {
        modelview[k * 5] = 1.0;
    }
    (modelview[3], modelview[7], modelview[11]) = (-CAMERA.x, -CAMERA.y, -CAMERA.z);
    let trace = RasterTrace {
        file: "test.trace".into(),
        model: None,
        window: (WIDTH, HEIGHT),
        y_up: true,
        subpixel: Some(8),
        shading,
        color: COLOR.to_array(),
        background: [0.1, 0.1, 0.12],
        lit: Some(Lit {
            light: lighting.light_position.as_dvec3().to_array(),
            modelview,
            lighting: LightingLine {
                ia,
                il,
                ka: lighting.ka as f64,
                kd: lighting.kd as f64,
                ks: lighting.ks as f64,
                shininess: lighting.shininess as f64,
                attenuation: lighting.attenuation.map(f64::from),
            },
        }),
        texture: filter.map(|f| ("texture.ppm".to_string(), f)),
        framebuffer: "frame.ppm".into(),
        depthbuffer: Some("frame.pfm".into()),
        attributes: Attribute::ALL.to_vec(),
        triangles,
    };
    // The program's buffers are the textbook rasterizer's, drawn from the trace as check
    // draws it, with the program's mistakes and rules.
    let mut frame = RasterFrame {
        framebuffer: Image::filled(WIDTH, HEIGHT, [0; 4]),
        depth: None,
        texture: filter.map(|_| texture()),
        trace,
    };
    let drawn = Redraw::new(&frame).draw(rules, mistakes);
    frame.framebuffer = drawn.image;
    frame.framebuffer.pixels.iter_mut().for_each(|p| p[3] = 255);
    frame.depth = Some(close2gl_trace_format::raster::images::DepthImage {
        width: WIDTH,
        height: HEIGHT,
        values: drawn.depth,
    });
    frame
}

/// The frames tried for each mistake, in order: the first where it can show is used.
const FRAMES: [(Shading, Option<TextureFilter>); 3] = [
    (Shading::Phong, Some(TextureFilter::Trilinear)),
    (Shading::GouraudAds, Some(TextureFilter::Nearest)),
    (Shading::Phong, Some(TextureFilter::Bilinear)),
];

fn frame_for(m: M) -> (Shading, Option<TextureFilter>) {
    use close2gl_check::raster::diagnose::can_show;
    (FRAMES.into_iter())
        .find(|&(shading, filter)| can_show(m, shading, filter, true))
        .expect("every mistake shows in one of the frames")
}

#[test]
fn the_right_rasterizer_agrees_and_nothing_is_named() {
    for (shading, filter) in FRAMES {
        let none = RasterMistakes::NONE;
        let frame = frame(shading, filter, RasterRules::default(), none, none);
        let report = check_raster(&frame);
        assert!(
            report.agrees(),
            "{shading:?} {filter:?}: {}",
            close2gl_check::raster::report::text(&report, "t")
        );
        assert!(report.mistakes().is_empty());
    }
}

#[test]
fn every_catalogue_mistake_is_named_on_a_frame_that_shows_it() {
    let mut missed = Vec::new();
    for &m in M::catalogue() {
        let (shading, filter) = frame_for(m);
        let none = RasterMistakes::NONE;
        let frame = frame(
            shading,
            filter,
            RasterRules::default(),
            RasterMistakes::one(m),
            none,
        );
        let report = check_raster(&frame);
        if report.agrees() || !report.mistakes().contains(&m.name()) {
            let text = close2gl_check::raster::report::text(&report, m.name());
            missed.push(format!("{}: {text}", m.name()));
        }
    }
    assert!(missed.is_empty(), "not named:\n{}", missed.join("\n"));
}

#[test]
fn gouraud_lighting_mistakes_are_named_at_the_corners() {
    let lit_wrong = [
        M::LightInWorld,
        M::NoSpecular,
        M::DiffuseUnclamped,
        M::BlinnPhong,
        M::NoAttenuation,
        M::ViewerAtInfinity,
    ];
    for m in lit_wrong {
        let none = RasterMistakes::NONE;
        let frame = frame(
            Shading::GouraudAds,
            None,
            RasterRules::default(),
            none,
            RasterMistakes::one(m),
        );
        let report = check_raster(&frame);
        let corners: &corners::CornerFacts =
            report.corners.as_ref().expect("Gouraud corners judged");
        assert!(corners.differing > 0, "{}", m.name());
        assert!(
            corners.named.contains(&m),
            "{}: named {:?}",
            m.name(),
            corners.named
        );
    }
}

#[test]
fn another_tie_rule_or_truncation_is_reported_as_the_legal_rule_it_is() {
    let none = RasterMistakes::NONE;
    let rules = RasterRules {
        tie: TieRule::BottomRight,
        conversion: ByteConversion::Truncate,
        ..RasterRules::default()
    };
    let frame = frame(Shading::Phong, None, rules, none, none);
    let report = check_raster(&frame);
    assert!(
        report.agrees(),
        "{}",
        close2gl_check::raster::report::text(&report, "t")
    );
    assert_eq!(report.rules(), rules);
    assert!(report.mistakes().is_empty());
}

/// The pairs search draws a band of rows before the whole frame: the band must hold exactly the
/// whole frame's pixels there, for every mistake (the rows written upside down are drawn at the
/// other end), or a pair that reproduces the trace would be ruled out.
#[test]
fn a_band_draws_what_the_whole_frame_draws_in_its_rows() {
    let bands = [8..24, 0..16, HEIGHT - 16..HEIGHT];
    for &m in M::catalogue() {
        let (shading, filter) = frame_for(m);
        let none = RasterMistakes::NONE;
        let frame = frame(shading, filter, RasterRules::default(), none, none);
        let redraw = Redraw::new(&frame);
        let (rules, mistakes) = (RasterRules::default(), RasterMistakes::one(m));
        let whole = redraw.draw(rules, mistakes);
        for rows in bands.clone() {
            let band = redraw.draw_band(rules, mistakes, &rows);
            let at = (rows.start * WIDTH) as usize..(rows.end * WIDTH) as usize;
            assert_eq!(
                band.image.pixels[at.clone()],
                whole.image.pixels[at.clone()],
                "{} rows {rows:?}",
                m.name()
            );
            assert_eq!(band.depth[at.clone()], whole.depth[at], "{}", m.name());
        }
    }
}

/// Pairs are tried in a band first; one with the rows written upside down (drawn at the other
/// end of the band) is still named.
#[test]
fn a_pair_with_the_rows_upside_down_is_named() {
    let none = RasterMistakes::NONE;
    let pair = RasterMistakes::one(M::RowsBottomFirst).with(M::UvAffine);
    let filter = Some(TextureFilter::Bilinear);
    let frame = frame(Shading::Phong, filter, RasterRules::default(), pair, none);
    let report = check_raster(&frame);
    assert_eq!(
        report.mistakes(),
        ["uv_affine", "rows_bottom_first"],
        "{}",
        close2gl_check::raster::report::text(&report, "t")
    );
}
