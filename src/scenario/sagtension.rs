//! The file of a sag-tension case (`ohl sagtension CASE.toml`, `ohl.sagtension` in Python): a conductor,
//! a span (or a ruling span), how it was strung, the creep and heavy-load weathers that stretch it, and
//! the list of weathers (conditions) its table is asked for; optionally a clearance or sag limit, for
//! the temperature at which it is reached. The model (the two-material law of [`crate::conductor`], the
//! change of state of the span) lives in the library's sag-tension solver; this module only reads and
//! validates the file, and resolves the named load cases of the codes ([`crate::loads::codes`]) into
//! plain weathers ([`Weather`]).
//!
//! ```toml
//! name = "Drake 700 ft"
//! [conductor]
//! catalog = "ACSR Drake"                   # a name of data/conductors.toml (or of conductor_catalog)
//! # conductor_catalog = "my.toml"          # optional user catalogue, relative to this file's folder
//! [span]                                   # or [ruling_span] lengths_m = [...]
//! length_m = 213.36
//! rise_m = 0.0
//! [stringing]
//! tension_n = 28024.0                      # or tension_fraction_of_rts, or sag_m
//! temperature_c = 15.56
//! state = "initial"                        # or "final"
//! [heavy_load]
//! case = "nesc_heavy"                      # or its weather: temperature, ice, wind, constant
//! [[condition]]
//! temperature_c = -20.0
//! [conditions]                             # a temperature range besides (or instead of) [[condition]]
//! from_temperature_c = -20.0
//! to_temperature_c = 100.0
//! temperature_step_k = 10.0
//! load_cases = ["nesc_heavy"]
//! [clearance]
//! max_sag_m = 9.0                          # or support_heights_m = [hA, hB] with min_clearance_m
//! ```
//!
//! A weather ([`WeatherSpec`]) is a conductor temperature, a radial ice thickness and density, a wind
//! pressure on the projected iced diameter with its drag coefficient, and the NESC constant `K` added to
//! the resultant load (NESC Rule 250B); a named load case (`case = "nesc_heavy"`, `ohl load-case list`)
//! gives what its code fixes, and a field written beside it overrides it. Every temperature has its
//! Celsius twin (`_c`, [`super::temperature`]).

use serde::Deserialize;

use super::range::{ICE_DENSITY_KG_PER_M3, RADIAL_ICE_M, Range as Allowed, SAG_TEMPERATURE_K};
use super::validate::{Check, MAX_SPAN_M, number};
use super::{InputError, Problem};
use crate::conductor::{Component, TwoMaterial};
use crate::loads::codes;
use crate::sagtension as sag;
use crate::thermal::catalog::{self, CatalogConductor};

/// Wind pressure on the projected (iced) diameter [Pa]: 5 kPa is the dynamic pressure of a 90 m/s wind,
/// above every design wind (validate::MAX_WIND_SPEED_M_PER_S is 100 m/s).
pub const WIND_PRESSURE_PA: Allowed = Allowed::closed(0.0, 5000.0, "Pa");

/// Drag (force) coefficient of the conductor on its projected diameter [-] (about 1 for a stranded or iced
/// conductor; NESC Rule 250B takes 1.0).
pub const DRAG_COEFFICIENT: Allowed = Allowed::open_closed(0.0, 3.0, "");

/// The NESC constant `K` added to the resultant load [N/m] (Table 251-1: 0.7 to 4.4 N/m).
pub const CONSTANT_N_PER_M: Allowed = Allowed::closed(0.0, 100.0, "N/m");

/// A span length [m].
pub const SPAN_LENGTH_M: Allowed = Allowed::open_closed(0.0, MAX_SPAN_M, "m");

/// A stringing tension [N].
pub const STRINGING_TENSION_N: Allowed = Allowed::open_closed(0.0, 1.0e7, "N");

/// A stringing tension as a fraction of the rated tensile strength [-].
pub const RTS_FRACTION: Allowed = Allowed::open(0.0, 1.0, "");

/// A sag, sag limit, clearance or support height [m].
pub const LENGTH_LIMIT_M: Allowed = Allowed::open_closed(0.0, 1.0e3, "m");

/// A temperature step of a range of conditions [K].
pub const TEMPERATURE_STEP_K: Allowed = Allowed::closed(0.1, 100.0, "K");

/// Largest number of conditions of a table [-].
pub const MAX_CONDITIONS: usize = 1000;

/// Largest number of spans of a ruling span [-].
pub const MAX_RULING_SPANS: usize = 1000;

/// Default ice density [kg/m^3]: the NESC's 57 lb/ft^3 (Rule 251, [`codes::NESC_ICE_DENSITY_KG_PER_M3`]), the
/// density of the published sag-tension tables this command is checked against (docs/sagtension_references.md).
pub const DEFAULT_ICE_DENSITY_KG_PER_M3: f64 = codes::NESC_ICE_DENSITY_KG_PER_M3;

/// Default drag coefficient [-]: 1.0, the NESC's for a cylindrical conductor (Rule 250B).
pub const DEFAULT_DRAG_COEFFICIENT: f64 = 1.0;

