//! Suspension insulator strings and elastic crossarms: how a line section hangs between its dead-ends.
//!
//! A suspension insulator string hangs from a crossarm pivot `p` to the conductor clamp, which is a node
//! `c` of the line. It is an elastic link that carries tension only:
//!
//! ```text
//! L_s = |c - p|,   e_s = L_s / L_i - 1,   T_s = EA_i max(e_s, 0),   F_clamp = -T_s (c - p) / L_s,
//! ```
//!
//! with `L_i` the string's unstretched length [m] and `EA_i` its axial stiffness [N]. The string's mass
//! `m_i` is lumped at the clamp (added to the clamp node's mass, so its weight reaches the crossarm through
//! `T_s`). Its elastic energy is `EA_i L_i e_s^2 / 2` for `e_s > 0`. The force the string applies to the
//! crossarm is `-F_clamp`.
//!
//! Axial damping. A string may carry an axial damper `BA_i` [N s] (MoorDyn's `BA`: a damper `BA_i / L_i`
//! [N s/m] along the string), which damps the clamp's ringing on the string's axial mode after a sudden
//! unloading:
//!
//! ```text
//! edot_s = (v_c - u) . (c - p) / (L_s L_i),   T_s = max(EA_i e_s + BA_i edot_s, 0) for e_s > 0, else 0,
//! ```
//!
//! with `v_c` the clamp's velocity and `u` the pivot's (an elastic crossarm's; zero for a rigid one), both
//! the kernel's half-step velocities `v^{n-1/2}`, as for the conductor's own Kelvin-Voigt rate. The force
//! is that of the line's link element ([`crate::element::LinkLaw`], tension only), evaluated operation for
//! operation as before for `BA_i = 0` (the velocities are then not read), so an undamped string gives the
//! same bits as it always did. The damper has no static effect: the static solver's force and Jacobian
//! ([`Insulator::force_on_clamp`], [`Insulator::stiffness`]) are those of the clamp at rest.
//!
//! Time step. The clamp node of mass `m_c` (the string plus its conductor share) is held by the string
//! and its two conductor segments; by Gershgorin's bound the highest frequency of the linearised system
//! satisfies `omega^2 <= (EA_i / L_i + 2 EA / l_l + 2 EA / l_r) / m_c`, and leapfrog is stable for
//! `dt <= 2 / omega` ([`clamp_stable_step_s`]). For the strings of real lines (3 to 5 m, 50 to 150 kg,
//! `EA_i` about 5e7 N) this is far above the conductor's step `C l0 / c` (a 100 kg clamp on 4 m segments
//! of Drake: 3.1e-3 s against 8.5e-4 s at Courant 0.9), so the string never shortens the step. With a
//! damper, the damped leapfrog's bound `W dt^2 / 4 + D dt / 2 <= 1` holds, `W` that bound on `omega^2`
//! and `D = BA_i / (L_i m_c)` ([`damped_clamp_stable_step_s`]); a damper of 1e4 N s on such a string
//! shortens its step by 2 %, one of 1e6 N s (a dashpot far beyond any string's) to 7e-4 s.
//!
//! Elastic crossarm. The pivot may move horizontally on springs along and across the line (a tower's
//! flexibility, which lowers broken-wire peaks): with rest position `p0`, longitudinal unit vector `e_l`
//! (horizontal, along the line) and transverse `e_t = e3 x e_l`,
//!
//! ```text
//! M a = -k_l ((p - p0) . e_l) e_l - k_t ((p - p0) . e_t) e_t - c_d u + (T_s (c - p) / L_s)_horizontal,
//! ```
//!
//! integrated with the same leapfrog (kick with the mean of the two step lengths, then drift), the damping
//! taken at the previous half step. The crossarm is rigid vertically. Its energy is the springs'
//! `k (d . e)^2 / 2` and `M |u|^2 / 2`.
//!
//! Time step with an elastic crossarm. The pivot and the clamp are then both moving masses joined by the
//! string, and Gershgorin's bound (in the form of the clamp's above, and of the line's,
//! [`crate::scheme::line`]: per moving mass the stiffness on it plus its couplings to the other moving
//! masses, over its mass) takes the pivot's row and the string's coupling in the clamp's row:
//!
//! ```text
//! pivot:  omega^2 <= (max(k_l, k_t) + 2 EA_i / L_i) / M,       D = (c_d + 2 BA_i / L_i) / M
//! clamp:  omega^2 <= (2 EA_i / L_i + 2 EA / l_l + 2 EA / l_r) / m_c,   D = 2 BA_i / (L_i m_c)
//! ```
//!
//! ([`pivot_stable_step_s`]; the clamp's by [`damped_clamp_stable_step_s`] with the string counted twice).
//! A tower top's sway (a few hertz: `k` of 1e5 to 1e7 N/m on hundreds of kilograms) sets no limit, but
//! the ranges allow a stiff arm on a light pivot: 1e10 N/m on 500 kg rings at 4.5e3 rad/s, whose stable
//! step 4.5e-4 s is about half the conductor's 8.5e-4 s on 4 m segments of Drake at Courant 0.9. The
//! geometric stiffness `T / L` of the strings, and of the conductor, is left out as it is in the
//! conductor's Courant limit: below 1e-3 of the axial stiffness for tensions below 1e-3 of `EA`.

