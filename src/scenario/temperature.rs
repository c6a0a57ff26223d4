//! Temperatures in kelvin or in degrees Celsius: every temperature field `NAME_k` of a file has a twin
//! `NAME_c` in degrees Celsius, and a file gives at most one of the two (both: an error naming both).
//!
//! One mechanism for every file ([`to_kelvin`]): before the document is read into the schema's types, each
//! `NAME_c` of a temperature field ([`STEMS`]) is replaced by `NAME_k` = `NAME_c` + 273.15
//! ([`ZERO_CELSIUS_K`]: the kelvin and the degree Celsius differ by exactly 273.15, SI Brochure, 9th
//! edition (2019), section 2.3.1; [`kelvin`] rounds the sum to 1e-9 K, so that a value written with up to
//! nine decimals gives the same number as its kelvin value written in decimal: `-100` C is `173.15` K,
//! where the plain sum is 173.14999999999998), in any table or array of tables of the document; a list of numbers
//! (`max_temperature_c = [75.0, 100.0]`) is converted item by item. The model and the validators see
//! kelvin only, so the conversion happens exactly once, here. The document remembers which fields were
//! written in Celsius ([`Celsius`]); the validators' problems about them are then written back in the
//! user's terms ([`Celsius::as_written`]): the field `NAME_c`, the value as written, and the allowed range
//! of [`super::range`] (stated once, in kelvin) shown in degrees Celsius ([`super::range::Range::celsius`]).
//!
//! A required temperature that is missing is reported with both names (``missing field `temperature_k`
//! (or `temperature_c`)``, [`name_twins`]), and so are the lists of accepted fields of an unknown key.

use super::range::TEMPERATURE_RANGES;
use super::validate::{Problem, number};

/// 0 degrees Celsius in kelvin [K], exact by the definition of the degree Celsius (SI Brochure, 9th
/// edition (2019), section 2.3.1: `t / C = T / K - 273.15`).
pub const ZERO_CELSIUS_K: f64 = 273.15;

/// A temperature in degrees Celsius in kelvin: `c + 273.15`, rounded to 1e-9 K ([module doc](self)). The
/// rounding moves the value by at most 5e-10 K, far below any temperature the model resolves.
pub fn kelvin(c: f64) -> f64 {
    ((c + ZERO_CELSIUS_K) * 1e9).round() / 1e9
}

/// The temperature fields of the files, without their unit suffix: `NAME_k` is in kelvin, `NAME_c` in
/// degrees Celsius (`conductor.reference_temperature`, `section.stringing_temperature`, the `temperature`
/// and `hold_temperature` of events, `thermal.initial_temperature`, `temperature_low`/`temperature_high`
/// of a conductor's resistance, `weather.air_temperature`, `max_temperature` of a rating or a thermal
/// case, a transient's `limit`, the `from_temperature`/`to_temperature` of a sag-tension case's range).
pub const STEMS: &[&str] = &[
    "reference_temperature",
    "stringing_temperature",
    "temperature",
    "hold_temperature",
    "initial_temperature",
    "temperature_low",
    "temperature_high",
    "air_temperature",
    "max_temperature",
    "limit",
    "from_temperature",
    "to_temperature",
];

/// The Celsius twin of a kelvin temperature field (`air_temperature_k` -> `air_temperature_c`); `None`
/// for any other name.
pub fn celsius_twin(kelvin: &str) -> Option<String> {
    let stem = kelvin.strip_suffix("_k")?;
    STEMS.contains(&stem).then(|| format!("{stem}_c"))
}

/// The kelvin twin of a Celsius temperature field (`air_temperature_c` -> `air_temperature_k`); `None`
/// for any other name.
pub fn kelvin_twin(celsius: &str) -> Option<String> {
    let stem = celsius.strip_suffix("_c")?;
    STEMS.contains(&stem).then(|| format!("{stem}_k"))
}

/// One field a file gave in degrees Celsius.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    /// its path with the kelvin name, as the validators name it (`conductor.reference_temperature_k`)
    pub kelvin: String,
    /// its path as written (`conductor.reference_temperature_c`)
    pub celsius: String,
    /// the value(s) as written [C] (one, or the items of a list)
    pub values: Vec<f64>,
}

/// The fields of a document that were written in degrees Celsius.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Celsius(pub Vec<Written>);

/// Replace every Celsius temperature field of `doc` by its kelvin twin ([module doc](self)); the fields
/// that were in Celsius, or the problems: both twins given, a value that is not a number.
pub fn to_kelvin(doc: &mut toml::Table) -> Result<Celsius, Vec<Problem>> {
    let mut out = Celsius::default();
    let mut problems = Vec::new();
    walk(doc, "", &mut out, &mut problems);
    if problems.is_empty() { Ok(out) } else { Err(problems) }
}