/// The `[conductor]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConductorTable {
    /// the conductor's name in the catalogue (`data/conductors.toml`) or in `conductor_catalog`; its
    /// stress-strain data (the two-material law) come from there, else it is the single-modulus conductor of
    /// its `axial_stiffness_n` and `thermal_expansion_per_k`
    pub catalog: String,
    /// a user conductor catalogue (the format of `data/conductors.toml`): its path relative to the case
    /// file's folder; its names are looked up before the built-in ones
    #[serde(default)]
    pub conductor_catalog: Option<String>,
}

/// One span (`[span]`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpanSpec {
    /// horizontal span length [m], in (0, 1e4]
    pub length_m: f64,
    /// height of the far support above the near one [m], |rise| below the length; default 0 (level)
    #[serde(default)]
    pub rise_m: f64,
}

/// A ruling span (`[ruling_span]`): the level spans of a tension section between dead-ends, whose
/// suspension strings equalise the horizontal tension.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RulingSpanSpec {
    /// the spans' horizontal lengths [m], each in (0, 1e4], 1 to 1000 spans
    pub lengths_m: Vec<f64>,
}

/// Whether a stringing tension or sag is of the conductor as strung or after creep.
#[derive(Clone, Copy, Debug, Default, Deserialize, serde::Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum StateSpec {
    /// as strung (new conductor, initial curves) (default)
    #[default]
    Initial,
    /// after creep and the heavy load (final curves)
    Final,
}

/// Where a stretch is taken in the span (`stretch_point`).
#[derive(Clone, Copy, Debug, Default, Deserialize, serde::Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum StretchPointSpec {
    /// the support with the larger tension (default)
    #[default]
    MostStrained,
    /// the length-averaged tension
    AverageTension,
}

/// A weather of a sag-tension table: the conductor temperature and its loads.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WeatherSpec {
    /// a label for the table (free text); default the named case or the temperature
    #[serde(default)]
    pub label: Option<String>,
    /// a named load case of a code (`ohl load-case list`): its temperature, ice, wind and constant, each
    /// overridden by a field given beside it
    #[serde(default)]
    pub case: Option<String>,
    /// conductor temperature [K], in [173.15, 573.15] (required unless `case` gives it)
    #[serde(default)]
    pub temperature_k: Option<f64>,
    /// radial ice thickness [m], in [0, 0.2]; default 0 (or the case's)
    #[serde(default)]
    pub ice_thickness_m: Option<f64>,
    /// ice density [kg/m^3], in [100, 1000]; default 913 (NESC Rule 251, 57 lb/ft^3) (or the case's)
    #[serde(default)]
    pub ice_density_kg_per_m3: Option<f64>,
    /// wind pressure on the projected iced diameter [Pa], in [0, 5000]; default 0 (or the case's)
    #[serde(default)]
    pub wind_pressure_pa: Option<f64>,
    /// drag coefficient on the projected diameter [-], in (0, 3]; default 1 (NESC Rule 250B) (or the case's)
    #[serde(default)]
    pub drag_coefficient: Option<f64>,
    /// constant added to the resultant load per metre (NESC `K`) [N/m], in [0, 100]; default 0 (or the case's)
    #[serde(default)]
    pub constant_n_per_m: Option<f64>,
}

/// The `[stringing]` table: how the conductor was strung (one tension or sag at one weather).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StringingSpec {
    /// horizontal tension [N], in (0, 1e7]
    #[serde(default)]
    pub tension_n: Option<f64>,
    /// horizontal tension as a fraction of the rated tensile strength [-], in (0, 1)
    #[serde(default)]
    pub tension_fraction_of_rts: Option<f64>,
    /// mid-span sag [m], in (0, 1e3] and below half the span
    #[serde(default)]
    pub sag_m: Option<f64>,
    /// `"initial"` (as strung, default) or `"final"` (after creep and the heavy load)
    #[serde(default)]
    pub state: StateSpec,
    /// a named load case (as [`WeatherSpec::case`])
    #[serde(default)]
    pub case: Option<String>,
    /// conductor temperature [K], in [173.15, 573.15]
    #[serde(default)]
    pub temperature_k: Option<f64>,
    /// radial ice thickness [m], in [0, 0.2]; default 0
    #[serde(default)]
    pub ice_thickness_m: Option<f64>,
    /// ice density [kg/m^3], in [100, 1000]; default 913
    #[serde(default)]
    pub ice_density_kg_per_m3: Option<f64>,
    /// wind pressure [Pa], in [0, 5000]; default 0
    #[serde(default)]
    pub wind_pressure_pa: Option<f64>,
    /// drag coefficient [-], in (0, 3]; default 1
    #[serde(default)]
    pub drag_coefficient: Option<f64>,
    /// NESC constant `K` [N/m], in [0, 100]; default 0
    #[serde(default)]
    pub constant_n_per_m: Option<f64>,
}

impl StringingSpec {
    /// The stringing weather as a [`WeatherSpec`].
    pub fn weather(&self) -> WeatherSpec {
        WeatherSpec {
            label: Some("stringing".into()),
            case: self.case.clone(),
            temperature_k: self.temperature_k,
            ice_thickness_m: self.ice_thickness_m,
            ice_density_kg_per_m3: self.ice_density_kg_per_m3,
            wind_pressure_pa: self.wind_pressure_pa,
            drag_coefficient: self.drag_coefficient,
            constant_n_per_m: self.constant_n_per_m,
        }
    }
}

