//! `ohl`: dynamics of overhead power-line wires.
//!
//! The model is an absolutely flexible, extensible wire in a Lagrangian coordinate (paper sections 1-2),
//! integrated by the explicit staggered-grid scheme (3.1)-(3.7) with Kelvin-Voigt tension (3.4),
//! aerodynamic loads with damping (2.5)-(2.6) and velocity smoothing (3.3). Everything is in SI units.
//!
//! Layers, one folder each (`docs/architecture.md` explains the design):
//! - [`wire`]: the physics of the line: nodes with constraints, segments with their own material,
//!   constitutive law, distributed loads;
//! - [`line`]: a line of several conductors (phases, earth wires, bundles) on shared supports, joined by
//!   attachments named by handle; [`element`]: the force elements written once over `f64` and dual numbers;
//! - [`conductor`]: real conductors (two materials, stress-strain polynomials, permanent set, creep);
//! - [`heat`]: heat conduction along the wire (5.1)-(5.4) and thermal expansion (5.5)-(5.6);
//! - [`scheme`]: the numerical schemes (explicit leapfrog, smoothing, Courant step);
//! - [`statics`]: the static equilibrium of the same discrete equations (Newton, faer);
//! - [`scenario`]: scenario files, their validation and the one conversion into a run plan;
//! - [`events`]: the event timeline of a run;
//! - [`observer`]: what a run tells its outputs (one time level, the events, the end), below both the
//!   run loop and the outputs; [`output`]: the observers that write or record a run; [`run`]: the run
//!   loop, which assembles the standard outputs;
//! - [`exact`]: exact static solutions the scheme is verified against;
//! - [`loads`]: ice and wind as the design codes give them (radial ice, the codes' load cases);
//! - [`thermal`]: conductor temperature from current and weather (IEEE 738, CIGRE TB 601).
//! - [`sagtension`]: sag-tension tables of a span or a ruling span (stringing, creep, heavy load, knee).
//! - [`shortcircuit`]: short-circuit forces on flexible conductors (IEC 60865-1 simplified method).
//! - [`verify`]: solution verification of a run's numbers (Celik's observed order, Richardson extrapolate
//!   and GCI over refined runs).
//!
//! The library holds the model only: the command line `ohl`, the paper cases, the plots, the benchmark
//! and the progress bar are the applications of the `ohl-app` crate (`app/`).

pub mod conductor;
pub mod element;
pub mod events;
pub mod exact;
pub mod heat;
pub mod line;
pub mod loads;
pub mod observer;
pub mod output;
pub mod run;
pub mod sagtension;
pub mod scenario;
pub mod scheme;
pub mod shortcircuit;
pub mod staggered_alloc;
pub mod statics;
pub mod thermal;
pub mod verify;
pub mod wire;

/// The unit tests run under the allocator the applications use (`staggered_alloc`), exercising it.
#[cfg(test)]
#[global_allocator]
static ALLOC: staggered_alloc::StaggeredAlloc = staggered_alloc::StaggeredAlloc;

#[cfg(test)]
mod test_rng;
