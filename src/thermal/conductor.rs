//! The thermal data of a bare stranded conductor (IEEE Std 738-2012 section 4.4 and Annex B; CIGRE TB 601
//! section 2): geometry, AC resistance at two temperatures, surface emissivity and absorptivity, and the
//! heat capacity of its core and outer layers.

/// The name of a conductor given by its properties without a `name` [-].
pub const UNNAMED: &str = "conductor given by its properties";

fn unnamed() -> String {
    UNNAMED.into()
}

fn zero() -> f64 {
    0.0
}

fn one() -> f64 {
    1.0
}

/// Thermal data of one conductor (SI units, temperatures in kelvin). It is also the table of a conductor
/// given by its properties in a scenario or thermal case (`[thermal.conductor]`, `[conductor]`;
/// `crate::scenario::thermal_conductor`), with the field names of the catalogue (`data/conductors.toml`),
/// the ranges its check allows (`check_thermal_conductor`) and the defaults below; the catalogue's entries
/// give every field ([`super::catalog::CatalogConductor::thermal`]).
#[derive(Clone, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalConductor {
    /// name (free text), e.g. "ACSR Drake 795 kcmil 26/7" [-]; default "conductor given by its properties"
    #[serde(default = "unnamed")]
    pub name: String,
    /// outside diameter `D` [m], in [1e-3, 0.2]
    pub diameter_m: f64,
    /// diameter of the steel core `D_c` [m], in [0, D); default 0 (no core, a homogeneous conductor; not used
    /// by the heat balance)
    #[serde(default = "zero")]
    pub core_diameter_m: f64,
    /// diameter of an outer-layer strand `d` [m], in [0, D/3] (0: a smooth surface; CIGRE TB 601 roughness
    /// `R_s = d / (2 (D - d))`)
    pub outer_strand_diameter_m: f64,
    /// AC resistance per unit length at the low reference temperature `R(T_low)` [ohm/m], in [1e-7, 0.1]
    pub resistance_low_ohm_per_m: f64,
    /// the low reference temperature `T_low` [K], in [200, 500] (IEEE 738 example: 25 C)
    pub temperature_low_k: f64,
    /// AC resistance per unit length at the high reference temperature `R(T_high)` [ohm/m], in [R_low, 0.1]
    pub resistance_high_ohm_per_m: f64,
    /// the high reference temperature `T_high` [K], in (T_low, 600] (IEEE 738 example: 75 C)
    pub temperature_high_k: f64,
    /// magnetic-core factor multiplying the resistance `k_m` [-], in [1, 1.5]; default 1 (CIGRE TB 601 section
    /// 2.2: about 1.0-1.06 for ACSR with one or three aluminium layers; 1 for two layers or a non-magnetic
    /// core)
    #[serde(default = "one")]
    pub magnetic_core_factor: f64,
    /// emissivity of the surface `epsilon` [-], in [0, 1] (0.23 new to 0.95 weathered; IEEE 738 example 0.8)
    pub emissivity: f64,
    /// solar absorptivity of the surface `alpha_s` [-], in [0, 1] (IEEE 738 example 0.8)
    pub absorptivity: f64,
    /// mass of the outer (aluminium) layers per unit length `m_a` [kg/m], in [1e-3, 100]
    pub outer_mass_kg_per_m: f64,
    /// specific heat of the outer layers at 20 C `c_a` [J/(kg K)], in [100, 5000] (aluminium: 897, IEEE 738
    /// table 1 note)
    pub outer_specific_heat_j_per_kg_k: f64,
    /// temperature coefficient of the outer layers' specific heat `beta_a` [1/K], in [0, 1e-3]: `c_a(T) = c_a
    /// (1 + beta_a (T - 20 C))`; default 0 (a constant `c_a`, as IEEE Std 738 takes it; CIGRE TB 601 section
    /// 4.3 gives 3.8e-4 for aluminium)
    #[serde(default = "zero")]
    pub outer_specific_heat_coefficient_per_k: f64,
    /// mass of the core per unit length `m_s` [kg/m], in [0, 100]; default 0 (no core)
    #[serde(default = "zero")]
    pub core_mass_kg_per_m: f64,
    /// specific heat of the core at 20 C `c_s` [J/(kg K)], in [100, 5000] when there is a core (steel: 481);
    /// default 0
    #[serde(default = "zero")]
    pub core_specific_heat_j_per_kg_k: f64,
    /// temperature coefficient of the core's specific heat `beta_s` [1/K], in [0, 1e-3]; default 0 (CIGRE TB
    /// 601: 1.0e-4 for steel)
    #[serde(default = "zero")]
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
