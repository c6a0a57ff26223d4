//! The heat balance of a conductor (IEEE Std 738-2012, CIGRE TB 601): steady temperature, ampacity, the
//! terms, transients and de-icing, with the conductor from the catalogue by name.
//!
//! Every function writes its arguments as a thermal case (the schema of `ohl thermal`,
//! `ohl::scenario::thermal::ThermalCase`) and reads it back with `parse_case`, so its inputs are checked
//! by the same rules, with the same messages, as the command's; the field names of the messages are
//! then made those of the Python arguments (`current_a`, `end_time_s`, `weather.wind_speed_m_per_s`).

use ohl::scenario::InputError;
use ohl::scenario::thermal::{ThermalCase, parse_case};
use ohl::thermal::catalog::{self, ConductorKind};
use ohl::thermal::deicing::DeicingOptions;
use ohl::thermal::transient::{CurrentSchedule, Transient, time_to_reach};
use ohl::thermal::{HeatBalance, Model, steady};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::args::{self, ARGUMENTS};
use crate::convert::array1;
use crate::dict_input;
use crate::errors::{input_error, raise};

/// The thermal case of the arguments, checked as `ohl thermal` checks a file; `rename` maps the case's
/// field names to the arguments'. `conductor` and `standard` must be str and `weather` a dict (else
/// `TypeError`); an error in the weather dict names its path (`weather.sun.day_of_year`), not a line of
/// the case's TOML text (`dict_input`).
fn case(
    py: Python<'_>,
    conductor: &Bound<'_, PyAny>,
    weather: &Bound<'_, PyAny>,
    standard: &Bound<'_, PyAny>,
    mut fields: toml::Table,
    rename: impl Fn(&str) -> String,
) -> PyResult<ThermalCase> {
    fields.insert("conductor".into(), args::text("conductor", conductor)?.into());
    fields.insert("standard".into(), args::text("standard", standard)?.into());
    fields
        .insert("weather".into(), toml::Value::Table(dict_input::table_of("weather", weather, ARGUMENTS, "weather")?));
    let text = dict_input::to_text(py, &fields, ARGUMENTS)?;
    dict_input::check::<ThermalCase>(&fields, ARGUMENTS).and_then(|()| parse_case(&text, ARGUMENTS)).map_err(|e| {
        let e = match e {
            InputError::Invalid { file, mut problems } => {
                for p in &mut problems {
                    p.field = rename(&p.field);
                }
                InputError::Invalid { file, problems }
            }
            other => other,
        };
        input_error(py, e)
    })
}

/// A computation that failed (no steady state, no ampacity, ice that does not shed) as `ohl.ThermalError`.
fn failed(py: Python<'_>, e: impl std::fmt::Display) -> PyErr {
    raise(py, "ThermalError", (format!("{ARGUMENTS}: {e}"),))
}

fn floats(v: &[f64]) -> toml::Value {
    toml::Value::Array(v.iter().map(|&x| toml::Value::Float(x)).collect())
}

/// `name[k]` -> `name` where the argument was a scalar (one value).
fn scalar_field(field: &str, name: &str, scalar: bool) -> String {
    if scalar && field.starts_with(&format!("{name}[")) { name.to_string() } else { field.to_string() }
}

fn model(py: Python<'_>, c: &ThermalCase) -> PyResult<Model> {
    c.model().map_err(|e| failed(py, e))
}

/// The names of the catalogue's conductors.
#[pyfunction]
pub fn conductors() -> Vec<String> {
    catalog::catalog().iter().map(|c| c.name.clone()).collect()
}

