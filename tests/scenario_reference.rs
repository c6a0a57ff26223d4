//! `docs/scenario.md` is the complete reference of the scenario file and of the thermal case file. This
//! test keeps it equal to what the parser accepts, in both directions, so that it cannot drift.
//!
//! How it works:
//!
//! 1. **The page.** Each reference table of the page follows a hidden marker `<!-- schema: PATH -->`, and
//!    the first column of each row is a field name in backticks. `PATH` names a TOML table: `scenario`
//!    (the top level of a scenario) or `thermal_case` (of a file for `ohl thermal`), then keys separated by
//!    dots; an array of tables is `key[]`, and an array of tables told apart by a tag field is
//!    `key[tag=value]` (`scenario.events[action=gust]`, `scenario.section.supports[kind=suspension]`).
//!    The documented tag values are those of the paths.
//! 2. **The examples.** Every ```` ```toml ```` block of the page is a complete file: a thermal case file
//!    if its first line is `# ohl thermal case file`, else a scenario. Each must parse and validate
//!    (`ohl::scenario::parse`, `ohl::scenario::thermal::parse_case`), and a scenario must also build into
//!    a plan (`ohl::scenario::plan`). Every documented table must occur in some example, every table in
//!    the examples must be documented, and every documented field must be used by some example (so the
//!    examples together are a maximal file that the parser accepts), except the fields of `NOT_IN_EXAMPLES`.
//! 3. **The accepted fields come from the parser itself.** Every struct of the schema is read by serde with
//!    `deny_unknown_fields`, whose error for an unknown key lists every field that struct accepts
//!    (``unknown field `x`, expected one of `a`, `b`, ...``). For each documented table the test takes an
//!    instance of it from the examples, adds the key `zz_probe` (which no table has), deserializes the
//!    document into the schema's type and reads that list: it must equal the documented fields. For a
//!    tagged array it sets the tag to `zz_probe` and reads the accepted tag values from the "unknown
//!    variant" error the same way: they must equal the documented ones.
//! 4. **Words.** Every documented field is also set to the word `"zz_probe"`: where the field is a choice of
//!    words (`law`, `shape`, `gate`, `standard`, ...) the "unknown variant" error lists the words accepted,
//!    and they must be exactly the quoted words (`` `"word"` ``) in the field's row.
//! 5. **Ranges** (`every_documented_range_is_the_validators`): a value outside the *Allowed* interval of each
//!    numeric field must be refused with a message that names the field and states the same interval
//!    and unit (the rule is in that test's doc).
//!
//! So a field added to a struct without a row fails (3), a row naming a field the parser does not know
//! fails (3), a new table or event kind fails (3, through its parent's field list or the tag values), a
//! renamed choice fails (4), an example that stops parsing or validating fails (2), and a range that the
//! page and the validator state differently fails (5).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use ohl::scenario::Scenario;

use crate::common::doc_ranges::{leading_interval, message_interval};
use ohl::scenario::thermal::ThermalCase;

/// The key and the word no table or choice has.
const PROBE: &str = "zz_probe";

/// The first line of a thermal case file among the page's examples.
const THERMAL_CASE_MARK: &str = "# ohl thermal case file";

/// Documented fields that no example uses, with the reason.
const NOT_IN_EXAMPLES: &[(&str, &str)] =
    &[("scenario.paper", "the checks of a paper case belong to `ohl paper`; the library ignores the table")];

/// One reference table of the page: its path and, per row, the field name and the row's text.
struct DocTable {
    path: String,
    rows: Vec<(String, String)>,
}

/// Which file a path or an example belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Scenario,
    ThermalCase,
}

impl Kind {
    fn root(self) -> &'static str {
        match self {
            Kind::Scenario => "scenario",
            Kind::ThermalCase => "thermal_case",
        }
    }

    /// Deserialize a document into the schema's type; the error message if it does not deserialize.
    /// The temperatures in degrees Celsius are read as the library reads them
    /// (`ohl::scenario::temperature::to_kelvin`), and a message lists each `NAME_c` twin beside its `NAME_k`
    /// as the library's messages do (`name_twins`).
    fn deserialize(self, mut doc: toml::Table) -> Result<(), String> {
        use ohl::scenario::temperature::{name_twins, to_kelvin};
        to_kelvin(&mut doc).map_err(|p| format!("{p:?}"))?;
        let v = toml::Value::Table(doc);
        match self {
            Kind::Scenario => v.try_into::<Scenario>().map(|_| ()),
            Kind::ThermalCase => v.try_into::<ThermalCase>().map(|_| ()),
        }
        .map_err(|e| name_twins(&e.to_string()))
    }
}

