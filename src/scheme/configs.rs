//! The benchmark configurations of the explicit kernel: the paper's test wire of section 4
//! (`EA = 80734 g` N, `rho0 = 1` kg/m, span 160 m) released from the straight chord, Courant number 0.9
//! unless stated. They are the workloads of the kernel's bitwise tests, of `ohl bench` and of the
//! criterion bench (`app/benches/kernel.rs`).
//! - [`Config::PlaneWeight`]: weight only; the motion stays in the vertical plane `x2 x3`;
//! - [`Config::Wind3d`]: weight and the aerodynamic wind (2.5) with damping (2.6), `mu = 0.2`, across the
//!   span: a 3D motion;
//! - [`Config::ViscousSmoothed`]: weight, the uniform normal pressure of section 4.1 (3.805 N/m), Kelvin-Voigt
//!   friction `eta = 2` N s (3.4) and velocity smoothing `b = 0.02` (3.3); Courant 0.8, below the
//!   internal-friction limit `sqrt(1 + z^2) - z` (> 0.93 for N <= 5000, see [`super::courant`]);
//! - [`Config::TwoMaterialPlane`]: weight only, in the vertical plane, with the real conductor's law:
//!   ACSR Drake's two materials from the catalogue (stress-strain polynomials, per-segment history,
//!   [`crate::conductor`]) and Drake's 1.628 kg/m; the wave speed and the step from the law's largest
//!   stiffness. The same span, released from the chord (at the curves' reference temperature the
//!   aluminium is slack until 0.028 %).

use super::courant;
use super::{Explicit, Loads, StepParams, WindGate, WindLoad};
use crate::element::aero::{Aerodynamic, UniformNormal};
use crate::element::tension::LawKind;
use crate::wire::{Conductor, Wire};

/// Axial stiffness of the paper's test wire, "E = 80734 g" [N] (section 4; docs/paper_notes.md).
pub const EA_N: f64 = 80734.0 * 9.81;
/// Linear density of the paper's iced test wire [kg/m] (section 4.1).
pub const RHO_KG_PER_M: f64 = 1.0;
/// Span [m] (section 4).
pub const SPAN_M: f64 = 160.0;
/// Conductor diameter [m] (section 4.1).
pub const DIAMETER_M: f64 = 0.01553;

/// A benchmark configuration of the kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Config {
    /// weight only, motion in the vertical plane
    PlaneWeight,
    /// weight plus aerodynamic wind with damping, 3D
    Wind3d,
    /// weight plus uniform normal pressure, Kelvin-Voigt friction and velocity smoothing, 3D
    ViscousSmoothed,
    /// weight only, in the plane, with ACSR Drake's two-material law
    TwoMaterialPlane,
}

impl Config {
    /// All configurations, in table order.
    pub const ALL: [Config; 4] =
        [Config::PlaneWeight, Config::Wind3d, Config::ViscousSmoothed, Config::TwoMaterialPlane];

    /// Short name used in tables and files.
    pub fn name(self) -> &'static str {
        match self {
            Config::PlaneWeight => "plane_weight",
            Config::Wind3d => "wind_3d",
            Config::ViscousSmoothed => "kv_smoothing_3d",
            Config::TwoMaterialPlane => "two_material_plane",
        }
    }

    /// Parse a name given by [`Config::name`].
    pub fn from_name(s: &str) -> Option<Config> {
        Config::ALL.into_iter().find(|c| c.name() == s)
    }

    /// A solver for this configuration with `n` segments, at rest on the straight chord at `t = 0`.
    pub fn solver(self, n: usize) -> Explicit {
        let eta = if self == Config::ViscousSmoothed { 2.0 } else { 0.0 };
        let conductor = Conductor { axial_stiffness_n: EA_N, internal_friction_n_s: eta, law: LawKind::TensionOnly };
        let x = [vec![0.0; n + 1], (0..=n).map(|i| SPAN_M * i as f64 / n as f64).collect(), vec![0.0; n + 1]];
        let ds = SPAN_M / n as f64;
        let (rho, mut wire) = if self == Config::TwoMaterialPlane {
            let drake = crate::thermal::catalog::find("ACSR Drake").expect("Drake is in the catalogue");
            let law = drake.two_material().expect("Drake has stress-strain data");
            let mut w = Wire::new(conductor, x, vec![ds; n], drake.linear_density_kg_per_m);
            w.set_two_material(law, crate::conductor::CurveKind::Initial);
            (drake.linear_density_kg_per_m, w)
        } else {
            (RHO_KG_PER_M, Wire::new(conductor, x, vec![ds; n], RHO_KG_PER_M))
        };
        if self == Config::TwoMaterialPlane {
            // At the curves' reference temperature (the strains are measured from there).
            let t = wire.material.as_ref().map_or(wire.reference_temperature_k, |m| m.law.reference_temperature_k);
            wire.temperature_k.fill(t);
        }
        let c = courant::wave_speed(wire.axial_stiffness_n[0], rho);
        let q = 0.5 * 1.225 * 20.0 * 20.0 * DIAMETER_M;
        let (wind, cfl, smoothing) = match self {
            Config::PlaneWeight | Config::TwoMaterialPlane => (None, 0.9, 0.0),
            Config::Wind3d => (
                Some(WindLoad::Aerodynamic(Aerodynamic {
                    direction: [1.0, 0.0, 0.0],
                    qd_cn: q * 1.8446,
                    qd_ct: q * 0.0554,
                    mu_over_u: 0.2 / 20.0,
                })),
                0.9,
                0.0,
            ),
            Config::ViscousSmoothed => (
                Some(WindLoad::UniformNormal(UniformNormal {
                    direction: [1.0, 0.0, 0.0],
                    pressure_n_per_m: q,
                    mu_over_u: 0.0,
                })),
                0.8,
                0.02,
            ),
        };
        let loads = Loads {
            gravity_m_per_s2: 9.81,
            uniform_load_n_per_m: [0.0; 3],
            wind,
            wind_scale: 1.0,
            wind_gate: WindGate::Always,
        };
        let params = StepParams {
            dt_s: courant::time_step(cfl, ds, c),
            smoothing,
            mass_damping_per_s: 0.0,
            max_speed_m_per_s: c,
        };
        Explicit::new(wire, loads, params)
    }
}
