//! IEC 60865-1:2011, clause 6 (flexible conductors), the simplified method for one span: from the span,
//! the conductor, the static tension `F_st` and the short circuit to the swing-out, the tensile forces,
//! the displacement and the clearance.
//!
//! ```text
//! F'   = mu0/(2 pi) 0.75 I''k3^2 / a  l_c / l                                       (19a)
//! r    = F' / (n m'_s g_n),   delta_1 = arctan r                                   (20), (21)
//! b_c  = n m'_s g_n l^2 / (8 F_st),   T = 2 pi sqrt(0.8 b_c / g_n)                  (22), (23)
//! T_res = T / ((1 + r^2)^(1/4) (1 - pi^2/64 (delta_1/90 deg)^2))                    (24)
//! N    = 1/(S l) + 1/(n E_eff A_s),   zeta = (n g_n m'_s l)^2 / (24 F_st^3 N)       (25)-(28)
//! delta_k (29), delta_m (30, 31), phi (32), psi (Annex A cubic), F_t = F_st (1 + phi psi) (33)
//! eps_ela, eps_th, C_D, C_F, b_D = C_F C_D b_c                                      (34)-(38)
//! F_f = 1.2 F_st sqrt(1 + 8 zeta delta_m / 180 deg)  if r > 0.6 and delta_m >= 70 deg  (43)
//! b_h (44) slack / (45) strained,   a_min = a - 2 b_h                               (48)
//! F_pi = 1.1 F_t  if the sub-conductors clash effectively                          (51)-(53)
//! F_pi otherwise by nu_1..nu_4, eps_st, eps_pi, j, xi / eta (clause 6.4.2)           (54)-(64)
//! ```
//!
//! The standard evaluates a span twice, with `F_st` at the lowest local winter temperature (-20 C) and at
//! the maximum operating temperature; [`evaluate`] does one state, so call it once per `F_st`.
//! Sources, equation numbers and the worked examples: docs/short_circuit_iec60865.md.

pub mod bundle;
pub mod equations;
pub mod error;
pub mod input;
pub mod psi;

pub use bundle::{Contraction, Pinch, PinchData};
pub use equations::{G_N, MU_0, SIGMA_FIN_PA};
pub use error::Iec60865Error;
pub use input::{Bundle, Fault, Input, MAX_SAG_RATIO, MAX_SPAN_M, Mounting};

use equations as eq;

/// Every quantity of the method for one state, named as IEC 60865-1:2011 names it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Output {
    /// `l_c`, conductor length in the span [m]
    pub l_c_m: f64,
    /// `m'_s` with the concentrated masses spread over the span [kg/m]
    pub m_s_kg_per_m: f64,
    /// `F'`, characteristic electromagnetic force per unit length, eq. (19a) [N/m]
    pub f_prime_n_per_m: f64,
    /// `r`, electromagnetic force over weight, eq. (20) [-]
    pub r: f64,
    /// `delta_1`, direction of the resultant force, eq. (21) [deg]
    pub delta_1_deg: f64,
    /// `b_c`, equivalent static sag at midspan, eq. (22) [m]
    pub b_c_m: f64,
    /// `T`, period of the span oscillation, eq. (23) [s]
    pub t_s: f64,
    /// `T_res`, resultant period during the short circuit, eq. (24) [s]
    pub t_res_s: f64,
    /// `E_eff`, actual Young's modulus, eq. (26) [Pa]
    pub e_eff_pa: f64,
    /// `N`, stiffness norm, eq. (25) [1/N]
    pub n_stiffness_per_n: f64,
    /// `zeta`, stress factor, eq. (28) [-]
    pub zeta: f64,
    /// `delta_k` (`delta_end`), swing-out angle at the end of the short circuit, eq. (29) [deg]
    pub delta_k_deg: f64,
    /// `chi`, eq. (31) [-]
    pub chi: f64,
    /// `delta_m`, maximum swing-out angle, eq. (30) [deg]
    pub delta_m_deg: f64,
    /// `phi`, load parameter, eq. (32) [-]
    pub phi: f64,
    /// `psi`, the factor of eq. (33) from the Annex A cubic [-]
    pub psi: f64,
    /// `F_t`, short-circuit tensile force, eq. (33) [N]
    pub f_t_n: f64,
    /// `eps_ela`, elastic expansion, eq. (34) [-]
    pub eps_ela: f64,
    /// `eps_th`, thermal expansion, eq. (35) [-]
    pub eps_th: f64,
    /// `C_D`, dilatation factor, eq. (36) [-]
    pub c_d: f64,
    /// `C_F`, form factor, eq. (37) [-]
    pub c_f: f64,
    /// `b_D`, dynamic sag at midspan, eq. (38) [m]
    pub b_d_m: f64,
    /// `F_f`, fall-of-span tensile force, eq. (43) [N]; `None` where clause 6.2.6 does not ask for it
    /// (`r <= 0.6` or `delta_m < 70 deg`)
    pub f_f_n: Option<f64>,
    /// `b_h`, maximum horizontal span displacement, eq. (44) or (45) [m]
    pub b_h_m: f64,
    /// `a_min`, minimum air clearance, eq. (48) [m]
    pub a_min_m: f64,
    /// `F_pi`, bundle pinch force (eq. (51)-(64)); `None` for a single conductor
    pub pinch: Option<Pinch>,
}

