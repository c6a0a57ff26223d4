//! The comparison table: one row per checked value, `quantity | unit | paper | exact | computed |
//! computed vs paper | computed vs exact | verdict`, with the explanations as numbered notes.
//!
//! Verdicts: a `match` check is "ok" when `|computed - paper| <= tolerance |paper|` and "NOT
//! REPRODUCED" otherwise; a `report` check (a transient, which depends on damping the paper does not
//! give) is "ok" or "differs (transient)". The relative differences are signed, `(computed - paper) /
//! |paper|`.

use std::fmt::Write;

use crate::paper::spec::{CheckSpec, CompareSpec, UnitSpec};

/// One row of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// case name
    pub case: String,
    /// what it is
    pub quantity: String,
    /// unit of the three values
    pub unit: UnitSpec,
    /// the paper's value, if it prints one
    pub paper: Option<f64>,
    /// the independent reference, if any
    pub exact: Option<f64>,
    /// the computed value (NaN if it could not be extracted)
    pub computed: f64,
    /// relative tolerance against the paper [-]
    pub tolerance: f64,
    /// verdict rule
    pub compare: CompareSpec,
    /// where in the paper
    pub source: String,
    /// why it differs, when known
    pub explanation: Option<String>,
}

impl Row {
    /// The row of the check `ch` of `case` with the computed value and the reference, both already in the
    /// check's unit.
    pub fn from_check<X, R>(case: &str, ch: &CheckSpec<X, R>, computed: f64, exact: Option<f64>) -> Row {
        Row {
            case: case.to_string(),
            quantity: ch.quantity.clone(),
            unit: ch.unit,
            paper: ch.paper,
            exact,
            computed,
            tolerance: ch.tolerance,
            compare: ch.compare,
            source: ch.source.clone(),
            explanation: ch.explanation.clone(),
        }
    }
    /// `(computed - paper) / |paper|`.
    pub fn relative_to_paper(&self) -> Option<f64> {
        self.paper.map(|p| (self.computed - p) / p.abs())
    }
    /// `(computed - exact) / |exact|`.
    pub fn relative_to_exact(&self) -> Option<f64> {
        self.exact.map(|e| (self.computed - e) / e.abs())
    }
    /// Within the tolerance of the paper's value (of the reference's where the paper prints none;
    /// true when there is neither).
    pub fn within_tolerance(&self) -> bool {
        match self.relative_to_paper().or_else(|| self.relative_to_exact()) {
            Some(d) => d.abs() <= self.tolerance,
            None => true,
        }
    }
    /// The verdict text.
    pub fn verdict(&self) -> &'static str {
        if self.paper.is_none() && self.exact.is_none() {
            return "reported (no paper value)";
        }
        match (self.compare, self.within_tolerance()) {
            (_, true) if self.paper.is_none() => "ok (vs exact; no paper value)",
            (_, true) => "ok",
            (CompareSpec::Match, false) => "NOT REPRODUCED",
            (CompareSpec::Report, false) => "differs (transient)",
        }
    }
}

fn num(v: f64) -> String {
    if !v.is_finite() {
        return "n/a".into();
    }
    let a = v.abs();
    if a != 0.0 && !(1e-2..1e5).contains(&a) { format!("{v:.4e}") } else { format!("{v:.5}") }
}

/// A relative difference in percent: two decimals, or two significant digits below 0.01 %.
fn pct(v: Option<f64>) -> String {
    match v {
        Some(x) if x.is_finite() => {
            let p = 100.0 * x;
            if p != 0.0 && p.abs() < 0.01 { format!("{p:+.1e} %") } else { format!("{p:+.2} %") }
        }
        _ => "-".into(),
    }
}

/// A tolerance in percent: one decimal, or two significant digits below 0.1 %.
fn tol(t: f64) -> String {
    let p = 100.0 * t;
    if p < 0.1 { format!("{p:.1e} %") } else { format!("{p:.1} %") }
}

/// The table as Markdown text, with the explanations of the rows that differ as numbered notes.
pub fn format(rows: &[Row]) -> String {
    let mut out = String::new();
    let mut notes: Vec<String> = Vec::new();
    out.push_str("| case | quantity | unit | paper | exact | computed | vs paper | vs exact | tol. | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|\n");
    for r in rows {
        let mut verdict = r.verdict().to_string();
        if let Some(e) = &r.explanation
            && !r.within_tolerance()
        {
            notes.push(e.clone());
            let _ = write!(verdict, " [{}]", notes.len());
        }
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.case,
            r.quantity,
            r.unit.label(),
            r.paper.map_or("-".into(), num),
            r.exact.map_or("-".into(), num),
            num(r.computed),
            pct(r.relative_to_paper()),
            pct(r.relative_to_exact()),
            tol(r.tolerance),
            verdict
        );
    }
    for (k, n) in notes.iter().enumerate() {
        let _ = writeln!(out, "\n[{}] {}", k + 1, n);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(paper: f64, computed: f64, compare: CompareSpec) -> Row {
        Row {
            case: "c".into(),
            quantity: "q".into(),
            unit: UnitSpec::Span,
            paper: Some(paper),
            exact: Some(paper),
            computed,
            tolerance: 0.01,
            compare,
            source: "s".into(),
            explanation: Some("why".into()),
        }
    }

    #[test]
    fn verdicts_follow_the_tolerance_and_the_rule() {
        assert_eq!(row(-0.0454, -0.04537, CompareSpec::Match).verdict(), "ok");
        assert_eq!(row(-0.0454, -0.0470, CompareSpec::Match).verdict(), "NOT REPRODUCED");
        assert_eq!(row(0.0543, 0.0600, CompareSpec::Report).verdict(), "differs (transient)");
        let t = format(&[row(1.0, 2.0, CompareSpec::Match), row(1.0, 1.0, CompareSpec::Match)]);
        assert!(t.contains("NOT REPRODUCED [1]") && t.contains("[1] why") && t.contains("+100.00 %"), "{t}");
        assert_eq!(t.matches("why").count(), 1, "only the differing row gets a note");
    }
}
