//! Reading the numbers of a model file fast without changing one bit of them: the plain decimals
//! model files are made of (`-0.577350`, `12.000000`) are read by Clinger's fast path, every
//! other spelling by `str::parse`, so the result is always `str::parse`'s.

/// Powers of ten exactly representable as `f32` (5^10 < 2^24).
const EXACT_POWERS: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];

/// The `f32` that `str::parse::<f32>` gives for `word`, or `None` where it fails.
pub(crate) fn parse_f32(word: &[u8]) -> Option<f32> {
    plain_decimal(word).or_else(|| std::str::from_utf8(word).ok()?.parse().ok())
}

/// `[+-]digits.digits` whose significant digits fit an `f32` exactly and whose fraction has at
/// most ten digits once its trailing zeros go: then the quotient of two exact `f32`s, rounded
/// once by the division, is the correctly rounded value `str::parse` gives. `None` for anything
/// else (exponents, `inf`, `.5`, `5.`, long mantissas), which then takes the slow path.
fn plain_decimal(word: &[u8]) -> Option<f32> {
    let (negative, digits) = match word.first()? {
        b'-' => (true, &word[1..]),
        b'+' => (false, &word[1..]),
        _ => (false, word),
    };
    let mut mantissa = 0;
    let mut digits = digits.iter();
    let mut whole_digits = 0;
    let mut dot = false;
    for &b in digits.by_ref() {
        if b == b'.' {
            dot = true;
            break;
        }
        push_digit(&mut mantissa, b)?;
        whole_digits += 1;
    }
    // Fraction digits, but for its trailing zeros, which change nothing: zeros are held back
    // until a digit after them shows they are not trailing.
    let (mut fraction, mut zeros, mut fraction_digits) = (0, 0, 0);
    for &b in digits {
        fraction_digits += 1;
        if b == b'0' {
            zeros += 1;
            continue;
        }
        for _ in 0..zeros {
            push_digit(&mut mantissa, b'0')?;
        }
        push_digit(&mut mantissa, b)?;
        fraction += zeros + 1;
        zeros = 0;
    }
    if whole_digits == 0 || (dot && fraction_digits == 0) || fraction >= EXACT_POWERS.len() {
        return None;
    }
    let value = mantissa as f32 / EXACT_POWERS[fraction];
    Some(if negative { -value } else { value })
}

/// `mantissa` with the decimal digit `b` appended, if `b` is a digit and the result is exact as
/// an `f32` (at most 2^24).
fn push_digit(mantissa: &mut u32, b: u8) -> Option<()> {
    let digit = b.wrapping_sub(b'0');
    if digit > 9 {
        return None;
    }
    // No overflow: the mantissa never passes 2^24 between calls.
    *mantissa = *mantissa * 10 + u32::from(digit);
    (*mantissa <= 1 << 24).then_some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn same_as_std(word: &str) -> Result<(), TestCaseError> {
        let ours = parse_f32(word.as_bytes()).map(f32::to_bits);
        let std = word.parse::<f32>().ok().map(f32::to_bits);
        prop_assert_eq!(ours, std, "{:?}", word);
        Ok(())
    }

    #[test]
    fn every_spelling_the_format_allows_reads_as_str_parse_reads_it() {
        for word in [
            "0",
            "-0",
            "+0",
            "-0.000",
            "1",
            "1.0",
            "1e-3",
            "1E3",
            ".5",
            "5.",
            "-.5",
            "+.5e1",
            "0.1",
            "16777216",
            "16777217",
            "16777217.0",
            "0.0000000001",
            "0.00000000001",
            "3.4028235e38",
            "1e39",
            "-1e-46",
            "inf",
            "-Infinity",
            "NaN",
            "",
            "-",
            ".",
            "1.2.3",
            "1-",
            "0x10",
            "1_0",
            "٣",
            "00000000000000000000001.5",
            "1.00000000000000000000",
            "123456.7890",
            "-0.577350",
            "99999999999999999999",
        ] {
            same_as_std(word).unwrap();
        }
    }

    proptest! {
        #[test]
        fn plain_decimals_read_as_str_parse_reads_them(
            sign in "[+-]?",
            whole in "[0-9]{0,12}",
            dot in proptest::bool::ANY,
            fraction in "[0-9]{0,14}",
        ) {
            let dot = if dot { "." } else { "" };
            same_as_std(&format!("{sign}{whole}{dot}{fraction}"))?;
        }

        #[test]
        fn any_number_str_parse_prints_reads_back_the_same(bits in proptest::num::u32::ANY) {
            let x = f32::from_bits(bits);
            same_as_std(&format!("{x}"))?;
            same_as_std(&format!("{x:.6}"))?;
            same_as_std(&format!("{x:e}"))?;
        }

        #[test]
        fn any_ascii_word_reads_as_str_parse_reads_it(word in "[-+.0-9eEinfaINFA]{0,12}") {
            same_as_std(&word)?;
        }
    }
}