/// Where a table lies in a document: the keys from the top, each with an index into an array of tables.
type Location = Vec<(String, Option<usize>)>;

/// One table of an example: its documentation path and where it is.
struct Instance {
    path: String,
    example: usize,
    at: Location,
}

fn page() -> String {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/scenario.md");
    std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()))
}

/// The cells of a Markdown table row (an escaped `\|` is part of a cell).
fn cells(row: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut chars = row.trim().trim_start_matches('|').chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                out.last_mut().unwrap().push('|');
                chars.next();
            }
            '|' => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out.iter().map(|c| c.trim().to_string()).filter(|c| !c.is_empty()).collect()
}

/// The reference tables of the page, in order.
fn doc_tables(md: &str) -> Vec<DocTable> {
    let lines: Vec<&str> = md.lines().collect();
    let mut tables = Vec::new();
    let mut k = 0;
    while k < lines.len() {
        let line = lines[k].trim();
        k += 1;
        let Some(path) = line.strip_prefix("<!-- schema:").and_then(|l| l.strip_suffix("-->")) else { continue };
        let path = path.trim().to_string();
        while k < lines.len() && lines[k].trim().is_empty() {
            k += 1;
        }
        let mut rows = Vec::new();
        let mut n = 0;
        while k < lines.len() && lines[k].trim_start().starts_with('|') {
            n += 1;
            let row = lines[k];
            k += 1;
            if n <= 2 {
                continue; // the header and the separator
            }
            let first = cells(row).into_iter().next().unwrap_or_default();
            let name = first
                .strip_prefix('`')
                .and_then(|f| f.strip_suffix('`'))
                .filter(|f| !f.is_empty() && f.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or_else(|| panic!("docs/scenario.md, table {path}: the first cell {first:?} is not a `field`"));
            rows.push((name.to_string(), row.to_string()));
        }
        assert!(!rows.is_empty(), "docs/scenario.md: the marker of {path} is not followed by a table with rows");
        tables.push(DocTable { path, rows });
    }
    tables
}

/// The ```` ```toml ```` blocks of the page.
fn toml_blocks(md: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in md.lines() {
        match (&mut current, line.trim_start()) {
            (None, l) if l.starts_with("```toml") => current = Some(String::new()),
            (Some(_), l) if l.starts_with("```") => blocks.push(current.take().unwrap_or_default()),
            (Some(b), _) => {
                b.push_str(line);
                b.push('\n');
            }
            (None, _) => {}
        }
    }
    assert!(current.is_none(), "docs/scenario.md: a toml block is not closed");
    blocks
}

/// The tag key of each tagged array, from the documented paths: `scenario.events` -> `action`.
fn tag_keys(tables: &[DocTable]) -> BTreeMap<String, String> {
    let mut tags = BTreeMap::new();
    for t in tables {
        let mut prefix = String::new();
        for seg in t.path.split('.') {
            let name = seg.split('[').next().unwrap_or(seg);
            let at = if prefix.is_empty() { name.to_string() } else { format!("{prefix}.{name}") };
            if let Some(tag) =
                seg.split_once('[').and_then(|(_, r)| r.strip_suffix(']')).and_then(|r| r.split_once('='))
            {
                tags.insert(at.clone(), tag.0.to_string());
            }
            prefix = if prefix.is_empty() { seg.to_string() } else { format!("{prefix}.{seg}") };
        }
    }
    tags
}

/// Every table of an example (the top level included), with its documentation path.
fn walk(
    table: &toml::Table,
    path: &str,
    at: &Location,
    example: usize,
    tags: &BTreeMap<String, String>,
) -> Vec<Instance> {
    let mut out = vec![Instance { path: path.to_string(), example, at: at.clone() }];
    for (key, value) in table {
        let here = format!("{path}.{key}");
        match value {
            toml::Value::Table(t) => {
                let mut loc = at.clone();
                loc.push((key.clone(), None));
                out.extend(walk(t, &here, &loc, example, tags));
            }
            toml::Value::Array(items) if !items.is_empty() && items.iter().all(|i| i.is_table()) => {
                for (i, item) in items.iter().enumerate() {
                    let t = item.as_table().unwrap();
                    let child = match tags.get(&here) {
                        Some(tag) => {
                            let v = t.get(tag).and_then(|v| v.as_str()).unwrap_or_else(|| {
                                panic!("example {example}: an element of {here} has no text field `{tag}`")
                            });
                            format!("{here}[{tag}={v}]")
                        }
                        None => format!("{here}[]"),
                    };
                    let mut loc = at.clone();
                    loc.push((key.clone(), Some(i)));
                    out.extend(walk(t, &child, &loc, example, tags));
                }
            }
            _ => {}
        }
    }
    out
}

/// The table at `at` in `doc`.
fn table_at<'a>(doc: &'a mut toml::Table, at: &Location) -> &'a mut toml::Table {
    let mut t = doc;
    for (key, index) in at {
        let v = t.get_mut(key).unwrap();
        let v = match index {
            Some(i) => &mut v.as_array_mut().unwrap()[*i],
            None => v,
        };
        t = v.as_table_mut().unwrap();
    }
    t
}

