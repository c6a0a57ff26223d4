//! Where in the text a TOML error lies. serde reads an internally tagged enum (an `[[events]]` table,
//! tagged by `action`) through a buffer of the whole table, so an error in one of its values (an unknown
//! gate, a range of three numbers, a string for a number) comes back pointing at the table header. The
//! message names the value (or its length), so the value's own line is found again in the table's text.

/// The parser's message re-pointed at the offending value's line, or `None` where the error already
/// points at a value (or the value cannot be found unambiguously).
pub(crate) fn relocate(text: &str, e: &toml::de::Error) -> Option<String> {
    let span = e.span()?;
    let header_start = text[..span.start].rfind('\n').map_or(0, |p| p + 1);
    if !text.get(header_start..)?.trim_start().starts_with('[') || !text.get(span.clone())?.starts_with('[') {
        return None;
    }
    let header_line = text[..header_start].matches('\n').count() + 1;
    let message = e.message();
    let wanted = Wanted::from_message(message)?;
    // The table's own lines: after the header, up to the next header.
    let mut found = None;
    let lines: Vec<&str> = text[header_start..].lines().collect();
    let mut k = 1;
    while k < lines.len() {
        let line = lines[k];
        let trimmed = line.trim_start();
        if trimmed.starts_with('[') {
            break;
        }
        let at = k;
        k += 1;
        let Some((key, first, column)) = key_value(line) else { continue };
        // A multi-line array: its value runs to the line where the brackets balance.
        let mut value = first.to_string();
        while value.starts_with('[') && depth(&value) > 0 && k < lines.len() {
            value.push(' ');
            value.push_str(strip_comment(lines[k]).trim());
            k += 1;
        }
        if wanted.matches(key, &value) {
            if found.is_some() {
                return None;
            }
            found = Some((header_line + at, column, line));
        }
    }
    let (line_no, column, line) = found?;
    let gutter = " ".repeat(line_no.to_string().len());
    Some(format!(
        "TOML parse error at line {line_no}, column {column}\n{gutter} |\n{line_no} | {line}\n{gutter} | {}^\n\
         {message} (in the table that starts at line {header_line})\n",
        " ".repeat(column - 1)
    ))
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

    fn matches(&self, key: &str, value: &str) -> bool {
        match self {
            Wanted::Key(k) => key == k,
            Wanted::Literal(l) => value == l || value.replace('\'', "\"") == *l || parses_equal(value, l),
            Wanted::Length(n) => array_len(value) == Some(*n),
        }
    }
}

/// Two number literals with the same value (`1.50` and `1.5`).
fn parses_equal(a: &str, b: &str) -> bool {
    matches!((a.parse::<f64>(), b.parse::<f64>()), (Ok(x), Ok(y)) if x == y)
}

/// A line without its comment (a `#` outside a string).
fn strip_comment(line: &str) -> &str {
    let mut in_string = false;
    for (i, ch) in line.char_indices() {
        match ch {
            '"' | '\'' => in_string = !in_string,
            '#' if !in_string => return &line[..i],
            _ => {}
        }
    }
    line
}

/// Open brackets minus closed ones, outside strings.
fn depth(value: &str) -> i64 {
    let (mut d, mut in_string) = (0i64, false);
    for ch in value.chars() {
        match ch {
            '"' | '\'' => in_string = !in_string,
            '[' | '{' if !in_string => d += 1,
            ']' | '}' if !in_string => d -= 1,
            _ => {}
        }
    }
    d
}

/// `key = value` of one line (the comment removed), with the value's 1-based column.
fn key_value(line: &str) -> Option<(&str, &str, usize)> {
    let eq = line.find('=')?;
    let key = line[..eq].trim().trim_matches('"');
    let end = eq + 1 + strip_comment(&line[eq + 1..]).len();
    let raw = &line[eq + 1..end];
    let value = raw.trim();
    let column = line[..eq + 1 + (raw.len() - raw.trim_start().len())].chars().count() + 1;
    Some((key, value, column))
}

/// The number of elements of a one-line array literal `[a, b, c]`.
fn array_len(value: &str) -> Option<usize> {
    let inner = value.strip_prefix('[')?.strip_suffix(']')?.trim();
    if inner.is_empty() {
        return Some(0);
    }
    let (mut depth, mut commas, mut in_string) = (0usize, 0usize, false);
    for ch in inner.chars() {
        match ch {
            '"' | '\'' => in_string = !in_string,
            '[' | '{' if !in_string => depth += 1,
            ']' | '}' if !in_string => depth = depth.saturating_sub(1),
            ',' if !in_string && depth == 0 => commas += 1,
            _ => {}
        }
    }
    Some(if inner.ends_with(',') { commas } else { commas + 1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> String {
        let e = toml::from_str::<crate::scenario::Scenario>(text).unwrap_err();
        relocate(text, &e).unwrap_or_else(|| e.to_string())
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

    #[test]
    fn array_lengths_and_values() {
        assert_eq!(array_len("[1, [2, 3], \"a,b\"]"), Some(3));
        assert_eq!(array_len("[1, 2,]"), Some(2));
        assert_eq!(array_len("[]"), Some(0));
        assert_eq!(array_len("[ 0.1, 0.2, 0.3, ]"), Some(3));
        assert_eq!(key_value("  gate = 'x' # c"), Some(("gate", "'x'", 10)));
    }
}
