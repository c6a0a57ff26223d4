//! The paper's test wire and the three static load cases, built directly (no scenario file).
//!
//! Wire of sections 4.1-4.2: span `l = 160 m`, axial stiffness `EA = 80734 g` [N] (docs/paper_notes.md: a force, not
//! a modulus), linear density `rho0 = 1.0 kg/m` (wire plus ice), `g = 9.81 m/s^2`, wind line load
//! `p = rho_air U^2 d / 2` with `rho_air = 1.225 kg/m^3`, `U = 20 m/s`, `d = 0.01553 m` (section 4.1).

use ohl::element::aero::{Aerodynamic, UniformNormal};
use ohl::element::tension::LawKind;
use ohl::exact::{ElasticArc, ElasticCatenary};
use ohl::scheme::courant;
use ohl::scheme::{Explicit, Loads, StepParams, WindGate, WindLoad};
use ohl::wire::{Conductor, Wire};

/// The wire of sections 4.1-4.2 in words, for figure headings.
pub const PAPER_WIRE: &str = "the paper's wire: 160 m span, 1.0 kg/m, EA = 792 kN, d = 15.53 mm";

/// axial stiffness `EA` [N] (section 4.1: "E = 80734 g")
pub const EA_N: f64 = 80734.0 * 9.81;
/// linear density `rho0` [kg/m] (wire plus equal ice, section 4.1)
pub const RHO_KG_PER_M: f64 = 1.0;
/// span `l` [m]
pub const SPAN_M: f64 = 160.0;
/// gravitational acceleration `g` [m/s^2]
pub const G_M_PER_S2: f64 = 9.81;
/// air density [kg/m^3]
pub const RHO_AIR: f64 = 1.225;
/// wind speed `U` [m/s]
pub const WIND_U_M_PER_S: f64 = 20.0;
/// conditional diameter `d` [m]
pub const DIAMETER_M: f64 = 0.01553;
/// wind line load `p = rho_air U^2 d / 2` [N/m] (section 4.1)
pub const P_N_PER_M: f64 = 0.5 * RHO_AIR * WIND_U_M_PER_S * WIND_U_M_PER_S * DIAMETER_M;
/// aerodynamic coefficients (2.5)
pub const C_N: f64 = 1.8446;
/// tangential aerodynamic coefficient (2.5)
pub const C_TAU: f64 = 0.0554;

/// Longitudinal wave speed `sqrt(EA / rho0)` [m/s] of the paper's wire.
pub fn wave_speed() -> f64 {
    courant::wave_speed(EA_N, RHO_KG_PER_M)
}

/// A straight wire of `n` equal segments along `x2` from `(0,0,0)` to `(0,l,0)`, stress-free length `l`,
/// at rest, with the given law and internal friction `eta` [N s].
pub fn straight_wire(n: usize, law: LawKind, eta_n_s: f64) -> Wire {
    let ds = SPAN_M / n as f64;
    let x2: Vec<f64> = (0..=n).map(|i| i as f64 * ds).collect();
    let conductor = Conductor { axial_stiffness_n: EA_N, internal_friction_n_s: eta_n_s, law };
    Wire::new(conductor, [vec![0.0; n + 1], x2, vec![0.0; n + 1]], vec![ds; n], RHO_KG_PER_M)
}

/// Loads with gravity `g` [m/s^2], a uniform load `q` [N/m] and an optional wind, always on.
pub fn loads(gravity: f64, uniform: [f64; 3], wind: Option<WindLoad>) -> Loads {
    Loads {
        gravity_m_per_s2: gravity,
        uniform_load_n_per_m: uniform,
        wind,
        wind_scale: 1.0,
        wind_gate: WindGate::Always,
    }
}

/// Step parameters for a Courant number `c` on `n` segments: `dt = C ds / sqrt(EA/rho0)` (3.7).
pub fn params(n: usize, courant_number: f64, smoothing: f64, mass_damping_per_s: f64) -> StepParams {
    StepParams {
        dt_s: courant::time_step(courant_number, SPAN_M / n as f64, wave_speed()),
        smoothing,
        mass_damping_per_s,
        max_speed_m_per_s: 1.0e3,
    }
}

