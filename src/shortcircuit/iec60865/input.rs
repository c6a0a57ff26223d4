//! The input of the IEC 60865-1 simplified method for one span of flexible conductors (SI units) and its
//! validation against the physical range and the range of validity the method states.

use super::error::Iec60865Error;

/// The short circuit that loads the span.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fault {
    /// Three-phase short circuit, initial symmetrical current `I''k3` [A] r.m.s. (eq. (19a): factor 0.75,
    /// the force on the centre phase of a flat arrangement).
    ThreePhase {
        /// `I''k3` [A]
        current_a: f64,
    },
    /// Line-to-line short circuit, initial symmetrical current `I''k2` [A] r.m.s.
    LineToLine {
        /// `I''k2` [A]
        current_a: f64,
    },
}

impl Fault {
    /// The r.m.s. current [A].
    pub fn current_a(&self) -> f64 {
        match *self {
            Fault::ThreePhase { current_a } | Fault::LineToLine { current_a } => current_a,
        }
    }
}

/// How the span is held (clause 6.2.2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mounting {
    /// Slack conductors on support insulators: `l_c = l`; `b_h` by eq. (44).
    Slack,
    /// Strained conductors with a tension insulator chain at each end: `l_c = l - 2 l_i`; `b_h` by eq. (45).
    Strained {
        /// `l_i`, length of one tension insulator chain [m]
        insulator_chain_length_m: f64,
    },
}

/// Sub-conductor bundle data, needed for the pinch force (clause 6.4) when `n >= 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bundle {
    /// `a_s`, effective distance between sub-conductors [m] (centre to centre)
    pub subconductor_distance_m: f64,
    /// `l_s`, mean distance between two adjacent spacers (or spacer and support) [m]
    pub spacer_distance_m: f64,
    /// `f`, system frequency [Hz] (pinch, Annex A.7)
    pub frequency_hz: f64,
    /// `kappa`, peak factor of the short-circuit current (IEC 60909-0), in (1.02, 2) [-] (pinch, Annex A.7)
    pub peak_factor: f64,
}

/// One span and its short circuit, SI units (symbols of IEC 60865-1:2011).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Input {
    /// `l`, centre-line distance between supports (span) [m]
    pub span_m: f64,
    /// `a`, centre-line distance between main conductors (phase distance) [m]
    pub phase_distance_m: f64,
    /// slack or strained, with `l_i` [m]
    pub mounting: Mounting,
    /// `n`, number of sub-conductors of a main conductor [-]
    pub subconductors: u32,
    /// `m'_s`, mass per unit length of one sub-conductor [kg/m]
    pub mass_per_length_kg_per_m: f64,
    /// `m_c`, sum of the concentrated masses in the span (spacers, clamps, droppers) [kg]; distributed
    /// over the conductor length as `m'_s + m_c / (n l_c)` (the practice of IEC TR 60865-2, example 8,
    /// as transcribed: 3.2482 kg/m + 74 kg / (2 * 37.4 m) = 4.24 kg/m)
    pub concentrated_mass_kg: f64,
    /// `A_s`, cross-section of one sub-conductor [m^2]
    pub area_m2: f64,
    /// `E`, Young's modulus of the conductor [Pa]
    pub young_modulus_pa: f64,
    /// `d`, outer diameter of one sub-conductor [m]
    pub diameter_m: f64,
    /// `F_st`, static tensile force in one main conductor (all sub-conductors) [N]
    pub static_tension_n: f64,
    /// `S`, resultant spring constant of both supports of the span [N/m]
    pub spring_constant_n_per_m: f64,
    /// the short circuit, `I''k3` or `I''k2` [A]
    pub fault: Fault,
    /// `T_k1`, duration of the first short-circuit current flow [s]
    pub first_duration_s: f64,
    /// `c_th`, material constant of the thermal expansion [m^4/(A^2 s)]; IEC 60865-1 gives 0.27e-18 for
    /// Al, Al alloy and Al/St with section ratio > 6, 0.17e-18 for Al/St with ratio <= 6, 0.088e-18 for Cu
    /// (the 0.27e-18 value as used for the TR 60865-2 examples by Kalandoros/Kurzschlussfestigkeit; the 0.17e-18
    /// and 0.088e-18 values are from memory, not confirmed in a public source)
    pub thermal_constant_m4_per_a2s: f64,
    /// `g_n` [m/s^2]; the standard's value is [`super::G_N`] = 9.81
    pub gravity_m_per_s2: f64,
    /// sub-conductor geometry, required when `subconductors >= 2`
    pub bundle: Option<Bundle>,
}

