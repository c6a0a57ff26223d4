//! The `[thermal]` table of a scenario: the conductor's temperature from its current and the weather
//! (IEEE Std 738-2012 or CIGRE TB 601, [`crate::thermal`]) drives every segment's temperature, hence its
//! stress-free length (5.5) and the sag, during the run and in the initial static solve; optionally an ice
//! shell melted by the current ([`crate::thermal::deicing`]), which sheds from its spans when it has
//! melted through.
//!
//! The heat balance does not depend on the wire's motion, so the whole temperature history is computed
//! before the run ([`thermal_history`]): RK4 steps of at most `step_s`, landing on the current schedule's
//! points; during the run each time level takes the linear interpolant of that history (error about
//! `h^2 |T''| / 8`, below 1e-4 K for `h` = 1 s and the conductor's time constant of minutes), sets it on
//! every segment and rescales the stress-free lengths.
//!
//! ```toml
//! [thermal]
//! standard = "ieee738"                  # or "cigre601"
//! conductor = "ACSR Drake"              # a name of the conductor catalogue (data/conductors.toml), or a
//!                                       # [thermal.conductor] table of properties, or a name in a user
//!                                       # catalogue (conductor_catalog): super::thermal_conductor
//! current_a = [[0.0, 400.0], [600.0, 400.0], [600.0, 1200.0]]   # (t [s], I [A]) points: a step at 600 s
//! [thermal.weather]
//! air_temperature_k = 298.15
//! wind_speed_m_per_s = 0.61
//! wind_angle_deg = 90.0                 # between the wind and the line's axis
//! ```

use serde::Deserialize;

use super::Problem;
use super::range::{
    CONDUCTOR_TEMPERATURE_K, CURRENT_A, HEAT_STEP_S, ICE_DENSITY_KG_PER_M3, ICE_THICKNESS_M, Range as Allowed,
};
use super::thermal_conductor::{ConductorSpec, check_inclination, check_thermal_conductor};
use super::validate::{Check, number};
use crate::thermal::deicing::{Deicing, DeicingOptions, IceShell, MELTING_POINT_K, ShedCriterion};
use crate::thermal::transient::{CurrentSchedule, Transient};
use crate::thermal::weather::{Atmosphere, Sun, Weather};
use crate::thermal::{Model, Standard, ThermalConductor, catalog, steady};

/// The heat-balance standard (written, as in `thermal.json`, by the names it is read by).
#[derive(Clone, Copy, Debug, Default, Deserialize, serde::Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum StandardSpec {
    /// IEEE Std 738-2012 (default)
    #[default]
    Ieee738,
    /// CIGRE TB 601 (2014)
    Cigre601,
}

impl From<StandardSpec> for Standard {
    fn from(s: StandardSpec) -> Self {
        match s {
            StandardSpec::Ieee738 => Standard::Ieee738,
            StandardSpec::Cigre601 => Standard::Cigre601,
        }
    }
}

/// The sun's position and the sky (omit the table for a night: no solar heating).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SunSpec {
    /// latitude `Lat` [deg], in [-90, 90], north positive
    pub latitude_deg: f64,
    /// day of the year `N` [-], in [1, 366]
    pub day_of_year: f64,
    /// local solar time [h], in [0, 24] (12 = solar noon)
    pub solar_hour: f64,
    /// azimuth of the line's axis `Z_l` [deg], in [0, 360], clockwise from north (90: east-west)
    pub line_azimuth_deg: f64,
    /// IEEE 738 clear-sky model: `"clear"` (default) or `"industrial"` (IEEE 738 only)
    #[serde(default)]
    pub atmosphere: Option<AtmosphereSpec>,
    /// CIGRE TB 601 clearness ratio `N_s` [-], in [0, 1.5]; default 1 (clean sky) (TB 601 only)
    #[serde(default)]
    pub clearness_ratio: Option<f64>,
    /// ground albedo `F` [-], in [0, 1]; default 0.1 (rural ground, TB 601 table) (TB 601 only)
    #[serde(default)]
    pub albedo: Option<f64>,
    /// measured global horizontal radiation [W/m^2], in [0, 1500] (TB 601 only; replaces the computed one)
    #[serde(default)]
    pub measured_global_w_per_m2: Option<f64>,
}