/// A range of conditions (`[conditions]`): bare conductor temperatures from/to/step, and named load cases.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConditionRange {
    /// first temperature [K], in [173.15, 573.15]
    #[serde(default)]
    pub from_temperature_k: Option<f64>,
    /// last temperature [K], in [173.15, 573.15], above `from`
    #[serde(default)]
    pub to_temperature_k: Option<f64>,
    /// step [K], in [0.1, 100]; default 10
    #[serde(default = "ten_kelvin")]
    pub temperature_step_k: f64,
    /// named load cases of the codes (`ohl load-case list`), each a condition
    #[serde(default)]
    pub load_cases: Vec<String>,
}

fn ten_kelvin() -> f64 {
    10.0
}

/// A clearance or sag limit (`[clearance]`): the temperature at which it is reached is reported.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClearanceSpec {
    /// largest mid-span sag [m], in (0, 1e3]
    #[serde(default)]
    pub max_sag_m: Option<f64>,
    /// heights of the two supports above level ground [m], each in (0, 1e3] (with `min_clearance_m`)
    #[serde(default)]
    pub support_heights_m: Option<[f64; 2]>,
    /// least clearance to the ground at mid-span [m], in (0, 1e3] (with `support_heights_m`)
    #[serde(default)]
    pub min_clearance_m: Option<f64>,
}

/// A file for `ohl sagtension`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SagTensionCase {
    /// short name (free text)
    #[serde(default)]
    pub name: Option<String>,
    /// the conductor
    pub conductor: ConductorTable,
    /// one span (or `ruling_span`)
    #[serde(default)]
    pub span: Option<SpanSpec>,
    /// a ruling span (or `span`)
    #[serde(default)]
    pub ruling_span: Option<RulingSpanSpec>,
    /// how the conductor was strung
    pub stringing: StringingSpec,
    /// the weather the conductor creeps in (10 years); default the stringing temperature, bare, still air
    #[serde(default)]
    pub creep: Option<WeatherSpec>,
    /// the heaviest load the conductor is stretched by (the final state's permanent set); default none
    #[serde(default)]
    pub heavy_load: Option<WeatherSpec>,
    /// the conditions of the table
    #[serde(default)]
    pub condition: Vec<WeatherSpec>,
    /// a range of conditions besides the list
    #[serde(default)]
    pub conditions: Option<ConditionRange>,
    /// a clearance or sag limit
    #[serde(default)]
    pub clearance: Option<ClearanceSpec>,
    /// where a stretch (creep, heavy load) is taken in the span: `"most_strained"` (the support with the
    /// larger tension, default) or `"average_tension"` (the length-averaged tension, as OTLS-Models and
    /// SAG10-type programs do) ([`sag::problem::StretchPoint`])
    #[serde(default)]
    pub stretch_point: StretchPointSpec,
    /// the temperature fields written in degrees Celsius (set by [`parse_case`], not a key of the file)
    #[serde(skip)]
    pub celsius: super::temperature::Celsius,
}

/// A resolved weather: every value given (the named case's, the user's, or the default).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Weather {
    /// label of the table's row
    pub label: String,
    /// conductor temperature [K]
    pub temperature_k: f64,
    /// radial ice thickness [m]
    pub ice_thickness_m: f64,
    /// ice density [kg/m^3]
    pub ice_density_kg_per_m3: f64,
    /// wind pressure on the projected iced diameter [Pa]
    pub wind_pressure_pa: f64,
    /// drag coefficient [-]
    pub drag_coefficient: f64,
    /// NESC constant [N/m]
    pub constant_n_per_m: f64,
}

impl Weather {
    /// The bare conductor at `temperature_k` in still air.
    pub fn bare(label: impl Into<String>, temperature_k: f64) -> Self {
        Weather {
            label: label.into(),
            temperature_k,
            ice_thickness_m: 0.0,
            ice_density_kg_per_m3: DEFAULT_ICE_DENSITY_KG_PER_M3,
            wind_pressure_pa: 0.0,
            drag_coefficient: DEFAULT_DRAG_COEFFICIENT,
            constant_n_per_m: 0.0,
        }
    }

    /// Horizontal wind load per metre [N/m] on a conductor of diameter `d` [m]: `q C (d + 2 t)`.
    pub fn wind_n_per_m(&self, diameter_m: f64) -> f64 {
        self.wind_pressure_pa * self.drag_coefficient * (diameter_m + 2.0 * self.ice_thickness_m)
    }

    /// Ice mass per metre [kg/m] on a conductor of diameter `d` [m]: `rho_i pi t (d + t)`.
    pub fn ice_kg_per_m(&self, diameter_m: f64) -> f64 {
        self.ice_density_kg_per_m3 * std::f64::consts::PI * self.ice_thickness_m * (diameter_m + self.ice_thickness_m)
    }

    /// Whether it is the bare conductor in still air.
    pub fn is_bare(&self) -> bool {
        self.ice_thickness_m == 0.0 && self.wind_pressure_pa == 0.0 && self.constant_n_per_m == 0.0
    }
}