/// A conductor of the catalogue by its name or an alias (case-insensitive): every field, SI units and
/// kelvin. An unknown name raises `ohl.ScenarioError` listing the names available.
#[pyfunction]
pub fn conductor<'py>(py: Python<'py>, name: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let name = args::text("name", name)?;
    let name = name.as_str();
    let c = catalog::find(name).map_err(|e| {
        let p =
            ohl::scenario::Problem { field: "conductor".into(), value: format!("{name:?}"), allowed: e.to_string() };
        input_error(py, InputError::Invalid { file: ARGUMENTS.into(), problems: vec![p] })
    })?;
    let d = PyDict::new(py);
    d.set_item("name", &c.name)?;
    d.set_item("aliases", c.aliases.clone())?;
    d.set_item(
        "kind",
        match c.kind {
            ConductorKind::Acsr => "ACSR",
            ConductorKind::Aaac => "AAAC",
        },
    )?;
    let numbers = [
        ("diameter_m", c.diameter_m),
        ("core_diameter_m", c.core_diameter_m),
        ("outer_strand_diameter_m", c.outer_strand_diameter_m),
        ("aluminium_area_m2", c.aluminium_area_m2),
        ("steel_area_m2", c.steel_area_m2),
        ("linear_density_kg_per_m", c.linear_density_kg_per_m),
        ("rated_tensile_strength_n", c.rated_tensile_strength_n),
        ("axial_stiffness_n", c.axial_stiffness_n),
        ("thermal_expansion_per_k", c.thermal_expansion_per_k),
        ("resistance_low_ohm_per_m", c.resistance_low_ohm_per_m),
        ("temperature_low_k", c.temperature_low_k),
        ("resistance_high_ohm_per_m", c.resistance_high_ohm_per_m),
        ("temperature_high_k", c.temperature_high_k),
        ("magnetic_core_factor", c.magnetic_core_factor),
        ("emissivity", c.emissivity),
        ("absorptivity", c.absorptivity),
        ("outer_mass_kg_per_m", c.outer_mass_kg_per_m),
        ("outer_specific_heat_j_per_kg_k", c.outer_specific_heat_j_per_kg_k),
        ("outer_specific_heat_coefficient_per_k", c.outer_specific_heat_coefficient_per_k),
        ("core_mass_kg_per_m", c.core_mass_kg_per_m),
        ("core_specific_heat_j_per_kg_k", c.core_specific_heat_j_per_kg_k),
        ("core_specific_heat_coefficient_per_k", c.core_specific_heat_coefficient_per_k),
    ];
    for (k, v) in numbers {
        d.set_item(k, v)?;
    }
    d.set_item("source", &c.source)?;
    Ok(d)
}

/// The heat-balance terms [W/m] at temperatures `temperature_k` [K] and currents `current_a` [A] (equal
/// lengths).
#[pyfunction]
#[pyo3(signature = (temperature_k, current_a, conductor, weather, standard, scalar))]
pub fn heat_terms<'py>(
    py: Python<'py>,
    temperature_k: Vec<f64>,
    current_a: Vec<f64>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    scalar: bool,
) -> PyResult<Bound<'py, PyDict>> {
    if temperature_k.len() != current_a.len() {
        return Err(PyTypeError::new_err("temperature_k and current_a must have the same length"));
    }
    // The terms are evaluated at any conductor temperature in the range of a thermal case's maximum
    // temperatures, also below the air (negative convection), which a maximum temperature may not be.
    for (k, &t) in temperature_k.iter().enumerate() {
        if !(250.0..=600.0).contains(&t) {
            let param = scalar_field(&format!("temperature_k[{k}]"), "temperature_k", scalar);
            return Err(crate::args::bad_value(
                py,
                &param,
                ohl::scenario::validate::number(t),
                "must be in [250, 600] K",
            ));
        }
    }
    let mut f = toml::Table::new();
    f.insert("current_a".into(), floats(&current_a));
    let c = case(py, conductor, weather, standard, f, |field| scalar_field(field, "current_a", scalar))?;
    let m = model(py, &c)?;
    let terms: Vec<_> = py.detach(|| temperature_k.iter().zip(&current_a).map(|(&t, &i)| m.terms(t, i)).collect());
    let d = terms_dict(py, &terms)?;
    d.set_item("temperature_k", array1(py, temperature_k))?;
    d.set_item("current_a", array1(py, current_a))?;
    Ok(d)
}