/// TB 601's clearness ratio of a clean sky `N_s` [-] (TB 601, solar radiation).
const CLEAN_SKY: f64 = 1.0;

/// Ground albedo of rural ground `F` [-] (TB 601, table of albedos).
const RURAL_ALBEDO: f64 = 0.1;

/// IEEE 738 atmosphere.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum AtmosphereSpec {
    /// clear (default)
    #[default]
    Clear,
    /// industrial
    Industrial,
}

/// The weather at the conductor.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WeatherSpec {
    /// ambient air temperature `T_a` [K], in [200, 350]
    pub air_temperature_k: f64,
    /// wind speed `V_w` [m/s], in [0, 50]
    pub wind_speed_m_per_s: f64,
    /// angle between the wind and the line's axis `phi` [deg], in [0, 180]; default 90 (perpendicular)
    #[serde(default = "perpendicular")]
    pub wind_angle_deg: f64,
    /// elevation above sea level `H_e` [m], in [0, 6000]; default 0
    #[serde(default)]
    pub elevation_m: f64,
    /// the sun; omit for a night
    #[serde(default)]
    pub sun: Option<SunSpec>,
}

fn perpendicular() -> f64 {
    90.0
}

/// Shedding criterion of a de-icing ice shell.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ShedSpec {
    /// the conductor melts a slot of its own width through the top of the shell (default)
    #[default]
    Slot,
    /// the whole shell melts (an upper bound on the time)
    FullMelt,
}

/// An ice shell on the conductor at `t = 0`, melted by the current (`[thermal.deicing]`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeicingSpec {
    /// radial ice thickness `t` [m], in [1e-4, 0.1] (as validated)
    pub thickness_m: f64,
    /// ice density `rho_i` [kg/m^3], in [100, 1000]; default 900 (glaze, IEC 60826)
    #[serde(default = "glaze_density")]
    pub density_kg_per_m3: f64,
    /// the iced spans of a `[section]` (0-based); default all; omit for a single span
    #[serde(default)]
    pub spans: Option<Vec<usize>>,
    /// when the shell sheds: `"slot"` (default) or `"full_melt"`
    #[serde(default)]
    pub criterion: ShedSpec,
}

fn glaze_density() -> f64 {
    900.0
}

/// The `[thermal]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalSpec {
    /// heat-balance standard: `"ieee738"` (default) or `"cigre601"`
    #[serde(default)]
    pub standard: StandardSpec,
    /// the conductor's thermal data: its name in the conductor catalogue (`data/conductors.toml`, e.g.
    /// "ACSR Drake") or in `conductor_catalog`, or a `[thermal.conductor]` table of its properties
    /// ([`ConductorSpec`]); its mechanical data stay those of `[conductor]`
    pub conductor: ConductorSpec,
    /// a user conductor catalogue (TOML, the format of `data/conductors.toml`): its path relative to the
    /// scenario file's folder; its names are looked up before the built-in ones (resolved when the file is
    /// parsed, [`super::thermal_conductor::resolve_user_catalog`])
    #[serde(default)]
    pub conductor_catalog: Option<String>,
    /// inclination of the span to the horizontal `beta` [deg], in [0, 80] (stranded) or [0, 60] (smooth or
    /// iced); default 0. CIGRE TB 601 only: it lowers natural convection (eq. (24))
    #[serde(default)]
    pub inclination_deg: f64,
    /// the weather, constant over the run
    pub weather: WeatherSpec,
    /// the current as `[t [s], I [A]]` points: piecewise linear, constant before the first and after the
    /// last, a step where two points share a time; times non-decreasing in [0, 1e8] s, currents in
    /// [0, 1e5] A
    #[serde(deserialize_with = "super::schema::pairs")]
    pub current_a: Vec<[f64; 2]>,
    /// the longest RK4 step of the heat balance [s], in [1e-3, 600]; default 1 s
    #[serde(default = "thermal_step")]
    pub step_s: f64,
    /// the conductor's temperature at `t = 0` [K], in [200, 500]; default the steady state of the first
    /// point's current (the current before the schedule: a step at `t = 0` starts from it)
    #[serde(default)]
    pub initial_temperature_k: Option<f64>,
    /// an ice shell melted by the current
    #[serde(default)]
    pub deicing: Option<DeicingSpec>,
}

fn thermal_step() -> f64 {
    1.0
}

