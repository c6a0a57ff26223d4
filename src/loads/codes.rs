//! Combined ice-and-wind load cases of the design codes as named presets: data only (one table,
//! [`CASES`]). A preset fixes what its code fixes and names what the user must still choose (a loading
//! district is the choice itself for the NESC; a reliability level, return period or national annex
//! value for IEC 60826 and EN 50341-1): those are explicit inputs ([`Inputs`]), never silent defaults.
//! docs/loads.md states what each preset contains and where it comes from.
//!
//! Wind pressure `q` [Pa] on the projected (iced) diameter becomes the scenario's aerodynamic law with
//! drag coefficient `C` = `normal_coefficient` (tangential 0) and wind speed from `q = rho_air U^2 / 2`:
//!
//! ```text
//! U = sqrt(2 q / rho_air),   load per metre  q C (d + 2 t)
//! ```
//!
//! NESC Rule 250B adds a constant `K` [N/m] to the resultant of weight and wind. In a static state the
//! resultant has one direction along the span (for a level span, uniform loads), so `K` along that
//! direction is the scenario's `loads.uniform_load_n_per_m = K (w_h, 0, -w_v) / |(w_h, w_v)|`, with `w_h`
//! the wind and `w_v` the weight per metre (wind along `x1`); [`Resolved::nesc_k_vector`] forms it.

/// Air density of the conversion pressure to speed [kg/m^3]: the standard atmosphere at sea level and 15 C
/// (ISO 2533), the value the scenario's `[loads.wind] air_density_kg_per_m3` defaults to.
pub const AIR_DENSITY_KG_PER_M3: f64 = 1.225;

/// NESC ice density 57 lb/ft^3 [kg/m^3] (NESC Rule 251; 57 * 0.45359237 / 0.3048^3 = 913.05, given as 913).
pub const NESC_ICE_DENSITY_KG_PER_M3: f64 = 913.0;

/// One load case of a code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoadCase {
    /// the name a user cites (`ohl load-case NAME`)
    pub name: &'static str,
    /// the code and the clause
    pub source: &'static str,
    /// radial ice thickness `t` [m]; `None`: an input
    pub radial_ice_m: Option<f64>,
    /// ice density [kg/m^3]; `None`: an input
    pub ice_density_kg_per_m3: Option<f64>,
    /// wind pressure on the projected iced diameter [Pa]; `None`: an input (pressure or speed)
    pub wind_pressure_pa: Option<f64>,
    /// drag (force) coefficient on the projected diameter [-]; `None`: an input
    pub drag_coefficient: Option<f64>,
    /// air temperature of the case [C]; `None`: an input
    pub temperature_c: Option<f64>,
    /// constant added to the resultant load [N/m] (NESC `K`; 0 elsewhere)
    pub constant_k_n_per_m: f64,
    /// what the user must still choose, in the code's words
    pub user_chooses: &'static str,
}

