//! `ohl load-case NAME`: a code's combined ice-and-wind load case ([`ohl::loads::codes`]) as the TOML of a
//! scenario (`[loads.wind]`, the NESC constant as `[loads] uniform_load_n_per_m`, and the radial ice as an
//! `ice` event at t = 0) for a catalogue conductor; `ohl load-case list` names the cases.
//!
//! Exit codes: 0 printed; 2 an unknown case or conductor, or a value the case leaves to the user missing
//! (the message names the option and what the code leaves to choose).

use std::process::ExitCode;

use ohl::loads::codes::{self, Inputs};

/// Arguments of `ohl load-case`.
#[derive(clap::Args)]
pub struct LoadCaseArgs {
    /// the load case (`list` prints them)
    case: String,
    /// catalogue conductor (data/conductors.toml) whose diameter and weight the case is stated for
    #[arg(long, default_value = "ACSR Drake")]
    conductor: String,
    /// radial ice thickness [m] (overrides the case's)
    #[arg(long)]
    radial_ice_m: Option<f64>,
    /// ice density [kg/m^3] (overrides the case's)
    #[arg(long)]
    ice_density_kg_per_m3: Option<f64>,
    /// wind pressure on the projected iced diameter [Pa] (or --wind-speed-m-per-s)
    #[arg(long)]
    wind_pressure_pa: Option<f64>,
    /// wind speed [m/s] (or --wind-pressure-pa)
    #[arg(long)]
    wind_speed_m_per_s: Option<f64>,
    /// drag coefficient of the (iced) conductor [-]
    #[arg(long)]
    drag_coefficient: Option<f64>,
    /// air temperature [C] (a negative value as `--temperature-c -5` or `--temperature-c=-5`)
    #[arg(long, allow_hyphen_values = true)]
    temperature_c: Option<f64>,
}

/// Run the command.
pub fn main(a: LoadCaseArgs) -> ExitCode {
    if a.case == "list" {
        for c in codes::CASES {
            out!("{}: {}\n  the user chooses: {}", c.name, c.source, c.user_chooses);
        }
        return ExitCode::SUCCESS;
    }
    let k = match ohl::thermal::catalog::find(&a.conductor) {
        Ok(k) => k,
        Err(e) => {
            err!("error: --conductor {:?}: {e}", a.conductor);
            return ExitCode::from(2);
        }
    };
    let inputs = Inputs {
        radial_ice_m: a.radial_ice_m,
        ice_density_kg_per_m3: a.ice_density_kg_per_m3,
        wind_pressure_pa: a.wind_pressure_pa,
        wind_speed_m_per_s: a.wind_speed_m_per_s,
        drag_coefficient: a.drag_coefficient,
        temperature_c: a.temperature_c,
    };
    match codes::resolve(&a.case, &inputs) {
        Ok(r) => {
            out!("# conductor {} (d = {} m, {} kg/m)", a.conductor, k.diameter_m, k.linear_density_kg_per_m);
            out_text!("{}", r.toml(k.diameter_m, k.linear_density_kg_per_m, 9.81));
            ExitCode::SUCCESS
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(2)
        }
    }
}
