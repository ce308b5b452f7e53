//! The journey and the matrices as tables: one small grid per stage with its columns named
//! (`x y z w`; the window's `x y depth`), every number in the same few monospace characters so
//! that the columns line up and never run together, and, as Eric Haines' pipeline demo marks the
//! numbers a transform changed, the row that changed most from the stage before highlighted.

use close2gl_core::glam::{Mat4, Vec3};
use close2gl_pipeline::journey::Journey;

/// Characters per number: a sign and five significant digits with their point. Five digits keep a
/// 1500-unit cow's corners (210.01 beside 209.99) apart, and a 2-unit cube's (0.3750) too.
const WIDTH: usize = 7;
const SIGNIFICANT: i32 = 5;
/// Small enough that the row name and four columns fit the panel's width.
const SIZE: f32 = 10.0;

/// One stage of the journey: its name as the course writes it, its columns and one row per point.
struct Stage {
    name: String,
    headers: &'static [&'static str],
    rows: Vec<Vec<f32>>,
}

const XYZ: &[&str] = &["x", "y", "z"];
const XYZW: &[&str] = &["x", "y", "z", "w"];

/// Each stage's points: world, eye = M·p, clip = P·M·p, the polygon after each clipping step,
/// NDC (÷ w) and window (V·ndc: pixels, depth).
fn stages(journey: &Journey) -> Vec<Stage> {
    let stage = |name: &str, headers, rows: Vec<Vec<f32>>| Stage {
        name: name.to_string(),
        headers,
        rows,
    };
    let xyz = |points: &[Vec3]| -> Vec<Vec<f32>> {
        points.iter().map(|p| p.to_array().to_vec()).collect()
    };
    let mut stages = vec![
        stage("world", XYZ, xyz(&journey.world)),
        stage("eye = M·p", XYZ, xyz(&journey.eye)),
        stage(
            "clip = P·M·p",
            XYZW,
            journey.clip.iter().map(|p| p.to_array().to_vec()).collect(),
        ),
    ];
    for step in &journey.clip_steps {
        stages.push(Stage {
            name: format!("clipped at the {} plane", step.plane.name()),
            headers: XYZW,
            rows: step.polygon.iter().map(|p| p.to_array().to_vec()).collect(),
        });
    }
    stages.push(stage("ndc (÷ w)", XYZ, xyz(&journey.ndc)));
    stages.push(stage(
        "window (V·ndc)",
        &["x", "y", "depth"],
        xyz(&journey.window),
    ));
    stages
}

/// The journey, one table per stage, each with the row that changed most highlighted.
pub fn journey_table(ui: &mut egui::Ui, journey: &Journey) {
    let stages = stages(journey);
    let mut previous: Option<&Stage> = None;
    for (k, stage) in stages.iter().enumerate() {
        if stage.rows.is_empty() {
            let text = format!("{}: nothing, clipping removed the triangle", stage.name);
            ui.label(egui::RichText::new(text).small());
            continue;
        }
        ui.label(egui::RichText::new(&stage.name).small());
        let changed = previous.and_then(|p| changed_most(&p.rows, &stage.rows));
        table(
            ui,
            format!("journey {k}"),
            stage.headers,
            &stage.rows,
            changed,
        );
        previous = Some(stage);
    }
}

/// M, P, V or one of the reference's matrices: its four rows, a column per coordinate it
/// multiplies.
pub fn matrix_table(ui: &mut egui::Ui, name: &str, matrix: Mat4) {
    ui.label(egui::RichText::new(name).small());
    let rows: Vec<Vec<f32>> = (0..4).map(|r| matrix.row(r).to_array().to_vec()).collect();
    table(ui, format!("matrix {name}"), XYZW, &rows, None);
}