/// The uniform normal pressure of section 4.1 along `+x1`, with damping coefficient `mu` (2.6).
pub fn uniform_wind(mu: f64) -> WindLoad {
    WindLoad::UniformNormal(UniformNormal {
        direction: [1.0, 0.0, 0.0],
        pressure_n_per_m: P_N_PER_M,
        mu_over_u: mu / WIND_U_M_PER_S,
    })
}

/// The aerodynamic law (2.5)-(2.6) for the paper's wire, wind along `+x1`.
pub fn aerodynamic_wind(mu: f64) -> WindLoad {
    WindLoad::Aerodynamic(Aerodynamic {
        direction: [1.0, 0.0, 0.0],
        qd_cn: P_N_PER_M * C_N,
        qd_ct: P_N_PER_M * C_TAU,
        mu_over_u: mu / WIND_U_M_PER_S,
    })
}

/// The three static cases with exact references.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case {
    /// weight only: the elastic catenary (section 4.2)
    Catenary,
    /// uniform normal wind pressure, no weight: the elastic circular arc (section 4.1)
    Arc,
    /// weight plus a fixed-direction wind load `p e1`: the catenary in the plane of the resultant (4.3)
    Combined,
}

impl Case {
    /// all cases
    pub const ALL: [Case; 3] = [Case::Catenary, Case::Arc, Case::Combined];

    /// short name
    pub fn name(self) -> &'static str {
        match self {
            Case::Catenary => "catenary",
            Case::Arc => "arc",
            Case::Combined => "combined",
        }
    }

    /// the loads of the case
    pub fn loads(self) -> Loads {
        match self {
            Case::Catenary => loads(G_M_PER_S2, [0.0; 3], None),
            Case::Arc => loads(0.0, [0.0; 3], Some(uniform_wind(0.0))),
            Case::Combined => loads(G_M_PER_S2, [P_N_PER_M, 0.0, 0.0], None),
        }
    }

    /// the exact equilibrium position at Lagrangian coordinate `s` [m] and the exact mid-span displacement
    pub fn exact(self) -> Exact {
        match self {
            Case::Catenary | Case::Combined => {
                let q = if self == Case::Catenary {
                    [0.0, 0.0, -RHO_KG_PER_M * G_M_PER_S2]
                } else {
                    [P_N_PER_M, 0.0, -RHO_KG_PER_M * G_M_PER_S2]
                };
                let c = ElasticCatenary::solve([0.0; 3], [0.0, SPAN_M, 0.0], SPAN_M, q, EA_N)
                    .expect("the paper's catenary has a solution");
                Exact::Catenary(c)
            }
            Case::Arc => Exact::Arc(ElasticArc::solve(SPAN_M, SPAN_M, P_N_PER_M, EA_N).expect("the paper's arc")),
        }
    }

    /// the fundamental transverse angular frequency of the equilibrium, `pi / l sqrt(T / rho0)` [rad/s]
    /// with the mid-span tension (the damping that makes dynamic relaxation near-critical)
    pub fn fundamental_rad_per_s(self) -> f64 {
        let t = self.exact().tension_n(0.5 * SPAN_M);
        std::f64::consts::PI / SPAN_M * (t / RHO_KG_PER_M).sqrt()
    }
}

/// An exact static reference.
#[derive(Clone, Debug)]
pub enum Exact {
    /// elastic catenary
    Catenary(ElasticCatenary),
    /// elastic arc (chord along `x2`, deflection along `+x1`)
    Arc(ElasticArc),
}

impl Exact {
    /// position at Lagrangian coordinate `s` [m]
    pub fn position(&self, s: f64) -> [f64; 3] {
        match self {
            Exact::Catenary(c) => c.position(s),
            Exact::Arc(a) => {
                let (xi, zeta) = a.position(s);
                [zeta, xi, 0.0]
            }
        }
    }

