//! The conductor of a thermal case (`ohl thermal`) or of a scenario's `[thermal]` table, and the span's
//! inclination: a conductor is named in the built-in catalogue (`data/conductors.toml`,
//! [`crate::thermal::catalog`]) or in a user catalogue file of the same format, or given by its properties in
//! the file itself.
//!
//! ```toml
//! conductor = "ACSR Drake"                 # a name: the user catalogue's first, then the built-in one
//! conductor_catalog = "my_conductors.toml" # optional: a user catalogue, relative to this file's folder
//! inclination_deg = 10.0                   # optional: the span's inclination (CIGRE TB 601 eq. (24))
//! ```
//!
//! or, instead of the name, the properties (`[thermal.conductor]` in a scenario, `[conductor]` in a thermal
//! case), with the field names of the catalogue:
//!
//! ```toml
//! [conductor]
//! name = "ACSR Drake (by its properties)"
//! diameter_m = 28.14e-3
//! outer_strand_diameter_m = 4.44e-3
//! resistance_low_ohm_per_m = 7.283e-5
//! temperature_low_k = 298.15
//! resistance_high_ohm_per_m = 8.688e-5
//! temperature_high_k = 348.15
//! emissivity = 0.8
//! absorptivity = 0.8
//! outer_mass_kg_per_m = 1.116
//! outer_specific_heat_j_per_kg_k = 897.0
//! core_mass_kg_per_m = 0.5119
//! core_specific_heat_j_per_kg_k = 481.0
//! ```
//!
//! A user catalogue is read while the file is parsed ([`resolve_user_catalog`]): every entry is validated
//! (messages name the catalogue file and the entry's field, `conductor[1].diameter_m`), and a name found there
//! is replaced by the entry's thermal properties. Its entries carry the catalogue's mechanical data too, which
//! a scenario's `[conductor] catalog = "NAME"` takes (`super::fill_from_catalog`). Every property is checked
//! by [`check_thermal_conductor`] with its allowed range.

use std::fmt;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, Visitor};

use super::range::{
    AXIAL_STIFFNESS_N, LINEAR_DENSITY_KG_PER_M, Range as Allowed, SPECIFIC_HEAT_COEFFICIENT_PER_K,
    SPECIFIC_HEAT_J_PER_KG_K, THERMAL_EXPANSION_PER_K,
};
use super::validate::Check;
use super::{InputError, Problem};
use crate::thermal::catalog::{self, CatalogConductor, CatalogError};
use crate::thermal::cigre601::convection::{is_smooth, roughness};
use crate::thermal::{Standard, ThermalConductor};

pub use crate::thermal::conductor::UNNAMED;

/// The conductor of a thermal table: a catalogue name (a string) or its properties (a table).
#[derive(Clone, Debug, PartialEq)]
pub enum ConductorSpec {
    /// a name or alias of the built-in catalogue (or of the user catalogue, resolved at parse)
    Name(String),
    /// the conductor's properties (the table has the fields of [`ThermalConductor`], with its defaults)
    Properties(Box<ThermalConductor>),
}

impl<'de> Deserialize<'de> for ConductorSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ConductorSpec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a conductor's name (text) or a table of its properties")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<ConductorSpec, E> {
                Ok(ConductorSpec::Name(v.to_string()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<ConductorSpec, A::Error> {
                let p = ThermalConductor::deserialize(de::value::MapAccessDeserializer::new(map))?;
                Ok(ConductorSpec::Properties(Box::new(p)))
            }
        }
        d.deserialize_any(V)
    }
}

impl ConductorSpec {
    /// The conductor's thermal data: the catalogue entry of a name, or the properties.
    pub fn thermal(&self) -> Result<ThermalConductor, CatalogError> {
        match self {
            ConductorSpec::Name(n) => Ok(catalog::find(n)?.thermal()),
            ConductorSpec::Properties(p) => Ok((**p).clone()),
        }
    }

    /// The conductor as the file gives it: the name as written, or the properties' name.
    pub fn label(&self) -> String {
        match self {
            ConductorSpec::Name(n) => n.clone(),
            ConductorSpec::Properties(p) => p.name.clone(),
        }
    }

    /// The catalogue's primary name of a name (the name as written if it is not found), or the properties'
    /// name.
    pub fn primary_name(&self) -> String {
        match self {
            ConductorSpec::Name(n) => catalog::find(n).map(|k| k.name.clone()).unwrap_or_else(|_| n.clone()),
            ConductorSpec::Properties(_) => self.label(),
        }
    }
}

/// The properties table of a catalogue entry's thermal data (what a user catalogue's name is replaced by):
/// its fields as [`ThermalConductor`] serialises them.
fn properties_table(t: &ThermalConductor) -> Result<toml::Table, toml::ser::Error> {
    toml::Table::try_from(t)
}

