//! The equations of IEC 60865-1:2011, clause 6.2 (tensile forces and displacement of a span of flexible
//! conductors), one function each. Equation numbers are those of IEC 60865-1:2011 = EN 60865-1:2012 as a
//! public implementation states them (Kalandoros/Kurzschlussfestigkeit, `kurzschlusskraefte_leiterseile_
//! berechnungen.py`, which cites "SN EN 60865-1:2012"); the formulas agree with the 1993 edition as
//! W. Meyer, G. Herold, E. Zeitler, "Short-circuit currents - calculation of effects: the second edition
//! of IEC publication 865", 6th Int. Symp. Short-Circuit Currents in Power Systems, Liege 1994, derives
//! them. docs/short_circuit_iec60865.md has the table.
//!
//! Units: SI (N, m, kg, s, A, Pa) throughout; angles in degrees, as the standard writes its case limits
//! (`delta_m = 10 deg + arccos chi`, `T_k1/T_res <= 0.5` with `360 deg T_k1/T_res`).

use std::f64::consts::PI;

/// Magnetic constant `mu_0 = 4 pi 10^-7` [H/m], the value IEC 60865-1 uses (clause 3 list of symbols).
pub const MU_0: f64 = 4.0 * PI * 1e-7;

/// `sigma_fin = 50 N/mm^2` [Pa]: the lowest stress above which the modulus of elasticity is constant,
/// eq. (27).
pub const SIGMA_FIN_PA: f64 = 50e6;

/// Conventional value of gravity `g_n = 9.81 m/s^2` used by IEC 60865-1 and its worked examples (IEC TR
/// 60865-2).
pub const G_N: f64 = 9.81;

fn sin_deg(x: f64) -> f64 {
    x.to_radians().sin()
}

fn cos_deg(x: f64) -> f64 {
    x.to_radians().cos()
}

/// Eq. (19a) and its two-phase form: characteristic electromagnetic force per unit length [N/m] on the
/// main conductor, `F' = mu0/(2 pi) * 0.75 * I''k3^2 / a * l_c / l` (three-phase, centre phase of a flat
/// arrangement) or `F' = mu0/(2 pi) * I''k2^2 / a * l_c / l` (line-to-line). `current_a` [A] r.m.s.,
/// `a` phase distance [m], `l_c` conductor length in the span [m], `l` span (support distance) [m].
pub fn characteristic_force(three_phase: bool, current_a: f64, a: f64, l_c: f64, l: f64) -> f64 {
    let factor = if three_phase { 0.75 } else { 1.0 };
    MU_0 / (2.0 * PI) * factor * current_a * current_a / a * l_c / l
}

/// Eq. (20): ratio of electromagnetic force to weight `r = F' / (n m'_s g_n)` [-].
pub fn force_ratio(f_prime: f64, n: f64, m_s: f64, g: f64) -> f64 {
    f_prime / (n * m_s * g)
}

/// Eq. (21): direction of the resultant force `delta_1 = arctan r` [deg].
pub fn resultant_direction_deg(r: f64) -> f64 {
    r.atan().to_degrees()
}

/// Eq. (22): equivalent static conductor sag at midspan `b_c = n m'_s g_n l^2 / (8 F_st)` [m].
pub fn static_sag(n: f64, m_s: f64, g: f64, l: f64, f_st: f64) -> f64 {
    n * m_s * g * l * l / (8.0 * f_st)
}

/// Eq. (23): period of the span oscillation `T = 2 pi sqrt(0.8 b_c / g_n)` [s].
pub fn period(b_c: f64, g: f64) -> f64 {
    2.0 * PI * (0.8 * b_c / g).sqrt()
}

/// Eq. (24): resultant period during the short-circuit current flow
/// `T_res = T / ( (1 + r^2)^(1/4) * (1 - pi^2/64 * (delta_1 / 90 deg)^2) )` [s].
pub fn resultant_period(t: f64, r: f64, delta_1_deg: f64) -> f64 {
    let q = delta_1_deg / 90.0;
    t / ((1.0 + r * r).powf(0.25) * (1.0 - PI * PI / 64.0 * q * q))
}