fn terms_dict<'py>(py: Python<'py>, terms: &[ohl::thermal::HeatTerms]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("joule_w_per_m", array1(py, terms.iter().map(|q| q.joule_w_per_m).collect()))?;
    d.set_item("solar_w_per_m", array1(py, terms.iter().map(|q| q.solar_w_per_m).collect()))?;
    d.set_item("convection_w_per_m", array1(py, terms.iter().map(|q| q.convection_w_per_m).collect()))?;
    d.set_item("radiation_w_per_m", array1(py, terms.iter().map(|q| q.radiation_w_per_m).collect()))?;
    Ok(d)
}

/// The steady solutions of `solve` for each of `inputs` (the case field `input`), as a dict of the heat
/// terms, `input` and `output`: `solve` gives a solution and the (temperature [K], current [A]) it holds at.
#[allow(clippy::too_many_arguments)]
fn steady_solutions<'py, E: std::fmt::Display + Send>(
    py: Python<'py>,
    inputs: Vec<f64>,
    input: &str,
    output: &str,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    scalar: bool,
    solve: impl Fn(&Model, f64) -> Result<(f64, (f64, f64)), E> + Send + Sync,
) -> PyResult<Bound<'py, PyDict>> {
    let mut f = toml::Table::new();
    f.insert(input.into(), floats(&inputs));
    let c = case(py, conductor, weather, standard, f, |field| scalar_field(field, input, scalar))?;
    let m = model(py, &c)?;
    let solved: Result<Vec<_>, E> =
        py.detach(|| inputs.iter().map(|&x| solve(&m, x).map(|(y, (t, i))| (y, m.terms(t, i)))).collect());
    let solved = solved.map_err(|e| failed(py, e))?;
    let terms: Vec<_> = solved.iter().map(|s| s.1).collect();
    let d = terms_dict(py, &terms)?;
    d.set_item(input, array1(py, inputs))?;
    d.set_item(output, array1(py, solved.iter().map(|s| s.0).collect()))?;
    Ok(d)
}

/// The steady conductor temperature [K] for each current [A], with the terms there (as `ohl thermal`).
#[pyfunction]
#[pyo3(signature = (current_a, conductor, weather, standard, scalar))]
pub fn steady_temperature<'py>(
    py: Python<'py>,
    current_a: Vec<f64>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    scalar: bool,
) -> PyResult<Bound<'py, PyDict>> {
    steady_solutions(py, current_a, "current_a", "temperature_k", conductor, weather, standard, scalar, |m, i| {
        steady::temperature(m, i).map(|s| (s.temperature_k, (s.temperature_k, i)))
    })
}

/// The steady ampacity [A] for each maximum conductor temperature [K], with the terms there.
#[pyfunction]
#[pyo3(signature = (max_temperature_k, conductor, weather, standard, scalar))]
pub fn ampacity<'py>(
    py: Python<'py>,
    max_temperature_k: Vec<f64>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    scalar: bool,
) -> PyResult<Bound<'py, PyDict>> {
    steady_solutions(
        py,
        max_temperature_k,
        "max_temperature_k",
        "current_a",
        conductor,
        weather,
        standard,
        scalar,
        |m, t| steady::ampacity(m, t).map(|a| (a.current_a, (t, a.current_a))),
    )
}