/// Check a conductor's thermal data, each field under `{at}.` (e.g. `thermal.conductor`, or `conductor[1]` of
/// a catalogue file); whether all are valid.
pub fn check_thermal_conductor(c: &mut Check, at: &str, t: &ThermalConductor) -> bool {
    let f = |name: &str| format!("{at}.{name}");
    let n0 = c.0.len();
    let d = t.diameter_m;
    if c.range(&f("diameter_m"), d, &Allowed::closed(1.0e-3, 0.2, "m")) {
        if !(t.core_diameter_m.is_finite() && t.core_diameter_m >= 0.0 && t.core_diameter_m < d) {
            c.fail(&f("core_diameter_m"), t.core_diameter_m, &format!("must be in [0, diameter_m) = [0, {d}) m"));
        }
        c.within(
            &f("outer_strand_diameter_m"),
            t.outer_strand_diameter_m,
            0.0,
            d / 3.0,
            &format!(
                "must be in [0, diameter_m / 3] = [0, {}] m (0: a smooth surface; a 7-wire conductor has d = D/3)",
                d / 3.0
            ),
        );
    }
    let (r_lo, t_lo) = (t.resistance_low_ohm_per_m, t.temperature_low_k);
    let lo_ok = c.range(&f("resistance_low_ohm_per_m"), r_lo, &Allowed::closed(1.0e-7, 0.1, "ohm/m"))
        & c.range(&f("temperature_low_k"), t_lo, &super::range::RESISTANCE_TEMPERATURE_K);
    if lo_ok {
        let hi_r = c.within(
            &f("resistance_high_ohm_per_m"),
            t.resistance_high_ohm_per_m,
            r_lo,
            0.1,
            &format!("must be in [resistance_low_ohm_per_m, 0.1] = [{r_lo}, 0.1] ohm/m"),
        );
        let hi_t = t.temperature_high_k.is_finite() && t.temperature_high_k > t_lo && t.temperature_high_k <= 600.0;
        if !hi_t {
            c.fail(
                &f("temperature_high_k"),
                t.temperature_high_k,
                &format!("must be in (temperature_low_k, 600] = ({t_lo}, 600] K"),
            );
        }
        if hi_r && hi_t {
            // The resistance line R(T) = R_low + (T - T_low) (R_high - R_low) / (T_high - T_low) must stay
            // positive over the temperatures the model may meet (from 200 K).
            let slope = (t.resistance_high_ohm_per_m - r_lo) / (t.temperature_high_k - t_lo);
            let at_200 = r_lo + (200.0 - t_lo) * slope;
            if at_200 <= 0.0 {
                c.fail(
                    &f("resistance_high_ohm_per_m"),
                    t.resistance_high_ohm_per_m,
                    &format!(
                        "makes the resistance line negative at 200 K ({at_200:.3e} ohm/m): the temperature \
                         coefficient (R_high - R_low) / (R_low (T_high - T_low)) must be below 1 / (T_low - 200 K)"
                    ),
                );
            }
        }
    }
    let fraction = Allowed::closed(0.0, 1.0, "");
    c.range(&f("magnetic_core_factor"), t.magnetic_core_factor, &Allowed::closed(1.0, 1.5, ""));
    c.range(&f("emissivity"), t.emissivity, &fraction);
    c.range(&f("absorptivity"), t.absorptivity, &fraction);
    c.range(&f("outer_mass_kg_per_m"), t.outer_mass_kg_per_m, &Allowed::closed(1.0e-3, 100.0, "kg/m"));
    let heat = SPECIFIC_HEAT_J_PER_KG_K;
    let beta = SPECIFIC_HEAT_COEFFICIENT_PER_K;
    c.range(&f("outer_specific_heat_j_per_kg_k"), t.outer_specific_heat_j_per_kg_k, &heat);
    c.range(&f("outer_specific_heat_coefficient_per_k"), t.outer_specific_heat_coefficient_per_k, &beta);
    if c.range(&f("core_mass_kg_per_m"), t.core_mass_kg_per_m, &Allowed::closed(0.0, 100.0, "kg/m"))
        && t.core_mass_kg_per_m > 0.0
    {
        c.range(&f("core_specific_heat_j_per_kg_k"), t.core_specific_heat_j_per_kg_k, &heat);
    } else {
        // Without a core its specific heat is not used: 0 is allowed too.
        c.range(&f("core_specific_heat_j_per_kg_k"), t.core_specific_heat_j_per_kg_k, &Allowed { lo: 0.0, ..heat });
    }
    c.range(&f("core_specific_heat_coefficient_per_k"), t.core_specific_heat_coefficient_per_k, &beta);
    c.0.len() == n0
}

/// Check a catalogue entry (a user catalogue's `conductor[k]`): its thermal data and its mechanical data.
fn check_catalog_entry(c: &mut Check, at: &str, k: &CatalogConductor) {
    check_thermal_conductor(c, at, &k.thermal());
    let f = |name: &str| format!("{at}.{name}");
    c.range(&f("aluminium_area_m2"), k.aluminium_area_m2, &Allowed::closed(1.0e-6, 1.0e-2, "m^2"));
    c.range(&f("steel_area_m2"), k.steel_area_m2, &Allowed::closed(0.0, 1.0e-2, "m^2"));
    c.range(&f("linear_density_kg_per_m"), k.linear_density_kg_per_m, &LINEAR_DENSITY_KG_PER_M);
    c.range(&f("rated_tensile_strength_n"), k.rated_tensile_strength_n, &Allowed::closed(1.0, 1.0e7, "N"));
    c.range(&f("axial_stiffness_n"), k.axial_stiffness_n, &AXIAL_STIFFNESS_N);
    c.range(&f("thermal_expansion_per_k"), k.thermal_expansion_per_k, &THERMAL_EXPANSION_PER_K);
}

