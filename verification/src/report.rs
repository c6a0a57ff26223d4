//! What a study returns, its tables (written as CSV and as Markdown) and the assembled `REPORT.md`.

use ohl_app::plot::{Chart, render_titled};
use std::fmt::Write as _;
use std::path::Path;

/// How much work a study does: `Full` for `verify`, `Coarse` for the CI test (small grids, short times).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Budget {
    /// small grids and short runs (seconds)
    Coarse,
    /// the full study (minutes for the whole harness)
    Full,
}

/// A table of numbers with a caption.
#[derive(Clone, Debug, Default)]
pub struct Table {
    /// file stem of its CSV (under the output directory)
    pub stem: String,
    /// caption in the report
    pub caption: String,
    /// column headers (with units)
    pub headers: Vec<String>,
    /// rows, already formatted
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with the given CSV stem, caption and headers.
    pub fn new(stem: &str, caption: &str, headers: &[&str]) -> Self {
        Table {
            stem: stem.into(),
            caption: caption.into(),
            headers: headers.iter().map(|h| h.to_string()).collect(),
            rows: vec![],
        }
    }

    /// Append a row.
    pub fn row(&mut self, cells: Vec<String>) {
        debug_assert_eq!(cells.len(), self.headers.len());
        self.rows.push(cells);
    }

    /// Write `dir/stem.csv`.
    pub fn write_csv(&self, dir: &Path) -> Result<(), String> {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let path = dir.join(format!("{}.csv", self.stem));
        let mut w = csv::Writer::from_path(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        w.write_record(&self.headers).map_err(|e| e.to_string())?;
        for r in &self.rows {
            w.write_record(r).map_err(|e| e.to_string())?;
        }
        w.flush().map_err(|e| e.to_string())
    }

    /// The table in Markdown.
    pub fn markdown(&self) -> String {
        let mut s = format!(
            "*{}* (`{}.csv`)\n\n| {} |\n|{}\n",
            self.caption,
            self.stem,
            self.headers.join(" | "),
            "---|".repeat(self.headers.len())
        );
        for r in &self.rows {
            let _ = writeln!(s, "| {} |", r.join(" | "));
        }
        s
    }
}

/// One asserted expectation of a study.
#[derive(Clone, Debug)]
pub struct Check {
    /// what is checked
    pub what: String,
    /// the expectation (with its tolerance)
    pub expected: String,
    /// what was measured
    pub observed: String,
    /// verdict
    pub pass: bool,
}

/// The outcome of a study.
#[derive(Clone, Debug, Default)]
pub struct StudyReport {
    /// command-line name
    pub name: String,
    /// title
    pub title: String,
    /// what the study does and how to read it (Markdown)
    pub summary: String,
    /// its tables
    pub tables: Vec<Table>,
    /// its figures (file names of the PNGs, relative to the output directory)
    pub figures: Vec<String>,
    /// its checks
    pub checks: Vec<Check>,
    /// discussion of the result (Markdown)
    pub discussion: String,
    /// wall time [s]
    pub wall_s: f64,
}

impl StudyReport {
    /// Add a check.
    pub fn check(
        &mut self,
        what: impl Into<String>,
        expected: impl Into<String>,
        observed: impl Into<String>,
        pass: bool,
    ) {
        self.checks.push(Check { what: what.into(), expected: expected.into(), observed: observed.into(), pass });
    }

    /// Every check passed (and there is at least one).
    pub fn passed(&self) -> bool {
        !self.checks.is_empty() && self.checks.iter().all(|c| c.pass)
    }

    /// One line per check: `  [pass] what: expected ...; observed ...`.
    pub fn check_lines(&self) -> String {
        self.checks
            .iter()
            .map(|c| {
                format!(
                    "  [{}] {}: expected {}; observed {}\n",
                    if c.pass { "pass" } else { "FAIL" },
                    c.what,
                    c.expected,
                    c.observed
                )
            })
            .collect()
    }

    /// Draw `panels` (`cols` to a row, each `panel_size` pixels, under the heading `title`) into
    /// `dir/stem.png` and `dir/stem.svg`, and list the PNG among the study's figures.
    pub fn figure(
        &mut self,
        panels: &[Chart],
        cols: usize,
        panel_size: (u32, u32),
        title: &str,
        dir: &Path,
        stem: &str,
    ) -> Result<(), String> {
        render_titled(panels, cols, panel_size, title, &dir.join(stem)).map_err(|e| e.to_string())?;
        self.figures.push(format!("{stem}.png"));
        Ok(())
    }

    /// Write the tables' CSVs.
    pub fn write_tables(&self, dir: &Path) -> Result<(), String> {
        self.tables.iter().try_for_each(|t| t.write_csv(dir))
    }

    /// The study's section of `REPORT.md`.
    pub fn markdown(&self) -> String {
        let verdict = if self.passed() { "PASS" } else { "FAIL" };
        let mut s = format!("## {} — `{}` — **{verdict}**\n\n{}\n\n", self.title, self.name, self.summary.trim());
        s.push_str("| check | expected | observed | verdict |\n|---|---|---|---|\n");
        for c in &self.checks {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} |",
                c.what,
                c.expected,
                c.observed,
                if c.pass { "pass" } else { "FAIL" }
            );
        }
        s.push('\n');
        for t in &self.tables {
            s.push_str(&t.markdown());
            s.push('\n');
        }
        for f in &self.figures {
            let _ = writeln!(s, "![{f}]({f})\n");
        }
        if !self.discussion.trim().is_empty() {
            s.push_str(self.discussion.trim());
            s.push_str("\n\n");
        }
        let _ = writeln!(s, "_wall time {:.1} s_\n", self.wall_s);
        s
    }
}

/// The whole `REPORT.md`: a summary table of verdicts, then one section per study.
/// `stamp` is [`stamp`] taken before the studies ran (they rewrite files of the tree, which would read as
/// changes).
pub fn full_report(reports: &[StudyReport], budget: Budget, wall_s: f64, stamp: &str) -> String {
    let mut s = String::from("# Verification report of the `ohl` wire solver\n\n");
    let _ = writeln!(
        s,
        "Generated by `cargo run --release --bin verify -- all` (budget {budget:?}, wall time {wall_s:.0} s). \
         Every number below is recomputed by that command; the CSV and PNG/SVG files sit beside this file.\n"
    );
    let _ = writeln!(s, "{stamp}\n");
    s.push_str("| study | verdict | checks passed | key results |\n|---|---|---|---|\n");
    for r in reports {
        let passed = r.checks.iter().filter(|c| c.pass).count();
        let key: Vec<String> = r.checks.iter().map(|c| format!("{}: {}", c.what, c.observed)).collect();
        let _ = writeln!(
            s,
            "| `{}` | {} | {passed}/{} | {} |",
            r.name,
            if r.passed() { "PASS" } else { "FAIL" },
            r.checks.len(),
            key.join("; ")
        );
    }
    s.push('\n');
    for r in reports {
        s.push_str(&r.markdown());
    }
    s
}

/// The provenance line of a report: see [`ohl_app::stamp::stamp`].
pub use ohl_app::stamp::stamp;

/// Format a number in scientific notation with 3 significant digits.
pub fn sci(v: f64) -> String {
    format!("{v:.3e}")
}

/// Format a number with 3 decimals.
pub fn f3(v: f64) -> String {
    format!("{v:.3}")
}