/// The names in backticks after `what` in a serde message (``unknown field `zz_probe`, expected one of
/// `a`, `b` ``): the names accepted. `None` if the message is not that error.
fn expected_after(message: &str, what: &str) -> Option<BTreeSet<String>> {
    let start = message.find(&format!("{what} `{PROBE}`"))?;
    let rest = &message[start..];
    let rest = rest.lines().next().unwrap_or(rest);
    let rest = rest.split_once("expected").map_or("", |(_, r)| r);
    Some(rest.split('`').skip(1).step_by(2).map(str::to_string).collect())
}

/// The quoted words of a row (`` `"word"` ``), outside its first cell.
fn quoted_words(row: &str) -> BTreeSet<String> {
    let after_first = cells(row).into_iter().skip(1).collect::<Vec<_>>().join(" | ");
    after_first
        .split('`')
        .skip(1)
        .step_by(2)
        .filter_map(|s| s.strip_prefix('"').and_then(|s| s.strip_suffix('"')))
        .map(str::to_string)
        .collect()
}

fn kind_of(path: &str) -> Kind {
    match path.split('.').next().unwrap_or("") {
        "scenario" => Kind::Scenario,
        "thermal_case" => Kind::ThermalCase,
        other => panic!("docs/scenario.md: a schema path must start with scenario or thermal_case, not {other:?}"),
    }
}

