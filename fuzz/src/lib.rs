//! What the fuzz targets share: the checks every loaded model must pass, and floats that favour
//! the values that break geometry code (NaN, infinities, huge, tiny, zero).

use arbitrary::Arbitrary;
use close2gl_model::LoadedModel;

/// A loader's answer is either a whole mesh (the invariants every consumer relies on, unit
/// normals, one-line warnings) or one line of error naming the file.
pub fn check_model(result: Result<LoadedModel, String>, label: &str) {
    match result {
        Ok(model) => {
            let mesh = &model.mesh;
            if let Err(e) = mesh.validate() {
                panic!("an accepted mesh is not whole: {e}");
            }
            for (i, n) in mesh.normals.iter().enumerate() {
                assert!(
                    (n.length() - 1.0).abs() < 1e-4,
                    "normal {i} is not a unit vector: {n}"
                );
            }
            for warning in &model.warnings {
                assert!(one_line(warning), "a warning of several lines: {warning:?}");
            }
        }
        Err(message) => {
            assert!(one_line(&message), "an error of several lines: {message:?}");
            assert!(
                message.starts_with(label),
                "an error not naming the file: {message:?}"
            );
        }
    }
}

/// Layout is not content: the same file with `\r\n` line ends (as Windows tools write it) loads
/// to the same mesh, or fails with the same error.
pub fn check_line_ends(
    parse: impl Fn(&str) -> Result<LoadedModel, String>,
    text: &str,
    first: &Result<LoadedModel, String>,
) {
    if text.contains('\r') {
        return;
    }
    let crlf = parse(&text.replace('\n', "\r\n"));
    match (first, &crlf) {
        (Ok(a), Ok(b)) => assert!(a.mesh == b.mesh, "\\r\\n line ends change the mesh"),
        (Err(a), Err(b)) => assert_eq!(a, b, "\\r\\n line ends change the error"),
        _ => panic!("\\r\\n line ends change the outcome: {first:?} vs {crlf:?}"),
    }
}

fn one_line(text: &str) -> bool {
    !text.contains(['\n', '\r'])
}

/// A float, most often one of the values that break geometry code.
#[derive(Arbitrary, Clone, Copy, Debug)]
pub enum Num {
    Special(Special),
    /// Quarter units in -32..32: ordinary coordinates, often equal to each other.
    Small(i8),
    /// Any bit pattern.
    Bits(u32),
}

#[derive(Arbitrary, Clone, Copy, Debug)]
pub enum Special {
    Zero,
    NegZero,
    One,
    NegOne,
    Nan,
    Inf,
    NegInf,
    Huge,
    NegHuge,
    Max,
    Min,
    Tiny,
    NegTiny,
    Subnormal,
    NegSubnormal,
    Epsilon,
}

impl Num {
    pub fn get(self) -> f32 {
        match self {
            Num::Special(s) => match s {
                Special::Zero => 0.0,
                Special::NegZero => -0.0,
                Special::One => 1.0,
                Special::NegOne => -1.0,
                Special::Nan => f32::NAN,
                Special::Inf => f32::INFINITY,
                Special::NegInf => f32::NEG_INFINITY,
                Special::Huge => 1e38,
                Special::NegHuge => -1e38,
                Special::Max => f32::MAX,
                Special::Min => f32::MIN,
                Special::Tiny => 1e-38,
                Special::NegTiny => -1e-38,
                Special::Subnormal => 1e-45,
                Special::NegSubnormal => -1e-45,
                Special::Epsilon => f32::EPSILON,
            },
            Num::Small(i) => f32::from(i) / 4.0,
            Num::Bits(bits) => f32::from_bits(bits),
        }
    }
}

/// Three [`Num`]s.
pub fn vec3(v: [Num; 3]) -> close2gl_core::glam::Vec3 {
    close2gl_core::glam::Vec3::new(v[0].get(), v[1].get(), v[2].get())
}