/// The conductor temperature after a current schedule (RK4, as `ohl thermal`'s `[transient]`).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn transient<'py>(
    py: Python<'py>,
    current_a: Vec<[f64; 2]>,
    end_time_s: &Bound<'py, PyAny>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    initial_temperature_k: Option<&Bound<'py, PyAny>>,
    step_s: &Bound<'py, PyAny>,
    limit_k: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let end_time_s = args::real("end_time_s", end_time_s)?;
    let step_s = args::real("step_s", step_s)?;
    let initial_temperature_k = args::optional_real("initial_temperature_k", initial_temperature_k)?;
    let limit_k = args::optional_real("limit_k", limit_k)?;
    let mut t = toml::Table::new();
    t.insert("current_a".into(), toml::Value::Array(current_a.iter().map(|p| floats(p)).collect()));
    t.insert("end_time_s".into(), end_time_s.into());
    t.insert("step_s".into(), step_s.into());
    if let Some(k) = initial_temperature_k {
        t.insert("initial_temperature_k".into(), k.into());
    }
    if let Some(k) = limit_k {
        t.insert("limit_k".into(), k.into());
    }
    let mut f = toml::Table::new();
    f.insert("transient".into(), toml::Value::Table(t));
    let c =
        case(py, conductor, weather, standard, f, |field| field.strip_prefix("transient.").unwrap_or(field).into())?;
    let m = model(py, &c)?;
    let spec = c.transient.as_ref().expect("the case has the [transient] table it was given");
    let schedule = CurrentSchedule::new(spec.current_a.iter().map(|p| (p[0], p[1])).collect())
        .ok_or_else(|| failed(py, "current_a: not a schedule"))?;
    let t0 = match spec.initial_temperature_k {
        Some(k) => k,
        None => steady::temperature(&m, schedule.initial_a()).map_err(|e| failed(py, e))?.temperature_k,
    };
    let (samples, reach) = py.detach(|| {
        let tr = Transient { model: &m, current: &schedule, step_s: spec.step_s };
        let samples = tr.run(0.0, t0, spec.end_time_s);
        let reach = spec.limit_k.map(|l| time_to_reach(&tr, 0.0, t0, l, spec.end_time_s));
        (samples, reach)
    });
    let d = PyDict::new(py);
    d.set_item("t_s", array1(py, samples.iter().map(|s| s.time_s).collect()))?;
    d.set_item("current_a", array1(py, samples.iter().map(|s| s.current_a).collect()))?;
    d.set_item("temperature_k", array1(py, samples.iter().map(|s| s.temperature_k).collect()))?;
    d.set_item("initial_temperature_k", t0)?;
    d.set_item("final_temperature_k", samples.last().map_or(t0, |s| s.temperature_k))?;
    d.set_item("limit_k", spec.limit_k)?;
    d.set_item("time_to_limit_s", reach.flatten())?;
    Ok(d)
}

/// The arguments of an ice shell common to `deicing` and `deicing_current`, as Python gave them.
struct Shell<'a, 'py> {
    thickness_m: &'a Bound<'py, PyAny>,
    conductor: &'a Bound<'py, PyAny>,
    weather: &'a Bound<'py, PyAny>,
    standard: &'a Bound<'py, PyAny>,
    density_kg_per_m3: &'a Bound<'py, PyAny>,
    criterion: &'a Bound<'py, PyAny>,
    step_s: &'a Bound<'py, PyAny>,
}

