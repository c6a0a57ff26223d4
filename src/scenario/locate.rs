//! Where in the text a TOML error lies, and which field it is. A document is read in two steps: the
//! TOML syntax into a table ([`toml::Table`]), then that table into the schema's types through
//! [`serde_path_to_error`], which records the path of the value being read when an error is raised
//! (`section.supports[1]`). The path is then walked in a spanned copy of the document
//! ([`toml::de::DeTable`]) to the value's own line. Where serde reports an error on a whole table (an
//! internally tagged `[[events]]` table or `supports` element is read through a buffer, which loses the
//! position of its values), the message names the value (or its length, or its key) and the value is
//! found among that table's entries. A missing field is reported with every other field missing from the
//! same table (the table is completed with placeholders and read again), not only the first.

use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::InputError;

/// Read `text` into `T`: a syntax error keeps the parser's line and column; an error of a value names its
/// field path and points at its line ([module doc](self)).
pub(crate) fn from_text<T: DeserializeOwned>(text: &str, file: &str) -> Result<T, InputError> {
    from_table(parse_table(text, file)?, text, file)
}

/// The TOML syntax of `text` into a table, once: a syntax error keeps the parser's line and column.
pub(crate) fn parse_table(text: &str, file: &str) -> Result<toml::Table, InputError> {
    text.parse().map_err(|e: toml::de::Error| InputError::Parse {
        file: file.to_string(),
        message: super::plain_types(&e.to_string()),
    })
}

/// Read an already parsed document (of `text`, perhaps completed: catalogue data filled in) into `T`,
/// errors located in `text`.
pub(crate) fn from_table<T: DeserializeOwned>(table: toml::Table, text: &str, file: &str) -> Result<T, InputError> {
    let (path, error) = match read::<T>(table.clone()) {
        Ok(v) => return Ok(v),
        Err(e) => e,
    };
    let mut message = error.message().to_string();
    if let Some(first) = missing_field(&message) {
        let all = all_missing::<T>(table, &path, first);
        if all.len() > 1 {
            let names: Vec<String> = all.iter().map(|f| format!("`{f}`")).collect();
            message = format!("missing fields {}", names.join(", "));
        }
    }
    let message = super::temperature::name_twins(&message);
    Err(InputError::Parse { file: file.to_string(), message: super::plain_types(&describe(text, &path, &message)) })
}

/// Read a document that has no source text (a Python dict made a table) into `T`. An error is a
/// [`Problem`](super::Problem) at the field's path as the user wrote it (`events[1].at_fraction`,
/// `(the top level)` for the document itself), with the value as TOML writes it (cut to 60 characters,
/// `a table` for a table) and the parser's message in plain terms; a missing field is `(missing)`, and every
/// field missing from the same table is a problem of its own.
pub fn from_table_alone<T: DeserializeOwned>(mut table: toml::Table, file: &str) -> Result<T, InputError> {
    super::temperature::to_kelvin(&mut table)
        .map_err(|problems| InputError::Invalid { file: file.to_string(), problems })?;
    let (mut path, error) = match read::<T>(table.clone()) {
        Ok(v) => return Ok(v),
        Err(e) => e,
    };
    let message = error.message();
    let problem = |field: &[Step], value: String, allowed: &str| super::Problem {
        field: if field.is_empty() { "(the top level)".into() } else { field_path(field) },
        value,
        allowed: super::plain_types(&super::temperature::name_twins(allowed)),
    };
    if let Some(first) = missing_field(message) {
        let problems = all_missing::<T>(table, &path, first)
            .into_iter()
            .map(|f| {
                let at: Vec<Step> = path.iter().cloned().chain([Step::Key(f.clone())]).collect();
                problem(&at, "(missing)".into(), &format!("missing field `{f}`"))
            })
            .collect();
        return Err(InputError::Invalid { file: file.to_string(), problems });
    }
    let root = toml::Value::Table(table);
    let mut node = &root;
    for (k, step) in path.iter().enumerate() {
        let next = match (step, node) {
            (Step::Key(key), toml::Value::Table(t)) => t.get(key),
            (Step::Index(i), toml::Value::Array(a)) => a.get(*i),
            _ => None,
        };
        match next {
            Some(n) => node = n,
            None => {
                path.truncate(k);
                break;
            }
        }
    }
    // A table read through a buffer: find the offending entry among its own.
    if let (toml::Value::Table(t), Some(wanted)) = (node, Wanted::from_message(message)) {
        let hits: Vec<_> = t.iter().filter(|(key, value)| wanted.matches_value(key, value)).collect();
        if let [(key, value)] = hits.as_slice() {
            path.push(Step::Key(key.to_string()));
            node = value;
        }
    }
    let value = match node {
        toml::Value::Table(_) => "a table".to_string(),
        v => {
            let s = v.to_string();
            if s.chars().count() > 60 { format!("{}...", s.chars().take(57).collect::<String>()) } else { s }
        }
    };
    Err(InputError::Invalid { file: file.to_string(), problems: vec![problem(&path, value, message)] })
}

