//! Field paths: where a value of the scenario document is, written as in the validator's messages.
//!
//! A path is keys separated by dots, each key optionally followed by 0-based indices in brackets:
//! `loads.wind.speed_m_per_s`, `events[2].time_s` (the third `[[events]]` table),
//! `geometry.right_support_m[1]` (the second component of an array), `section.supports[1].pivot_m[2]`.
//! Inline tables are tables (`duration.until_settled.max_time_s`). Keys are bare TOML keys (letters,
//! digits, `_` and `-`).
//!
//! In an array of tables that have a `name` (a line's `line.conductors` and `line.towers`, the probes of
//! `output.probes`), `[name=NAME]` selects the table with that name instead of an index:
//! `line.conductors[name=A].section.tension_fraction_of_rts` is `line.conductors[0]...` when the first
//! conductor is `A`. NAME is the text as written in the file, without quotes (spaces and dots included); it
//! cannot contain `]` (such a table is selected by its index).

use std::fmt;

/// One step of a path: a key of a table or a 0-based index into an array.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Step {
    /// a key of a table
    Key(String),
    /// a 0-based index into an array (of values or of tables)
    Index(usize),
    /// the table of an array of tables whose `name` is this text (`[name=A]`)
    Name(String),
}

/// A path into the scenario document ([module docs](self)).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FieldPath {
    /// the steps from the top of the document; the first is a key
    pub steps: Vec<Step>,
}

/// Why a path is not well formed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("field path {text:?}: {reason}")]
pub struct PathSyntaxError {
    /// the path as written
    pub text: String,
    /// what is wrong, and what a path looks like
    pub reason: String,
}

const FORM: &str = "a path is keys separated by dots, each optionally followed by 0-based indices or a name in \
                    brackets, e.g. `loads.wind.speed_m_per_s`, `events[2].time_s`, `geometry.right_support_m[1]`, \
                    `line.conductors[name=A].section.tension_fraction_of_rts`";

impl FieldPath {
    /// Parse a path ([module docs](self)).
    pub fn parse(text: &str) -> Result<FieldPath, PathSyntaxError> {
        let fail = |reason: String| PathSyntaxError { text: text.to_string(), reason: format!("{reason}; {FORM}") };
        if text.trim().is_empty() {
            return Err(fail("empty".into()));
        }
        let mut steps = Vec::new();
        let mut rest = text;
        loop {
            // A key, up to the next dot or bracket.
            let end = rest.find(['.', '[']).unwrap_or(rest.len());
            let key = &rest[..end];
            let part = &rest[..rest[end..].find('.').map_or(rest.len(), |d| end + d)];
            if key.is_empty() {
                return Err(fail(format!("missing key in {part:?}")));
            }
            if let Some(c) = key.chars().find(|c| !(c.is_ascii_alphanumeric() || *c == '_' || *c == '-')) {
                return Err(fail(format!("{c:?} cannot be part of a key")));
            }
            steps.push(Step::Key(key.to_string()));
            rest = &rest[end..];
            // Its indices or names, each in brackets.
            while rest.starts_with('[') {
                let Some(close) = rest.find(']') else {
                    return Err(fail(format!("{rest:?} is not an index in brackets")));
                };
                steps.push(selector(&rest[1..close]).map_err(fail)?);
                rest = &rest[close + 1..];
            }
            match rest.strip_prefix('.') {
                Some(next) => rest = next,
                None if rest.is_empty() => break,
                None => return Err(fail(format!("{rest:?} is not an index in brackets"))),
            }
        }
        Ok(FieldPath { steps })
    }

    /// Whether `self` is `other` or leads into it (`geometry.right_support_m` and
    /// `geometry.right_support_m[1]`): two such fields cannot both be varied.
    pub fn overlaps(&self, other: &FieldPath) -> bool {
        let n = self.steps.len().min(other.steps.len());
        self.steps[..n] == other.steps[..n]
    }

    /// The path of the first `n` steps, as written.
    pub fn prefix(&self, n: usize) -> String {
        FieldPath { steps: self.steps[..n].to_vec() }.to_string()
    }
}

/// What is between brackets: a 0-based index, or `name=NAME`.
fn selector(inside: &str) -> Result<Step, String> {
    if let Some(name) = inside.strip_prefix("name=") {
        return if name.is_empty() { Err("[name=] names nothing".into()) } else { Ok(Step::Name(name.to_string())) };
    }
    inside
        .parse::<usize>()
        .ok()
        .filter(|_| inside.bytes().all(|b| b.is_ascii_digit()))
        .map(Step::Index)
        .ok_or_else(|| format!("index [{inside}] is not a whole number >= 0 (nor a name, [name=NAME])"))
}

impl fmt::Display for FieldPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, s) in self.steps.iter().enumerate() {
            match s {
                Step::Key(key) if k == 0 => write!(f, "{key}")?,
                Step::Key(key) => write!(f, ".{key}")?,
                Step::Index(i) => write!(f, "[{i}]")?,
                Step::Name(name) => write!(f, "[name={name}]")?,
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_parse_and_print_back() {
        for text in [
            "loads.wind.speed_m_per_s",
            "events[2].time_s",
            "geometry.right_support_m[1]",
            "a[0][3].b-c",
            "line.conductors[name=earth wire.2].section.supports[1].pivot_m[2]",
        ] {
            assert_eq!(FieldPath::parse(text).unwrap().to_string(), text);
        }
        let p = FieldPath::parse("events[2].time_s").unwrap();
        assert_eq!(p.steps, vec![Step::Key("events".into()), Step::Index(2), Step::Key("time_s".into())]);
        let p = FieldPath::parse("line.conductors[name=A.b c].name").unwrap();
        let key = |k: &str| Step::Key(k.into());
        assert_eq!(p.steps, vec![key("line"), key("conductors"), Step::Name("A.b c".into()), key("name")]);
    }

    #[test]
    fn malformed_paths_are_refused_with_the_reason() {
        for (text, reason) in [
            ("", "empty"),
            ("loads..wind", "missing key"),
            ("[1].time_s", "missing key"),
            ("events[x].time_s", "index [x]"),
            ("events[-1]", "index [-1]"),
            ("events[1", "not an index"),
            ("events[1]x", "not an index"),
            ("loads wind", "' ' cannot be part of a key"),
            ("line.conductors[name=].x", "[name=] names nothing"),
            ("line.conductors[nom=A].x", "index [nom=A]"),
            ("line.conductors[name=A", "not an index"),
            ("line.conductors[name=A]x", "not an index"),
            ("a.", "missing key"),
        ] {
            let e = FieldPath::parse(text).unwrap_err();
            assert!(e.to_string().contains(reason), "{text:?}: {e}");
        }
    }

    #[test]
    fn overlap_is_a_shared_prefix() {
        let p = |t| FieldPath::parse(t).unwrap();
        assert!(p("geometry.right_support_m").overlaps(&p("geometry.right_support_m[1]")));
        assert!(p("a.b").overlaps(&p("a.b")));
        assert!(!p("a.b").overlaps(&p("a.c")));
        assert!(!p("events[0].time_s").overlaps(&p("events[1].time_s")));
    }
}
