//! The matrix clue: a found matrix against the expected one, row by row, as a ratio when the
//! row is the expected one scaled ("rows 1, 2 and 3 of M are 0.9063 of close2gl's (= cos 25°,
//! the pitch)"), or as the expected matrix transposed.

use glam::DMat4;

use super::{MATCH, Named, Values};

/// The most rows or entries one clue names.
const MAX_PARTS: usize = 4;

/// What a found row is to the expected one.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Row {
    /// Agrees.
    Same,
    /// Every entry that matters is `ratio` times the expected one; `entry`: the one entry that
    /// matters, when there is only one.
    Scaled { ratio: f64, entry: Option<usize> },
    /// Something else.
    Other,
}

/// The clue for matrix `name` (entries in the trace's rows: `found.col(c)[r]` is row r, column
/// c), over the `rows` checked; None when neither a ratio nor a transposition explains a row.
pub fn matrix(
    name: &str,
    expected: DMat4,
    found: DMat4,
    rows: &[usize],
    values: &Values,
) -> Option<String> {
    let at = |m: DMat4, r: usize, c: usize| m.col(c)[r];
    let largest = [expected, found]
        .iter()
        .flat_map(|m| m.to_cols_array())
        .fold(0.0f64, |a, b| a.max(b.abs()));
    let close = |e: f64, f: f64| (e - f).abs() <= MATCH * e.abs() + 1e-6 * largest;
    let all_rows = |m: DMat4, f: &dyn Fn(usize, usize) -> f64| {
        rows.iter()
            .all(|&r| (0..4).all(|c| close(f(r, c), at(m, r, c))))
    };
    let symmetric = all_rows(expected, &|r, c| at(expected, c, r));
    if !symmetric && all_rows(found, &|r, c| at(expected, c, r)) {
        return Some(format!(
            "{name} is close2gl's transposed: its row k is close2gl's column k"
        ));
    }
    let scaled: Vec<(usize, Row)> = rows
        .iter()
        .map(|&r| {
            let row = |m: DMat4| [0, 1, 2, 3].map(|c| at(m, r, c));
            (r, row_ratio(row(expected), row(found), 1e-6 * largest))
        })
        .collect();
    let parts = describe(name, &scaled, values);
    (!parts.is_empty()).then(|| parts.join("; "))
}

/// What `found` is to `expected`, entries below `negligible` counting as zero.
fn row_ratio(expected: [f64; 4], found: [f64; 4], negligible: f64) -> Row {
    let matters: Vec<usize> = (0..4).filter(|&c| expected[c].abs() > negligible).collect();
    let zero_kept = (0..4)
        .filter(|c| !matters.contains(c))
        .all(|c| found[c].abs() <= negligible);
    let ratios: Vec<f64> = matters.iter().map(|&c| found[c] / expected[c]).collect();
    let Some(&first) = ratios.first() else {
        return Row::Other;
    };
    let constant = ratios
        .iter()
        .all(|r| (r - first).abs() <= MATCH * first.abs());
    match (zero_kept, constant) {
        (true, true) if (first - 1.0).abs() <= MATCH => Row::Same,
        (true, true) => Row::Scaled {
            ratio: ratios.iter().sum::<f64>() / ratios.len() as f64,
            entry: (matters.len() == 1).then(|| matters[0]),
        },
        _ => Row::Other,
    }
}

/// The rows scaled alike in one part each ("rows 1 and 2 of M are ..."), a row alone with one
/// entry that matters as that entry ("P[0][0] is ..."), a negated row as such.
fn describe(name: &str, rows: &[(usize, Row)], values: &Values) -> Vec<String> {
    let mut parts: Vec<String> = Vec::new();
    let mut done = vec![false; rows.len()];
    for (i, &(r, row)) in rows.iter().enumerate() {
        let Row::Scaled { ratio, entry } = row else {
            continue;
        };
        if done[i] {
            continue;
        }
        let alike: Vec<usize> = (i..rows.len())
            .filter(|&j| !done[j] && same_ratio(rows[j].1, ratio))
            .collect();
        alike.iter().for_each(|&j| done[j] = true);
        let numbers: Vec<String> = alike.iter().map(|&j| (rows[j].0 + 1).to_string()).collect();
        let what = match (numbers.as_slice(), entry) {
            ([_], Some(c)) => format!("{name}[{r}][{c}] (row {}, column {}) is", r + 1, c + 1),
            ([one], None) => format!("row {one} of {name} is"),
            _ => format!("rows {} of {name} are", and_list(&numbers)),
        };
        parts.push(match values.name(ratio) {
            Named::Is(n) if n == "−1" => format!("{what} close2gl's negated"),
            _ => format!("{what} {}", values.of(ratio, "close2gl's")),
        });
    }
    parts.truncate(MAX_PARTS);
    parts
}