/// A grid with a header row, the rows numbered from 0, and `highlight` shaded.
fn table(
    ui: &mut egui::Ui,
    id: String,
    headers: &[&str],
    rows: &[Vec<f32>],
    highlight: Option<usize>,
) {
    let shade = ui.visuals().selection.bg_fill.gamma_multiply(0.6);
    egui::Grid::new(id)
        .num_columns(headers.len() + 1)
        .spacing([6.0, 1.0])
        // Row 0 is the header.
        .with_row_color(move |row, _| (Some(row) == highlight.map(|h| h + 1)).then_some(shade))
        .show(ui, |ui| {
            ui.label("");
            for header in headers {
                ui.add(cell(format!("{header:>WIDTH$}")));
            }
            ui.end_row();
            for (i, row) in rows.iter().enumerate() {
                ui.add(cell(i.to_string()));
                for &value in row {
                    ui.add(cell(number(value)));
                }
                ui.end_row();
            }
        });
}

fn cell(text: String) -> egui::Label {
    egui::Label::new(egui::RichText::new(text).monospace().size(SIZE))
        .wrap_mode(egui::TextWrapMode::Extend)
}

/// `value` right-aligned in [`WIDTH`] characters with about [`SIGNIFICANT`] digits whatever its
/// size; what would need more characters (or is tiny but not zero) in scientific notation.
pub fn number(value: f32) -> String {
    // -0.0 + 0.0 is 0.0: a zero shows without a sign.
    let value = value + 0.0;
    let magnitude = value.abs();
    if !value.is_finite() || magnitude >= 99_999.5 || (magnitude < 1e-3 && magnitude > 0.0) {
        return format!("{value:>WIDTH$.1e}");
    }
    let whole_digits = if magnitude == 0.0 {
        1
    } else {
        magnitude.log10().floor() as i32 + 1
    };
    let mut decimals = (SIGNIFICANT - whole_digits).clamp(0, 4) as usize;
    loop {
        // Rounding may carry a digit (9.99996 to 10.0000): drop a decimal then.
        let text = format!("{value:>WIDTH$.decimals$}");
        if text.len() <= WIDTH || decimals == 0 {
            return text;
        }
        decimals -= 1;
    }
}

/// The row of `rows` that moved most from the stage before: from the same row when both stages
/// have as many (the corners, transformed), else from the nearest row before (clipping adds
/// points where an edge crosses a plane; the corners it keeps do not move). None when nothing
/// moved.
fn changed_most(before: &[Vec<f32>], rows: &[Vec<f32>]) -> Option<usize> {
    let distance =
        |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f32>();
    let change = |i: usize, row: &[f32]| match before.len() == rows.len() {
        true => distance(row, &before[i]),
        false => before
            .iter()
            .map(|b| distance(row, b))
            .fold(f32::INFINITY, f32::min),
    };
    rows.iter()
        .enumerate()
        .map(|(i, row)| (i, change(i, row)))
        .filter(|(_, d)| *d > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_their_width_and_five_digits_at_any_scale() {
        for (value, text) in [
            (-1496.136, "-1496.1"),
            (210.007, " 210.01"),
            (209.996, " 210.00"),
            (0.375, " 0.3750"),
            (-14.247, "-14.247"),
            (0.0, " 0.0000"),
            (-0.0, " 0.0000"),
            (9.99996, "10.0000"),
            (-9.99996, "-10.000"),
            (123_456.0, "1.2e5"),
            (-0.00002, "-2.0e-5"),
        ] {
            let shown = number(value);
            assert_eq!(shown.trim(), text.trim(), "{value}");
            assert_eq!(shown.len(), WIDTH, "{shown:?}");
        }
    }

    #[test]
    fn the_row_that_moved_most_is_the_one_highlighted() {
        let before = vec![vec![0.0, 0.0], vec![1.0, 0.0], vec![0.0, 1.0]];
        let after = vec![vec![0.0, 0.0], vec![5.0, 0.0], vec![0.0, 2.0]];
        assert_eq!(changed_most(&before, &after), Some(1));
        assert_eq!(changed_most(&before, &before), None, "nothing moved");
        // A clip step: the new point is the one that changed, the kept corners did not.
        let clipped = vec![
            vec![0.0, 0.0],
            vec![0.5, 0.0],
            vec![0.0, 0.5],
            vec![0.0, 1.0],
        ];
        let new = changed_most(&before, &clipped).expect("a point was added");
        assert!(new == 1 || new == 2, "{new}");
    }
}
