//! Which peaks come from the start: the overshoot of a wind switched on (at once, or by a ramp too short
//! for the span) is a dynamic artefact of how the run begins, not a design value. It is flagged in
//! `summary.json` (`start_up`), in `ohl run`'s printed summary and in a sweep's table.
//!
//! # The rule
//!
//! The *onset* is the time `t_on` the wind load is raised: a `wind` event raising the multiplier (the
//! first such event; a `[loads.wind] ramp_s` is one at `t = 0`), or `t = 0` when the wind acts from the
//! start on a shape that is not its static equilibrium. The *start-up window* is
//!
//! ```text
//! [t_on, t_on + R + 2 T1],      T1 = 2 L sqrt(rho / H)   (the longest of the spans)
//! ```
//!
//! with `R` the onset's ramp time (0 for a step) and `T1` the period of the span's first swinging mode:
//! the taut-string fundamental `2 L / c`, `c = sqrt(H / rho)`, which is also the first out-of-plane mode
//! of a sagging cable (Irvine, *Cable Structures*, 1981, section 3.3: the out-of-plane modes are the
//! string's), with the chord `L`, the mass per unit chord `rho` and the span's largest segment tension
//! `H` at the end of the run. An undamped oscillator reaches the first maximum of its response half a
//! period after a step; two periods after the ramp's end leave room for the slower swing of a sagging
//! span under a load that turns it.
//!
//! A peak (the run's largest tension, each support's largest force magnitude) is flagged when it
//! occurs within the window AND exceeds the value at the end of the run by more than
//! [`START_UP_EXCESS`] (2 %): the end value is then the settled response to the same load, and the peak
//! its transient overshoot. The end value stands for the settled one only when no later event changes
//! the loads: with events after the onset the check is not made (`assessed = false`).
//!
//! The threshold: a run started from the static equilibrium under the wind stays at rest to the static
//! solver's tolerance (far below 2 %); a linear ramp of `R` overshoots the load's static response by at
//! most `T1 / (pi R)` of the wind's share ([`crate::events::wind_ramp`]): 2 % of the total for a ramp of
//! about 5 to 15 periods, depending on that share (the wind's increase of the tension).

use serde::Serialize;

/// The excess of a peak over the end value above which a peak within the start-up window is flagged
/// [-]: 2 % (module doc).
pub const START_UP_EXCESS: f64 = 0.02;

/// The start-up check of a run (module doc).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StartUp {
    /// the onset `t_on` [s]
    pub onset_s: f64,
    /// what raised the wind there
    pub onset: String,
    /// the onset's ramp time `R` [s] (0: a step)
    pub ramp_s: f64,
    /// the first swinging mode's period `T1` [s]
    pub first_mode_period_s: f64,
    /// the window's end `t_on + R + 2 T1` [s]
    pub window_end_s: f64,
    /// whether the check was made (false: events after the onset change the loads)
    pub assessed: bool,
    /// the flagged peaks (empty: none comes from the start)
    pub flagged: Vec<StartUpPeak>,
}

/// A peak that comes from the start.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StartUpPeak {
    /// `"max_tension"` or `"support N"` (N the support's node)
    pub quantity: String,
    /// the peak [N]
    pub peak_n: f64,
    /// when [s]
    pub time_s: f64,
    /// the value at the end of the run [N]
    pub final_n: f64,
}

impl StartUpPeak {
    /// The peak over the end value [-].
    pub fn ratio(&self) -> f64 {
        self.peak_n / self.final_n
    }
}

impl StartUp {
    /// The check for an onset at `onset_s` with ramp `ramp_s` and first-mode period `period_s`, of the
    /// peaks `(quantity, peak, time, end value)`; `assessed`: no later event changes the loads.
    pub fn check(
        onset_s: f64,
        onset: String,
        ramp_s: f64,
        period_s: f64,
        assessed: bool,
        peaks: &[(String, f64, f64, f64)],
    ) -> Self {
        let window_end_s = onset_s + ramp_s + 2.0 * period_s;
        let flagged = if assessed {
            peaks
                .iter()
                .filter(|(_, peak, time, end)| {
                    (onset_s..=window_end_s).contains(time) && *peak > (1.0 + START_UP_EXCESS) * end
                })
                .map(|(q, peak, time, end)| StartUpPeak {
                    quantity: q.clone(),
                    peak_n: *peak,
                    time_s: *time,
                    final_n: *end,
                })
                .collect()
        } else {
            Vec::new()
        };
        StartUp { onset_s, onset, ramp_s, first_mode_period_s: period_s, window_end_s, assessed, flagged }
    }

    /// One line per flagged peak, for a warning.
    pub fn describe(&self) -> Vec<String> {
        self.flagged
            .iter()
            .map(|p| {
                format!(
                    "{} peak {:.1} N at {:.3} s is {:.1} % above its end value {:.1} N and lies in the start-up \
                     window [{:.3}, {:.3}] s ({}; first mode period {:.2} s): it is the start's overshoot, not a \
                     design value; start from the equilibrium under the wind or ramp the wind over several \
                     periods (`ramp_s`)",
                    p.quantity,
                    p.peak_n,
                    p.time_s,
                    100.0 * (p.ratio() - 1.0),
                    p.final_n,
                    self.onset_s,
                    self.window_end_s,
                    self.onset,
                    self.first_mode_period_s
                )
            })
            .collect()
    }
}

/// The period of the first swinging mode of a span [s]: `2 L sqrt(rho / H)` (module doc), with the chord
/// `L` [m], the mass per unit chord `rho` [kg/m] and the tension `H` [N]; `None` unless all are positive.
pub fn first_mode_period_s(chord_m: f64, mass_per_chord_kg_per_m: f64, tension_n: f64) -> Option<f64> {
    let t = 2.0 * chord_m * (mass_per_chord_kg_per_m / tension_n).sqrt();
    (chord_m > 0.0 && mass_per_chord_kg_per_m > 0.0 && tension_n > 0.0 && t.is_finite()).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_an_early_overshoot_and_nothing_else() {
        let peaks = vec![
            ("max_tension".to_string(), 148.0, 4.0, 100.0), // in the window, 48 % over: flagged
            ("support 0".to_string(), 101.0, 4.0, 100.0),   // in the window, 1 % over: not
            ("support 50".to_string(), 150.0, 30.0, 100.0), // 50 % over, but after the window: not
        ];
        let s = StartUp::check(1.0, "wind".into(), 0.0, 6.0, true, &peaks);
        assert_eq!(s.window_end_s, 13.0);
        assert_eq!(s.flagged.len(), 1);
        assert_eq!(s.flagged[0].quantity, "max_tension");
        assert!((s.flagged[0].ratio() - 1.48).abs() < 1e-15);
        assert!(StartUp::check(1.0, "wind".into(), 0.0, 6.0, false, &peaks).flagged.is_empty());
    }

    #[test]
    fn first_mode_is_the_string_fundamental() {
        // 400 m, 1.628 kg/m, 28 kN: c = sqrt(28000 / 1.628) = 131.1 m/s, T1 = 800 / c = 6.10 s.
        let t = first_mode_period_s(400.0, 1.628, 28000.0).unwrap();
        assert!((t - 800.0 / (28000.0f64 / 1.628).sqrt()).abs() < 1e-12);
        assert!(first_mode_period_s(400.0, 1.628, 0.0).is_none());
    }
}
