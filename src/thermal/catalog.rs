//! The conductor catalogue: a few common bare overhead conductors, selectable by name.
//!
//! The data are in `data/conductors.toml` (one `[[conductor]]` table each, SI units with the unit in the
//! key's name, temperatures in kelvin), compiled into the library with `include_str!` so that a binary
//! finds them from any directory. The file holds ACSR Drake 795 kcmil 26/7, ACSR Linnet 336.4 kcmil 26/7,
//! ACSR Zebra 54/7 (28.62 mm) and the all-aluminium-alloy conductor 366-AL3 (ASTER 366), each with its
//! geometry, areas, mass, rated tensile strength, axial stiffness, thermal expansion, AC resistance at two
//! temperatures, surface coefficients and the masses and specific heats of its layers.
//!
//! Sources, entry by entry in the file's `source` strings: IEEE Std 738-2012 Annex B (Drake's diameter and
//! resistances), CIGRE TB 601 (2014) examples (Drake's core, layer masses and specific heats), ASTM B232
//! and the US manufacturers' ACSR tables (Drake and Linnet: wires, weight, strength, resistances), CPUC
//! General Order 95 Table 23 (Drake's area and strength), BS 215-2 / IS 398-2 / EN 50182 (Zebra), and
//! EN 50182's final moduli and expansion coefficients per stranding. The file says which numbers are
//! computed rather than quoted: the areas from the wire diameters or the kcmil size, `EA` as a tabulated
//! final modulus times the total area, the split of a quoted linear density into layer masses, Zebra's and
//! the AAAC's AC resistances (DC resistance, temperature coefficient and the IEC 60287-1-1 skin effect),
//! and every number of the AAAC entry (from its construction by the rules of EN 50182 / EN 50183). The
//! emissivity and absorptivity are typical values (0.8, as IEEE 738 Annex B), not properties of the
//! conductors.
//!
//! [`catalog`] parses the file once; [`find`] looks a conductor up by its name or an alias (ignoring case
//! and surrounding whitespace); [`CatalogConductor::thermal`] gives the [`ThermalConductor`] of an entry.
//! [`parse`] reads a file of the same format (for a user's own catalogue) and rejects duplicate names.
//!
//! Checks (the tests below), each with its tolerance: every entry's linear density is `A_al 2703 + A_st
//! 7780` kg/m within 3 % (the stranding lengthens the wires by 1-3 %); the layer masses add up to the
//! linear density within 1 %; the DC resistance of the aluminium area at 20 C (`rho / A_al`, `rho` =
//! 2.8264e-8 ohm m for the 1350/AL1 aluminium of ACSR, 3.284e-8 ohm m for the AL3 alloy of AAAC) is the
//! AC resistance interpolated to 20 C within 10 % (stranding, skin effect and the steel's share); `R_high >
//! R_low` and `T_high > T_low`; `pi D^2 / 4` is at least the total area and the core fits inside the
//! conductor; the modulus `EA / A` is within 50-90 GPa, `RTS / A` within 200-400 MPa and the expansion
//! within 15-25e-6 /K; Drake's thermal data are exactly IEEE 738 Annex B's and TB 601's numbers; every
//! name and alias finds its own entry.

use std::sync::OnceLock;

use serde::Deserialize;

use super::ThermalConductor;
use crate::conductor::TwoMaterial;
use crate::conductor::data::{StressStrainData, StressStrainError};

/// The catalogue file, compiled in.
const CATALOG_TOML: &str = include_str!("../../data/conductors.toml");

/// The kind of conductor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum ConductorKind {
    /// aluminium conductor, steel reinforced: aluminium (1350 / AL1) wires on a zinc-coated steel core
    #[serde(rename = "ACSR")]
    Acsr,
    /// all aluminium alloy conductor (6201 / AL3 wires), no core
    #[serde(rename = "AAAC")]
    Aaac,
}