/// The de-icing case of the arguments (`[deicing]` of `ohl thermal`) with the asked quantity (`current_a`
/// or `shed_within_s`) and its value.
fn deicing_case(
    py: Python<'_>,
    shell: Shell<'_, '_>,
    asked: (&str, &Bound<'_, PyAny>),
) -> PyResult<(ohl::thermal::deicing::Deicing, DeicingOptions, f64)> {
    let thickness_m = args::real("thickness_m", shell.thickness_m)?;
    let value = args::real(asked.0, asked.1)?;
    let density_kg_per_m3 = args::real("density_kg_per_m3", shell.density_kg_per_m3)?;
    let criterion = args::text("criterion", shell.criterion)?;
    let step_s = args::real("step_s", shell.step_s)?;
    let mut t = toml::Table::new();
    t.insert("thickness_m".into(), thickness_m.into());
    t.insert("density_kg_per_m3".into(), density_kg_per_m3.into());
    t.insert("criterion".into(), criterion.into());
    t.insert("step_s".into(), step_s.into());
    t.insert(asked.0.into(), floats(&[value]));
    let mut f = toml::Table::new();
    f.insert("deicing".into(), toml::Value::Table(t));
    let c = case(py, shell.conductor, shell.weather, shell.standard, f, |field| {
        scalar_field(field.strip_prefix("deicing.").unwrap_or(field), asked.0, true)
    })?;
    let de = c.deicing().map_err(|e| failed(py, e))?.expect("the case has the [deicing] table it was given");
    let opts = DeicingOptions { step_s, ..Default::default() };
    Ok((de, opts, value))
}

/// De-icing of an ice shell by a current: warming, melting and the time to shed. `record_every_s` is the
/// interval of the series [s], `>= 0` and finite (`DeicingOptions::record_every_s`; 0 records every step).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn deicing<'py>(
    py: Python<'py>,
    thickness_m: &Bound<'py, PyAny>,
    current_a: &Bound<'py, PyAny>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    density_kg_per_m3: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
    step_s: &Bound<'py, PyAny>,
    record_every_s: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let shell = Shell { thickness_m, conductor, weather, standard, density_kg_per_m3, criterion, step_s };
    let (de, mut opts, current_a) = deicing_case(py, shell, ("current_a", current_a))?;
    let record = args::real("record_every_s", record_every_s)?;
    if !(record.is_finite() && record >= 0.0) {
        let allowed = "must be a finite number >= 0 s (0 records every step)";
        return Err(args::bad_value(py, "record_every_s", ohl::scenario::validate::number(record), allowed));
    }
    opts.record_every_s = record;
    let (min, r) = py.detach(|| (de.minimum_current_a(), de.run(current_a, &opts)));
    let min = min.map_err(|e| failed(py, e))?;
    let r = r.map_err(|e| failed(py, e))?;
    let d = PyDict::new(py);
    d.set_item("current_a", r.current_a)?;
    d.set_item("minimum_current_a", min)?;
    d.set_item("melting_from_s", r.warm_time_s)?;
    d.set_item("shed_time_s", r.shed_time_s)?;
    d.set_item("initial_temperature_k", r.initial_temperature_k)?;
    d.set_item("ice_kg_per_m", r.ice_mass_kg_per_m)?;
    d.set_item("shed_kg_per_m", r.shed_mass_kg_per_m)?;
    d.set_item("melt_rate_kg_per_m_s", r.melt_rate_kg_per_m_s)?;
    let e = PyDict::new(py);
    e.set_item("joule", r.energy.joule_j_per_m)?;
    e.set_item("sensible", r.energy.sensible_j_per_m)?;
    e.set_item("latent", r.energy.latent_j_per_m)?;
    e.set_item("losses", r.energy.losses_j_per_m)?;
    e.set_item("closure", r.energy.closure_j_per_m)?;
    d.set_item("energy_j_per_m", e)?;
    let s = &r.series;
    d.set_item("t_s", array1(py, s.iter().map(|p| p.time_s).collect()))?;
    d.set_item("conductor_k", array1(py, s.iter().map(|p| p.conductor_k).collect()))?;
    d.set_item("surface_k", array1(py, s.iter().map(|p| p.surface_k).collect()))?;
    d.set_item("melted_kg_per_m", array1(py, s.iter().map(|p| p.melted_kg_per_m).collect()))?;
    d.set_item("joule_w_per_m", array1(py, s.iter().map(|p| p.joule_w_per_m).collect()))?;
    d.set_item("loss_w_per_m", array1(py, s.iter().map(|p| p.loss_w_per_m).collect()))?;
    Ok(d)
}

/// The least current [A] that sheds the shell within `shed_within_s` [s] (bisection to 1e-3 A).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn deicing_current<'py>(
    py: Python<'py>,
    thickness_m: &Bound<'py, PyAny>,
    shed_within_s: &Bound<'py, PyAny>,
    conductor: &Bound<'py, PyAny>,
    weather: &Bound<'py, PyAny>,
    standard: &Bound<'py, PyAny>,
    density_kg_per_m3: &Bound<'py, PyAny>,
    criterion: &Bound<'py, PyAny>,
    step_s: &Bound<'py, PyAny>,
) -> PyResult<f64> {
    let shell = Shell { thickness_m, conductor, weather, standard, density_kg_per_m3, criterion, step_s };
    let (de, mut opts, shed_within_s) = deicing_case(py, shell, ("shed_within_s", shed_within_s))?;
    opts.record_every_s = 10.0;
    py.detach(|| de.current_to_shed_in(shed_within_s, &opts)).map_err(|e| failed(py, e))
}
