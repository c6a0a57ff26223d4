//! The sag-tension problem and its change of state: a stringing condition fixes the conductor's
//! unstressed length `L0`; every other condition then solves its span for `H` with the same `L0` and the
//! history of the state asked for (Aluminum Association / Winkelman graphic method; Douglass and Thrash,
//! Electric Power Engineering Handbook ch. 14; IEEE Std 1283 and CIGRE TB 324 for the states):
//!
//! - INITIAL: as strung, the virgin loading curves ([`TwoMaterial::virgin`] on the initial curves);
//! - AFTER CREEP: the creep stretch condition (default: the stringing temperature, bare; the published
//!   10-year creep at the everyday condition) solved on the creep curves; each component keeps the
//!   largest mechanical strain it reached there, and every other condition unloads from it along the
//!   final modulus ([`crate::conductor::component`]); a short-term load beyond the creep stretch follows
//!   the initial curve again, from where the unloading line meets it
//!   ([`TwoMaterial::creep_history_on_initial`]);
//! - AFTER LOAD: the heavy load condition solved on the initial curves, the largest strains kept;
//! - FINAL: whichever of the two leaves the conductor longer, i.e. gives the lower `H` (larger sag) at the
//!   stringing condition's weather ("the state with the larger sag increase", Douglass and Thrash); with
//!   only one stretch condition given, that one; with none, INITIAL.
//!
//! The largest strain of a stretch is one number for the whole span ([`StretchPoint`]): by default the
//! conductor strain at the support with the larger tension, the most strained point of the span (`T` is
//! largest there and `e(T)` increasing): the permanent set of the span is then that of its most loaded
//! point, a conservative (longer) summary of a set that in truth varies along the span with the
//! tension. OTLS-Models uses the strain at the span's average tension instead
//! (`LineCableLoaderBase::UpdateConstraintCableModel`, the reloaded catenary's `TensionAverage`):
//! [`StretchPoint::AverageTension`]; docs/sagtension.md compares the two on reference D.
//!
//! A stringing condition in a stretched state (the tension wanted "final") is met by the same root on
//! `L0`: the history then depends on `L0`, and the root finder sees the whole chain.

use super::catenary::{DEFAULT_PANELS, SpanLaw, SpanSolution};
use super::row::Row;
use super::search::illinois;
use super::{SagConductor, SagTensionError, Span, Weather};
use crate::conductor::{CurveKind, History, TwoMaterial};

/// What the stringing condition fixes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StringingTarget {
    /// the horizontal tension `H` [N]
    HorizontalTension(f64),
    /// the mid-span sag below the chord [m] ([`Row::sag_midspan_m`])
    Sag(f64),
}

/// A state of the conductor (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum State {
    /// as strung (virgin curves)
    Initial,
    /// after the creep stretch
    AfterCreep,
    /// after the heavy load stretch
    AfterLoad,
    /// the longer of after creep and after load
    Final,
}

impl State {
    /// The state's name in tables: `initial`, `after_creep`, `after_load`, `final`.
    pub fn name(self) -> &'static str {
        match self {
            State::Initial => "initial",
            State::AfterCreep => "after_creep",
            State::AfterLoad => "after_load",
            State::Final => "final",
        }
    }
}

/// The stringing condition: `target` at `weather` in `state`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stringing {
    /// what is fixed
    pub target: StringingTarget,
    /// the weather at which it holds
    pub weather: Weather,
    /// the state in which it holds (usually [`State::Initial`])
    pub state: State,
}

/// Where along the span a stretch condition sets the components' largest strains (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StretchPoint {
    /// at the support with the larger tension (the most strained point)
    #[default]
    MostStrained,
    /// at the length-averaged tension of the span (OTLS-Models; SAG10-type programs)
    AverageTension,
}