/// The weather of the spec.
pub fn weather(w: &WeatherSpec) -> Weather {
    Weather {
        air_temperature_k: w.air_temperature_k,
        wind_speed_m_per_s: w.wind_speed_m_per_s,
        wind_angle_deg: w.wind_angle_deg,
        elevation_m: w.elevation_m,
        sun: w.sun.as_ref().map(|s| Sun {
            latitude_deg: s.latitude_deg,
            day_of_year: s.day_of_year,
            solar_hour: s.solar_hour,
            line_azimuth_deg: s.line_azimuth_deg,
            atmosphere: match s.atmosphere.unwrap_or_default() {
                AtmosphereSpec::Clear => Atmosphere::Clear,
                AtmosphereSpec::Industrial => Atmosphere::Industrial,
            },
            clearness_ratio: s.clearness_ratio.unwrap_or(CLEAN_SKY),
            albedo: s.albedo.unwrap_or(RURAL_ALBEDO),
            measured_global_w_per_m2: s.measured_global_w_per_m2,
        }),
    }
}

/// Check a weather table under the field prefix `at` (e.g. `thermal.weather`).
pub fn check_weather(c: &mut Check, at: &str, w: &WeatherSpec, standard: StandardSpec) {
    c.range(&format!("{at}.air_temperature_k"), w.air_temperature_k, &super::range::AIR_TEMPERATURE_K);
    c.range(&format!("{at}.wind_speed_m_per_s"), w.wind_speed_m_per_s, &Allowed::closed(0.0, 50.0, "m/s"));
    c.range(&format!("{at}.wind_angle_deg"), w.wind_angle_deg, &Allowed::closed(0.0, 180.0, "deg"));
    c.range(&format!("{at}.elevation_m"), w.elevation_m, &Allowed::closed(0.0, 6000.0, "m"));
    if let Some(s) = &w.sun {
        c.range(&format!("{at}.sun.latitude_deg"), s.latitude_deg, &Allowed::closed(-90.0, 90.0, "deg"));
        c.range(&format!("{at}.sun.day_of_year"), s.day_of_year, &Allowed::closed(1.0, 366.0, ""));
        c.range(&format!("{at}.sun.solar_hour"), s.solar_hour, &Allowed::closed(0.0, 24.0, "h"));
        c.range(&format!("{at}.sun.line_azimuth_deg"), s.line_azimuth_deg, &Allowed::closed(0.0, 360.0, "deg"));
        if let Some(n) = s.clearness_ratio {
            c.range(&format!("{at}.sun.clearness_ratio"), n, &Allowed::closed(0.0, 1.5, ""));
        }
        if let Some(a) = s.albedo {
            c.range(&format!("{at}.sun.albedo"), a, &Allowed::closed(0.0, 1.0, ""));
        }
        // A measured radiation the chosen standard would ignore: the run would silently use a computed
        // clear sky instead of the measurement (the sky descriptors only warn: [`unused_weather_inputs`]).
        if let (StandardSpec::Ieee738, Some(g)) = (standard, s.measured_global_w_per_m2) {
            c.fail(
                &format!("{at}.sun.measured_global_w_per_m2"),
                number(g),
                "is used only with standard = \"cigre601\" (CIGRE TB 601): IEEE 738 computes the radiation from \
                 the sun's position and atmosphere and would ignore the measurement",
            );
        }
        if let Some(g) = s.measured_global_w_per_m2 {
            c.range(&format!("{at}.sun.measured_global_w_per_m2"), g, &Allowed::closed(0.0, 1500.0, "W/m^2"));
        }
    }
}