#[test]
fn the_scenario_reference_is_the_schema() {
    let md = page();
    let tables = doc_tables(&md);
    assert!(tables.len() >= 30, "docs/scenario.md has only {} reference tables", tables.len());
    let mut seen = BTreeSet::new();
    for t in &tables {
        assert!(seen.insert(t.path.clone()), "docs/scenario.md documents {} twice", t.path);
        kind_of(&t.path);
        let mut names = BTreeSet::new();
        for (name, _) in &t.rows {
            assert!(names.insert(name.clone()), "docs/scenario.md, table {}: `{name}` appears twice", t.path);
        }
    }
    let tags = tag_keys(&tables);

    // 2. The examples parse, validate and build; their tables are documented.
    let blocks = toml_blocks(&md);
    assert!(blocks.len() >= 2, "docs/scenario.md has no examples");
    let mut examples: Vec<(Kind, toml::Table)> = Vec::new();
    for (k, text) in blocks.iter().enumerate() {
        let file = format!("docs/scenario.md, toml block {}", k + 1);
        let kind = if text.lines().next() == Some(THERMAL_CASE_MARK) { Kind::ThermalCase } else { Kind::Scenario };
        match kind {
            Kind::Scenario => {
                let s = ohl::scenario::parse(text, &file).unwrap_or_else(|e| panic!("{e}"));
                ohl::scenario::plan(&s, &file).unwrap_or_else(|e| panic!("{e}"));
            }
            Kind::ThermalCase => {
                ohl::scenario::thermal::parse_case(text, &file).unwrap_or_else(|e| panic!("{e}"));
            }
        }
        let doc: toml::Table = text.parse().unwrap_or_else(|e| panic!("{file}: {e}"));
        examples.push((kind, doc));
    }
    let mut instances: Vec<Instance> = Vec::new();
    for (k, (kind, doc)) in examples.iter().enumerate() {
        instances.extend(walk(doc, kind.root(), &Vec::new(), k, &tags));
    }
    for i in &instances {
        assert!(
            seen.contains(&i.path),
            "docs/scenario.md, toml block {}: its table {} has no reference table (<!-- schema: {} -->)",
            i.example + 1,
            i.path,
            i.path
        );
    }

    let mut failures = Vec::new();
    for t in &tables {
        let kind = kind_of(&t.path);
        let here: Vec<&Instance> = instances.iter().filter(|i| i.path == t.path).collect();
        let Some(first) = here.first() else {
            failures.push(format!("{}: no example of the page contains this table; add one", t.path));
            continue;
        };
        let documented: BTreeSet<String> = t.rows.iter().map(|(n, _)| n.clone()).collect();

        // Every documented field is used by some example.
        for name in &documented {
            let full = format!("{}.{name}", t.path);
            let used = here.iter().any(|i| {
                let mut doc = examples[i.example].1.clone();
                table_at(&mut doc, &i.at).contains_key(name)
            });
            if !used && !NOT_IN_EXAMPLES.iter().any(|(f, _)| *f == full) {
                failures.push(format!("{full}: documented, but no example of the page uses it"));
            }
        }

        // 3. The fields the parser accepts in this table.
        let mut doc = examples[first.example].1.clone();
        table_at(&mut doc, &first.at).insert(PROBE.into(), toml::Value::Integer(0));
        let message = kind.deserialize(doc).expect_err("a table that accepts an unknown key");
        let accepted = match expected_after(&message, "unknown field") {
            Some(a) => a,
            None if message.contains(&format!("unknown field `{PROBE}`, there are no fields")) => BTreeSet::new(),
            None => panic!("{}: the probe gave an unexpected error: {message}", t.path),
        };
        // A tagged table's tag is read by the enum, not by the variant's fields.
        let tag = t
            .path
            .strip_suffix(']')
            .and_then(|p| p.rsplit_once('['))
            .and_then(|(_, r)| r.split_once('='))
            .map(|(k, _)| k.to_string());
        let documented_fields: BTreeSet<String> =
            documented.iter().filter(|n| Some(*n) != tag.as_ref()).cloned().collect();
        let undocumented: Vec<_> = accepted.difference(&documented_fields).collect();
        let unknown: Vec<_> = documented_fields.difference(&accepted).collect();
        if !undocumented.is_empty() {
            failures.push(format!("{}: the parser accepts {undocumented:?}, which the page does not document", t.path));
        }
        if !unknown.is_empty() {
            failures.push(format!("{}: the page documents {unknown:?}, which the parser does not accept", t.path));
        }

        // 4. Choices of words: exactly the quoted words of the row.
        for (name, row) in &t.rows {
            if Some(name) == tag.as_ref() || !accepted.contains(name) {
                continue;
            }
            let mut doc = examples[first.example].1.clone();
            table_at(&mut doc, &first.at).insert(name.clone(), toml::Value::String(PROBE.into()));
            let Err(message) = kind.deserialize(doc) else { continue };
            if let Some(words) = expected_after(&message, "unknown variant") {
                let quoted = quoted_words(row);
                if words != quoted {
                    failures.push(format!(
                        "{}.{name}: the parser accepts the words {words:?}, the row quotes {quoted:?}",
                        t.path
                    ));
                }
            }
        }
    }

    // 3. Tag values: for each tagged array, the documented values against the accepted ones.
    for (array, tag) in &tags {
        let documented: BTreeSet<String> = tables
            .iter()
            .filter_map(|t| t.path.strip_prefix(&format!("{array}[{tag}=")))
            .map(|r| r.split(']').next().unwrap_or(r).to_string())
            .collect();
        let Some(i) = instances.iter().find(|i| i.path.starts_with(&format!("{array}["))) else {
            failures.push(format!("{array}: no example of the page contains it"));
            continue;
        };
        let mut doc = examples[i.example].1.clone();
        table_at(&mut doc, &i.at).insert(tag.clone(), toml::Value::String(PROBE.into()));
        let message = kind_of(array).deserialize(doc).expect_err("an unknown tag value");
        let accepted = expected_after(&message, "unknown variant")
            .unwrap_or_else(|| panic!("{array}: the probe of `{tag}` gave an unexpected error: {message}"));
        if accepted != documented {
            failures.push(format!(
                "{array}: `{tag}` accepts {accepted:?}, the page documents {documented:?} (one reference table each)"
            ));
        }
    }

    assert!(failures.is_empty(), "docs/scenario.md does not match the schema:\n  {}", failures.join("\n  "));
}