/// Eq. (26) with (27): actual Young's modulus [Pa],
/// `E_eff = E [0.3 + 0.7 sin(F_st / (n A_s sigma_fin) * 90 deg)]` for `F_st / (n A_s) <= sigma_fin`,
/// `E_eff = E` above.
pub fn effective_modulus(e: f64, f_st: f64, n: f64, a_s: f64) -> f64 {
    let stress = f_st / (n * a_s);
    if stress <= SIGMA_FIN_PA { e * (0.3 + 0.7 * sin_deg(stress / SIGMA_FIN_PA * 90.0)) } else { e }
}

/// Eq. (25): stiffness norm `N = 1/(S l) + 1/(n E_eff A_s)` [1/N]; `s` the resultant spring constant of
/// both supports of the span [N/m].
pub fn stiffness_norm(s: f64, l: f64, n: f64, e_eff: f64, a_s: f64) -> f64 {
    1.0 / (s * l) + 1.0 / (n * e_eff * a_s)
}

/// Eq. (28): stress factor `zeta = (n g_n m'_s l)^2 / (24 F_st^3 N)` [-].
pub fn stress_factor(n: f64, g: f64, m_s: f64, l: f64, f_st: f64, stiffness: f64) -> f64 {
    let w = n * g * m_s * l;
    w * w / (24.0 * f_st.powi(3) * stiffness)
}

/// Eq. (29): swing-out angle at the end of the short-circuit current flow [deg],
/// `delta_k = delta_1 [1 - cos(360 deg T_k1 / T_res)]` for `0 <= T_k1/T_res <= 0.5`, `2 delta_1` above.
pub fn swing_out_end_deg(delta_1_deg: f64, t_k1: f64, t_res: f64) -> f64 {
    let ratio = t_k1 / t_res;
    if ratio <= 0.5 { delta_1_deg * (1.0 - cos_deg(360.0 * ratio)) } else { 2.0 * delta_1_deg }
}

/// Eq. (31): `chi = 1 - r sin delta_k` for `0 <= delta_k <= 90 deg`, `chi = 1 - r` for `delta_k > 90 deg`.
pub fn chi(r: f64, delta_k_deg: f64) -> f64 {
    if delta_k_deg <= 90.0 { 1.0 - r * sin_deg(delta_k_deg) } else { 1.0 - r }
}

/// Eq. (30): maximum swing-out angle [deg]: `1.25 arccos chi` for `0.766 <= chi <= 1`,
/// `10 deg + arccos chi` for `-0.985 <= chi < 0.766`, `180 deg` for `chi < -0.985`.
pub fn max_swing_out_deg(chi: f64) -> f64 {
    if chi >= 0.766 {
        1.25 * chi.min(1.0).acos().to_degrees()
    } else if chi >= -0.985 {
        10.0 + chi.acos().to_degrees()
    } else {
        180.0
    }
}

/// Eq. (32): load parameter `phi = 3 (sqrt(1 + r^2) - 1)` for `T_k1 >= T_res/4`,
/// `phi = 3 (r sin delta_k + cos delta_k - 1)` for `T_k1 < T_res/4` [-].
pub fn load_parameter(r: f64, t_k1: f64, t_res: f64, delta_k_deg: f64) -> f64 {
    if t_k1 >= t_res / 4.0 {
        3.0 * ((1.0 + r * r).sqrt() - 1.0)
    } else {
        3.0 * (r * sin_deg(delta_k_deg) + cos_deg(delta_k_deg) - 1.0)
    }
}

/// Eq. (33): short-circuit tensile force during the swing-out `F_t = F_st (1 + phi psi)` [N].
pub fn tensile_force(f_st: f64, phi: f64, psi: f64) -> f64 {
    f_st * (1.0 + phi * psi)
}