/// A path segment of a value in the document.
#[derive(Clone, Debug, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

fn read<T: DeserializeOwned>(table: toml::Table) -> Result<T, (Vec<Step>, toml::de::Error)> {
    serde_path_to_error::deserialize(toml::Value::Table(table)).map_err(|e| {
        let steps = e
            .path()
            .iter()
            .filter_map(|s| match s {
                serde_path_to_error::Segment::Map { key } => Some(Step::Key(key.clone())),
                serde_path_to_error::Segment::Seq { index } => Some(Step::Index(*index)),
                _ => None,
            })
            .collect();
        (steps, e.into_inner())
    })
}

/// The field of a "missing field `f`" message.
fn missing_field(message: &str) -> Option<String> {
    let rest = message.strip_prefix("missing field `")?;
    Some(rest[..rest.find('`')?].to_string())
}

/// Every field missing from the table at `path`: each missing one is given a placeholder (the first of a
/// few kinds of value its type accepts) and the document read again, until the error moves elsewhere.
fn all_missing<T: DeserializeOwned>(mut table: toml::Table, path: &[Step], first: String) -> Vec<String> {
    let placeholders = || {
        [
            toml::Value::Float(1.0),
            toml::Value::Integer(2),
            toml::Value::String(String::new()),
            toml::Value::Boolean(false),
            toml::Value::Array(vec![toml::Value::Float(1.0); 3]),
            toml::Value::Array(vec![toml::Value::Float(1.0); 2]),
            toml::Value::Array(Vec::new()),
            toml::Value::Table(toml::Table::new()),
        ]
    };
    let mut found = vec![first];
    'fields: while found.len() < 64 {
        let field = found.last().expect("one field").clone();
        for value in placeholders() {
            let Some(at) = table_at(&mut table, path) else { break 'fields };
            at.insert(field.clone(), value);
            match read::<T>(table.clone()) {
                Ok(_) => break 'fields,
                Err((p, e)) => match missing_field(e.message()) {
                    Some(next) if p == path && !found.contains(&next) => {
                        found.push(next);
                        continue 'fields;
                    }
                    // The placeholder's type is wrong (reported at the field, or at a buffered table).
                    _ if p.starts_with(path) && (p.len() > path.len() || e.message().starts_with("invalid")) => {}
                    _ => break 'fields,
                },
            }
        }
        break;
    }
    found
}

/// The table at `path` in a document.
fn table_at<'a>(table: &'a mut toml::Table, path: &[Step]) -> Option<&'a mut toml::Table> {
    let mut value: &mut toml::Table = table;
    let mut k = 0;
    while k < path.len() {
        let Step::Key(key) = &path[k] else { return None };
        let mut v = value.get_mut(key)?;
        k += 1;
        while let Some(Step::Index(i)) = path.get(k) {
            v = v.as_array_mut()?.get_mut(*i)?;
            k += 1;
        }
        value = v.as_table_mut()?;
    }
    Some(value)
}

