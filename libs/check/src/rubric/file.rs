//! A rubric file as a teacher writes it (TOML): `assignment = "..."` and one `[[line]]` table
//! per line. What both assignments' rubrics share: the file's shape, and each line's `id`,
//! `title` and `points`, every fault an error naming the file and the key (or line) that is
//! wrong. Each assignment reads the rest of its lines' keys.

/// The assignment a rubric file says it is for (`assignment = "..."`), when it reads as TOML and
/// says so.
pub fn assignment(text: &str) -> Option<String> {
    let table: toml::Table = text.parse().ok()?;
    table.get("assignment")?.as_str().map(String::from)
}

/// The `[[line]]` tables of a rubric for `assignment`, each with the key errors name it by
/// (`line[2]`).
pub fn lines(
    text: &str,
    file: &str,
    assignment: &str,
) -> Result<Vec<(String, toml::Table)>, String> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let line = e
            .span()
            .map_or(0, |s| 1 + text[..s.start].matches('\n').count());
        format!("{file}:{line}: {}", e.message())
    })?;
    let fail = |key: &str, what: &str| format!("{file}: {key}: expected {what}");
    if table.get("assignment").and_then(|v| v.as_str()) != Some(assignment) {
        return Err(fail("assignment", &format!("\"{assignment}\"")));
    }
    if let Some(key) = table
        .keys()
        .find(|k| !["assignment", "line"].contains(&k.as_str()))
    {
        return Err(fail(key, "only 'assignment' and '[[line]]' tables"));
    }
    let lines = table
        .get("line")
        .and_then(|v| v.as_array())
        .filter(|a| !a.is_empty());
    let lines = lines.ok_or_else(|| fail("line", "at least one [[line]]"))?;
    (lines.iter().enumerate())
        .map(|(i, line)| {
            let key = format!("line[{}]", i + 1);
            let table = line.as_table().ok_or_else(|| fail(&key, "a table"))?;
            Ok((key, table.clone()))
        })
        .collect()
}

/// A line's `id`, `title` and `points`, after checking it has only the keys `known`.
pub fn head(
    line: &toml::Table,
    key: &str,
    file: &str,
    known: &[&str],
) -> Result<(String, String, u32), String> {
    let fail = |name: &str, what: &str| format!("{file}: {key}.{name}: expected {what}");
    if let Some(other) = line.keys().find(|k| !known.contains(&k.as_str())) {
        return Err(fail(other, &format!("only {}", known.join(", "))));
    }
    let text = |name: &str| {
        let value = line
            .get(name)
            .and_then(|v| v.as_str())
            .filter(|s| !s.is_empty());
        value.map(String::from).ok_or_else(|| fail(name, "a text"))
    };
    let points = line.get("points").and_then(|v| v.as_integer());
    let points = points
        .and_then(|p| u32::try_from(p).ok())
        .ok_or_else(|| fail("points", "a whole number of points, 0 or more"))?;
    Ok((text("id")?, text("title")?, points))
}