/// The case resolved: the conductor's catalogue entry and every weather as plain values.
#[derive(Clone, Debug)]
pub struct Resolved {
    /// the catalogue entry of the conductor
    pub conductor: CatalogConductor,
    /// the spans' lengths [m] (one for `[span]`)
    pub lengths_m: Vec<f64>,
    /// the rise of a single span [m] (0 for a ruling span)
    pub rise_m: f64,
    /// the stringing weather
    pub stringing: Weather,
    /// the stringing horizontal tension [N] (from `tension_n` or `tension_fraction_of_rts`)
    pub stringing_target: Option<f64>,
    /// the stringing mid-span sag [m]
    pub stringing_sag_m: Option<f64>,
    /// the state the stringing holds in
    pub stringing_state: sag::State,
    /// the creep weather
    pub creep: Weather,
    /// the heavy-load weather
    pub heavy_load: Option<Weather>,
    /// the conditions, in the order of the file: `[[condition]]` first, then `[conditions]`
    pub conditions: Vec<Weather>,
    /// the sag limit at mid-span [m] (from `max_sag_m`, or the mean support height less the clearance)
    pub sag_limit_m: Option<f64>,
    /// where a stretch is taken in the span
    pub stretch_point: sag::problem::StretchPoint,
}

/// Whether a parsed TOML document is a sag-tension case: a `[stringing]` table with a `[span]` or a
/// `[ruling_span]` (a wire scenario has neither a `stringing` table nor these).
pub fn is_sagtension_table(t: &toml::Table) -> bool {
    t.get("stringing").is_some_and(toml::Value::is_table) && (t.contains_key("span") || t.contains_key("ruling_span"))
}

/// The message for a sag-tension case given to another command.
pub const NOT_HERE: &str = "a sag-tension case ([stringing] with [span] or [ruling_span]), not for this command: \
                            compute it with `ohl sagtension` (docs/sagtension_cases.md)";

/// Parse and validate a sag-tension case; `file` names it in messages.
pub fn parse_case(text: &str, file: &str) -> Result<(SagTensionCase, Resolved), InputError> {
    let mut doc = super::locate::parse_table(text, file)?;
    if super::thermal::is_thermal_table(&doc) && !doc.contains_key("stringing") {
        return Err(InputError::Parse {
            file: file.into(),
            message: "a thermal case (a top-level [weather] and `conductor = \"NAME\"`), not a sag-tension case: \
                      compute it with `ohl thermal`"
                .into(),
        });
    }
    if !doc.contains_key("stringing") && doc.get("conductor").is_some_and(toml::Value::is_table) {
        return Err(InputError::Parse {
            file: file.into(),
            message: "a wire scenario (no [stringing] table), not a sag-tension case: run it with `ohl run`".into(),
        });
    }
    let user = match doc.get_mut("conductor") {
        Some(toml::Value::Table(t)) => super::thermal_conductor::resolve_user_catalog(t, "conductor.", file)?,
        _ => None,
    };
    let celsius = super::temperature::to_kelvin(&mut doc)
        .map_err(|problems| InputError::Invalid { file: file.into(), problems })?;
    let mut case: SagTensionCase = super::locate::from_table(doc, text, file)?;
    case.celsius = celsius;
    let mut c = Check(Vec::new());
    let resolved = check(&mut c, &case, user.as_deref());
    match resolved {
        Some(r) if c.0.is_empty() => Ok((case, r)),
        _ => Err(InputError::Invalid { file: file.into(), problems: case.celsius.as_written(c.0) }),
    }
}

/// Read, parse and validate a sag-tension case file.
pub fn load(path: &std::path::Path) -> Result<(SagTensionCase, Resolved), InputError> {
    let text = super::read_text(path)?;
    parse_case(&text, &path.display().to_string())
}