/// Whether `row` is scaled by `ratio`.
fn same_ratio(row: Row, ratio: f64) -> bool {
    matches!(row, Row::Scaled { ratio: r, .. } if (r - ratio).abs() <= MATCH * ratio.abs())
}

/// "1", "1 and 2", "1, 2 and 3".
fn and_list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::pitched;
    use super::*;
    use close2gl_pipeline::mistakes::Mistakes;
    use close2gl_pipeline::program::given;

    fn values() -> Values {
        let (camera, window) = pitched();
        Values::new(&camera, window)
    }

    fn m() -> DMat4 {
        given::modelview(&pitched().0, Mistakes::NONE)
    }

    fn p() -> DMat4 {
        given::projection(&pitched().0, Mistakes::NONE)
    }

    /// `m` with row `r` times `k`.
    fn scaled(m: DMat4, r: usize, k: f64) -> DMat4 {
        let mut rows = m.transpose().to_cols_array_2d();
        rows[r].iter_mut().for_each(|x| *x *= k);
        DMat4::from_cols_array_2d(&rows).transpose()
    }

    fn clue(name: &str, expected: DMat4, found: DMat4) -> Option<String> {
        matrix(name, expected, found, &[0, 1, 2, 3], &values())
    }

    #[test]
    fn rows_scaled_alike_are_named_together() {
        let c = 25f64.to_radians().cos();
        let found = scaled(scaled(scaled(m(), 0, c), 1, c), 2, c);
        assert_eq!(
            clue("M", m(), found).as_deref(),
            Some("rows 1, 2 and 3 of M are 0.9063 of close2gl's (= cos 25°, the pitch)")
        );
        assert_eq!(
            clue("M", m(), scaled(m(), 1, c)).as_deref(),
            Some("row 2 of M is 0.9063 of close2gl's (= cos 25°, the pitch)")
        );
    }

    #[test]
    fn a_row_of_one_entry_is_named_as_the_entry() {
        assert_eq!(
            clue("P", p(), scaled(p(), 0, 0.75)).as_deref(),
            Some("P[0][0] (row 1, column 1) is 0.7500 of close2gl's (= 3/4)")
        );
    }

    #[test]
    fn a_negated_row_and_a_transposed_matrix() {
        assert_eq!(
            clue("V", m(), scaled(m(), 1, -1.0)).as_deref(),
            Some("row 2 of V is close2gl's negated")
        );
        assert_eq!(
            clue("M", m(), m().transpose()).as_deref(),
            Some("M is close2gl's transposed: its row k is close2gl's column k")
        );
    }

    #[test]
    fn a_ratio_that_is_not_constant_or_not_known() {
        let mut rows = m().transpose().to_cols_array_2d();
        rows[1][1] *= 0.9;
        rows[1][2] *= 0.8;
        let found = DMat4::from_cols_array_2d(&rows).transpose();
        assert_eq!(clue("M", m(), found), None, "0.9 and 0.8: no ratio");
        assert_eq!(
            clue("M", m(), scaled(m(), 0, 0.8123)).as_deref(),
            Some("row 1 of M is 0.8123 of close2gl's")
        );
        assert_eq!(clue("M", m(), m()), None, "the same matrix");
        let mut moved = m();
        moved.w_axis.x += 3.0;
        assert_eq!(
            clue("M", m(), moved),
            None,
            "a translation entry off, not a ratio"
        );
    }

    #[test]
    fn only_the_checked_rows_count() {
        let found = scaled(m(), 2, 2.0);
        assert_eq!(matrix("V", m(), found, &[0, 1, 3], &values()), None);
    }
}
