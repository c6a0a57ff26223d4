//! `ohl sweep merge`: the tables of a sweep's shards joined into one `sweep.csv`, sorted by case id.
//!
//! Inputs are directories (every `sweep.K-of-N.csv` in them) or table files; each table's manifest is the
//! file of the same name ending `.json`. The merge refuses, naming the files and what differs, tables of
//! different sweeps (base file, varied fields or values, `--allow-large`, number of cases or of shards,
//! `ohl` version) or with different headers; and it refuses an incomplete or overlapping set, listing the
//! missing and the duplicated case ids. Rows are copied as text, so the merged table's values are bitwise
//! the shards'.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::manifest::Manifest;
use super::shard::Shard;
use super::table;

/// Why shard tables cannot be merged (exit code 2), or the merged files cannot be written (exit code 1).
#[derive(Debug, thiserror::Error)]
pub enum MergeError {
    /// Nothing to merge.
    #[error("{0}: no shard tables (sweep.K-of-N.csv) found")]
    NoTables(String),
    /// A table or manifest cannot be read or is malformed.
    #[error("{}: {message}", path.display())]
    Read {
        /// the file
        path: PathBuf,
        /// what is wrong
        message: String,
    },
    /// Tables of different sweeps.
    #[error("{} and {} are not tables of the same sweep; they differ in: {}", a.display(), b.display(), differences.join("; "))]
    Mixed {
        /// the first table
        a: PathBuf,
        /// a table that differs from it
        b: PathBuf,
        /// what differs
        differences: Vec<String>,
    },
    /// Cases missing or present twice.
    #[error("{}", cases_message(*.cases, .missing, .duplicated))]
    Cases {
        /// cases of the sweep
        cases: usize,
        /// case ids in no table
        missing: Vec<usize>,
        /// case ids in more than one row, with the tables holding them
        duplicated: Vec<(usize, Vec<String>)>,
    },
    /// The merged table or manifest cannot be written.
    #[error("{}: {source}", path.display())]
    Write {
        /// the file
        path: PathBuf,
        /// the error
        source: std::io::Error,
    },
}

impl MergeError {
    /// The exit code: 1 for a file that could not be written, 2 for inputs that cannot be merged.
    pub fn exit_code(&self) -> u8 {
        if matches!(self, MergeError::Write { .. }) { 1 } else { 2 }
    }
}

fn cases_message(cases: usize, missing: &[usize], duplicated: &[(usize, Vec<String>)]) -> String {
    let mut parts = Vec::new();
    if !missing.is_empty() {
        parts.push(format!(
            "{} of the sweep's {cases} cases are in no table (run their shards, then merge again): {}",
            missing.len(),
            ranges(missing)
        ));
    }
    if !duplicated.is_empty() {
        let listed: Vec<String> =
            duplicated.iter().take(10).map(|(id, files)| format!("case {id} in {}", files.join(" and "))).collect();
        let more = if duplicated.len() > 10 { format!("; and {} more", duplicated.len() - 10) } else { String::new() };
        parts.push(format!("{} cases are in more than one row: {}{more}", duplicated.len(), listed.join("; ")));
    }
    parts.join("; ")
}

/// Sorted ids as ranges, `0-3, 7, 9-12`, the first 20 ranges.
pub fn ranges(ids: &[usize]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut k = 0;
    while k < ids.len() {
        let mut j = k;
        while j + 1 < ids.len() && ids[j + 1] == ids[j] + 1 {
            j += 1;
        }
        out.push(if j == k { ids[k].to_string() } else { format!("{}-{}", ids[k], ids[j]) });
        k = j + 1;
    }
    let n = out.len();
    if n > 20 {
        out.truncate(20);
        out.push(format!("... ({n} ranges in all)"));
    }
    out.join(", ")
}

/// What a merge wrote.
#[derive(Clone, Debug)]
pub struct Merged {
    /// the merged table
    pub table: PathBuf,
    /// its manifest
    pub manifest: PathBuf,
    /// cases (rows)
    pub cases: usize,
    /// tables merged
    pub tables: usize,
    /// rows per status
    pub statuses: BTreeMap<String, usize>,
}

