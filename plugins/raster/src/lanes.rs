//! Eight pixels at a time: a small vector type whose every operation is a loop over its eight
//! lanes, straight-line code the compiler turns into one SIMD instruction (two with SSE2 only).
//! Stable Rust has no portable SIMD; this is the plain code that vectorises instead.

use std::ops::{Add, Div, Mul, Neg, Sub};

pub(crate) const LANES: usize = 8;

/// Which lanes of a block pass a test: all ones where a lane passes, zero where it does not.
pub(crate) type Mask = [u32; LANES];

/// `[T; 3]::map`, which the compiler does not always inline into setup's hot loop (it then
/// costs more than the arithmetic).
#[inline(always)]
pub(crate) fn map3<T, U>(a: &[T; 3], f: impl Fn(&T) -> U) -> [U; 3] {
    [f(&a[0]), f(&a[1]), f(&a[2])]
}

/// Defines `fn $name[generics](args) { body }`: a function whose body is compiled twice, for
/// the baseline x86-64 and, chosen at run time, for AVX2 and FMA, where eight lanes are one
/// instruction rather than two. The AVX2 copy is not inlined, so that everything the body
/// inlines is compiled with those features; the attributes given (`#[inline(always)]` or none)
/// are the dispatcher's.
macro_rules! with_avx2 {
    (
        $(#[$attr:meta])*
        $vis:vis fn $name:ident[$($generics:tt)*]($($arg:ident: $ty:ty),* $(,)?) $body:block
    ) => {
        $(#[$attr])*
        $vis fn $name<$($generics)*>($($arg: $ty),*) {
            #[inline(always)]
            fn portable<$($generics)*>($($arg: $ty),*) $body
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx2,fma")]
                #[inline(never)]
                fn avx2<$($generics)*>($($arg: $ty),*) {
                    portable($($arg),*)
                }
                if std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
                {
                    // SAFETY: the CPU has the features `avx2` is compiled for, checked just above.
                    unsafe { avx2($($arg),*) };
                    return;
                }
            }
            portable($($arg),*)
        }
    };
}
pub(crate) use with_avx2;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct F8(pub [f32; LANES]);

impl F8 {
    #[inline(always)]
    pub fn splat(x: f32) -> F8 {
        F8([x; LANES])
    }

    /// x, x + 1, ..., x + 7.
    #[inline(always)]
    pub fn ramp(x: f32) -> F8 {
        F8([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]) + F8::splat(x)
    }

    // Plain loops of a constant count writing an array: the compiler unrolls them and packs the
    // lanes into vector instructions more reliably than it does array::map or from_fn.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f32) -> f32) -> F8 {
        let mut out = [0.0; LANES];
        for (o, a) in out.iter_mut().zip(self.0) {
            *o = f(a);
        }
        F8(out)
    }

    #[inline(always)]
    fn zip(self, other: F8, f: impl Fn(f32, f32) -> f32) -> F8 {
        let mut out = [0.0; LANES];
        for (o, (a, b)) in out.iter_mut().zip(self.0.into_iter().zip(other.0)) {
            *o = f(a, b);
        }
        F8(out)
    }

    #[inline(always)]
    pub fn floor(self) -> F8 {
        self.map(f32::floor)
    }

    #[inline(always)]
    pub fn sqrt(self) -> F8 {
        self.map(f32::sqrt)
    }

    /// The larger of the two, lane by lane (the second where either is NaN).
    #[inline(always)]
    pub fn max(self, other: F8) -> F8 {
        self.zip(other, |a, b| if a > b { a } else { b })
    }

    #[inline(always)]
    pub fn min(self, other: F8) -> F8 {
        self.zip(other, |a, b| if a < b { a } else { b })
    }

    #[inline(always)]
    pub fn mul_add(self, b: F8, c: F8) -> F8 {
        self * b + c
    }

    /// x^n for x in (0, 1] (up to rounding), n >= 0, as 2^(n·log2 x): the way GPUs evaluate
    /// pow, in arithmetic that vectorises (a call into libm cannot). Within 1e-4 of the value
    /// and 4e-6 absolute for the exponents lighting uses, far under an 8-bit colour step.
    #[inline(always)]
    pub fn pow(self, n: f32) -> F8 {
        (self.log2() * F8::splat(n)).exp2()
    }

    /// log2 of positive normal numbers: the exponent, plus log2 of the mantissa m in [1, 2) from
    /// the series of atanh: log2 m = 2/ln 2 · (t + t³/3 + t⁵/5 + ...), t = (m − 1)/(m + 1) < 1/3.
    #[inline(always)]
    pub fn log2(self) -> F8 {
        let exponent = self.map(|x| (((x.to_bits() >> 23) & 0xff) as i32 - 127) as f32);
        let m = self.map(|x| f32::from_bits((x.to_bits() & 0x007f_ffff) | 0x3f80_0000));
        let one = F8::splat(1.0);
        let t = (m - one) / (m + one);
        let t2 = t * t;
        let series = [1.0 / 11.0, 1.0 / 9.0, 1.0 / 7.0, 0.2, 1.0 / 3.0, 1.0]
            .into_iter()
            .fold(F8::splat(1.0 / 13.0), |acc, c| {
                acc.mul_add(t2, F8::splat(c))
            });
        exponent + t * series * F8::splat(2.0 / std::f32::consts::LN_2)
    }

    /// 2^x, flushed to 0 at and below 2^-126: the integer part as the exponent, the fraction f
    /// from the Taylor series of e^(f ln 2).
    #[inline(always)]
    pub fn exp2(self) -> F8 {
        let x = self.max(F8::splat(-126.0)).min(F8::splat(127.0));
        let whole = x.floor();
        let f = x - whole;
        let p = [
            0.001_333_355_8,
            0.009_618_129,
            0.055_504_11,
            0.240_226_5,
            std::f32::consts::LN_2,
            1.0,
        ]
        .into_iter()
        .fold(F8::splat(0.000_154_035_3), |acc, c| {
            acc.mul_add(f, F8::splat(c))
        });
        let scale = whole.map(|w| {
            // SAFETY: w is a whole number in -126..=127 (clamped above), which an i32 holds;
            // the checked `as` conversion would not vectorise.
            let w: i32 = unsafe { w.to_int_unchecked() };
            f32::from_bits(((w + 127) as u32) << 23)
        });
        let flushed = x.zip(scale, |x, s| if x <= -126.0 { 0.0 } else { s });
        flushed * p
    }
}

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait for F8 {
            type Output = F8;
            #[inline(always)]
            fn $method(self, other: F8) -> F8 {
                self.zip(other, |a, b| a $op b)
            }
        }
    };
}

lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl Neg for F8 {
    type Output = F8;
    #[inline(always)]
    fn neg(self) -> F8 {
        self.map(|x| -x)
    }
}

/// Three F8: eight 3-vectors.
#[derive(Clone, Copy, Debug)]
pub(crate) struct V8 {
    pub x: F8,
    pub y: F8,
    pub z: F8,
}

impl V8 {
    #[inline(always)]
    pub fn splat(v: glam::Vec3) -> V8 {
        V8 {
            x: F8::splat(v.x),
            y: F8::splat(v.y),
            z: F8::splat(v.z),
        }
    }

    /// The first lane's vector: what a point given to all eight lanes (`splat`) comes to.
    #[inline(always)]
    pub fn first(self) -> glam::Vec3 {
        glam::Vec3::new(self.x.0[0], self.y.0[0], self.z.0[0])
    }

    #[inline(always)]
    pub fn dot(self, o: V8) -> F8 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    #[inline(always)]
    pub fn scale(self, s: F8) -> V8 {
        V8 {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    #[inline(always)]
    pub fn sub(self, o: V8) -> V8 {
        V8 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pow_agrees_with_the_library_to_a_tiny_fraction() {
        for n in [0.0f32, 1.0, 2.5, 10.0, 64.0, 200.0] {
            for i in 0..125 {
                let x = F8::ramp(1.0 + 8.0 * i as f32) * F8::splat(1e-3);
                let fast = x.pow(n);
                for (x, fast) in x.0.iter().zip(fast.0) {
                    let exact = x.powf(n);
                    // A thousandth of an 8-bit colour step, or 1e-4 of the value.
                    assert!(
                        (fast - exact).abs() <= 4e-6_f32.max(1e-4 * exact),
                        "{x}^{n}: {fast} vs {exact}"
                    );
                }
            }
        }
        assert_eq!(F8::splat(1e-20).pow(10.0).0[0], 0.0);
    }
}