/// The presets. NESC: Rule 250B, Table 250-1 (ice, pressure, temperature), Rule 251 (ice density) and Table
/// 251-1 (`K`), in the
/// code's metric values. IEC 60826 and EN 50341-1: the code fixes the method (ice as a concentric
/// cylinder, the wind on the iced diameter, a coincident reduced wind) but every number is a site,
/// reliability-level or national-annex value: they are inputs (docs/loads.md).
pub const CASES: &[LoadCase] = &[
    LoadCase {
        name: "nesc_heavy",
        source: "NESC (IEEE C2) Rule 250B, heavy loading district (Table 250-1; ice density and K: Rule 251, Table 251-1)",
        radial_ice_m: Some(0.0125),
        ice_density_kg_per_m3: Some(NESC_ICE_DENSITY_KG_PER_M3),
        wind_pressure_pa: Some(190.0),
        drag_coefficient: Some(1.0),
        temperature_c: Some(-20.0),
        constant_k_n_per_m: 4.4,
        user_chooses: "the loading district (from the NESC map); the load factors of the grade of construction",
    },
    LoadCase {
        name: "nesc_medium",
        source: "NESC (IEEE C2) Rule 250B, medium loading district (Table 250-1; ice density and K: Rule 251, Table 251-1)",
        radial_ice_m: Some(0.0065),
        ice_density_kg_per_m3: Some(NESC_ICE_DENSITY_KG_PER_M3),
        wind_pressure_pa: Some(190.0),
        drag_coefficient: Some(1.0),
        temperature_c: Some(-10.0),
        constant_k_n_per_m: 2.5,
        user_chooses: "the loading district (from the NESC map); the load factors of the grade of construction",
    },
    LoadCase {
        name: "nesc_light",
        source: "NESC (IEEE C2) Rule 250B, light loading district (Table 250-1; ice density and K: Rule 251, Table 251-1)",
        radial_ice_m: Some(0.0),
        ice_density_kg_per_m3: Some(NESC_ICE_DENSITY_KG_PER_M3),
        wind_pressure_pa: Some(430.0),
        drag_coefficient: Some(1.0),
        temperature_c: Some(-1.0),
        constant_k_n_per_m: 0.7,
        user_chooses: "the loading district (from the NESC map); the load factors of the grade of construction",
    },
    LoadCase {
        name: "iec60826_ice_wind",
        source: "IEC 60826 (design criteria of overhead lines), combined wind and ice loadings (clause 6.4)",
        radial_ice_m: None,
        ice_density_kg_per_m3: None,
        wind_pressure_pa: None,
        drag_coefficient: None,
        temperature_c: None,
        constant_k_n_per_m: 0.0,
        user_chooses: "the reliability level and its return period T; the ice of that return period (as a thickness, \
                       from the ice weight g and the ice type's density); the wind velocity coincident with that ice \
                       (low or high probability, as the combination requires); the drag coefficient of the iced \
                       conductor; the temperature",
    },
    LoadCase {
        name: "en50341_ice_wind",
        source: "EN 50341-1 (overhead electrical lines exceeding AC 1 kV), combined wind and ice loads (clause 4.6), \
                 with the national normative aspects (NNA) of the country",
        radial_ice_m: None,
        ice_density_kg_per_m3: None,
        wind_pressure_pa: None,
        drag_coefficient: None,
        temperature_c: None,
        constant_k_n_per_m: 0.0,
        user_chooses: "the national annex (NNA) values: the characteristic ice load and its ice type and density, the \
                       wind coincident with ice (the reduced wind of the combination), the drag factor of the iced \
                       conductor and the temperature",
    },
];

/// The preset named `name`.
pub fn case(name: &str) -> Option<&'static LoadCase> {
    CASES.iter().find(|c| c.name == name)
}

/// Wind speed [m/s] whose dynamic pressure `rho_air U^2 / 2` is `q` [Pa].
pub fn wind_speed_m_per_s(pressure_pa: f64, air_density_kg_per_m3: f64) -> f64 {
    (2.0 * pressure_pa / air_density_kg_per_m3).sqrt()
}

/// The user's values for what a preset leaves open (each also overrides a preset's value).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Inputs {
    /// radial ice thickness [m]
    pub radial_ice_m: Option<f64>,
    /// ice density [kg/m^3]
    pub ice_density_kg_per_m3: Option<f64>,
    /// wind pressure [Pa] (or give the speed)
    pub wind_pressure_pa: Option<f64>,
    /// wind speed [m/s] (or give the pressure)
    pub wind_speed_m_per_s: Option<f64>,
    /// drag coefficient [-]
    pub drag_coefficient: Option<f64>,
    /// air temperature [C]
    pub temperature_c: Option<f64>,
}

/// A preset with every value given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolved {
    /// the preset
    pub case: &'static LoadCase,
    /// radial ice [m]
    pub radial_ice_m: f64,
    /// ice density [kg/m^3]
    pub ice_density_kg_per_m3: f64,
    /// wind speed [m/s] (from the pressure with [`AIR_DENSITY_KG_PER_M3`], or given)
    pub wind_speed_m_per_s: f64,
    /// drag coefficient [-]
    pub drag_coefficient: f64,
    /// air temperature [C]
    pub temperature_c: f64,
}

/// What is missing or conflicting when a preset is resolved.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum LoadCaseError {
    /// no preset of that name
    #[error("no load case named {0:?}; the load cases are: {1}")]
    Unknown(String, String),
    /// a value the preset leaves to the user was not given
    #[error("load case {case} needs {input}: {chooses}")]
    Missing {
        /// the preset
        case: &'static str,
        /// the input's option name
        input: &'static str,
        /// what the code leaves to the user
        chooses: &'static str,
    },
    /// both the wind pressure and the wind speed were given
    #[error("give the wind as a pressure or as a speed, not both")]
    WindTwice,
}