use crate::element::LinkLaw;

/// Horizontal springs, mass and damping of an elastic crossarm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossarm {
    /// rest position of the pivot `p0` [m]
    pub rest_m: [f64; 3],
    /// horizontal unit vector along the line `e_l` [-]
    pub longitudinal: [f64; 3],
    /// longitudinal spring `k_l` [N/m]
    pub longitudinal_n_per_m: f64,
    /// transverse spring `k_t` [N/m]
    pub transverse_n_per_m: f64,
    /// mass moving with the pivot `M` [kg]
    pub mass_kg: f64,
    /// viscous damping `c_d` [N s/m]
    pub damping_n_s_per_m: f64,
    /// pivot velocity `u` [m/s] at the last half step
    pub velocity_m_per_s: [f64; 3],
}

impl Crossarm {
    /// Transverse unit vector `e_t = e3 x e_l` [-].
    pub fn transverse(&self) -> [f64; 3] {
        let l = self.longitudinal;
        [-l[1], l[0], 0.0]
    }

    /// Spring and damping force on the pivot at position `p` [N] (no string force).
    pub fn spring_force(&self, p: [f64; 3]) -> [f64; 3] {
        let d = sub(p, self.rest_m);
        let (el, et) = (self.longitudinal, self.transverse());
        let (dl, dt) = (dot(d, el), dot(d, et));
        let u = self.velocity_m_per_s;
        std::array::from_fn(|k| {
            let f = -self.longitudinal_n_per_m * dl * el[k] - self.transverse_n_per_m * dt * et[k];
            if k == 2 { 0.0 } else { f - self.damping_n_s_per_m * u[k] }
        })
    }

    /// Elastic energy of the springs at pivot position `p` [J].
    pub fn spring_energy(&self, p: [f64; 3]) -> f64 {
        let d = sub(p, self.rest_m);
        let (dl, dt) = (dot(d, self.longitudinal), dot(d, self.transverse()));
        0.5 * (self.longitudinal_n_per_m * dl * dl + self.transverse_n_per_m * dt * dt)
    }
}

