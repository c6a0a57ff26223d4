//! Axis ticks chosen so that their labels never collide, formatted with one precision per axis.
//!
//! Linear axes take the densest step of the 1-2-5 series whose formatted labels, measured in the bundled
//! font, fit between their neighbours with a gap; every label of an axis carries the same number of
//! decimals (the step's), so a narrow range never prints one value five times. Logarithmic axes label the
//! data's own abscissae when there are few (grid sizes of a convergence plot), else the decades, then the
//! 2 and 5 multiples and the other integers as long as they fit; a label that would collide is dropped.

use super::text;

/// Ticks of one axis and their labels.
#[derive(Clone, Debug, Default)]
pub(super) struct Ticks {
    /// positions (data units)
    pub at: Vec<f64>,
    /// label of each position
    pub labels: Vec<String>,
    /// grid lines between labelled ticks (the other integer multiples of a decade on log axes)
    pub minor: Vec<f64>,
}

/// Which direction labels are stacked in: along x they sit side by side, along y above each other.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Along {
    X,
    Y,
}

/// Room a label needs along the axis [px].
fn extent(label: &str, font_px: f64, along: Along) -> f64 {
    match along {
        Along::X => text::width(label, font_px as f32) as f64,
        Along::Y => font_px,
    }
}

/// Whether labels at pixel positions `px` fit with a gap of `gap` pixels.
fn fits(px: &[f64], labels: &[String], font_px: f64, along: Along, gap: f64) -> bool {
    px.windows(2).zip(labels.windows(2)).all(|(p, l)| {
        (p[1] - p[0]).abs() >= 0.5 * (extent(&l[0], font_px, along) + extent(&l[1], font_px, along)) + gap
    })
}

/// Labels of the values `v` on a linear axis whose step is `step`.
pub(super) fn format_linear(v: &[f64], step: f64) -> Vec<String> {
    let big = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let step_exp = step.abs().log10().floor() as i32;
    if big >= 1.0e5 || (big > 0.0 && big < 1.0e-3) {
        // One exponent per label, mantissa decimals down to the step.
        let e = big.log10().floor() as i32;
        let decimals = (e - step_exp).max(0) as usize;
        v.iter().map(|&x| if x.abs() < 0.5 * step { "0".to_string() } else { format!("{:.*e}", decimals, x) }).collect()
    } else {
        let decimals = (-step_exp).max(0) as usize;
        v.iter()
            .map(|&x| {
                // Rounding residue at zero prints as 0, not -0.
                let x = if x.abs() < 0.5 * step { 0.0 } else { x };
                format!("{:.*}", decimals, x)
            })
            .collect()
    }
}

/// Ticks of a linear axis over `[lo, hi]` drawn over `length_px` pixels.
pub(super) fn linear(lo: f64, hi: f64, length_px: f64, font_px: f64, along: Along) -> Ticks {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return Ticks::default();
    }
    let gap = match along {
        Along::X => 1.2 * font_px,
        Along::Y => 0.9 * font_px,
    };
    let mut exp = (span / 20.0).log10().floor() as i32;
    let mut best = Ticks::default();
    for _ in 0..12 {
        for m in [1.0, 2.0, 5.0] {
            let step = m * 10f64.powi(exp);
            if span / step > 12.0 {
                continue;
            }
            let first = (lo / step).ceil() as i64;
            let last = (hi / step).floor() as i64;
            let at: Vec<f64> = (first..=last).map(|i| i as f64 * step).collect();
            let labels = format_linear(&at, step);
            let px: Vec<f64> = at.iter().map(|v| (v - lo) / span * length_px).collect();
            best = Ticks { at, labels, minor: Vec::new() };
            if fits(&px, &best.labels, font_px, along, gap) {
                return best;
            }
        }
        exp += 1;
    }
    best
}

/// Label of a value on a logarithmic axis: shortest exact form, scientific if `sci`.
pub(super) fn format_log(v: f64, sci: bool) -> String {
    if !sci {
        let s = format!("{:.6}", v);
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        let s = format!("{:.3e}", v);
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
            None => s,
        }
    }
}

