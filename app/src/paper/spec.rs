//! The `[paper]` section of a case file in `paper_cases/`: which values of the paper the case checks,
//! where they come from, how each is extracted from the run, the tolerance and its justification, and
//! which panels the figure shows. A case file is otherwise an ordinary scenario (the library keeps this
//! table as an opaque [`toml::Value`] and ignores it; `ohl run` runs the scenario); `ohl paper` runs it and
//! prints the comparison table (see [`crate::paper`]). [`parse`] reads the table from the case file's
//! text (so that the line and column of an error are those of the file) and [`validate`] checks it.
//!
//! ```toml
//! [paper]
//! section = "4.1"
//! title = "Wind on a weightless wire: mid-span deflection"
//!
//! [[paper.checks]]
//! quantity = "equilibrium mid-span x1"
//! paper = 0.03310
//! unit = "span"                       # the paper's dimensionless length, metres / 160
//! source = "section 4.1, text after (4.1), Fig. 2a"
//! extract = { kind = "midspan", component = "x1" }      # at the end of the run
//! reference = "exact_arc"
//! tolerance = 0.01
//! justification = "equilibrium: independent of damping; O(ds^2) = 5e-4 at N = 50"
//!
//! [[paper.panels]]
//! kind = "midspan"
//! component = "x1"
//! ```

use ohl::scenario::validate::{Check, Problem};
use ohl::scenario::{InputError, from_toml};
use serde::Deserialize;

/// A case file as the paper tool reads it: the `[paper]` table, every other key ignored (the library
/// reads those).
#[derive(Deserialize)]
struct CaseFile {
    #[serde(default)]
    paper: Option<PaperSpec>,
}

/// The `[paper]` table of a case file's text (none if it has none), validated against the run's end
/// time `end_s` [s]; `file` names it in messages.
pub fn parse(text: &str, file: &str, end_s: f64) -> Result<Option<PaperSpec>, InputError> {
    let case: CaseFile = from_toml(text, file)?;
    let Some(spec) = case.paper else { return Ok(None) };
    let problems = validate(&spec, end_s);
    if problems.is_empty() { Ok(Some(spec)) } else { Err(InputError::Invalid { file: file.to_string(), problems }) }
}

/// The fields every `[[paper.checks]]` row has, wire or heat case: a finite paper value, a paper value
/// or a reference for a `"match"` row, a tolerance in (0, 10]. `f` makes the field's path.
pub fn check_row(
    c: &mut Check,
    f: &dyn Fn(&str) -> String,
    paper: Option<f64>,
    has_reference: bool,
    compare: CompareSpec,
    tolerance: f64,
) {
    if let Some(v) = paper
        && !v.is_finite()
    {
        c.fail(&f("paper"), v, "must be a finite number");
    }
    if paper.is_none() && !has_reference && compare == CompareSpec::Match {
        c.fail(&f("paper"), "(missing)", "a \"match\" check needs a paper value or a reference");
    }
    c.within(&f("tolerance"), tolerance, f64::MIN_POSITIVE, 10.0, "must be a relative tolerance in (0, 10]");
}

/// All problems of a `[paper]` table (tolerances, extractors and windows) of a run that ends at `end_s`
/// [s] at the latest; empty when it is valid.
pub fn validate(p: &PaperSpec, end_s: f64) -> Vec<Problem> {
    let mut c = Check::default();
    c.positive("paper.length_scale_m", p.length_scale_m);
    let hi = end_s;
    for (k, ch) in p.checks.iter().enumerate() {
        let f = |name: &str| format!("paper.checks[{k}].{name}");
        check_row(&mut c, &f, ch.paper, ch.reference.is_some(), ch.compare, ch.tolerance);
        let x = &ch.extract;
        let needs_component = matches!(
            x.kind,
            ExtractKind::Midspan
                | ExtractKind::MidspanPeak
                | ExtractKind::MidspanPeakTime
                | ExtractKind::MidspanFirstExtreme
                | ExtractKind::MidspanFirstExtremeTime
                | ExtractKind::MidspanAmplitude
        );
        if needs_component && x.component.is_none() {
            c.fail(
                &f("extract.component"),
                "(missing)",
                "required for the midspan extractors: \"x1\", \"x2\" or \"x3\"",
            );
        }
        if let Some(t) = x.at_s {
            c.within(&f("extract.at_s"), t, 0.0, hi, "must be in [0, end time]");
        }
        if let Some(w) = x.window_s
            && !(w[0].is_finite() && w[1].is_finite() && 0.0 <= w[0] && w[0] < w[1] && w[1] <= hi)
        {
            c.fail(&f("extract.window_s"), format!("{w:?}"), "must be [t0, t1] with 0 <= t0 < t1 <= end time");
        }
    }
    c.0
}

