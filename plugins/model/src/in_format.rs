//! The course's `.in` triangle format (see the README's Models section): a header, material blocks,
//! an optional `Texture =` line, a free comment line, then four records per triangle. Layout
//! is tolerated (runs of spaces, `\r\n`, blank lines, any keyword case, a missing final newline);
//! content is not (every number finite, every record complete, material indices in range).

use std::io::{self, BufRead, BufReader, Read};

use crate::diagnostics::expected;
use crate::in_parallel;
use crate::in_triangles::{Body, FileTriangle, VERTEX_TAGS, VertexLayout};
use crate::line_reader::Lines;
use crate::mesh_builder::MeshBuilder;
use crate::{LoadedModel, file_stem};

/// Parses the text of a `.in` file; `label` names the file in messages and warnings.
pub fn parse_in(text: &str, label: &str) -> Result<LoadedModel, String> {
    read_in(|| Ok(text.as_bytes()), text.len() as u64, label)
}

/// Parses a `.in` file read from the start by each `open()`: the header line by line, then the
/// triangles in blocks on all cores (see `in_parallel`), so that memory follows the mesh, not
/// the file. A body the parallel reader does not take whole (any bad record) is read again line
/// by line, whose error is the one reported: the same file and line as ever. `size` is the
/// file's length in bytes.
pub(crate) fn read_in<R: Read>(
    open: impl Fn() -> Result<R, String>,
    size: u64,
    label: &str,
) -> Result<LoadedModel, String> {
    read_in_blocks(open, size, label, in_parallel::block_bytes())
}

/// [`read_in`] reading the triangles `block` bytes at a time (the tests use tiny blocks).
pub(crate) fn read_in_blocks<R: Read>(
    open: impl Fn() -> Result<R, String>,
    size: u64,
    label: &str,
    block: usize,
) -> Result<LoadedModel, String> {
    let mut records = Records::new(Lines::new(BufReader::new(open()?), label));
    let header = Header::read(&mut records)?;
    let body_start = records.next_offset();
    drop(records);
    let mut reader = open()?;
    io::copy(&mut (&mut reader).take(body_start), &mut io::sink())
        .map_err(|e| format!("{label}: cannot read: {e}"))?;
    let capacity = header.triangles_to_expect(size.saturating_sub(body_start));
    let empty = Body::new(MeshBuilder::with_capacity(header.name.clone(), capacity));
    match in_parallel::read_body(reader, &header.layout, empty, block, label)? {
        Some(body) => Ok(header.finish(body, label)),
        None => read_in_lines(Lines::new(BufReader::new(open()?), label)),
    }
}

/// Parses a `.in` file line by line as `lines` reads it: the reference for what a file means and
/// where it is wrong.
pub(crate) fn read_in_lines<R: BufRead>(lines: Lines<R>) -> Result<LoadedModel, String> {
    let label = lines.label();
    let mut records = Records::new(lines);
    let header = Header::read(&mut records)?;
    let mut body = Body::new(MeshBuilder::new(header.name.clone()));
    // A file without triangles fails in the first pass, at the v0 it expected.
    loop {
        let triangle = header.layout.triangle(&mut records)?;
        body.add(triangle)?;
        if records.peek()?.is_none() {
            break;
        }
    }
    Ok(header.finish(body, label))
}

/// The fewest bytes a triangle's four records take: `v0 0 0 0 0 0 0 0` and its newline, three
/// times, then `face normal 0 0 0` (69 bytes), rounded down.
const MIN_TRIANGLE_BYTES: u64 = 64;

/// Everything before the first triangle.
struct Header {
    name: String,
    /// The triangle count the header claims; only compared with what the file holds.
    triangles: u64,
    layout: VertexLayout,
    warnings: Vec<String>,
}

impl Header {
    /// Reads the header, the material blocks, the `Texture =` line and the comment line.
    fn read<R: BufRead>(records: &mut Records<R>) -> Result<Self, String> {
        let label = records.label;
        let (_, name) = records.key_value("Object name", "Object name = <name>")?;
        let triangles = records.count("# triangles", "# triangles = <N>")?;
        let material_count = records.count("Material count", "Material count = <M>")?;
        // Counted, never allocated from: a lying header only makes the loop meet the vertices
        // early.
        let mut materials = MaterialCheck::default();
        for _ in 0..material_count {
            materials.block(records)?;
        }
        let layout = VertexLayout::new(records.texture()?, material_count);
        records.skip_comment()?;
        Ok(Self {
            name: if name.is_empty() {
                file_stem(label)
            } else {
                name
            },
            triangles,
            layout,
            warnings: materials.warnings(label).into_iter().collect(),
        })
    }