/// The tables among `inputs`: every `sweep.K-of-N.csv` of a directory, and the files as given.
fn tables(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, MergeError> {
    let mut all = Vec::new();
    for input in inputs {
        if !input.exists() {
            return Err(MergeError::Read { path: input.clone(), message: "no such file or directory".into() });
        }
        if !input.is_dir() {
            all.push(input.clone());
            continue;
        }
        let read = |e: std::io::Error| MergeError::Read { path: input.clone(), message: e.to_string() };
        let mut found: Vec<(Shard, PathBuf)> = Vec::new();
        for entry in std::fs::read_dir(input).map_err(read)? {
            let entry = entry.map_err(read)?;
            if let Some(s) = entry.file_name().to_str().and_then(Shard::of_file_name) {
                found.push((s, entry.path()));
            }
        }
        if found.is_empty() {
            return Err(MergeError::NoTables(input.display().to_string()));
        }
        found.sort_by_key(|(s, _)| (s.count, s.index));
        all.extend(found.into_iter().map(|(_, p)| p));
    }
    if all.is_empty() {
        return Err(MergeError::NoTables("(no input)".into()));
    }
    Ok(all)
}

fn read_manifest(table: &Path) -> Result<Manifest, MergeError> {
    let path = table.with_extension("json");
    let fail = |message: String| MergeError::Read { path: path.clone(), message };
    let text = std::fs::read_to_string(&path)
        .map_err(|e| fail(format!("cannot read the manifest of {}: {e}", table.display())))?;
    serde_json::from_str(&text).map_err(|e| fail(format!("not a sweep manifest: {e}")))
}

/// Merge the shard tables of `inputs` ([module docs](self)) into `out/sweep.csv` and `out/sweep.json`;
/// `out` defaults to the first input if it is a directory, else the directory of the first input.
pub fn merge(inputs: &[PathBuf], out: Option<&Path>) -> Result<Merged, MergeError> {
    let files = tables(inputs)?;
    let manifests = files.iter().map(|f| read_manifest(f)).collect::<Result<Vec<_>, _>>()?;
    let first = &manifests[0];
    for (f, m) in files.iter().zip(&manifests).skip(1) {
        let differences = first.differences(m);
        if !differences.is_empty() {
            return Err(MergeError::Mixed { a: files[0].clone(), b: f.clone(), differences });
        }
    }
    let mut header: Option<(PathBuf, Vec<String>)> = None;
    let mut rows: BTreeMap<usize, Vec<String>> = BTreeMap::new();
    let mut seen: BTreeMap<usize, Vec<String>> = BTreeMap::new();
    for f in &files {
        let t = table::read(f).map_err(|e| MergeError::Read { path: f.clone(), message: e.to_string() })?;
        match &header {
            None => header = Some((f.clone(), t.header.clone())),
            Some((g, h)) if *h != t.header => {
                return Err(MergeError::Mixed {
                    a: g.clone(),
                    b: f.clone(),
                    differences: vec![format!("table columns ({} and {})", h.join(","), t.header.join(","))],
                });
            }
            Some(_) => {}
        }
        for (k, record) in t.records.into_iter().enumerate() {
            let bad = |why: String| MergeError::Read { path: f.clone(), message: format!("row {}: {why}", k + 1) };
            let cell = record.first().cloned().unwrap_or_default();
            let id: usize = cell.parse().map_err(|_| bad(format!("case id {cell:?} is not a whole number")))?;
            if id >= first.cases {
                return Err(bad(format!(
                    "case {id} is beyond the sweep's {} cases (0 to {})",
                    first.cases,
                    first.cases - 1
                )));
            }
            seen.entry(id).or_default().push(f.display().to_string());
            rows.insert(id, record);
        }
    }
    let missing: Vec<usize> = (0..first.cases).filter(|id| !seen.contains_key(id)).collect();
    let duplicated: Vec<(usize, Vec<String>)> = seen.into_iter().filter(|(_, v)| v.len() > 1).collect();
    if !missing.is_empty() || !duplicated.is_empty() {
        return Err(MergeError::Cases { cases: first.cases, missing, duplicated });
    }
    let (_, header) = header.unwrap_or_default();
    let status_column = header.iter().position(|h| h == "status");
    let mut statuses = BTreeMap::new();
    for r in rows.values() {
        let s = status_column.and_then(|c| r.get(c)).cloned().unwrap_or_default();
        *statuses.entry(s).or_insert(0) += 1;
    }
    let out = match out {
        Some(o) => o.to_path_buf(),
        None if inputs[0].is_dir() => inputs[0].clone(),
        None => files[0].parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf),
    };
    let write_err = |path: &Path| {
        let path = path.to_path_buf();
        move |source| MergeError::Write { path, source }
    };
    std::fs::create_dir_all(&out).map_err(write_err(&out))?;
    let table_path = out.join("sweep.csv");
    let cases = rows.len();
    table::write(&table_path, &header, rows.into_values()).map_err(write_err(&table_path))?;
    let manifest = Manifest {
        shard: None,
        table: "sweep.csv".into(),
        rows: cases,
        statuses: statuses.clone(),
        threads: None,
        wall_time_s: None,
        cases_per_second: None,
        merged_from: files.iter().map(|f| f.display().to_string()).collect(),
        ..first.clone()
    };
    let manifest_path = out.join("sweep.json");
    super::execute::write_manifest(&manifest_path, &manifest).map_err(|e| match e {
        super::SweepError::Write { path, source } => MergeError::Write { path, source },
        other => MergeError::Write { path: manifest_path.clone(), source: std::io::Error::other(other.to_string()) },
    })?;
    Ok(Merged { table: table_path, manifest: manifest_path, cases, tables: files.len(), statuses })
}

#[cfg(test)]
mod tests {
    use super::ranges;

    #[test]
    fn ids_are_listed_as_ranges() {
        assert_eq!(ranges(&[0, 1, 2, 3, 7, 9, 10, 11, 12]), "0-3, 7, 9-12");
        assert_eq!(ranges(&[5]), "5");
        let many: Vec<usize> = (0..100).map(|k| 2 * k).collect();
        assert!(ranges(&many).ends_with("... (100 ranges in all)"));
    }
}
