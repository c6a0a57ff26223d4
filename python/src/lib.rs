//! `ohl._ohl`: the Rust half of the Python package `ohl` (PyO3). It wraps the library, not the command
//! line: scenarios are parsed, validated and planned by `ohl::scenario`, run by `ohl::run::run_observed`
//! with the GIL released, and the numbers come back as NumPy arrays taken from the same code that writes
//! `timeseries.csv` and `snapshots.csv` (`ohl::output::timeseries::Columns`,
//! `ohl::output::snapshots::node_rows`). Line scenarios (`[line]`, several conductors) are run by
//! `ohl::run::line::run_line_observed` with the same observer on each conductor ([`line`]). The pure-Python
//! half (`python/ohl/__init__.py`) holds the result classes and the exceptions; `docs/python.md` documents
//! the API. `ohl.converge` runs the convergence study of the application crate
//! (`ohl_app::converge`, as `ohl run --converge`). Every argument is checked at the call ([`args`]; dicts: [`dict_input`]), as
//! `python/README.md` states the error contract.

mod args;
mod converge;
mod convert;
mod dict_input;
mod errors;
mod line;
mod sagtension;
mod scenario;
mod shortcircuit;
mod thermal;

use pyo3::prelude::*;

/// The kernel's arrays spread over the page (`ohl::staggered_alloc`; results are bitwise the same).
#[global_allocator]
static ALLOC: ohl::staggered_alloc::StaggeredAlloc = ohl::staggered_alloc::StaggeredAlloc;

/// The Rust extension of the `ohl` package (use `import ohl`, not this module).
#[pymodule]
fn _ohl(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<scenario::Scenario>()?;
    m.add_function(wrap_pyfunction!(scenario::run_raw, m)?)?;
    m.add_function(wrap_pyfunction!(scenario::equilibrium, m)?)?;
    m.add_class::<line::LineScenario>()?;
    m.add_function(wrap_pyfunction!(line::run_line_raw, m)?)?;
    m.add_function(wrap_pyfunction!(line::line_equilibrium, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::conductors, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::conductor, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::heat_terms, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::steady_temperature, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::ampacity, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::transient, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::deicing, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::deicing_current, m)?)?;
    m.add_function(wrap_pyfunction!(sagtension::sagtension_raw, m)?)?;
    m.add_function(wrap_pyfunction!(shortcircuit::shortcircuit_raw, m)?)?;
    m.add_function(wrap_pyfunction!(converge::converge_raw, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