/// The sky descriptors of `w` that `standard` does not read (TB 601's `clearness_ratio` and `albedo` under
/// IEEE 738, IEEE 738's `atmosphere` under TB 601): valid, since one weather may be computed by both
/// standards, but ignored, so each is a warning that says so.
pub fn unused_weather_inputs(at: &str, w: &WeatherSpec, standard: StandardSpec) -> Vec<super::Warning> {
    let Some(s) = &w.sun else { return Vec::new() };
    let (given, reason): (Vec<(&str, String)>, &str) = match standard {
        StandardSpec::Ieee738 => (
            [s.clearness_ratio.map(|v| ("clearness_ratio", number(v))), s.albedo.map(|v| ("albedo", number(v)))]
                .into_iter()
                .flatten()
                .collect(),
            "read by CIGRE TB 601 only (standard = \"cigre601\"): ignored by IEEE 738, which describes the sky by \
             atmosphere",
        ),
        StandardSpec::Cigre601 => (
            s.atmosphere
                .map(|a| ("atmosphere", format!("\"{}\"", format!("{a:?}").to_lowercase())))
                .into_iter()
                .collect(),
            "read by IEEE 738 only (standard = \"ieee738\"): ignored by CIGRE TB 601, which describes the sky by \
             clearness_ratio and albedo",
        ),
    };
    given
        .into_iter()
        .map(|(field, value)| super::Warning { field: format!("{at}.sun.{field}"), value, reason: reason.into() })
        .collect()
}

/// The conductor at `field`: a catalogue conductor (or a problem naming the names available), or its
/// properties (each checked, [`check_thermal_conductor`]).
pub fn conductor(c: &mut Check, field: &str, spec: &ConductorSpec) -> Option<ThermalConductor> {
    match spec {
        ConductorSpec::Name(name) => match catalog::find(name) {
            Ok(k) => Some(k.thermal()),
            Err(e) => {
                c.fail(field, format!("{name:?}"), &e.to_string());
                None
            }
        },
        ConductorSpec::Properties(p) => check_thermal_conductor(c, field, p).then(|| (**p).clone()),
    }
}

/// Check the current points under `field`; the schedule if they are valid.
pub fn check_current(c: &mut Check, field: &str, points: &[[f64; 2]]) -> Option<CurrentSchedule> {
    if points.is_empty() {
        c.fail(field, "[]", "must have at least one [t_s, I_a] point");
        return None;
    }
    let mut ok = true;
    for (k, p) in points.iter().enumerate() {
        let time = Allowed::closed(0.0, super::validate::MAX_TIME_S, "s").words("time must be in");
        ok &= c.range(&format!("{field}[{k}][0]"), p[0], &time);
        ok &= c.range(&format!("{field}[{k}][1]"), p[1], &CURRENT_A.words("current must be in"));
        if k > 0 && p[0] < points[k - 1][0] {
            c.fail(&format!("{field}[{k}][0]"), p[0], "times must not decrease (equal times make a step)");
            ok = false;
        }
    }
    if !ok {
        return None;
    }
    CurrentSchedule::new(points.iter().map(|p| (p[0], p[1])).collect())
}

/// Check the `[thermal]` table; `has_temperature_events` refuses it together with temperature or heat
/// conduction events (the thermal model owns the temperature).
pub(crate) fn check(c: &mut Check, t: &ThermalSpec, temperature_event: Option<usize>) {
    let k = conductor(c, "thermal.conductor", &t.conductor);
    check_inclination(
        c,
        "thermal.inclination_deg",
        t.inclination_deg,
        t.standard.into(),
        k.as_ref(),
        t.deicing.is_some(),
    );
    check_weather(c, "thermal.weather", &t.weather, t.standard);
    check_current(c, "thermal.current_a", &t.current_a);
    c.range("thermal.step_s", t.step_s, &HEAT_STEP_S);
    if let Some(k) = t.initial_temperature_k {
        c.range("thermal.initial_temperature_k", k, &CONDUCTOR_TEMPERATURE_K);
    }
    if let Some(k) = temperature_event {
        c.fail(
            &format!("events[{k}].action"),
            "a temperature or heat-conduction event",
            "must not be combined with [thermal]: the heat balance sets the conductor's temperature",
        );
    }
    if let Some(d) = &t.deicing {
        c.range("thermal.deicing.thickness_m", d.thickness_m, &ICE_THICKNESS_M);
        c.range("thermal.deicing.density_kg_per_m3", d.density_kg_per_m3, &ICE_DENSITY_KG_PER_M3);
        let constant = t.current_a.windows(2).all(|w| w[0][1] == w[1][1]);
        if !constant {
            c.fail(
                "thermal.current_a",
                "a varying current",
                "must be constant with [thermal.deicing] (the de-icing model takes one current)",
            );
        }
    }
}

/// Most samples a temperature history may hold [-] (one per RK4 step; 160 MB).
pub const MAX_HISTORY_SAMPLES: f64 = 1.0e7;