/// The simplified method for one static state (one `F_st`). Validates the input first.
pub fn evaluate(input: &Input) -> Result<Output, Iec60865Error> {
    input.validate()?;
    let n = f64::from(input.subconductors);
    let g = input.gravity_m_per_s2;
    let l = input.span_m;
    let f_st = input.static_tension_n;
    let current = input.fault.current_a();
    let l_c = input.conductor_length_m();
    let m_s = input.effective_mass_per_length_kg_per_m();
    let three_phase = matches!(input.fault, Fault::ThreePhase { .. });

    let f_prime = eq::characteristic_force(three_phase, current, input.phase_distance_m, l_c, l);
    let r = eq::force_ratio(f_prime, n, m_s, g);
    let delta_1 = eq::resultant_direction_deg(r);
    let b_c = eq::static_sag(n, m_s, g, l, f_st);
    if b_c / l > MAX_SAG_RATIO {
        return Err(Iec60865Error::OutsideMethod {
            quantity: "b_c / l (static sag over span)",
            value: b_c / l,
            limit: "<= 0.08 (clause 6.2.1)",
        });
    }
    let t = eq::period(b_c, g);
    let t_res = eq::resultant_period(t, r, delta_1);
    let e_eff = eq::effective_modulus(input.young_modulus_pa, f_st, n, input.area_m2);
    let stiffness = eq::stiffness_norm(input.spring_constant_n_per_m, l, n, e_eff, input.area_m2);
    let zeta = eq::stress_factor(n, g, m_s, l, f_st, stiffness);
    let t_k1 = input.first_duration_s;
    let delta_k = eq::swing_out_end_deg(delta_1, t_k1, t_res);
    let chi = eq::chi(r, delta_k);
    let delta_m = eq::max_swing_out_deg(chi);
    let phi = eq::load_parameter(r, t_k1, t_res, delta_k);
    let psi = psi::psi(phi, zeta).ok_or(Iec60865Error::Psi { phi, zeta })?;
    let f_t = eq::tensile_force(f_st, phi, psi);
    let eps_ela = eq::elastic_expansion(stiffness, f_t, f_st);
    let eps_th = eq::thermal_expansion(input.thermal_constant_m4_per_a2s, current, n, input.area_m2, t_k1, t_res);
    let c_d = eq::dilatation_factor(l, b_c, eps_ela, eps_th);
    let c_f = eq::form_factor(r);
    let b_d = eq::dynamic_sag(c_d, c_f, b_c);
    let f_f = eq::fall_force_relevant(r, delta_m).then(|| eq::fall_force(f_st, zeta, delta_m));
    let strained = matches!(input.mounting, Mounting::Strained { .. });
    let b_h = eq::horizontal_displacement(strained, b_d, delta_m, delta_1);
    let a_min = eq::minimum_clearance(input.phase_distance_m, b_h);
    let pinch = match input.bundle {
        Some(b) if input.subconductors >= 2 => {
            let data = bundle::PinchData {
                n,
                a_s: b.subconductor_distance_m,
                d: input.diameter_m,
                l_s: b.spacer_distance_m,
                m_s,
                current_a: current,
                frequency_hz: b.frequency_hz,
                kappa: b.peak_factor,
                f_st,
                stiffness,
            };
            Some(bundle::pinch(&data, f_t).ok_or(Iec60865Error::Pinch)?)
        }
        _ => None,
    };
    Ok(Output {
        l_c_m: l_c,
        m_s_kg_per_m: m_s,
        f_prime_n_per_m: f_prime,
        r,
        delta_1_deg: delta_1,
        b_c_m: b_c,
        t_s: t,
        t_res_s: t_res,
        e_eff_pa: e_eff,
        n_stiffness_per_n: stiffness,
        zeta,
        delta_k_deg: delta_k,
        chi,
        delta_m_deg: delta_m,
        phi,
        psi,
        f_t_n: f_t,
        eps_ela,
        eps_th,
        c_d,
        c_f,
        b_d_m: b_d,
        f_f_n: f_f,
        b_h_m: b_h,
        a_min_m: a_min,
        pinch,
    })
}