/// A sag-tension problem (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Problem {
    /// the conductor
    pub conductor: SagConductor,
    /// the span (or ruling span, [`Span::ruling`])
    pub span: Span,
    /// the stringing condition
    pub stringing: Stringing,
    /// the creep stretch condition (`None`: no creep state)
    pub creep: Option<Weather>,
    /// the heavy load stretch condition (`None`: no after-load state)
    pub heavy_load: Option<Weather>,
    /// gravity `g` [m/s^2] ([`super::STANDARD_GRAVITY_M_PER_S2`])
    pub gravity_m_per_s2: f64,
    /// where a stretch sets the largest strains ([`StretchPoint::MostStrained`] by default)
    pub stretch_point: StretchPoint,
}

/// A strung conductor: the problem with its unstressed length and the states' histories.
#[derive(Clone, Debug, PartialEq)]
pub struct Strung {
    /// the problem
    pub problem: Problem,
    /// unstressed length `L0` [m] at the law's reference temperature
    pub unstressed_length_m: f64,
    /// histories of the initial, after-creep and after-load states
    pub histories: Histories,
}

/// The histories of the states for one `L0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Histories {
    /// initial (virgin initial curves)
    pub initial: History,
    /// after the creep stretch, if a creep condition is given
    pub after_creep: Option<History>,
    /// after the heavy load stretch, if one is given
    pub after_load: Option<History>,
    /// the state FINAL stands for
    pub final_is: State,
}

impl Problem {
    fn law(&self) -> &TwoMaterial {
        &self.conductor.law
    }