/// A suspension insulator string from a crossarm pivot to the clamp node of the line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Insulator {
    /// the clamp: a node of the line
    pub node: usize,
    /// pivot position `p` [m] (moves only with an elastic crossarm)
    pub pivot_m: [f64; 3],
    /// unstretched length `L_i` [m]
    pub length_m: f64,
    /// axial stiffness `EA_i` [N]
    pub stiffness_n: f64,
    /// axial damping `BA_i` [N s] (a damper `BA_i / L_i` [N s/m] along the string); 0: none
    pub damping_n_s: f64,
    /// mass `m_i` [kg], lumped at the clamp (included in the clamp node's mass by the wire)
    pub mass_kg: f64,
    /// false once the string has failed: it then carries nothing
    pub intact: bool,
    /// horizontal unit vector along the line at the support [-] (swing angles are measured in it)
    pub along: [f64; 3],
    /// an elastic crossarm, or `None` for a rigid one
    pub crossarm: Option<Crossarm>,
}

impl Insulator {
    /// Tension `T_s` [N] with the clamp at `clamp` [m].
    pub fn tension(&self, clamp: [f64; 3]) -> f64 {
        if !self.intact {
            return 0.0;
        }
        let len = norm(sub(clamp, self.pivot_m));
        self.stiffness_n * (len / self.length_m - 1.0).max(0.0)
    }

    /// The string's axial law: tension only, of length `L_i`, stiffness `EA_i` and damping `BA_i`.
    pub fn law(&self) -> LinkLaw {
        LinkLaw::string(self.length_m, self.stiffness_n, self.damping_n_s)
    }

    /// Velocity of the pivot [m/s]: an elastic crossarm's (horizontal), zero for a rigid one.
    pub fn pivot_velocity_m_per_s(&self) -> [f64; 3] {
        self.crossarm.map_or([0.0; 3], |a| a.velocity_m_per_s)
    }

    /// Force the string applies to the clamp at rest [N] (no damper force): the statics' force.
    pub fn force_on_clamp(&self, clamp: [f64; 3]) -> [f64; 3] {
        self.force_on_moving_clamp(clamp, [0.0; 3])
    }

    /// Force the string applies to the clamp at `clamp` [m] moving at `clamp_velocity` [m/s] [N], the
    /// damper's included (module doc). For `BA_i = 0` the velocities are not read, and the operations are
    /// those of the elastic force `-EA_i max(e_s, 0) (c - p) / L_s`; a slack or failed string exerts `+0`.
    pub fn force_on_moving_clamp(&self, clamp: [f64; 3], clamp_velocity: [f64; 3]) -> [f64; 3] {
        if !self.intact {
            return [0.0; 3];
        }
        let (u, v) = if self.damping_n_s == 0.0 {
            ([0.0; 3], [0.0; 3])
        } else {
            (self.pivot_velocity_m_per_s(), clamp_velocity)
        };
        let (t, f) = self.law().tension_and_force_on_b(self.pivot_m, clamp, u, v);
        if t == 0.0 {
            return [0.0; 3];
        }
        f
    }

    /// Elastic energy of the string [J].
    pub fn energy(&self, clamp: [f64; 3]) -> f64 {
        if !self.intact {
            return 0.0;
        }
        let e = (norm(sub(clamp, self.pivot_m)) / self.length_m - 1.0).max(0.0);
        0.5 * self.stiffness_n * self.length_m * e * e
    }

    /// Swing angles of the string from plumb [rad] at its own line direction [`Insulator::along`].
    pub fn swing(&self, clamp: [f64; 3]) -> [f64; 2] {
        self.swing_rad(clamp, self.along)
    }

    /// Displacement of the pivot from its rest position [m] (zero for a rigid crossarm).
    pub fn pivot_displacement_m(&self) -> [f64; 3] {
        self.crossarm.map_or([0.0; 3], |a| sub(self.pivot_m, a.rest_m))
    }

    /// Swing angles of the string [rad], for the line's horizontal direction `along` (unit): along the
    /// line, the angle from plumb within the line's vertical plane, `atan2(d . e_l, -d3)` (positive toward
    /// `+e_l`, beyond 90 degrees when the clamp rises above the pivot); across it, the angle out of that
    /// plane, `asin(d . e_t / |d|)` (positive toward `+e_t`). For a string in the plane the second is 0
    /// at any swing (an `atan2` over `-d3` would jump to 180 degrees there).
    pub fn swing_rad(&self, clamp: [f64; 3], along: [f64; 3]) -> [f64; 2] {
        let ([y, x], out) = self.swing_parts(clamp, along);
        [y.atan2(x), out]
    }