/// The message with the field's path and its place in the text.
fn describe(text: &str, path: &[Step], message: &str) -> String {
    let mut shown = path.to_vec();
    let span = DeTable::parse(text).ok().map(|root| {
        let (span, table) = (root.span(), root.into_inner());
        let root = Spanned::new(span, DeValue::Table(table));
        let mut node = &root;
        for (k, step) in path.iter().enumerate() {
            let next = match (step, node.get_ref()) {
                (Step::Key(key), DeValue::Table(t)) => t.get(key.as_str()),
                (Step::Index(i), DeValue::Array(a)) => a.get(*i),
                _ => None,
            };
            match next {
                Some(n) => node = n,
                None => {
                    shown.truncate(k);
                    break;
                }
            }
        }
        // A table read through a buffer: find the offending entry among its own.
        if let (DeValue::Table(t), Some(wanted)) = (node.get_ref(), Wanted::from_message(message)) {
            let hits: Vec<_> = t
                .iter()
                .filter(|(key, value)| {
                    let literal = text.get(value.span()).unwrap_or("");
                    wanted.matches(key.get_ref(), literal.trim(), value.get_ref())
                })
                .collect();
            if let [(key, value)] = hits.as_slice() {
                shown.push(Step::Key(key.get_ref().to_string()));
                return if matches!(wanted, Wanted::Key(_)) { key.span() } else { value.span() };
            }
        }
        node.span()
    });
    let field = field_path(&shown);
    let what = if field.is_empty() { message.to_string() } else { format!("field `{field}`: {message}") };
    match span {
        Some(span) => format!("{}{what}\n", snippet(text, span.start)),
        None => what,
    }
}

