//! Radial ice: a concentric cylindrical shell of thickness `t` [m] and density `rho_ice` [kg/m^3] on a
//! conductor of diameter `d` [m], the form in which IEC 60826, EN 50341-1 and the NESC (Rule 250B) give
//! ice. Per metre of conductor the shell's cross-section is `pi ((d + 2 t)^2 - d^2) / 4 = pi t (d + t)`, so
//!
//! ```text
//! mass per unit length   m_ice = rho_ice pi t (d + t)        [kg/m]
//! iced diameter          D = d + 2 t,   k = D / d             [-]
//! ```
//!
//! and the wind acts on `D`: the aerodynamic law (2.5), and with it its damping correction (2.6), scale
//! by `k` ([`crate::element::aero`]).

/// A radial ice shell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadialIce {
    /// radial thickness `t` [m]
    pub thickness_m: f64,
    /// density `rho_ice` [kg/m^3]
    pub density_kg_per_m3: f64,
}

impl RadialIce {
    /// Mass per unit length `rho_ice pi t (d + t)` [kg/m] on a conductor of diameter `d` [m].
    pub fn kg_per_m(&self, diameter_m: f64) -> f64 {
        let t = self.thickness_m;
        self.density_kg_per_m3 * std::f64::consts::PI * t * (diameter_m + t)
    }

    /// Iced diameter `d + 2 t` [m].
    pub fn iced_diameter_m(&self, diameter_m: f64) -> f64 {
        diameter_m + 2.0 * self.thickness_m
    }

    /// Wind diameter factor `k = (d + 2 t) / d` [-] (1 for `t = 0`).
    pub fn diameter_factor(&self, diameter_m: f64) -> f64 {
        self.iced_diameter_m(diameter_m) / diameter_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shell_mass_is_the_annulus_area_times_density() {
        // The annulus between diameters d and d + 2t, as the difference of two discs (an independent
        // formula: the two agree to rounding, 1e-15 relative).
        let d = 0.02814;
        let ice = RadialIce { thickness_m: 0.015, density_kg_per_m3: 900.0 };
        let disc = |dia: f64| std::f64::consts::PI * dia * dia / 4.0;
        let annulus = 900.0 * (disc(d + 0.03) - disc(d));
        assert!((ice.kg_per_m(d) - annulus).abs() < 1e-13 * annulus, "{} vs {annulus}", ice.kg_per_m(d));
        // The Drake shedding example's hand value (examples/mechanical/drake_inclined_350m_ice_shedding.toml).
        assert!((ice.kg_per_m(d) - 1.830).abs() < 5e-4);
        assert_eq!(ice.diameter_factor(d), (d + 0.03) / d);
        assert_eq!(RadialIce { thickness_m: 0.0, density_kg_per_m3: 913.0 }.diameter_factor(d), 1.0);
    }
}