/// `v` rounded to `digits` significant digits.
fn round_sig(v: f64, digits: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// Ticks of a logarithmic axis over `[lo, hi]` (both > 0); `data` are the abscissae of the points drawn
/// (used as ticks when there are at most 8 distinct ones).
pub(super) fn log(lo: f64, hi: f64, length_px: f64, font_px: f64, along: Along, data: &[f64]) -> Ticks {
    if !(lo > 0.0 && hi > lo) {
        return Ticks::default();
    }
    let to_px = |v: f64| (v.ln() - lo.ln()) / (hi.ln() - lo.ln()) * length_px;
    let gap = match along {
        Along::X => 1.0 * font_px,
        Along::Y => 0.6 * font_px,
    };
    let (d0, d1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let mut minor = Vec::new();
    for d in d0..=d1 {
        for m in 1..10 {
            let v = m as f64 * 10f64.powi(d);
            if v >= lo && v <= hi {
                minor.push(v);
            }
        }
    }
    // Candidates in priority order.
    let mut distinct: Vec<f64> = data.iter().copied().filter(|v| *v >= lo && *v <= hi).collect();
    distinct.sort_by(f64::total_cmp);
    distinct.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * b.abs());
    let mut candidates: Vec<f64> = Vec::new();
    // The third tier only where the axis spans less than a decade.
    let tiers: &[&[i32]] = if hi / lo < 10.0 { &[&[1], &[2, 5], &[3, 4, 6, 7, 8, 9]] } else { &[&[1], &[2, 5]] };
    if !distinct.is_empty() && distinct.len() <= 8 {
        candidates.extend(&distinct);
    } else {
        for &mults in tiers {
            for d in d0..=d1 {
                for &m in mults.iter() {
                    let v = m as f64 * 10f64.powi(d);
                    if v >= lo && v <= hi {
                        candidates.push(v);
                    }
                }
            }
        }
    }
    // One format per axis: scientific as soon as one candidate is outside [1e-3, 1e5).
    let sci = candidates.iter().any(|v| !(1.0e-3..1.0e5).contains(&v.abs()));
    // Greedy: keep a candidate if its label clears every kept one.
    let mut kept: Vec<(f64, String)> = Vec::new();
    let from_data = !distinct.is_empty() && distinct.len() <= 8;
    for v in candidates {
        // Data abscissae (grid sizes, segment lengths) print with at most 3 significant digits.
        let l = if from_data { format_log(round_sig(v, 3), sci) } else { format_log(v, sci) };
        let (p, e) = (to_px(v), extent(&l, font_px, along));
        let clear = kept.iter().all(|(k, kl)| (to_px(*k) - p).abs() >= 0.5 * (e + extent(kl, font_px, along)) + gap);
        if clear {
            kept.push((v, l));
        }
    }
    kept.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (at, labels) = kept.into_iter().unzip();
    Ticks { at, labels, minor }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_narrow_range_gets_distinct_labels() {
        let t = linear(0.19605, 0.19618, 400.0, 13.0, Along::Y);
        let mut l = t.labels.clone();
        l.dedup();
        assert_eq!(l.len(), t.labels.len(), "{:?}", t.labels);
        assert!(t.at.len() >= 3, "{:?}", t.labels);
    }

    #[test]
    fn x_labels_never_collide() {
        for (lo, hi) in [(0.0, 8.0), (-1.2e5, 3.4e5), (0.0, 1.0e-4), (97.3, 103.9), (0.0, 1000.0)] {
            for len in [150.0, 300.0, 900.0] {
                let t = linear(lo, hi, len, 13.0, Along::X);
                let px: Vec<f64> = t.at.iter().map(|v| (v - lo) / (hi - lo) * len).collect();
                assert!(fits(&px, &t.labels, 13.0, Along::X, 0.0), "{lo} {hi} {len}: {:?}", t.labels);
            }
        }
    }

    #[test]
    fn log_axes_label_few_data_abscissae() {
        let t = log(20.0, 1200.0, 400.0, 13.0, Along::X, &[25.0, 50.0, 100.0, 200.0, 400.0, 800.0]);
        assert_eq!(t.labels, ["25", "50", "100", "200", "400", "800"]);
        // Segment lengths of a convergence plot print with 3 significant digits.
        let h = [4.944184, 9.767779, 19.070426, 36.407176];
        assert_eq!(log(4.0, 45.0, 400.0, 13.0, Along::X, &h).labels, ["4.94", "9.77", "19.1", "36.4"]);
        let t = log(20.0, 1200.0, 400.0, 13.0, Along::X, &(1..100).map(f64::from).collect::<Vec<_>>());
        assert!(t.labels.contains(&"100".to_string()) && t.labels.contains(&"1000".to_string()), "{:?}", t.labels);
    }
}