/// Resolve a weather at `at` (`condition[2]`), recording its problems; `default_temperature_k` is used
/// when neither the field nor the case gives one (`None`: required).
pub fn resolve_weather(
    c: &mut Check,
    at: &str,
    w: &WeatherSpec,
    default_temperature_k: Option<f64>,
) -> Option<Weather> {
    let field = |name: &str| if at.is_empty() { name.to_string() } else { format!("{at}.{name}") };
    let named = match &w.case {
        Some(name) => match codes::case(name) {
            Some(k) => Some(k),
            None => {
                let names: Vec<&str> = codes::CASES.iter().map(|k| k.name).collect();
                c.fail(&field("case"), format!("{name:?}"), &format!("must be a load case: {}", names.join(", ")));
                return None;
            }
        },
        None => None,
    };
    let mut missing: Vec<&str> = Vec::new();
    let mut pick = |name: &'static str, own: Option<f64>, of_case: Option<f64>, default: Option<f64>| -> f64 {
        match (own, of_case, default, named) {
            (Some(x), ..) => x,
            (None, Some(x), ..) => x,
            // A code that leaves its values to the user (IEC 60826, EN 50341-1): no default stands in.
            (None, None, _, Some(k)) if k.radial_ice_m.is_none() || k.wind_pressure_pa.is_none() => {
                missing.push(name);
                f64::NAN
            }
            (None, None, Some(d), _) => d,
            (None, None, None, _) => {
                missing.push(name);
                f64::NAN
            }
        }
    };
    let temperature_k = pick(
        "temperature_k",
        w.temperature_k,
        named.and_then(|k| k.temperature_c.map(super::temperature::kelvin)),
        default_temperature_k,
    );
    let ice_thickness_m = pick("ice_thickness_m", w.ice_thickness_m, named.and_then(|k| k.radial_ice_m), Some(0.0));
    let ice_density_kg_per_m3 = pick(
        "ice_density_kg_per_m3",
        w.ice_density_kg_per_m3,
        named.and_then(|k| k.ice_density_kg_per_m3),
        Some(DEFAULT_ICE_DENSITY_KG_PER_M3),
    );
    let wind_pressure_pa =
        pick("wind_pressure_pa", w.wind_pressure_pa, named.and_then(|k| k.wind_pressure_pa), Some(0.0));
    let drag_coefficient = pick(
        "drag_coefficient",
        w.drag_coefficient,
        named.and_then(|k| k.drag_coefficient),
        Some(DEFAULT_DRAG_COEFFICIENT),
    );
    let constant_n_per_m = pick("constant_n_per_m", w.constant_n_per_m, named.map(|k| k.constant_k_n_per_m), Some(0.0));
    match (missing.is_empty(), named) {
        (true, _) => {}
        (false, Some(k)) => {
            c.fail(
                &field("case"),
                format!("{:?}", k.name),
                &format!(
                    "leaves {} to the user: give them beside it (the code leaves: {})",
                    missing.join(", "),
                    k.user_chooses
                ),
            );
            return None;
        }
        (false, None) => {
            c.fail(&field(missing[0]), "(missing)", "must be given (or a named `case` that gives it)");
            return None;
        }
    }
    let mut ok = true;
    // Only the values the file wrote are checked with their own field names; a case's values are the code's.
    if w.temperature_k.is_some() || named.is_none() {
        ok &= c.range(&field("temperature_k"), temperature_k, &SAG_TEMPERATURE_K);
    }
    if let Some(x) = w.ice_thickness_m {
        ok &= c.range(&field("ice_thickness_m"), x, &RADIAL_ICE_M);
    }
    if let Some(x) = w.ice_density_kg_per_m3 {
        ok &= c.range(&field("ice_density_kg_per_m3"), x, &ICE_DENSITY_KG_PER_M3);
    }
    if let Some(x) = w.wind_pressure_pa {
        ok &= c.range(&field("wind_pressure_pa"), x, &WIND_PRESSURE_PA);
    }
    if let Some(x) = w.drag_coefficient {
        ok &= c.range(&field("drag_coefficient"), x, &DRAG_COEFFICIENT);
    }
    if let Some(x) = w.constant_n_per_m {
        ok &= c.range(&field("constant_n_per_m"), x, &CONSTANT_N_PER_M);
    }
    let label = w.label.clone().unwrap_or_else(|| {
        let t = format!("{:.1} C", temperature_k - super::temperature::ZERO_CELSIUS_K);
        match (&w.case, ice_thickness_m > 0.0 || wind_pressure_pa > 0.0) {
            (Some(name), _) => format!("{name}, {t}"),
            (None, true) => {
                format!("{t}, {} mm ice, {} Pa wind", number(ice_thickness_m * 1e3), number(wind_pressure_pa))
            }
            (None, false) => t,
        }
    });
    ok.then_some(Weather {
        label,
        temperature_k,
        ice_thickness_m,
        ice_density_kg_per_m3,
        wind_pressure_pa,
        drag_coefficient,
        constant_n_per_m,
    })
}