/// The temperature history of a run: `(t [s], T [K])` at every RK4 step, and what it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct ThermalHistory {
    /// the samples, times increasing from 0 to at least the horizon
    pub samples: Vec<(f64, f64)>,
    /// the conductor's name
    pub conductor: String,
    /// the standard
    pub standard: Standard,
    /// a de-icing: when the shell sheds [s], its mass [kg/m] and the segments it covers (span ranges)
    pub shed: Option<Shed>,
}

/// The shedding of a de-icing shell.
#[derive(Clone, Debug, PartialEq)]
pub struct Shed {
    /// when it sheds [s]
    pub time_s: f64,
    /// when the conductor reached 0 C and melting began [s]
    pub melting_from_s: f64,
    /// the shell's mass per unit length [kg/m]
    pub ice_kg_per_m: f64,
    /// the iced spans (0-based)
    pub spans: Vec<usize>,
}

/// The temperature history of `t` up to `horizon_s` [s] (module doc), or a problem; `spans` are the line's
/// spans as (first segment, segments) for a de-icing shell.
///
/// With `[thermal.deicing]` the history is the de-icing model's (conductor and ice warming to 0 C, then
/// melting at 0 C) until the shell sheds, then the bare conductor's transient from 0 C with the same
/// current. The shell's whole mass stays on the span until it sheds (the melt water is taken to stay in
/// the shell; the melted slot is a quarter of a 10 mm shell on Drake), so the jump at shedding is that of
/// the full shell.
pub(crate) fn thermal_history(
    t: &ThermalSpec,
    horizon_s: f64,
    spans: &[(usize, usize)],
) -> Result<ThermalHistory, Problem> {
    let mut c = Check(Vec::new());
    // The history holds a sample per step: bound it (8 bytes x 2 per sample: 1e7 samples are 160 MB).
    let samples = horizon_s / t.step_s;
    if samples > MAX_HISTORY_SAMPLES {
        return Err(Problem {
            field: "thermal.step_s".into(),
            value: format!("{}", t.step_s),
            allowed: format!(
                "must be at least {:.3} s for this run's {horizon_s} s (the temperature history holds one sample per \
                 step, at most {MAX_HISTORY_SAMPLES:e})",
                horizon_s / MAX_HISTORY_SAMPLES
            ),
        });
    }
    let name = t.conductor.primary_name();
    let (Some(conductor), Some(schedule)) = (
        conductor(&mut c, "thermal.conductor", &t.conductor),
        check_current(&mut c, "thermal.current_a", &t.current_a),
    ) else {
        return Err(c.0.remove(0));
    };
    let model =
        Model::new(t.standard.into(), conductor.clone(), weather(&t.weather)).with_inclination(t.inclination_deg);
    if let Some(d) = &t.deicing {
        return deicing_history(t, d, conductor, &model, &schedule, horizon_s, spans)
            .map(|h| ThermalHistory { conductor: name, ..h });
    }
    let initial = match t.initial_temperature_k {
        Some(k) => k,
        None => steady::temperature(&model, schedule.initial_a()).map(|s| s.temperature_k).map_err(|e| Problem {
            field: "thermal.current_a".into(),
            value: format!("{} A before t = 0", schedule.initial_a()),
            allowed: format!("must have a steady state to start from: {e}"),
        })?,
    };
    let tr = Transient { model: &model, current: &schedule, step_s: t.step_s };
    let samples = tr.run(0.0, initial, horizon_s).into_iter().map(|s| (s.time_s, s.temperature_k)).collect();
    Ok(ThermalHistory { samples, conductor: name, standard: t.standard.into(), shed: None })
}

