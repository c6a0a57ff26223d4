//! `docs/line.md`'s table of the `[line]` scenario fields is the schema: for every table of a line
//! scenario that the page documents (`line`, `line.towers[]`, `line.towers[].elastic`,
//! `line.conductors[]`, `line.conductors[].tension_strings[]`, `line.conductors[].bundle`,
//! `line.conductors[].bundle.spacers[]`, `line.conductors[].dropper`, `initial`, and the top level), the fields the page lists are exactly those the parser accepts. The accepted fields
//! come from the parser itself: a probe key added to the table makes serde (`deny_unknown_fields`) list
//! every field it accepts. Fields of the single-conductor tables (`conductor`, `section`, `events`, and
//! the top-level `loads`, `numerics`, `duration`, `output`, `ground`, `name`, `description`) are
//! referenced in `docs/scenario.md` and checked there.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use crate::common::doc_ranges::{leading_interval, message_interval};

/// A line scenario with every table of the page present (the probe goes into each in turn).
const FULL: &str = r#"
[line]
string_damping_n_s = 0.0
towers = [{ name = "T", position_m = [0.0, 400.0, 30.0], elastic = { along_n_per_m = 1e5, across_n_per_m = 1e5, mass_kg = 500.0 } }]
[[line.conductors]]
name = "A"
conductor = { axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628, diameter_m = 0.0281 }
section = { horizontal_tension_n = 28000.0, segments_per_span = 8, supports = [
  { kind = "dead_end", point_m = [0.0, 0.0, 26.5] },
  { kind = "suspension", pivot_m = [0.0, 400.0, 30.0], insulator_length_m = 3.5, insulator_mass_kg = 100.0, insulator_stiffness_n = 5.0e7 },
  { kind = "dead_end", point_m = [0.0, 800.0, 26.5] } ] }
towers = ["", "T", ""]
tension_strings = [{ support = 2, length_m = 3.0, mass_kg = 60.0, stiffness_n = 2.0e7, damping_n_s = 0.0 }]
[line.conductors.bundle]
sub_conductors = 2
diameter_m = 0.4
spacers = [{ span = 0, at_fraction = 0.5 }]
[[line.conductors]]
name = "B"
conductor = { axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628 }
section = { horizontal_tension_n = 28000.0, segments_per_span = 8, supports = [
  { kind = "dead_end", point_m = [10.0, 0.0, 26.5] },
  { kind = "dead_end", point_m = [10.0, 400.0, 26.5] } ] }
[[line.conductors]]
name = "D"
conductor = { axial_stiffness_n = 2.9e7, linear_density_kg_per_m = 1.628 }
dropper = { from = "B", span = 0, at_fraction = 0.5, length_m = 12.0, segments = 4, to_m = [13.0, 200.0, 5.0] }
[initial]
shape = "strung"
[duration]
end_time_s = 1.0
"#;

/// The table rows of the page's scenario section (lines starting with ``| ` ``): what [`documented`]
/// and [`documented_rows`] read their columns from.
fn table_rows() -> Vec<String> {
    let page = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/line.md")).unwrap();
    let start = page.find("## Scenario format").expect("the page has its scenario section");
    let end = page[start..].find("\n## ").map_or(page.len(), |e| start + e);
    page[start..end].lines().filter(|l| l.starts_with("| `")).map(String::from).collect()
}

/// The documented field paths: the first column of the page's table (backticked), e.g.
/// `line.conductors[].bundle.diameter_m`.
fn documented() -> BTreeSet<String> {
    table_rows().iter().filter_map(|l| l.split('`').nth(1).map(String::from)).collect()
}

/// The rows of the page's table: (field path, the *unit, range* cell).
fn documented_rows() -> Vec<(String, String)> {
    table_rows()
        .iter()
        .filter_map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            Some((cells.get(1)?.trim_matches('`').to_string(), cells.get(2)?.to_string()))
        })
        .collect()
}

/// Split a field path into (its table, the field): `a.b[].c` -> (`a.b[]`, `c`); a path that names an
/// array of tables (`line.towers`) is a field of its parent.
fn split(path: &str) -> (String, String) {
    match path.rsplit_once('.') {
        Some((table, field)) => (table.to_string(), field.trim_end_matches("[]").to_string()),
        None => (String::new(), path.trim_end_matches("[]").to_string()),
    }
}

/// The table at `path` (`line.conductors[].bundle`) of the document, and its path as the file writes it
/// (`line.conductors[0].bundle`): of each array, the first element that has the path's next key (the
/// first element if none has, or the path ends there).
fn table_at<'a>(doc: &'a mut toml::Table, path: &str) -> (&'a mut toml::Table, String) {
    let keys: Vec<&str> = path.split('.').filter(|k| !k.is_empty()).map(|k| k.trim_end_matches("[]")).collect();
    let mut t = doc;
    let mut written = Vec::new();
    for (i, name) in keys.iter().enumerate() {
        let v = t.get_mut(*name).unwrap_or_else(|| panic!("no {name} in the full example"));
        t = match v {
            toml::Value::Table(x) => {
                written.push(name.to_string());
                x
            }
            toml::Value::Array(a) => {
                let next = keys.get(i + 1);
                let k = next
                    .and_then(|n| a.iter().position(|e| e.as_table().is_some_and(|x| x.contains_key(*n))))
                    .unwrap_or(0);
                written.push(format!("{name}[{k}]"));
                match &mut a[k] {
                    toml::Value::Table(x) => x,
                    other => panic!("{name}: {other:?}"),
                }
            }
            other => panic!("{name}: {other:?}"),
        };
    }
    (t, written.join("."))
}

