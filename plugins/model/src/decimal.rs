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
    let (whole, fraction) = match digits.iter().position(|&b| b == b'.') {
        Some(dot) => (&digits[..dot], Some(&digits[dot + 1..])),
        None => (digits, None),
    };
    if whole.is_empty() || fraction.is_some_and(<[u8]>::is_empty) {
        return None;
    }
    let fraction = fraction.unwrap_or_default();
    let fraction = &fraction[..fraction.len() - trailing_zeros(fraction)];
    if fraction.len() >= EXACT_POWERS.len() {
        return None;
    }
    let mut mantissa: u32 = 0;
    for &b in whole.iter().chain(fraction) {
        let digit = b.wrapping_sub(b'0');
        if digit > 9 {
            return None;
        }
        mantissa = mantissa.checked_mul(10)?.checked_add(u32::from(digit))?;
        if mantissa > 1 << 24 {
            return None;
        }
    }
    let value = mantissa as f32 / EXACT_POWERS[fraction.len()];
    Some(if negative { -value } else { value })
}

fn trailing_zeros(digits: &[u8]) -> usize {
    digits.iter().rev().take_while(|&&b| b == b'0').count()
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