/// Documented numeric fields whose *Allowed* cell is not a plain interval of numbers, with the reason
/// (their checks depend on other fields, or on more than one number).
const RICHER: &[(&str, &str)] = &[
    ("scenario.numerics.mass_damping_per_s", "`>= 0 with zeta dt < 1`: the bound is the time step"),
    ("scenario.output.snapshot_times_s", "each in [0, end time]: the end is another field"),
    ("scenario.output.peaks_from_s", "[0, end time]: the end is another field"),
    ("scenario.geometry.unstretched_length_m", "[chord / 2, 100 chord]: the chord is the supports'"),
    ("scenario.geometry.left_support_m", "a vector: each component within 1e5"),
    ("scenario.geometry.right_support_m", "a vector, and the chord's length"),
    ("scenario.initial.sag_m", "(0, chord]: the chord is the supports'"),
    ("scenario.loads.uniform_load_n_per_m", "a vector: each component within 1e4"),
    ("scenario.loads.wind.direction", "a vector, not zero"),
    ("scenario.ground.height_m", "below every support and the initial shape"),
    ("scenario.ground.profile_m", "points with increasing x2 and bounded slopes"),
    ("scenario.section.supports[kind=dead_end].point_m", "a vector: each component within 1e5"),
    ("scenario.section.supports[kind=suspension].pivot_m", "a vector: each component within 1e5"),
    ("scenario.section.spans[].unstretched_length_m", "[chord / 2, 2 chord]: the chord is the supports'"),
    ("scenario.section.spans[].sag_m", "(0, chord / 2]: the chord is the supports'"),
    ("scenario.thermal.current_a", "points [t, I], each end its own range, times not decreasing"),
    ("thermal_case.transient.current_a", "points [t, I] as thermal.current_a"),
    ("scenario.thermal.inclination_deg", "[0, 80] or [0, 60] by the conductor's surface and the standard"),
    ("thermal_case.inclination_deg", "[0, 80] or [0, 60] by the conductor's surface and the standard"),
    ("scenario.thermal.deicing.spans", "span indices of the section"),
    ("scenario.rating.span", "a span index of the line, checked by `ohl rating`"),
];

/// Fields of the `scenario.events[...]` tables: `time_s` is in [0, end time] (the end is another field);
/// `span` and `support` are indices; `range` and `hold_range` are `[a, b]` with `0 <= a < b <= 1`.
const RICHER_EVENT_FIELDS: &[&str] = &["time_s", "span", "support", "range", "hold_range"];

/// Fields of `scenario.thermal.conductor` and `thermal_case.conductor` whose range ends are other fields.
const RICHER_CONDUCTOR_FIELDS: &[&str] = &[
    "core_diameter_m",
    "outer_strand_diameter_m",
    "resistance_high_ohm_per_m",
    "temperature_high_k",
    "temperature_high_c",
    "core_specific_heat_j_per_kg_k",
];

/// The field as a message names it: the keys from the top of the file, with array indices
/// (`section.supports[1].insulator_length_m`, `events[3].scale`).
fn message_field(at: &Location, name: &str) -> String {
    let mut out = String::new();
    for (key, index) in at {
        out.push_str(key);
        if let Some(i) = index {
            out.push_str(&format!("[{i}]"));
        }
        out.push('.');
    }
    out + name
}

