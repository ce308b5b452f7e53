//! The grade as one self-contained HTML page (no network: styles inline, pictures as data:
//! URIs): the rubric table, then every failing scene with close2gl's picture, the trace's, the
//! difference, the scene's text and check's findings.

use std::fmt::Write;

use base64::Engine;
use base64::engine::general_purpose::STANDARD;

use super::sandboxing::Sandboxing;
use super::sheet::{FailingScene, Sheet};

const STYLE: &str = "body{font:14px/1.4 system-ui,sans-serif;margin:2em;color:#222;max-width:1200px}\
table{border-collapse:collapse}td,th{padding:.25em .8em;border-bottom:1px solid #ddd;text-align:left;vertical-align:top}\
td.n{text-align:right;white-space:nowrap}tr.full td.n{color:#186a2b}tr.lost td.n{color:#b3261e;font-weight:600}\
.why{font-size:12px;color:#555;white-space:pre-wrap}pre{background:#f6f6f6;padding:.6em;overflow-x:auto;font-size:12px}\
figure{display:inline-block;margin:0 1em 1em 0}figcaption{font-size:12px;color:#555}\
img{image-rendering:pixelated;border:1px solid #ccc;max-width:360px}section{border-top:2px solid #ddd;margin-top:2em}\
li.lost{color:#b3261e}ul.sandbox{font-size:12px}.legend span{display:inline-block;padding:0 .5em;margin-right:.3em;color:#fff;font-size:12px}";

/// The page for `grade`, of the program run as `command`.
pub fn page(grade: &Sheet, title: &str, command: &str, sandboxing: &Sandboxing) -> String {
    let mut out = String::new();
    let _ = write!(
        out,
        "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>{}</title><style>{STYLE}\
         </style></head><body><h1>{}: {}/{}</h1><p><code>{}</code></p>",
        escape(title),
        escape(title),
        grade.total,
        grade.max,
        escape(command)
    );
    sandbox_list(&mut out, sandboxing);
    let _ = write!(
        out,
        "<h2>To fix</h2><pre>{}</pre>",
        escape(&grade.to_fix.join("\n"))
    );
    rubric_table(&mut out, grade);
    if !grade.failing.is_empty() {
        let _ = write!(
            out,
            "<h2>Failing scenes ({})</h2>{}",
            grade.failing.len(),
            legend(&grade.legend)
        );
    }
    for scene in &grade.failing {
        failing_scene(&mut out, scene);
    }
    out.push_str("</body></html>\n");
    out
}

/// A failing scene's section: the lines it failed and why, the pictures, check's report and
/// the scene file.
fn failing_scene(out: &mut String, scene: &FailingScene) {
    let _ = write!(
        out,
        "<section><h3 id=\"{0}\">{0}</h3><ul>",
        escape(&scene.id)
    );
    for (line, why) in &scene.lines {
        let _ = write!(
            out,
            "<li><b>{}</b>: <span class=\"why\">{}</span></li>",
            escape(line),
            escape(why)
        );
    }
    out.push_str("</ul>");
    for (caption, png) in &scene.pictures {
        let _ = write!(
            out,
            "<figure><img alt=\"{caption}\" src=\"data:image/png;base64,{}\">\
             <figcaption>{caption}</figcaption></figure>",
            STANDARD.encode(png)
        );
    }
    if let Some(check) = &scene.check {
        let _ = write!(out, "<h4>check</h4><pre>{}</pre>", escape(check));
    }
    let _ = write!(
        out,
        "<h4>scene</h4><pre>{}</pre></section>",
        escape(&scene.scene_text)
    );
}

fn rubric_table(out: &mut String, grade: &Sheet) {
    out.push_str("<table><tr><th>line</th><th>points</th><th>scenes</th><th></th></tr>");
    for line in &grade.lines {
        let class = if line.full() { "full" } else { "lost" };
        let mut why = line.evidence.join("\n");
        for note in &line.notes {
            why.push_str(&format!("\naccepted: {note}"));
        }
        let _ = write!(
            out,
            "<tr class=\"{class}\"><td>{}</td><td class=\"n\">{}/{}</td><td class=\"n\">{}/{}</td>\
             <td class=\"why\">{}</td></tr>",
            escape(&line.title),
            line.points,
            line.max,
            line.passed,
            line.scenes,
            escape(why.trim())
        );
    }
    let _ = write!(
        out,
        "<tr><th>total</th><th class=\"n\">{}/{}</th><th></th><th></th></tr></table>",
        grade.total, grade.max
    );
}

/// The protections the programs ran under, each enforced or missing.
fn sandbox_list(out: &mut String, sandboxing: &Sandboxing) {
    out.push_str("<p class=\"sandbox\">Sandbox:</p><ul class=\"sandbox\">");
    for (name, enforced, detail) in sandboxing.rows() {
        let (class, word) = match enforced {
            true => ("full", "enforced"),
            false => ("lost", "missing"),
        };
        let _ = write!(
            out,
            "<li class=\"{class}\"><b>{name}</b> ({word}): {}</li>",
            escape(&detail)
        );
    }
    out.push_str("</ul>");
}

/// The difference picture's colours, as the sheet names them; nothing when it has none.
fn legend(colours: &[(&str, [u8; 4])]) -> String {
    if colours.is_empty() {
        return String::new();
    }
    let mut out = String::from("<p class=\"legend\">In the difference: grey agrees; ");
    for (name, [r, g, b, _]) in colours {
        let _ = write!(
            out,
            "<span style=\"background:rgb({r},{g},{b})\">{name}</span>"
        );
    }
    out.push_str("</p>");
    out
}

/// Text for HTML: `&`, `<`, `>` and quotes escaped (a program's stderr is quoted on the page).
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}