fn walk(t: &mut toml::Table, at: &str, out: &mut Celsius, problems: &mut Vec<Problem>) {
    let path = |key: &str| if at.is_empty() { key.to_string() } else { format!("{at}.{key}") };
    let keys: Vec<String> = t.keys().cloned().collect();
    for key in keys {
        if let Some(k_key) = kelvin_twin(&key) {
            let value = t.get(&key).expect("listed");
            if t.contains_key(&k_key) {
                problems.push(Problem {
                    field: path(&key),
                    value: value.to_string(),
                    allowed: format!(
                        "`{}` is given too: give the temperature once, in kelvin (`{k_key}`) or in degrees Celsius \
                         (`{key}`)",
                        path(&k_key)
                    ),
                });
                continue;
            }
            let number = |v: &toml::Value| match v {
                toml::Value::Float(x) => Some(*x),
                toml::Value::Integer(i) => Some(*i as f64),
                _ => None,
            };
            let values: Option<Vec<f64>> = match value {
                toml::Value::Array(items) => items.iter().map(number).collect(),
                v => number(v).map(|x| vec![x]),
            };
            let Some(values) = values else {
                let what = if value.is_array() { "a list of numbers" } else { "a number" };
                problems.push(Problem {
                    field: path(&key),
                    value: value.to_string(),
                    allowed: format!("must be {what} (degrees Celsius)"),
                });
                continue;
            };
            let kelvin_value = match value {
                toml::Value::Array(_) => {
                    toml::Value::Array(values.iter().map(|c| toml::Value::Float(kelvin(*c))).collect())
                }
                _ => toml::Value::Float(kelvin(values[0])),
            };
            t.remove(&key);
            t.insert(k_key.clone(), kelvin_value);
            out.0.push(Written { kelvin: path(&k_key), celsius: path(&key), values });
            continue;
        }
        match t.get_mut(&key) {
            Some(toml::Value::Table(inner)) => walk(inner, &path(&key), out, problems),
            Some(toml::Value::Array(items)) => {
                for (k, item) in items.iter_mut().enumerate() {
                    if let toml::Value::Table(inner) = item {
                        walk(inner, &format!("{}[{k}]", path(&key)), out, problems);
                    }
                }
            }
            _ => {}
        }
    }
}

impl Celsius {
    /// The problems written in the user's units: a problem about a field given in Celsius names the field
    /// as written (`NAME_c`, an item `NAME_c[k]`) with the value as written, and a range of
    /// [`TEMPERATURE_RANGES`] is shown in Celsius ([`Range::celsius`]). Other problems are left as they are.
    pub fn as_written(&self, problems: Vec<Problem>) -> Vec<Problem> {
        if self.0.is_empty() {
            return problems;
        }
        problems
            .into_iter()
            .map(|p| {
                let Some((w, item, rest)) = self.0.iter().find_map(|w| {
                    let rest = p.field.strip_prefix(&w.kelvin)?;
                    if rest.is_empty() {
                        return Some((w, 0, String::new()));
                    }
                    let (index, after) = rest.strip_prefix('[')?.split_once(']')?;
                    Some((w, index.parse::<usize>().ok()?, format!("[{index}]{after}")))
                }) else {
                    return p;
                };
                let Some(&value) = w.values.get(item) else { return p };
                let allowed = match TEMPERATURE_RANGES.iter().find(|r| r.to_string() == p.allowed) {
                    Some(r) => r.celsius().to_string(),
                    None => p.allowed,
                };
                Problem { field: format!("{}{rest}", w.celsius), value: number(value), allowed }
            })
            .collect()
    }
}