/// The fields serde accepts at `path`: the list in its error for an unknown key.
fn accepted(path: &str) -> BTreeSet<String> {
    let mut doc: toml::Table = FULL.parse().unwrap();
    table_at(&mut doc, path).0.insert("zz_probe".into(), toml::Value::Integer(1));
    let text = toml::to_string(&doc).unwrap();
    let err = match ohl::scenario::line::parse(&text, "probe") {
        Err(e) => e.to_string(),
        Ok(_) => panic!("{path}: the probe key was accepted"),
    };
    let list =
        err.split("expected one of").nth(1).or_else(|| err.split("expected").nth(1)).unwrap_or_else(|| panic!("{err}"));
    list.split('`').skip(1).step_by(2).map(String::from).collect()
}

#[test]
fn the_line_reference_is_the_schema() {
    // The full example is a valid line scenario.
    let sc = ohl::scenario::line::parse(FULL, "full").unwrap();
    ohl::scenario::line::plan(&sc, "full").unwrap_or_else(|e| panic!("{e}"));
    let mut tables: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for path in documented() {
        // The field, and each table on its way as a field of its parent (`line.towers[].elastic.mass_kg`
        // documents `line`, `line.towers` and `line.towers[].elastic` too).
        let mut p = path.as_str();
        loop {
            let (table, field) = split(p);
            tables.entry(table.clone()).or_default().insert(field);
            if table.is_empty() {
                break;
            }
            p = path.get(..table.len()).unwrap_or("");
        }
    }
    // The top level: the page documents `line`, `initial` and `events`; the rest is scenario.md's.
    let top = tables.entry(String::new()).or_default();
    for f in ["name", "description", "loads", "numerics", "duration", "output", "ground"] {
        top.insert(f.into());
    }
    for t in [
        "line",
        "line.towers[]",
        "line.towers[].elastic",
        "line.conductors[]",
        "line.conductors[].tension_strings[]",
        "line.conductors[].bundle",
        "line.conductors[].dropper",
        "initial",
    ] {
        assert!(tables.contains_key(t), "docs/line.md documents no field of {t}");
    }
    for (table, fields) in &tables {
        // `line.conductors[].bundle.spacers` entries are `{ span, at_fraction }`, described in their row.
        let got = accepted(table);
        assert_eq!(&got, fields, "docs/line.md, table {table:?}: documented (right) vs accepted (left)");
    }
}

/// Every documented field of a `[line]` whose *unit, range* cell holds an interval of numbers (`N/m, [1e2,
/// 1e10]`: the unit, then the interval; `[2, 8]`: no unit) is set in the full example to a value outside
/// it (`nan`; for an integer, one below the lower end), the first element of each array on the way. The
/// line scenario is parsed and validated (`ohl::scenario::line::parse` and `plan`, which checks the line's
/// own tables), and a problem must name the field
/// as the file writes it (`line.towers[0].elastic.mass_kg`) with the same interval (ends compared as
/// numbers, open ends alike) followed by the cell's unit.
#[test]
fn every_documented_line_range_is_the_validators() {
    let mut failures = Vec::new();
    let mut tested = 0;
    for (path, cell) in documented_rows() {
        let (unit, rest) = match cell.split_once(", ") {
            Some((u, r)) if !cell.starts_with(['[', '(']) => (u, r),
            _ => ("", cell.as_str()),
        };
        let Some((expected, _)) = leading_interval(rest) else { continue };
        let (table, name) = split(&path);
        let mut doc: toml::Table = FULL.parse().unwrap();
        let (t, written) = table_at(&mut doc, &table);
        let bad = match t.get(&name) {
            Some(toml::Value::Integer(_)) => toml::Value::Integer(expected.1 as i64 - 1),
            _ => toml::Value::Float(f64::NAN),
        };
        t.insert(name.clone(), bad.clone());
        let field = if written.is_empty() { name.clone() } else { format!("{written}.{name}") };
        let text = toml::to_string(&doc).unwrap();
        // The line's own tables are validated by `plan`.
        let planned = ohl::scenario::line::parse(&text, "full").and_then(|sc| ohl::scenario::line::plan(&sc, "full"));
        let problems = match planned {
            Err(ohl::scenario::InputError::Invalid { problems, .. }) => problems,
            Err(e) => {
                failures.push(format!("{field} = {bad}: not a validation error: {e}"));
                continue;
            }
            Ok(_) => {
                failures.push(format!("{field} = {bad} is accepted"));
                continue;
            }
        };
        let Some(p) = problems.iter().find(|p| p.field == field) else {
            let named: Vec<&str> = problems.iter().map(|p| p.field.as_str()).collect();
            failures.push(format!("{field} = {bad} is refused, but the problems name {named:?}"));
            continue;
        };
        tested += 1;
        match message_interval(&p.allowed) {
            Some((stated, after)) => {
                if stated != expected {
                    failures.push(format!("{field}: the page allows {cell:?}, the validator says {:?}", p.allowed));
                }
                if !unit.is_empty() && !after.starts_with(&format!(" {unit}")) {
                    failures.push(format!("{field}: the page's unit is {unit:?}, the validator says {:?}", p.allowed));
                }
            }
            None => failures.push(format!("{field}: the message states no interval: {:?}", p.allowed)),
        }
    }
    assert!(failures.is_empty(), "docs/line.md's ranges differ from the validators':\n  {}", failures.join("\n  "));
    assert!(tested >= 12, "only {tested} ranges were checked");
}
