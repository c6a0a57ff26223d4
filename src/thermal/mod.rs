//! Conductor temperature from current and weather: the steady heat balance per unit length
//!
//! ```text
//! q_J(T) + q_S = q_c(T) + q_r(T)        [W/m],   and in time   m c dT/dt = q_J + q_S - q_c - q_r,
//! ```
//!
//! (Joule heating, solar heating, convective and radiative cooling) as the two standards write it:
//! IEEE Std 738-2012 ([`ieee738`]) and CIGRE Technical Brochure 601 (2014) ([`cigre601`]). Each term is
//! one file with its equation and source; the terms the standards share (Joule heating with the AC
//! resistance interpolated linearly between two reference temperatures, radiative cooling) are at this
//! level. Everything is in SI units and kelvin at the interfaces; the standards' own units (degrees
//! Celsius inside the correlations, W/m) are the modules' business.
//!
//! Layout: [`conductor`] (the thermal data of a conductor), [`weather`] (the ambient conditions),
//! [`joule`], [`radiation`], [`ieee738`] and [`cigre601`] (their convection, solar heating and air
//! properties), and the [`HeatBalance`] trait that the steady-state and transient solvers use.

pub mod catalog;
pub mod cigre601;
pub mod conductor;
pub mod deicing;
pub mod examples;
pub mod ieee738;
pub mod joule;
pub mod ode;
pub mod radiation;
pub mod steady;
pub mod transient;
pub mod weather;

pub use conductor::ThermalConductor;
pub use weather::Weather;

/// The terms of the heat balance per unit length of conductor [W/m]. Heating terms are non-negative; the
/// cooling terms are signed (negative when the conductor is colder than the air, so that a transient
/// warms a cold conductor).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HeatTerms {
    /// Joule (resistive) heating `q_J = I^2 R(T)` [W/m]
    pub joule_w_per_m: f64,
    /// solar heating `q_S` [W/m]
    pub solar_w_per_m: f64,
    /// convective cooling `q_c` [W/m]
    pub convection_w_per_m: f64,
    /// radiative cooling `q_r` [W/m]
    pub radiation_w_per_m: f64,
}

impl HeatTerms {
    /// Net heating `q_J + q_S - q_c - q_r` [W/m]: zero in steady state, `m c dT/dt` in a transient.
    pub fn net_w_per_m(&self) -> f64 {
        self.joule_w_per_m + self.solar_w_per_m - self.convection_w_per_m - self.radiation_w_per_m
    }
}

/// A heat-balance model of one standard for one conductor in one weather: the terms at a conductor
/// (surface) temperature and a current.
pub trait HeatBalance {
    /// The heat-balance terms [W/m] at conductor temperature `temperature_k` [K] carrying the RMS current
    /// `current_a` [A].
    fn terms(&self, temperature_k: f64, current_a: f64) -> HeatTerms;

    /// The conductor's heat capacity per unit length `m c = sum_k m_k c_k(T)` [J/(m K)] at the conductor
    /// temperature `temperature_k` [K] (for transients; [`ThermalConductor::heat_capacity_at_j_per_m_k`]).
    fn heat_capacity_j_per_m_k(&self, temperature_k: f64) -> f64;

    /// The ambient air temperature `T_a` [K] (the conductor's temperature without current or sun).
    fn air_temperature_k(&self) -> f64;
}

/// Which standard's heat balance.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Standard {
    /// IEEE Std 738-2012 ([`ieee738::Ieee738`])
    #[default]
    Ieee738,
    /// CIGRE TB 601 (2014) ([`cigre601::Cigre601`], level span)
    Cigre601,
}

/// The heat balance of `standard` for `conductor` in `weather`.
pub fn heat_balance(
    standard: Standard,
    conductor: ThermalConductor,
    weather: Weather,
) -> Box<dyn HeatBalance + Send + Sync> {
    Box::new(Model::new(standard, conductor, weather))
}

/// The heat balance of either standard, as a value (clonable, unlike a boxed trait object).
#[derive(Clone, Debug, PartialEq)]
pub enum Model {
    /// IEEE Std 738-2012
    Ieee738(ieee738::Ieee738),
    /// CIGRE TB 601, level span
    Cigre601(cigre601::Cigre601),
}

impl Model {
    /// The heat balance of `standard` for `conductor` in `weather`.
    pub fn new(standard: Standard, conductor: ThermalConductor, weather: Weather) -> Self {
        match standard {
            Standard::Ieee738 => Model::Ieee738(ieee738::Ieee738 { conductor, weather }),
            Standard::Cigre601 => Model::Cigre601(cigre601::Cigre601::new(conductor, weather)),
        }
    }

    /// The same heat balance for a conductor inclined by `inclination_deg` [deg] to the horizontal. CIGRE TB 601
    /// lowers its natural convection with it (eq. (24), [`cigre601::convection::inclination_factor`]); IEEE Std
    /// 738 has no inclination term, so its model is returned unchanged.
    pub fn with_inclination(mut self, inclination_deg: f64) -> Self {
        if let Model::Cigre601(m) = &mut self {
            m.inclination_deg = inclination_deg;
        }
        self
    }

    fn inner(&self) -> &dyn HeatBalance {
        match self {
            Model::Ieee738(m) => m,
            Model::Cigre601(m) => m,
        }
    }
}

impl HeatBalance for Model {
    fn terms(&self, temperature_k: f64, current_a: f64) -> HeatTerms {
        self.inner().terms(temperature_k, current_a)
    }

    fn heat_capacity_j_per_m_k(&self, temperature_k: f64) -> f64 {
        self.inner().heat_capacity_j_per_m_k(temperature_k)
    }

    fn air_temperature_k(&self) -> f64 {
        self.inner().air_temperature_k()
    }
}