    /// The checks every problem passes before it is solved.
    pub fn validate(&self) -> Result<(), SagTensionError> {
        use SagTensionError::Invalid;
        self.span.validate()?;
        self.stringing.weather.validate()?;
        for w in self.creep.iter().chain(self.heavy_load.iter()) {
            w.validate()?;
        }
        let c = &self.conductor;
        let law = &c.law;
        let core = law.core.as_ref();
        for (what, value) in [
            ("conductor diameter [m]", c.diameter_m),
            ("conductor mass per length [kg/m]", c.mass_kg_per_m),
            ("gravity [m/s^2]", self.gravity_m_per_s2),
            ("law reference temperature [K]", law.reference_temperature_k),
            ("outer layers' area [m^2]", law.outer.area_m2),
            ("outer layers' unloading stiffness [N]", law.outer.unloading_stiffness_n),
            ("core area [m^2]", core.map_or(1.0, |k| k.area_m2)),
            ("core unloading stiffness [N]", core.map_or(1.0, |k| k.unloading_stiffness_n)),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(Invalid { what, value, allowed: "finite and > 0" });
            }
        }
        for (what, value) in [
            ("outer layers' expansion coefficient [1/K]", law.outer.expansion_per_k),
            ("outer layers' compression stiffness [N]", law.outer.compression_stiffness_n),
            ("core expansion coefficient [1/K]", core.map_or(0.0, |k| k.expansion_per_k)),
            ("core compression stiffness [N]", core.map_or(0.0, |k| k.compression_stiffness_n)),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(Invalid { what, value, allowed: "finite and >= 0" });
            }
        }
        let (what, value) = match self.stringing.target {
            StringingTarget::HorizontalTension(h) => ("stringing horizontal tension [N]", h),
            StringingTarget::Sag(s) => ("stringing sag [m]", s),
        };
        if !(value.is_finite() && value > 0.0) {
            return Err(Invalid { what, value, allowed: "finite and > 0" });
        }
        match self.stringing.state {
            State::AfterCreep if self.creep.is_none() => Err(SagTensionError::MissingStretch("after_creep")),
            State::AfterLoad if self.heavy_load.is_none() => Err(SagTensionError::MissingStretch("after_load")),
            _ => Ok(()),
        }
    }

    /// The span's quadrature data at `weather` with `history` and `l0` [m]: the load plane's span and
    /// rise (the chord projected normal to and along the resultant load, [`super::weather`]).
    pub(crate) fn span_law(&self, weather: &Weather, history: History, l0: f64) -> SpanLaw<'_> {
        let c = &self.conductor;
        let ice = crate::loads::RadialIce {
            thickness_m: weather.ice_thickness_m,
            density_kg_per_m3: weather.ice_density_kg_per_m3,
        };
        let wv = (c.mass_kg_per_m + ice.kg_per_m(c.diameter_m)) * self.gravity_m_per_s2;
        let wh = weather.wind_pressure_pa * ice.iced_diameter_m(c.diameter_m);
        let (l, h) = (self.span.length_m, self.span.rise_m);
        let rise = h * wv / wv.hypot(wh);
        let span = (l * l + h * h - rise * rise).max(0.0).sqrt();
        SpanLaw {
            law: self.law(),
            history,
            temperature_k: weather.temperature_k,
            load_n_per_m: weather.load_n_per_m(c, self.gravity_m_per_s2),
            span_m: span,
            rise_m: rise,
            unstressed_length_m: l0,
            panels: DEFAULT_PANELS,
        }
    }

    /// The stretched history after loading a span of `l0` [m] at `weather`, from `start`.
    fn stretch(&self, weather: &Weather, start: History, l0: f64) -> Result<History, SagTensionError> {
        let span = self.span_law(weather, start, l0);
        let sol = span.solve()?;
        let t = match self.stretch_point {
            StretchPoint::MostStrained => span.tension_at(0.0, sol.hv()).max(span.tension_at(l0, sol.hv())),
            StretchPoint::AverageTension => span.means(sol.hv())?.0[0],
        };
        let e = span.strain(t)?;
        let mut h = start;
        self.law().load(e, weather.temperature_k, &mut h);
        Ok(h)
    }

    /// The histories of the states for the unstressed length `l0` [m] (module doc).
    pub fn histories(&self, l0: f64) -> Result<Histories, SagTensionError> {
        let law = self.law();
        let initial = law.virgin(CurveKind::Initial);
        let after_creep = match &self.creep {
            Some(w) => Some(law.creep_history_on_initial(&self.stretch(w, law.virgin(CurveKind::Creep), l0)?)),
            None => None,
        };
        let after_load = match &self.heavy_load {
            Some(w) => Some(self.stretch(w, initial, l0)?),
            None => None,
        };
        let final_is = match (after_creep, after_load) {
            (Some(c), Some(l)) => {
                let w = &self.stringing.weather;
                let hc = self.span_law(w, c, l0).solve()?.horizontal_tension_n;
                let hl = self.span_law(w, l, l0).solve()?.horizontal_tension_n;
                if hc < hl { State::AfterCreep } else { State::AfterLoad }
            }
            (Some(_), None) => State::AfterCreep,
            (None, Some(_)) => State::AfterLoad,
            (None, None) => State::Initial,
        };
        Ok(Histories { initial, after_creep, after_load, final_is })
    }

    /// The span solved at `weather` in `state` for `l0` [m] with `histories`.
    fn solve_with(
        &self,
        weather: &Weather,
        state: State,
        l0: f64,
        histories: &Histories,
    ) -> Result<(SpanLaw<'_>, SpanSolution, State), SagTensionError> {
        let (h, is) = histories.get(state)?;
        let span = self.span_law(weather, h, l0);
        let sol = span.solve()?;
        Ok((span, sol, is))
    }

    /// The stringing target's value [N or m] for `l0` [m].
    fn stringing_value(&self, l0: f64) -> Result<f64, SagTensionError> {
        let hist = self.histories(l0)?;
        let (span, sol, _) = self.solve_with(&self.stringing.weather, self.stringing.state, l0, &hist)?;
        match self.stringing.target {
            StringingTarget::HorizontalTension(_) => Ok(sol.horizontal_tension_n),
            StringingTarget::Sag(_) => span.sag_at_x(0.5 * span.span_m, sol.hv()),
        }
    }

    /// Strings the conductor: finds `L0` from the stringing condition (a root on `L0`: `H` falls and
    /// the sag grows with `L0`) and the states' histories.
    pub fn string(&self) -> Result<Strung, SagTensionError> {
        self.validate()?;
        let (target, sign) = match self.stringing.target {
            StringingTarget::HorizontalTension(h) => (h, -1.0),
            StringingTarget::Sag(s) => (s, 1.0),
        };
        // f(L0) = sign (value - target) increases with L0.
        let f = |l0: f64| self.stringing_value(l0).map(|v| sign * (v - target) / target);
        let l0 = root_on_length(self.span.length_m.hypot(self.span.rise_m), f, "stringing condition")?;
        Ok(Strung { problem: *self, unstressed_length_m: l0, histories: self.histories(l0)? })
    }
}