/// The history of a de-icing (see [`thermal_history`]).
fn deicing_history(
    t: &ThermalSpec,
    d: &DeicingSpec,
    conductor: ThermalConductor,
    model: &Model,
    schedule: &CurrentSchedule,
    horizon_s: f64,
    spans: &[(usize, usize)],
) -> Result<ThermalHistory, Problem> {
    let current = schedule.at(0.0);
    let mut ice = IceShell::glaze(d.thickness_m);
    ice.density_kg_per_m3 = d.density_kg_per_m3;
    let mut de = Deicing::new(conductor, weather(&t.weather), t.standard.into(), ice);
    de.inclination_deg = t.inclination_deg;
    de.criterion = match d.criterion {
        ShedSpec::Slot => ShedCriterion::Slot,
        ShedSpec::FullMelt => ShedCriterion::FullMelt,
    };
    let opts = DeicingOptions {
        step_s: t.step_s,
        max_time_s: horizon_s,
        initial_temperature_k: t.initial_temperature_k,
        record_every_s: 0.0,
        ..Default::default()
    };
    let r = de.run(current, &opts).map_err(|e| Problem {
        field: "thermal.deicing".into(),
        value: format!("{} m of ice at {current} A", d.thickness_m),
        allowed: format!("must shed within the run ({horizon_s} s): {e}"),
    })?;
    let mut samples: Vec<(f64, f64)> = r.series.iter().map(|p| (p.time_s, p.conductor_k)).collect();
    // After shedding: the bare conductor from the melting point with the same current.
    let tr = Transient { model, current: schedule, step_s: t.step_s };
    let last = samples.last().map_or(r.shed_time_s, |p| p.0);
    let from_k = samples.last().map_or(MELTING_POINT_K, |p| p.1);
    samples.extend(tr.run(last, from_k, horizon_s.max(last)).into_iter().skip(1).map(|s| (s.time_s, s.temperature_k)));
    let iced: Vec<usize> = d.spans.clone().unwrap_or_else(|| (0..spans.len()).collect());
    Ok(ThermalHistory {
        samples,
        conductor: t.conductor.label(),
        standard: t.standard.into(),
        shed: Some(Shed {
            time_s: r.shed_time_s,
            melting_from_s: r.warm_time_s,
            ice_kg_per_m: r.ice_mass_kg_per_m,
            spans: iced,
        }),
    })
}

/// A transient of a thermal case (`[transient]` of a file for `ohl thermal`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransientSpec {
    /// the current as `[t [s], I [A]]` points (as `thermal.current_a` of a scenario)
    #[serde(deserialize_with = "super::schema::pairs")]
    pub current_a: Vec<[f64; 2]>,
    /// end of the transient [s], in (0, 1e7]
    pub end_time_s: f64,
    /// the conductor's temperature at `t = 0` [K], in [200, 500]; default the steady state of the first
    /// point's current (the current before the schedule)
    #[serde(default)]
    pub initial_temperature_k: Option<f64>,
    /// the longest RK4 step [s], in [1e-3, 600]; default 1 s
    #[serde(default = "thermal_step")]
    pub step_s: f64,
    /// a temperature limit [K], in [200, 600]: the time the transient first reaches it is reported
    #[serde(default)]
    pub limit_k: Option<f64>,
}

/// A de-icing question of a thermal case (`[deicing]` of a file for `ohl thermal`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeicingCaseSpec {
    /// radial ice thickness `t` [m], in [1e-4, 0.1]
    pub thickness_m: f64,
    /// ice density [kg/m^3], in [100, 1000]; default 900 (glaze)
    #[serde(default = "glaze_density")]
    pub density_kg_per_m3: f64,
    /// `"slot"` (default) or `"full_melt"`
    #[serde(default)]
    pub criterion: ShedSpec,
    /// de-icing currents [A], each in (0, 1e5]: the time to shed for each
    #[serde(default)]
    pub current_a: Vec<f64>,
    /// times [s], each in (0, 1e6]: the current that sheds within each
    #[serde(default)]
    pub shed_within_s: Vec<f64>,
    /// the RK4 step [s], in [1e-3, 600]; default 1 s
    #[serde(default = "thermal_step")]
    pub step_s: f64,
}

