//! The terminal progress bar of `ohl run`: an observer of the library's run loop ([`ohl::run::Observer`]).
//!
//! A run to a fixed end time shows a bar that fills to 100 % at the end time. A run that stops when the
//! wire has settled has no known end (its `max_time_s` is only a limit, and a settled run typically stops
//! well before it), so it shows a spinner with the simulated time and "at most MAX s, stops when
//! settled" instead of a bar scaled to the limit. The message (the simulated time) is set before the
//! first frame is drawn.

use std::io::IsTerminal;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use ohl::run::{Control, Ending, Level, Observer, OutputError};
use ohl::scenario::Plan;
use ohl::scenario::build::Stop;

/// Steps of the bar for a run to a fixed end time.
const LENGTH: u64 = 1000;

/// A progress bar (or spinner) for one run.
pub struct Bar {
    bar: ProgressBar,
    settling: bool,
    horizon_s: f64,
    next_s: f64,
}

impl Bar {
    /// The bar for a run of `plan`, drawn on stderr; none when stderr is not a terminal.
    pub fn for_plan(plan: &Plan) -> Option<Bar> {
        std::io::stderr().is_terminal().then(|| Bar::new(plan.stop, ProgressDrawTarget::stderr()))
    }

    /// The bar for a run that stops as `stop` says, drawn on `target`.
    pub fn new(stop: Stop, target: ProgressDrawTarget) -> Bar {
        let settling = matches!(stop, Stop::Settled { .. });
        // Hidden until the style and the first message are set, so that no frame shows an empty `t`.
        let bar = ProgressBar::with_draw_target(Some(LENGTH), ProgressDrawTarget::hidden());
        let template = match stop {
            Stop::EndTime(_) => "{bar:40} {percent:>3}% t = {msg} s, eta {eta}".to_string(),
            Stop::Settled { max_time_s, .. } => {
                format!("{{spinner}} t = {{msg}} s (at most {max_time_s} s, stops when settled), {{elapsed}}")
            }
        };
        bar.set_style(ProgressStyle::with_template(&template).expect("static template"));
        bar.set_message(format!("{:.3}", 0.0));
        bar.set_draw_target(target);
        if settling {
            bar.enable_steady_tick(Duration::from_millis(120));
        }
        Bar { bar, settling, horizon_s: stop.horizon_s(), next_s: 0.0 }
    }

    /// Show the simulated time `t` [s].
    fn show(&self, t: f64) {
        self.bar.set_message(format!("{t:.3}"));
        if !self.settling && self.horizon_s > 0.0 {
            self.bar.set_position(((LENGTH as f64 * t / self.horizon_s) as u64).min(LENGTH));
        }
    }
}

impl Observer for Bar {
    /// Updates at most every thousandth of the horizon (the bar's resolution): a cheap test per step.
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        if level.t_s >= self.next_s {
            self.show(level.t_s);
            self.next_s = level.t_s + self.horizon_s / LENGTH as f64;
        }
        Ok(Control::Continue)
    }

    fn finish(&mut self, level: &Level, _ending: &Ending) -> Result<(), OutputError> {
        self.show(level.t_s);
        self.bar.finish_and_clear();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_time_bar_reaches_the_end_and_settling_run_shows_time() {
        let b = Bar::new(Stop::EndTime(2.0), ProgressDrawTarget::hidden());
        assert_eq!(b.bar.message(), "0.000");
        b.show(1.0);
        assert_eq!(b.bar.position(), LENGTH / 2);
        b.show(2.0);
        assert_eq!(b.bar.position(), LENGTH);
        assert_eq!(b.bar.message(), "2.000");

        let stop = Stop::Settled { fraction: 1e-4, window_s: 1.0, max_time_s: 100.0 };
        let b = Bar::new(stop, ProgressDrawTarget::hidden());
        assert_eq!(b.bar.message(), "0.000");
        b.show(28.0);
        assert_eq!(b.bar.message(), "28.000");
        assert_eq!(b.bar.position(), 0, "a settling run is not scaled to its limit");
    }
}
