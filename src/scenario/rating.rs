//! Thermal rating by clearance: the largest current for which a span's (or a section's) sag or ground
//! clearance stays within a limit, in steady state and after a current step (`ohl rating`).
//!
//! The scenario's `[thermal]` table gives the conductor, the weather and, by its first point, the current
//! before a step; its `[rating]` table the limit. Method:
//!
//! 1. The clearance (or sag) of the line at a uniform conductor temperature `T` is that of its static
//!    equilibrium with every segment at `T` ([`crate::statics::solve`], the stress-free lengths following
//!    (5.5)); it falls (the sag grows) with `T`. The limiting temperature `T_lim` is its root, bracketed
//!    between the air temperature and the conductor's maximum temperature (or 600 K), by bisection to
//!    1e-3 K (each solve starts from the last one's state).
//! 2. The steady rating for the clearance is the ampacity at `T_lim` ([`crate::thermal::steady::ampacity`],
//!    closed form); with a maximum conductor temperature `T_max` the rating is the smaller of the two.
//! 3. The margin ([`OtherLimit`]): where `T_max` governs, the temperature at which the clearance (or sag)
//!    limit would be reached, by the same bisection between `T_max` and 600 K (the top of
//!    [`super::range::RATING_TEMPERATURE_K`]), and the steady ampacity there (the same closed form); where
//!    the clearance governs, `T_max` and its ampacity. So the margin between the two limits is visible in
//!    temperature and in current.
//! 4. After a step from the first point's current to `step_to_a`: the conductor starts at the steady state
//!    of the first current and the transient ([`crate::thermal::transient`]) is run until it reaches the
//!    governing temperature (the time to reach the limit), or for 24 h. The sag follows the temperature
//!    quasi-statically: the mechanical response (seconds) is fast beside the thermal one (minutes).
//!
//! The static solve ignores ground contact (the ground only measures the clearance), wind and other loads
//! are those of the scenario at `t = 0`.

use serde::Deserialize;

use super::range::Range as Allowed;
use super::validate::Check;
use super::{InputError, Plan, Problem, Scenario};
use crate::statics::{self, StaticOptions};
use crate::thermal::transient::{CurrentSchedule, Transient, time_to_reach};
use crate::thermal::{HeatBalance, Model, steady};

/// The `[rating]` table of a scenario.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RatingSpec {
    /// least vertical clearance to the `[ground]` allowed [m], in (0, 1e3] (needs a `[ground]` table)
    #[serde(default)]
    pub min_clearance_m: Option<f64>,
    /// largest mid-span sag below the chord allowed [m], in (0, 1e3]
    #[serde(default)]
    pub max_sag_m: Option<f64>,
    /// the span whose clearance or sag is limited (0-based); default every span (the least clearance or
    /// the largest sag of the line)
    #[serde(default)]
    pub span: Option<usize>,
    /// the conductor's maximum temperature `T_max` [K], in [273.15, 600]; default none
    #[serde(default)]
    pub max_temperature_k: Option<f64>,
    /// a current step [A], in (0, 1e5]: from the first point of `thermal.current_a` to this current
    #[serde(default)]
    pub step_to_a: Option<f64>,
}

/// Check the `[rating]` table.
/// A clearance or sag limit [m] (`rating.min_clearance_m`, `rating.max_sag_m`).
const LIMIT_M: Allowed = Allowed::open_closed(0.0, 1.0e3, "m");

pub(crate) fn check(c: &mut Check, s: &Scenario, r: &RatingSpec) {
    match (r.min_clearance_m, r.max_sag_m) {
        (Some(_), Some(_)) | (None, None) => {
            c.fail("rating", "", "must give exactly one of min_clearance_m and max_sag_m");
        }
        (Some(m), None) => {
            c.range("rating.min_clearance_m", m, &LIMIT_M);
            if s.ground.is_none() {
                c.fail("rating.min_clearance_m", m, "needs a [ground] table to measure the clearance from");
            }
        }
        (None, Some(m)) => {
            c.range("rating.max_sag_m", m, &LIMIT_M);
        }
    }
    if let Some(t) = r.max_temperature_k {
        c.range("rating.max_temperature_k", t, &super::range::RATING_TEMPERATURE_K);
    }
    if let Some(i) = r.step_to_a {
        c.range("rating.step_to_a", i, &Allowed::open_closed(0.0, 1.0e5, "A"));
    }
    if s.thermal.is_none() {
        c.fail("rating", "", "needs a [thermal] table (conductor, weather, current)");
    }
}