/// The `[paper]` section.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PaperSpec {
    /// section of the paper reproduced, e.g. "4.1"
    pub section: String,
    /// title of the figure
    pub title: String,
    /// length scale of the paper's dimensionless lengths `l` [m]; default 160 (the span, section 4)
    #[serde(default = "default_length")]
    pub length_scale_m: f64,
    /// the values checked, one table row each
    #[serde(default)]
    pub checks: Vec<CheckSpec>,
    /// the figure's panels, in order
    #[serde(default)]
    pub panels: Vec<PanelSpec>,
    /// notes printed under the table (choices the paper leaves open, damping used, ...)
    #[serde(default)]
    pub notes: Vec<String>,
}

fn default_length() -> f64 {
    160.0
}

/// Unit in which a paper value is printed; the computed SI value is converted to it.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum UnitSpec {
    /// dimensionless length: metres / `length_scale_m`
    Span,
    /// metres
    M,
    /// kilonewtons
    Kn,
    /// dimensionless time `tau = t U / l` (the run's `output.tau_speed_m_per_s` and the chord)
    Tau,
    /// seconds
    S,
    /// dimensionless (strains, ratios)
    One,
}

impl UnitSpec {
    /// Short name for the table.
    pub fn label(self) -> &'static str {
        match self {
            UnitSpec::Span => "l",
            UnitSpec::M => "m",
            UnitSpec::Kn => "kN",
            UnitSpec::Tau => "tau",
            UnitSpec::S => "s",
            UnitSpec::One => "-",
        }
    }
}

/// Component of the mid-span displacement.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ComponentSpec {
    /// across the line (wind direction)
    X1,
    /// along the span
    X2,
    /// vertical
    X3,
}

impl ComponentSpec {
    /// Index 0, 1 or 2.
    pub fn index(self) -> usize {
        match self {
            ComponentSpec::X1 => 0,
            ComponentSpec::X2 => 1,
            ComponentSpec::X3 => 2,
        }
    }
    /// "x1", "x2" or "x3".
    pub fn name(self) -> &'static str {
        ["x1", "x2", "x3"][self.index()]
    }
}

/// What is extracted from the run (all generic: no case-specific code).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ExtractKind {
    /// mid-span displacement from the chord midpoint [m] (component), at `at_s` or at the end
    Midspan,
    /// the mid-span displacement of largest magnitude within `window_s` [m] (component)
    MidspanPeak,
    /// the time of that extreme [s]
    MidspanPeakTime,
    /// the first local extreme of the component within `window_s` (the first swing) [m]
    MidspanFirstExtreme,
    /// the time of the first local extreme [s]
    MidspanFirstExtremeTime,
    /// largest segment tension [N], at `at_s` or at the end
    MaxTension,
    /// largest segment tension within `window_s` [N]
    MaxTensionPeak,
    /// tension of the segment at the left support [N], at `at_s` or at the end
    SupportTension,
    /// amplitude of the component within `window_s`: (max - min) / 2 [m]
    MidspanAmplitude,
    /// mean thermal strain of the wire `(sum l0 - sum L) / sum L` [-], at `at_s` or at the end
    ThermalStrain,
    /// thermal force `EA eps_t` [N], eq. (5.6), at `at_s` or at the end
    ThermalForce,
}