/// Check the whole case; the resolved case if every field is valid.
fn check(c: &mut Check, case: &SagTensionCase, user: Option<&[CatalogConductor]>) -> Option<Resolved> {
    let name = &case.conductor.catalog;
    let from_user = user.and_then(|u| super::thermal_conductor::find_in(u, name)).cloned();
    let conductor = match from_user.map_or_else(|| catalog::find(name).cloned(), Ok) {
        Ok(k) => Some(k),
        Err(e) => {
            c.fail("conductor.catalog", format!("{name:?}"), &e.to_string());
            None
        }
    };
    let (lengths_m, rise_m) = match (&case.span, &case.ruling_span) {
        (Some(s), None) => {
            if c.range("span.length_m", s.length_m, &SPAN_LENGTH_M) {
                c.within(
                    "span.rise_m",
                    s.rise_m,
                    -0.9 * s.length_m,
                    0.9 * s.length_m,
                    &format!(
                        "must be within +-0.9 span.length_m = +-{} m (an incline below 42 deg)",
                        number(0.9 * s.length_m)
                    ),
                );
            }
            (vec![s.length_m], s.rise_m)
        }
        (None, Some(r)) => {
            if r.lengths_m.is_empty() || r.lengths_m.len() > MAX_RULING_SPANS {
                c.fail(
                    "ruling_span.lengths_m",
                    format!("{} spans", r.lengths_m.len()),
                    &format!("must list 1 to {MAX_RULING_SPANS} span lengths"),
                );
            }
            for (k, &l) in r.lengths_m.iter().enumerate() {
                c.range(&format!("ruling_span.lengths_m[{k}]"), l, &SPAN_LENGTH_M);
            }
            (r.lengths_m.clone(), 0.0)
        }
        (Some(_), Some(_)) => {
            c.fail(
                "ruling_span",
                "(given with [span])",
                "give one span ([span]) or a ruling span ([ruling_span]), not both",
            );
            (Vec::new(), 0.0)
        }
        (None, None) => {
            c.fail("span", "(missing)", "give one span ([span]) or a ruling span ([ruling_span])");
            (Vec::new(), 0.0)
        }
    };
    let s = &case.stringing;
    let given = [s.tension_n.is_some(), s.tension_fraction_of_rts.is_some(), s.sag_m.is_some()];
    match given.iter().filter(|g| **g).count() {
        0 => c.fail("stringing.tension_n", "(missing)", "give one of tension_n, tension_fraction_of_rts and sag_m"),
        1 => {}
        _ => c.fail(
            "stringing",
            "(two of tension_n, tension_fraction_of_rts, sag_m)",
            "give one of tension_n, tension_fraction_of_rts and sag_m, not two",
        ),
    }
    if let Some(t) = s.tension_n
        && c.range("stringing.tension_n", t, &STRINGING_TENSION_N)
        && let Some(k) = &conductor
        && t >= k.rated_tensile_strength_n
    {
        c.fail(
            "stringing.tension_n",
            number(t),
            &format!("must be below the conductor's rated tensile strength {} N", number(k.rated_tensile_strength_n)),
        );
    }
    if let Some(f) = s.tension_fraction_of_rts {
        c.range("stringing.tension_fraction_of_rts", f, &RTS_FRACTION);
    }
    // The stringing sag is the sag of the span the solver sees: the span, or the ruling span of a section
    // (sqrt(sum l^3 / sum l), computed here only where every length is valid).
    let solver_span = (!lengths_m.is_empty() && lengths_m.iter().all(|l| SPAN_LENGTH_M.contains(*l)))
        .then(|| (lengths_m.iter().map(|l| l * l * l).sum::<f64>() / lengths_m.iter().sum::<f64>()).sqrt());
    if let Some(d) = s.sag_m
        && c.range("stringing.sag_m", d, &LENGTH_LIMIT_M)
        && let Some(l) = solver_span
        && d >= 0.5 * l
    {
        let what = if lengths_m.len() > 1 { "the ruling span" } else { "the span" };
        c.fail("stringing.sag_m", number(d), &format!("must be below half {what}, {} m", number(0.5 * l)));
    }
    let stringing = resolve_weather(c, "stringing", &s.weather(), None);
    let creep = match &case.creep {
        Some(w) => resolve_weather(c, "creep", w, stringing.as_ref().map(|w| w.temperature_k)),
        None => stringing.as_ref().map(|w| Weather::bare("creep", w.temperature_k)),
    };
    let heavy_load = case.heavy_load.as_ref().map(|w| resolve_weather(c, "heavy_load", w, None));
    let mut conditions = Vec::new();
    let mut all_ok = true;
    for (k, w) in case.condition.iter().enumerate() {
        match resolve_weather(c, &format!("condition[{k}]"), w, None) {
            Some(w) => conditions.push(w),
            None => all_ok = false,
        }
    }
    if let Some(r) = &case.conditions {
        match (r.from_temperature_k, r.to_temperature_k) {
            (Some(a), Some(b)) => {
                let ok_a = c.range("conditions.from_temperature_k", a, &SAG_TEMPERATURE_K);
                let ok_b = c.range("conditions.to_temperature_k", b, &SAG_TEMPERATURE_K);
                let ok_s = c.range("conditions.temperature_step_k", r.temperature_step_k, &TEMPERATURE_STEP_K);
                all_ok &= ok_a && ok_b && ok_s && b >= a;
                if ok_a && ok_b && b < a {
                    c.fail(
                        "conditions.to_temperature_k",
                        number(b),
                        "must be at least the range's start, from_temperature: the range runs upwards",
                    );
                } else if ok_a && ok_b && ok_s {
                    let n = ((b - a) / r.temperature_step_k + 1e-9).floor() as usize + 1;
                    if n + conditions.len() > MAX_CONDITIONS {
                        c.fail(
                            "conditions.temperature_step_k",
                            number(r.temperature_step_k),
                            &format!("gives {n} temperatures: at most {MAX_CONDITIONS} conditions in a table"),
                        );
                    } else {
                        for j in 0..n {
                            let t = ((a + j as f64 * r.temperature_step_k) * 1e9).round() / 1e9;
                            conditions
                                .push(Weather::bare(format!("{:.1} C", t - super::temperature::ZERO_CELSIUS_K), t));
                        }
                    }
                }
            }
            (None, None) => {}
            (a, _) => {
                let missing = if a.is_none() { "conditions.from_temperature_k" } else { "conditions.to_temperature_k" };
                all_ok = false;
                c.fail(missing, "(missing)", "a temperature range needs from_temperature_k and to_temperature_k");
            }
        }
        for (k, name) in r.load_cases.iter().enumerate() {
            let w = WeatherSpec { case: Some(name.clone()), ..Default::default() };
            match resolve_weather(c, &format!("conditions.load_cases[{k}]"), &w, None) {
                Some(w) => conditions.push(w),
                None => all_ok = false,
            }
        }
    }
    if all_ok && conditions.is_empty() {
        c.fail("condition", "(missing)", "the case asks nothing: give [[condition]] tables or a [conditions] range");
    }
    if conditions.len() > MAX_CONDITIONS {
        c.fail("condition", format!("{} conditions", conditions.len()), &format!("at most {MAX_CONDITIONS}"));
    }
    let sag_limit_m =
        case.clearance.as_ref().and_then(|cl| match (cl.max_sag_m, cl.support_heights_m, cl.min_clearance_m) {
            (Some(m), None, None) => c.range("clearance.max_sag_m", m, &LENGTH_LIMIT_M).then_some(m),
            (None, Some([ha, hb]), Some(m)) => {
                let ok = c.range("clearance.support_heights_m[0]", ha, &LENGTH_LIMIT_M)
                    & c.range("clearance.support_heights_m[1]", hb, &LENGTH_LIMIT_M)
                    & c.range("clearance.min_clearance_m", m, &LENGTH_LIMIT_M);
                let mid = 0.5 * (ha + hb);
                if ok && m >= mid {
                    c.fail(
                        "clearance.min_clearance_m",
                        number(m),
                        &format!("must be below the chord's height at mid-span, {} m", number(mid)),
                    );
                    return None;
                }
                ok.then_some(mid - m)
            }
            _ => {
                c.fail(
                "clearance",
                "(incomplete)",
                "give max_sag_m, or support_heights_m with min_clearance_m (clearance at mid-span above level ground)",
            );
                None
            }
        });
    if !c.0.is_empty() {
        return None;
    }
    let rts = conductor.as_ref()?.rated_tensile_strength_n;
    Some(Resolved {
        conductor: conductor?,
        lengths_m,
        rise_m,
        stringing: stringing?,
        stringing_target: s.tension_n.or(s.tension_fraction_of_rts.map(|f| f * rts)),
        stringing_sag_m: s.sag_m,
        stringing_state: match s.state {
            StateSpec::Initial => sag::State::Initial,
            StateSpec::Final => sag::State::Final,
        },
        creep: creep?,
        heavy_load: heavy_load.flatten(),
        conditions,
        sag_limit_m,
        stretch_point: match case.stretch_point {
            StretchPointSpec::MostStrained => sag::problem::StretchPoint::MostStrained,
            StretchPointSpec::AverageTension => sag::problem::StretchPoint::AverageTension,
        },
    })
}