    /// How many triangles to make room for in a body of `bytes` bytes: the header's count, but
    /// never more than the body can hold, so that a header that lies costs what the file's size
    /// allows, not what it claims (the corner index made for it, the only part touched before
    /// a triangle is read, is under a fifth of the body).
    fn triangles_to_expect(&self, bytes: u64) -> usize {
        let most = bytes / MIN_TRIANGLE_BYTES;
        usize::try_from(self.triangles.min(most)).unwrap_or(0)
    }

    /// The model, with what was forgiven on the way.
    fn finish(mut self, body: Body, label: &str) -> LoadedModel {
        if body.triangles != self.triangles {
            self.warnings.push(format!(
                "{label}: header says {} triangles, found {}",
                self.triangles, body.triangles
            ));
        }
        self.warnings.extend(body.orientation.warnings(label));
        LoadedModel {
            mesh: body.builder.finish(),
            warnings: self.warnings,
        }
    }
}

/// The file's non-blank lines ("records"), trimmed, in order. The record last handed out stays
/// readable, so errors can quote it.
struct Records<'l, R> {
    lines: Lines<'l, R>,
    /// The record last read, trimmed.
    text: String,
    /// Its 1-based line number.
    line: usize,
    /// The byte offset at which its line starts.
    start: u64,
    /// Whether it was only peeked at, not yet handed out.
    peeked: bool,
    /// Whether the file has no more records.
    ended: bool,
    label: &'l str,
}

impl<'l, R: BufRead> Records<'l, R> {
    fn new(lines: Lines<'l, R>) -> Self {
        Self {
            label: lines.label(),
            lines,
            text: String::new(),
            line: 0,
            start: 0,
            peeked: false,
            ended: false,
        }
    }

    /// The line number of the next record without handing it out, or `None` at the end.
    fn peek(&mut self) -> Result<Option<usize>, String> {
        if !self.peeked && !self.ended {
            loop {
                let start = self.lines.offset();
                let Some((line, text)) = self.lines.next_line()? else {
                    self.ended = true;
                    break;
                };
                let text = if line == 1 {
                    text.strip_prefix('\u{feff}').unwrap_or(text)
                } else {
                    text
                };
                let text = text.trim();
                if !text.is_empty() {
                    self.text.clear();
                    self.text.push_str(text);
                    self.line = line;
                    self.start = start;
                    self.peeked = true;
                    break;
                }
            }
        }
        Ok(self.peeked.then_some(self.line))
    }

    /// The byte offset of the next record (or of the blank lines before it).
    fn next_offset(&self) -> u64 {
        if self.peeked {
            self.start
        } else {
            self.lines.offset()
        }
    }

    /// The text of the record last peeked at or handed out.
    fn text(&self) -> &str {
        &self.text
    }

    /// The next record's line number, which must exist: the end of the file is an error naming
    /// `what`. Its text is [`Records::text`] until the next call.
    fn expect(&mut self, what: &str) -> Result<usize, String> {
        match self.peek()? {
            Some(line) => {
                self.peeked = false;
                Ok(line)
            }
            None => Err(expected(self.label, self.line + 1, what, None)),
        }
    }

    /// The error for the record last handed out (at `line`).
    fn error(&self, line: usize, what: &str) -> String {
        expected(self.label, line, what, Some(&self.text))
    }

    /// The value of a `key = value` record; the key is compared ignoring case and spaces.
    fn key_value(&mut self, key: &str, what: &str) -> Result<(usize, String), String> {
        let line = self.expect(what)?;
        match self.text.split_once('=') {
            Some((k, value)) if same_key(k, key) => Ok((line, value.trim().to_string())),
            _ => Err(self.error(line, what)),
        }
    }

    /// A `key = <count>` header record. The count is only compared with what the file holds,
    /// never allocated from.
    fn count(&mut self, key: &str, what: &str) -> Result<u64, String> {
        let (line, value) = self.key_value(key, what)?;
        value.parse().map_err(|_| self.error(line, what))
    }