    /// [`Insulator::swing_rad`] with the angle along the line left as the two arguments of its `atan2`:
    /// `([d . e_l, -d3], across)` (for the peaks, which need the angle only where it could be a new peak).
    pub fn swing_parts(&self, clamp: [f64; 3], along: [f64; 3]) -> ([f64; 2], f64) {
        let d = sub(clamp, self.pivot_m);
        let across = [-along[1], along[0], 0.0];
        let len = norm(d);
        let out = if len > 0.0 { (dot(d, across) / len).clamp(-1.0, 1.0).asin() } else { 0.0 };
        ([dot(d, along), -d[2]], out)
    }

    /// Derivative of [`Insulator::force_on_clamp`] with respect to the clamp position [N/m] (row-major
    /// 3x3): `-(k t t^T + (T / L_s) (I - t t^T))` while taut, zero when slack. With `floor_n`, the slack
    /// string is linearised with its axial stiffness `EA_i / L_i` and the transverse stiffness is taken
    /// with at least that tension (the static solver's regularisation, [`crate::statics`]).
    pub fn stiffness(&self, clamp: [f64; 3], floor_n: Option<f64>) -> [f64; 9] {
        let d = sub(clamp, self.pivot_m);
        let len = norm(d);
        if !self.intact || len == 0.0 {
            return [0.0; 9];
        }
        let t = std::array::from_fn::<f64, 3, _>(|k| d[k] / len);
        let taut = len > self.length_m;
        let axial = if taut || floor_n.is_some() { self.stiffness_n / self.length_m } else { 0.0 };
        let tension = self.tension(clamp).max(floor_n.unwrap_or(0.0));
        let geometric = tension / len;
        std::array::from_fn(|m| {
            let (k, l) = (m / 3, m % 3);
            let id = if k == l { 1.0 } else { 0.0 };
            -(axial * t[k] * t[l] + geometric * (id - t[k] * t[l]))
        })
    }
}

/// Largest stable leapfrog step [s] at a clamp node of mass `clamp_mass_kg` [kg] held by a string of
/// stiffness `string_n_per_m = EA_i / L_i` [N/m] and conductor segments of stiffness `EA / l` [N/m] on
/// each side (module doc: Gershgorin's bound).
pub fn clamp_stable_step_s(clamp_mass_kg: f64, string_n_per_m: f64, left_n_per_m: f64, right_n_per_m: f64) -> f64 {
    2.0 * (clamp_mass_kg / (string_n_per_m + 2.0 * left_n_per_m + 2.0 * right_n_per_m)).sqrt()
}

/// [`clamp_stable_step_s`] with the string's damper `string_n_s_per_m = BA_i / L_i` [N s/m]: the largest
/// `dt` with `W dt^2 / 4 + D dt / 2 <= 1`, `W` the undamped bound on `omega^2` and `D = BA_i / (L_i m_c)`
/// (Gershgorin's bound on the damping rate; the conductor's own Kelvin-Voigt friction is the Courant
/// limit's, as for the undamped clamp). Without a damper it is [`clamp_stable_step_s`], to the bit.
pub fn damped_clamp_stable_step_s(
    clamp_mass_kg: f64,
    string_n_per_m: f64,
    left_n_per_m: f64,
    right_n_per_m: f64,
    string_n_s_per_m: f64,
) -> f64 {
    if string_n_s_per_m == 0.0 {
        return clamp_stable_step_s(clamp_mass_kg, string_n_per_m, left_n_per_m, right_n_per_m);
    }
    let w = (string_n_per_m + 2.0 * left_n_per_m + 2.0 * right_n_per_m) / clamp_mass_kg;
    let d = string_n_s_per_m / clamp_mass_kg;
    2.0 / (0.5 * d + (0.25 * d * d + w).sqrt())
}