/// Every documented field whose *Allowed* cell starts with an interval of numbers (after `integer in ` or,
/// for an array of numbers, `each in `) is set, in an example of the page that uses it, to a value outside
/// it: `nan` for a float, one below the lower end (else one above the upper end) for an integer, `nan` as
/// the first element of an array. The file is then parsed and validated (`ohl::scenario::parse`,
/// `ohl::scenario::thermal::parse_case`), and one of the problems reported must name the field as the
/// file writes it, with the same interval (ends compared as numbers, so `1e3` is `1000`; which ends are
/// open) followed by the cell's unit (the *Unit* column; none for `-`). The validators' own texts come
/// from `ohl::scenario::range::Range`, so the page and the messages state each range the same way.
///
/// Numeric fields whose cell is not such an interval are listed in `RICHER`, `RICHER_EVENT_FIELDS` and
/// `RICHER_CONDUCTOR_FIELDS` with the reason; a listed field whose cell became a plain interval fails
/// (the list must not go stale).
#[test]
fn every_documented_range_is_the_validators() {
    let md = page();
    let tables = doc_tables(&md);
    let tags = tag_keys(&tables);
    let examples: Vec<(Kind, toml::Table)> = toml_blocks(&md)
        .iter()
        .map(|text| {
            let kind = if text.lines().next() == Some(THERMAL_CASE_MARK) { Kind::ThermalCase } else { Kind::Scenario };
            (kind, text.parse().unwrap())
        })
        .collect();
    let mut instances: Vec<Instance> = Vec::new();
    for (k, (kind, doc)) in examples.iter().enumerate() {
        instances.extend(walk(doc, kind.root(), &Vec::new(), k, &tags));
    }

    let mut failures = Vec::new();
    let mut tested = 0;
    for t in &tables {
        let kind = kind_of(&t.path);
        for (name, row) in &t.rows {
            let full = format!("{}.{name}", t.path);
            let row_cells = cells(row);
            let (unit, allowed) = (row_cells[1].as_str(), row_cells[3].as_str());
            // The example that uses the field, and its value there.
            let Some((i, value)) = instances.iter().filter(|i| i.path == t.path).find_map(|i| {
                let mut doc = examples[i.example].1.clone();
                table_at(&mut doc, &i.at).get(name).cloned().map(|v| (i, v))
            }) else {
                continue; // NOT_IN_EXAMPLES, checked by the_scenario_reference_is_the_schema
            };
            let numeric = |v: &toml::Value| v.is_float() || v.is_integer();
            let array = value.as_array().is_some_and(|a| !a.is_empty() && a.iter().all(numeric));
            if !numeric(&value) && !array {
                continue;
            }
            let richer = RICHER.iter().any(|(f, _)| *f == full)
                || (t.path.starts_with("scenario.events[") && RICHER_EVENT_FIELDS.contains(&name.as_str()))
                || (t.path.ends_with(".conductor") && RICHER_CONDUCTOR_FIELDS.contains(&name.as_str()));
            let cell =
                allowed.strip_prefix("integer in ").or_else(|| allowed.strip_prefix("each in ")).unwrap_or(allowed);
            let interval = leading_interval(cell);
            let expected = match (interval, richer) {
                (Some((_, "")), true) => {
                    failures.push(format!("{full}: listed as richer, but its cell {allowed:?} is an interval"));
                    continue;
                }
                (_, true) => continue,
                (None, false) => {
                    failures
                        .push(format!("{full}: a numeric field whose cell {allowed:?} is not an interval; list it"));
                    continue;
                }
                (Some((iv, _)), false) => iv,
            };
            // The value outside the range.
            let (bad, field) = if array {
                let mut items = value.as_array().unwrap().clone();
                items[0] = toml::Value::Float(f64::NAN);
                (toml::Value::Array(items), message_field(&i.at, &format!("{name}[0]")))
            } else if value.is_integer() {
                let (_, lo, hi, _) = expected;
                let v = if lo >= 1.0 { lo as i64 - 1 } else { hi as i64 + 1 };
                (toml::Value::Integer(v), message_field(&i.at, name))
            } else {
                (toml::Value::Float(f64::NAN), message_field(&i.at, name))
            };
            let mut doc = examples[i.example].1.clone();
            table_at(&mut doc, &i.at).insert(name.clone(), bad.clone());
            let text = toml::to_string(&doc).unwrap();
            let label = format!("docs/scenario.md, toml block {} with {field} = {bad}", i.example + 1);
            let result = match kind {
                Kind::Scenario => ohl::scenario::parse(&text, &label).map(|_| ()),
                Kind::ThermalCase => ohl::scenario::thermal::parse_case(&text, &label).map(|_| ()),
            };
            let problems = match result {
                Err(ohl::scenario::InputError::Invalid { problems, .. }) => problems,
                Err(e) => {
                    failures.push(format!("{full}: {field} = {bad} is not a validation error: {e}"));
                    continue;
                }
                Ok(()) => {
                    failures.push(format!("{full}: {field} = {bad} is accepted"));
                    continue;
                }
            };
            let Some(p) = problems.iter().find(|p| p.field == field) else {
                let named: Vec<&str> = problems.iter().map(|p| p.field.as_str()).collect();
                failures.push(format!("{full}: {field} = {bad} is refused, but the problems name {named:?}"));
                continue;
            };
            tested += 1;
            let Some((stated, after)) = message_interval(&p.allowed) else {
                failures.push(format!("{full}: the message states no interval: {:?}", p.allowed));
                continue;
            };
            if stated != expected {
                failures.push(format!("{full}: the page allows {allowed:?}, the validator says {:?}", p.allowed));
            }
            if unit != "-" && !after.starts_with(&format!(" {unit}")) {
                failures.push(format!("{full}: the page's unit is {unit:?}, the validator says {:?}", p.allowed));
            }
        }
    }
    assert!(tested >= 100, "only {tested} ranges were checked");
    assert!(failures.is_empty(), "docs/scenario.md's ranges differ from the validators':\n  {}", failures.join("\n  "));
}