/// `section.supports[1].kind`
fn field_path(path: &[Step]) -> String {
    let mut s = String::new();
    for step in path {
        match step {
            Step::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// "TOML parse error at line L, column C" and the line with a caret under byte offset `at`.
fn snippet(text: &str, at: usize) -> String {
    let at = at.min(text.len());
    let line_start = text[..at].rfind('\n').map_or(0, |p| p + 1);
    let line_end = text[at..].find('\n').map_or(text.len(), |p| at + p);
    let line_no = text[..line_start].matches('\n').count() + 1;
    let column = text[line_start..at].chars().count() + 1;
    let line = text[line_start..line_end].trim_end_matches('\r');
    let gutter = " ".repeat(line_no.to_string().len());
    format!(
        "TOML parse error at line {line_no}, column {column}\n{gutter} |\n{line_no} | {line}\n{gutter} | {}^\n",
        " ".repeat(column - 1)
    )
}

/// What identifies the offending value, read from the parser's message.
enum Wanted {
    /// a value equal to this literal (`"sideways"`, `1.5`, `true`)
    Literal(String),
    /// an array of this many elements
    Length(usize),
    /// this key
    Key(String),
}

impl Wanted {
    fn from_message(m: &str) -> Option<Wanted> {
        let between = |s: &str, open: char, close: char| -> Option<String> {
            let a = s.find(open)? + open.len_utf8();
            let b = a + s[a..].find(close)?;
            Some(s[a..b].to_string())
        };
        if let Some(rest) = m.strip_prefix("unknown variant ") {
            return Some(Wanted::Literal(format!("\"{}\"", between(rest, '`', '`')?)));
        }
        if let Some(rest) = m.strip_prefix("unknown field ") {
            return Some(Wanted::Key(between(rest, '`', '`')?));
        }
        if let Some(rest) = m.strip_prefix("invalid length ") {
            return rest.split(',').next()?.trim().parse().ok().map(Wanted::Length);
        }
        if let Some(rest) = m.strip_prefix("invalid type: string ") {
            return Some(Wanted::Literal(format!("\"{}\"", between(rest, '"', '"')?)));
        }
        if let Some(rest) = m.strip_prefix("invalid type: ") {
            return Some(Wanted::Literal(between(rest, '`', '`')?));
        }
        if let Some(rest) = m.strip_prefix("invalid value: ") {
            return Some(Wanted::Literal(between(rest, '`', '`')?));
        }
        None
    }

    /// Whether the entry `key = value` of a document without text is the one wanted (the value's
    /// literal as TOML writes it).
    fn matches_value(&self, key: &str, value: &toml::Value) -> bool {
        match self {
            Wanted::Key(k) => key == k,
            Wanted::Literal(l) => {
                let literal = value.to_string();
                !value.is_table() && (literal == *l || parses_equal(&literal, l))
            }
            Wanted::Length(n) => matches!(value, toml::Value::Array(a) if a.len() == *n),
        }
    }

    /// Whether the entry `key = value` (`literal` its text) is the one wanted.
    fn matches(&self, key: &str, literal: &str, value: &DeValue) -> bool {
        match self {
            Wanted::Key(k) => key == k,
            Wanted::Literal(l) => literal == l || literal.replace('\'', "\"") == *l || parses_equal(literal, l),
            Wanted::Length(n) => matches!(value, DeValue::Array(a) if a.len() == *n),
        }
    }
}

/// Two number literals with the same value (`1.50` and `1.5`).
fn parses_equal(a: &str, b: &str) -> bool {
    matches!((a.parse::<f64>(), b.parse::<f64>()), (Ok(x), Ok(y)) if x == y)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> String {
        from_text::<crate::scenario::Scenario>(text, "t.toml").unwrap_err().to_string()
    }

    const BASE: &str = "[conductor]\naxial_stiffness_n = 792000.0\nlinear_density_kg_per_m = 1.0\n\
        [geometry]\nleft_support_m = [0.0, 0.0, 0.0]\nright_support_m = [0.0, 160.0, 0.0]\nsegments = 20\n\
        [duration]\nend_time_s = 0.5\n";

    #[test]
    fn an_error_inside_an_event_points_at_the_value_not_the_table() {
        let t = format!(
            "{BASE}[[events]]\ntime_s = 0.1\naction = \"ice\"\nlinear_density_kg_per_m = 0.5\nrange = [0.1, 0.2, 0.3]\n"
        );
        let m = error(&t);
        assert!(m.contains("line 14, column 9") && m.contains("invalid length 3"), "{m}");
        let t = format!("{BASE}[[events]]\ntime_s = 0.1\naction = \"wind\"\nscale = 1.0\ngate = \"sideways\" # no\n");
        let m = error(&t);
        assert!(m.contains("line 14, column 8") && m.contains("unknown variant `sideways`"), "{m}");
        // A multi-line array, with comments and a trailing comma: the error points at its first line.
        let t = format!(
            "{BASE}[[events]]\ntime_s = 0.1\naction = \"ice\"\nrange = [\n  0.1, # from\n  0.2,\n  0.3,\n]\n\
             linear_density_kg_per_m = 0.5\n"
        );
        let m = error(&t);
        assert!(m.contains("line 13, column 9") && m.contains("invalid length 3"), "{m}");
        let t = format!("{BASE}[[events]]\ntime_s = 0.1\naction = \"break\"\nat_fraction = \"half\"\n");
        let m = error(&t);
        assert!(m.contains("line 13, column 15") && m.contains("invalid type: string"), "{m}");
    }

    #[test]
    fn four_components_where_three_are_meant_are_refused() {
        let t = BASE.replace("left_support_m = [0.0, 0.0, 0.0]", "left_support_m = [0.0, 0.0, 0.0, 5.0]");
        let m = error(&t);
        assert!(m.contains("line 5") && m.contains("invalid length 4, expected exactly 3 components"), "{m}");
    }
}
