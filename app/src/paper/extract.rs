//! Generic extractors: a number from a recorded run, as a case's `extract = { kind = ... }` asks
//! (see [`crate::paper::spec::ExtractKind`]). Values are SI (metres, newtons, seconds).
//!
//! Values "at a time" interpolate the recorded samples linearly (the cases sample every 0.02 s or finer,
//! well below every time scale they check); values "at the end" are taken from the final state. Peaks
//! are taken over the samples within the window.

use crate::paper::spec::{ComponentSpec, ExtractKind, ExtractSpec};
use ohl::run::{Outcome, Probe};

/// Linear interpolation of `f(sample)` at time `t` over samples with times `ts`.
fn interpolate(ts: &[f64], ys: &[f64], t: f64) -> Option<f64> {
    if ts.is_empty() {
        return None;
    }
    let k = ts.partition_point(|&x| x < t);
    if k == 0 {
        return Some(ys[0]);
    }
    if k == ts.len() {
        return Some(ys[ts.len() - 1]);
    }
    let (t0, t1) = (ts[k - 1], ts[k]);
    let w = if t1 > t0 { (t - t0) / (t1 - t0) } else { 1.0 };
    Some(ys[k - 1] + w * (ys[k] - ys[k - 1]))
}

/// The recorded series of a run, column by column.
pub struct Series {
    /// times [s]
    pub t: Vec<f64>,
    /// mid-span displacement components [m]
    pub mid: [Vec<f64>; 3],
    /// largest segment tension [N]
    pub max_tension: Vec<f64>,
    /// probes beside each sample
    pub probes: Vec<Probe>,
}

impl Series {
    /// Columns of an outcome's samples, with the final state appended if the last sample is earlier.
    pub fn of(o: &Outcome) -> Self {
        let mut t: Vec<f64> = o.samples.iter().map(|s| s.t_s).collect();
        let mut mid = [0, 1, 2]
            .map(|k| o.samples.iter().map(|s| [s.mid_dx1_m, s.mid_dx2_m, s.mid_dx3_m][k]).collect::<Vec<f64>>());
        let mut max_tension: Vec<f64> = o.samples.iter().map(|s| s.max_tension_n).collect();
        let mut probes = o.probes.clone();
        let end = o.summary.final_time_s;
        if t.last().is_none_or(|&l| l < end) {
            t.push(end);
            for k in 0..3 {
                mid[k].push(o.summary.final_midspan_displacement_m[k]);
            }
            max_tension.push(o.summary.final_max_tension_n);
            probes.push(Probe::of(&o.solver));
        }
        Series { t, mid, max_tension, probes }
    }

    fn window(&self, w: Option<[f64; 2]>) -> std::ops::Range<usize> {
        let [a, b] = w.unwrap_or([f64::NEG_INFINITY, f64::INFINITY]);
        let lo = self.t.partition_point(|&x| x < a - 1e-9);
        let hi = self.t.partition_point(|&x| x <= b + 1e-9);
        lo..hi.max(lo)
    }

    /// The probe at (or just before) time `t`, or the last one.
    pub fn probe_at(&self, t: Option<f64>) -> Probe {
        match t {
            None => *self.probes.last().expect("a run records at least one probe"),
            Some(t) => {
                let k = self.t.partition_point(|&x| x <= t + 1e-9).max(1) - 1;
                self.probes[k.min(self.probes.len() - 1)]
            }
        }
    }
}

fn component(x: &ExtractSpec) -> usize {
    x.component.map_or(2, ComponentSpec::index)
}

/// Index of the sample of largest magnitude of `ys` within `r`.
fn peak_index(ys: &[f64], r: std::ops::Range<usize>) -> Option<usize> {
    r.max_by(|&a, &b| ys[a].abs().total_cmp(&ys[b].abs()))
}

/// Index of the first local extreme of `ys` within `r` (a sample larger in magnitude than both
/// neighbours, after the signal has left zero).
fn first_extreme(ys: &[f64], r: std::ops::Range<usize>) -> Option<usize> {
    let (lo, hi) = (r.start, r.end);
    (lo + 1..hi.saturating_sub(1)).find(|&i| {
        let (a, b, c) = (ys[i - 1], ys[i], ys[i + 1]);
        b != 0.0 && ((b >= a && b > c) || (b <= a && b < c))
    })
}

/// Extract a value [SI]; `None` if the run recorded nothing usable for it.
pub fn extract(series: &Series, x: &ExtractSpec, axial_stiffness_n: f64) -> Option<f64> {
    let s = series;
    let k = component(x);
    let at = |ys: &[f64]| match x.at_s {
        Some(t) => interpolate(&s.t, ys, t),
        None => ys.last().copied(),
    };
    match x.kind {
        ExtractKind::Midspan => at(&s.mid[k]),
        ExtractKind::MidspanPeak => peak_index(&s.mid[k], s.window(x.window_s)).map(|i| s.mid[k][i]),
        ExtractKind::MidspanPeakTime => peak_index(&s.mid[k], s.window(x.window_s)).map(|i| s.t[i]),
        ExtractKind::MidspanFirstExtreme => first_extreme(&s.mid[k], s.window(x.window_s)).map(|i| s.mid[k][i]),
        ExtractKind::MidspanFirstExtremeTime => first_extreme(&s.mid[k], s.window(x.window_s)).map(|i| s.t[i]),
        ExtractKind::MidspanAmplitude => {
            let r = s.window(x.window_s);
            let v = &s.mid[k][r];
            let (lo, hi) = v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
            (lo.is_finite()).then_some(0.5 * (hi - lo))
        }
        ExtractKind::MaxTension => at(&s.max_tension),
        ExtractKind::MaxTensionPeak => {
            let r = s.window(x.window_s);
            s.max_tension[r].iter().copied().fold(None, |m: Option<f64>, y| Some(m.map_or(y, |m| m.max(y))))
        }
        ExtractKind::SupportTension => {
            let left: Vec<f64> = s.probes.iter().map(|p| p.support_tension_n[0]).collect();
            at(&left)
        }
        ExtractKind::ThermalStrain | ExtractKind::ThermalForce => {
            let p = s.probe_at(x.at_s);
            let eps = p.rest_length_m / p.reference_length_m - 1.0;
            Some(if x.kind == ExtractKind::ThermalForce { axial_stiffness_n * eps } else { eps })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_peaks_and_first_extreme() {
        let ts = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let ys = [0.0, -1.0, -3.0, -2.0, -4.0, -3.5];
        assert_eq!(interpolate(&ts, &ys, 1.5), Some(-2.0));
        assert_eq!(interpolate(&ts, &ys, 9.0), Some(-3.5));
        assert_eq!(peak_index(&ys, 0..6), Some(4));
        assert_eq!(first_extreme(&ys, 0..6), Some(2));
        assert_eq!(first_extreme(&ys, 3..6), Some(4));
    }
}