/// One conductor of the catalogue, as `data/conductors.toml` gives it (SI units, temperatures in kelvin).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CatalogConductor {
    /// primary name, e.g. "ACSR Drake" \[-\]
    pub name: String,
    /// other names that [`find`] accepts, e.g. "drake", "795 kcmil 26/7" \[-\]
    pub aliases: Vec<String>,
    /// ACSR or AAAC \[-\]
    pub kind: ConductorKind,
    /// outside diameter `D` \[m\]
    pub diameter_m: f64,
    /// diameter of the steel core `D_c` \[m\] (0 for AAAC)
    pub core_diameter_m: f64,
    /// diameter of one wire of the outer layer `d` \[m\]
    pub outer_strand_diameter_m: f64,
    /// cross-section of the aluminium (or alloy) wires `A_al` \[m^2\]
    pub aluminium_area_m2: f64,
    /// cross-section of the steel wires `A_st` \[m^2\] (0 for AAAC)
    pub steel_area_m2: f64,
    /// mass per unit length of the conductor `m` \[kg/m\]
    pub linear_density_kg_per_m: f64,
    /// rated tensile strength `RTS` \[N\]
    pub rated_tensile_strength_n: f64,
    /// axial stiffness `EA` (final modulus times total area) \[N\]
    pub axial_stiffness_n: f64,
    /// coefficient of linear thermal expansion `alpha_T` \[1/K\]
    pub thermal_expansion_per_k: f64,
    /// AC resistance per unit length at the low reference temperature `R(T_low)` \[ohm/m\]
    pub resistance_low_ohm_per_m: f64,
    /// the low reference temperature `T_low` \[K\]
    pub temperature_low_k: f64,
    /// AC resistance per unit length at the high reference temperature `R(T_high)` \[ohm/m\]
    pub resistance_high_ohm_per_m: f64,
    /// the high reference temperature `T_high` \[K\]
    pub temperature_high_k: f64,
    /// magnetic-core factor on the resistance `k_m` \[-\] (1.0 unless a source says otherwise)
    pub magnetic_core_factor: f64,
    /// surface emissivity `epsilon` \[-\] (a typical value)
    pub emissivity: f64,
    /// solar absorptivity of the surface `alpha_s` \[-\] (a typical value)
    pub absorptivity: f64,
    /// mass of the aluminium (alloy) wires per unit length `m_a` \[kg/m\]
    pub outer_mass_kg_per_m: f64,
    /// specific heat of the aluminium (alloy) wires at 20 C `c_a` \[J/(kg K)\]
    pub outer_specific_heat_j_per_kg_k: f64,
    /// temperature coefficient of `c_a`, `beta_a` \[1/K\] (CIGRE TB 601 section 4.3)
    pub outer_specific_heat_coefficient_per_k: f64,
    /// mass of the steel core per unit length `m_s` \[kg/m\] (0 for AAAC)
    pub core_mass_kg_per_m: f64,
    /// specific heat of the steel core at 20 C `c_s` \[J/(kg K)\]
    pub core_specific_heat_j_per_kg_k: f64,
    /// temperature coefficient of `c_s`, `beta_s` \[1/K\] (CIGRE TB 601 section 4.3)
    pub core_specific_heat_coefficient_per_k: f64,
    /// where each number comes from, and which numbers are computed \[-\]
    pub source: String,
    /// the materials' stress-strain data (`[conductor.stress_strain]`, [`crate::conductor::data`]) for
    /// the two-material law and sag-tension; absent: the entry has only its linear `EA` and expansion
    #[serde(default)]
    pub stress_strain: Option<StressStrainData>,
}

impl CatalogConductor {
    /// Total metallic cross-section `A = A_al + A_st` \[m^2\].
    pub fn total_area_m2(&self) -> f64 {
        self.aluminium_area_m2 + self.steel_area_m2
    }

    /// The thermal data of this conductor (IEEE 738 / CIGRE TB 601 heat balance), named by the entry's name.
    pub fn thermal(&self) -> ThermalConductor {
        ThermalConductor {
            name: self.name.clone(),
            diameter_m: self.diameter_m,
            core_diameter_m: self.core_diameter_m,
            outer_strand_diameter_m: self.outer_strand_diameter_m,
            resistance_low_ohm_per_m: self.resistance_low_ohm_per_m,
            temperature_low_k: self.temperature_low_k,
            resistance_high_ohm_per_m: self.resistance_high_ohm_per_m,
            temperature_high_k: self.temperature_high_k,
            magnetic_core_factor: self.magnetic_core_factor,
            emissivity: self.emissivity,
            absorptivity: self.absorptivity,
            outer_mass_kg_per_m: self.outer_mass_kg_per_m,
            outer_specific_heat_j_per_kg_k: self.outer_specific_heat_j_per_kg_k,
            core_mass_kg_per_m: self.core_mass_kg_per_m,
            core_specific_heat_j_per_kg_k: self.core_specific_heat_j_per_kg_k,
            outer_specific_heat_coefficient_per_k: self.outer_specific_heat_coefficient_per_k,
            core_specific_heat_coefficient_per_k: self.core_specific_heat_coefficient_per_k,
        }
    }

