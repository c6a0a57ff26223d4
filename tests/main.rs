//! The library's integration tests, one test binary: each file below is one module (one concern: a
//! verification problem with its exact solution, a scenario family, a reference page). One binary instead
//! of one per file: each test binary links the whole library and its dependencies, which on 2 cores made
//! the test build most of the test command's time (issue 23). Run one file's tests with
//! `cargo test --release --test library catenary_sag::`.

mod catenary_sag;
mod common;
mod conductor_catalog;
mod conductor_contact;
mod dropper;
mod em_force;
mod energy;
mod equilibrium;
mod events;
mod fault_current;
mod fuzz_scenarios;
mod ground_friction;
mod iec60865;
mod knee_rating;
mod line;
mod line_reference;
mod line_scenario;
mod rating;
mod readme_example;
mod run_loop;
mod sagtension;
mod scenario_reference;
mod section;
mod section_events;
mod section_step;
mod section_stringing;
mod short_circuit_contact;
mod short_circuit_line;
mod short_circuit_scenario;
mod statics;
mod terrain;
mod thermal_conductor;
mod thermal_linerate;
mod two_material;
mod wind_arc;
