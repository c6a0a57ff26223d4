//! The progress display of `ohl run`: an observer of the run loop that draws a bar on a terminal
//! (nothing without one). A run to an end time shows the fraction of it; a run until settled has no
//! known end, so it shows the simulated time against its cap and jumps to 100 % when it settles.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};
use ohl::run::{Control, Ending, Level, Observer, OutputError};
use ohl::scenario::build::Stop;

/// Draws progress at most every `1/1000` of the horizon.
pub struct Progress {
    bar: Option<ProgressBar>,
    horizon_s: f64,
    next_s: f64,
}

impl Progress {
    /// A bar for a run that stops as `stop` says; drawn only when stderr is a terminal.
    pub fn new(stop: Stop) -> Self {
        let horizon_s = stop.horizon_s();
        let bar = std::io::stderr().is_terminal().then(|| {
            let template = match stop {
                Stop::EndTime(_) => "{bar:40} {percent:>3}% t = {msg} s, eta {eta}".to_string(),
                Stop::Settled { .. } => {
                    format!("{{bar:40}} t = {{msg}} s of at most {horizon_s} s (stops when settled), {{elapsed}}")
                }
            };
            let b = ProgressBar::hidden();
            b.set_length(1000);
            b.set_style(ProgressStyle::with_template(&template).expect("static template"));
            b.set_message("0.000");
            b.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            b
        });
        Progress { bar, horizon_s, next_s: 0.0 }
    }
}

impl Observer for Progress {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        if let Some(b) = &self.bar
            && level.t_s >= self.next_s
        {
            b.set_position((1000.0 * level.t_s / self.horizon_s) as u64);
            b.set_message(format!("{:.3}", level.t_s));
            self.next_s = level.t_s + 1.0e-3 * self.horizon_s;
        }
        Ok(Control::Continue)
    }

    fn finish(&mut self, level: &Level, _ending: &Ending) -> Result<(), OutputError> {
        if let Some(b) = self.bar.take() {
            b.set_message(format!("{:.3}", level.t_s));
            b.set_position(1000);
            b.finish_and_clear();
        }
        Ok(())
    }
}