/// Eq. (34): elastic expansion `eps_ela = N (F_t - F_st)` [-].
pub fn elastic_expansion(stiffness: f64, f_t: f64, f_st: f64) -> f64 {
    stiffness * (f_t - f_st)
}

/// Eq. (35): thermal expansion [-], `eps_th = c_th (I/(n A_s))^2 T_res/4` for `T_k1 >= T_res/4`,
/// `c_th (I/(n A_s))^2 T_k1` otherwise; `c_th` [m^4/(A^2 s)], `current_a` = `I''k3` or `I''k2` [A].
pub fn thermal_expansion(c_th: f64, current_a: f64, n: f64, a_s: f64, t_k1: f64, t_res: f64) -> f64 {
    let j = current_a / (n * a_s);
    let t = if t_k1 >= t_res / 4.0 { t_res / 4.0 } else { t_k1 };
    c_th * j * j * t
}

/// Eq. (36): dilatation factor `C_D = sqrt(1 + 3/8 (l / b_c)^2 (eps_ela + eps_th))` [-].
pub fn dilatation_factor(l: f64, b_c: f64, eps_ela: f64, eps_th: f64) -> f64 {
    let q = l / b_c;
    (1.0 + 3.0 / 8.0 * q * q * (eps_ela + eps_th)).sqrt()
}

/// Eq. (37): form factor `C_F = 1.05` for `r <= 0.8`, `0.97 + 0.1 r` for `0.8 < r < 1.8`, `1.15` for
/// `r >= 1.8` [-].
pub fn form_factor(r: f64) -> f64 {
    if r <= 0.8 {
        1.05
    } else if r < 1.8 {
        0.97 + 0.1 * r
    } else {
        1.15
    }
}

/// Eq. (38): dynamic conductor sag at midspan `b_D = C_F C_D b_c` [m].
pub fn dynamic_sag(c_d: f64, c_f: f64, b_c: f64) -> f64 {
    c_d * c_f * b_c
}

/// Eq. (43): fall-of-span tensile force `F_f = 1.2 F_st sqrt(1 + 8 zeta delta_m / 180 deg)` [N]; the
/// standard asks for it only when `r > 0.6` and `delta_m >= 70 deg` ([`fall_force_relevant`]).
pub fn fall_force(f_st: f64, zeta: f64, delta_m_deg: f64) -> f64 {
    1.2 * f_st * (1.0 + 8.0 * zeta * delta_m_deg / 180.0).sqrt()
}

/// The condition under which clause 6.2.6 asks for the fall-of-span force: `r > 0.6` and
/// `delta_m >= 70 deg` (spans without a mid-span dropper).
pub fn fall_force_relevant(r: f64, delta_m_deg: f64) -> bool {
    r > 0.6 && delta_m_deg >= 70.0
}

/// Eq. (44) (slack conductors, `l_c = l`): `b_h = b_D` for `delta_m >= 90 deg`, `b_D sin delta_m` below;
/// eq. (45) (strained conductors, `l_c = l - 2 l_i`): `b_h = b_D sin delta_1` for `delta_m >= delta_1`,
/// `b_D sin delta_m` below [m].
pub fn horizontal_displacement(strained: bool, b_d: f64, delta_m_deg: f64, delta_1_deg: f64) -> f64 {
    if strained {
        if delta_m_deg >= delta_1_deg { b_d * sin_deg(delta_1_deg) } else { b_d * sin_deg(delta_m_deg) }
    } else if delta_m_deg >= 90.0 {
        b_d
    } else {
        b_d * sin_deg(delta_m_deg)
    }
}

/// Eq. (48): minimum air clearance between two main conductors swinging towards each other,
/// `a_min = a - 2 b_h` [m].
pub fn minimum_clearance(a: f64, b_h: f64) -> f64 {
    a - 2.0 * b_h
}
