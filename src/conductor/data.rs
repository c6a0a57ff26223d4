//! The stress-strain data of a catalogue conductor, as `data/conductors.toml` (or a user's catalogue of
//! the same format) gives them in a `[conductor.stress_strain]` sub-table, and their conversion into the
//! conductor's axial law [`TwoMaterial`].
//!
//! The published form is kept (Aluminum Association, IEEE Std 1283, Alcoa SAG10, CIGRE TB 324): each
//! material's stress `sigma = a0 + a1 x + a2 x^2 + a3 x^3 + a4 x^4` [Pa] on the WHOLE conductor's area
//! `A_s` (`stress_area_m2`) as a function of the strain `x` in PERCENT, a final (unloading) modulus on the
//! same area, and the temperature the curves were measured at. The conversion
//! ([`Curve::from_percent`]) gives the component's force `F = A_s sigma` [N] against the strain as a
//! fraction. A material without a polynomial is linear with its final modulus (no permanent set, no
//! creep), which is how the catalogue gives conductors whose curves are not published: their moduli are
//! then split so that the composite has the entry's `EA` and expansion coefficient exactly.
//!
//! [`StressStrainData::validate`] checks every number's range and that each curve is a loading curve
//! (increasing from its zero to its limit), naming the field.

use serde::Deserialize;

use super::component::Component;
use super::curve::Curve;
use super::two_material::TwoMaterial;

/// Allowed ranges (inclusive) of the fields, with the reason.
/// Reference temperature of the curves [K]: the published curves are measured at 15-30 C; -50 to 100 C.
pub const REFERENCE_TEMPERATURE_K: (f64, f64) = (223.15, 373.15);
/// Expansion coefficients [1/K]: steel 11.5e-6, aluminium 23e-6, invar 1.5e-6; 0 to 5e-5.
pub const EXPANSION_PER_K: (f64, f64) = (0.0, 5.0e-5);
/// Final moduli on the stress area [Pa]: a steel core of ACSR 6/1 is about 70 GPa on the total area,
/// the aluminium of a 54/7 about 47 GPa; a steel wire alone 200 GPa. 1 to 300 GPa.
pub const FINAL_MODULUS_PA: (f64, f64) = (1.0e9, 3.0e11);
/// Compression modulus [Pa], at most the final modulus (fixtures use 1500 psi/% = 1 GPa).
pub const COMPRESSION_MODULUS_PA: (f64, f64) = (0.0, 3.0e11);

/// One material's data (module doc).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ComponentData {
    /// linear thermal expansion coefficient `alpha` [1/K], in [0, 5e-5]
    pub expansion_per_k: f64,
    /// final (unloading) modulus on the stress area `E_f` [Pa] (stress per unit strain), in [1e9, 3e11]
    pub final_modulus_pa: f64,
    /// the virgin curve's coefficients `a0..a4` [Pa] (stress on the stress area, strain in percent);
    /// absent: linear with the final modulus
    #[serde(default)]
    pub initial_pa_percent: Option<[f64; 5]>,
    /// the stress [Pa] up to which the virgin curve was fitted (beyond it: its tangent); absent: no limit
    #[serde(default)]
    pub initial_limit_pa: Option<f64>,
    /// the 10-year creep curve's coefficients `a0..a4` [Pa] (same form); absent: no creep
    #[serde(default)]
    pub creep_pa_percent: Option<[f64; 5]>,
    /// the stress [Pa] up to which the creep curve was fitted; absent: no limit
    #[serde(default)]
    pub creep_limit_pa: Option<f64>,
    /// modulus in compression on the stress area [Pa], in [0, 3e11]; default 0 (aluminium strands
    /// birdcage rather than carry compression)
    #[serde(default)]
    pub compression_modulus_pa: f64,
}

/// A conductor's stress-strain data (module doc).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StressStrainData {
    /// temperature the curves were measured at, the zero of the thermal strains `theta_ref` [K], in
    /// [223.15, 373.15]
    pub reference_temperature_k: f64,
    /// the area the stresses are given on `A_s` [m^2]; default the entry's total metallic area
    #[serde(default)]
    pub stress_area_m2: Option<f64>,
    /// the outer layers (aluminium or its alloy)
    pub outer: ComponentData,
    /// the core (steel); absent for a conductor of one material
    #[serde(default)]
    pub core: Option<ComponentData>,
    /// where the numbers come from, and which are derived
    pub source: String,
}