/// Largest stable leapfrog step [s] at the pivot of an elastic crossarm (module doc, "Time step with an
/// elastic crossarm"): pivot mass `pivot_mass_kg` [kg], the stiffer of its two springs `arm_n_per_m`
/// [N/m], its string `string_n_per_m = EA_i / L_i` [N/m] (on the pivot and coupling it to the clamp),
/// the crossarm's damping `arm_n_s_per_m` [N s/m] and the string's damper `string_n_s_per_m = BA_i / L_i`
/// [N s/m]: the largest `dt` with `W dt^2 / 4 + D dt / 2 <= 1`.
pub fn pivot_stable_step_s(
    pivot_mass_kg: f64,
    arm_n_per_m: f64,
    string_n_per_m: f64,
    arm_n_s_per_m: f64,
    string_n_s_per_m: f64,
) -> f64 {
    let w = (arm_n_per_m + 2.0 * string_n_per_m) / pivot_mass_kg;
    let d = (arm_n_s_per_m + 2.0 * string_n_s_per_m) / pivot_mass_kg;
    2.0 / (0.5 * d + (0.25 * d * d + w).sqrt())
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn string() -> Insulator {
        Insulator {
            node: 3,
            pivot_m: [0.0, 0.0, 10.0],
            length_m: 3.5,
            stiffness_n: 5.0e7,
            damping_n_s: 0.0,
            mass_kg: 100.0,
            intact: true,
            along: [0.0, 1.0, 0.0],
            crossarm: None,
        }
    }

    #[test]
    fn tension_only_and_energy_is_its_potential() {
        let s = string();
        assert_eq!(s.tension([0.0, 0.0, 7.0]), 0.0, "shorter than its length: slack");
        // Stretched by 1 mm: T = EA * 0.001 / 3.5.
        let c = [0.0, 0.0, 10.0 - 3.501];
        assert!((s.tension(c) - 5.0e7 * 0.001 / 3.5).abs() < 1e-6);
        let f = s.force_on_clamp(c);
        assert!(f[2] > 0.0 && f[0] == 0.0, "the string pulls the clamp up toward the pivot");
        // F = -dE/dc, by central differences (step 1e-7 m; truncation O(h^2 EA/L^3) ~ 1e-8 N).
        let h = 1e-7;
        for k in 0..3 {
            let (mut a, mut b) = (c, c);
            a[k] += h;
            b[k] -= h;
            let de = (s.energy(a) - s.energy(b)) / (2.0 * h);
            assert!((f[k] + de).abs() < 1e-3, "component {k}: {} vs {}", f[k], -de);
        }
    }

    /// Through the link law, the undamped force is bit for bit the elastic formula it replaced,
    /// `-EA_i max(e_s, 0) (c - p) / L_s` (zero when slack), whatever the clamp's velocity.
    #[test]
    fn the_undamped_force_is_the_elastic_formula_to_the_bit() {
        let s = string();
        let old = |c: [f64; 3]| {
            let d = sub(c, s.pivot_m);
            let len = norm(d);
            let t = s.stiffness_n * (len / s.length_m - 1.0).max(0.0);
            if t == 0.0 || len == 0.0 { [0.0; 3] } else { std::array::from_fn(|k| -t * d[k] / len) }
        };
        for k in 0..2000 {
            let a = k as f64 * 0.37;
            let r = 3.49 + 0.02 * (a * 1.3).sin().abs();
            let c = [r * 0.2 * a.sin(), r * 0.3 * a.cos(), 10.0 - r * (1.0 - 0.13 * a.sin().powi(2)).sqrt()];
            let v = [a.sin(), -a.cos(), 0.5 * a.sin()];
            let (f, g) = (s.force_on_clamp(c), s.force_on_moving_clamp(c, v));
            let o = old(c);
            for i in 0..3 {
                assert_eq!(f[i].to_bits(), o[i].to_bits(), "at {c:?}");
                assert_eq!(g[i].to_bits(), o[i].to_bits(), "at {c:?} moving");
            }
        }
    }

    /// A damper `BA` adds `(BA / L_i)` times the opening speed along the string, nothing for a motion
    /// across it, never a push; the crossarm's velocity counts as the pivot's.
    #[test]
    fn the_damper_acts_on_the_opening_speed_and_never_pushes() {
        let s = Insulator { damping_n_s: 2.0e4, ..string() };
        let c = [0.0, 0.0, 10.0 - 3.501];
        let still = s.force_on_moving_clamp(c, [0.0; 3]);
        assert_eq!(still, string().force_on_clamp(c));
        let opening = s.force_on_moving_clamp(c, [0.0, 0.0, -0.1]);
        let expected = 2.0e4 / 3.5 * 0.1;
        assert!((opening[2] - still[2] - expected).abs() < 1e-9 * expected, "{opening:?}");
        let across = s.force_on_moving_clamp(c, [0.1, 0.0, 0.0]);
        assert!((across[2] - still[2]).abs() < 1e-9 * still[2]);
        // Closing fast: the damper would push; a string does not.
        assert_eq!(s.force_on_moving_clamp(c, [0.0, 0.0, 10.0]), [0.0; 3]);
        // A pivot moving with its crossarm as fast as the clamp: no damper force.
        let arm = Crossarm {
            rest_m: s.pivot_m,
            longitudinal: [0.0, 1.0, 0.0],
            longitudinal_n_per_m: 1e5,
            transverse_n_per_m: 1e5,
            mass_kg: 500.0,
            damping_n_s_per_m: 0.0,
            velocity_m_per_s: [0.0, 0.0, -0.1],
        };
        let moving = Insulator { crossarm: Some(arm), ..s }.force_on_moving_clamp(c, [0.0, 0.0, -0.1]);
        assert!((moving[2] - still[2]).abs() < 1e-9 * still[2]);
    }

    #[test]
    fn stiffness_is_the_derivative_of_the_force() {
        let s = string();
        let c = [0.3, -0.2, 10.0 - 3.52];
        let j = s.stiffness(c, None);
        let h = 1e-6;
        for l in 0..3 {
            let (mut a, mut b) = (c, c);
            a[l] += h;
            b[l] -= h;
            let (fa, fb) = (s.force_on_clamp(a), s.force_on_clamp(b));
            for k in 0..3 {
                let fd = (fa[k] - fb[k]) / (2.0 * h);
                // Central difference: truncation O(h^2 T / L^3) < 1e-6 N/m, rounding eps |F| / h ~ 1e-4 N/m,
                // against entries up to EA / L = 1.4e7 N/m.
                assert!((j[3 * k + l] - fd).abs() < 1e-2, "({k},{l}): {} vs {fd}", j[3 * k + l]);
            }
        }
    }

    #[test]
    fn swing_angles_and_step_limit() {
        let s = string();
        let c = [0.0, 3.5 * 0.1f64.sin(), 10.0 - 3.5 * 0.1f64.cos()];
        let [along, across] = s.swing_rad(c, [0.0, 1.0, 0.0]);
        assert!((along - 0.1).abs() < 1e-12 && across.abs() < 1e-12);
        // Swung beyond horizontal in the line's plane: along > 90 degrees, across still 0.
        let up = [0.0, 3.5 * 2.0f64.sin(), 10.0 - 3.5 * 2.0f64.cos()];
        let [along, across] = s.swing_rad(up, [0.0, 1.0, 0.0]);
        assert!((along - 2.0).abs() < 1e-12 && across == 0.0, "{along} {across}");
        // Out of the plane toward e_t = e3 x e2 = -e1: x1 = -L sin(0.2) gives +0.2 across.
        let side = [-3.5 * 0.2f64.sin(), 0.0, 10.0 - 3.5 * 0.2f64.cos()];
        let [_, across] = s.swing_rad(side, [0.0, 1.0, 0.0]);
        assert!((across - 0.2).abs() < 1e-12, "{across}");
        // Drake on 4 m segments (EA = 2.9e7 N) with a 100 kg string: well above the conductor's 8.5e-4 s.
        let dt = clamp_stable_step_s(100.0 + 6.5, 5.0e7 / 3.5, 2.9e7 / 4.0, 2.9e7 / 4.0);
        assert!(dt > 3.0e-3 && dt < 3.2e-3, "{dt}");
        // Undamped, the damped bound is the undamped one to the bit; damped, it satisfies
        // W dt^2 / 4 + D dt / 2 = 1 (module doc's numbers: 2 % shorter at 1e4 N s, 7e-4 s at 1e6 N s).
        assert_eq!(damped_clamp_stable_step_s(106.5, 5.0e7 / 3.5, 7.25e6, 7.25e6, 0.0).to_bits(), dt.to_bits());
        let w = (5.0e7 / 3.5 + 4.0 * 7.25e6) / 106.5;
        for (ba, lo, hi) in [(1.0e4, 0.975, 0.985), (1.0e6, 0.2, 0.23)] {
            let c = ba / 3.5;
            let dd = damped_clamp_stable_step_s(106.5, 5.0e7 / 3.5, 7.25e6, 7.25e6, c);
            assert!((w * dd * dd / 4.0 + c / 106.5 * dd / 2.0 - 1.0).abs() < 1e-12, "{dd}");
            assert!(dd / dt > lo && dd / dt < hi, "{ba}: {dd} vs {dt}");
        }
    }

    /// The pivot's bound is, for a pivot without a string, the exact stability limit of the damped
    /// leapfrog of one mass on a spring and damper (the scheme's kick with the damping at the previous
    /// half step: `x^{n+1} - 2 x^n + x^{n-1} = -w dt^2 x^n - D dt (x^n - x^{n-1})`). Iterated for 1e5
    /// steps: at 0.999 of it the largest `|x|` of the last 1000 steps stays at most that of the first 1000
    /// (neutral or damped; rounding allowed for at 1e-9), at 1.001 of it it has grown by more than 1e3.
    #[test]
    fn the_pivots_bound_is_the_damped_leapfrogs_limit() {
        for (k, m, c) in [(1.0e10, 500.0, 0.0), (1.0e8, 20.0, 0.0), (1.0e9, 500.0, 2.0e5), (4.0e6, 300.0, 1.0e4)] {
            let limit = pivot_stable_step_s(m, k, 0.0, c, 0.0);
            if c == 0.0 {
                assert!((limit - 2.0 * (m / k).sqrt()).abs() <= 1e-15 * limit, "{limit}");
            }
            let growth = |dt: f64| {
                let (n, window) = (100_000, 1000);
                let (mut x, mut v) = (1.0e-3, 0.0);
                let (mut first, mut last) = (0.0_f64, 0.0_f64);
                for step in 0..n {
                    v += dt * (-k * x - c * v) / m;
                    x += dt * v;
                    if x.abs() > 1e100 {
                        return f64::INFINITY;
                    }
                    if step < window {
                        first = first.max(x.abs());
                    } else if step >= n - window {
                        last = last.max(x.abs());
                    }
                }
                last / first
            };
            let (below, above) = (growth(0.999 * limit), growth(1.001 * limit));
            println!("k = {k:e} N/m, M = {m} kg, c = {c:e} N s/m: growth {below:.6} at 0.999, {above:.3e} at 1.001");
            assert!(below <= 1.0 + 1e-9, "k = {k}, m = {m}, c = {c}: {below}");
            assert!(above > 1e3, "k = {k}, m = {m}, c = {c}: {above}");
        }
    }
}