impl Weather {
    /// The solver's weather ([`crate::sagtension::Weather`]): the drag coefficient folded into the pressure,
    /// as the codes state a pressure on the projected diameter.
    pub fn to_solver(&self) -> sag::Weather {
        sag::Weather {
            temperature_k: self.temperature_k,
            ice_thickness_m: self.ice_thickness_m,
            ice_density_kg_per_m3: self.ice_density_kg_per_m3,
            wind_pressure_pa: self.wind_pressure_pa * self.drag_coefficient,
            constant_n_per_m: self.constant_n_per_m,
        }
    }
}

/// Which axial law a case's conductor has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LawKind {
    /// the catalogue's stress-strain data: two materials, polynomials, creep, permanent set
    TwoMaterial,
    /// one material of the catalogue's `axial_stiffness_n` and `thermal_expansion_per_k` (no stress-strain
    /// data in the catalogue entry)
    SingleModulus,
}

impl Resolved {
    /// The span the solver sees: the single span, or the ruling span of the section
    /// ([`sag::Span::ruling`]).
    pub fn span(&self) -> Result<sag::Span, sag::SagTensionError> {
        if self.lengths_m.len() == 1 {
            Ok(sag::Span { length_m: self.lengths_m[0], rise_m: self.rise_m })
        } else {
            sag::Span::ruling(&self.lengths_m)
        }
    }

    /// The single-modulus law of the catalogue entry: one material of area `A` (the entry's total area),
    /// `E = EA / A` and the entry's expansion, unstressed at the stringing temperature.
    pub fn single_modulus_law(&self) -> TwoMaterial {
        let k = &self.conductor;
        let area = k.total_area_m2();
        TwoMaterial {
            outer: Component::linear(area, k.axial_stiffness_n / area, k.thermal_expansion_per_k),
            core: None,
            reference_temperature_k: self.stringing.temperature_k,
        }
    }

    /// The conductor's law: the catalogue's two-material law where the entry has stress-strain data, else
    /// the single-modulus one ([`Resolved::single_modulus_law`]).
    pub fn law(&self) -> (TwoMaterial, LawKind) {
        match self.conductor.two_material() {
            Some(law) => (law, LawKind::TwoMaterial),
            None => (self.single_modulus_law(), LawKind::SingleModulus),
        }
    }

    /// The solver's problem with the axial law `law` (the case's or the single-modulus comparison).
    pub fn problem(&self, law: TwoMaterial) -> Result<sag::Problem, sag::SagTensionError> {
        let k = &self.conductor;
        let target = match (self.stringing_target, self.stringing_sag_m) {
            (_, Some(d)) => sag::StringingTarget::Sag(d),
            (Some(h), None) => sag::StringingTarget::HorizontalTension(h),
            (None, None) => unreachable!("validated: one of tension and sag"),
        };
        Ok(sag::Problem {
            conductor: sag::SagConductor {
                law,
                diameter_m: k.diameter_m,
                mass_kg_per_m: k.linear_density_kg_per_m,
                rated_tensile_strength_n: k.rated_tensile_strength_n,
            },
            span: self.span()?,
            stringing: sag::Stringing { target, weather: self.stringing.to_solver(), state: self.stringing_state },
            creep: Some(self.creep.to_solver()),
            heavy_load: self.heavy_load.as_ref().map(Weather::to_solver),
            gravity_m_per_s2: sag::STANDARD_GRAVITY_M_PER_S2,
            stretch_point: self.stretch_point,
        })
    }
}

