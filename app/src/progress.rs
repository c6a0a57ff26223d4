//! The terminal progress bar of `ohl run`, driven by the library's run hook ([`ohl::run::Progress`]).
//!
//! A run to a fixed end time shows a bar that fills to 100 % at the end time. A run that stops when the
//! wire has settled has no known end (its `max_time_s` is only a limit, and a settled run typically stops
//! well before it), so it shows a spinner with the simulated time and "at most MAX s, stops when
//! settled" instead of a bar scaled to the limit. The message (the simulated time) is set before the
//! first frame is drawn.

use std::io::IsTerminal;
use std::sync::Arc;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use ohl::run::Progress;
use ohl::scenario::Plan;
use ohl::scenario::build::Stop;

/// Steps of the bar for a run to a fixed end time.
const LENGTH: u64 = 1000;

/// A progress bar (or spinner) for one run.
pub struct Bar {
    bar: ProgressBar,
    settling: bool,
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
        Bar { bar, settling }
    }

    /// The hook to put in [`ohl::run::RunOptions::progress`].
    pub fn hook(&self) -> Progress {
        let bar = self.bar.clone();
        let settling = self.settling;
        Arc::new(move |t, horizon| {
            bar.set_message(format!("{t:.3}"));
            if !settling && horizon > 0.0 {
                bar.set_position(((LENGTH as f64 * t / horizon) as u64).min(LENGTH));
            }
        })
    }

    /// Remove the bar once the run has ended.
    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_time_bar_reaches_the_end_and_settling_run_shows_time() {
        let b = Bar::new(Stop::EndTime(2.0), ProgressDrawTarget::hidden());
        assert_eq!(b.bar.message(), "0.000");
        let h = b.hook();
        h(1.0, 2.0);
        assert_eq!(b.bar.position(), LENGTH / 2);
        h(2.0, 2.0);
        assert_eq!(b.bar.position(), LENGTH);
        assert_eq!(b.bar.message(), "2.000");
        b.finish();

        let stop = Stop::Settled { fraction: 1e-4, window_s: 1.0, max_time_s: 100.0 };
        let b = Bar::new(stop, ProgressDrawTarget::hidden());
        assert_eq!(b.bar.message(), "0.000");
        b.hook()(28.0, 100.0);
        assert_eq!(b.bar.message(), "28.000");
        assert_eq!(b.bar.position(), 0, "a settling run is not scaled to its limit");
        b.finish();
    }
}
