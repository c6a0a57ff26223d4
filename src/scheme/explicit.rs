//! The explicit staggered-grid scheme (3.1), (3.6) in SI units and vector form.
//!
//! With node positions `r_i^n`, velocities `v_i^{n-1/2}` and segment tension `T_{i+1/2}^n` from the
//! Kelvin-Voigt law (3.4),
//!
//! ```text
//! F_i^n       = T_{i+1/2} t_{i+1/2} - T_{i-1/2} t_{i-1/2} + (P_{i+1/2} + P_{i-1/2}) / 2      [N]
//! v_i^{n+1/2} = v_i^{n-1/2} + (dt_{n-1/2} + dt_{n+1/2}) / 2 (F_i^n / m_i - g e3 - zeta v_i^{n-1/2})
//! vbar        = smoothing (3.3) of v^{n+1/2}
//! r_i^{n+1}   = r_i^n + dt_{n+1/2} vbar_i                                             (3.6)
//! ```
//!
//! where `t_{i+1/2} = (r_{i+1} - r_i) / |r_{i+1} - r_i|` is the unit tangent (the paper's
//! `(x_{k,i+1} - x_{k,i}) / (ds lambda)`), `P_{i+1/2}` the total distributed load on the segment (wind
//! (2.5)-(2.6) evaluated with the velocities of the previous half step, plus any uniform load), `m_i`
//! the lumped node mass and `zeta` [1/s] an optional mass-proportional damping (not in the paper; a
//! dynamic-relaxation aid). The strain rate in (3.4) is `(v_{i+1} - v_i) . t / l0` at `n - 1/2`.
//!
//! The kick uses the mean of the previous and the next step, so steps may vary (to land exactly on an
//! event or snapshot time) without losing second order, and the very first kick (`dt_{-1/2} = 0`) is the
//! half step `v^{1/2} = v^0 + dt/2 a^0` (docs/paper_notes.md, "Starting the leapfrog"). This is kick-drift-kick
//! velocity Verlet with the two half kicks fused.
//!
//! Cost per node and step: one square root, one division, about 60 flops; no allocation, no dynamic
//! dispatch (the tension law and the wind law are type parameters chosen once per step outside the loop).

use super::contact::{self, Ground};
use super::smoothing;
use crate::conductor::History;
use crate::element::aero::{Downwind, NoWind, SegmentLoad};
use crate::element::segment;
use crate::element::tension::{LawKind, Linear, TensionLaw, TensionOnly, from_order_key, order_key};
use crate::staggered_alloc;
use crate::wire::Wire;
use crate::wire::insulator::Insulator;
use crate::wire::material::segment_tension;

pub use crate::element::aero::WindLoad;

/// External loads.
#[derive(Clone, Copy, Debug)]
pub struct Loads {
    /// gravitational acceleration `g` [m/s^2], acting along `-x3`
    pub gravity_m_per_s2: f64,
    /// uniform force per unit stress-free length `q` [N/m], fixed direction (0 for none)
    pub uniform_load_n_per_m: [f64; 3],
    /// wind, if any
    pub wind: Option<WindLoad>,
    /// multiplier on the wind load [-] (1 = on, 0 = off; gusts vary it)
    pub wind_scale: f64,
    /// where the wind acts
    pub wind_gate: WindGate,
}

impl Loads {
    /// The weight alone: gravity `g` [m/s^2] along `-x3` (0 for none), no uniform load, no wind.
    pub fn gravity_only(gravity_m_per_s2: f64) -> Self {
        Loads {
            gravity_m_per_s2,
            uniform_load_n_per_m: [0.0; 3],
            wind: None,
            wind_scale: 1.0,
            wind_gate: WindGate::Always,
        }
    }
}

/// Where the wind acts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WindGate {
    /// on every segment (default)
    #[default]
    Always,
    /// only on segments moving downwind (the "dancing wires" gust of section 4.5)
    Downwind,
}

/// Numerical parameters of the step.
#[derive(Clone, Copy, Debug)]
pub struct StepParams {
    /// nominal time step `dt` [s] from (3.7)
    pub dt_s: f64,
    /// smoothing coefficient `b = beta / ds^2` per nominal step [-], eq. (3.3); scaled by `dt / dt_nominal`
    /// on a shortened step so that it acts as a fixed viscosity per unit time
    pub smoothing: f64,
    /// mass-proportional damping `zeta` [1/s] (not in the paper)
    pub mass_damping_per_s: f64,
    /// bound on node speed [m/s]; a faster node stops the run as unstable
    pub max_speed_m_per_s: f64,
}

/// Why a run was stopped as unstable.
#[derive(Clone, Debug, PartialEq)]
pub enum InstabilityReason {
    /// A velocity or position became NaN or infinite.
    NonFinite,
    /// A node moved faster than the stated bound [m/s].
    SpeedLimit {
        /// node speed reached [m/s]
        speed_m_per_s: f64,
        /// the bound [m/s]
        bound_m_per_s: f64,
    },
}

/// A numerical failure with its context.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("unstable at t = {time_s:.6} s (step {step}), node {node}: {}", describe(.reason))]
pub struct Instability {
    /// simulated time at which it was detected [s]
    pub time_s: f64,
    /// step number
    pub step: u64,
    /// node index `i` (0 at the left support)
    pub node: usize,
    /// what went wrong
    pub reason: InstabilityReason,
}

/// The instruction set of the kernel's compiled copies (see `isa_dispatch!`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Isa {
    /// the target's baseline (x86-64: SSE2, 2 doubles per vector)
    Baseline,
    /// AVX2 (4 doubles per vector)
    Avx2,
    /// AVX-512 F, DQ and VL (8 doubles per vector, mask registers, 64-bit integer maxima)
    Avx512,
}

/// AVX-512's features that the AVX-512 copies are compiled with: F (the 512-bit vectors), DQ (64-bit
/// integer and double conversions) and VL (the same instructions on 128- and 256-bit vectors).
#[cfg(target_arch = "x86_64")]
fn has_avx512() -> bool {
    std::is_x86_feature_detected!("avx512f")
        && std::is_x86_feature_detected!("avx512dq")
        && std::is_x86_feature_detected!("avx512vl")
}

/// The widest copy of the passes that may run here: AVX-512 where the processor reports F, DQ and VL and
/// the environment variable `OHL_NO_AVX512` is not set, else AVX2 where the processor reports it and
/// `OHL_NO_AVX2` is not set (which also rules out AVX-512), else the baseline: the variables select a
/// narrower copy, to measure or compare it.
fn detected_isa() -> Isa {
    #[cfg(target_arch = "x86_64")]
    {
        if !std::is_x86_feature_detected!("avx2") || std::env::var_os("OHL_NO_AVX2").is_some() {
            Isa::Baseline
        } else if has_avx512() && std::env::var_os("OHL_NO_AVX512").is_none() {
            Isa::Avx512
        } else {
            Isa::Avx2
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        Isa::Baseline
    }
}

/// Whether code compiled for AVX2 may run here (the AVX2 or AVX-512 copy is chosen, [`detected_isa`]): the
/// processor reports AVX2 and the environment variable `OHL_NO_AVX2` is not set (to measure or compare
/// the baseline copy). Used by the elements' own AVX2 copies (pair forces, contact walk, the least
/// clearance above the ground). Read once: the ground's clearance asks at every time level, and the
/// environment's lookup is a few hundred instructions.
pub(crate) fn avx2_available() -> bool {
    static AVX2: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *AVX2.get_or_init(|| detected_isa() >= Isa::Avx2)
}

/// The instruction set the kernel's passes run with on this machine: `"avx512"` (the AVX-512 copies),
/// `"avx2"` (the AVX2 copies) or `"baseline"` (x86-64 SSE2, or the target's baseline elsewhere); the
/// environment variables `OHL_NO_AVX512` and `OHL_NO_AVX2` select a narrower copy.
pub fn kernel_instruction_set() -> &'static str {
    match detected_isa() {
        Isa::Avx512 => "avx512",
        Isa::Avx2 => "avx2",
        Isa::Baseline => "baseline",
    }
}

fn describe(r: &InstabilityReason) -> String {
    match r {
        InstabilityReason::NonFinite => "velocity or position is not finite (NaN or infinity)".into(),
        InstabilityReason::SpeedLimit { speed_m_per_s, bound_m_per_s } => {
            format!("speed {speed_m_per_s:.4e} m/s exceeds the bound {bound_m_per_s:.4e} m/s")
        }
    }
}

/// Energies and extreme values at a synchronised time level `n`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// kinetic energy `sum m |v^n|^2 / 2` [J], with `v^n = v^{n-1/2} + dt/2 a^n`
    pub kinetic_j: f64,
    /// elastic energy `sum l0 W(e)` [J]
    pub elastic_j: f64,
    /// potential energy of gravity and of the uniform load, `sum m g x3 - sum q . r L` [J]
    pub potential_j: f64,
    /// largest segment tension [N]
    pub max_tension_n: f64,
    /// segment where it occurs
    pub max_tension_segment: usize,
}

/// `max_j (f1_j^2 + f2_j^2 + f3_j^2)` (0 for empty slices of equal length), bitwise the fold of `f64::max`
/// in order: [`Explicit::max_tension_in`], observed every level (per span of a section), so a tight loop
/// of independent maxima in lanes the compiler keeps in vector registers. A maximum is exact and the
/// squares are +0 or more, so the order does not change it; `if s > m` passes over a NaN as `f64::max`
/// does (the lanes start at 0 and never hold one) with one vector instruction.
#[inline(always)]
fn largest_square_sum(f1: &[f64], f2: &[f64], f3: &[f64]) -> f64 {
    const LANES: usize = 8;
    let mut lanes = [0.0_f64; LANES];
    let whole = f1.len() / LANES * LANES;
    for c in (0..whole).step_by(LANES) {
        let (g1, g2, g3) = (&f1[c..c + LANES], &f2[c..c + LANES], &f3[c..c + LANES]);
        for k in 0..LANES {
            let s = g1[k] * g1[k] + g2[k] * g2[k] + g3[k] * g3[k];
            lanes[k] = if s > lanes[k] { s } else { lanes[k] };
        }
    }
    let mut m2 = 0.0_f64;
    for j in whole..f1.len() {
        m2 = m2.max(f1[j] * f1[j] + f2[j] * f2[j] + f3[j] * f3[j]);
    }
    lanes.into_iter().fold(m2, f64::max)
}

/// [`largest_square_sum`] compiled for AVX2 (the same IEEE operations: bitwise the same number).
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn largest_square_sum_avx2(f1: &[f64], f2: &[f64], f3: &[f64]) -> f64 {
    largest_square_sum(f1, f2, f3)
}

/// [`largest_square_sum`] compiled for AVX-512 (the same IEEE operations: bitwise the same number).
///
/// # Safety
/// Only where the processor has AVX-512 F, DQ and VL.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f,avx512dq,avx512vl")]
unsafe fn largest_square_sum_avx512(f1: &[f64], f2: &[f64], f3: &[f64]) -> f64 {
    largest_square_sum(f1, f2, f3)
}

/// [`Wire::set_uniform_temperature`] compiled for AVX2 (the same IEEE multiplications: bitwise the same
/// lengths), for [`Explicit::set_uniform_temperature`].
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn set_uniform_temperature_avx2(wire: &mut Wire, temperature_k: f64) {
    wire.set_uniform_temperature(temperature_k);
}

/// `sum_i m_i (v1_i^2 + v2_i^2 + v3_i^2)`, added in node order ([`Explicit::kinetic_energy_half_step`],
/// which the settle detector asks for every level). The terms of a block of nodes are formed together
/// (the compiler vectorises them), then added one by one in node order, so the sum is bitwise that of
/// the loop adding each node's term in turn (each term is the same three products and two sums, and the
/// additions are the same chain in the same order). The AVX2 copy keeps LLVM's two lanes (the ordered
/// additions take a lane at a time) in three-operand instructions: about 10 % fewer instructions.
#[inline(always)]
fn kinetic_sum(m: &[f64], v1: &[f64], v2: &[f64], v3: &[f64]) -> f64 {
    const BLOCK: usize = 8;
    let n1 = m.len();
    let (v1, v2, v3) = (&v1[..n1], &v2[..n1], &v3[..n1]);
    let whole = n1 / BLOCK * BLOCK;
    let mut e = 0.0;
    for c in (0..whole).step_by(BLOCK) {
        let (m, v1, v2, v3) = (&m[c..c + BLOCK], &v1[c..c + BLOCK], &v2[c..c + BLOCK], &v3[c..c + BLOCK]);
        let mut terms = [0.0; BLOCK];
        for k in 0..BLOCK {
            terms[k] = m[k] * (v1[k] * v1[k] + v2[k] * v2[k] + v3[k] * v3[k]);
        }
        for t in terms {
            e += t;
        }
    }
    for i in whole..n1 {
        e += m[i] * (v1[i] * v1[i] + v2[i] * v2[i] + v3[i] * v3[i]);
    }
    e
}

/// [`kinetic_sum`] compiled for AVX2 (the same IEEE operations in the same order: bitwise the same sum).
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn kinetic_sum_avx2(m: &[f64], v1: &[f64], v2: &[f64], v3: &[f64]) -> f64 {
    kinetic_sum(m, v1, v2, v3)
}

/// [`kinetic_sum`] compiled for AVX-512 (the same IEEE operations in the same order: bitwise the same
/// sum).
///
/// # Safety
/// Only where the processor has AVX-512 F, DQ and VL.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f,avx512dq,avx512vl")]
unsafe fn kinetic_sum_avx512(m: &[f64], v1: &[f64], v2: &[f64], v3: &[f64]) -> f64 {
    kinetic_sum(m, v1, v2, v3)
}

/// `sum_i m_i (v1_i^2 + v2_i^2 + v3_i^2)` with the same terms as [`kinetic_sum`] added in another order:
/// sixteen running sums (lane `k` takes the nodes `k, k + 16, ...`), then the sixteen added. Not bitwise
/// the node-order sum; [`Explicit::kinetic_energy_half_step_bounds`] turns it into bounds on it. No
/// addition waits for the one before it across lanes, so this is a few instructions per node and no
/// chain of `N` dependent additions (callgrind, 81 nodes: about 380 instructions against 570 for the
/// node-order sum; eight lanes took 460).
#[inline(always)]
fn kinetic_sum_lanes(m: &[f64], v1: &[f64], v2: &[f64], v3: &[f64]) -> f64 {
    const LANES: usize = 16;
    let n1 = m.len();
    let (v1, v2, v3) = (&v1[..n1], &v2[..n1], &v3[..n1]);
    let whole = n1 / LANES * LANES;
    let mut acc = [0.0; LANES];
    for c in (0..whole).step_by(LANES) {
        let (m, v1, v2, v3) = (&m[c..c + LANES], &v1[c..c + LANES], &v2[c..c + LANES], &v3[c..c + LANES]);
        for k in 0..LANES {
            acc[k] += m[k] * (v1[k] * v1[k] + v2[k] * v2[k] + v3[k] * v3[k]);
        }
    }
    for i in whole..n1 {
        acc[i - whole] += m[i] * (v1[i] * v1[i] + v2[i] * v2[i] + v3[i] * v3[i]);
    }
    acc.iter().sum()
}

/// [`kinetic_sum_lanes`] compiled for AVX2.
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn kinetic_sum_lanes_avx2(m: &[f64], v1: &[f64], v2: &[f64], v3: &[f64]) -> f64 {
    kinetic_sum_lanes(m, v1, v2, v3)
}

/// An integer whose order is that of a speed squared `s2 = v1^2 + v2^2 + v3^2`: `s2` is `+0`, positive,
/// `+inf` or a NaN of either sign (never `-0`: a square is `+0` or positive, and `+0 + +0 = +0`). Its bits
/// without the sign bit: for the numbers, integers in the order of the numbers (non-negative doubles
/// order as their bits); every NaN above `+inf`. So for a bound `b2 >= 0` (not NaN), `speed2_key(s2) <=
/// speed2_key(b2)` is exactly `s2 <= b2`, NaN included (false). An integer maximum vectorises where a
/// floating-point one does not (the node loops fold it in place of a comparison per node).
#[inline(always)]
fn speed2_key(s2: f64) -> i64 {
    (s2.to_bits() & !(1 << 63)) as i64
}

/// [`kinetic_sum_lanes`] from the speeds squared `s2_i = v1_i^2 + v2_i^2 + v3_i^2` as formed: the same
/// terms `m_i s2_i` in the same sixteen lanes, added in the same order, so the same sum bit for bit, from
/// two arrays instead of four and without the squares.
#[inline(always)]
fn kinetic_sum_lanes_of(m: &[f64], s2: &[f64]) -> f64 {
    const LANES: usize = 16;
    let n1 = m.len();
    let s2 = &s2[..n1];
    let whole = n1 / LANES * LANES;
    let mut acc = [0.0; LANES];
    for c in (0..whole).step_by(LANES) {
        let (m, s2) = (&m[c..c + LANES], &s2[c..c + LANES]);
        for k in 0..LANES {
            acc[k] += m[k] * s2[k];
        }
    }
    for i in whole..n1 {
        acc[i - whole] += m[i] * s2[i];
    }
    acc.iter().sum()
}