    /// The conductor's axial law from its stress-strain data (`None` where the entry has none): aluminium
    /// outer layers of `aluminium_area_m2` on a core of `steel_area_m2`.
    ///
    /// # Panics
    /// If the data are invalid: [`parse`] has checked them (a value of this type built by hand is the
    /// caller's to check with [`StressStrainData::two_material`]).
    pub fn two_material(&self) -> Option<TwoMaterial> {
        self.stress_strain.as_ref().map(|d| {
            d.two_material(self.aluminium_area_m2, self.steel_area_m2)
                .unwrap_or_else(|e| panic!("{}: {e} (parse checks this)", self.name))
        })
    }

    /// Whether `key` (already trimmed and lower-cased) is this conductor's name or one of its aliases.
    fn answers_to(&self, key: &str) -> bool {
        std::iter::once(&self.name).chain(&self.aliases).any(|n| normalise(n) == key)
    }
}

/// Why a conductor could not be had from the catalogue.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CatalogError {
    /// No entry has this name or alias.
    #[error("no conductor named \"{asked}\" in the catalogue; available: {}", .available.join("; "))]
    NotFound {
        /// the name asked for, as given
        asked: String,
        /// every entry's name with its aliases, e.g. "ACSR Drake (drake, 795 kcmil 26/7)"
        available: Vec<String>,
    },
    /// The catalogue text is not valid TOML of the catalogue's format (the message has line and column).
    #[error("conductor catalogue: {0}")]
    Parse(String),
    /// Two entries answer to the same name (names and aliases are compared ignoring case and whitespace
    /// around them).
    #[error("conductor catalogue: the name \"{0}\" is used by more than one entry")]
    Duplicate(String),
    /// An entry's stress-strain data are out of range or a curve is not a loading curve.
    #[error("conductor catalogue: \"{conductor}\": {error}")]
    StressStrain {
        /// the entry's name
        conductor: String,
        /// the field, its value and what is allowed
        error: StressStrainError,
    },
}

/// The file's top level: a list of `[[conductor]]` tables.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CatalogFile {
    conductor: Vec<CatalogConductor>,
}

/// The comparison key of a name: without surrounding whitespace, lower-cased.
fn normalise(name: &str) -> String {
    name.trim().to_lowercase()
}

/// Parses a catalogue in the format of `data/conductors.toml`; rejects unknown fields, missing fields and
/// a name or alias used by two entries.
pub fn parse(text: &str) -> Result<Vec<CatalogConductor>, CatalogError> {
    let file: CatalogFile = toml::from_str(text).map_err(|e| CatalogError::Parse(e.to_string()))?;
    let mut seen: Vec<(String, usize)> = Vec::new();
    for (k, c) in file.conductor.iter().enumerate() {
        for n in std::iter::once(&c.name).chain(&c.aliases) {
            let key = normalise(n);
            // The same entry may repeat a name as an alias; another entry may not use it.
            if seen.iter().any(|(s, owner)| *s == key && *owner != k) {
                return Err(CatalogError::Duplicate(n.trim().to_string()));
            }
            seen.push((key, k));
        }
        if let Some(d) = &c.stress_strain {
            d.two_material(c.aluminium_area_m2, c.steel_area_m2)
                .map_err(|error| CatalogError::StressStrain { conductor: c.name.clone(), error })?;
        }
    }
    Ok(file.conductor)
}

/// The built-in catalogue (`data/conductors.toml`), parsed on the first call.
///
/// # Panics
/// If the compiled-in file does not parse: it is fixed at build time, and the tests parse it.
pub fn catalog() -> &'static [CatalogConductor] {
    static CATALOG: OnceLock<Vec<CatalogConductor>> = OnceLock::new();
    CATALOG.get_or_init(|| parse(CATALOG_TOML).unwrap_or_else(|e| panic!("data/conductors.toml: {e}")))
}