/// Resolve preset `name` with the user's `inputs` (an input overrides the preset's value).
pub fn resolve(name: &str, inputs: &Inputs) -> Result<Resolved, LoadCaseError> {
    let case = case(name).ok_or_else(|| {
        LoadCaseError::Unknown(name.into(), CASES.iter().map(|c| c.name).collect::<Vec<_>>().join(", "))
    })?;
    let need = |v: Option<f64>, input: &'static str| {
        v.ok_or(LoadCaseError::Missing { case: case.name, input, chooses: case.user_chooses })
    };
    if inputs.wind_pressure_pa.is_some() && inputs.wind_speed_m_per_s.is_some() {
        return Err(LoadCaseError::WindTwice);
    }
    let wind_speed_m_per_s = match inputs.wind_speed_m_per_s {
        Some(u) => u,
        None => wind_speed_m_per_s(
            need(inputs.wind_pressure_pa.or(case.wind_pressure_pa), "--wind-pressure-pa or --wind-speed-m-per-s")?,
            AIR_DENSITY_KG_PER_M3,
        ),
    };
    Ok(Resolved {
        case,
        radial_ice_m: need(inputs.radial_ice_m.or(case.radial_ice_m), "--radial-ice-m")?,
        ice_density_kg_per_m3: need(
            inputs.ice_density_kg_per_m3.or(case.ice_density_kg_per_m3),
            "--ice-density-kg-per-m3",
        )?,
        wind_speed_m_per_s,
        drag_coefficient: need(inputs.drag_coefficient.or(case.drag_coefficient), "--drag-coefficient")?,
        temperature_c: need(inputs.temperature_c.or(case.temperature_c), "--temperature-c")?,
    })
}

impl Resolved {
    /// The NESC constant as a uniform load [N/m] along the resultant of the weight `w_v` [N/m] (bare plus
    /// ice) and the wind `w_h` [N/m] (along `x1`): `K (w_h, 0, -w_v) / |(w_h, w_v)|` (module doc).
    pub fn nesc_k_vector(&self, weight_n_per_m: f64, wind_n_per_m: f64) -> [f64; 3] {
        let k = self.case.constant_k_n_per_m;
        let r = weight_n_per_m.hypot(wind_n_per_m);
        [k * wind_n_per_m / r, 0.0, -k * weight_n_per_m / r]
    }