    /// tension at Lagrangian coordinate `s` [m]
    pub fn tension_n(&self, s: f64) -> f64 {
        match self {
            Exact::Catenary(c) => c.tension_n(s),
            Exact::Arc(a) => a.tension_n(),
        }
    }

    /// magnitude of the mid-span displacement from the chord midpoint [m]
    pub fn midspan_deflection_m(&self) -> f64 {
        let p = self.position(0.5 * SPAN_M);
        (p[0] * p[0] + (p[1] - 0.5 * SPAN_M).powi(2) + p[2] * p[2]).sqrt()
    }
}

/// A wire of `n` segments whose nodes lie on a parabola through the supports with mid-span displacement
/// `mid` [m] (a vector): the starting shape of dynamic relaxation and of Newton's method.
pub fn parabolic_wire(n: usize, law: LawKind, eta_n_s: f64, mid: [f64; 3]) -> Wire {
    let mut w = straight_wire(n, law, eta_n_s);
    for i in 0..=n {
        let s = i as f64 / n as f64;
        let f = 4.0 * s * (1.0 - s);
        for k in 0..3 {
            w.x[k][i] += f * mid[k];
        }
    }
    w
}

/// The explicit solver for a case on `n` segments from a parabolic start.
pub fn explicit_for(case: Case, n: usize, courant_number: f64, mass_damping: f64, start_mid: [f64; 3]) -> Explicit {
    let wire = parabolic_wire(n, LawKind::Linear, 0.0, start_mid);
    Explicit::new(wire, case.loads(), params(n, courant_number, 0.0, mass_damping))
}

/// Largest net force on a free node [N] (the static residual of the discrete equations).
pub fn max_residual(s: &mut Explicit) -> f64 {
    let n1 = s.wire().nodes();
    let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    s.net_force(&mut f);
    let mut m: f64 = 0.0;
    for i in 0..n1 {
        if s.wire().free[i] > 0.0 {
            for fk in &f {
                m = m.max(fk[i].abs());
            }
        }
    }
    m
}

/// Run dynamic relaxation until the largest nodal residual falls below `tol_n` [N] and every speed below
/// 1e-8 m/s (above the rounding noise of the axial modes, about 2e-9 m/s at N = 400), checked every 256
/// steps; gives the simulated time [s], or an error after `max_time_s`.
pub fn settle(s: &mut Explicit, tol_n: f64, max_time_s: f64) -> Result<f64, String> {
    let every = 256;
    let dt = s.params().dt_s;
    loop {
        for _ in 0..every {
            s.step(dt).map_err(|e| e.to_string())?;
        }
        let r = max_residual(s);
        // At a check the velocities are those of the last half step; a settled state needs both the
        // static residual and the motion to vanish.
        let vmax = s.wire().v.iter().flat_map(|v| v.iter()).fold(0.0_f64, |m, x| m.max(x.abs()));
        if r < tol_n && vmax < 1e-8 {
            return Ok(s.time_s());
        }
        if s.time_s() > max_time_s {
            return Err(format!("not settled after {:.1} s: residual {r:.3e} N, speed {vmax:.3e} m/s", s.time_s()));
        }
    }
}

/// Node positions of a wire as `[x1, x2, x3]` per node.
pub fn positions(w: &Wire) -> Vec<[f64; 3]> {
    (0..w.nodes()).map(|i| w.position(i)).collect()
}

/// Largest distance between corresponding nodes [m].
pub fn max_distance(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(p, q)| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt())
        .fold(0.0, f64::max)
}

/// Tolerance on the largest nodal residual [N] for a converged static or implicit solve on `n`
/// segments under a line load `w` [N/m]: `1e-10 w ds` (a position error of about 1e-10 of the sag), but
/// never below 200 times the rounding floor `EA N eps` of the axial forces (positions of order `l` are
/// known to `l eps`, and the axial stiffness `EA / ds` turns that into a force of `EA N eps`).
pub fn residual_tolerance(n: usize, load_n_per_m: f64) -> f64 {
    let ds = SPAN_M / n as f64;
    (1e-10 * load_n_per_m * ds).max(200.0 * EA_N * n as f64 * f64::EPSILON)
}
