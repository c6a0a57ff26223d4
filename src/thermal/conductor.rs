//! The thermal data of a bare stranded conductor (IEEE Std 738-2012 section 4.4 and Annex B; CIGRE TB 601
//! section 2): geometry, AC resistance at two temperatures, surface emissivity and absorptivity, and the
//! heat capacity of its core and outer layers.

/// Thermal data of one conductor.
#[derive(Clone, Debug, PartialEq)]
pub struct ThermalConductor {
    /// name, e.g. "ACSR Drake 795 kcmil 26/7" [-]
    pub name: String,
    /// outside diameter `D` [m]
    pub diameter_m: f64,
    /// diameter of the steel core `D_c` [m] (0 for a homogeneous conductor)
    pub core_diameter_m: f64,
    /// diameter of an outer-layer strand `d` [m] (CIGRE TB 601 roughness `R_s = d / (2 (D - d))`)
    pub outer_strand_diameter_m: f64,
    /// AC resistance per unit length at the low reference temperature `R(T_low)` [ohm/m]
    pub resistance_low_ohm_per_m: f64,
    /// the low reference temperature `T_low` [K] (IEEE 738 example: 25 C)
    pub temperature_low_k: f64,
    /// AC resistance per unit length at the high reference temperature `R(T_high)` [ohm/m]
    pub resistance_high_ohm_per_m: f64,
    /// the high reference temperature `T_high` [K] (IEEE 738 example: 75 C)
    pub temperature_high_k: f64,
    /// magnetic-core factor multiplying the resistance (CIGRE TB 601 section 2.2: about 1.0-1.06 for ACSR
    /// with one or three aluminium layers; 1 for two layers or a non-magnetic core) [-]
    pub magnetic_core_factor: f64,
    /// emissivity of the surface `epsilon` [-] (0.23 new to 0.95 weathered; IEEE 738 example 0.8)
    pub emissivity: f64,
    /// solar absorptivity of the surface `alpha` [-] (IEEE 738 example 0.8)
    pub absorptivity: f64,
    /// mass of the outer (aluminium) layers per unit length `m_a` [kg/m]
    pub outer_mass_kg_per_m: f64,
    /// specific heat of the outer layers at 20 C `c_a` [J/(kg K)] (aluminium: 897, IEEE 738 table 1 note)
    pub outer_specific_heat_j_per_kg_k: f64,
    /// mass of the core per unit length `m_s` [kg/m] (0 for a homogeneous conductor)
    pub core_mass_kg_per_m: f64,
    /// specific heat of the core at 20 C `c_s` [J/(kg K)] (steel: 481)
    pub core_specific_heat_j_per_kg_k: f64,
    /// temperature coefficient of the outer layers' specific heat `beta_a` [1/K]: `c_a(T) = c_a (1 + beta_a (T -
    /// 20 C))` (CIGRE TB 601 section 4.3: 3.8e-4 for aluminium; 0 keeps `c_a` constant, as IEEE 738 does)
    pub outer_specific_heat_coefficient_per_k: f64,
    /// temperature coefficient of the core's specific heat `beta_s` [1/K] (CIGRE TB 601: 1.0e-4 for steel)
    pub core_specific_heat_coefficient_per_k: f64,
}

impl ThermalConductor {
    /// Total heat capacity per unit length `m_a c_a + m_s c_s` [J/(m K)].
    pub fn heat_capacity_j_per_m_k(&self) -> f64 {
        self.outer_mass_kg_per_m * self.outer_specific_heat_j_per_kg_k
            + self.core_mass_kg_per_m * self.core_specific_heat_j_per_kg_k
    }

    /// The data as `standard` uses them: IEEE 738 takes the specific heats as constants (its eq. (2) with
    /// `m C_p` fixed), so its copy has both temperature coefficients zero; CIGRE TB 601 keeps them. For
    /// models that read the coefficients themselves (the de-icing's enthalpy); the IEEE 738 heat balance
    /// itself ignores them.
    pub fn for_standard(&self, standard: super::Standard) -> ThermalConductor {
        let mut c = self.clone();
        if standard == super::Standard::Ieee738 {
            c.outer_specific_heat_coefficient_per_k = 0.0;
            c.core_specific_heat_coefficient_per_k = 0.0;
        }
        c
    }

    /// Heat capacity per unit length at the conductor temperature `temperature_k` [K] with the specific heats'
    /// temperature coefficients, `m_a c_a (1 + beta_a (T - 20 C)) + m_s c_s (1 + beta_s (T - 20 C))` [J/(m K)]
    /// (CIGRE TB 601 section 4.3); equal to [`ThermalConductor::heat_capacity_j_per_m_k`] at 20 C or with
    /// both coefficients zero.
    pub fn heat_capacity_at_j_per_m_k(&self, temperature_k: f64) -> f64 {
        let rise = temperature_k - 293.15;
        self.outer_mass_kg_per_m
            * self.outer_specific_heat_j_per_kg_k
            * (1.0 + self.outer_specific_heat_coefficient_per_k * rise)
            + self.core_mass_kg_per_m
                * self.core_specific_heat_j_per_kg_k
                * (1.0 + self.core_specific_heat_coefficient_per_k * rise)
    }
}
