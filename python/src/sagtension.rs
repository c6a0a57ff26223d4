//! `ohl.sagtension`: the sag-tension table of a case ([`ohl::scenario::sagtension`], the file of
//! `ohl sagtension`) from a file or a dict, solved by the library ([`ohl::scenario::sagtension_table`])
//! with the GIL released. The rows come back as columns (lists, made NumPy arrays by `ohl/__init__.py`)
//! with the names of `sagtension.csv`'s columns, so that a table from Python and the command's file hold
//! the same numbers.

use ohl::sagtension::State;
use ohl::scenario::sagtension::{self, LawKind};
use ohl::scenario::sagtension_table::{self, Found};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::dict_input::{table_of, to_text};
use crate::errors::{input_error, raise};

fn found<'py>(py: Python<'py>, f: &[(State, Found)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (s, v) in f {
        d.set_item(s.name(), v.as_ref().ok().copied())?;
    }
    Ok(d)
}

/// The table of a sag-tension case: `source` a path (str or os.PathLike) or a mapping with the file's
/// tables; `name` stands for the file in messages of a mapping. Invalid input raises `ohl.ScenarioError`
/// (file, field, value, allowed); a case the solver cannot solve `ohl.StaticsError` with its reason.
#[pyfunction]
#[pyo3(signature = (source, name))]
pub fn sagtension_raw<'py>(py: Python<'py>, source: &Bound<'py, PyAny>, name: &str) -> PyResult<Bound<'py, PyDict>> {
    let (parsed, file) = if source.cast::<pyo3::types::PyMapping>().is_ok() {
        let table = table_of("case", source, name, "")?;
        let text = to_text(py, &table, name)?;
        (sagtension::parse_case(&text, name), name.to_string())
    } else {
        let path = crate::args::path("case", source)?;
        (sagtension::load(&path), path.display().to_string())
    };
    let (case, r) = parsed.map_err(|e| input_error(py, e))?;
    let table = py.detach(|| sagtension_table::solve(&r));
    let t = table.map_err(|e| raise(py, "StaticsError", (format!("{file}: {e}"),)))?;
    let per = t.states.len();
    let d = PyDict::new(py);
    let rows = &t.rows;
    let col = |f: &dyn Fn(usize) -> f64| -> Vec<f64> { (0..rows.len()).map(f).collect() };
    let cond = |k: usize| &r.conditions[k / per];
    d.set_item("name", case.name.clone())?;
    d.set_item("conductor", r.conductor.name.clone())?;
    d.set_item(
        "law",
        match t.law {
            LawKind::TwoMaterial => "two_material",
            LawKind::SingleModulus => "single_modulus",
        },
    )?;
    d.set_item("spans_m", r.lengths_m.clone())?;
    d.set_item("span_m", t.span_m)?;
    d.set_item("states", t.states.iter().map(|s| s.name()).collect::<Vec<_>>())?;
    d.set_item("final_is", t.final_is.name())?;
    d.set_item("knee_temperature_k", found(py, &t.knee_k)?)?;
    d.set_item("sag_limit_m", t.sag_limit_m)?;
    d.set_item("sag_limit_temperature_k", found(py, &t.limit_k)?)?;
    d.set_item("labels", r.conditions.iter().map(|w| w.label.clone()).collect::<Vec<_>>())?;
    let c = PyDict::new(py);
    c.set_item("condition", (0..rows.len()).map(|k| k / per).collect::<Vec<_>>())?;
    c.set_item("state", rows.iter().map(|x| x.state.name()).collect::<Vec<_>>())?;
    c.set_item("history_of", rows.iter().map(|x| x.history_of.name()).collect::<Vec<_>>())?;
    c.set_item("temperature_k", col(&|k| cond(k).temperature_k))?;
    c.set_item("ice_thickness_m", col(&|k| cond(k).ice_thickness_m))?;
    c.set_item("wind_pressure_pa", col(&|k| cond(k).wind_pressure_pa * cond(k).drag_coefficient))?;
    c.set_item("constant_n_per_m", col(&|k| cond(k).constant_n_per_m))?;
    c.set_item("load_n_per_m", col(&|k| rows[k].load_n_per_m))?;
    c.set_item("horizontal_tension_n", col(&|k| rows[k].horizontal_tension_n))?;
    c.set_item("sag_m", col(&|k| rows[k].sag_midspan_m))?;
    c.set_item("sag_max_m", col(&|k| rows[k].sag_max_m))?;
    c.set_item("support_tension_n", col(&|k| rows[k].support_tension_a_n.max(rows[k].support_tension_b_n)))?;
    c.set_item("tension_percent_rts", col(&|k| 100.0 * rows[k].max_tension_fraction_rts))?;
    c.set_item("aluminium_stress_pa", col(&|k| rows[k].outer_stress_pa))?;
    c.set_item("core_stress_pa", col(&|k| rows[k].core_stress_pa))?;
    c.set_item("knee_passed", rows.iter().map(|x| x.knee_passed).collect::<Vec<_>>())?;
    c.set_item("strain", col(&|k| rows[k].strain_max))?;
    c.set_item("conductor_length_m", col(&|k| rows[k].length_m))?;
    let spans = r.lengths_m.len();
    let flat: Vec<f64> = t.span_sags_m.iter().flatten().copied().collect();
    c.set_item("span_sags_m", crate::convert::array2(py, flat, rows.len(), spans)?)?;
    d.set_item("rows", c)?;
    Ok(d)
}
