//! The start-up check of a single-conductor run or of a line's conductor ([`crate::output::start_up`] states the rule): the wind's
//! onset from the plan, the first mode's period from the state at the end, the peaks from the run.

use crate::events::Action;
use crate::output::start_up::{StartUp, first_mode_period_s};
use crate::scenario::Plan;
use crate::scheme::Explicit;

/// The wind's onset in a plan: `(t_on, what, R, index of the onset's event)` (`None` for the index: the
/// wind acts from `t = 0` on a shape that is not its equilibrium); `None` when the wind is never raised.
/// `from_equilibrium`: the run starts from the static equilibrium of its loads at `t = 0` (a line's
/// conductor: the line's).
pub fn wind_onset(plan: &Plan, from_equilibrium: bool) -> Option<(f64, String, f64, Option<usize>)> {
    let loads = plan.solver.loads();
    loads.wind?;
    let mut scale = loads.wind_scale;
    if scale > 0.0 && !from_equilibrium {
        return Some((0.0, "wind on from t = 0 on a shape that is not its equilibrium".into(), 0.0, None));
    }
    for (k, e) in plan.events.iter().enumerate() {
        match e.action {
            Action::Wind { scale: s, ramp_s, .. } if s > scale => {
                let what = if ramp_s > 0.0 {
                    format!("wind raised from {scale} to {s} over a ramp of {ramp_s} s")
                } else {
                    format!("wind raised from {scale} to {s} at once")
                };
                return Some((e.time_s, what, ramp_s, Some(k)));
            }
            Action::Wind { scale: s, .. } => scale = s,
            // A gust is a load history of its own, not an onset of a steady wind.
            Action::Gust { .. } => return None,
            _ => {}
        }
    }
    None
}

/// The check after a run: `solver` at the end (forces evaluated), `from_equilibrium` as for
/// [`wind_onset`], `peaks` as [`StartUp::check`] takes them. `None` without an onset or without a
/// positive tension at the end.
pub fn check(
    plan: &Plan,
    solver: &Explicit,
    from_equilibrium: bool,
    peaks: &[(String, f64, f64, f64)],
) -> Option<StartUp> {
    let (onset_s, what, ramp_s, index) = wind_onset(plan, from_equilibrium)?;
    let w = solver.wire();
    let n = w.segments();
    let spans: Vec<(usize, usize)> = if plan.spans.is_empty() { vec![(0, n)] } else { plan.spans.clone() };
    let period = spans
        .iter()
        .filter_map(|&(first, last)| {
            let chord = (0..3).map(|k| (w.x[k][last] - w.x[k][first]).powi(2)).sum::<f64>().sqrt();
            let mass: f64 = w.segment_mass[first..last].iter().sum();
            first_mode_period_s(chord, mass / chord, solver.max_tension_in(first..last))
        })
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.max(t))))?;
    // The end value stands for the settled response only when no later event changes the loads.
    let assessed = match index {
        Some(k) => plan.events.len() == k + 1,
        None => plan.events.is_empty(),
    };
    Some(StartUp::check(onset_s, what, ramp_s, period, assessed, peaks))
}