/// A field out of range or a curve that is not a loading curve: the field's path within the
/// `stress_strain` table, its value and what is allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("stress_strain.{field} = {value}: {allowed}")]
pub struct StressStrainError {
    /// e.g. `outer.initial_pa_percent`
    pub field: String,
    /// the value as written
    pub value: String,
    /// what is allowed
    pub allowed: String,
}

fn range(field: &str, v: f64, (lo, hi): (f64, f64), why: &str) -> Result<(), StressStrainError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(StressStrainError {
            field: field.into(),
            value: format!("{v}"),
            allowed: format!("must be in [{lo:e}, {hi:e}] ({why})"),
        })
    }
}

impl ComponentData {
    fn curve(
        &self,
        prefix: &str,
        which: &str,
        coefficients: Option<[f64; 5]>,
        limit_pa: Option<f64>,
        stress_area_m2: f64,
    ) -> Result<Option<Curve>, StressStrainError> {
        let Some(a) = coefficients else { return Ok(None) };
        let field = format!("{prefix}.{which}_pa_percent");
        if a.iter().any(|x| !x.is_finite()) {
            return Err(StressStrainError {
                field,
                value: format!("{a:?}"),
                allowed: "must be five finite numbers".into(),
            });
        }
        if let Some(l) = limit_pa {
            range(&format!("{prefix}.{which}_limit_pa"), l, (1.0e6, 2.0e9), "a stress of 1 MPa to 2 GPa")?;
        }
        Curve::from_percent(a, stress_area_m2, limit_pa).map(Some).ok_or_else(|| StressStrainError {
            field,
            value: format!("{a:?}"),
            allowed: "must be a loading curve: cross zero at a strain in [-0.1, 0.5] % below its limit and increase from there \
                      to the limit (limit_pa, if given, must be reached)"
                .into(),
        })
    }

    fn component(&self, prefix: &str, own_area_m2: f64, stress_area_m2: f64) -> Result<Component, StressStrainError> {
        range(&format!("{prefix}.expansion_per_k"), self.expansion_per_k, EXPANSION_PER_K, "metals: 1e-6 to 3e-5")?;
        range(&format!("{prefix}.final_modulus_pa"), self.final_modulus_pa, FINAL_MODULUS_PA, "1 to 300 GPa")?;
        range(
            &format!("{prefix}.compression_modulus_pa"),
            self.compression_modulus_pa,
            (COMPRESSION_MODULUS_PA.0, self.final_modulus_pa),
            "at most the final modulus",
        )?;
        let k_u = self.final_modulus_pa * stress_area_m2;
        let initial = self
            .curve(prefix, "initial", self.initial_pa_percent, self.initial_limit_pa, stress_area_m2)?
            .unwrap_or_else(|| Curve::linear(k_u));
        let creep = self.curve(prefix, "creep", self.creep_pa_percent, self.creep_limit_pa, stress_area_m2)?;
        Ok(Component {
            area_m2: own_area_m2,
            expansion_per_k: self.expansion_per_k,
            initial,
            creep,
            unloading_stiffness_n: k_u,
            compression_stiffness_n: self.compression_modulus_pa * stress_area_m2,
        })
    }
}

impl StressStrainData {
    /// The conductor's axial law, for the areas of its outer layers and core `outer_area_m2`,
    /// `core_area_m2` [m^2] (the stresses are on `stress_area_m2`, default their sum); the first field out of
    /// range or curve that is not a loading curve is the error.
    pub fn two_material(&self, outer_area_m2: f64, core_area_m2: f64) -> Result<TwoMaterial, StressStrainError> {
        range("reference_temperature_k", self.reference_temperature_k, REFERENCE_TEMPERATURE_K, "-50 to 100 C")?;
        let total = outer_area_m2 + core_area_m2;
        let area = self.stress_area_m2.unwrap_or(total);
        range("stress_area_m2", area, (0.5 * total, 2.0 * total), "within a factor 2 of the metallic area")?;
        let outer = self.outer.component("outer", outer_area_m2, area)?;
        let core = match (&self.core, core_area_m2 > 0.0) {
            (Some(c), true) => Some(c.component("core", core_area_m2, area)?),
            (None, false) => None,
            (Some(_), false) => {
                return Err(StressStrainError {
                    field: "core".into(),
                    value: "a table".into(),
                    allowed: "must be absent for a conductor without a core (steel_area_m2 = 0)".into(),
                });
            }
            (None, true) => {
                return Err(StressStrainError {
                    field: "core".into(),
                    value: "absent".into(),
                    allowed: "must be given for a conductor with a core (steel_area_m2 > 0)".into(),
                });
            }
        };
        Ok(TwoMaterial { outer, core, reference_temperature_k: self.reference_temperature_k })
    }
}