/// A file for `ohl thermal`: a conductor in a weather, and what is asked of its heat balance.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalCase {
    /// short name (free text)
    #[serde(default)]
    pub name: Option<String>,
    /// `"ieee738"` (default) or `"cigre601"`
    #[serde(default)]
    pub standard: StandardSpec,
    /// the conductor: its name in the catalogue (`data/conductors.toml`) or in `conductor_catalog`, or a
    /// `[conductor]` table of its properties ([`ConductorSpec`])
    pub conductor: ConductorSpec,
    /// a user conductor catalogue (the format of `data/conductors.toml`): its path relative to the case
    /// file's folder; its names are looked up before the built-in ones
    #[serde(default)]
    pub conductor_catalog: Option<String>,
    /// inclination of the span to the horizontal `beta` [deg], in [0, 80] (stranded) or [0, 60] (smooth or
    /// with `[deicing]`); default 0. CIGRE TB 601 only (eq. (24))
    #[serde(default)]
    pub inclination_deg: f64,
    /// the weather
    pub weather: WeatherSpec,
    /// currents [A], each in [0, 1e5]: the steady temperature for each
    #[serde(default)]
    pub current_a: Vec<f64>,
    /// maximum conductor temperatures [K], each in [250, 600]: the steady ampacity for each
    #[serde(default)]
    pub max_temperature_k: Vec<f64>,
    /// a transient
    #[serde(default)]
    pub transient: Option<TransientSpec>,
    /// de-icing
    #[serde(default)]
    pub deicing: Option<DeicingCaseSpec>,
    /// the temperature fields the file gave in degrees Celsius (set by [`parse_case`], not a key of the
    /// file)
    #[serde(skip)]
    pub celsius: super::temperature::Celsius,
}

/// Whether TOML text is a thermal case (a file for `ohl thermal`): a top-level `weather` table, or a
/// `conductor` given as a name rather than a `[conductor]` table. Text that does not parse is not.
pub fn is_thermal_case(text: &str) -> bool {
    text.parse::<toml::Table>().is_ok_and(|t| is_thermal_table(&t))
}

/// Whether a parsed TOML document is a thermal case ([`is_thermal_case`]).
pub fn is_thermal_table(t: &toml::Table) -> bool {
    t.get("weather").is_some_and(toml::Value::is_table) || t.get("conductor").is_some_and(toml::Value::is_str)
}

/// What a document that is not a thermal case is, and the command that reads it; `None` for a thermal
/// case.
fn other_kind(t: &toml::Table) -> Option<&'static str> {
    if is_thermal_table(t) {
        None
    } else if super::sagtension::is_sagtension_table(t) {
        Some(super::sagtension::NOT_HERE)
    } else if t.contains_key("line") {
        Some("a line scenario ([line]), not a thermal case: run it with `ohl run`")
    } else if t.contains_key("rod") {
        Some("a heat-conduction case ([rod]), not a thermal case: run it with `ohl paper`")
    } else if t.contains_key("rating") {
        Some("a scenario with a [rating] table, not a thermal case: rate it with `ohl rating`")
    } else if t.get("conductor").is_some_and(toml::Value::is_table) {
        Some("a wire scenario ([conductor]), not a thermal case: run it with `ohl run`")
    } else {
        None
    }
}