    /// The optional `Texture = YES|NO` record: whether `<s> <t>` follow each vertex, or `None`
    /// when the file does not say.
    fn texture(&mut self) -> Result<Option<bool>, String> {
        const WHAT: &str = "Texture = YES|NO";
        let is_texture = self.peek()?.is_some()
            && self
                .text()
                .split_once('=')
                .is_some_and(|(k, _)| same_key(k, "Texture"));
        if !is_texture {
            return Ok(None);
        }
        let (line, value) = self.key_value("Texture", WHAT)?;
        if value.eq_ignore_ascii_case("yes") {
            Ok(Some(true))
        } else if value.eq_ignore_ascii_case("no") {
            Ok(Some(false))
        } else {
            Err(self.error(line, WHAT))
        }
    }

    /// The comment line before the first triangle is optional and its wording free: anything
    /// that is not the first `v0` record is taken for it.
    fn skip_comment(&mut self) -> Result<(), String> {
        if self.peek()?.is_some()
            && !self
                .text()
                .split_whitespace()
                .next()
                .is_some_and(|w| w.eq_ignore_ascii_case(VERTEX_TAGS[0]))
        {
            self.peeked = false;
        }
        Ok(())
    }

    /// The numbers of a `keywords n1 n2 ...` record, which must have one of `counts` numbers,
    /// all finite.
    fn numbers(
        &mut self,
        keywords: &[&str],
        counts: &[usize],
        what: &str,
    ) -> Result<(usize, Vec<f32>), String> {
        let line = self.expect(what)?;
        let mut words = self.text.split_whitespace();
        let keywords_match = keywords
            .iter()
            .all(|k| words.next().is_some_and(|w| w.eq_ignore_ascii_case(k)));
        let values: Option<Vec<f32>> = keywords_match
            .then(|| words.map(|w| w.parse().ok()).collect())
            .flatten();
        match values {
            Some(v) if counts.contains(&v.len()) => {
                if v.iter().all(|x| x.is_finite()) {
                    Ok((line, v))
                } else {
                    Err(format!(
                        "{} (numbers must be finite)",
                        self.error(line, what)
                    ))
                }
            }
            _ => Err(self.error(line, what)),
        }
    }
}

fn same_key(text: &str, key: &str) -> bool {
    let squeeze = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
    squeeze(text).eq_ignore_ascii_case(&squeeze(key))
}

/// Checks the material blocks, whose colours the app does not use (it shows one user-picked
/// colour) but which must still be well formed. Values out of range are forgiven with a warning.
#[derive(Default)]
struct MaterialCheck {
    /// The first record with a colour outside 0..1 or a negative shine.
    out_of_range: Option<usize>,
}

impl MaterialCheck {
    fn block<R: BufRead>(&mut self, records: &mut Records<R>) -> Result<(), String> {
        for (keywords, what) in [
            (["ambient", "color"], "ambient color r g b"),
            (["diffuse", "color"], "diffuse color r g b"),
            (["specular", "color"], "specular color r g b"),
        ] {
            let (line, rgb) = records.numbers(&keywords, &[3], what)?;
            if rgb.iter().any(|c| !(0.0..=1.0).contains(c)) {
                self.out_of_range.get_or_insert(line);
            }
        }
        let (line, shine) = records.numbers(&["material", "shine"], &[1], "material shine s")?;
        if shine[0] < 0.0 {
            self.out_of_range.get_or_insert(line);
        }
        Ok(())
    }

    fn warnings(&self, label: &str) -> Option<String> {
        self.out_of_range.map(|line| {
            format!("{label}:{line}: material value out of range (colours 0..1, shine >= 0); ignored, the model is drawn in the chosen colour")
        })
    }
}

impl VertexLayout {
    fn triangle<R: BufRead>(&self, records: &mut Records<R>) -> Result<FileTriangle, String> {
        let mut triangle = FileTriangle::default();
        for (k, (tag, what)) in VERTEX_TAGS.iter().zip(&self.forms).enumerate() {
            let (line, v) = records.numbers(&[tag], self.counts, what)?;
            if !self.is_material(v[6]) {
                return Err(format!(
                    "{} (the material index must be a whole number below the material count, {})",
                    records.error(line, what),
                    self.material_count
                ));
            }
            triangle.set_corner(k, &v);
        }
        let (_, n) = records.numbers(&["face", "normal"], &[3], "face normal nx ny nz")?;
        triangle.set_face_normal(&n);
        Ok(triangle)
    }
}