/// The built-in conductor called `name`: its name or one of its aliases, ignoring case and surrounding
/// whitespace (`"drake"`, `"  ACSR Drake "` and `"795 kcmil 26/7"` all find Drake). The error names the
/// name asked for and lists the names available.
pub fn find(name: &str) -> Result<&'static CatalogConductor, CatalogError> {
    let key = normalise(name);
    catalog().iter().find(|c| c.answers_to(&key)).ok_or_else(|| CatalogError::NotFound {
        asked: name.to_string(),
        available: catalog().iter().map(|c| format!("{} ({})", c.name, c.aliases.join(", "))).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// density of aluminium and its alloys \[kg/m^3\] (IEEE 738, EN 50183)
    const RHO_AL: f64 = 2703.0;
    /// density of zinc-coated steel wire \[kg/m^3\]
    const RHO_ST: f64 = 7780.0;
    /// offset between the kelvin and Celsius scales \[K\]
    const C_TO_K: f64 = 273.15;

    /// Resistivity at 20 C of the outer wires' metal \[ohm m\]: 1350-H19 / AL1 aluminium (61 % IACS) for
    /// ACSR, 6201-T81 / AL3 alloy (52.5 % IACS, EN 50183) for AAAC.
    fn resistivity_20c(kind: ConductorKind) -> f64 {
        match kind {
            ConductorKind::Acsr => 2.8264e-8,
            ConductorKind::Aaac => 3.284e-8,
        }
    }

    /// The resistance line through the two reference points: its value at 20 C \[ohm/m\] and its slope
    /// \[ohm/(m K)\].
    fn interpolated_at_20c(c: &CatalogConductor) -> (f64, f64) {
        let slope =
            (c.resistance_high_ohm_per_m - c.resistance_low_ohm_per_m) / (c.temperature_high_k - c.temperature_low_k);
        (c.resistance_low_ohm_per_m + slope * (20.0 + C_TO_K - c.temperature_low_k), slope)
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn the_file_parses_and_holds_the_promised_conductors() {
        let names: Vec<&str> = catalog().iter().map(|c| c.name.as_str()).collect();
        for want in ["ACSR Drake", "ACSR Linnet", "ACSR Zebra", "AAAC 366-AL3"] {
            assert!(names.contains(&want), "{want} missing from {names:?}");
        }
        for c in catalog() {
            assert!(!c.source.trim().is_empty(), "{}: no source", c.name);
            assert!(!c.aliases.is_empty(), "{}: no alias", c.name);
        }
    }

    #[test]
    fn linear_density_is_the_areas_times_the_densities_within_3_percent() {
        // Stranding lengthens every wire but the centre one by 1-3 % (lay ratios 10-16).
        for c in catalog() {
            let from_areas = c.aluminium_area_m2 * RHO_AL + c.steel_area_m2 * RHO_ST;
            let e = rel(c.linear_density_kg_per_m, from_areas);
            assert!(
                e <= 0.03,
                "{}: m = {} kg/m vs A rho = {from_areas} kg/m ({e:.4})",
                c.name,
                c.linear_density_kg_per_m
            );
            // and the stranding only ever adds length
            assert!(c.linear_density_kg_per_m >= from_areas, "{}: lighter than its straight wires", c.name);
        }
    }

    #[test]
    fn layer_masses_add_up_to_the_linear_density_within_1_percent() {
        for c in catalog() {
            let sum = c.outer_mass_kg_per_m + c.core_mass_kg_per_m;
            let e = rel(sum, c.linear_density_kg_per_m);
            assert!(e <= 0.01, "{}: m_a + m_s = {sum} vs m = {} ({e:.4})", c.name, c.linear_density_kg_per_m);
        }
    }

    #[test]
    fn dc_resistance_of_the_aluminium_area_is_the_interpolated_resistance_at_20c_within_10_percent() {
        // rho / A_al ignores the longer stranded wires (+1-3 %), the skin effect (+1-2 % at 50-60 Hz) and the
        // steel's small share of the current (-1 %): 10 % is far above those and far below a unit error.
        for c in catalog() {
            let (r20, _) = interpolated_at_20c(c);
            let from_area = resistivity_20c(c.kind) / c.aluminium_area_m2;
            let e = rel(r20, from_area);
            assert!(e <= 0.10, "{}: R(20 C) = {r20:e} vs rho/A = {from_area:e} ({e:.4})", c.name);
        }
    }

    #[test]
    fn resistance_rises_with_temperature_at_the_metal_rate() {
        for c in catalog() {
            assert!(c.temperature_high_k > c.temperature_low_k, "{}", c.name);
            assert!(c.resistance_high_ohm_per_m > c.resistance_low_ohm_per_m, "{}", c.name);
            // The relative slope at 20 C is that of the metal (AL1 4.03e-3 /K, AL3 3.6e-3 /K) give or take
            // the skin effect, which falls as R rises: between 3e-3 and 4.5e-3 /K.
            let (r20, slope) = interpolated_at_20c(c);
            let alpha = slope / r20;
            assert!((3.0e-3..=4.5e-3).contains(&alpha), "{}: alpha = {alpha:e} /K", c.name);
        }
    }

    #[test]
    fn diameters_and_areas_are_consistent() {
        for c in catalog() {
            let disc = std::f64::consts::PI * c.diameter_m * c.diameter_m / 4.0;
            assert!(disc >= c.total_area_m2(), "{}: pi D^2/4 = {disc:e} < A = {:e}", c.name, c.total_area_m2());
            // round wires fill 70-90 % of the disc
            let fill = c.total_area_m2() / disc;
            assert!((0.70..=0.90).contains(&fill), "{}: fill factor {fill}", c.name);
            assert!(c.outer_strand_diameter_m > 0.0 && 2.0 * c.outer_strand_diameter_m < c.diameter_m, "{}", c.name);
            assert!(c.core_diameter_m + 2.0 * c.outer_strand_diameter_m <= c.diameter_m + 1e-9, "{}", c.name);
            match c.kind {
                ConductorKind::Acsr => {
                    assert!(
                        c.core_diameter_m > 0.0 && c.steel_area_m2 > 0.0 && c.core_mass_kg_per_m > 0.0,
                        "{}",
                        c.name
                    );
                    let core_disc = std::f64::consts::PI * c.core_diameter_m * c.core_diameter_m / 4.0;
                    assert!(core_disc >= c.steel_area_m2, "{}: the steel does not fit in the core", c.name);
                }
                ConductorKind::Aaac => {
                    assert!(
                        c.core_diameter_m == 0.0 && c.steel_area_m2 == 0.0 && c.core_mass_kg_per_m == 0.0,
                        "{}",
                        c.name
                    );
                }
            }
        }
    }

    #[test]
    fn mechanical_data_are_plausible() {
        for c in catalog() {
            // final moduli of stranded conductors: 50-90 GPa (AAAC about 55, ACSR 26/7 about 77)
            let e = c.axial_stiffness_n / c.total_area_m2();
            assert!((50e9..=90e9).contains(&e), "{}: E = {e:e} Pa", c.name);
            // breaking stress of the whole section: 200-400 MPa
            let s = c.rated_tensile_strength_n / c.total_area_m2();
            assert!((200e6..=400e6).contains(&s), "{}: RTS / A = {s:e} Pa", c.name);
            assert!((15e-6..=25e-6).contains(&c.thermal_expansion_per_k), "{}", c.name);
            for v in [c.emissivity, c.absorptivity] {
                assert!(v > 0.0 && v <= 1.0, "{}", c.name);
            }
            assert!((1.0..=1.1).contains(&c.magnetic_core_factor), "{}", c.name);
        }
    }

    #[test]
    fn drake_reproduces_ieee_738_annex_b_and_tb_601_exactly() {
        let t = find("drake").unwrap().thermal();
        assert_eq!(t.name, "ACSR Drake");
        // IEEE Std 738-2012 Annex B
        assert_eq!(t.diameter_m, 28.14e-3);
        assert_eq!(t.resistance_low_ohm_per_m, 7.283e-5);
        assert_eq!(t.temperature_low_k, 25.0 + C_TO_K);
        assert_eq!(t.resistance_high_ohm_per_m, 8.688e-5);
        assert_eq!(t.temperature_high_k, 75.0 + C_TO_K);
        assert_eq!((t.emissivity, t.absorptivity), (0.8, 0.8));
        assert_eq!(t.magnetic_core_factor, 1.0);
        // CIGRE TB 601 examples: core, layer masses, specific heats and their coefficients
        assert_eq!(t.core_diameter_m, 10.4e-3);
        assert_eq!(t.outer_mass_kg_per_m, 1.116);
        assert_eq!(t.outer_specific_heat_j_per_kg_k, 897.0);
        assert_eq!(t.core_mass_kg_per_m, 0.5119);
        assert_eq!(t.core_specific_heat_j_per_kg_k, 481.0);
        assert_eq!(t.outer_specific_heat_coefficient_per_k, 3.8e-4);
        assert_eq!(t.core_specific_heat_coefficient_per_k, 1.0e-4);
        // ASTM B232: 0.1749 in outer wires
        assert_eq!(t.outer_strand_diameter_m, 4.44e-3);
        let c = find("drake").unwrap();
        assert_eq!(c.linear_density_kg_per_m, 1.628);
        // 31,200 lbf, to the 0.1 kN written in the file
        assert!((c.rated_tensile_strength_n - 31_200.0 * 4.448_221_615_260_5).abs() < 50.0);
        // the heat capacity m_a c_a + m_s c_s = 1247.3 J/(m K)
        assert!((t.heat_capacity_j_per_m_k() - (1.116 * 897.0 + 0.5119 * 481.0)).abs() < 1e-9);
    }

    #[test]
    fn every_name_and_alias_finds_its_own_entry() {
        for c in catalog() {
            for n in std::iter::once(&c.name).chain(&c.aliases) {
                assert_eq!(find(n).unwrap().name, c.name, "{n}");
                assert_eq!(find(&format!("  {}\t", n.to_uppercase())).unwrap().name, c.name, "{n}");
            }
        }
    }

    #[test]
    fn find_ignores_case_and_surrounding_whitespace() {
        assert_eq!(find("drake").unwrap().name, "ACSR Drake");
        assert_eq!(find("  ACSR Drake ").unwrap().name, "ACSR Drake");
        assert_eq!(find("795 KCMIL 26/7").unwrap().name, "ACSR Drake");
        assert_eq!(find("linnet").unwrap().name, "ACSR Linnet");
        assert_eq!(find("Zebra").unwrap().kind, ConductorKind::Acsr);
        assert_eq!(find("aster 366").unwrap().kind, ConductorKind::Aaac);
        // inner whitespace is part of the name
        assert!(find("ACSR  Drake").is_err());
    }

    #[test]
    fn an_unknown_name_fails_with_the_names_available() {
        let e = find("nope").unwrap_err();
        let CatalogError::NotFound { asked, available } = &e else { panic!("{e:?}") };
        assert_eq!(asked, "nope");
        assert_eq!(available.len(), catalog().len());
        let msg = e.to_string();
        assert!(msg.contains("\"nope\""), "{msg}");
        for c in catalog() {
            assert!(msg.contains(&c.name), "{msg} lacks {}", c.name);
        }
    }

    #[test]
    fn parse_rejects_duplicates_unknown_and_missing_fields() {
        // the built-in text with Drake's table repeated under a new name but the old alias "drake"
        let drake = CATALOG_TOML.split("\n[[conductor]]\n").nth(1).unwrap();
        assert!(drake.starts_with("name = \"ACSR Drake\""), "{drake}");
        let twice = format!("{CATALOG_TOML}\n[[conductor]]\n{}", drake.replacen("\"ACSR Drake\"", "\"Drake copy\"", 1));
        assert_eq!(parse(&twice), Err(CatalogError::Duplicate("drake".into())));

        let unknown =
            CATALOG_TOML.replacen("magnetic_core_factor = 1.0", "magnetic_core_factor = 1.0\ncolour = \"grey\"", 1);
        assert!(matches!(parse(&unknown), Err(CatalogError::Parse(m)) if m.contains("colour")));

        let missing = CATALOG_TOML.replacen("emissivity = 0.8\n", "", 1);
        assert!(matches!(parse(&missing), Err(CatalogError::Parse(m)) if m.contains("emissivity")));

        assert!(matches!(parse("[[conductor]]\nkind = \"ACSS\""), Err(CatalogError::Parse(_))));
    }

    #[test]
    fn linear_stress_strain_data_reproduce_the_entry_s_ea_and_expansion_below_the_knee() {
        // The split moduli (header of data/conductors.toml) are rounded to 5 digits: K_o + K_c = EA and the
        // K-weighted expansion = alpha within 1e-4 relative.
        use crate::conductor::CurveKind;
        for c in catalog() {
            let (Some(law), Some(d)) = (c.two_material(), &c.stress_strain) else { continue };
            if d.outer.initial_pa_percent.is_some() {
                continue;
            }
            let h = law.virgin(CurveKind::Initial);
            let k: f64 = law.stiffness(1e-3, law.reference_temperature_k, &h);
            assert!(rel(k, c.axial_stiffness_n) < 1e-4, "{}: K = {k:e}, EA = {:e}", c.name, c.axial_stiffness_n);
            let ko = law.outer.unloading_stiffness_n;
            let kc = law.core.map_or(0.0, |m| m.unloading_stiffness_n);
            let alpha = (ko * law.outer.expansion_per_k + kc * law.core.map_or(0.0, |m| m.expansion_per_k)) / (ko + kc);
            assert!(rel(alpha, c.thermal_expansion_per_k) < 1e-4, "{}: alpha = {alpha:e}", c.name);
            // And the tension 30 K above the reference at a strain 1e-3 is the linear law's.
            let theta = law.reference_temperature_k + 30.0;
            let t = law.tension(1e-3, theta, &h);
            let linear = c.axial_stiffness_n * (1e-3 - c.thermal_expansion_per_k * 30.0);
            assert!(rel(t, linear) < 1e-3, "{}: {t} vs {linear}", c.name);
        }
    }

    #[test]
    fn drake_s_curves_are_the_published_polynomials_in_psi_on_0_7264_square_inches() {
        // Evaluate the published coefficients (psi, strain in %; OTLS-Models test/factory.cc) directly and
        // compare with the law's forces: the conversion to SI is then checked to the 7 digits the file keeps.
        use crate::conductor::CurveKind;
        let law = find("drake").unwrap().two_material().expect("Drake has stress-strain data");
        let area_in2 = 0.7264;
        let lbf = 4.4482216;
        let poly = |a: [f64; 5], x: f64| a[0] + a[1] * x + a[2] * x * x + a[3] * x.powi(3) + a[4] * x.powi(4);
        let al = [-1213.0, 44308.1, -14004.4, -37618.0, 30676.0];
        let st = [-69.3, 38629.0, 3998.1, -45713.0, 27892.0];
        let h = law.virgin(CurveKind::Initial);
        for x in [0.1, 0.2, 0.3, 0.5] {
            let f = law.forces(x / 100.0, law.reference_temperature_k, &h);
            let want = [poly(al, x) * area_in2 * lbf, poly(st, x) * area_in2 * lbf];
            for k in 0..2 {
                assert!((f[k] - want[k]).abs() < 1e-6 * want[k].abs().max(1e3), "x = {x} %: {:?} vs {want:?}", f);
            }
        }
        // The final moduli add up to 101000 psi/% on 0.7264 in^2: 69.64 GPa.
        let k = law.outer.unloading_stiffness_n + law.core.unwrap().unloading_stiffness_n;
        assert!(rel(k / 4.68644e-4, 101000.0 * 100.0 * 6894.757) < 1e-6);
    }

    #[test]
    fn a_user_catalogue_with_a_curve_that_is_not_a_loading_curve_names_the_field() {
        let drake = CATALOG_TOML.split("\n[[conductor]]\n").nth(1).unwrap();
        // The aluminium's initial curve turned down (a4 negative): it peaks near 0.5 % at 75 MPa and never
        // reaches its stated limit of 140 MPa.
        let bad = format!("[[conductor]]\n{}", drake.replacen("2.115036e8", "-2.115036e8", 1));
        let err = parse(&bad).unwrap_err().to_string();
        assert!(err.contains("\"ACSR Drake\"") && err.contains("stress_strain.outer.initial_pa_percent"), "{err}");
        let bad =
            format!("[[conductor]]\n{}", drake.replacen("expansion_per_k = 23.04e-6", "expansion_per_k = 2.3e-3", 1));
        let err = parse(&bad).unwrap_err().to_string();
        assert!(err.contains("stress_strain.outer.expansion_per_k = 0.0023") && err.contains("[0e0, 5e-5]"), "{err}");
    }
}