/// [`kinetic_sum_lanes_of`] compiled for AVX2.
///
/// # Safety
/// Only where the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn kinetic_sum_lanes_of_avx2(m: &[f64], s2: &[f64]) -> f64 {
    kinetic_sum_lanes_of(m, s2)
}

/// The relative margin `4 n u` (`u = 2^-53`) that the kinetic-energy bounds put around a sum of `n`
/// non-negative terms formed in another order ([`Explicit::kinetic_energy_half_step_bounds`],
/// [`Explicit::kinetic_energy_quick_bounds`] derive it); `None` from `4 n u >= 1e-3` (about `2e12` terms),
/// where the first-order bound it stands for no longer holds.
fn sum_rounding_margin(n: usize) -> Option<f64> {
    let delta = 4.0 * n as f64 * f64::EPSILON * 0.5;
    (delta < 1e-3).then_some(delta)
}

/// A number not given before in this process ([`Explicit::wire_stamp`]).
fn next_wire_stamp() -> u64 {
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
    NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
}

/// One definition, three compiled copies: `fn NAME[generics][generic args](args) -> R = BODY;` defines the
/// method `NAME` that calls the `#[inline(always)]` method `BODY` through a copy compiled for AVX-512 (F,
/// DQ, VL) or for AVX2 where the processor has it (chosen at construction, [`Explicit::new`]) and through a
/// copy for the baseline instruction set otherwise. All copies perform the same IEEE operations in the
/// same order (no FMA: Rust never contracts `a * b + c`, and the bodies call no `mul_add`), so their
/// results are bitwise identical (tested); only the vector width and the instruction encoding differ.
macro_rules! isa_dispatch {
    (
        $(#[$doc:meta])*
        fn $name:ident [$($g:tt)*] [$($ga:tt)*] ($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty = $body:ident;
    ) => {
        $(#[$doc])*
        fn $name<$($g)*>(&mut self, $($arg: $ty),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            #[inline(never)]
            #[target_feature(enable = "avx2,avx512f,avx512dq,avx512vl")]
            fn avx512<$($g)*>(s: &mut Explicit, $($arg: $ty),*) -> $ret {
                s.$body::<$($ga)*>($($arg),*)
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(never)]
            #[target_feature(enable = "avx2")]
            fn avx2<$($g)*>(s: &mut Explicit, $($arg: $ty),*) -> $ret {
                s.$body::<$($ga)*>($($arg),*)
            }
            #[inline(never)]
            fn baseline<$($g)*>(s: &mut Explicit, $($arg: $ty),*) -> $ret {
                s.$body::<$($ga)*>($($arg),*)
            }
            #[cfg(target_arch = "x86_64")]
            match self.isa {
                // SAFETY: `isa` is `Avx512` only where the processor reports AVX-512 F, DQ and VL and
                // `Avx2` only where it reports AVX2 (`detected_isa`).
                Isa::Avx512 => return unsafe { avx512::<$($ga)*>(self, $($arg),*) },
                Isa::Avx2 => return unsafe { avx2::<$($ga)*>(self, $($arg),*) },
                Isa::Baseline => {}
            }
            baseline::<$($ga)*>(self, $($arg),*)
        }
    };
}

/// The explicit solver: the wire, its loads and numerics, the clock, and preallocated scratch.
///
/// A clone is the same solver with the kernel's arrays spread over the page again, as
/// [`Explicit::new`] places them ([`Explicit::spread_arrays`]): the arrays a field-by-field clone
/// allocates would start wherever the allocator puts them.
#[derive(Debug)]
pub struct Explicit {
    /// the wire state (read with [`Explicit::wire`], changed through [`Explicit::wire_mut`])
    wire: Wire,
    /// the loads
    loads: Loads,
    /// numerical parameters
    params: StepParams,
    /// simulated time `t_n` [s]
    time_s: f64,
    /// steps taken
    steps: u64,
    /// ground plane, if contact is on
    ground: Option<Ground>,
    /// prescribed nodal forces `f_i` [N] added to every node's force (e.g. the source term of a
    /// manufactured solution), set by the caller before each step for the time `t_n`; `None` for none
    nodal_force: Option<[Vec<f64>; 3]>,
    /// length of the last drift `dt_{n-1/2}` [s] (0 before the first step)
    dt_prev: f64,
    /// `fs`, `es` and `max_tension_n` hold the segment pass of the current state ([`Explicit::evaluate_forces`])
    fresh: bool,
    /// largest segment tension of the last segment pass [N]
    max_tension_n: f64,
    /// whether any segment has internal friction (`None`: not known since the wire last changed)
    viscous: Option<bool>,
    /// whether every node's exposure (the ground contact's share of its load, [`contact`]) is 1 (`None`:
    /// not known since the wire or the ground last changed; only asked without a ground)
    all_exposed: Option<bool>,
    /// whether every segment is intact (`intact = 1`: no break), and the wind diameter factor every
    /// segment shares, if they share one (1 bare, `(d + 2 t) / d` under a uniform ice shell); `None`: not
    /// known since the wire last changed
    plain: Option<(bool, Option<f64>)>,
    /// `1.0 / l0` of every segment [1/m], for the segment pass; valid while `inv_rest_length_fresh`
    inv_rest_length: Vec<f64>,
    /// `inv_rest_length` holds the wire's stress-free lengths (false once the wire may have changed)
    inv_rest_length_fresh: bool,
    /// a number new at every [`Explicit::wire_mut`] ([`Explicit::wire_stamp`])
    wire_stamp: u64,
    /// the largest `|v_i|^2` of the velocities the last step ended with, as the node loops formed it
    /// (the kinetic sum's `v1^2 + v2^2 + v3^2`) [m^2/s^2]; NaN where not known (before a step, after
    /// [`Explicit::wire_mut`], where contact or the strings' kick changed a velocity after the loops)
    speed2_max: f64,
    /// each node's `|v_i|^2` as the smoothing loop formed it [m^2/s^2] (index `i`), valid while
    /// `speed2_fresh` (for the vectorised kinetic sum, [`Explicit::kinetic_energy_half_step_bounds`])
    speed2: Vec<f64>,
    /// `speed2` holds the velocities the last step ended with (a step with smoothing and without ground
    /// contact, not followed by [`Explicit::wire_mut`])
    speed2_fresh: bool,
    /// the least node mass and the sum of the node masses [kg] ([`Explicit::kinetic_energy_quick_bounds`]),
    /// formed at the first call after a change of the wire
    mass_range: std::sync::OnceLock<(f64, f64)>,
    /// segment tension force `T t` [N], padded: index `j + 1` for segment `j`, zero at 0 and `N + 1`
    fs: [Vec<f64>; 3],
    /// half the segment load `P / 2` [N], padded like `fs` (between the segment pass's two loops, the
    /// unit tangent `t`)
    es: [Vec<f64>; 3],
    /// every entry of `es` is `+0.0`: the last segment pass had no distributed load (no wind, `q = 0`),
    /// whose share `0 * intact / 2` is `+0.0` in every segment, and `es` was filled with it once rather than
    /// written at every pass. The node pass then leaves `es` and the exposure out: `f + (+0 + +0) ex` is
    /// `f + 0` exactly for an exposure `ex` of 1 or 0.
    es_zero: bool,
    /// the wire lies in its plane `x1 = c` and stays there: every `x1` the same finite value `c` (not
    /// `-0`), every `v1` `+0` (`None`: not known since the wire last changed; `Some(false)` also after a
    /// step with a force across the plane, until the wire changes). A pass without a load then leaves the
    /// `x1` component out (`PLANAR`).
    planar: Option<bool>,
    /// each segment's length `|r_{i+1} - r_i|` [m] from the segment pass's tension loop for its load loop
    /// (index `j` for segment `j`)
    seg_len: Vec<f64>,
    /// force of each suspension insulator string on its clamp node `(node, F)` [N], in the order of
    /// `Wire::insulators`, from the last segment pass
    point_force: Vec<(usize, [f64; 3])>,
    /// point forces `(node, F)` [N] from outside the conductor (the links of a multi-conductor line:
    /// spacers, strings to shared supports, [`crate::line`]), applied in the node pass like the strings'
    /// forces, held until changed ([`Explicit::set_point_forces`]); empty for a single conductor
    external_force: Vec<(usize, [f64; 3])>,
    /// scratch for the strings' and the external point forces together (no allocation once grown)
    point_scratch: Vec<(usize, [f64; 3])>,
    /// the supports' nodes at construction (fixed nodes and strings' clamps, in node order): the list
    /// [`Explicit::support_forces`] reports, fixed for the run (a released dead-end reports zero)
    supports: Vec<usize>,
    /// the copy of the passes that runs: AVX-512, AVX2 or the baseline (detected at construction; see
    /// [`Explicit::step`])
    isa: Isa,
}

impl Clone for Explicit {
    /// Every field cloned, then the kernel's arrays spread over the page as [`Explicit::new`] spreads them
    /// (measured in issue 27's thirteenth round: `ohl bench`, which times clones, ran its wind and
    /// Kelvin-Voigt workloads 13-36 % slower at N = 1000 and 5000 with the arrays where a plain clone left
    /// them). Addresses never enter the arithmetic: the clone steps to the same bits.
    fn clone(&self) -> Self {
        let mut c = Explicit {
            wire: self.wire.clone(),
            loads: self.loads,
            params: self.params,
            time_s: self.time_s,
            steps: self.steps,
            ground: self.ground.clone(),
            nodal_force: self.nodal_force.clone(),
            dt_prev: self.dt_prev,
            fresh: self.fresh,
            max_tension_n: self.max_tension_n,
            viscous: self.viscous,
            all_exposed: self.all_exposed,
            plain: self.plain,
            inv_rest_length: self.inv_rest_length.clone(),
            inv_rest_length_fresh: self.inv_rest_length_fresh,
            wire_stamp: self.wire_stamp,
            speed2_max: self.speed2_max,
            speed2: self.speed2.clone(),
            speed2_fresh: self.speed2_fresh,
            mass_range: self.mass_range.clone(),
            fs: self.fs.clone(),
            es: self.es.clone(),
            es_zero: self.es_zero,
            planar: self.planar,
            seg_len: self.seg_len.clone(),
            point_force: self.point_force.clone(),
            external_force: self.external_force.clone(),
            point_scratch: self.point_scratch.clone(),
            supports: self.supports.clone(),
            isa: self.isa,
        };
        c.spread_arrays();
        c
    }
}

impl Explicit {
    /// A solver at `t = 0` for the given wire (positions and velocities are the initial state).
    pub fn new(wire: Wire, loads: Loads, params: StepParams) -> Self {
        let pad = wire.segments() + 2;
        let z = || [vec![0.0; pad], vec![0.0; pad], vec![0.0; pad]];
        let supports = wire.supports().into_iter().map(|(i, _)| i).collect();
        let mut solver = Explicit {
            wire,
            loads,
            params,
            time_s: 0.0,
            steps: 0,
            ground: None,
            nodal_force: None,
            dt_prev: 0.0,
            fresh: false,
            max_tension_n: 0.0,
            viscous: None,
            all_exposed: None,
            plain: None,
            inv_rest_length: vec![0.0; pad],
            inv_rest_length_fresh: false,
            wire_stamp: next_wire_stamp(),
            speed2_max: f64::NAN,
            speed2: vec![0.0; pad],
            speed2_fresh: false,
            mass_range: std::sync::OnceLock::new(),
            fs: z(),
            es: z(),
            es_zero: false,
            planar: None,
            seg_len: vec![0.0; pad],
            point_force: Vec::new(),
            external_force: Vec::new(),
            point_scratch: Vec::new(),
            supports,
            isa: detected_isa(),
        };
        solver.spread_arrays();
        solver
    }

    /// The arrays the kernel streams, spread evenly over the page ([`staggered_alloc::spread_evenly`]:
    /// a layout, under the `StaggeredAlloc` global allocator, in which no two of them start within a few
    /// doubles of each other modulo 4 KiB, where the processor takes loads for stores they are not).
    fn spread_arrays(&mut self) {
        staggered_alloc::spread_evenly(&mut self.kernel_arrays());
    }

    /// The arrays the kernel's loops stream, in the order [`Self::spread_arrays`] places them.
    fn kernel_arrays(&mut self) -> [&mut Vec<f64>; 26] {
        let w = &mut self.wire;
        let [x1, x2, x3] = &mut w.x;
        let [v1, v2, v3] = &mut w.v;
        let [f1, f2, f3] = &mut self.fs;
        let [e1, e2, e3] = &mut self.es;
        let [w1, w2] = &mut w.smoothing_weight;
        [
            x1,
            x2,
            x3,
            v1,
            v2,
            v3,
            f1,
            f2,
            f3,
            e1,
            e2,
            e3,
            &mut self.seg_len,
            &mut self.inv_rest_length,
            &mut self.speed2,
            &mut w.inv_mass,
            &mut w.free,
            &mut w.exposed,
            &mut w.axial_stiffness_n,
            &mut w.internal_friction_n_s,
            &mut w.intact,
            &mut w.reference_length,
            &mut w.wind_diameter_factor,
            &mut w.mass,
            w1,
            w2,
        ]
    }

    /// Advance by one step of length `dt` [s] (at most the nominal step; shorter to land on a time).
    ///
    /// Two passes over the arrays: the segment pass (tension and loads), then one node pass that kicks,
    /// drifts and checks the speed; with smoothing (3.3) the node pass is split into the kick, the
    /// smoothing differences, and smoothing fused with the drift. The variant of each pass (law, wind,
    /// gate, uniform load, damping, prescribed forces) is chosen here, once per step, so the node loops
    /// carry no branch on the scenario's options.
    ///
    /// On x86-64 processors with AVX-512 (F, DQ, VL) or AVX2 the same passes run from copies compiled for
    /// them (8 or 4 doubles per vector instead of SSE2's 2), chosen once at construction. All copies
    /// perform the same IEEE operations in the same order (Rust neither contracts to FMA nor
    /// reassociates), so the results are bitwise identical; a test checks it.
    pub fn step(&mut self, dt: f64) -> Result<(), Instability> {
        debug_assert!(dt > 0.0 && dt <= self.params.dt_s * (1.0 + 1e-12));
        if !self.fresh {
            self.compute_segment_forces();
        }
        self.fresh = false;
        if let Some(m) = self.wire.material.as_mut() {
            // The level n the step advances is reached: the materials remember its strains.
            m.advance(&self.wire.temperature_k);
        }
        let kick = 0.5 * (self.dt_prev + dt);
        let damp = self.params.mass_damping_per_s != 0.0;
        let smooth = self.params.smoothing > 0.0;
        if !self.external_force.is_empty() {
            // The strings' forces, then the external ones, in one list for the node pass.
            self.point_scratch.clear();
            self.point_scratch.extend_from_slice(&self.point_force);
            self.point_scratch.extend_from_slice(&self.external_force);
        }
        let key = match (self.nodal_force.is_some(), damp, smooth) {
            (false, false, false) => self.node_pass_of_shares::<false, false, false>(kick, dt),
            (false, true, false) => self.node_pass_of_shares::<false, true, false>(kick, dt),
            (true, false, false) => self.node_pass_of_shares::<true, false, false>(kick, dt),
            (true, true, false) => self.node_pass_of_shares::<true, true, false>(kick, dt),
            (false, false, true) => self.node_pass_of_shares::<false, false, true>(kick, dt),
            (false, true, true) => self.node_pass_of_shares::<false, true, true>(kick, dt),
            (true, false, true) => self.node_pass_of_shares::<true, false, true>(kick, dt),
            (true, true, true) => self.node_pass_of_shares::<true, true, true>(kick, dt),
        };
        let points = !self.point_force.is_empty() || !self.external_force.is_empty();
        // `<=` on the keys is `<=` on the speeds squared (`s2 <= bound2`), except that a NaN (of either
        // sign) fails: [`speed2_key`].
        let bound2 = self.params.max_speed_m_per_s * self.params.max_speed_m_per_s;
        let ok = key <= speed2_key(bound2);
        // The largest speed squared of the velocities the level ends with, for the kinetic-energy bounds
        // ([`Explicit::kinetic_energy_quick_bounds`]), unless something changes a velocity after the
        // node loops: the strings' kick without smoothing (the loop's key holds the clamps' speed before
        // it), or the ground contact.
        self.speed2_max =
            if (points && !smooth) || self.ground.is_some() { f64::NAN } else { f64::from_bits(key as u64) };
        // The smoothing loop wrote every node's `|v|^2` (point forces kick before it).
        self.speed2_fresh = smooth && self.ground.is_none();
        if !self.point_force.is_empty() {
            advance_crossarms(&mut self.wire.insulators, &self.point_force, kick, dt);
        }
        // Locate a failure before ground contact, which may change the offending velocity.
        let failure = if ok { None } else { Some(self.locate_instability()) };
        if let Some(g) = &self.ground {
            let w = &mut self.wire;
            contact::apply(g, &mut w.x, &mut w.v, &mut w.exposed);
        }
        self.dt_prev = dt;
        self.time_s += dt;
        self.steps += 1;
        match failure {
            None => Ok(()),
            Some((node, reason)) => Err(Instability { time_s: self.time_s, step: self.steps, node, reason }),
        }
    }

    /// The wire's state (positions, velocities, segment properties).
    pub fn wire(&self) -> &Wire {
        &self.wire
    }

    /// The wire, to change it (an event, a temperature, a prescribed motion): the segment forces of the
    /// current level are evaluated again before they are next used.
    pub fn wire_mut(&mut self) -> &mut Wire {
        self.fresh = false;
        self.planar = None;
        self.viscous = None;
        self.all_exposed = None;
        self.plain = None;
        self.inv_rest_length_fresh = false;
        self.wire_stamp = next_wire_stamp();
        self.speed2_max = f64::NAN;
        self.speed2_fresh = false;
        self.mass_range = std::sync::OnceLock::new();
        &mut self.wire
    }

    /// `wire_mut().set_uniform_temperature(temperature_k)` ([`Wire::set_uniform_temperature`]: every
    /// segment at `temperature_k` [K], the stress-free lengths rescaled), except that the solver keeps
    /// whether any segment is viscous: a temperature changes no internal friction, so recomputing that
    /// flag (a scan of every segment) would give the same answer. Everything else `wire_mut` marks stale
    /// is marked stale (the forces of the level, `1 / l0`, the wire stamp). For a temperature history
    /// played at every step (`[thermal]`, [`crate::events::Heating`]).
    ///
    /// Where the processor has AVX2, the fill and the multiplications `L * factor` are compiled for it (4
    /// at a time): the same IEEE multiplications, the same bits.
    pub fn set_uniform_temperature(&mut self, temperature_k: f64) {
        self.fresh = false;
        self.inv_rest_length_fresh = false;
        self.wire_stamp = next_wire_stamp();
        #[cfg(target_arch = "x86_64")]
        match self.isa {
            // SAFETY: `isa` is `Avx2` or `Avx512` only where the processor reports AVX2 (`detected_isa`).
            Isa::Avx2 | Isa::Avx512 => return unsafe { set_uniform_temperature_avx2(&mut self.wire, temperature_k) },
            Isa::Baseline => {}
        }
        self.wire.set_uniform_temperature(temperature_k);
    }

    /// A number that changes at every [`Explicit::wire_mut`] and is never given twice in the process (a
    /// clone keeps it until its own `wire_mut`): while it is the one read after a change, the wire's
    /// segment properties (stress-free and reference lengths, temperatures, the thermal data) are those
    /// that change left (the step changes none of them: only positions, velocities, the ground contact's
    /// exposure, the crossarms and the two-material history).
    pub fn wire_stamp(&self) -> u64 {
        self.wire_stamp
    }

    /// The external loads.
    pub fn loads(&self) -> &Loads {
        &self.loads
    }

    /// The external loads, to change them (a wind switch, a gust); forces are evaluated again.
    pub fn loads_mut(&mut self) -> &mut Loads {
        self.fresh = false;
        &mut self.loads
    }

    /// The numerical parameters.
    pub fn params(&self) -> &StepParams {
        &self.params
    }

    /// The numerical parameters, to change them; forces are evaluated again.
    pub fn params_mut(&mut self) -> &mut StepParams {
        self.fresh = false;
        &mut self.params
    }

    /// Simulated time `t_n` [s].
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Set the clock to `t_s` [s] after a step that was shortened to land on that time (the sum of the
    /// step lengths may differ from it by rounding).
    pub fn land_on(&mut self, t_s: f64) {
        self.time_s = t_s;
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The ground in contact, if any.
    pub fn ground(&self) -> Option<&Ground> {
        self.ground.as_ref()
    }

    /// Switch ground contact (a plane, or none).
    pub fn set_ground(&mut self, g: Option<Ground>) {
        self.ground = g;
        self.all_exposed = None;
    }

    /// The prescribed nodal forces `f_i` [N], if any.
    pub fn nodal_force(&self) -> Option<&[Vec<f64>; 3]> {
        self.nodal_force.as_ref()
    }

    /// Prescribe nodal forces `f_i` [N] (three arrays of length `N + 1`) added to every node's force from
    /// now on (e.g. the source term of a manufactured solution at the time `t_n`), or none.
    pub fn set_nodal_force(&mut self, f: Option<[Vec<f64>; 3]>) {
        self.fresh = false;
        self.nodal_force = f;
    }

    /// The prescribed nodal forces in place, to set, change or remove without marking the level's segment
    /// pass stale (it does not read them; the node pass and the diagnostics do): for a load evaluated at
    /// each level from the state, the short circuit's electromagnetic force
    /// ([`crate::scheme::electromagnetic`]), with no allocation once its arrays exist. Three arrays of
    /// length `N + 1` [N].
    pub fn nodal_force_slot(&mut self) -> &mut Option<[Vec<f64>; 3]> {
        &mut self.nodal_force
    }

    /// Point forces `(node, F)` [N] acting on the conductor from outside it (the links of a multi-conductor
    /// line, [`crate::line`]), added to the node's force from now on (copied; no allocation once the list
    /// has grown to its size). They enter the node pass as the strings' forces do (after the node loop,
    /// so the loop over all nodes is untouched and a conductor without them steps bitwise as before), the
    /// support forces of fixed nodes, and the diagnostics. The segment pass does not depend on them, so
    /// forces evaluated at this level stay valid.
    pub fn set_point_forces(&mut self, forces: &[(usize, [f64; 3])]) {
        debug_assert!(forces.iter().all(|&(i, _)| i < self.wire.nodes()));
        self.external_force.clear();
        self.external_force.extend_from_slice(forces);
    }

    /// The external point forces `(node, F)` [N] in force ([`Explicit::set_point_forces`]).
    pub fn point_forces(&self) -> &[(usize, [f64; 3])] {
        &self.external_force
    }

    /// Evaluate the segment pass unless the forces of this level are already evaluated
    /// ([`Explicit::evaluate_forces`] without repeating work).
    pub fn ensure_forces(&mut self) {
        if !self.fresh {
            self.evaluate_forces();
        }
    }

    /// Evaluate the segment pass (tension and distributed loads) of the current state, so that what is
    /// read of it at this time level ([`Explicit::max_tension_n`], [`Explicit::support_forces`],
    /// [`Explicit::diagnostics`]) costs nothing and the next [`Explicit::step`] does not repeat it. The
    /// state can only change through methods that mark these forces stale, so the step always uses the
    /// forces of the state it advances.
    pub fn evaluate_forces(&mut self) {
        self.compute_segment_forces();
        self.fresh = true;
    }

    /// Largest segment tension [N] at the current level: Kelvin-Voigt (3.4) with the strain rate at
    /// `n - 1/2`, the value the step's kick uses. Requires [`Explicit::evaluate_forces`] at this level
    /// (panics otherwise: internal misuse).
    pub fn max_tension_n(&self) -> f64 {
        assert!(self.fresh, "max_tension_n needs evaluate_forces at this time level");
        self.max_tension_n
    }

    /// The largest tension of the segments `segments` at this time level [N] (0 for an empty range): from
    /// the segment pass's forces `|T t|` under the tension-only law (one square root per call), from
    /// [`Explicit::segment_tension`] under the linear law (whose tension may be negative). Requires
    /// [`Explicit::evaluate_forces`] at this level (panics otherwise: internal misuse).
    pub fn max_tension_in(&self, segments: std::ops::Range<usize>) -> f64 {
        assert!(self.fresh, "max_tension_in needs evaluate_forces at this time level");
        if self.wire.law == LawKind::Linear {
            return segments.map(|j| self.segment_tension(j)).fold(0.0, f64::max);
        }
        let [f1, f2, f3] = &self.fs;
        let (a, b) = (segments.start + 1, segments.end + 1);
        let (f1, f2, f3) = (&f1[a..b], &f2[a..b], &f3[a..b]);
        #[cfg(target_arch = "x86_64")]
        match self.isa {
            // SAFETY: `isa` is `Avx512` only where the processor reports AVX-512 F, DQ and VL and `Avx2`
            // only where it reports AVX2 (`detected_isa`).
            Isa::Avx512 => return unsafe { largest_square_sum_avx512(f1, f2, f3) }.sqrt(),
            Isa::Avx2 => return unsafe { largest_square_sum_avx2(f1, f2, f3) }.sqrt(),
            Isa::Baseline => {}
        }
        largest_square_sum(f1, f2, f3).sqrt()
    }

    /// The force the wire applies to each support [N], `(node, [f1, f2, f3])`, at the current level, for
    /// the supports of the wire at construction in node order: at a fixed node the tension of the
    /// adjacent segments, their distributed loads' shares and the node's lumped weight (minus the reaction
    /// the support provides); at a suspension string's clamp the string's pull on its crossarm; zero at a
    /// node released since (the list never changes during a run, so output columns stay aligned). At a
    /// static equilibrium their sum is the total external load on the line (weight, wind, uniform load).
    /// Requires [`Explicit::evaluate_forces`] at this level (panics otherwise: internal misuse). Writes
    /// into `out` (its previous contents replaced).
    pub fn support_forces(&self, out: &mut Vec<(usize, [f64; 3])>) {
        assert!(self.fresh, "support_forces needs evaluate_forces at this time level");
        // (Written in place where `out` already has one entry per support, as from the second call of a
        // caller that keeps it: no length to reserve or store. The arrays are sliced once to the nodes,
        // so that the test of `free[i]` bounds every read of node `i` in them.)
        if out.len() != self.supports.len() {
            out.clear();
            out.resize(self.supports.len(), (0, [0.0; 3]));
        }
        let own = self.own_force();
        let free = &self.wire.free[..self.wire.nodes()];
        for (o, &i) in out.iter_mut().zip(&self.supports) {
            let f = if free[i] <= 0.0 {
                self.node_force3_with(&own, i)
            } else if let Some(&(_, p)) = self.point_force.iter().find(|(n, _)| *n == i) {
                // A suspension support: the string's pull on its crossarm, minus its force on the clamp.
                [-p[0], -p[1], -p[2]]
            } else {
                // Released: no longer held.
                [0.0; 3]
            };
            *o = (i, f);
        }
    }

    /// Length of the last step `dt_{n-1/2}` [s].
    pub fn last_step_s(&self) -> f64 {
        self.dt_prev
    }

    /// Pass 1 over segments: tension force and distributed load, dispatched once on (wind, gate, law);
    /// then the force of each insulator string on its clamp ([`crate::wire::insulator`]), its damper's
    /// from the half-step velocities `v^{n-1/2}` of the clamp and of an elastic crossarm's pivot (as the
    /// segments' Kelvin-Voigt rate).
    fn compute_segment_forces(&mut self) {
        self.segment_and_load_pass();
        self.point_force.clear();
        let w = &self.wire;
        for ins in &w.insulators {
            let i = ins.node;
            let v = [w.v[0][i], w.v[1][i], w.v[2][i]];
            self.point_force.push((i, ins.force_on_moving_clamp(w.position(i), v)));
        }
    }

    #[inline(always)]
    fn segment_and_load_pass(&mut self) {
        let scale = self.loads.wind_scale;
        let q = self.loads.uniform_load_n_per_m;
        match self.loads.wind {
            None => self.dispatch_law(&NoWind, q),
            Some(WindLoad::UniformNormal(mut u)) => {
                u.pressure_n_per_m *= scale;
                self.dispatch_gate(u, u.direction, q);
            }
            Some(WindLoad::Aerodynamic(mut a)) => {
                a.qd_cn *= scale;
                a.qd_ct *= scale;
                // Without a tangential coefficient (the codes' drag), the law without its tangential
                // term: the same bits, fewer operations ([`NormalDrag`]).
                match a.normal_only() {
                    Some(n) => self.dispatch_gate(n, a.direction, q),
                    None => self.dispatch_gate(a, a.direction, q),
                }
            }
        }
    }

    #[inline(always)]
    fn dispatch_gate<W: SegmentLoad>(&mut self, load: W, direction: [f64; 3], q: [f64; 3]) {
        match self.loads.wind_gate {
            WindGate::Always => self.dispatch_law(&load, q),
            WindGate::Downwind => self.dispatch_law(&Downwind { load, direction }, q),
        }
    }

    #[inline(always)]
    fn dispatch_law<W: SegmentLoad>(&mut self, load: &W, q: [f64; 3]) {
        let viscous = *self.viscous.get_or_insert_with(|| self.wire.internal_friction_n_s.iter().any(|&e| e != 0.0));
        match (self.wire.law, q != [0.0; 3], viscous) {
            (LawKind::TensionOnly, true, true) => self.segment_pass::<TensionOnly, W, true, true>(load, q),
            (LawKind::TensionOnly, false, true) => self.segment_pass::<TensionOnly, W, false, true>(load, q),
            (LawKind::Linear, true, true) => self.segment_pass::<Linear, W, true, true>(load, q),
            (LawKind::Linear, false, true) => self.segment_pass::<Linear, W, false, true>(load, q),
            (LawKind::TensionOnly, true, false) => self.segment_pass::<TensionOnly, W, true, false>(load, q),
            (LawKind::TensionOnly, false, false) => self.segment_pass::<TensionOnly, W, false, false>(load, q),
            (LawKind::Linear, true, false) => self.segment_pass::<Linear, W, true, false>(load, q),
            (LawKind::Linear, false, false) => self.segment_pass::<Linear, W, false, false>(load, q),
            (LawKind::TwoMaterial, true, true) => self.two_material_pass::<W, true, true>(load, q),
            (LawKind::TwoMaterial, false, true) => self.two_material_pass::<W, false, true>(load, q),
            (LawKind::TwoMaterial, true, false) => self.two_material_pass::<W, true, false>(load, q),
            (LawKind::TwoMaterial, false, false) => self.two_material_pass::<W, false, false>(load, q),
        }
    }

    /// The segment pass of a two-material wire ([`crate::wire::material`]): the segment element with each
    /// segment's tension from the conductor's law at the segment's temperature and history; the strain of
    /// each segment is recorded for [`Explicit::step`] to fold into the history. A pass of its own (the
    /// law's branches keep it scalar), so the paper's law's passes are untouched.
    fn two_material_pass<W: SegmentLoad, const UNIFORM: bool, const VISCOUS: bool>(&mut self, load: &W, q: [f64; 3]) {
        let w = &mut self.wire;
        let n = w.rest_length.len();
        let Some(mat) = w.material.as_mut() else { unreachable!("LawKind::TwoMaterial without its material") };
        // Every array sliced to its length once, so that the loop's indexing carries no bounds checks.
        let (law, curve) = (&mat.law, mat.curve);
        let (m_o, m_c, last) = (&mat.max_strain[0][..n], &mat.max_strain[1][..n], &mut mat.last_strain[..n]);
        let x = [&w.x[0][..=n], &w.x[1][..=n], &w.x[2][..=n]];
        let v = [&w.v[0][..=n], &w.v[1][..=n], &w.v[2][..=n]];
        let (l0, lref, theta) = (&w.rest_length[..n], &w.reference_length[..n], &w.temperature_k[..n]);
        let (eta, intact, kd) = (&w.internal_friction_n_s[..n], &w.intact[..n], &w.wind_diameter_factor[..n]);
        let [fs0, fs1, fs2] = &mut self.fs;
        let [es0, es1, es2] = &mut self.es;
        self.es_zero = false;
        let (fs0, fs1, fs2) = (&mut fs0[1..=n], &mut fs1[1..=n], &mut fs2[1..=n]);
        let (es0, es1, es2) = (&mut es0[1..=n], &mut es1[1..=n], &mut es2[1..=n]);
        let mut kmax = order_key(0.0);
        for j in 0..n {
            let (va, vb) = ([v[0][j], v[1][j], v[2][j]], [v[0][j + 1], v[1][j + 1], v[2][j + 1]]);
            let (xa, xb) = ([x[0][j], x[1][j], x[2][j]], [x[0][j + 1], x[1][j + 1], x[2][j + 1]]);
            let st = segment::stretch(xa, xb, va, vb, l0[j]);
            let h = History { curve, max_strain: [m_o[j], m_c[j]] };
            let tension = if VISCOUS {
                segment_tension(law, &h, st.e, st.edot, eta[j], theta[j]) * intact[j]
            } else {
                segment_tension(law, &h, st.e, 0.0, 0.0, theta[j]) * intact[j]
            };
            last[j] = if intact[j] > 0.0 { st.e } else { f64::NEG_INFINITY };
            kmax = kmax.max(order_key(tension));
            let t = st.t;
            fs0[j] = tension * t[0];
            fs1[j] = tension * t[1];
            fs2[j] = tension * t[2];
            let e = segment::share::<f64, W, UNIFORM>(load, &st, va, vb, q, lref[j], intact[j], kd[j]);
            es0[j] = e[0];
            es1[j] = e[1];
            es2[j] = e[2];
        }
        self.max_tension_n = from_order_key(kmax);
    }

    isa_dispatch! {
        /// The segment pass ([`Explicit::segment_pass_body`]), from the widest copy the processor runs.
        fn segment_pass[L: TensionLaw, W: SegmentLoad, const UNIFORM: bool, const VISCOUS: bool][L, W, UNIFORM, VISCOUS](
            load: &W, q: [f64; 3]) -> ()
            = segment_pass_body;
    }

    /// `UNIFORM = false` skips the uniform load `q L` (all of `q` zero): the sum `P + 0 L` it saves can
    /// differ from `P` only in the sign of a zero. `VISCOUS = false` (no segment has internal friction)
    /// skips the strain rate, likewise. Each segment's `EA` and `eta` are read from its own arrays.
    #[inline(always)]
    fn segment_pass_body<L: TensionLaw, W: SegmentLoad, const UNIFORM: bool, const VISCOUS: bool>(
        &mut self,
        load: &W,
        q: [f64; 3],
    ) {
        let n = self.wire.segments();
        if !self.inv_rest_length_fresh {
            // The division the segment element performs, once per change of the wire rather than every
            // step: the same quotient, so the same bits.
            for (inv, l0) in self.inv_rest_length[..n].iter_mut().zip(&self.wire.rest_length[..n]) {
                *inv = 1.0 / l0;
            }
            self.inv_rest_length_fresh = true;
        }
        // No break: the factor `intact = 1` enters as a constant, whose products (`T * 1`, `0.5 * 1`) are
        // the other factor exactly, and are left out. One diameter factor `k` on every segment (1 bare, or
        // a uniform ice shell): the law on that diameter is formed once (its `q d c * k`, the products
        // each segment formed) and evaluated at `k = 1` (`q d c k * 1` is `q d c k`): the same bits.
        let (intact_all, shared_k) = *self.plain.get_or_insert_with(|| {
            let w = &self.wire;
            let k0 = w.wind_diameter_factor.first().copied().unwrap_or(1.0);
            let shared = w.wind_diameter_factor.iter().all(|k| k.to_bits() == k0.to_bits());
            (w.intact.iter().all(|&x| x == 1.0), shared.then_some(k0))
        });
        // No load: the shares are `+0.0` (`0 * intact / 2`, intact 1 or 0), written into `es` once.
        if W::ZERO && !UNIFORM {
            if !self.es_zero {
                for e in &mut self.es {
                    e.fill(0.0);
                }
                self.es_zero = true;
            }
        } else {
            self.es_zero = false;
        }
        let planar = W::ZERO && !UNIFORM && *self.planar.get_or_insert_with(|| planar_wire(&self.wire));
        let w = &self.wire;
        let ea = &w.axial_stiffness_n[..n];
        let eta = &w.internal_friction_n_s[..n];
        let (x1, x2, x3) = (&w.x[0][..=n], &w.x[1][..=n], &w.x[2][..=n]);
        let (v1, v2, v3) = (&w.v[0][..=n], &w.v[1][..=n], &w.v[2][..=n]);
        let inv_l0 = &self.inv_rest_length[..n];
        let lref = &w.reference_length[..n];
        let intact = &w.intact[..n];
        let dfac = &w.wind_diameter_factor[..n];
        let [fs1, fs2, fs3] = &mut self.fs;
        let [es1, es2, es3] = &mut self.es;
        let (fs1, fs2, fs3) = (&mut fs1[1..n + 1], &mut fs2[1..n + 1], &mut fs3[1..n + 1]);
        let (es1, es2, es3) = (&mut es1[1..n + 1], &mut es2[1..n + 1], &mut es3[1..n + 1]);
        // The largest tension, as a maximum of order keys: an integer reduction vectorises, a
        // floating-point one does not (it would leave the whole pass scalar, 3-4x slower).
        let kmax = order_key(0.0);
        // The loops are functions taking one slice per argument (inlined here): the compiler then knows
        // that the arrays written do not overlap the arrays read, and vectorises without comparing the
        // addresses of every pair of them at run time before each loop (callgrind, AVX2 copy: about 900
        // instructions fewer per step of plane_weight with both passes, 56.5 -> 38.9 per node-step at
        // N = 50). The operations and their order are the loops' as they were: the same bits.
        if W::ZERO && !UNIFORM {
            // No load: one loop, the tension alone (the zero shares are in `es` already); in the plane
            // `x1 = c` with the `x1` differences the constant `+0` they are (`c - c`, `+0 - +0`).
            let kmax = if planar {
                segment_loop::<L, VISCOUS, true>(kmax, x1, x2, x3, v1, v2, v3, inv_l0, ea, eta, intact, fs1, fs2, fs3)
            } else {
                segment_loop::<L, VISCOUS, false>(kmax, x1, x2, x3, v1, v2, v3, inv_l0, ea, eta, intact, fs1, fs2, fs3)
            };
            self.max_tension_n = from_order_key(kmax);
            return;
        }
        // Two loops: the tension loop (square root, division, the law) keeps each segment's tangent and
        // length, the load loop (the wind law's square root and division) reads them back. Each value is
        // the one the single loop forms (stored and loaded as it is), so the result is bitwise the same;
        // two shorter dependency chains per iteration let the processor overlap more segments.
        let len = &mut self.seg_len[..n];
        let kmax = match (intact_all, shared_k) {
            (true, Some(k)) => {
                let kmax = tension_loop::<L, VISCOUS, true>(
                    kmax, x1, x2, x3, v1, v2, v3, inv_l0, ea, eta, intact, fs1, fs2, fs3, es1, es2, es3, len,
                );
                let load = load.at_diameter_factor(k);
                load_loop::<W, UNIFORM, true, true>(&load, q, v1, v2, v3, len, lref, intact, dfac, es1, es2, es3);
                kmax
            }
            (true, None) => {
                let kmax = tension_loop::<L, VISCOUS, true>(
                    kmax, x1, x2, x3, v1, v2, v3, inv_l0, ea, eta, intact, fs1, fs2, fs3, es1, es2, es3, len,
                );
                load_loop::<W, UNIFORM, true, false>(load, q, v1, v2, v3, len, lref, intact, dfac, es1, es2, es3);
                kmax
            }
            (false, _) => {
                let kmax = tension_loop::<L, VISCOUS, false>(
                    kmax, x1, x2, x3, v1, v2, v3, inv_l0, ea, eta, intact, fs1, fs2, fs3, es1, es2, es3, len,
                );
                load_loop::<W, UNIFORM, false, false>(load, q, v1, v2, v3, len, lref, intact, dfac, es1, es2, es3);
                kmax
            }
        };
        self.max_tension_n = from_order_key(kmax);
    }

    /// The node pass with the shares (`LOADED`) or without them ([`Explicit::es_zero`]), and without them
    /// in the plane (`PLANAR`, [`Explicit::planar`]): a copy of its own for each, so that no compiled pass
    /// holds two copies of the node loop without smoothing (which left the compiler moving the arrays'
    /// addresses between registers at every iteration: callgrind, wind_3d at N = 1000, 42.3 -> 46.3
    /// instructions per node-step with both loops in one pass). Every pass but the plane's may move the
    /// wire out of its plane, so each of them gives up what `planar` knew.
    #[inline(always)]
    fn node_pass_of_shares<const EXTRA: bool, const DAMP: bool, const SMOOTH: bool>(
        &mut self,
        kick: f64,
        dt: f64,
    ) -> i64 {
        if !self.es_zero {
            // A load (a wind across the plane) may move the wire out of it: looked for again (once) when the
            // load is gone.
            self.planar = None;
            return self.node_pass::<EXTRA, DAMP, SMOOTH, true, false>(kick, dt);
        }
        // In the plane (the segment pass found it so: `planar` is known wherever `es_zero` is) with no
        // force across it, the `x1` component stays as it is (the argument at `PLANAR` in `node_loop`).
        let across = |f: &[(usize, [f64; 3])]| f.iter().any(|(_, f)| f[0] != 0.0);
        if self.planar == Some(true) && !EXTRA && !across(&self.point_force) && !across(&self.external_force) {
            self.node_pass::<EXTRA, DAMP, SMOOTH, false, true>(kick, dt)
        } else {
            // A force across the plane: the wire may leave it. It is not looked for again until the wire
            // changes (a wire pulled out of its plane by a string or a link stays out, and a scan at
            // every step would walk its arrays up to the first node that moved).
            self.planar = Some(false);
            self.node_pass::<EXTRA, DAMP, SMOOTH, false, false>(kick, dt)
        }
    }

    isa_dispatch! {
        /// The node pass ([`Explicit::kick_drift`]), from the widest copy the processor runs.
        fn node_pass[const EXTRA: bool, const DAMP: bool, const SMOOTH: bool, const LOADED: bool, const PLANAR: bool][EXTRA, DAMP, SMOOTH, LOADED, PLANAR](
            kick: f64, dt: f64) -> i64
            = kick_drift;
    }

    /// Pass 2 over nodes: `v += kick a` on free nodes, then (without smoothing) `r += dt v` in the same
    /// loop; returns the largest [`speed2_key`] of the new velocities (and, without smoothing, of the
    /// clamps' velocities before their strings' kick: the speed check only). `EXTRA` adds the prescribed
    /// nodal forces; `DAMP = false` drops the mass damping `- zeta v` (zeta = 0: the term can change only
    /// the sign of a zero); `SMOOTH` inserts (3.3) between the kick and the drift; `LOADED = false` leaves
    /// out the shares, all `+0.0` ([`Explicit::es_zero`]).
    ///
    /// Each operation is the one of the unfused passes, in the same order, so the result is identical:
    /// `a = (F / m + g_k) - zeta v`, `v + (kick free) a`, `x + dt v`.
    ///
    /// The point forces (`point_force`, with `external_force` through `point_scratch`) act on a few nodes
    /// (the insulator strings on their clamps, the links of a line): their kick
    /// `kick F / m` is added after the node loop (and, without smoothing, its drift `dt kick F / m`), which
    /// is the same update up to rounding and leaves the loop over all nodes untouched.
    #[inline(always)]
    fn kick_drift<const EXTRA: bool, const DAMP: bool, const SMOOTH: bool, const LOADED: bool, const PLANAR: bool>(
        &mut self,
        kick: f64,
        dt: f64,
    ) -> i64 {
        // Fields borrowed one by one (the wire mutably, the point forces and the nodal force shared).
        let extra = if EXTRA { self.nodal_force.as_ref().expect("EXTRA with a nodal force") } else { &NO_NODAL_FORCE };
        let points = if self.external_force.is_empty() { &self.point_force[..] } else { &self.point_scratch[..] };
        // Every exposure 1 (no ground, none left below 1 by an earlier one): the loop skips `* 1`. Only
        // with smoothing, where the loop does not drift: without it the loop reads fifteen arrays, and a
        // second copy of it in the pass left the compiler shuffling their addresses between registers at
        // every iteration (callgrind, case a: 60 -> 74 instructions per iteration).
        let bare = SMOOTH
            && self.ground.is_none()
            && *self.all_exposed.get_or_insert_with(|| self.wire.exposed.iter().all(|&e| e == 1.0));
        let w = &mut self.wire;
        let n1 = w.nodes();
        let inv_m = &w.inv_mass[..n1];
        let free = &w.free[..n1];
        let exposed = &w.exposed[..n1];
        let zeta = self.params.mass_damping_per_s;
        let g = -self.loads.gravity_m_per_s2;
        let [fs1, fs2, fs3] = &mut self.fs;
        let [es1, es2, es3] = &self.es;
        let (f1, f2, f3) = (&fs1[..=n1], &fs2[..=n1], &fs3[..=n1]);
        let (e1, e2, e3) = (&es1[..=n1], &es2[..=n1], &es3[..=n1]);
        let (ex1, ex2, ex3) =
            if EXTRA { (&extra[0][..n1], &extra[1][..n1], &extra[2][..n1]) } else { (&[][..], &[][..], &[][..]) };
        let [v1, v2, v3] = &mut w.v;
        let (v1, v2, v3) = (&mut v1[..n1], &mut v2[..n1], &mut v3[..n1]);
        let [x1, x2, x3] = &mut w.x;
        let (x1, x2, x3) = (&mut x1[..n1], &mut x2[..n1], &mut x3[..n1]);
        // One slice per argument, as in the segment pass (no run-time overlap checks).
        let mut kmax = if !LOADED {
            node_loop::<EXTRA, DAMP, SMOOTH, true, false, PLANAR>(
                kick, dt, zeta, g, inv_m, free, exposed, f1, f2, f3, e1, e2, e3, ex1, ex2, ex3, v1, v2, v3, x1, x2, x3,
            )
        } else if bare {
            node_loop::<EXTRA, DAMP, SMOOTH, true, true, false>(
                kick, dt, zeta, g, inv_m, free, exposed, f1, f2, f3, e1, e2, e3, ex1, ex2, ex3, v1, v2, v3, x1, x2, x3,
            )
        } else {
            node_loop::<EXTRA, DAMP, SMOOTH, false, true, false>(
                kick, dt, zeta, g, inv_m, free, exposed, f1, f2, f3, e1, e2, e3, ex1, ex2, ex3, v1, v2, v3, x1, x2, x3,
            )
        };
        for &(i, f) in points {
            let kf = kick * free[i] * inv_m[i];
            let dv = [kf * f[0], kf * f[1], kf * f[2]];
            v1[i] += dv[0];
            v2[i] += dv[1];
            v3[i] += dv[2];
            if !SMOOTH {
                x1[i] += dt * dv[0];
                x2[i] += dt * dv[1];
                x3[i] += dt * dv[2];
                kmax = kmax.max(speed2_key(v1[i] * v1[i] + v2[i] * v2[i] + v3[i] * v3[i]));
            }
        }
        if !SMOOTH {
            return kmax;
        }
        // Smoothing (3.3), scaled by dt / dt_nominal, then the drift (3.6) with the smoothed velocity. The
        // segment tension forces are no longer needed: their arrays hold the differences.
        let b = self.params.smoothing * (dt / self.params.dt_s);
        let intact = &w.intact;
        if !PLANAR {
            smoothing::differences(v1, fs1, intact);
        }
        smoothing::differences(v2, fs2, intact);
        smoothing::differences(v3, fs3, intact);
        let (d1, d2, d3) = (&fs1[..n1 + 1], &fs2[..n1 + 1], &fs3[..n1 + 1]);
        // One slice per argument, as in the node loop (no run-time overlap checks: about 250
        // instructions per step before the loop, measured at 81 nodes).
        if w.uniform_smoothing {
            // Every weight is 1: the paper's (3.3) exactly.
            smooth_drift_loop::<false, PLANAR>(
                b,
                dt,
                free,
                &[],
                &[],
                d1,
                d2,
                d3,
                v1,
                v2,
                v3,
                x1,
                x2,
                x3,
                &mut self.speed2,
            )
        } else {
            let [wl, wr] = &w.smoothing_weight;
            smooth_drift_loop::<true, PLANAR>(b, dt, free, wl, wr, d1, d2, d3, v1, v2, v3, x1, x2, x3, &mut self.speed2)
        }
    }

    /// Find the first offending node after the node pass reported a failure: `(node, reason)`. The pass
    /// flags a speed beyond the bound or a non-finite one, so some node shows it; should none (which
    /// would be a kernel bug), the fastest node is reported rather than panicking.
    #[cold]
    fn locate_instability(&self) -> (usize, InstabilityReason) {
        let w = &self.wire;
        let bound = self.params.max_speed_m_per_s;
        let mut fastest = (0, 0.0_f64);
        for i in 0..w.nodes() {
            let v = [w.v[0][i], w.v[1][i], w.v[2][i]];
            let s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let finite = s.is_finite() && w.position(i).iter().all(|c| c.is_finite());
            if !finite {
                return (i, InstabilityReason::NonFinite);
            }
            if s > bound {
                return (i, InstabilityReason::SpeedLimit { speed_m_per_s: s, bound_m_per_s: bound });
            }
            if s > fastest.1 {
                fastest = (i, s);
            }
        }
        (fastest.0, InstabilityReason::SpeedLimit { speed_m_per_s: fastest.1, bound_m_per_s: bound })
    }

    /// Energies, synchronised velocity and the largest tension at the current time level.
    ///
    /// Not on the hot path: uses the segment forces of [`Explicit::evaluate_forces`] (or computes them,
    /// without marking them fresh for the step, if they are not) to get `a^n`, then `v^n = v^{n-1/2} +
    /// dt_{n-1/2}/2 a^n` (the first half of the next kick, the velocity-Verlet synchronisation). The largest
    /// tension is the segment pass's, the value the kick uses.
    pub fn diagnostics(&mut self) -> Diagnostics {
        if !self.fresh {
            self.compute_segment_forces();
        }
        self.diagnostics_of_forces()
    }

    /// [`Explicit::diagnostics`] at a level whose forces were evaluated ([`Explicit::evaluate_forces`];
    /// panics otherwise: internal misuse), for the observers of a run, which may not change the state.
    pub fn level_diagnostics(&self) -> Diagnostics {
        assert!(self.fresh, "level_diagnostics needs evaluate_forces at this time level");
        self.diagnostics_of_forces()
    }

    /// The energies of [`Explicit::level_diagnostics`] (bitwise the same numbers) without its largest
    /// tension, which costs a tension per segment: `max_tension_n` and `max_tension_segment` are 0. For
    /// the time series' rows, whose largest tension is the kernel's ([`Explicit::max_tension_n`]).
    pub fn level_energies(&self) -> Diagnostics {
        assert!(self.fresh, "level_energies needs evaluate_forces at this time level");
        self.energies_of_forces::<false>()
    }

    /// Kinetic energy of the half-step velocities `sum m_i |v_i^{n-1/2}|^2 / 2` [J]: one pass over the
    /// nodes, no forces needed (the settle detector's measure).
    pub fn kinetic_energy_half_step(&self) -> f64 {
        let w = &self.wire;
        let n1 = w.nodes();
        let (m, v1, v2, v3) = (&w.mass[..n1], &w.v[0][..n1], &w.v[1][..n1], &w.v[2][..n1]);
        #[cfg(target_arch = "x86_64")]
        match self.isa {
            // SAFETY: `isa` is `Avx512` only where the processor reports AVX-512 F, DQ and VL and `Avx2`
            // only where it reports AVX2 (`detected_isa`).
            Isa::Avx512 => return 0.5 * unsafe { kinetic_sum_avx512(m, v1, v2, v3) },
            Isa::Avx2 => return 0.5 * unsafe { kinetic_sum_avx2(m, v1, v2, v3) },
            Isa::Baseline => {}
        }
        0.5 * kinetic_sum(m, v1, v2, v3)
    }

    /// Bounds `[lo, hi]` [J] on [`Explicit::kinetic_energy_half_step`] without its node-order sum (a
    /// chain of `N + 1` dependent additions): the same terms `t_i = m_i |v_i|^2 >= 0` summed in sixteen
    /// lanes ([`kinetic_sum_lanes`]). Any order of summing `n` non-negative numbers gives the exact sum
    /// `S` within `gamma_{n-1} S`, `gamma_k = k u / (1 - k u)`, `u = 2^-53` (Higham, *Accuracy and
    /// Stability of Numerical Algorithms*, 2nd ed., eq. (4.4); additions of subnormal numbers are exact),
    /// so the node-order sum lies within `(1 +- gamma) / (1 -+ gamma)` of the lanes' sum, inside the
    /// factors `1 -+ 4 n u` used here (for `n u < 1e-3`, and covering the rounding of the bounds' own
    /// products). Halving is monotone, so `lo <= kinetic_energy_half_step() <= hi`. Both bounds are NaN
    /// where the lanes' sum is not finite or `4 n u >= 1e-3` (more than about `2e12` nodes): the caller
    /// then needs the sum itself.
    pub fn kinetic_energy_half_step_bounds(&self) -> (f64, f64) {
        let w = &self.wire;
        let n1 = w.nodes();
        let (m, v1, v2, v3) = (&w.mass[..n1], &w.v[0][..n1], &w.v[1][..n1], &w.v[2][..n1]);
        let s2 = &self.speed2[..n1];
        let fresh = self.speed2_fresh;
        // From the speeds squared the smoothing loop kept where they are those of `v` (the same terms
        // `m_i s2_i` in the same lanes: the same sum), else from the velocities.
        #[cfg(target_arch = "x86_64")]
        let s = match (self.isa, fresh) {
            // SAFETY: `isa` is `Avx2` or wider only where the processor reports AVX2 (`detected_isa`).
            (Isa::Avx512 | Isa::Avx2, true) => unsafe { kinetic_sum_lanes_of_avx2(m, s2) },
            (Isa::Avx512 | Isa::Avx2, false) => unsafe { kinetic_sum_lanes_avx2(m, v1, v2, v3) },
            (Isa::Baseline, true) => kinetic_sum_lanes_of(m, s2),
            (Isa::Baseline, false) => kinetic_sum_lanes(m, v1, v2, v3),
        };
        #[cfg(not(target_arch = "x86_64"))]
        let s = if fresh { kinetic_sum_lanes_of(m, s2) } else { kinetic_sum_lanes(m, v1, v2, v3) };
        let Some(delta) = sum_rounding_margin(n1).filter(|_| s.is_finite()) else { return (f64::NAN, f64::NAN) };
        (0.5 * (s * (1.0 - delta)), 0.5 * (s * (1.0 + delta)))
    }

    /// Bounds `[lo, hi]` [J] on [`Explicit::kinetic_energy_half_step`] from the largest speed squared
    /// `s2_max` the last step's node loops formed (no pass over the nodes; NaN where the step did not keep
    /// it: `speed2_max`): with the least node mass `m_min` and the sum `M` of the masses,
    ///
    /// - `lo = (m_min s2_max) / 2`: the node-order sum of the non-negative terms `t_i = m_i s2_i` is at
    ///   least each term (a rounded sum of non-negative numbers is at least each of them, rounding being
    ///   monotone), and the term of the fastest node is at least `m_min s2_max` as rounded (monotone
    ///   again);
    /// - `hi = ((s2_max M) (1 + 4 n u) + 2^-1022) / 2`: each term is at most `m_i s2_max (1 + u)`, their
    ///   node-order sum at most `(1 + gamma_{n-1})` times their exact sum and `M` as summed at least `(1 -
    ///   gamma_{n-1})` times the exact one (Higham, eq. (4.4), as in
    ///   [`Explicit::kinetic_energy_half_step_bounds`]); the factor `1 + 4 n u` covers these and the
    ///   products' roundings for `n u < 1e-3`, and `2^-1022` the absolute error of products that underflow.
    ///
    /// Halving is monotone, so `lo <= kinetic_energy_half_step() <= hi`. Their ratio is about `M / m_min`
    /// (about `2 N` on a uniform wire), wide, but enough for the settle detector at most levels, where the
    /// energy is far above its threshold and below its peak. Both NaN where `s2_max` is unknown or not
    /// finite, or `4 n u >= 1e-3`.
    pub fn kinetic_energy_quick_bounds(&self) -> (f64, f64) {
        let s2 = self.speed2_max;
        let n1 = self.wire.nodes();
        let Some(delta) = sum_rounding_margin(n1).filter(|_| s2.is_finite()) else { return (f64::NAN, f64::NAN) };
        let &(m_min, m_sum) = self.mass_range.get_or_init(|| {
            let m = &self.wire.mass[..n1];
            (m.iter().copied().fold(f64::INFINITY, f64::min), m.iter().sum::<f64>())
        });
        (0.5 * (m_min * s2), 0.5 * ((s2 * m_sum) * (1.0 + delta) + f64::MIN_POSITIVE))
    }

    fn diagnostics_of_forces(&self) -> Diagnostics {
        self.energies_of_forces::<true>()
    }

    /// The diagnostics of the forces last computed, with the largest tension if `MAX_TENSION`.
    ///
    /// The arrays are sliced to their lengths once (no bounds check per element) and each segment's
    /// strain is formed in place by [`segment::stretch`], the function [`Wire::strain`] calls (the same
    /// operations on the same operands); every term and every sum is the one of the loops as they were
    /// (each node's own force from [`OwnForce::component`]), in the same order: bitwise the same energies.
    fn energies_of_forces<const MAX_TENSION: bool>(&self) -> Diagnostics {
        let w = &self.wire;
        let n = w.segments();
        let n1 = n + 1;
        let half = 0.5 * self.dt_prev;
        let zeta = self.params.mass_damping_per_s;
        let g = self.loads.gravity_m_per_s2;
        let q = self.loads.uniform_load_n_per_m;
        let mut d = Diagnostics::default();
        // The point forces (strings, external forces) by node, each node's in the order `node_force`
        // adds them: each node's net force is `node_force`'s sum, without a scan of every point force at
        // every node.
        let mut points: Vec<(usize, [f64; 3])> = self.point_force.iter().chain(&self.external_force).copied().collect();
        points.sort_by_key(|&(node, _)| node);
        let (mass, inv_mass, free) = (&w.mass[..n1], &w.inv_mass[..n1], &w.free[..n1]);
        let x = [&w.x[0][..n1], &w.x[1][..n1], &w.x[2][..n1]];
        let v = [&w.v[0][..n1], &w.v[1][..n1], &w.v[2][..n1]];
        let own = self.own_force();
        let mut next = 0;
        for i in 0..n1 {
            let first = next;
            while next < points.len() && points[next].0 == i {
                next += 1;
            }
            let at_i = &points[first..next];
            let mut v2 = 0.0;
            for k in 0..3 {
                // The node's own force, then the point forces at the node.
                let mut f = own.component(k, i);
                for (_, p) in at_i {
                    f += p[k];
                }
                let a = f * inv_mass[i] - zeta * v[k][i];
                let vn = v[k][i] + half * free[i] * a;
                v2 += vn * vn;
            }
            d.kinetic_j += 0.5 * mass[i] * v2;
            d.potential_j += mass[i] * g * x[2][i];
        }
        let (ea, l0, lref, intact) =
            (&w.axial_stiffness_n[..n], &w.rest_length[..n], &w.reference_length[..n], &w.intact[..n]);
        let zero = [0.0; 3];
        for j in 0..n {
            let (a, b) = ([x[0][j], x[1][j], x[2][j]], [x[0][j + 1], x[1][j + 1], x[2][j + 1]]);
            // `Wire::strain(j)`.
            let (ea, e) = (ea[j], segment::stretch(a, b, zero, zero, l0[j]).e);
            let energy = match (w.law, &w.material) {
                (LawKind::TwoMaterial, Some(m)) => m.energy_density(j, e, w.temperature_k[j]),
                (LawKind::Linear, _) => Linear::energy_density(ea, e),
                _ => TensionOnly::energy_density(ea, e),
            };
            d.elastic_j += energy * l0[j] * intact[j];
            if MAX_TENSION {
                let tension = self.segment_tension(j);
                if tension > d.max_tension_n {
                    d.max_tension_n = tension;
                    d.max_tension_segment = j;
                }
            }
            // Potential of the uniform load: each segment's share q L sits half on each end node.
            for k in 0..3 {
                d.potential_j -= q[k] * lref[j] * 0.5 * (a[k] + b[k]);
            }
        }
        // Insulator strings and elastic crossarms; a crossarm's velocity is synchronised like the nodes'.
        for (ins, &(_, f)) in w.insulators.iter().zip(&self.point_force) {
            d.elastic_j += ins.energy(w.position(ins.node));
            if let Some(arm) = &ins.crossarm {
                d.elastic_j += arm.spring_energy(ins.pivot_m);
                let spring = arm.spring_force(ins.pivot_m);
                for k in 0..2 {
                    let u = arm.velocity_m_per_s[k] + half * (spring[k] - f[k]) / arm.mass_kg;
                    d.kinetic_j += 0.5 * arm.mass_kg * u * u;
                }
            }
        }
        d
    }

    /// Net force on node `i` along `x_k` [N] from the segment forces last computed: tension, distributed
    /// loads, gravity and the prescribed nodal force (no mass damping).
    #[cfg(test)]
    fn node_force(&self, k: usize, i: usize) -> f64 {
        self.node_force_with(&self.own_force(), k, i)
    }

    /// [`Explicit::node_force`] from the arrays `own` ([`Explicit::own_force`]) sliced once by a caller
    /// that forms several nodes' forces.
    #[inline(always)]
    fn node_force_with(&self, own: &OwnForce<'_>, k: usize, i: usize) -> f64 {
        let mut f = own.component(k, i);
        for &(node, p) in self.point_force.iter().chain(&self.external_force) {
            if node == i {
                f += p[k];
            }
        }
        f
    }

    /// [`Explicit::node_force`] of the three components at once: one scan of the point forces, each
    /// component summed in the same order (the same bits). (The supports' forces call
    /// [`Explicit::node_force3_with`]; the tests compare this with `node_force`.)
    #[cfg(test)]
    fn node_force3(&self, i: usize) -> [f64; 3] {
        self.node_force3_with(&self.own_force(), i)
    }

    /// [`Explicit::node_force3`] from the arrays `own` ([`Explicit::own_force`]) sliced once by a caller
    /// that forms several nodes' forces.
    #[inline(always)]
    fn node_force3_with(&self, own: &OwnForce<'_>, i: usize) -> [f64; 3] {
        let mut f = [0, 1, 2].map(|k| own.component(k, i));
        // (The peaks ask for every support's force at every level; most runs have no point force.)
        if self.point_force.is_empty() && self.external_force.is_empty() {
            return f;
        }
        // The strings' forces, then the external ones: the order of `node_force`'s chain, in two plain
        // loops (a chained iterator tests which half it is in at every element).
        for &(node, p) in &self.point_force {
            if node == i {
                for k in 0..3 {
                    f[k] += p[k];
                }
            }
        }
        for &(node, p) in &self.external_force {
            if node == i {
                for k in 0..3 {
                    f[k] += p[k];
                }
            }
        }
        f
    }

    /// The arrays of the nodes' own forces (without the point forces: the strings', the external ones),
    /// each sliced once to the wire's nodes.
    #[inline(always)]
    fn own_force(&self) -> OwnForce<'_> {
        let (w, n1) = (&self.wire, self.wire.nodes());
        OwnForce {
            fs: [&self.fs[0][..n1 + 1], &self.fs[1][..n1 + 1], &self.fs[2][..n1 + 1]],
            es: [&self.es[0][..n1 + 1], &self.es[1][..n1 + 1], &self.es[2][..n1 + 1]],
            exposed: &w.exposed[..n1],
            mass: &w.mass[..n1],
            gravity: self.loads.gravity_m_per_s2,
            nodal: self.nodal_force.as_ref().map(|x| [&x[0][..n1], &x[1][..n1], &x[2][..n1]]),
        }
    }

    /// Net force on every node [N] at the current state (tension with the Kelvin-Voigt rate from the
    /// current velocities, distributed loads, gravity, prescribed nodal forces; no mass damping), written
    /// into `out` (three arrays of length `N + 1`). At a static equilibrium it vanishes on free nodes: the
    /// residual of the discrete equations that an implicit solver drives to zero.
    pub fn net_force(&mut self, out: &mut [Vec<f64>; 3]) {
        self.compute_segment_forces();
        let own = self.own_force();
        for k in 0..3 {
            for i in 0..self.wire.nodes() {
                out[k][i] = self.node_force_with(&own, k, i);
            }
        }
    }

    /// Tension of segment `j` [N] at the current level (Kelvin-Voigt, strain rate at `n - 1/2`): the
    /// segment element's ([`crate::element::segment`]), the value the kernel's segment pass forms.
    pub fn segment_tension(&self, j: usize) -> f64 {
        let w = &self.wire;
        let (ea, eta) = (w.axial_stiffness_n[j], w.internal_friction_n_s[j]);
        let st = segment::stretch(w.position(j), w.position(j + 1), w.velocity(j), w.velocity(j + 1), w.rest_length[j]);
        let t = match (w.law, &w.material) {
            (LawKind::TwoMaterial, Some(m)) => m.tension(j, st.e, st.edot, eta, w.temperature_k[j]),
            (LawKind::Linear, _) => Linear::tension(ea, eta, st.e, st.edot),
            _ => TensionOnly::tension(ea, eta, st.e, st.edot),
        };
        t * w.intact[j]
    }
}

/// Leapfrog step of the elastic crossarms ([`crate::wire::insulator`]): the kick with the string force
/// of this level `points` and the springs, then the drift; the pivots of rigid crossarms stay.
fn advance_crossarms(insulators: &mut [Insulator], points: &[(usize, [f64; 3])], kick: f64, dt: f64) {
    for (ins, &(_, f)) in insulators.iter_mut().zip(points) {
        let p = ins.pivot_m;
        let Some(arm) = ins.crossarm.as_mut() else { continue };
        let spring = arm.spring_force(p);
        for k in 0..2 {
            let a = (spring[k] - f[k]) / arm.mass_kg;
            arm.velocity_m_per_s[k] += kick * a;
            ins.pivot_m[k] += dt * arm.velocity_m_per_s[k];
        }
    }
}

/// No prescribed nodal force (the node pass's argument without one: nothing to build per step).
static NO_NODAL_FORCE: [Vec<f64>; 3] = [const { Vec::new() }; 3];

/// The arrays of the nodes' own forces (without point forces), each sliced to the wire's nodes (`fs`,
/// `es`: one more, the padding after the last segment): a node's index tested against one of them
/// bounds its reads in all.
struct OwnForce<'a> {
    fs: [&'a [f64]; 3],
    es: [&'a [f64]; 3],
    exposed: &'a [f64],
    mass: &'a [f64],
    gravity: f64,
    nodal: Option<[&'a [f64]; 3]>,
}

impl OwnForce<'_> {
    /// Node `i`'s own force along `x_k` [N]: the segments' tension and loads, gravity and the prescribed
    /// nodal force, summed in that order (the node pass's sum, [`Explicit::node_force`]).
    #[inline(always)]
    fn component(&self, k: usize, i: usize) -> f64 {
        let (fs, es) = (self.fs[k], self.es[k]);
        let mut f = fs[i + 1] - fs[i] + (es[i + 1] + es[i]) * self.exposed[i];
        if k == 2 {
            f -= self.mass[i] * self.gravity;
        }
        if let Some(x) = &self.nodal {
            f += x[k][i];
        }
        f
    }
}

/// The segment element's tension of each segment, without a distributed load (its share, `+0.0`, is in
/// `es` already: [`Explicit::segment_pass_body`]), with the largest tension's order key folded into `kmax`
/// (returned). Every slice has the length of `fs1`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn segment_loop<L: TensionLaw, const VISCOUS: bool, const PLANAR: bool>(
    mut kmax: i64,
    x1: &[f64],
    x2: &[f64],
    x3: &[f64],
    v1: &[f64],
    v2: &[f64],
    v3: &[f64],
    inv_l0: &[f64],
    ea: &[f64],
    eta: &[f64],
    intact: &[f64],
    fs1: &mut [f64],
    fs2: &mut [f64],
    fs3: &mut [f64],
) -> i64 {
    let n = fs1.len();
    // Each pair of neighbours from one array (one base address, two offsets: fewer registers).
    let (x1a, x1b, x2a, x2b, x3a, x3b) = (&x1[..n], &x1[1..n + 1], &x2[..n], &x2[1..n + 1], &x3[..n], &x3[1..n + 1]);
    let (v1a, v1b, v2a, v2b, v3a, v3b) = (&v1[..n], &v1[1..n + 1], &v2[..n], &v2[1..n + 1], &v3[..n], &v3[1..n + 1]);
    let (inv_l0, ea, eta, intact) = (&inv_l0[..n], &ea[..n], &eta[..n], &intact[..n]);
    let (fs2, fs3) = (&mut fs2[..n], &mut fs3[..n]);
    for j in 0..n {
        // The segment element (`element::segment`) on f64, piece by piece: the same operations in the
        // same order as its dual-number evaluation in the static Jacobian.
        // `PLANAR`: `x1 = c` and `v1 = +0` at both ends, whose differences `c - c` and `+0 - +0` are the
        // constant `+0` that `0.0 - 0.0` gives (the rest of the element, `0 * inv_len` included, as it is).
        let (xa1, xb1, va1, vb1) = if PLANAR { (0.0, 0.0, 0.0, 0.0) } else { (x1a[j], x1b[j], v1a[j], v1b[j]) };
        let (va, vb) = ([va1, v2a[j], v3a[j]], [vb1, v2b[j], v3b[j]]);
        let st = segment::stretch_by_inverse([xa1, x2a[j], x3a[j]], [xb1, x2b[j], x3b[j]], va, vb, inv_l0[j]);
        let tension = if VISCOUS {
            L::tension(ea[j], eta[j], st.e, st.edot) * intact[j]
        } else {
            L::tension(ea[j], 0.0, st.e, 0.0) * intact[j]
        };
        kmax = kmax.max(L::order_key(tension));
        let t = st.t;
        fs1[j] = tension * t[0];
        fs2[j] = tension * t[1];
        fs3[j] = tension * t[2];
    }
    kmax
}

/// Whether `w` lies in its plane `x1 = c` at rest across it ([`Explicit::planar`]): every `x1` has the
/// bits of one finite `c` that is not `-0` (`c + 0` is `c`), every `v1` is `+0`.
fn planar_wire(w: &Wire) -> bool {
    let (x1, v1) = (&w.x[0], &w.v[0]);
    let c = x1[0];
    c.is_finite()
        && c.to_bits() != (-0.0_f64).to_bits()
        && x1.iter().all(|x| x.to_bits() == c.to_bits())
        && v1.iter().all(|v| v.to_bits() == 0)
}

/// The tension loop of [`Explicit::segment_pass_body`] under a load: each segment's tension force into
/// `fs`, its tangent into `es` and its length into `len` for [`load_loop`]; the largest tension's order
/// key folded into `kmax` (returned). Every slice has the length of `fs1`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn tension_loop<L: TensionLaw, const VISCOUS: bool, const INTACT: bool>(
    mut kmax: i64,
    x1: &[f64],
    x2: &[f64],
    x3: &[f64],
    v1: &[f64],
    v2: &[f64],
    v3: &[f64],
    inv_l0: &[f64],
    ea: &[f64],
    eta: &[f64],
    intact: &[f64],
    fs1: &mut [f64],
    fs2: &mut [f64],
    fs3: &mut [f64],
    es1: &mut [f64],
    es2: &mut [f64],
    es3: &mut [f64],
    len: &mut [f64],
) -> i64 {
    let n = fs1.len();
    // Each pair of neighbours from one array (one base address, two offsets: fewer registers).
    let (x1a, x1b, x2a, x2b, x3a, x3b) = (&x1[..n], &x1[1..n + 1], &x2[..n], &x2[1..n + 1], &x3[..n], &x3[1..n + 1]);
    let (v1a, v1b, v2a, v2b, v3a, v3b) = (&v1[..n], &v1[1..n + 1], &v2[..n], &v2[1..n + 1], &v3[..n], &v3[1..n + 1]);
    let (inv_l0, ea, eta, intact) = (&inv_l0[..n], &ea[..n], &eta[..n], &intact[..n]);
    let (fs2, fs3, es1, es2, es3, len) =
        (&mut fs2[..n], &mut fs3[..n], &mut es1[..n], &mut es2[..n], &mut es3[..n], &mut len[..n]);
    for j in 0..n {
        // The segment element (`element::segment`) on f64, piece by piece: the same operations in the
        // same order as its dual-number evaluation in the static Jacobian.
        let (va, vb) = ([v1a[j], v2a[j], v3a[j]], [v1b[j], v2b[j], v3b[j]]);
        let st = segment::stretch_by_inverse([x1a[j], x2a[j], x3a[j]], [x1b[j], x2b[j], x3b[j]], va, vb, inv_l0[j]);
        // Without internal friction anywhere (`VISCOUS = false`) the viscous term is the constant
        // `0 * 0`: it changes only the sign of a zero tension, and the strain rate is not computed.
        // `INTACT`: every segment intact, the factor the constant 1.
        let it = if INTACT { 1.0 } else { intact[j] };
        let tension = if VISCOUS {
            L::tension(ea[j], eta[j], st.e, st.edot) * it
        } else {
            L::tension(ea[j], 0.0, st.e, 0.0) * it
        };
        kmax = kmax.max(L::order_key(tension));
        let t = st.t;
        fs1[j] = tension * t[0];
        fs2[j] = tension * t[1];
        fs3[j] = tension * t[2];
        es1[j] = t[0];
        es2[j] = t[1];
        es3[j] = t[2];
        len[j] = st.len;
    }
    kmax
}

/// The load loop of [`Explicit::segment_pass_body`]: each segment's load share from its tangent (in `es`)
/// and length (`len`) into `es`. `UNIT_K`: `load` is the law on the diameter every segment shares
/// ([`SegmentLoad::at_diameter_factor`]), evaluated at `k = 1`; else each segment's factor from `dfac`.
/// Every slice has the length of `es1`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn load_loop<W: SegmentLoad, const UNIFORM: bool, const INTACT: bool, const UNIT_K: bool>(
    load: &W,
    q: [f64; 3],
    v1: &[f64],
    v2: &[f64],
    v3: &[f64],
    len: &[f64],
    lref: &[f64],
    intact: &[f64],
    dfac: &[f64],
    es1: &mut [f64],
    es2: &mut [f64],
    es3: &mut [f64],
) {
    let n = es1.len();
    let (v1a, v1b, v2a, v2b, v3a, v3b) = (&v1[..n], &v1[1..n + 1], &v2[..n], &v2[1..n + 1], &v3[..n], &v3[1..n + 1]);
    let (len, lref, intact, dfac) = (&len[..n], &lref[..n], &intact[..n], &dfac[..n]);
    let (es2, es3) = (&mut es2[..n], &mut es3[..n]);
    for j in 0..n {
        let (va, vb) = ([v1a[j], v2a[j], v3a[j]], [v1b[j], v2b[j], v3b[j]]);
        // `e` and `edot` are not read by the load.
        let st = segment::Stretch { len: len[j], t: [es1[j], es2[j], es3[j]], e: 0.0, edot: 0.0 };
        // `INTACT`, `UNIT_K`: every segment intact, at the diameter of `load`; the factor the constant 1.
        let it = if INTACT { 1.0 } else { intact[j] };
        let k = if UNIT_K { 1.0 } else { dfac[j] };
        let e = segment::share::<f64, W, UNIFORM>(load, &st, va, vb, q, lref[j], it, k);
        es1[j] = e[0];
        es2[j] = e[1];
        es3[j] = e[2];
    }
}

/// The node loop of [`Explicit::kick_drift`]: kick (and, without smoothing, drift) of each node from its
/// two segments' arrays (`lo`: segment `i - 1`, `hi`: segment `i`). Without smoothing it returns the
/// largest [`speed2_key`] of the nodes' new velocities (the speed check and the kinetic-energy bounds,
/// [`Explicit::step`]), with smoothing `0` (the smoothing loop checks). Every slice has the length of `v1`
/// (the `ex` only with `EXTRA`).
///
/// Each operation is the one of the unfused passes, in the same order, so the result is identical:
/// `a = (F / m + g_k) - zeta v`, `v + (kick free) a`, `x + dt v`. `LOADED = false`: every share in `e` is
/// `+0.0` ([`Explicit::segment_pass_body`] without a load) and every exposure 1 or 0, so `(e_hi + e_lo) ex`
/// is `+0.0` and the sum `f + 0.0` is formed without reading them (`e`, `exposed` and `BARE` unused).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn node_loop<
    const EXTRA: bool,
    const DAMP: bool,
    const SMOOTH: bool,
    const BARE: bool,
    const LOADED: bool,
    const PLANAR: bool,
>(
    kick: f64,
    dt: f64,
    zeta: f64,
    g: f64,
    inv_m: &[f64],
    free: &[f64],
    exposed: &[f64],
    f1: &[f64],
    f2: &[f64],
    f3: &[f64],
    e1: &[f64],
    e2: &[f64],
    e3: &[f64],
    ex1: &[f64],
    ex2: &[f64],
    ex3: &[f64],
    v1: &mut [f64],
    v2: &mut [f64],
    v3: &mut [f64],
    x1: &mut [f64],
    x2: &mut [f64],
    x3: &mut [f64],
) -> i64 {
    let n1 = v1.len();
    let (inv_m, free, exposed) = (&inv_m[..n1], &free[..n1], &exposed[..n1]);
    // Each node's two segments from one array (one base address, two offsets: fewer registers).
    let (f1lo, f1hi, f2lo, f2hi) = (&f1[..n1], &f1[1..n1 + 1], &f2[..n1], &f2[1..n1 + 1]);
    let (f3lo, f3hi, e1lo, e1hi) = (&f3[..n1], &f3[1..n1 + 1], &e1[..n1], &e1[1..n1 + 1]);
    let (e2lo, e2hi, e3lo, e3hi) = (&e2[..n1], &e2[1..n1 + 1], &e3[..n1], &e3[1..n1 + 1]);
    let (ex1, ex2, ex3) = if EXTRA { (&ex1[..n1], &ex2[..n1], &ex3[..n1]) } else { (ex1, ex2, ex3) };
    let (v2, v3, x1, x2, x3) = (&mut v2[..n1], &mut v3[..n1], &mut x1[..n1], &mut x2[..n1], &mut x3[..n1]);
    let mut kmax = 0;
    for i in 0..n1 {
        let (im, kf) = (inv_m[i], kick * free[i]);
        // `BARE` (every exposure 1): `(e_hi + e_lo) * 1` is `e_hi + e_lo` exactly, so the product is left out.
        let mut f = if !LOADED {
            [f1hi[i] - f1lo[i] + 0.0, f2hi[i] - f2lo[i] + 0.0, f3hi[i] - f3lo[i] + 0.0]
        } else if BARE {
            [
                f1hi[i] - f1lo[i] + (e1hi[i] + e1lo[i]),
                f2hi[i] - f2lo[i] + (e2hi[i] + e2lo[i]),
                f3hi[i] - f3lo[i] + (e3hi[i] + e3lo[i]),
            ]
        } else {
            let ex = exposed[i];
            [
                f1hi[i] - f1lo[i] + (e1hi[i] + e1lo[i]) * ex,
                f2hi[i] - f2lo[i] + (e2hi[i] + e2lo[i]) * ex,
                f3hi[i] - f3lo[i] + (e3hi[i] + e3lo[i]) * ex,
            ]
        };
        if EXTRA {
            f[0] += ex1[i];
            f[1] += ex2[i];
            f[2] += ex3[i];
        }
        let mut a = [f[0] * im + 0.0, f[1] * im + 0.0, f[2] * im + g];
        if DAMP {
            a[0] -= zeta * v1[i];
            a[1] -= zeta * v2[i];
            a[2] -= zeta * v3[i];
        }
        // `PLANAR`: `v1 = +0` stays `+0` (`a1 = f1 / m + 0.0` is `+0` for the zero `f1` of a wire in its
        // plane, `+0 - zeta +0` too, and `+0 + kf +0` is `+0`), and `x1 = c` stays `c`: neither is written.
        let v0 = if PLANAR { 0.0 } else { v1[i] + kf * a[0] };
        let v = [v0, v2[i] + kf * a[1], v3[i] + kf * a[2]];
        if !PLANAR {
            v1[i] = v[0];
        }
        v2[i] = v[1];
        v3[i] = v[2];
        if !SMOOTH {
            if !PLANAR {
                x1[i] += dt * v[0];
            }
            x2[i] += dt * v[1];
            x3[i] += dt * v[2];
            kmax = kmax.max(speed2_key(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
        }
    }
    kmax
}

/// The second half of the smoothing (3.3) and the drift (3.6) of [`Explicit::kick_drift`]: each node's
/// smoothed velocity from the differences `d` ([`smoothing::differences`]; `WEIGHTED`: with the
/// weights `wl`, `wr`, else the paper's unweighted form), then `x + dt v`; returns the largest
/// [`speed2_key`] of the smoothed velocities (as [`node_loop`]). `free`, `v` and `x` have one length, `d` one more, `wl`
/// and `wr` that of `v` (empty without `WEIGHTED`). The operations are those of the loops it replaces,
/// in the same order: the result is identical.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn smooth_drift_loop<const WEIGHTED: bool, const PLANAR: bool>(
    b: f64,
    dt: f64,
    free: &[f64],
    wl: &[f64],
    wr: &[f64],
    d1: &[f64],
    d2: &[f64],
    d3: &[f64],
    v1: &mut [f64],
    v2: &mut [f64],
    v3: &mut [f64],
    x1: &mut [f64],
    x2: &mut [f64],
    x3: &mut [f64],
    speed2: &mut [f64],
) -> i64 {
    let n1 = v1.len();
    let free = &free[..n1];
    let speed2 = &mut speed2[..n1];
    let (wl, wr) = if WEIGHTED { (&wl[..n1], &wr[..n1]) } else { (wl, wr) };
    // Each node's two differences from one array at two offsets, as the node loop reads its segments (a
    // single index `i + 1` let the compiler carry the difference across iterations in shuffles: more
    // instructions than a second load).
    let (d1lo, d1hi, d2lo, d2hi) = (&d1[..n1], &d1[1..n1 + 1], &d2[..n1], &d2[1..n1 + 1]);
    let (d3lo, d3hi) = (&d3[..n1], &d3[1..n1 + 1]);
    let (v2, v3, x1, x2, x3) = (&mut v2[..n1], &mut v3[..n1], &mut x1[..n1], &mut x2[..n1], &mut x3[..n1]);
    let mut kmax = 0;
    for i in 0..n1 {
        let bf = b * free[i];
        let v = if WEIGHTED {
            let (l, r) = (wl[i], wr[i]);
            [
                smoothing::smoothed_weighted(v1[i], bf, d1lo[i], d1hi[i], l, r),
                smoothing::smoothed_weighted(v2[i], bf, d2lo[i], d2hi[i], l, r),
                smoothing::smoothed_weighted(v3[i], bf, d3lo[i], d3hi[i], l, r),
            ]
        } else {
            [
                smoothing::smoothed(v1[i], bf, d1lo[i], d1hi[i]),
                smoothing::smoothed(v2[i], bf, d2lo[i], d2hi[i]),
                smoothing::smoothed(v3[i], bf, d3lo[i], d3hi[i]),
            ]
        };
        // `PLANAR`: the differences of `v1 = +0` are `+0` and its smoothed value `+0` (`d1` is not formed).
        let v = if PLANAR { [0.0, v[1], v[2]] } else { v };
        if !PLANAR {
            v1[i] = v[0];
            x1[i] += dt * v[0];
        }
        v2[i] = v[1];
        v3[i] = v[2];
        x2[i] += dt * v[1];
        x3[i] += dt * v[2];
        let s2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        speed2[i] = s2;
        kmax = kmax.max(speed2_key(s2));
    }
    kmax
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::aero::Aerodynamic;
    use crate::scheme::configs::Config;

    /// The step as first written (three unfused passes: kick, smoothing, drift), kept as the reference
    /// that the fused kernel must reproduce bit for bit.
    fn reference_step(s: &mut Explicit, dt: f64) -> bool {
        s.compute_segment_forces();
        if let Some(m) = s.wire.material.as_mut() {
            m.advance(&s.wire.temperature_k);
        }
        let kick = 0.5 * (s.dt_prev + dt);
        let w = &mut s.wire;
        let n1 = w.nodes();
        let g = [0.0, 0.0, -s.loads.gravity_m_per_s2];
        for k in 0..3 {
            for i in 0..n1 {
                let mut f = s.fs[k][i + 1] - s.fs[k][i] + (s.es[k][i + 1] + s.es[k][i]) * w.exposed[i];
                if let Some(x) = &s.nodal_force {
                    f += x[k][i];
                }
                let a = f * w.inv_mass[i] + g[k] - s.params.mass_damping_per_s * w.v[k][i];
                w.v[k][i] += kick * w.free[i] * a;
            }
        }
        if s.params.smoothing > 0.0 {
            let b = s.params.smoothing * (dt / s.params.dt_s);
            for k in 0..3 {
                smoothing::smooth(&mut w.v[k], &mut s.fs[k], &w.intact, &w.free, &w.smoothing_weight, b);
            }
        }
        let mut ok = true;
        for i in 0..n1 {
            for k in 0..3 {
                w.x[k][i] += dt * w.v[k][i];
            }
            ok &= w.v[0][i] * w.v[0][i] + w.v[1][i] * w.v[1][i] + w.v[2][i] * w.v[2][i]
                <= s.params.max_speed_m_per_s * s.params.max_speed_m_per_s;
        }
        if let Some(g) = &s.ground {
            let w = &mut s.wire;
            contact::apply(g, &mut w.x, &mut w.v, &mut w.exposed);
        }
        s.dt_prev = dt;
        ok
    }

    fn assert_bitwise(a: &Explicit, b: &Explicit, what: &str) {
        for k in 0..3 {
            for i in 0..a.wire.nodes() {
                assert_eq!(a.wire.x[k][i].to_bits(), b.wire.x[k][i].to_bits(), "{what}: x{k}[{i}]");
                assert_eq!(a.wire.v[k][i].to_bits(), b.wire.v[k][i].to_bits(), "{what}: v{k}[{i}]");
            }
        }
    }

    /// The benchmark configurations, then every option the passes specialise on: mass damping, a uniform
    /// load, prescribed nodal forces, a break, the downwind gate, ground contact.
    fn option_cases() -> Vec<(String, Explicit)> {
        let mut cases: Vec<(String, Explicit)> = Config::ALL.map(|c| (c.name().to_string(), c.solver(40))).into();
        let mut s = Config::Wind3d.solver(41);
        s.params.mass_damping_per_s = 0.3;
        s.params.smoothing = 0.03;
        s.loads.uniform_load_n_per_m = [0.5, 0.0, -1.0];
        s.loads.wind_gate = WindGate::Downwind;
        s.nodal_force = Some([vec![0.1; 42], vec![-0.2; 42], vec![0.3; 42]]);
        s.ground = Some(Ground::level(-0.05, 0.6, 0.0));
        s.wire.break_segment(20);
        cases.push(("all options".into(), s));
        // Unequal node masses take the mass-weighted smoothing path.
        let mut s = Config::Wind3d.solver(41);
        s.params.smoothing = 0.03;
        s.wire.point_mass_kg[10] = 50.0 * s.wire.mass[10];
        s.wire.update_node_masses();
        s.wire.break_segment(30);
        assert!(!s.wire.uniform_smoothing);
        cases.push(("weighted smoothing".into(), s));
        cases
    }

    /// The kernel's arrays start spread evenly over the page (the unit tests run under
    /// `StaggeredAlloc`): the `i`-th of the 26 arrays long enough to be placed at `64 floor(64 i / 26)`
    /// bytes modulo 4 KiB, at a length (1025 doubles, N = 1024) where the system allocator would start
    /// them all within a few cache lines of each other, and at N = 50 (51 doubles), where it would put
    /// them next to each other at 16-byte boundaries; a clone's arrays too, and a clone steps to the bits
    /// of its original.
    #[test]
    fn kernel_arrays_are_spread_over_the_page() {
        fn assert_spread(s: &mut Explicit, what: &str) {
            let mut slot = 0;
            let arrays = s.kernel_arrays();
            let m = arrays.len();
            for (i, a) in arrays.into_iter().enumerate() {
                if std::mem::size_of_val(a.as_slice()) < staggered_alloc::MIN_SIZE {
                    continue;
                }
                assert_eq!(a.as_ptr() as usize % staggered_alloc::PAGE, 64 * (64 * slot / m), "{what}: array {i}");
                slot += 1;
            }
            assert!(slot >= 24, "{what}: only {slot} arrays placed");
        }
        for n in [1024, 50] {
            let mut s = Config::Wind3d.solver(n);
            s.params.smoothing = 0.02;
            assert_spread(&mut s, &format!("N = {n}"));
            let mut c = s.clone();
            assert_spread(&mut c, &format!("N = {n}, a clone"));
            for _ in 0..10 {
                s.step(s.params.dt_s).unwrap();
                c.step(c.params.dt_s).unwrap();
            }
            let bits =
                |e: &Explicit| e.wire.x.iter().chain(&e.wire.v).flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&s), bits(&c), "N = {n}: the clone's steps");
        }
    }

    /// The passes' shortcuts for a plain wire (every segment intact, at one diameter: the factors 1 left
    /// out, the law on the shared diameter formed once) and for full exposure (no ground: `* 1` left out)
    /// give the bits of the general passes: the option cases stepped 300 times with the shortcuts and with
    /// the general passes forced, an iced case (wind diameter factor 1.4 on every third segment), whose
    /// diameters differ, and a uniformly iced one (1.35 on every segment, in a wind without a tangential
    /// coefficient: the IEC combined case), whose law is formed once.
    #[test]
    fn plain_wire_and_full_exposure_shortcuts_change_no_bit() {
        let mut cases = option_cases();
        let mut iced = Config::Wind3d.solver(41);
        iced.params.smoothing = 0.02;
        for j in (0..41).step_by(3) {
            iced.wire.wind_diameter_factor[j] = 1.4;
        }
        cases.push(("iced".into(), iced));
        let mut uniform = Config::Wind3d.solver(41);
        uniform.params.smoothing = 0.02;
        uniform.wire.wind_diameter_factor.fill(1.35);
        if let Some(WindLoad::Aerodynamic(a)) = &mut uniform.loads.wind {
            a.qd_ct = 0.0;
        }
        cases.push(("uniformly iced".into(), uniform));
        let (mut shortcuts, mut iced_intact, mut uniformly_iced) = (0, 0, 0);
        for (name, mut fast) in cases {
            let mut general = fast.clone();
            let dt = fast.params.dt_s;
            for step in 0..300 {
                (general.plain, general.all_exposed) = (Some((false, None)), Some(false));
                assert_eq!(fast.step(dt).is_ok(), general.step(dt).is_ok(), "{name}: step {step}");
            }
            for k in 0..3 {
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&fast.fs[k]), bits(&general.fs[k]), "{name}: fs{k}");
                assert_eq!(bits(&fast.es[k]), bits(&general.es[k]), "{name}: es{k}");
            }
            assert_bitwise(&fast, &general, &name);
            shortcuts +=
                usize::from(fast.plain == Some((true, Some(1.0)))) + usize::from(fast.all_exposed == Some(true));
            iced_intact += usize::from(fast.plain == Some((true, None)));
            uniformly_iced += usize::from(fast.plain == Some((true, Some(1.35))));
        }
        assert!(
            shortcuts >= 6 && iced_intact == 1 && uniformly_iced == 1,
            "{shortcuts} shortcuts taken, {iced_intact} iced and intact, {uniformly_iced} uniformly iced"
        );
    }

    #[test]
    fn fused_kernel_is_bitwise_identical_to_the_unfused_passes() {
        // The option cases (`option_cases`), with shortened steps.
        let cases = option_cases();
        for (name, mut fused) in cases {
            let mut reference = fused.clone();
            let dt = fused.params.dt_s;
            for step in 0..400 {
                let h = if step % 7 == 3 { 0.37 * dt } else { dt };
                let ok = reference_step(&mut reference, h);
                assert_eq!(fused.step(h).is_ok(), ok, "{name}: stability verdicts differ at step {step}");
            }
            assert_bitwise(&fused, &reference, &name);
        }
    }

    /// The shares of a pass without a load are not written but filled once ([`Explicit::es_zero`]): a wind
    /// switched off, on and off again (with a ground, a break and smoothing, and without smoothing) steps
    /// bitwise as the unfused reference, which reads `es` at every node, and after each calm stretch `es`
    /// holds `+0.0` in every entry (no share of the windy stretch left behind).
    #[test]
    fn zero_shares_filled_once_follow_the_wind_on_and_off() {
        for smoothing in [0.0, 0.03] {
            let mut fused = Config::Wind3d.solver(41);
            fused.params.smoothing = smoothing;
            fused.ground = Some(Ground::level(-0.05, 0.6, 0.0));
            fused.wire.break_segment(17);
            let wind = fused.loads.wind;
            let mut reference = fused.clone();
            let dt = fused.params.dt_s;
            for (stretch, w) in [None, wind, None].into_iter().enumerate() {
                fused.loads.wind = w;
                reference.loads.wind = w;
                for step in 0..150 {
                    let ok = reference_step(&mut reference, dt);
                    assert_eq!(fused.step(dt).is_ok(), ok, "stretch {stretch}, step {step}");
                }
                assert_bitwise(&fused, &reference, &format!("smoothing {smoothing}, stretch {stretch}"));
                assert_eq!(fused.es_zero, w.is_none());
                let zeros = fused.es.iter().flatten().all(|e| e.to_bits() == 0);
                assert_eq!(zeros, w.is_none(), "stretch {stretch}: es all +0 exactly when calm");
            }
        }
    }

    /// The kernel takes an aerodynamic wind without a tangential coefficient as a
    /// [`crate::element::aero::NormalDrag`]; its segment pass gives the general law's bits. Three wires in that wind (plain; Kelvin-Voigt with
    /// smoothing and a third of the segments iced, `k = 1.35`; a broken segment with the downwind gate of
    /// the paper's gust), each stepped 400 times from the straight chord with the wind ramped on over the
    /// first 100 steps (its zero start included); at every level a copy evaluates the forces through the
    /// general law, compared in the tension forces and the load shares.
    #[test]
    fn normal_drag_pass_gives_the_general_laws_bits() {
        let mut cases = Vec::new();
        let mut plain = Config::Wind3d.solver(40);
        if let Some(WindLoad::Aerodynamic(a)) = &mut plain.loads.wind {
            a.qd_ct = 0.0;
        }
        cases.push(("plain", plain.clone()));
        let mut iced = plain.clone();
        iced.params.smoothing = 0.02;
        for j in 0..iced.wire.segments() {
            iced.wire.internal_friction_n_s[j] = 2.0;
            if j % 3 == 0 {
                iced.wire.wind_diameter_factor[j] = 1.35;
            }
        }
        cases.push(("iced, Kelvin-Voigt, smoothing", iced));
        let mut broken = plain;
        broken.wire.break_segment(13);
        broken.loads.wind_gate = WindGate::Downwind;
        cases.push(("broken, downwind", broken));
        for (name, mut s) in cases {
            let Some(WindLoad::Aerodynamic(law)) = s.loads.wind else { unreachable!() };
            let dt = s.params.dt_s;
            for step in 0..400 {
                s.loads.wind_scale = (step as f64 / 100.0).min(1.0);
                let mut general = s.clone();
                s.evaluate_forces();
                let scale = s.loads.wind_scale;
                let a = Aerodynamic { qd_cn: law.qd_cn * scale, qd_ct: law.qd_ct * scale, ..law };
                assert!(a.normal_only().is_some());
                general.dispatch_gate(a, a.direction, s.loads.uniform_load_n_per_m);
                let bits = |x: &[Vec<f64>; 3]| x.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&s.fs), bits(&general.fs), "{name}, step {step}: tension forces");
                assert_eq!(bits(&s.es), bits(&general.es), "{name}, step {step}: load shares");
                s.step(dt).unwrap();
            }
            // The wire has left its chord across the wind.
            assert!(s.wire.x[0].iter().any(|&x| x.abs() > 1e-3), "{name}");
        }
    }

    /// A wire in its plane `x1 = c` without a load steps with the `x1` component left out (`PLANAR`) and
    /// gives the bits of the passes that form it: each case stepped 300 times (a step in 7 shortened) and
    /// a copy forced through the general passes at every step, compared in `x`, `v` and the forces the
    /// observers read. The planar cases (plain; smoothing, damping, Kelvin-Voigt, a ground and a break;
    /// `c = 0.25` m with mass-weighted smoothing) stay planar to the end; a nodal force across the plane,
    /// a point force across it from step 100, and a wind across it from step 100 to 200 (the calm after it
    /// must not take the plane's pass again) take the wire out of it (and the copy with them).
    #[test]
    fn planar_passes_leave_out_the_x1_component_bit_for_bit() {
        let plane = || Config::PlaneWeight.solver(40);
        let mut cases: Vec<(&str, Explicit, bool)> = vec![("plain", plane(), true)];
        let mut s = plane();
        s.params.smoothing = 0.03;
        s.params.mass_damping_per_s = 0.3;
        s.wire.internal_friction_n_s.fill(3.0);
        s.ground = Some(Ground::level(-0.05, 0.6, 0.4));
        s.wire.break_segment(25);
        cases.push(("smoothing, damping, viscous, ground, break", s, true));
        let mut s = plane();
        s.params.smoothing = 0.03;
        s.wire.x[0].fill(0.25);
        s.wire.point_mass_kg[10] = 20.0 * s.wire.mass[10];
        s.wire.update_node_masses();
        cases.push(("c = 0.25 m, weighted smoothing", s, true));
        let mut s = plane();
        s.nodal_force = Some([vec![0.1; 41], vec![0.0; 41], vec![0.0; 41]]);
        cases.push(("nodal force across", s, false));
        cases.push(("point force across from step 100", plane(), false));
        cases.push(("wind across from step 100 to 200", plane(), false));
        let wind = Config::Wind3d.solver(40).loads.wind;
        assert!(wind.is_some());
        for (name, mut fast, stays) in cases {
            let mut general = fast.clone();
            let dt = fast.params.dt_s;
            for step in 0..300 {
                if name.starts_with("point") && step == 100 {
                    fast.set_point_forces(&[(12, [0.5, 0.0, 0.0])]);
                    general.set_point_forces(&[(12, [0.5, 0.0, 0.0])]);
                }
                if name.starts_with("wind") && (step == 100 || step == 200) {
                    let w = if step == 100 { wind } else { None };
                    fast.loads_mut().wind = w;
                    general.loads_mut().wind = w;
                }
                general.planar = Some(false);
                let h = if step % 7 == 3 { 0.37 * dt } else { dt };
                assert_eq!(fast.step(h).is_ok(), general.step(h).is_ok(), "{name}: step {step}");
            }
            fast.evaluate_forces();
            general.evaluate_forces();
            assert_bitwise(&fast, &general, name);
            for k in 0..3 {
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&fast.fs[k]), bits(&general.fs[k]), "{name}: fs{k}");
            }
            assert_eq!(fast.planar == Some(true), stays, "{name}: {:?}", fast.planar);
            let moved = fast.wire.v[0].iter().any(|v| *v != 0.0);
            assert_eq!(moved, !stays, "{name}: the wire left the plane exactly when pushed across it");
        }
    }

    /// The kept inverses of the stress-free lengths follow a change of the wire: a solver whose
    /// stress-free lengths change mid-run (a temperature step through `wire_mut`) steps bitwise as one that
    /// divides afresh every step, and differently from one without the change (so the change reached
    /// the tension).
    #[test]
    fn kept_inverse_rest_lengths_follow_the_wire() {
        for config in [Config::PlaneWeight, Config::Wind3d, Config::ViscousSmoothed] {
            let mut kept = config.solver(40);
            let mut afresh = kept.clone();
            let mut unchanged = kept.clone();
            let dt = kept.params.dt_s;
            for step in 0..300 {
                if step == 100 {
                    for s in [&mut kept, &mut afresh] {
                        // aluminium's expansion, 1.9e-5 /K (any nonzero value would do)
                        let t = s.wire.reference_temperature_k + 40.0;
                        s.wire_mut().thermal_expansion_per_k = 1.9e-5;
                        s.wire_mut().set_temperature(0..40, t);
                    }
                }
                afresh.inv_rest_length_fresh = false;
                for s in [&mut kept, &mut afresh, &mut unchanged] {
                    s.step(dt).expect("stable");
                }
            }
            assert_bitwise(&kept, &afresh, config.name());
            assert_ne!(kept.wire.x[2][20].to_bits(), unchanged.wire.x[2][20].to_bits(), "{}", config.name());
        }
    }

    #[test]
    fn order_keys_order_like_the_numbers() {
        let xs = [f64::NEG_INFINITY, -3.5e300, -1.0, -1e-310, -0.0, 0.0, 1e-310, 2.0, 7.1e305, f64::INFINITY];
        for w in xs.windows(2) {
            assert!(order_key(w[0]) < order_key(w[1]), "{} < {}", w[0], w[1]);
        }
        for x in xs {
            assert_eq!(from_order_key(order_key(x)).to_bits(), x.to_bits());
        }
    }

    #[test]
    fn largest_tension_is_the_largest_segment_tension() {
        for (name, mut s) in option_cases() {
            for _ in 0..50 {
                s.step(s.params.dt_s).expect("stable");
            }
            s.evaluate_forces();
            let direct = (0..s.wire.segments()).map(|j| s.segment_tension(j)).fold(0.0_f64, f64::max);
            // Both are the segment element's tension (`element::segment`): the same number, exactly.
            assert_eq!(s.max_tension_n(), direct, "{name}");
        }
    }

    /// The observers' tight loops give the numbers of the plain loops they replace, bit for bit: the
    /// largest tension of any range of segments (lanes of maxima) against the fold of the segment pass's
    /// `|T t|` in order, the kinetic energy (terms by blocks, added in node order) against the sum node by
    /// node, and the energies (point forces by node) against the same sums with each node's point forces
    /// found by scanning all of them.
    #[test]
    fn observer_loops_equal_the_plain_loops_bitwise() {
        for (name, mut s) in option_cases() {
            // strings' forces at arbitrary nodes (two at one node, out of node order) as external forces
            s.set_point_forces(&[(7, [1.0, -2.0, 3.0]), (3, [0.5, 0.25, -4.0]), (7, [-0.125, 8.0, 1e-3])]);
            for _ in 0..50 {
                s.step(s.params.dt_s).expect("stable");
            }
            s.evaluate_forces();
            let n = s.wire.segments();
            for (a, b) in [(0, n), (0, 0), (3, 4), (1, 17), (5, n), (0, 9), (2, n - 1)] {
                let (f1, f2, f3) = (&s.fs[0], &s.fs[1], &s.fs[2]);
                let plain = (a + 1..b + 1)
                    .map(|j| f1[j] * f1[j] + f2[j] * f2[j] + f3[j] * f3[j])
                    .fold(0.0_f64, f64::max)
                    .sqrt();
                if s.wire.law != LawKind::Linear {
                    assert_eq!(s.max_tension_in(a..b).to_bits(), plain.to_bits(), "{name} {a}..{b}");
                }
            }
            let w = &s.wire;
            let mut e = 0.0;
            for i in 0..w.nodes() {
                e += w.mass[i] * (w.v[0][i] * w.v[0][i] + w.v[1][i] * w.v[1][i] + w.v[2][i] * w.v[2][i]);
            }
            assert_eq!(s.kinetic_energy_half_step().to_bits(), (0.5 * e).to_bits(), "{name}");
            let (half, zeta) = (0.5 * s.dt_prev, s.params.mass_damping_per_s);
            let mut kinetic = 0.0;
            for i in 0..w.nodes() {
                let mut v2 = 0.0;
                for k in 0..3 {
                    let a = s.node_force(k, i) * w.inv_mass[i] - zeta * w.v[k][i];
                    let vn = w.v[k][i] + half * w.free[i] * a;
                    v2 += vn * vn;
                }
                kinetic += 0.5 * w.mass[i] * v2;
            }
            // The elastic and potential energies as the loops formed them before their arrays were sliced
            // (`Wire::strain`, `Wire::position` per segment).
            let (g, q) = (s.loads.gravity_m_per_s2, s.loads.uniform_load_n_per_m);
            let (mut elastic, mut potential) = (0.0, 0.0);
            for i in 0..w.nodes() {
                potential += w.mass[i] * g * w.x[2][i];
            }
            for j in 0..w.segments() {
                let (ea, e) = (w.axial_stiffness_n[j], w.strain(j));
                let energy = match (w.law, &w.material) {
                    (LawKind::TwoMaterial, Some(m)) => m.energy_density(j, e, w.temperature_k[j]),
                    (LawKind::Linear, _) => Linear::energy_density(ea, e),
                    _ => TensionOnly::energy_density(ea, e),
                };
                elastic += energy * w.rest_length[j] * w.intact[j];
                let (a, b) = (w.position(j), w.position(j + 1));
                for k in 0..3 {
                    potential -= q[k] * w.reference_length[j] * 0.5 * (a[k] + b[k]);
                }
            }
            for ins in &w.insulators {
                elastic += ins.energy(w.position(ins.node));
                if let Some(arm) = &ins.crossarm {
                    elastic += arm.spring_energy(ins.pivot_m);
                }
            }
            let (d, energies) = (s.level_diagnostics(), s.level_energies());
            if w.insulators.iter().all(|i| i.crossarm.is_none()) {
                assert_eq!(d.kinetic_j.to_bits(), kinetic.to_bits(), "{name}");
            }
            assert_eq!(
                [d.elastic_j, d.potential_j].map(f64::to_bits),
                [elastic, potential].map(f64::to_bits),
                "{name}"
            );
            assert_eq!(
                [energies.kinetic_j, energies.elastic_j, energies.potential_j].map(f64::to_bits),
                [d.kinetic_j, d.elastic_j, d.potential_j].map(f64::to_bits),
                "{name}"
            );
        }
    }

    /// The three components at once ([`Explicit::node_force3`], the supports' forces) are the bits of
    /// [`Explicit::node_force`] per component, at every node of the option cases after 50 steps, with
    /// point forces on a support node (twice), an inner node and the last node.
    #[test]
    fn node_force3_is_node_force_per_component() {
        for (name, mut s) in option_cases() {
            let dt = s.params.dt_s;
            for _ in 0..50 {
                s.step(dt).unwrap();
            }
            s.evaluate_forces();
            let last = s.wire.nodes() - 1;
            s.external_force.extend([
                (0, [1.5, -2.25, 3.125]),
                (7, [1e-3, 2e4, -5.0]),
                (0, [-0.1, 0.3, 7.0]),
                (last, [2.0; 3]),
            ]);
            for i in 0..=last {
                let want = [0, 1, 2].map(|k| s.node_force(k, i).to_bits());
                assert_eq!(s.node_force3(i).map(f64::to_bits), want, "{name}: node {i}");
            }
        }
    }

    /// The kinetic energy's bounds contain the node-order sum and are `(8 n + 4) u` wide at most, on
    /// every option case after some steps (each copy this processor runs) and on speeds spread over 150
    /// orders of magnitude (the terms over 300), where the order of the additions matters most.
    #[test]
    fn kinetic_energy_bounds_contain_the_node_order_sum() {
        let check = |s: &Explicit, what: &str| {
            let (ke, (lo, hi)) = (s.kinetic_energy_half_step(), s.kinetic_energy_half_step_bounds());
            assert!(lo <= ke && ke <= hi, "{what}: {lo:e} <= {ke:e} <= {hi:e}");
            // `2 * 4 n u` and the rounding of the two products and of the sums' difference (`4 u`).
            let u = 0.5 * f64::EPSILON;
            let width = (8.0 * s.wire.nodes() as f64 + 4.0) * u;
            assert!(hi - lo <= width * ke, "{what}: [{lo:e}, {hi:e}] around {ke:e}");
        };
        for (name, mut s) in option_cases() {
            let dt = s.params.dt_s;
            for _ in 0..50 {
                let _ = s.step(dt);
            }
            // The sum from the speeds squared the smoothing loop kept is the sum from the velocities.
            assert_eq!(s.speed2_fresh, s.params.smoothing > 0.0 && s.ground.is_none(), "{name}");
            let mut from_v = s.clone();
            from_v.speed2_fresh = false;
            for isa in [Isa::Baseline, Isa::Avx2, Isa::Avx512].into_iter().filter(|&i| i <= detected_isa()) {
                s.isa = isa;
                from_v.isa = isa;
                let (a, b) = (s.kinetic_energy_half_step_bounds(), from_v.kinetic_energy_half_step_bounds());
                assert_eq!([a.0.to_bits(), a.1.to_bits()], [b.0.to_bits(), b.1.to_bits()], "{name} {isa:?}");
                check(&s, &format!("{name} {isa:?}"));
                // Spread the terms: every third node's speed far above the rest, masses uneven.
                // (Through `wire_mut`, as any change of the state: the speeds the step kept are stale.)
                let mut t = s.clone();
                let w = t.wire_mut();
                let n1 = w.nodes();
                for i in 0..n1 {
                    let scale = [1e75, 1.0, 1e-75][i % 3] * (1.0 + i as f64 / 7.0);
                    for k in 0..3 {
                        w.v[k][i] = scale * (0.3 + k as f64);
                    }
                    w.mass[i] *= 1.0 + (i % 5) as f64 * 0.37;
                }
                check(&t, &format!("{name} {isa:?} spread"));
                // A NaN speed: no bounds, the caller sums in node order.
                t.wire_mut().v[1][n1 / 2] = f64::NAN;
                let (lo, hi) = t.kinetic_energy_half_step_bounds();
                assert!(lo.is_nan() && hi.is_nan(), "{name} {isa:?}: NaN speed");
            }
        }
    }

    /// `speed2_key(s2) <= speed2_key(b2)` is `s2 <= b2` for every speed squared the loops can form (`+0`,
    /// subnormal, normal, `+inf`, NaN of either sign) and every bound `b2 >= 0`, at and one rounding either
    /// side of each bound.
    #[test]
    fn speed_keys_compare_like_the_speeds_squared() {
        let neg_nan = f64::from_bits(0xfff8_0000_0000_0000);
        assert!(neg_nan.is_nan() && neg_nan.is_sign_negative());
        let mut squares = vec![0.0, 5e-324, 1e-310, f64::MIN_POSITIVE, 1.0, 2.5e15, f64::MAX, f64::INFINITY];
        squares.extend([f64::NAN, neg_nan, -f64::NAN]);
        let bounds = [0.0, 5e-324, 1.0, 2.5e15, 1e14, f64::MAX, f64::INFINITY];
        for &b2 in &bounds {
            let mut near = vec![b2, b2.next_up(), b2.next_down().max(0.0)];
            near.extend(&squares);
            for s2 in near {
                assert_eq!(speed2_key(s2) <= speed2_key(b2), s2 <= b2, "{s2:e} against {b2:e}");
            }
        }
    }

    /// The step's speed check through the keys: a node at exactly the bound passes, one rounding above it
    /// fails with the speed named, a NaN of either sign fails as not finite (with and without smoothing,
    /// each copy this processor runs).
    #[test]
    fn step_flags_a_speed_above_the_bound_or_a_nan() {
        for smoothing in [0.0, 0.02] {
            for isa in [Isa::Baseline, Isa::Avx2, Isa::Avx512].into_iter().filter(|&i| i <= detected_isa()) {
                let mut base = Config::PlaneWeight.solver(40);
                base.isa = isa;
                base.params.smoothing = smoothing;
                base.loads.gravity_m_per_s2 = 0.0;
                base.params.max_speed_m_per_s = 3.0;
                // At rest and weightless on the straight chord: one node moving at `v` along x keeps it
                // through a step (no force), so its speed squared is `v * v` as the loops form it.
                let run = |v: f64| {
                    let mut s = base.clone();
                    s.wire.v[0][17] = v;
                    s.wire.v[0][16] = v;
                    s.wire.v[0][18] = v;
                    s.step(1e-9 * s.params.dt_s).map(|_| ())
                };
                let what = format!("smoothing {smoothing}, {isa:?}");
                assert!(run(3.0).is_ok(), "{what}: at the bound");
                let above = run(3.0_f64.next_up()).expect_err(&what);
                assert!(matches!(above.reason, InstabilityReason::SpeedLimit { .. }), "{what}: {above:?}");
                for nan in [f64::NAN, f64::from_bits(0xfff8_0000_0000_0000)] {
                    let e = run(nan).expect_err(&what);
                    assert!(matches!(e.reason, InstabilityReason::NonFinite), "{what}: {e:?}");
                }
            }
        }
    }

    /// The wide bounds of [`Explicit::kinetic_energy_quick_bounds`] contain the node-order sum after every
    /// step of the option cases (each copy this processor runs), and are given wherever the step keeps
    /// the largest speed (no ground; no strings); after `wire_mut`, or before a step, none.
    #[test]
    fn quick_kinetic_energy_bounds_contain_the_node_order_sum() {
        for (name, s0) in option_cases() {
            for isa in [Isa::Baseline, Isa::Avx2, Isa::Avx512].into_iter().filter(|&i| i <= detected_isa()) {
                let mut s = s0.clone();
                s.isa = isa;
                let (lo, hi) = s.kinetic_energy_quick_bounds();
                assert!(lo.is_nan() && hi.is_nan(), "{name}: before a step");
                let dt = s.params.dt_s;
                let (mut given, mut moving) = (0, 0);
                for _ in 0..200 {
                    if s.step(dt).is_err() {
                        break;
                    }
                    let (ke, (lo, hi)) = (s.kinetic_energy_half_step(), s.kinetic_energy_quick_bounds());
                    if s.ground.is_some() {
                        assert!(lo.is_nan() && hi.is_nan(), "{name} {isa:?}: with a ground");
                        continue;
                    }
                    assert!(lo <= ke && ke <= hi, "{name} {isa:?}: {lo:e} <= {ke:e} <= {hi:e}");
                    given += 1;
                    moving += usize::from(lo > 0.0);
                }
                assert!(s.ground.is_some() || (given == 200 && moving > 100), "{name} {isa:?}: {given}, {moving}");
                s.wire_mut();
                let (lo, hi) = s.kinetic_energy_quick_bounds();
                assert!(lo.is_nan() && hi.is_nan(), "{name}: after wire_mut");
            }
        }
        // Point forces from outside (a line's links) kick their nodes after the node loop: without
        // smoothing the loop's largest speed is then stale and no bounds are given; with smoothing (which
        // follows the kick) they are, and contain the sum.
        for smoothing in [0.0, 0.02] {
            let mut s = Config::PlaneWeight.solver(40);
            s.params.smoothing = smoothing;
            s.set_point_forces(&[(13, [0.0, 0.0, 5e3]), (27, [2e3, 0.0, 0.0])]);
            let dt = s.params.dt_s;
            for _ in 0..50 {
                s.step(dt).unwrap();
                let (ke, (lo, hi)) = (s.kinetic_energy_half_step(), s.kinetic_energy_quick_bounds());
                if smoothing > 0.0 {
                    assert!(
                        lo <= ke && ke <= hi && lo > 0.0,
                        "smoothed, with point forces: {lo:e} <= {ke:e} <= {hi:e}"
                    );
                } else {
                    assert!(lo.is_nan() && hi.is_nan(), "point forces without smoothing");
                }
            }
        }
    }

    #[test]
    fn wide_copies_are_bitwise_identical_to_the_baseline() {
        let widest = detected_isa();
        if widest == Isa::Baseline {
            eprintln!("no AVX2 here (or OHL_NO_AVX2 set): only the baseline copy runs, nothing to compare");
            return;
        }
        if widest == Isa::Avx2 {
            eprintln!("no AVX-512 here (or OHL_NO_AVX512 set): the AVX2 copy is compared alone");
        }
        // The option cases (`option_cases`), 400 steps with shortened steps, in every copy this processor
        // runs, each against the baseline copy; the largest tension of the observers too.
        for isa in [Isa::Avx2, Isa::Avx512].into_iter().filter(|&i| i <= widest) {
            for (name, mut wide) in option_cases() {
                wide.isa = isa;
                let mut baseline = wide.clone();
                baseline.isa = Isa::Baseline;
                let dt = wide.params.dt_s;
                for step in 0..400 {
                    let h = if step % 7 == 3 { 0.37 * dt } else { dt };
                    let (a, b) = (wide.step(h).is_ok(), baseline.step(h).is_ok());
                    assert_eq!(a, b, "{isa:?} {name}: verdicts differ at step {step}");
                }
                assert_bitwise(&wide, &baseline, &format!("{isa:?} {name}"));
                wide.evaluate_forces();
                baseline.evaluate_forces();
                let n = wide.wire.segments();
                assert_eq!(wide.max_tension_n().to_bits(), baseline.max_tension_n().to_bits(), "{isa:?} {name}");
                for r in [0..n, 3..n - 2, 1..9] {
                    let (a, b) = (wide.max_tension_in(r.clone()), baseline.max_tension_in(r.clone()));
                    assert_eq!(a.to_bits(), b.to_bits(), "{isa:?} {name} {r:?}");
                }
                let (a, b) = (wide.kinetic_energy_half_step(), baseline.kinetic_energy_half_step());
                assert_eq!(a.to_bits(), b.to_bits(), "{isa:?} {name}: kinetic energy");
            }
        }
    }
}