/// A problem of the case file `file` as an [`InputError`] (for the checks after parsing).
pub fn invalid(file: &str, field: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> InputError {
    InputError::Invalid {
        file: file.into(),
        problems: vec![Problem { field: field.into(), value: value.to_string(), allowed: allowed.into() }],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<(SagTensionCase, Resolved), InputError> {
        parse_case(text, "case.toml")
    }

    fn problems(text: &str) -> Vec<Problem> {
        match parse(text) {
            Err(InputError::Invalid { problems, .. }) => problems,
            other => panic!("expected invalid, got {other:?}"),
        }
    }

    const BASE: &str = "[conductor]\ncatalog = \"ACSR Drake\"\n[span]\nlength_m = 213.36\n[stringing]\n\
                        tension_n = 28023.796\ntemperature_c = 15.555555556\n";

    #[test]
    fn the_handbook_example_reads_as_its_table_states_it() {
        let text =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/sagtension/drake_700ft.toml"))
                .unwrap();
        let (case, r) = parse(&text).unwrap();
        assert_eq!(case.stringing.state, StateSpec::Initial);
        // 60 F = (60 - 32) / 1.8 C = 288.705555... K, to the 1e-9 K of the Celsius conversion.
        assert!((r.stringing.temperature_k - (273.15 + 28.0 / 1.8)).abs() < 1e-8);
        // The creep weather defaults to the stringing temperature, bare.
        assert_eq!(r.creep.temperature_k, r.stringing.temperature_k);
        assert!(r.creep.is_bare());
        // Ten rows; the first carries 0.5 in of ice and 4 psf of wind.
        assert_eq!(r.conditions.len(), 10);
        assert_eq!(r.conditions[0].ice_thickness_m, 0.5 * 0.0254);
        assert!((r.conditions[0].wind_pressure_pa - 4.0 * 0.3048f64.powi(-2) * 4.4482216152605).abs() < 1e-4);
        // The default ice density is the NESC's 57 lb/ft^3 (913.05 kg/m^3, given as 913).
        assert!((r.conditions[1].ice_density_kg_per_m3 - 57.0 * 0.45359237 / 0.3048f64.powi(3)).abs() < 0.06);
        assert_eq!(r.conductor.name, "ACSR Drake");
        assert_eq!(r.lengths_m, [213.36]);
    }

    #[test]
    fn a_named_load_case_gives_the_codes_values_and_a_field_beside_it_wins() {
        let text = format!(
            "{BASE}[[condition]]\ncase = \"nesc_heavy\"\n[[condition]]\ncase = \"nesc_heavy\"\ntemperature_c = 0.0\n"
        );
        let (_, r) = parse(&text).unwrap();
        // NESC Rule 250B heavy district, metric: 12.5 mm, 190 Pa, -20 C, K 4.4 N/m (Table 250-1, 251-1).
        let w = &r.conditions[0];
        assert_eq!((w.ice_thickness_m, w.wind_pressure_pa, w.constant_n_per_m), (0.0125, 190.0, 4.4));
        assert_eq!(w.temperature_k, 253.15);
        assert_eq!(r.conditions[1].temperature_k, 273.15);
        assert_eq!(r.conditions[1].ice_thickness_m, 0.0125);
    }

    #[test]
    fn a_temperature_range_gives_every_step_and_its_ends() {
        let text = format!(
            "{BASE}[conditions]\nfrom_temperature_c = -20.0\nto_temperature_c = 100.0\ntemperature_step_k = 10.0\n\
             load_cases = [\"nesc_light\"]\n"
        );
        let (_, r) = parse(&text).unwrap();
        // (100 - (-20)) / 10 + 1 = 13 temperatures, then the load case.
        assert_eq!(r.conditions.len(), 14);
        assert_eq!(r.conditions[0].temperature_k, 253.15);
        assert_eq!(r.conditions[12].temperature_k, 373.15);
        assert!(r.conditions[..13].iter().all(Weather::is_bare));
        assert_eq!(r.conditions[13].wind_pressure_pa, 430.0);
    }

    #[test]
    fn every_bad_value_is_named_with_its_field_and_range() {
        let p = problems(&format!("{BASE}[[condition]]\ntemperature_c = 400.0\nice_thickness_m = -0.01\n"));
        assert_eq!(p.len(), 2, "{p:?}");
        assert_eq!(p[0].field, "condition[0].temperature_c");
        assert_eq!(p[0].allowed, "must be in [-100, 300] C");
        assert_eq!(p[1].field, "condition[0].ice_thickness_m");
        assert_eq!(p[1].allowed, "must be in [0, 0.2] m");
        // A code that leaves its values to the user is refused, naming what it leaves.
        let p = problems(&format!("{BASE}[[condition]]\ncase = \"iec60826_ice_wind\"\n"));
        assert_eq!(p.len(), 1, "{p:?}");
        assert_eq!(p[0].field, "condition[0].case");
        assert!(
            p[0].allowed.starts_with(
                "leaves temperature_k, ice_thickness_m, ice_density_kg_per_m3, wind_pressure_pa, drag_coefficient to \
                 the user"
            ),
            "{}",
            p[0].allowed
        );
        // Nothing asked.
        let p = problems(BASE);
        assert_eq!(p[0].field, "condition");
        // Two ways of stringing.
        let p = problems(&format!("{BASE}sag_m = 5.0\n[[condition]]\ntemperature_c = 0.0\n"));
        assert!(p[0].allowed.contains("not two"), "{p:?}");
        // A tension above the rated tensile strength of Drake (140 kN).
        let text = BASE.replace("28023.796", "2e5") + "[[condition]]\ntemperature_c = 0.0\n";
        assert!(problems(&text)[0].allowed.contains("rated tensile strength"));
    }
}
