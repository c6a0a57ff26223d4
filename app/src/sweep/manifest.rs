//! `sweep.json` (or `sweep.K-of-N.json`): what a table belongs to, so that `ohl sweep merge` joins only
//! the shards of one sweep.
//!
//! The identity of a sweep is the base file's bytes, the varied fields with every value of every axis
//! (not where they came from: the same cases file given by another path is the same sweep), whether
//! `--allow-large` was given (it changes which cases run), the number of cases and the `ohl` version. The
//! two fingerprints are 64-bit FNV-1a hashes: they tell sweeps apart, they are no protection against a
//! file crafted to collide.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::shard::Shard;
use super::spec::Spec;

/// The format tag of a manifest.
pub const FORMAT: &str = "ohl-sweep 1";

/// A 64-bit FNV-1a hash, as 16 hexadecimal digits.
pub fn fnv1a64(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// The fingerprint of what a sweep varies: fields and values of every axis, and `allow_large`.
pub fn spec_fingerprint(spec: &Spec, allow_large: bool) -> String {
    let axes: Vec<serde_json::Value> = (spec.axes.iter())
        .map(|a| serde_json::json!([a.fields.iter().map(|f| f.to_string()).collect::<Vec<_>>(), a.rows]))
        .collect();
    let canonical = serde_json::to_string(&(axes, allow_large)).unwrap_or_default();
    fnv1a64(canonical.as_bytes())
}

/// The contents of `sweep.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// [`FORMAT`]
    pub format: String,
    /// the version of `ohl` that ran the cases
    pub ohl_version: String,
    /// the base scenario, as given on the command line (for the reader; not part of the identity)
    pub base: String,
    /// FNV-1a of the base file's bytes
    pub base_fnv1a64: String,
    /// FNV-1a of the fields and values ([`spec_fingerprint`])
    pub spec_fnv1a64: String,
    /// whether cases above the work budget ran
    pub allow_large: bool,
    /// the varied fields, in column order
    pub fields: Vec<String>,
    /// number of cases of the whole sweep
    pub cases: usize,
    /// the shard this table holds (none: the whole sweep)
    pub shard: Option<Shard>,
    /// the table's file name
    pub table: String,
    /// rows in the table
    pub rows: usize,
    /// rows per status
    pub statuses: BTreeMap<String, usize>,
    /// worker threads (none for a merged table)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub threads: Option<usize>,
    /// wall-clock time of running the cases [s] (none for a merged table)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wall_time_s: Option<f64>,
    /// cases per second of wall-clock time (none for a merged table)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cases_per_second: Option<f64>,
    /// the shard tables a merged table was made from
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub merged_from: Vec<String>,
    /// the axes as given (sources, fields, values), for the record
    pub axes: serde_json::Value,
}

impl Manifest {
    /// Whether `self` and `other` describe tables of the same sweep; else what differs, in words.
    pub fn differences(&self, other: &Manifest) -> Vec<String> {
        let mut d = Vec::new();
        if self.format != other.format {
            d.push(format!("format {:?} and {:?}", self.format, other.format));
        }
        if self.ohl_version != other.ohl_version {
            d.push(format!("ohl version {} and {}", self.ohl_version, other.ohl_version));
        }
        if self.base_fnv1a64 != other.base_fnv1a64 {
            d.push(format!(
                "base file {} ({}) and {} ({}): the base scenarios differ",
                self.base, self.base_fnv1a64, other.base, other.base_fnv1a64
            ));
        }
        if self.spec_fnv1a64 != other.spec_fnv1a64 || self.fields != other.fields {
            d.push(format!(
                "varied fields and values ({}: {}; {}: {})",
                self.spec_fnv1a64,
                self.fields.join(", "),
                other.spec_fnv1a64,
                other.fields.join(", ")
            ));
        }
        if self.cases != other.cases {
            d.push(format!("{} and {} cases", self.cases, other.cases));
        }
        let count = |m: &Manifest| m.shard.map_or(1, |s| s.count);
        if count(self) != count(other) {
            d.push(format!("split into {} and {} shards", count(self), count(other)));
        }
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_matches_the_reference_values() {
        assert_eq!(fnv1a64(b""), "cbf29ce484222325");
        assert_eq!(fnv1a64(b"a"), "af63dc4c8601ec8c");
        assert_eq!(fnv1a64(b"foobar"), "85944171f73967e8");
    }

    #[test]
    fn the_fingerprint_follows_the_values_not_their_source() {
        let a = Spec::new(None, &["x=1,2".into()]).unwrap();
        let b = Spec::new(None, &["x = 1, 2".into()]).unwrap();
        let c = Spec::new(None, &["x=1,3".into()]).unwrap();
        assert_eq!(spec_fingerprint(&a, false), spec_fingerprint(&b, false));
        assert_ne!(spec_fingerprint(&a, false), spec_fingerprint(&c, false));
        assert_ne!(spec_fingerprint(&a, false), spec_fingerprint(&a, true));
    }
}