/// Span limit of the method [m]: "spans up to about 120 m" (IEC 60865-1:2011, clause 6.2.1, as stated by
/// the documentation of Kalandoros/Kurzschlussfestigkeit; the 1993 edition: 60 m, Meyer et al. 1994).
/// Not confirmed against the standard's own text.
pub const MAX_SPAN_M: f64 = 120.0;

/// Sag limit of the method, `b_c / l <= 8 %` (same source and caveat as [`MAX_SPAN_M`]).
pub const MAX_SAG_RATIO: f64 = 0.08;

fn positive(field: &'static str, value: f64) -> Result<(), Iec60865Error> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(Iec60865Error::OutOfRange { field, value, range: "a finite number > 0" })
    }
}

impl Input {
    /// `l_c`, conductor length of a main conductor in the span [m].
    pub fn conductor_length_m(&self) -> f64 {
        match self.mounting {
            Mounting::Slack => self.span_m,
            Mounting::Strained { insulator_chain_length_m } => self.span_m - 2.0 * insulator_chain_length_m,
        }
    }

    /// `m'_s` with the concentrated masses spread over `n l_c` [kg/m].
    pub fn effective_mass_per_length_kg_per_m(&self) -> f64 {
        let n = f64::from(self.subconductors);
        self.mass_per_length_kg_per_m + self.concentrated_mass_kg / (n * self.conductor_length_m())
    }

    /// Every field in its physical range and the span in the method's range; the first violation.
    pub fn validate(&self) -> Result<(), Iec60865Error> {
        positive("span_m", self.span_m)?;
        positive("phase_distance_m", self.phase_distance_m)?;
        if let Mounting::Strained { insulator_chain_length_m } = self.mounting {
            positive("insulator_chain_length_m", insulator_chain_length_m)?;
            if 2.0 * insulator_chain_length_m >= self.span_m {
                return Err(Iec60865Error::OutOfRange {
                    field: "insulator_chain_length_m",
                    value: insulator_chain_length_m,
                    range: "< span_m / 2 (l_c = l - 2 l_i > 0)",
                });
            }
        }
        if self.subconductors == 0 {
            return Err(Iec60865Error::OutOfRange { field: "subconductors", value: 0.0, range: "an integer >= 1" });
        }
        positive("mass_per_length_kg_per_m", self.mass_per_length_kg_per_m)?;
        if !(self.concentrated_mass_kg.is_finite() && self.concentrated_mass_kg >= 0.0) {
            return Err(Iec60865Error::OutOfRange {
                field: "concentrated_mass_kg",
                value: self.concentrated_mass_kg,
                range: "a finite number >= 0",
            });
        }
        positive("area_m2", self.area_m2)?;
        positive("young_modulus_pa", self.young_modulus_pa)?;
        positive("diameter_m", self.diameter_m)?;
        if self.diameter_m >= self.phase_distance_m {
            return Err(Iec60865Error::OutOfRange {
                field: "diameter_m",
                value: self.diameter_m,
                range: "< phase_distance_m",
            });
        }
        positive("static_tension_n", self.static_tension_n)?;
        positive("spring_constant_n_per_m", self.spring_constant_n_per_m)?;
        positive("current_a", self.fault.current_a())?;
        positive("first_duration_s", self.first_duration_s)?;
        positive("thermal_constant_m4_per_a2s", self.thermal_constant_m4_per_a2s)?;
        positive("gravity_m_per_s2", self.gravity_m_per_s2)?;
        if self.subconductors >= 2 {
            let Some(b) = self.bundle else {
                return Err(Iec60865Error::MissingBundle { subconductors: self.subconductors });
            };
            positive("subconductor_distance_m", b.subconductor_distance_m)?;
            positive("spacer_distance_m", b.spacer_distance_m)?;
            positive("frequency_hz", b.frequency_hz)?;
            if !(b.peak_factor > 1.02 && b.peak_factor < 2.0) {
                return Err(Iec60865Error::OutOfRange {
                    field: "peak_factor",
                    value: b.peak_factor,
                    range: "1.02 < kappa < 2 (IEC 60909-0: kappa = 1.02 + 0.98 exp(-3 R/X))",
                });
            }
            if b.subconductor_distance_m <= self.diameter_m {
                return Err(Iec60865Error::OutOfRange {
                    field: "subconductor_distance_m",
                    value: b.subconductor_distance_m,
                    range: "> diameter_m",
                });
            }
        }
        if self.span_m > MAX_SPAN_M {
            return Err(Iec60865Error::OutsideMethod {
                quantity: "span_m",
                value: self.span_m,
                limit: "<= 120 m (clause 6.2.1)",
            });
        }
        Ok(())
    }
}