/// Check the inclination `inclination_deg` [deg] of a span at `field`: TB 601 only (IEEE Std 738 has no such
/// term), within the range of eq. (24) for the surface (80 deg stranded, 60 deg smooth; a de-icing's ice
/// surface is smooth).
pub fn check_inclination(
    c: &mut Check,
    field: &str,
    inclination_deg: f64,
    standard: Standard,
    conductor: Option<&ThermalConductor>,
    iced: bool,
) {
    if inclination_deg == 0.0 {
        return;
    }
    if standard == Standard::Ieee738 {
        c.fail(
            field,
            inclination_deg,
            "is used by CIGRE TB 601 only (its natural convection, eq. (24)); IEEE Std 738 has no inclination \
             term: set standard = \"cigre601\" or leave it out",
        );
        return;
    }
    let smooth = iced || conductor.is_some_and(|t| is_smooth(roughness(t.diameter_m, t.outer_strand_diameter_m)));
    let (limit, surface) = if smooth { (60.0, "a smooth surface") } else { (80.0, "a stranded conductor") };
    c.within(
        field,
        inclination_deg,
        0.0,
        limit,
        &format!("must be in [0, {limit}] deg for {surface} (the range TB 601 gives eq. (24) for)"),
    );
}

/// The label of a user catalogue in messages: its path, and whose catalogue it is.
fn catalog_label(path: &Path, file: &str) -> String {
    format!("{} (conductor_catalog of {file})", path.display())
}

/// Read the user catalogue that the table `t` names in `conductor_catalog` (a path relative to the folder of
/// `file`), validate every entry, and replace `t`'s `conductor` by the entry's thermal properties if the
/// entry is found there (a name not found there is left for the built-in catalogue, and refused with both
/// catalogues' names if neither has it). `at` is the table's dotted prefix in messages (`thermal.` or
/// empty). Returns the catalogue's entries (for `[conductor] catalog`).
pub(crate) fn resolve_user_catalog(
    t: &mut toml::Table,
    at: &str,
    file: &str,
) -> Result<Option<Vec<CatalogConductor>>, InputError> {
    let Some(path) = t.get("conductor_catalog") else { return Ok(None) };
    let invalid = |field: String, value: String, allowed: String| InputError::Invalid {
        file: file.into(),
        problems: vec![Problem { field, value, allowed }],
    };
    let field = format!("{at}conductor_catalog");
    let Some(rel) = path.as_str() else {
        return Err(invalid(field, path.to_string(), "must be the path of a conductor catalogue (text)".into()));
    };
    let full: PathBuf = Path::new(file).parent().unwrap_or(Path::new("")).join(rel);
    let label = catalog_label(&full, file);
    let text = std::fs::read_to_string(&full).map_err(|e| {
        invalid(
            field.clone(),
            format!("{rel:?}"),
            format!(
                "must name a readable conductor catalogue (TOML, the format of data/conductors.toml), relative \
                 to the folder of {file}: {}: {e}",
                full.display()
            ),
        )
    })?;
    let entries =
        catalog::parse(&text).map_err(|e| InputError::Parse { file: label.clone(), message: e.to_string() })?;
    let mut c = Check(Vec::new());
    for (k, e) in entries.iter().enumerate() {
        check_catalog_entry(&mut c, &format!("conductor[{k}]"), e);
    }
    if !c.0.is_empty() {
        return Err(InputError::Invalid { file: label, problems: c.0 });
    }
    if let Some(toml::Value::String(name)) = t.get("conductor").cloned() {
        if let Some(e) = find_in(&entries, &name) {
            let table = properties_table(&e.thermal())
                .map_err(|err| InputError::Parse { file: label.clone(), message: err.to_string() })?;
            t.insert("conductor".into(), toml::Value::Table(table));
        } else if let Err(CatalogError::NotFound { available, .. }) = catalog::find(&name) {
            let user: Vec<String> = entries.iter().map(|e| e.name.clone()).collect();
            return Err(invalid(
                format!("{at}conductor"),
                format!("{name:?}"),
                format!(
                    "no conductor of that name in {} (available: {}) nor in the built-in catalogue (available: {})",
                    full.display(),
                    user.join("; "),
                    available.join("; ")
                ),
            ));
        }
    }
    Ok(Some(entries))
}

/// The user catalogue entry called `name` (name or alias, ignoring case and surrounding whitespace).
pub(crate) fn find_in<'a>(entries: &'a [CatalogConductor], name: &str) -> Option<&'a CatalogConductor> {
    let key = name.trim().to_lowercase();
    entries.iter().find(|e| std::iter::once(&e.name).chain(&e.aliases).any(|n| n.trim().to_lowercase() == key))
}
