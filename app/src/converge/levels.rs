//! The levels of a convergence study: the scenario as written, refined (or coarsened) by a ratio `r` per
//! level, in the grid (the segments of every span and conductor times `r`, the time step following at the
//! scenario's Courant number, so `ds` and `dt` both fall by `r`) or in the time step alone (the Courant
//! number divided by `r` on the written grid, and the velocity smoothing `b` with it, so that its viscosity
//! `nu = b ds^2 / dt = b ds c / C` (paper 3.3) stays that of the written scenario and the limit is the
//! written grid's semi-discrete problem, as in the `section_transients` study).
//!
//! The smoothing's viscosity falls with `ds` only to first order under grid refinement (verification study
//! `mms`: order 0.996). `scaled_smoothing` divides `b` by the grid factor as well (`b ds / ds0`, `ds0` the
//! written grid's: `nu ~ ds^2`, order 2 in `mms`), so that the smoothing's effect vanishes at the scheme's
//! own order; the written scenario's level keeps its `b`.
//!
//! The scenario as written is the coarsest level by default: the study adds finer runs to the user's own
//! (so its finest run, whose files are written as usual, is at least as good as the one the user asked for);
//! with `coarsen` it is the finest level and the others are coarser (cheaper: the GCI is then the error
//! band of the user's own grid). Each level is validated again as a whole scenario (a refined grid can
//! exceed the segment limit, a coarsened Courant number the friction limit): a level that is no valid
//! scenario is refused with the problems and the level named.

use ohl::scenario::{InputError, Scenario};

/// What is refined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Refine {
    /// segments of every span times `r`, the time step following at a fixed Courant number
    Grid,
    /// the time step alone: the Courant number divided by `r`, the grid as written
    Step,
}

/// One level of the study.
#[derive(Clone, Debug)]
pub struct Level {
    /// `r^k` relative to the scenario as written: above 1 finer, below 1 coarser [-]
    pub factor: f64,
    /// the representative size relative to the scenario's (`1 / factor`) [-]
    pub h: f64,
    /// the scenario of this level
    pub scenario: Scenario,
}

impl Level {
    /// `x2`, `x1/4`: the level's grid relative to the scenario as written.
    pub fn label(&self) -> String {
        label(self.factor)
    }
}

/// `x2`, `x1/4`: a level's grid (or step) relative to the scenario as written, from its factor.
pub fn label(factor: f64) -> String {
    if factor >= 1.0 { format!("x{factor}") } else { format!("x1/{}", 1.0 / factor) }
}

/// A study that cannot be set up.
#[derive(Debug, thiserror::Error)]
pub enum LevelError {
    /// fewer than three levels, or a ratio below 2
    #[error("--levels {levels} --ratio {ratio}: a study needs at least 3 levels and a whole ratio of at least 2")]
    Shape {
        /// levels asked for
        levels: usize,
        /// ratio asked for
        ratio: usize,
    },
    /// coarsening a grid that does not divide
    #[error(
        "{file}: --coarsen: field `{field}` = {value} is not divisible by {divisor} with at least 2 segments left (ratio^(levels-1)); give a multiple of {divisor} or refine instead"
    )]
    Indivisible {
        /// the scenario file
        file: String,
        /// the field as written in the file
        field: String,
        /// its value
        value: usize,
        /// what it must divide by
        divisor: usize,
    },
    /// a level that is no valid scenario
    #[error("level {label} of the study ({what}) is not a valid scenario:\n{source}")]
    Invalid {
        /// the level
        label: String,
        /// what was changed
        what: String,
        /// the problems
        source: InputError,
    },
}

/// The levels, coarse to fine, of `scenario` (read from `file`).
pub fn levels(
    scenario: &Scenario,
    file: &str,
    refine: Refine,
    levels: usize,
    ratio: usize,
    coarsen: bool,
    scaled_smoothing: bool,
) -> Result<Vec<Level>, LevelError> {
    if levels < 3 || ratio < 2 {
        return Err(LevelError::Shape { levels, ratio });
    }
    let top = ratio.checked_pow(levels as u32 - 1).ok_or(LevelError::Shape { levels, ratio })?;
    if coarsen && refine == Refine::Grid {
        for (field, n) in grid_fields(scenario) {
            if !n.is_multiple_of(top) || n / top < 2 {
                return Err(LevelError::Indivisible { file: file.into(), field, value: n, divisor: top });
            }
        }
    }
    (0..levels)
        .map(|k| {
            // k = 0 the coarsest; the written scenario is k = 0 (refine) or k = levels - 1 (coarsen)
            let power = if coarsen { k as i32 - (levels as i32 - 1) } else { k as i32 };
            let factor = (ratio as f64).powi(power);
            let sc = scaled(scenario, refine, ratio, power, scaled_smoothing);
            let level = Level { factor, h: 1.0 / factor, scenario: sc };
            let problems = ohl::scenario::validate::validate(&level.scenario);
            if problems.is_empty() {
                Ok(level)
            } else {
                let what = match refine {
                    Refine::Grid => format!("segments times {}", level.label().trim_start_matches('x')),
                    Refine::Step => format!("Courant number {}", level.scenario.numerics.courant),
                };
                Err(LevelError::Invalid {
                    label: level.label(),
                    what,
                    source: InputError::Invalid { file: file.into(), problems },
                })
            }
        })
        .collect()
}

/// The grid fields the scenario gives, as written, with their values.
fn grid_fields(sc: &Scenario) -> Vec<(String, usize)> {
    let mut f = Vec::new();
    if let Some(g) = &sc.geometry {
        f.push(("geometry.segments".into(), g.segments));
    }
    if let Some(s) = &sc.section {
        if let Some(n) = s.segments_per_span {
            f.push(("section.segments_per_span".into(), n));
        }
        for (k, sp) in s.spans.iter().enumerate() {
            if let Some(n) = sp.segments {
                f.push((format!("section.spans[{k}].segments"), n));
            }
        }
    }
    f
}

/// `sc` with its grid or step scaled by `ratio^power`.
fn scaled(sc: &Scenario, refine: Refine, ratio: usize, power: i32, scaled_smoothing: bool) -> Scenario {
    let mut s = sc.clone();
    let factor = (ratio as f64).powi(power);
    let scale = |n: usize| if power >= 0 { n * ratio.pow(power as u32) } else { n / ratio.pow((-power) as u32) };
    match refine {
        Refine::Grid => {
            if let Some(g) = s.geometry.as_mut() {
                g.segments = scale(g.segments);
            }
            if let Some(sec) = s.section.as_mut() {
                sec.segments_per_span = sec.segments_per_span.map(scale);
                for sp in &mut sec.spans {
                    sp.segments = sp.segments.map(scale);
                }
            }
            if scaled_smoothing {
                s.numerics.smoothing = sc.numerics.smoothing / factor;
            }
        }
        Refine::Step => {
            s.numerics.courant = sc.numerics.courant / factor;
            s.numerics.smoothing = sc.numerics.smoothing / factor;
        }
    }
    s
}