/// The root of `f(L0)`, increasing in `L0`, bracketed from `chord (1 -+ 0.002)` outwards (down to half the
/// chord, up to three times it), to `1e-14` of the chord.
fn root_on_length<F>(chord: f64, mut f: F, what: &'static str) -> Result<f64, SagTensionError>
where
    F: FnMut(f64) -> Result<f64, SagTensionError>,
{
    let (mut lo, mut hi) = (chord * (1.0 - 2e-3), chord * (1.0 + 2e-3));
    let mut f_lo = f(lo)?;
    while f_lo > 0.0 {
        lo = chord - 2.0 * (chord - lo);
        if lo < 0.5 * chord {
            return Err(SagTensionError::NoSolution {
                what,
                detail: format!("not reached by any length between 0.5 and 1 times the chord {chord} m"),
            });
        }
        f_lo = f(lo)?;
    }
    let mut f_hi = f(hi)?;
    while f_hi < 0.0 {
        hi = chord + 2.0 * (hi - chord);
        if hi > 3.0 * chord {
            return Err(SagTensionError::NoSolution {
                what,
                detail: format!("not reached by any length between 1 and 3 times the chord {chord} m"),
            });
        }
        f_hi = f(hi)?;
    }
    illinois(f, lo, hi, f_lo, f_hi, 1e-14 * chord)
}

impl Histories {
    /// The history of `state` and the state it stands for (FINAL: the governing one).
    pub fn get(&self, state: State) -> Result<(History, State), SagTensionError> {
        match state {
            State::Initial => Ok((self.initial, State::Initial)),
            State::AfterCreep => {
                self.after_creep.map(|h| (h, State::AfterCreep)).ok_or(SagTensionError::MissingStretch("after_creep"))
            }
            State::AfterLoad => {
                self.after_load.map(|h| (h, State::AfterLoad)).ok_or(SagTensionError::MissingStretch("after_load"))
            }
            State::Final => self.get(self.final_is),
        }
    }
}

impl Strung {
    /// The table row of `weather` in `state` ([`Row`]).
    pub fn solve(&self, weather: &Weather, state: State) -> Result<Row, SagTensionError> {
        weather.validate()?;
        let p = &self.problem;
        let (span, sol, is) = p.solve_with(weather, state, self.unstressed_length_m, &self.histories)?;
        Row::new(p, weather, state, is, &span, &sol)
    }

    /// The row of another span `span` of the section whose ruling span this is, at `weather` in `state`:
    /// the span that carries the ruling span's horizontal tension there ([`super::span`]: the section's
    /// strings equalise `H`), with the state's history. Its unstressed length is found by a root on `L0`
    /// (`H` falls with it).
    pub fn section_span(&self, weather: &Weather, state: State, span: Span) -> Result<Row, SagTensionError> {
        span.validate()?;
        let target = self.solve(weather, state)?.horizontal_tension_n;
        let p = Problem { span, ..self.problem };
        let (history, is) = self.histories.get(state)?;
        let f = |l0: f64| p.span_law(weather, history, l0).solve().map(|s| (target - s.horizontal_tension_n) / target);
        let l0 = root_on_length(span.length_m.hypot(span.rise_m), f, "span of the section at the ruling span's H")?;
        let law = p.span_law(weather, history, l0);
        let sol = law.solve()?;
        Row::new(&p, weather, state, is, &law, &sol)
    }

    /// The states a table holds: initial, then after creep and after load where given, then final.
    pub fn states(&self) -> Vec<State> {
        let mut s = vec![State::Initial];
        if self.histories.after_creep.is_some() {
            s.push(State::AfterCreep);
        }
        if self.histories.after_load.is_some() {
            s.push(State::AfterLoad);
        }
        s.push(State::Final);
        s
    }
}
