//! A weather condition of a sag-tension table and the conductor it loads: the resultant load per unit
//! length of a conductor with radial ice and wind, the form of the NESC (IEEE C2, Rule 250B) and of the
//! sag-tension programs (Alcoa SAG10; Douglass and Thrash, "Sag and Tension of Conductor", Electric Power
//! Engineering Handbook ch. 14):
//!
//! ```text
//! w_v = (m + m_ice) g,   m_ice = rho_ice pi t (d + t)     ([`crate::loads::radial_ice`])
//! w_h = p (d + 2 t)                                       (wind pressure on the iced diameter)
//! w   = sqrt(w_v^2 + w_h^2) + K                           (NESC constant K along the resultant)
//! ```
//!
//! The load acts per unit unstressed length (the ice and the wind are per metre of conductor; the
//! difference from per stretched metre is the strain, below 0.3 %, and the published programs make the
//! same choice). The span lies in the plane of the resultant: with wind, sag is measured in that
//! (swung) plane.

use crate::conductor::TwoMaterial;
use crate::loads::RadialIce;

/// Standard gravity [m/s^2] (CGPM 1901, the value that defines the pound-force): a weight published in
/// lb/ft converts to N/m exactly with it.
pub const STANDARD_GRAVITY_M_PER_S2: f64 = 9.80665;

/// A conductor for sag-tension: its axial law and what loads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SagConductor {
    /// the axial law of its materials (the reference length: unstressed at the law's reference
    /// temperature)
    pub law: TwoMaterial,
    /// outer diameter `d` [m]
    pub diameter_m: f64,
    /// mass per unit length `m` [kg/m]
    pub mass_kg_per_m: f64,
    /// rated tensile strength [N] (reported as a percentage; not a limit of the solver)
    pub rated_tensile_strength_n: f64,
}

impl SagConductor {
    /// A catalogue conductor with its stress-strain data (`None`: the entry has none;
    /// [`crate::thermal::catalog::CatalogConductor::two_material`]).
    pub fn from_catalog(c: &crate::thermal::catalog::CatalogConductor) -> Option<SagConductor> {
        Some(SagConductor {
            law: c.two_material()?,
            diameter_m: c.diameter_m,
            mass_kg_per_m: c.linear_density_kg_per_m,
            rated_tensile_strength_n: c.rated_tensile_strength_n,
        })
    }
}

/// One weather condition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weather {
    /// conductor temperature `theta` [K]
    pub temperature_k: f64,
    /// radial ice thickness `t` [m] (0: bare)
    pub ice_thickness_m: f64,
    /// ice density `rho_ice` [kg/m^3] (NESC: 913, [`crate::loads::codes::NESC_ICE_DENSITY_KG_PER_M3`])
    pub ice_density_kg_per_m3: f64,
    /// wind pressure `p` [Pa] on the projected iced diameter (drag coefficient included, as the codes
    /// state it; 0: still air)
    pub wind_pressure_pa: f64,
    /// constant `K` [N/m] added to the resultant (NESC Rule 250B, Table 251-1; 0 elsewhere)
    pub constant_n_per_m: f64,
}

impl Weather {
    /// A bare conductor in still air at `temperature_k` [K].
    pub fn bare(temperature_k: f64) -> Weather {
        Weather {
            temperature_k,
            ice_thickness_m: 0.0,
            ice_density_kg_per_m3: 0.0,
            wind_pressure_pa: 0.0,
            constant_n_per_m: 0.0,
        }
    }

    /// The resultant load `w` [N/m] per unit length on `conductor` under gravity `g` [m/s^2] (module doc).
    pub fn load_n_per_m(&self, conductor: &SagConductor, gravity_m_per_s2: f64) -> f64 {
        let ice = RadialIce { thickness_m: self.ice_thickness_m, density_kg_per_m3: self.ice_density_kg_per_m3 };
        let d = conductor.diameter_m;
        let vertical = (conductor.mass_kg_per_m + ice.kg_per_m(d)) * gravity_m_per_s2;
        let horizontal = self.wind_pressure_pa * ice.iced_diameter_m(d);
        vertical.hypot(horizontal) + self.constant_n_per_m
    }

    /// The checks every weather passes: finite, temperature > 0 K, ice, density, wind and `K` >= 0.
    pub fn validate(&self) -> Result<(), super::SagTensionError> {
        use super::SagTensionError::Invalid;
        let checks = [
            ("weather temperature [K]", self.temperature_k, self.temperature_k > 0.0, "> 0"),
            ("radial ice thickness [m]", self.ice_thickness_m, self.ice_thickness_m >= 0.0, ">= 0"),
            ("ice density [kg/m^3]", self.ice_density_kg_per_m3, self.ice_density_kg_per_m3 >= 0.0, ">= 0"),
            ("wind pressure [Pa]", self.wind_pressure_pa, self.wind_pressure_pa >= 0.0, ">= 0"),
            ("load constant K [N/m]", self.constant_n_per_m, self.constant_n_per_m >= 0.0, ">= 0"),
        ];
        for (what, value, ok, allowed) in checks {
            if !(value.is_finite() && ok) {
                return Err(Invalid { what, value, allowed });
            }
        }
        Ok(())
    }
}