    /// The scenario's TOML for this case on a conductor of diameter `d` [m] and linear density `rho0`
    /// [kg/m] under gravity `g` [m/s^2]: `[loads]` (the NESC `K` as a uniform load, wind across the line
    /// along `x1`), `[loads.wind]` and the ice as an `ice` event at `t = 0` (part of a static start).
    pub fn toml(&self, diameter_m: f64, linear_density_kg_per_m: f64, gravity_m_per_s2: f64) -> String {
        let ice = super::RadialIce { thickness_m: self.radial_ice_m, density_kg_per_m3: self.ice_density_kg_per_m3 };
        let weight = (linear_density_kg_per_m + ice.kg_per_m(diameter_m)) * gravity_m_per_s2;
        let q = 0.5 * AIR_DENSITY_KG_PER_M3 * self.wind_speed_m_per_s.powi(2);
        let wind = q * self.drag_coefficient * ice.iced_diameter_m(diameter_m);
        let k = self.nesc_k_vector(weight, wind);
        let mut s = format!(
            "# load case {} ({})\n# ice {} m radial, {} kg/m^3: {:.4} kg/m; wind {:.4} m/s (q = {:.2} Pa, C = {}) on \
             the iced diameter {:.5} m: {:.4} N/m; weight {:.4} N/m\n# temperature {} C ({:.2} K): set the conductor's \
             state for it (conductor.reference_temperature_k with thermal_expansion_per_k, or a temperature event)\n",
            self.case.name,
            self.case.source,
            self.radial_ice_m,
            self.ice_density_kg_per_m3,
            ice.kg_per_m(diameter_m),
            self.wind_speed_m_per_s,
            q,
            self.drag_coefficient,
            ice.iced_diameter_m(diameter_m),
            wind,
            weight,
            self.temperature_c,
            self.temperature_c + 273.15,
        );
        if self.case.constant_k_n_per_m != 0.0 {
            s += &format!(
                "[loads]\n# NESC constant K = {} N/m along the static resultant of weight and wind\n\
                 uniform_load_n_per_m = [{:.6}, 0.0, {:.6}]\n\n",
                self.case.constant_k_n_per_m, k[0], k[2]
            );
        }
        s += &format!(
            "[loads.wind]\nlaw = \"aerodynamic\"\ndirection = [1.0, 0.0, 0.0]\nspeed_m_per_s = {:.6}\n\
             air_density_kg_per_m3 = {AIR_DENSITY_KG_PER_M3:?}\nnormal_coefficient = {:?}\ntangential_coefficient = 0.0\n\n\
             [[events]]\ntime_s = 0.0\naction = \"ice\"\nradial_thickness_m = {:?}\ndensity_kg_per_m3 = {:?}\n",
            self.wind_speed_m_per_s, self.drag_coefficient, self.radial_ice_m, self.ice_density_kg_per_m3
        );
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nesc_presets_hold_the_values_docs_loads_md_states() {
        // docs/loads.md, table "NESC Rule 250B": (name, t [mm], p [Pa], T [C], K [N/m]), ice 913 kg/m^3.
        let table = [
            ("nesc_heavy", 12.5, 190.0, -20.0, 4.4),
            ("nesc_medium", 6.5, 190.0, -10.0, 2.5),
            ("nesc_light", 0.0, 430.0, -1.0, 0.7),
        ];
        for (name, t_mm, p, temp, k) in table {
            let r = resolve(name, &Inputs::default()).unwrap();
            assert_eq!(r.radial_ice_m, t_mm / 1000.0, "{name}");
            assert_eq!(r.ice_density_kg_per_m3, 913.0, "{name}");
            assert_eq!(r.temperature_c, temp, "{name}");
            assert_eq!(r.case.constant_k_n_per_m, k, "{name}");
            assert_eq!(r.drag_coefficient, 1.0, "{name}");
            // q = rho U^2 / 2 gives back the pressure (to rounding, 1e-14 relative).
            let q = 0.5 * 1.225 * r.wind_speed_m_per_s.powi(2);
            assert!((q - p).abs() < 1e-12 * p, "{name}: {q} vs {p}");
        }
        // The docs' speeds: 190 Pa -> 17.61 m/s, 430 Pa -> 26.50 m/s.
        assert!((wind_speed_m_per_s(190.0, 1.225) - 17.61).abs() < 0.005);
        assert!((wind_speed_m_per_s(430.0, 1.225) - 26.50).abs() < 0.005);
        // 57 lb/ft^3 in kg/m^3 (0.45359237 kg/lb, 0.3048 m/ft, exact definitions): 913.05.
        assert!((57.0 * 0.45359237 / 0.3048_f64.powi(3) - NESC_ICE_DENSITY_KG_PER_M3).abs() < 0.06);
    }

    #[test]
    fn code_presets_refuse_to_guess_what_the_user_must_choose() {
        let e = resolve("iec60826_ice_wind", &Inputs::default()).unwrap_err();
        assert!(matches!(e, LoadCaseError::Missing { input: "--wind-pressure-pa or --wind-speed-m-per-s", .. }));
        let all = Inputs {
            radial_ice_m: Some(0.02),
            ice_density_kg_per_m3: Some(900.0),
            wind_speed_m_per_s: Some(18.0),
            drag_coefficient: Some(1.0),
            temperature_c: Some(-5.0),
            ..Inputs::default()
        };
        let r = resolve("en50341_ice_wind", &all).unwrap();
        assert_eq!((r.radial_ice_m, r.wind_speed_m_per_s), (0.02, 18.0));
        let no_t = Inputs { temperature_c: None, ..all };
        assert!(matches!(
            resolve("iec60826_ice_wind", &no_t),
            Err(LoadCaseError::Missing { input: "--temperature-c", .. })
        ));
        let twice = Inputs { wind_pressure_pa: Some(300.0), ..all };
        assert_eq!(resolve("iec60826_ice_wind", &twice), Err(LoadCaseError::WindTwice));
        assert!(matches!(resolve("nesc_extreme", &all), Err(LoadCaseError::Unknown(..))));
    }

    #[test]
    fn nesc_k_lies_along_the_resultant_and_adds_to_its_magnitude() {
        let r = resolve("nesc_heavy", &Inputs::default()).unwrap();
        let (w, h) = (30.0, 12.0);
        let k = r.nesc_k_vector(w, h);
        let total = [h + k[0], -w + k[2]];
        assert!((total[0].hypot(total[1]) - (w.hypot(h) + 4.4)).abs() < 1e-12);
        assert!((k[0] / -k[2] - h / w).abs() < 1e-15);
    }
}