/// Parse and validate a thermal case; `file` names it in messages.
pub fn parse_case(text: &str, file: &str) -> Result<ThermalCase, super::InputError> {
    let mut doc = super::locate::parse_table(text, file)?;
    if let Some(message) = other_kind(&doc) {
        return Err(super::InputError::Parse { file: file.to_string(), message: message.to_string() });
    }
    super::thermal_conductor::resolve_user_catalog(&mut doc, "", file)?;
    let celsius = super::temperature::to_kelvin(&mut doc)
        .map_err(|problems| super::InputError::Invalid { file: file.to_string(), problems })?;
    let mut case: ThermalCase = super::locate::from_table(doc, text, file)?;
    case.celsius = celsius;
    let mut c = Check(Vec::new());
    let k = conductor(&mut c, "conductor", &case.conductor);
    check_inclination(
        &mut c,
        "inclination_deg",
        case.inclination_deg,
        case.standard.into(),
        k.as_ref(),
        case.deicing.is_some(),
    );
    check_weather(&mut c, "weather", &case.weather, case.standard);
    for (k, &i) in case.current_a.iter().enumerate() {
        c.range(&format!("current_a[{k}]"), i, &CURRENT_A);
    }
    let air = case.weather.air_temperature_k;
    for (k, &t) in case.max_temperature_k.iter().enumerate() {
        if c.range(&format!("max_temperature_k[{k}]"), t, &super::range::AMPACITY_TEMPERATURE_K) && t <= air {
            c.fail(
                &format!("max_temperature_k[{k}]"),
                number(t),
                &format!(
                    "must be above the air temperature weather.air_temperature_k = {} K: a conductor carrying \
                     current is warmer than the air, so no current keeps it at or below the air temperature",
                    number(air)
                ),
            );
        }
    }
    if case.current_a.is_empty()
        && case.max_temperature_k.is_empty()
        && case.transient.is_none()
        && case.deicing.is_none()
    {
        c.fail(
            "current_a",
            "(missing)",
            "the case asks nothing: give current_a (steady temperatures), max_temperature_k (ampacities), a \
             [transient] or a [deicing] table",
        );
    }
    if let Some(t) = &case.transient {
        check_current(&mut c, "transient.current_a", &t.current_a);
        c.range("transient.end_time_s", t.end_time_s, &Allowed::open_closed(0.0, 1.0e7, "s"));
        if c.range("transient.step_s", t.step_s, &HEAT_STEP_S) && t.end_time_s / t.step_s > MAX_HISTORY_SAMPLES {
            c.fail(
                "transient.step_s",
                number(t.step_s),
                &format!(
                    "must be at least {} s for transient.end_time_s = {} s: the transient takes one RK4 step and \
                     writes one row of transient.csv per step, at most {MAX_HISTORY_SAMPLES:e}",
                    number(t.end_time_s / MAX_HISTORY_SAMPLES),
                    number(t.end_time_s)
                ),
            );
        }
        if let Some(k) = t.initial_temperature_k {
            c.range("transient.initial_temperature_k", k, &CONDUCTOR_TEMPERATURE_K);
        }
        if let Some(k) = t.limit_k {
            c.range("transient.limit_k", k, &super::range::TRANSIENT_LIMIT_K);
        }
    }
    if let Some(d) = &case.deicing {
        c.range("deicing.thickness_m", d.thickness_m, &ICE_THICKNESS_M);
        c.range("deicing.density_kg_per_m3", d.density_kg_per_m3, &ICE_DENSITY_KG_PER_M3);
        if c.range("deicing.step_s", d.step_s, &HEAT_STEP_S) {
            // Each de-icing run goes to its shedding, at most the longest time asked (the de-icing's default
            // cap is a day); the current that sheds in time is found by bisection over such runs.
            let horizon = d.shed_within_s.iter().copied().fold(DeicingOptions::default().max_time_s, f64::max);
            if horizon / d.step_s > MAX_HISTORY_SAMPLES {
                c.fail(
                    "deicing.step_s",
                    number(d.step_s),
                    &format!(
                        "must be at least {} s: a de-icing run may last {} s (a day, or the longest \
                         deicing.shed_within_s), at most {MAX_HISTORY_SAMPLES:e} steps",
                        number(horizon / MAX_HISTORY_SAMPLES),
                        number(horizon)
                    ),
                );
            }
        }
        for (k, &i) in d.current_a.iter().enumerate() {
            c.range(&format!("deicing.current_a[{k}]"), i, &Allowed::open_closed(0.0, 1.0e5, "A"));
        }
        for (k, &t) in d.shed_within_s.iter().enumerate() {
            c.range(&format!("deicing.shed_within_s[{k}]"), t, &Allowed::open_closed(0.0, 1.0e6, "s"));
        }
    }
    if c.0.is_empty() {
        Ok(case)
    } else {
        Err(super::InputError::Invalid { file: file.into(), problems: case.celsius.as_written(c.0) })
    }
}

impl ThermalCase {
    /// The heat balance of the case (after [`parse_case`], whose conductor exists).
    pub fn model(&self) -> Result<Model, catalog::CatalogError> {
        let k = self.conductor.thermal()?;
        Ok(Model::new(self.standard.into(), k, weather(&self.weather)).with_inclination(self.inclination_deg))
    }

    /// The de-icing model of the case's `[deicing]`, if any.
    pub fn deicing(&self) -> Result<Option<Deicing>, catalog::CatalogError> {
        let Some(d) = &self.deicing else { return Ok(None) };
        let k = self.conductor.thermal()?;
        let mut ice = IceShell::glaze(d.thickness_m);
        ice.density_kg_per_m3 = d.density_kg_per_m3;
        let mut de = Deicing::new(k, weather(&self.weather), self.standard.into(), ice);
        de.inclination_deg = self.inclination_deg;
        de.criterion = match d.criterion {
            ShedSpec::Slot => ShedCriterion::Slot,
            ShedSpec::FullMelt => ShedCriterion::FullMelt,
        };
        Ok(Some(de))
    }
}