/// A parser message with the Celsius twin beside each kelvin temperature field it names: a missing
/// field ``missing field `temperature_k` `` becomes ``missing field `temperature_k` (or `temperature_c`)``,
/// and the list of accepted fields of an unknown key gains `temperature_c` after `temperature_k`.
pub fn name_twins(message: &str) -> String {
    let missing = message.starts_with("missing field");
    let listing = message.contains("expected one of") || message.contains("expected `");
    if !missing && !listing {
        return message.to_string();
    }
    let mut m = message.to_string();
    for stem in STEMS {
        let (k, c) = (format!("`{stem}_k`"), format!("`{stem}_c`"));
        if m.contains(&k) && !m.contains(&c) {
            let with = if missing { format!("{k} (or {c})") } else { format!("{k}, {c}") };
            m = m.replace(&k, &with);
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(text: &str) -> toml::Table {
        text.parse().unwrap()
    }

    #[test]
    fn celsius_fields_become_kelvin_once() {
        let mut d = doc("[conductor]\nreference_temperature_c = 15\n[[events]]\ntemperature_c = -5.5\n[[events]]\n\
             temperature_k = 300.0\n[x]\nmax_temperature_c = [75.0, 100]\nother_c = 1.0\n");
        let w = to_kelvin(&mut d).unwrap();
        // T = t + 273.15 (15 C = 288.15 K, -5.5 C = 267.65 K), the numbers of the decimal kelvin values.
        assert_eq!(d["conductor"]["reference_temperature_k"].as_float(), Some(288.15));
        assert!(d["conductor"].get("reference_temperature_c").is_none());
        assert_eq!(d["events"][0]["temperature_k"].as_float(), Some(267.65));
        assert_eq!(d["events"][1]["temperature_k"].as_float(), Some(300.0));
        let list: Vec<f64> =
            d["x"]["max_temperature_k"].as_array().unwrap().iter().map(|v| v.as_float().unwrap()).collect();
        assert_eq!(list, [348.15, 373.15]);
        assert_eq!(d["x"]["other_c"].as_float(), Some(1.0), "not a temperature field: left alone");
        let paths: Vec<&str> = w.0.iter().map(|w| w.celsius.as_str()).collect();
        assert_eq!(paths, ["conductor.reference_temperature_c", "events[0].temperature_c", "x.max_temperature_c"]);
    }

    #[test]
    fn both_twins_or_a_non_number_are_refused_naming_the_fields() {
        let p = to_kelvin(&mut doc("[conductor]\nreference_temperature_c = 15.0\nreference_temperature_k = 288.15\n"))
            .unwrap_err();
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].field, "conductor.reference_temperature_c");
        assert!(p[0].allowed.contains("`conductor.reference_temperature_k` is given too"), "{}", p[0].allowed);
        let p = to_kelvin(&mut doc("[w]\nair_temperature_c = \"warm\"\n")).unwrap_err();
        assert_eq!(p[0].allowed, "must be a number (degrees Celsius)");
    }

    #[test]
    fn problems_are_written_back_in_celsius() {
        let w = Celsius(vec![Written {
            kelvin: "events[0].temperature_k".into(),
            celsius: "events[0].temperature_c".into(),
            values: vec![-300.0],
        }]);
        let k = super::super::range::EVENT_TEMPERATURE_K;
        let p = Problem { field: "events[0].temperature_k".into(), value: "-26.85".into(), allowed: k.to_string() };
        let q = w.as_written(vec![p.clone()]);
        assert_eq!(q[0].field, "events[0].temperature_c");
        assert_eq!(q[0].value, "-300");
        assert_eq!(q[0].allowed, "must be in (-273.15, 4726.85] C");
        // Another field is left as it is.
        let other = Problem { field: "events[1].temperature_k".into(), ..p };
        assert_eq!(w.as_written(vec![other.clone()]), vec![other]);
    }

    #[test]
    fn a_celsius_value_gives_the_kelvin_value_written_in_decimal() {
        // The plain sum misses the decimal kelvin value by an ulp; the rounded one is it, so each range
        // end in Celsius is the range end in kelvin (-100 C the floor 173.15 K of the reference
        // temperature).
        assert_ne!(-100.0 + ZERO_CELSIUS_K, 173.15);
        for (c, k) in
            [(-100.0, 173.15), (-73.15, 200.0), (-50.0, 223.15), (-23.15, 250.0), (15.0, 288.15), (100.0, 373.15)]
        {
            assert_eq!(kelvin(c), k, "{c} C");
        }
        for r in TEMPERATURE_RANGES {
            assert_eq!((kelvin(r.celsius().lo), kelvin(r.celsius().hi)), (r.lo, r.hi), "{r}");
        }
    }

    #[test]
    fn messages_name_both_twins() {
        assert_eq!(
            name_twins("missing fields `time_s`, `temperature_k`"),
            "missing fields `time_s`, `temperature_k` (or `temperature_c`)"
        );
        assert_eq!(
            name_twins("unknown field `zz`, expected one of `limit_k`, `step_s`"),
            "unknown field `zz`, expected one of `limit_k`, `limit_c`, `step_s`"
        );
        assert_eq!(name_twins("invalid type: `temperature_k`"), "invalid type: `temperature_k`");
    }
}