/// The rating of a scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Rating {
    /// what is limited: "clearance" or "sag"
    pub quantity: &'static str,
    /// the limit [m]
    pub limit_m: f64,
    /// the temperature at which the line reaches the limit `T_lim` [K] (`None`: not within `T_max`)
    pub limit_temperature_k: Option<f64>,
    /// the clearance or sag at the air temperature [m]
    pub at_air_m: f64,
    /// the clearance or sag at the governing temperature [m]
    pub at_rating_m: f64,
    /// the steady ampacity for the clearance or sag [A] (`None` where `T_max` governs)
    pub clearance_ampacity_a: Option<f64>,
    /// the steady ampacity for `T_max` [A]
    pub temperature_ampacity_a: Option<f64>,
    /// the steady rating: the smaller [A]
    pub rating_a: f64,
    /// the governing temperature [K]
    pub governing_temperature_k: f64,
    /// a step: (from [A], to [A], the steady temperature before [K], the time to reach the governing
    /// temperature [s] or `None` if not within 24 h)
    pub step: Option<(f64, f64, f64, Option<f64>)>,
    /// static solves spent [-] on the rating (1. and 2.)
    pub solves: usize,
    /// the limit that does not govern (`None` without `T_max`)
    pub other: Option<OtherLimit>,
}

/// The limit that does not govern a rating: where it lies in conductor temperature and current, so that the
/// margin to it is visible (module doc, 3.).
#[derive(Clone, Debug, PartialEq)]
pub struct OtherLimit {
    /// what it limits: `"clearance"`, `"sag"` (where `T_max` governs) or `"temperature"` (where the
    /// clearance or sag governs)
    pub quantity: &'static str,
    /// the conductor temperature at which it is reached [K] (`None`: the clearance or sag stays within its
    /// limit up to 600 K)
    pub temperature_k: Option<f64>,
    /// the steady ampacity at that temperature [A] (`None` where there is none)
    pub current_a: Option<f64>,
    /// static solves spent on it [-]
    pub solves: usize,
    /// why the temperature could not be found (a static solve beyond `T_max` failed)
    pub failed: Option<String>,
}