/// How to extract a computed value.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExtractSpec {
    /// the extractor
    pub kind: ExtractKind,
    /// component of the mid-span displacement, for the `midspan*` kinds
    #[serde(default)]
    pub component: Option<ComponentSpec>,
    /// time [s] (default: the end of the run)
    #[serde(default)]
    pub at_s: Option<f64>,
    /// time window `[t0, t1]` [s] for peaks (default: the whole run)
    #[serde(default)]
    pub window_s: Option<[f64; 2]>,
}

/// Independent reference computed from the scenario's data (and the wire's state at the extraction
/// time) with [`ohl::exact`].
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ReferenceKind {
    /// the exact elastic circular arc under the wind's uniform normal pressure
    ExactArc,
    /// the paper's approximate arc (4.1)
    PaperArc,
    /// the exact elastic catenary under the wire's weight at the extraction time (mass, stress-free
    /// length and temperature as they are then)
    ExactCatenary,
    /// the exact elastic catenary under weight plus the wind pressure taken as a fixed-direction load
    /// (the resultant-plane approximation of section 4.3)
    ExactCatenaryWithWind,
    /// the paper's approximate parabola (4.3)-(4.4)
    PaperParabola,
    /// thermal strain (5.5) `alpha_t (u - u_ref)` with the mean segment temperature at the time
    ThermalStrain,
    /// thermal force (5.6) `EA alpha_t (u - u_ref)`
    ThermalForce,
}

/// Verdict rule.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum CompareSpec {
    /// must be within the tolerance (equilibria, exact formulas)
    #[default]
    Match,
    /// reported beside the paper's value: it depends on damping the paper does not give (peaks, times)
    Report,
}

/// One checked value. Generic over how the computed value is extracted (`X`) and which reference it is
/// compared with (`R`): a wire case uses [`ExtractSpec`] and [`ReferenceKind`], a heat case
/// ([`crate::paper::heat_spec`]) its own.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CheckSpec<X = ExtractSpec, R = ReferenceKind> {
    /// what it is
    pub quantity: String,
    /// the paper's value, in `unit`; absent where the paper prints none (then the computed value is
    /// compared with the reference, or only reported)
    #[serde(default)]
    pub paper: Option<f64>,
    /// unit of `paper` (and of the table row)
    pub unit: UnitSpec,
    /// where in the paper it is printed
    pub source: String,
    /// how the computed value is extracted
    pub extract: X,
    /// an independent reference value, if one exists
    #[serde(default = "none")]
    pub reference: Option<R>,
    /// relative tolerance against the paper's value (or the reference's, without one) [-], > 0
    pub tolerance: f64,
    /// why that tolerance
    pub justification: String,
    /// `"match"` (default) or `"report"`
    #[serde(default)]
    pub compare: CompareSpec,
    /// why the value differs from the paper, when it is known to
    #[serde(default)]
    pub explanation: Option<String>,
    /// dimensionless time `tau` at which the paper prints the value (places its marker in the figure)
    #[serde(default)]
    pub paper_tau: Option<f64>,
}

fn none<R>() -> Option<R> {
    None
}

/// A figure panel kind.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum PanelKind {
    /// history of a mid-span displacement component, with the paper's points and the reference
    Midspan,
    /// mid-span trajectory in a plane (`plane = ["x1", "x3"]`)
    Trajectory,
    /// shapes at the snapshot times in a plane (`plane = ["x2", "x3"]`)
    Shapes,
    /// history of the largest segment tension
    MaxTension,
    /// history of the tension at the supports
    SupportTension,
    /// history of the mean wire temperature
    Temperature,
}

/// One figure panel.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PanelSpec {
    /// what it shows
    pub kind: PanelKind,
    /// component, for `midspan`
    #[serde(default)]
    pub component: Option<ComponentSpec>,
    /// horizontal and vertical axes, for `trajectory` and `shapes`
    #[serde(default)]
    pub plane: Option<[ComponentSpec; 2]>,
    /// time window [s] shown (default: the whole run)
    #[serde(default)]
    pub window_s: Option<[f64; 2]>,
    /// panel title (default: from the kind)
    #[serde(default)]
    pub title: Option<String>,
    /// time axis: `"tau"` (default, the paper's sections 4) or `"s"` (section 5.6 prints seconds)
    #[serde(default)]
    pub time_unit: Option<UnitSpec>,
}