/// Why a rating failed.
#[derive(Debug, thiserror::Error)]
pub enum RatingError {
    /// invalid input
    #[error("{0}")]
    Input(#[from] InputError),
    /// a static solve or a heat balance failed
    #[error("{0}")]
    Failed(String),
}

fn problem(field: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> InputError {
    InputError::Invalid {
        file: "scenario".into(),
        problems: vec![Problem { field: field.into(), value: value.to_string(), allowed: allowed.into() }],
    }
}

/// The rating of scenario `s` (read from `file`).
pub fn rate(s: &Scenario, file: &str) -> Result<Rating, RatingError> {
    let Some(r) = &s.rating else {
        return Err(problem("rating", "(missing)", "the scenario needs a [rating] table").into());
    };
    // Building the plan validates the whole scenario, the [rating] table included.
    let plan: Plan = super::plan(s, file)?;
    let t = s.thermal.as_ref().expect("validated: [rating] needs [thermal]");
    let conductor = t.conductor.thermal().map_err(|e| RatingError::Failed(e.to_string()))?;
    let model = Model::new(t.standard.into(), conductor, super::thermal::weather(&t.weather))
        .with_inclination(t.inclination_deg);
    let mut solver = plan.solver.clone();
    solver.set_ground(None);
    let spans: Vec<(usize, usize)> =
        if plan.spans.is_empty() { vec![(0, solver.wire().segments())] } else { plan.spans.clone() };
    let chosen: Vec<(usize, usize)> = match r.span {
        Some(k) if k < spans.len() => vec![spans[k]],
        Some(k) => return Err(problem("rating.span", k, format!("must be a span, in [0, {}]", spans.len() - 1)).into()),
        None => spans,
    };
    let ground = plan.ground.clone();
    let (quantity, limit) = match (r.min_clearance_m, r.max_sag_m) {
        (Some(m), _) => ("clearance", m),
        (_, Some(m)) => ("sag", m),
        _ => unreachable!("checked"),
    };
    let n = solver.wire().segments();
    let solves = std::cell::Cell::new(0);
    // margin(T) >= 0 while within the limit.
    let mut margin = |temp: f64| -> Result<(f64, f64), RatingError> {
        solver.wire_mut().set_temperature(0..n, temp);
        statics::solve(&mut solver, &StaticOptions::default())
            .map_err(|e| RatingError::Failed(format!("static solve at {temp:.3} K: {e}")))?;
        solves.set(solves.get() + 1);
        let w = solver.wire();
        let value = match &ground {
            Some(g) if quantity == "clearance" => {
                chosen.iter().map(|&(a, b)| g.least_clearance_m(&w.x, a..=b)).fold(f64::INFINITY, f64::min)
            }
            _ => chosen
                .iter()
                .map(|&(a, b)| {
                    let (pa, pb, m) = (w.position(a), w.position(b), w.position((a + b) / 2));
                    0.5 * (pa[2] + pb[2]) - m[2]
                })
                .fold(f64::NEG_INFINITY, f64::max),
        };
        let m = if quantity == "clearance" { value - limit } else { limit - value };
        Ok((m, value))
    };
    let air = model.air_temperature_k();
    let (m_air, at_air) = margin(air)?;
    if m_air < 0.0 {
        return Err(RatingError::Failed(format!(
            "the {quantity} is {at_air:.3} m at the air temperature ({:.2} C), already beyond the limit {limit} m",
            air - 273.15
        )));
    }
    let top = r.max_temperature_k.unwrap_or(600.0).max(air);
    let (m_top, _) = margin(top)?;
    let limit_temperature_k =
        if m_top >= 0.0 { None } else { Some(last_within(air, top, |t| Ok(margin(t)?.0 >= 0.0))?) };
    // Each limit's ampacity, or why it has none (kept for the message if neither has one).
    let mut reasons = Vec::new();
    let mut ampacity = |limit: String, temp: Option<f64>| match temp.map(|t| (t, steady::ampacity(&model, t))) {
        Some((_, Ok(a))) => Some(a.current_a),
        Some((t, Err(e))) => {
            reasons.push(format!("{limit}, at {t:.3} K ({:.2} C): {e}", t - 273.15));
            None
        }
        None => None,
    };
    let clearance_ampacity_a = ampacity(format!("the {quantity} limit {limit} m"), limit_temperature_k);
    let temperature_ampacity_a = ampacity("rating.max_temperature_k".into(), r.max_temperature_k);
    if limit_temperature_k.is_none() {
        reasons.insert(0, format!("the {quantity} stays within its limit {limit} m up to {top:.3} K"));
    }
    let (rating_a, governing) = match (clearance_ampacity_a, temperature_ampacity_a) {
        (Some(a), Some(b)) if b < a => (b, r.max_temperature_k.expect("given")),
        (Some(a), _) => (a, limit_temperature_k.expect("found")),
        (None, Some(b)) => (b, r.max_temperature_k.expect("given")),
        (None, None) => {
            let why = reasons.join("; ");
            return Err(RatingError::Failed(format!("no ampacity at the limiting temperature: {why}")));
        }
    };
    let (m_gov, at_rating) = margin(governing)?;
    debug_assert!(m_gov >= -1e-6);
    let rating_solves = solves.get();
    let other = match r.max_temperature_k {
        None => None,
        Some(t_max) if governing != t_max => Some(OtherLimit {
            quantity: "temperature",
            temperature_k: Some(t_max),
            current_a: temperature_ampacity_a,
            solves: 0,
            failed: None,
        }),
        Some(t_max) => {
            // T_max governs: where the clearance or sag limit is reached, below T_max (found above, without
            // an ampacity) or beyond it (the same bisection, from T_max on).
            let from = t_max.max(air);
            let top = super::range::RATING_TEMPERATURE_K.hi.max(from);
            let mut search = || -> Result<Option<f64>, RatingError> {
                if limit_temperature_k.is_some() {
                    return Ok(limit_temperature_k);
                }
                if margin(top)?.0 >= 0.0 {
                    return Ok(None);
                }
                Ok(Some(last_within(from, top, |t| Ok(margin(t)?.0 >= 0.0))?))
            };
            // A failed static solve beyond T_max leaves the rating as it is; the margin says why it is missing.
            let (found, failed) = match search() {
                Ok(t) => (t, None),
                Err(e) => (None, Some(e.to_string())),
            };
            let current_a = found.and_then(|t| steady::ampacity(&model, t).ok()).map(|a| a.current_a);
            Some(OtherLimit { quantity, temperature_k: found, current_a, solves: solves.get() - rating_solves, failed })
        }
    };
    let step = match r.step_to_a {
        Some(to) => {
            let schedule = CurrentSchedule::new(t.current_a.iter().map(|p| (p[0], p[1])).collect())
                .ok_or_else(|| RatingError::Failed("thermal.current_a".into()))?;
            let from = schedule.initial_a();
            let start = steady::temperature(&model, from).map_err(|e| RatingError::Failed(e.to_string()))?;
            let step = CurrentSchedule::step(0.0, from, to);
            let tr = Transient { model: &model, current: &step, step_s: t.step_s };
            let when = time_to_reach(&tr, 0.0, start.temperature_k, governing, 86_400.0);
            Some((from, to, start.temperature_k, when))
        }
        None => None,
    };
    Ok(Rating {
        quantity,
        limit_m: limit,
        limit_temperature_k,
        at_air_m: at_air,
        at_rating_m: at_rating,
        clearance_ampacity_a,
        temperature_ampacity_a,
        rating_a,
        governing_temperature_k: governing,
        step,
        solves: rating_solves,
        other,
    })
}

/// The last temperature [K] in `[lo, hi]` at which `within` holds, by bisection to 1e-3 K: `within(lo)`
/// holds and `within(hi)` does not (the caller checked both ends), and the limit's margin decreases
/// monotonically with temperature (the sag grows with the thermal strain).
fn last_within(
    mut lo: f64,
    mut hi: f64,
    mut within: impl FnMut(f64) -> Result<bool, RatingError>,
) -> Result<f64, RatingError> {
    while hi - lo > 1e-3 {
        let mid = 0.5 * (lo + hi);
        if within(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}
