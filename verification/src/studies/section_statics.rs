//! Study `section_statics`: exact statics of a line section on suspension strings (issue "Verification 1-2").
//!
//! # What is compared
//!
//! The library builds a section of spans on suspension insulator strings (`ohl::wire::section::build`:
//! every span strung by the horizontal tension `H0` with the strings plumb, Drake conductor, strings of
//! 3.5 m, 100 kg, `EA_i` 5e7 N) and finds its static equilibrium on `N` segments per span, either by
//! Newton's method on the scheme's own discrete equations (`ohl::statics::solve`) or, where Newton refuses
//! (a broken segment), by running the explicit scheme to rest with mass damping (dynamic relaxation: the
//! damping force `-m zeta v` vanishes at rest, so it changes the path and not the equilibrium). The
//! answer is compared with [`crate::exact_section`], written without any `ohl` solver code: per span the
//! closed-form elastic catenary (Irvine)
//!
//! ```text
//! x(s) = H s/EA + (H/w) [asinh(V/H) - asinh((V - w s)/H)]
//! z(s) = -(V s - w s^2/2)/EA - (H/w) [sqrt(1 + (V/H)^2) - sqrt(1 + ((V - w s)/H)^2)]
//! ```
//!
//! closed between the clamps, each string an elastic tension link `P = Q + l (1 + T/k) (sin theta,
//! -cos theta)` with its mass at the clamp, every clamp in force balance, a broken span two pieces hanging
//! plumb from their clamps; solved by its own damped Newton iteration to 1e-9 N and 1e-11 m. Coordinates:
//! the reference is planar (`x` along the line, `z` up); the library is 3-D with `x2` along the line, `x3`
//! up and `x1` across, which stays zero here (it enters every distance below).
//!
//! Like is compared with like: the exact reference is given the library's own unstretched span lengths
//! (`Layout::unstretched_length_m`), so the difference is the discretisation of the chain alone. The
//! stringing is a definition (an `O(1)` computation of a length, not a discretisation); it is checked
//! separately by stringing the same supports with the reference's own `exact_section::string_section`.
//!
//! # Cases and quantities
//!
//! * (a) level: three 400 m spans, pivots at 30 m, dead-end points at the plumb clamp height, `H0` = 28 kN.
//!   The discrete spans are congruent, so by symmetry their discrete horizontal tensions are equal and
//!   each clamp carries exactly half of each adjacent span's weight: the library's clamps and string
//!   forces are exact to rounding on every grid (checked as such, at the Newton tolerance over the clamp's
//!   stiffness), and only the shape inside the spans carries the `O(ds^2)` error.
//! * (b) inclined: spans 350/420/380/300 m, pivots at 45, 30, 75 m, dead-ends at 20 and 50 m, span 2 iced
//!   (linear density x 1.5: `Wire::add_linear_density`, `w x 1.5` in the reference).
//! * (c) broken: case (a) with the middle span broken at its middle (`Wire::break_segment`, reference
//!   `broken: Some(0.5)`), settled by the explicit scheme (Newton refuses broken segments): from the strung
//!   state with the two pieces placed plumb below their clamps, Courant 0.5, mass damping 0.55 /s (twice
//!   the pendulum frequency of a 200 m piece), until the kinetic energy is below `1e-20` of its peak or
//!   has stagnated at the rounding floor of a damped run (`settle`). Neither the start,
//!   the step nor the damping changes the equilibrium; why not Courant 0.9 is told at `BROKEN_COURANT`.
//!   `N` is odd here so that the broken segment is centred on the span's middle: each piece then carries
//!   exactly half the span's weight (the broken segment's mass sits half on each end node), as in the
//!   reference. The discrete hanging piece is exact relative to its clamp (its tension is the weight
//!   below, sampled at segment midpoints, and the stretch integrand is linear), so its end inherits the
//!   clamp's error.
//! * (d) case (b) on elastic crossarms (springs 5e4 N/m along and across the line): the library's Newton
//!   solves for the pivots too (`ohl::statics::pivots`); the reference's pivot rests at `Q0 + (T sin
//!   theta / k_a, 0)`. The pivot positions are a further quantity, of order 2 like the clamps.
//!
//! Newton runs with the library's default options. With strings of a millimetre or less (limit (i)) it
//! stops on its iteration limit: the library's rounding floor omits the strings' stiffness (a finding,
//! see the report's discussion); its last iterate is then accepted only if the residual meets the
//! tolerance on every node but the clamps and lies within 4 times the strings' rounding floor at them.
//!
//! Quantities: the mid-span material point `s = L/2` (node `N/2`, or the mean of the two middle nodes for
//! odd `N`) against `SectionSolution::point`, which measures the sag without the sampling error of a
//! nodal maximum (the nodal sag against `SectionSolution::sag` is tabulated too); every node against the
//! material point it discretises; the clamps; the force of each string on its pivot; for (c) the lower ends
//! of the hanging pieces (node at `s = L/2 - ds/2` against the plumb piece `z = z_c - (s + w (l s -
//! s^2/2)/EA)`, which is `SectionSolution::broken_piece_ends` at `s = l`).
//!
//! # Tolerances and why
//!
//! * Observed order `2 +- 0.1`, least squares over the three finest grids: the lumped chain is a
//!   second-order discretisation of the string (central differences on the staggered grid), and the
//!   insulator strings are exact point links, so the clamp and the string force inherit `O(ds^2)` from the
//!   spans. Grids `N` = 10, 20, 40, 80 per span (full), 10, 20, 40 (CI, under a second); `N + 1` for (c).
//!   `h` is the largest segment length. The errors at the finest grid are 1e-5 to 1e-3 m, far above the
//!   solvers' tolerances (Newton: 1e-10 of the nodal loads; the settled run: 1e-8 m or less).
//! * Case (a), clamps and string forces exact by symmetry: below 10 times the Newton residual over the
//!   clamp's softest stiffness (the string's pendulum stiffness `T/l_i`) plus 1e-10 m, and below 10 times
//!   the residual plus 1e-6 N (the reference's own tolerances are 1e-11 m and 1e-9 N).
//! * Stringing: the library's span lengths against `exact_section::string_section`, 1e-9 m (both are
//!   solved to rounding).
//! * Newton against the settled explicit run (cases b and d, every grid): `1e-8` of the clamps' (and the
//!   pivots') largest displacement from the strung state; the run stops when the kinetic energy is below `1e-20` of its peak, which
//!   leaves amplitudes of about `1e-10` of the motion.
//! * Limit (i): strings of length `l_i` and mass 1e-6 kg against dead-ends at the pivots: the clamps lie
//!   `l_i (1 + T/EA_i)` from the pivots, and a span's shape responds to a shift `u` of its ends by at most
//!   `u (1 + 3 l/(8 f))` (rigid translation plus the sag change `df/dl = 3 l/(16 f)` of a parabola for
//!   each end moving along the line), so the gap must lie below that bound and be linear in `l_i`
//!   (two lengths 1e-3 and 1e-6 m: gap ratio 1000 within 1 %).
//! * Limit (ii): unequal level spans strung at one `H0`: the continuous strings are plumb; the discrete
//!   spans' horizontal tensions differ from `H0` by `O(ds^2)`, each by its own amount, so the swing falls at
//!   order `2 +- 0.1`.
//! * Limit (iii): the ruling-span tension after icing all spans (`exact_section::ruling_span_tension`)
//!   against the exact section. The method assumes strings that equalise `H` exactly and a parabolic
//!   change of state with `T = H`; its error is stated, and checked against the spread of the exact `H`
//!   plus the neglected terms' order `(w l_max/H)^2 / 24`.
//!
//! # Output
//!
//! Tables `section_statics_errors`, `_orders`, `_newton_vs_explicit`, `_limits`, `_ruling` (CSV), figures
//! `section_statics_convergence` (errors against the segment length, slope-2 line; the swing of limit
//! (ii)) and `section_statics_shape` (library nodes against the exact section for (b) and (c), and a
//! close-up of a swung string in (c)), PNG and SVG.

use crate::convergence::{ls_order, pair_orders};
use crate::exact_section as ex;
use crate::report::{Budget, StudyReport, Table, sci};
use ohl::element::tension::LawKind;
use ohl::scheme::{Explicit, Loads, StepParams};
use ohl::statics::{StaticError, StaticOptions, solve as solve_static};
use ohl::wire::insulator::clamp_stable_step_s;
use ohl::wire::section::{self, CrossarmSpec, Layout, Section, Span, Stringing, Support};
use ohl::wire::{Conductor, Wire};
use ohl_app::plot::{Chart, Series, Style};
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

/// gravitational acceleration \[m/s^2\]
const G: f64 = 9.81;
/// Drake: axial stiffness `EA` \[N\]
const EA: f64 = 2.9e7;
/// Drake: linear density \[kg/m\]
const RHO: f64 = 1.628;
/// stringing tension `H0` \[N\] (20 % of the rated strength 140 kN)
const H0: f64 = 28_000.0;
/// suspension string: length \[m\], mass \[kg\], axial stiffness \[N\]
const STRING: Strings = Strings { length_m: 3.5, mass_kg: 100.0, stiffness_n: 5.0e7 };
/// ice: factor on the linear density of the iced span(s) \[-\]
const ICE_FACTOR: f64 = 1.5;
/// pivot height of the level sections \[m\]
const PIVOT_Z: f64 = 30.0;
/// Courant number of the explicit runs of the intact sections \[-\]
const COURANT: f64 = 0.9;
/// Courant number of the broken section's run \[-\]: at 0.9 (and 0.8, and 0.6 on 41 segments per span)
/// without smoothing the run gains energy and blows up within seconds, while segments of the outer
/// spans go slack and snap taut again as the unbalanced clamps swing out (a unilateral, tension-only
/// spring near the step limit); at 0.5 it relaxes cleanly on every grid. The step does not change the
/// equilibrium.
const BROKEN_COURANT: f64 = 0.5;
/// the settled explicit run stops when the kinetic energy is below this fraction of its peak \[-\]
const KE_RATIO: f64 = 1e-20;

/// The strings of a section.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Strings {
    length_m: f64,
    mass_kg: f64,
    stiffness_n: f64,
}

/// The cases of item 1, and the sections of the limits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case {
    /// (a) three level 400 m spans
    Level,
    /// (b) four inclined spans, span 2 iced
    Inclined,
    /// (c) case (a) with the middle span broken at its middle
    Broken,
    /// (d) case (b) on elastic crossarms
    Flexible,
    /// limit (ii): four level spans of unequal length, no ice
    LevelUnequal,
}

impl Case {
    /// the cases of item 1
    pub const ITEM1: [Case; 4] = [Case::Level, Case::Inclined, Case::Broken, Case::Flexible];

    /// short name
    pub fn name(self) -> &'static str {
        match self {
            Case::Level => "(a) level",
            Case::Inclined => "(b) inclined + ice",
            Case::Broken => "(c) broken",
            Case::Flexible => "(d) (b) on elastic crossarms",
            Case::LevelUnequal => "level unequal spans",
        }
    }

    /// Dead-end points and pivots `[x, z]` \[m\], in order along the line.
    fn towers(self) -> Vec<[f64; 2]> {
        match self {
            Case::Level | Case::Broken => {
                // Dead-ends at the plumb clamp height: the string carries w S + m g, S the strung length.
                let s = ex::unstretched_length_for_tension(EA, RHO * G, [0.0, 0.0], [400.0, 0.0], H0)
                    .expect("a level Drake span strings at 28 kN");
                let t = RHO * G * s + STRING.mass_kg * G;
                let zc = PIVOT_Z - STRING.length_m * (1.0 + t / STRING.stiffness_n);
                vec![[0.0, zc], [400.0, PIVOT_Z], [800.0, PIVOT_Z], [1200.0, zc]]
            }
            Case::Inclined | Case::Flexible => {
                vec![[0.0, 20.0], [350.0, 45.0], [770.0, 30.0], [1150.0, 75.0], [1450.0, 50.0]]
            }
            Case::LevelUnequal => {
                let zc = PIVOT_Z - STRING.length_m;
                vec![[0.0, zc], [350.0, PIVOT_Z], [770.0, PIVOT_Z], [1150.0, PIVOT_Z], [1450.0, zc]]
            }
        }
    }

    /// the iced span
    fn iced(self) -> Option<usize> {
        matches!(self, Case::Inclined | Case::Flexible).then_some(2)
    }

    /// the crossarms of the suspension supports: elastic in case (d), else rigid
    fn crossarm(self) -> Option<CrossarmSpec> {
        (self == Case::Flexible).then_some(ARM)
    }

    /// the broken span
    fn broken(self) -> Option<usize> {
        (self == Case::Broken).then_some(1)
    }

    /// segments per span on grid `n`: odd for the broken case (the broken segment centred on mid-span)
    fn segments(self, n: usize) -> usize {
        if self == Case::Broken { n + 1 } else { n }
    }

    /// mass damping of the settled explicit run \[1/s\]
    fn damping_per_s(self) -> f64 {
        match self {
            Case::Broken => BROKEN_DAMPING,
            _ => INTACT_DAMPING,
        }
    }
}

/// Elastic crossarms of case (d): springs of 5e4 N/m along and across the line (the longitudinal
/// stiffness of a suspension tower's crossarm tip is of order 1e5 to 1e6 N/m; a softer one makes the
/// pivots move by centimetres here), 200 kg, and critical damping `2 sqrt(k M)` for the settled run (the
/// damping vanishes at rest and does not change the equilibrium).
const ARM: CrossarmSpec =
    CrossarmSpec { longitudinal_n_per_m: 5.0e4, transverse_n_per_m: 5.0e4, mass_kg: 200.0, damping_n_s_per_m: 6325.0 };

/// Mass damping for the intact sections \[1/s\]: twice the lowest in-plane frequency, about `pi/l
/// sqrt(H/rho)` = 1 rad/s for 400 m of Drake at 28 kN (near-critical for the slowest mode).
const INTACT_DAMPING: f64 = 2.0;
/// Mass damping for the broken section \[1/s\]: twice the pendulum frequency of a 200 m piece hanging from
/// its clamp, `1.2 sqrt(g/l)` = 0.27 rad/s (the first zero of `J0` over 2).
const BROKEN_DAMPING: f64 = 0.55;

fn conductor() -> Conductor {
    Conductor { axial_stiffness_n: EA, internal_friction_n_s: 0.0, law: LawKind::TensionOnly }
}

/// The library's section of `case` on `n` segments per span, strung at `H0`; `strings: None` puts
/// dead-ends at the pivots.
fn ohl_section(case: Case, n: usize, strings: Option<Strings>) -> Section {
    let towers = case.towers();
    let last = towers.len() - 1;
    let supports = towers
        .iter()
        .enumerate()
        .map(|(i, &[x, z])| match strings {
            Some(s) if i > 0 && i < last => Support::Suspension {
                pivot_m: [0.0, x, z],
                length_m: s.length_m,
                mass_kg: s.mass_kg,
                stiffness_n: s.stiffness_n,
                crossarm: case.crossarm(),
            },
            _ => Support::DeadEnd { point_m: [0.0, x, z] },
        })
        .collect();
    let span = Span {
        conductor: conductor(),
        linear_density_kg_per_m: RHO,
        segments: case.segments(n),
        stringing: Stringing::HorizontalTension(H0),
    };
    Section { supports, spans: vec![span; last], gravity_m_per_s2: G }
}

/// The reference's supports of `case`.
fn exact_supports(case: Case, strings: Option<Strings>) -> Vec<ex::Support> {
    let towers = case.towers();
    let last = towers.len() - 1;
    towers
        .iter()
        .enumerate()
        .map(|(i, &p)| match strings {
            Some(s) if i > 0 && i < last => ex::Support::Suspension {
                pivot: p,
                length_m: s.length_m,
                mass_kg: s.mass_kg,
                stiffness_n: s.stiffness_n,
                crossarm_n_per_m: case.crossarm().map_or(f64::INFINITY, |a| a.longitudinal_n_per_m),
            },
            _ => ex::Support::DeadEnd { point: p },
        })
        .collect()
}

/// The reference section of `case` with the given unstretched span lengths \[m\], ice and break applied.
fn exact_section(case: Case, strings: Option<Strings>, lengths: &[f64]) -> ex::Section {
    let spans = lengths
        .iter()
        .enumerate()
        .map(|(k, &l)| ex::Span {
            ea_n: EA,
            w_n_per_m: RHO * G * if case.iced() == Some(k) { ICE_FACTOR } else { 1.0 },
            length_m: l,
            broken: (case.broken() == Some(k)).then_some(0.5),
        })
        .collect();
    ex::Section { supports: exact_supports(case, strings), spans, g_m_per_s2: G }
}

/// Loads: gravity only.
fn loads() -> Loads {
    crate::setup::loads(G, [0.0; 3], None)
}

/// Stable step \[s\]: Courant `courant` on the shortest segment (bare conductor's wave speed: ice only lowers
/// it) and the same fraction of each clamp's Gershgorin limit (`ohl::wire::insulator::clamp_stable_step_s`).
fn time_step(w: &Wire, courant: f64) -> f64 {
    let c = (EA / RHO).sqrt();
    let shortest = w.rest_length.iter().copied().fold(f64::INFINITY, f64::min);
    let mut dt = courant * shortest / c;
    for ins in &w.insulators {
        let i = ins.node;
        let k = |j: usize| w.axial_stiffness_n[j] / w.rest_length[j];
        let clamp = clamp_stable_step_s(w.mass[i], ins.stiffness_n / ins.length_m, k(i - 1), k(i));
        dt = dt.min(courant * clamp);
    }
    dt
}

/// The library's strung section of `case` on grid `n` with ice and break applied, as an explicit solver
/// at rest with mass damping `zeta` \[1/s\].
fn library_strung(case: Case, n: usize, strings: Option<Strings>, zeta: f64) -> Result<(Explicit, Layout), String> {
    let (mut wire, layout) = section::build(&ohl_section(case, n, strings)).map_err(|e| e.to_string())?;
    if let Some(k) = case.iced()
        && !wire.add_linear_density(layout.segments(k), (ICE_FACTOR - 1.0) * RHO)
    {
        return Err("ice refused".into());
    }
    if let Some(k) = case.broken() {
        let nk = layout.first_node[k + 1] - layout.first_node[k];
        debug_assert!(nk % 2 == 1);
        let (a, b) = (layout.first_node[k], layout.first_node[k + 1]);
        let j = a + nk / 2;
        wire.break_segment(j);
        // Start of the relaxation: each piece plumb below its clamp at its unstretched spacing (the fall
        // of a released piece from the span's shape is a violent transient that the relaxation does not
        // need; the equilibrium does not depend on the start).
        let ds = layout.unstretched_length_m[k] / nk as f64;
        for i in a + 1..b {
            let (clamp, s) = if i <= j { (a, (i - a) as f64 * ds) } else { (b, (b - i) as f64 * ds) };
            let (y, z) = (wire.x[1][clamp], wire.x[2][clamp]);
            wire.x[1][i] = y;
            wire.x[2][i] = z - s;
        }
    }
    let dt = time_step(&wire, if case.broken().is_some() { BROKEN_COURANT } else { COURANT });
    let params = StepParams { dt_s: dt, smoothing: 0.0, mass_damping_per_s: zeta, max_speed_m_per_s: 1.0e3 };
    Ok((Explicit::new(wire, loads(), params), layout))
}

/// Rounding floor of the strings' forces at their clamps \[N\]: a clamp at distance `X` from the origin is
/// known to `X eps`, which the string's axial stiffness `EA_i/l_i` turns into a force. The library's
/// `ohl::statics::rounding_floor_n` counts only the conductor segments' `EA/l0`; with strings of a
/// millimetre this floor is far above the library's default tolerance.
fn string_floor_n(s: &Explicit) -> f64 {
    let w = s.wire();
    w.insulators
        .iter()
        .map(|i| {
            i.stiffness_n / i.length_m * w.position(i.node).iter().map(|c| c * c).sum::<f64>().sqrt() * f64::EPSILON
        })
        .fold(0.0, f64::max)
}

/// How the library's equilibrium was found.
#[derive(Clone, Debug, Default)]
pub struct Cost {
    /// Newton iterations (0 for a settled run)
    pub iterations: usize,
    /// explicit steps (0 for Newton)
    pub steps: u64,
    /// simulated time of the settled run \[s\]
    pub simulated_s: f64,
    /// wall time \[s\]
    pub wall_s: f64,
    /// final largest nodal residual over the free nodes \[N\]
    pub residual_n: f64,
    /// the Newton tolerance \[N\] (0 for a settled run)
    pub tolerance_n: f64,
    /// peak and final kinetic energy of a settled run \[J\]
    pub kinetic_j: (f64, f64),
    /// Newton stopped on its iteration limit with the residual at the strings' rounding floor
    pub stalled: bool,
}

/// Largest net force on a free node \[N\].
fn max_residual(s: &mut Explicit) -> f64 {
    let n1 = s.wire().nodes();
    let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
    s.net_force(&mut f);
    (0..n1)
        .filter(|&i| s.wire().free[i] > 0.0)
        .flat_map(|i| (0..3).map(move |k| (k, i)))
        .fold(0.0, |m, (k, i)| f64::max(m, f[k][i].abs()))
}

/// Newton's method from the strung state, with the library's default options. Where it stops on its
/// iteration limit, its last iterate is accepted only if the residual meets the tolerance on every node
/// but the clamps and lies within 4 times [`string_floor_n`] at the clamps (rounding of the strings'
/// forces, which no iteration can remove); `Cost::stalled` records it.
fn newton(s: &mut Explicit) -> Result<Cost, String> {
    let t0 = Instant::now();
    match solve_static(s, &StaticOptions::default()) {
        Ok(rep) => Ok(Cost {
            iterations: rep.iterations,
            wall_s: t0.elapsed().as_secs_f64(),
            residual_n: rep.residual_n,
            tolerance_n: rep.tolerance_n,
            ..Default::default()
        }),
        Err(StaticError::NotConverged { iterations, residual_n, tolerance_n }) => {
            let n1 = s.wire().nodes();
            let mut f = [vec![0.0; n1], vec![0.0; n1], vec![0.0; n1]];
            s.net_force(&mut f);
            let w = s.wire();
            let clamp = |i: usize| w.insulators.iter().any(|ins| ins.node == i);
            let (mut off, mut at): (f64, f64) = (0.0, 0.0);
            for i in (0..n1).filter(|&i| w.free[i] > 0.0) {
                let m = (0..3).map(|k| f[k][i].abs()).fold(0.0, f64::max);
                if clamp(i) { at = at.max(m) } else { off = off.max(m) }
            }
            let floor = string_floor_n(s);
            if off <= tolerance_n && at <= 4.0 * floor {
                Ok(Cost {
                    iterations,
                    wall_s: t0.elapsed().as_secs_f64(),
                    residual_n,
                    tolerance_n,
                    stalled: true,
                    ..Default::default()
                })
            } else {
                Err(format!(
                    "Newton: {iterations} iterations, residual {residual_n:.3e} N > {tolerance_n:.3e} N (off the \
                     clamps {off:.3e} N, at the clamps {at:.3e} N, strings' rounding floor {floor:.3e} N)"
                ))
            }
        }
        Err(e) => Err(e.to_string()),
    }
}

/// Run the explicit scheme until the half-step kinetic energy is below [`KE_RATIO`] of its peak (checked
/// every 16 steps), or until it has stagnated at the rounding floor: no halving of its lowest value for
/// `20/zeta` \[s\] of simulated time, in which a damped mode's energy `~ exp(-zeta t)` falls by `e^20`
/// (rounding kicks every node by `(EA/l0) X eps` at random, which keeps up a kinetic energy of order
/// `n R^2 dt / (4 zeta m)`: 1e-18 to 1e-15 J here). Fails after `max_time_s` \[s\].
fn settle(s: &mut Explicit, max_time_s: f64) -> Result<Cost, String> {
    let t0 = Instant::now();
    let dt = s.params().dt_s;
    let patience = 20.0 / s.params().mass_damping_per_s;
    let (mut peak, mut low, mut low_t): (f64, f64, f64) = (0.0, f64::INFINITY, 0.0);
    loop {
        for _ in 0..16 {
            s.step(dt).map_err(|e| e.to_string())?;
        }
        let ke = s.kinetic_energy_half_step();
        peak = peak.max(ke);
        if ke < 0.5 * low {
            (low, low_t) = (ke, s.time_s());
        }
        if peak > 0.0 && (ke <= KE_RATIO * peak || s.time_s() - low_t > patience) {
            let residual_n = max_residual(s);
            return Ok(Cost {
                iterations: 0,
                steps: s.steps(),
                simulated_s: s.time_s(),
                wall_s: t0.elapsed().as_secs_f64(),
                residual_n,
                tolerance_n: 0.0,
                kinetic_j: (peak, ke),
                stalled: false,
            });
        }
        if s.time_s() > max_time_s {
            return Err(format!("not settled after {:.0} s: kinetic energy {ke:.3e} J, peak {peak:.3e} J", s.time_s()));
        }
    }
}

/// Distance between a library node `[x1, x2, x3]` and a reference point `[x, z]` (`x1` counts) \[m\].
fn gap(p: [f64; 3], q: [f64; 2]) -> f64 {
    (p[0] * p[0] + (p[1] - q[0]).powi(2) + (p[2] - q[1]).powi(2)).sqrt()
}

/// Point of a piece of unstretched length `l` \[m\] hanging plumb from `clamp`, at unstretched distance `s`
/// \[m\] from the clamp: `z = z_c - (s + w (l s - s^2/2)/EA)` (tension `w (l - s)`, Hooke's law); at `s = l`
/// this is `SectionSolution::broken_piece_ends`.
fn hanging_point(clamp: [f64; 2], l: f64, s: f64, w: f64) -> [f64; 2] {
    [clamp[0], clamp[1] - (s + w * (l * s - 0.5 * s * s) / EA)]
}

/// Errors of one grid against the reference (largest over spans, nodes or strings).
#[derive(Clone, Debug, Default)]
pub struct Errors {
    /// mid-span material point \[m\]
    pub mid_m: f64,
    /// every node against its material point \[m\]
    pub nodal_m: f64,
    /// clamps \[m\]
    pub clamp_m: f64,
    /// force of each string on its pivot \[N\]
    pub force_n: f64,
    /// string tension \[N\]
    pub tension_n: f64,
    /// string swing \[rad\]
    pub swing_rad: f64,
    /// horizontal tension of the intact spans \[N\]
    pub h_n: f64,
    /// nodal sag (largest vertical distance chord-node) against the exact sag \[m\]
    pub sag_m: f64,
    /// lower ends of the broken span's pieces \[m\] (NaN where no span is broken)
    pub piece_end_m: f64,
    /// crossarm pivots \[m\] (zero on rigid crossarms: both sides leave them where they are)
    pub pivot_m: f64,
}

/// Horizontal tension of segment `j` of the library's state \[N\]: `T t . e2`.
fn segment_h(s: &Explicit, j: usize) -> f64 {
    let w = s.wire();
    let (a, b) = (w.position(j), w.position(j + 1));
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    s.segment_tension(j) * d[1] / len
}

/// Compare the library's state with the reference solution.
fn compare(s: &Explicit, layout: &Layout, sec: &ex::Section, sol: &ex::SectionSolution) -> Errors {
    let w = s.wire();
    let mut e = Errors { piece_end_m: f64::NAN, ..Default::default() };
    for (k, span) in sec.spans.iter().enumerate() {
        let (a, b) = (layout.first_node[k], layout.first_node[k + 1]);
        let nk = b - a;
        let ds = span.length_m / nk as f64;
        if span.broken.is_some() {
            // Two pieces of length L/2 plumb below the reference's clamps; the broken segment joins nodes
            // a + nk/2 and a + nk/2 + 1.
            let half = 0.5 * span.length_m;
            let (cl, cr) = (sol.spans[k].left_clamp, sol.spans[k].right_clamp);
            let j = a + nk / 2;
            for i in a..=b {
                let p = if i <= j {
                    hanging_point(cl, half, (i - a) as f64 * ds, span.w_n_per_m)
                } else {
                    hanging_point(cr, half, (b - i) as f64 * ds, span.w_n_per_m)
                };
                e.nodal_m = e.nodal_m.max(gap(w.position(i), p));
            }
            let ends = sol.broken_piece_ends(sec, k).expect("a broken span has piece ends");
            debug_assert!((hanging_point(cl, half, half, span.w_n_per_m)[1] - ends[0][1]).abs() < 1e-9);
            let el = hanging_point(cl, half, half - 0.5 * ds, span.w_n_per_m);
            let er = hanging_point(cr, half, half - 0.5 * ds, span.w_n_per_m);
            e.piece_end_m = gap(w.position(j), el).max(gap(w.position(j + 1), er));
            continue;
        }
        for i in a..=b {
            let p = sol.point(sec, k, (i - a) as f64 * ds);
            e.nodal_m = e.nodal_m.max(gap(w.position(i), p));
        }
        let (m0, m1) = (a + nk / 2, a + nk.div_ceil(2));
        let (p, q) = (w.position(m0), w.position(m1));
        let mid = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])];
        e.mid_m = e.mid_m.max(gap(mid, sol.point(sec, k, 0.5 * span.length_m)));
        // Nodal sag: the largest vertical distance of a node below the chord of the span's end nodes.
        let (pa, pb) = (w.position(a), w.position(b));
        let sag = (a..=b)
            .map(|i| {
                let r = w.position(i);
                pa[2] + (pb[2] - pa[2]) * (r[1] - pa[1]) / (pb[1] - pa[1]) - r[2]
            })
            .fold(f64::NEG_INFINITY, f64::max);
        e.sag_m = e.sag_m.max((sag - sol.sag(sec, k)).abs());
        e.h_n = e.h_n.max((segment_h(s, a) - sol.spans[k].h_n).abs());
    }
    for (i, st) in sol.supports.iter().enumerate() {
        let node = layout.support_node[i];
        let Some(ins) = w.insulators.iter().find(|ins| ins.node == node) else { continue };
        let c = w.position(node);
        e.clamp_m = e.clamp_m.max(gap(c, st.clamp));
        let f = ins.force_on_clamp(c).map(|v| -v);
        e.force_n = e.force_n.max(gap(f, st.force_on_support_n));
        e.tension_n = e.tension_n.max((ins.tension(c) - st.insulator_tension_n).abs());
        e.swing_rad = e.swing_rad.max((ins.swing_rad(c, layout.along[i])[0] - st.swing_rad).abs());
        e.pivot_m = e.pivot_m.max(gap(ins.pivot_m, st.pivot));
    }
    e
}

/// One grid of one case of item 1.
#[derive(Clone, Debug)]
pub struct GridResult {
    /// case
    pub case: Case,
    /// segments per span
    pub segments: usize,
    /// largest segment length `h` \[m\]
    pub h_m: f64,
    /// errors against the reference
    pub errors: Errors,
    /// how the equilibrium was found
    pub cost: Cost,
    /// largest |library stringing length - reference stringing length| \[m\]
    pub stringing_gap_m: f64,
}

/// The library's equilibrium of `case` on grid `n` (Newton, or settled for the broken case), the reference
/// with the library's unstretched lengths, and the errors.
fn grid(case: Case, n: usize) -> Result<(GridResult, Explicit, Layout, ex::Section, ex::SectionSolution), String> {
    let (mut s, layout) = library_strung(case, n, Some(STRING), case.damping_per_s())?;
    let cost = if case.broken().is_some() { settle(&mut s, 2000.0) } else { newton(&mut s) }
        .map_err(|e| format!("{} N = {n}: {e}", case.name()))?;
    let sec = exact_section(case, Some(STRING), &layout.unstretched_length_m);
    let sol = ex::solve(&sec).map_err(|e| format!("{}: reference: {e}", case.name()))?;
    // The stringing itself, independently: the reference strings the same supports at H0.
    let strung = ex::string_section(exact_supports(case, Some(STRING)), EA, RHO * G, H0, G)?;
    let stringing_gap_m =
        strung.spans.iter().zip(&layout.unstretched_length_m).map(|(a, b)| (a.length_m - b).abs()).fold(0.0, f64::max);
    let h_m = layout
        .unstretched_length_m
        .iter()
        .enumerate()
        .map(|(k, l)| l / (layout.first_node[k + 1] - layout.first_node[k]) as f64)
        .fold(0.0, f64::max);
    let errors = compare(&s, &layout, &sec, &sol);
    let r = GridResult { case, segments: case.segments(n), h_m, errors, cost, stringing_gap_m };
    Ok((r, s, layout, sec, sol))
}

/// The grids of a budget (segments per span; `N + 1` for the broken case).
pub fn grids(budget: Budget) -> Vec<usize> {
    match budget {
        Budget::Coarse => vec![10, 20, 40],
        Budget::Full => vec![10, 20, 40, 80],
    }
}

/// A quantity of item 1: name, unit, how to read it from the errors, whether its order is a check (the
/// others are tabulated), and its panel in the convergence figure.
struct Quantity {
    name: &'static str,
    unit: &'static str,
    get: fn(&Errors) -> f64,
    checked: bool,
    panel: Option<usize>,
}

const QUANTITIES: [Quantity; 8] = [
    Quantity { name: "mid-span point", unit: "m", get: |e| e.mid_m, checked: true, panel: Some(0) },
    Quantity { name: "clamp position", unit: "m", get: |e| e.clamp_m, checked: true, panel: Some(1) },
    Quantity { name: "insulator force", unit: "N", get: |e| e.force_n, checked: true, panel: Some(2) },
    Quantity { name: "piece end", unit: "m", get: |e| e.piece_end_m, checked: true, panel: None },
    Quantity { name: "pivot position", unit: "m", get: |e| e.pivot_m, checked: true, panel: None },
    Quantity { name: "max nodal", unit: "m", get: |e| e.nodal_m, checked: false, panel: None },
    Quantity { name: "span H", unit: "N", get: |e| e.h_n, checked: false, panel: None },
    Quantity { name: "string swing", unit: "rad", get: |e| e.swing_rad, checked: false, panel: None },
];

/// Whether a quantity carries an `O(ds^2)` error in a case: case (a)'s clamps and string forces are exact
/// by symmetry (checked at rounding instead), and only case (c) has piece ends.
fn has_order(case: Case, quantity: &str) -> bool {
    match quantity {
        "clamp position" | "insulator force" | "string swing" => case != Case::Level,
        "piece end" => case == Case::Broken,
        "pivot position" => case == Case::Flexible,
        _ => true,
    }
}

/// Newton against the settled explicit run on one grid of case (b) or (d).
struct Compared {
    /// the case
    case: Case,
    /// segments per span
    n: usize,
    /// largest clamp gap \[m\]
    gap_m: f64,
    /// largest clamp displacement from the strung state \[m\]
    moved_m: f64,
    /// largest nodal gap \[m\]
    nodal_gap_m: f64,
    /// largest pivot gap \[m\] (zero on rigid crossarms)
    pivot_gap_m: f64,
    /// largest pivot displacement from rest \[m\]
    pivot_moved_m: f64,
    /// Newton's cost
    newton: Cost,
    /// the settled run's cost
    explicit: Cost,
    /// its step \[s\]
    dt_s: f64,
}

/// Run the study.
pub fn run(budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let ns = grids(budget);
    let jobs: Vec<(Case, usize)> = Case::ITEM1.iter().flat_map(|&c| ns.iter().map(move |&n| (c, n))).collect();
    let solved: Vec<_> = jobs.par_iter().map(|&(c, n)| grid(c, n)).collect::<Result<Vec<_>, _>>()?;
    let results: Vec<GridResult> = solved.iter().map(|g| g.0.clone()).collect();
    let mut rep = StudyReport {
        title: "Exact statics of a line section on suspension strings".into(),
        summary: "Sections of Drake spans on 3.5 m, 100 kg strings strung at H0 = 28 kN are solved by the library \
                  (Newton on the discrete equations; the broken case by the explicit scheme run to rest with mass \
                  damping) on N = 10 ... 80 segments per span (CI: 10 ... 40) and compared with the independent exact section \
                  (`exact_section`: closed-form elastic catenaries, elastic strings, own Newton), given the \
                  library's own unstretched span lengths. Cases: (a) three level 400 m spans, (b) four inclined \
                  spans with ice (w x 1.5) on span 2, (c) case (a) with its middle span broken at mid-span, (d) case (b) on \
                  elastic crossarms (5e4 N/m; the pivots are unknowns of Newton). \
                  Limits: vanishing strings against dead-ends, plumb strings of a level section strung at one \
                  H0, and the ruling-span approximation after icing all spans."
            .into(),
        ..Default::default()
    };

    // ---- item 1: errors per grid ----
    let mut table = Table::new(
        "section_statics_errors",
        "Library vs exact section, per grid (largest over spans / nodes / strings)",
        &[
            "case",
            "N per span",
            "h [m]",
            "mid-span point [m]",
            "max nodal [m]",
            "nodal sag [m]",
            "clamp [m]",
            "string force [N]",
            "string tension [N]",
            "swing [rad]",
            "span H [N]",
            "piece end [m]",
            "solver",
        ],
    );
    for r in &results {
        let e = &r.errors;
        let solver = if r.cost.steps > 0 {
            format!(
                "settled: {} steps, {:.0} s simulated, {:.2} s wall",
                r.cost.steps, r.cost.simulated_s, r.cost.wall_s
            )
        } else {
            format!("Newton: {} iterations, {:.3} s", r.cost.iterations, r.cost.wall_s)
        };
        table.row(vec![
            r.case.name().into(),
            r.segments.to_string(),
            format!("{:.3}", r.h_m),
            sci(e.mid_m),
            sci(e.nodal_m),
            sci(e.sag_m),
            sci(e.clamp_m),
            sci(e.force_n),
            sci(e.tension_n),
            sci(e.swing_rad),
            sci(e.h_n),
            if e.piece_end_m.is_nan() { "-".into() } else { sci(e.piece_end_m) },
            solver,
        ]);
    }
    let mut otable = Table::new(
        "section_statics_orders",
        "Observed orders: least squares over the three finest grids (a check where marked), and each consecutive pair",
        &["case", "quantity", "finest error", "order (LS, 3 finest)", "pair orders", "checked"],
    );
    let mut panels: Vec<Chart> = QUANTITIES
        .iter()
        .filter(|q| q.panel.is_some())
        .map(|q| Chart {
            title: format!("{}: library vs exact", q.name),
            x_label: "largest segment length h [m]".into(),
            y_label: format!("{} error [{}]", q.name, q.unit),
            log_x: true,
            log_y: true,
            ..Default::default()
        })
        .collect();
    for (ci, &case) in Case::ITEM1.iter().enumerate() {
        let rs: Vec<&GridResult> = results.iter().filter(|r| r.case == case).collect();
        let h: Vec<f64> = rs.iter().map(|r| r.h_m).collect();
        for q in QUANTITIES.iter().filter(|q| has_order(case, q.name)) {
            let (name, unit) = (q.name, q.unit);
            let e: Vec<f64> = rs.iter().map(|r| (q.get)(&r.errors)).collect();
            let k = e.len();
            let p = ls_order(&h[k - 3..], &e[k - 3..]);
            let pairs: Vec<String> = pair_orders(&h, &e).iter().map(|p| format!("{p:.3}")).collect();
            otable.row(vec![
                case.name().into(),
                name.into(),
                format!("{} {unit}", sci(e[k - 1])),
                format!("{p:.3}"),
                pairs.join(" / "),
                if q.checked { "2 ± 0.1".into() } else { "-".into() },
            ]);
            if q.checked {
                rep.check(
                    format!("{}: order of the {name} error", case.name()),
                    "2 ± 0.1",
                    format!("{p:.3} (finest {} {unit})", sci(e[k - 1])),
                    (p - 2.0).abs() < 0.1,
                );
            }
            if let Some(i) = q.panel {
                panels[i].series.push(Series::new(
                    case.name(),
                    h.iter().copied().zip(e.iter().copied()).collect(),
                    Style::LineMarkers,
                    ci,
                ));
            }
        }
    }
    // Case (a): clamps and string forces exact by symmetry. Bound: the Newton tolerance over the clamp's
    // smallest stiffness (the string's pendulum stiffness T/l_i), plus the reference's own tolerances
    // (1e-9 N, 1e-11 m) — a few 1e-9 m and 1e-6 N at most.
    {
        let rs: Vec<&GridResult> = results.iter().filter(|r| r.case == Case::Level).collect();
        let worst_c = rs.iter().map(|r| r.errors.clamp_m).fold(0.0, f64::max);
        let worst_f = rs.iter().map(|r| r.errors.force_n).fold(0.0, f64::max);
        let worst_mid = rs.iter().map(|r| r.errors.mid_m).fold(f64::INFINITY, f64::min);
        let tol_n = rs.iter().map(|r| r.cost.residual_n).fold(0.0, f64::max);
        let t = 2.0 * RHO * G * 400.0 + STRING.mass_kg * G;
        let bound_m = 10.0 * (tol_n.max(1e-9) / (t / STRING.length_m)) + 1e-10;
        let bound_n = 10.0 * tol_n.max(1e-9) + 1e-6;
        rep.check(
            "(a) level: clamps exact by symmetry",
            format!("< {} m (10 x Newton residual / (T/l_i)), vs mid-span errors >= {}", sci(bound_m), sci(worst_mid)),
            format!("{} m", sci(worst_c)),
            worst_c < bound_m,
        );
        rep.check(
            "(a) level: string forces exact by symmetry",
            format!("< {} N", sci(bound_n)),
            format!("{} N", sci(worst_f)),
            worst_f < bound_n,
        );
    }
    // Stringing: library lengths vs the reference's own stringing.
    {
        let worst = results.iter().map(|r| r.stringing_gap_m).fold(0.0, f64::max);
        rep.check(
            "stringing: library span lengths vs exact_section::string_section",
            "< 1e-9 m (both solved to rounding: bisection, closure 1e-11 m)",
            format!("{} m", sci(worst)),
            worst < 1e-9,
        );
    }
    let h_all: Vec<f64> = results.iter().map(|r| r.h_m).collect();
    let (h_lo, h_hi) = (h_all.iter().copied().fold(f64::INFINITY, f64::min), h_all.iter().copied().fold(0.0, f64::max));
    for p in &mut panels {
        let top = p.series.iter().filter_map(|s| s.points.iter().map(|q| q.1).reduce(f64::max)).fold(0.0, f64::max);
        p.series.push(Series::new(
            "slope 2",
            vec![(h_hi, 2.0 * top), (h_lo, 2.0 * top * (h_lo / h_hi).powi(2))],
            Style::Dashed,
            7,
        ));
    }

    // ---- Newton vs settled explicit, cases (b) and (d), every grid ----
    let mut ntable = Table::new(
        "section_statics_newton_vs_explicit",
        "Cases (b) and (d): Newton vs the explicit scheme run to rest from the strung state (Courant 0.9, mass \
         damping 2 /s, crossarms of (d) critically damped, until the kinetic energy is below 1e-20 of its peak or \
         stagnates at rounding); (d) also compares the pivots",
        &[
            "case",
            "N per span",
            "clamp gap [m]",
            "largest clamp displacement [m]",
            "relative",
            "max nodal gap [m]",
            "Newton",
            "explicit",
            "final / peak kinetic energy",
            "pivot gap [m] / largest pivot displacement [m]",
        ],
    );
    let cmp_jobs: Vec<(Case, usize)> =
        [Case::Inclined, Case::Flexible].iter().flat_map(|&c| ns.iter().map(move |&n| (c, n))).collect();
    let compared: Vec<Compared> = cmp_jobs
        .par_iter()
        .map(|&(case, n)| {
            let (mut nw, layout) = library_strung(case, n, Some(STRING), INTACT_DAMPING)?;
            let strung: Vec<[f64; 3]> = layout.support_node.iter().map(|&i| nw.wire().position(i)).collect();
            let mut dr = nw.clone();
            let newton = newton(&mut nw)?;
            let explicit = settle(&mut dr, 2000.0)?;
            let (mut gap_m, mut moved_m): (f64, f64) = (0.0, 0.0);
            for (k, &i) in layout.support_node.iter().enumerate() {
                gap_m = gap_m.max(dist(nw.wire().position(i), dr.wire().position(i)));
                moved_m = moved_m.max(dist(nw.wire().position(i), strung[k]));
            }
            let nodal_gap_m =
                (0..dr.wire().nodes()).map(|i| dist(nw.wire().position(i), dr.wire().position(i))).fold(0.0, f64::max);
            let (mut pivot_gap_m, mut pivot_moved_m): (f64, f64) = (0.0, 0.0);
            for (a, b) in nw.wire().insulators.iter().zip(&dr.wire().insulators) {
                pivot_gap_m = pivot_gap_m.max(dist(a.pivot_m, b.pivot_m));
                pivot_moved_m = pivot_moved_m.max(dist(a.pivot_displacement_m(), [0.0; 3]));
            }
            Ok::<_, String>(Compared {
                case,
                n,
                gap_m,
                moved_m,
                nodal_gap_m,
                pivot_gap_m,
                pivot_moved_m,
                newton,
                explicit,
                dt_s: dr.params().dt_s,
            })
        })
        .collect::<Result<_, _>>()?;
    for c in &compared {
        ntable.row(vec![
            c.case.name().into(),
            c.n.to_string(),
            sci(c.gap_m),
            format!("{:.6}", c.moved_m),
            sci(c.gap_m / c.moved_m),
            sci(c.nodal_gap_m),
            format!(
                "{} iterations, {:.4} s, residual {} N",
                c.newton.iterations,
                c.newton.wall_s,
                sci(c.newton.residual_n)
            ),
            format!(
                "{} steps (dt {} s), {:.1} s simulated, {:.3} s wall, residual {} N",
                c.explicit.steps,
                sci(c.dt_s),
                c.explicit.simulated_s,
                c.explicit.wall_s,
                sci(c.explicit.residual_n)
            ),
            sci(c.explicit.kinetic_j.1 / c.explicit.kinetic_j.0),
            if c.case.crossarm().is_some() {
                format!("{} / {:.6}", sci(c.pivot_gap_m), c.pivot_moved_m)
            } else {
                "-".into()
            },
        ]);
    }
    let flexible: Vec<&Compared> = compared.iter().filter(|c| c.case == Case::Flexible).collect();
    let pivot_worst = flexible.iter().map(|c| c.pivot_gap_m / c.pivot_moved_m).fold(0.0, f64::max);
    let pivot_moved = flexible.iter().map(|c| c.pivot_moved_m).fold(0.0, f64::max);
    let arm_iterations: Vec<String> = flexible.iter().map(|c| c.newton.iterations.to_string()).collect();
    rep.check(
        "(d) Newton vs settled explicit: crossarm pivots",
        "< 1e-8 of the largest pivot displacement, every grid",
        format!("worst {} of {pivot_moved:.5} m; Newton iterations {}", sci(pivot_worst), arm_iterations.join(", ")),
        pivot_worst < 1e-8,
    );
    let worst =
        compared.iter().max_by(|a, b| (a.gap_m / a.moved_m).total_cmp(&(b.gap_m / b.moved_m))).ok_or("no grid")?;
    let (case_cmp, n_cmp, gap_c, moved, rel) =
        (worst.case, worst.n, worst.gap_m, worst.moved_m, worst.gap_m / worst.moved_m);
    let coarse = &compared[0];
    rep.check(
        "(b), (d) Newton vs settled explicit: clamps",
        "< 1e-8 of the largest clamp displacement, every grid",
        format!(
            "worst {} at {} N = {n_cmp} ({} m of {moved:.4} m); (b) N = {}: {} steps, {:.3} s wall vs Newton {:.4} s",
            sci(rel),
            case_cmp.name(),
            sci(gap_c),
            coarse.n,
            coarse.explicit.steps,
            coarse.explicit.wall_s,
            coarse.newton.wall_s
        ),
        rel < 1e-8,
    );

    // ---- limit (i): vanishing strings against dead-ends at the pivots (case b, N = 20) ----
    let n_lim = 20;
    let mut ltable = Table::new(
        "section_statics_limits",
        "Limits: (i) vanishing strings vs dead-ends at the pivots (case b, N = 20); (ii) swing of a level section strung at one H0",
        &["limit", "parameter", "value", "bound / expectation"],
    );
    let (mut rigid, _) = library_strung(Case::Inclined, n_lim, None, 0.0)?;
    newton(&mut rigid)?;
    let rigid_pos: Vec<[f64; 3]> = (0..rigid.wire().nodes()).map(|i| rigid.wire().position(i)).collect();
    // Amplification of an end shift: 1 + 3 l/(8 f) with the reference's sags of the rigid section.
    let rigid_sec = exact_section(
        Case::Inclined,
        None,
        &section::build(&ohl_section(Case::Inclined, n_lim, None)).map_err(|e| e.to_string())?.1.unstretched_length_m,
    );
    let rigid_sol = ex::solve(&rigid_sec)?;
    let towers = Case::Inclined.towers();
    let amp = (0..rigid_sec.spans.len())
        .map(|k| 1.0 + 3.0 * (towers[k + 1][0] - towers[k][0]) / (8.0 * rigid_sol.sag(&rigid_sec, k)))
        .fold(0.0, f64::max);
    let mut limit_gaps = vec![];
    let mut limit_costs: Vec<Cost> = vec![];
    for li in [1e-3, 1e-6] {
        let tiny = Strings { length_m: li, mass_kg: 1e-6, stiffness_n: STRING.stiffness_n };
        let (mut s, _) = library_strung(Case::Inclined, n_lim, Some(tiny), 0.0)?;
        let cost = newton(&mut s)?;
        let g = (0..s.wire().nodes()).map(|i| dist(s.wire().position(i), rigid_pos[i])).fold(0.0, f64::max);
        let t_max = s.wire().insulators.iter().map(|ins| ins.tension(s.wire().position(ins.node))).fold(0.0, f64::max);
        let bound = amp * li * (1.0 + t_max / tiny.stiffness_n);
        ltable.row(vec![
            "(i) strings -> 0".into(),
            format!("l_i = {li:e} m, m_i = 1e-6 kg"),
            format!(
                "max nodal gap {} m (Newton: {} iterations, residual {} N{})",
                sci(g),
                cost.iterations,
                sci(cost.residual_n),
                if cost.stalled { ", stopped at the iteration limit on the strings' rounding floor" } else { "" }
            ),
            format!("< (1 + 3 l/(8 f)) l_i (1 + T/EA_i) = {} m", sci(bound)),
        ]);
        rep.check(
            format!("(i) strings of {li:e} m vs dead-ends"),
            format!("max nodal gap < {} m", sci(bound)),
            format!("{} m", sci(g)),
            g < bound,
        );
        limit_gaps.push(g);
        limit_costs.push(cost);
    }
    let ratio = limit_gaps[0] / limit_gaps[1];
    ltable.row(vec![
        "(i) linearity".into(),
        "gap(1e-3) / gap(1e-6)".into(),
        format!("{ratio:.2}"),
        "1000 ± 1 %".into(),
    ]);
    rep.check(
        "(i) gap linear in the string length",
        "gap(1e-3 m)/gap(1e-6 m) = 1000 ± 1 %",
        format!("{ratio:.2}"),
        (ratio / 1000.0 - 1.0).abs() < 0.01,
    );

    // ---- limit (ii): level section of unequal spans strung at one H0: plumb strings ----
    let swings: Vec<(usize, f64, f64, f64)> = ns
        .par_iter()
        .map(|&n| {
            let (mut s, layout) = library_strung(Case::LevelUnequal, n, Some(STRING), 0.0)?;
            newton(&mut s)?;
            let w = s.wire();
            let mut sw: f64 = 0.0;
            for ins in &w.insulators {
                let k = layout.support_node.iter().position(|&i| i == ins.node).expect("a clamp is a support node");
                sw = sw.max(ins.swing_rad(w.position(ins.node), layout.along[k])[0].abs());
            }
            let dh = (0..layout.unstretched_length_m.len())
                .map(|k| (segment_h(&s, layout.first_node[k]) - H0).abs())
                .fold(0.0, f64::max);
            let h = layout.unstretched_length_m.iter().map(|l| l / n as f64).fold(0.0, f64::max);
            Ok::<_, String>((n, h, sw, dh))
        })
        .collect::<Result<_, _>>()?;
    let exact_level =
        ex::solve(&ex::string_section(exact_supports(Case::LevelUnequal, Some(STRING)), EA, RHO * G, H0, G)?)?;
    let exact_swing = exact_level.supports.iter().map(|s| s.swing_rad.abs()).fold(0.0, f64::max);
    for &(n, _, sw, dh) in &swings {
        ltable.row(vec![
            "(ii) plumb strings".into(),
            format!("N = {n}"),
            format!("max |swing| {} rad, max |H - H0| {} N", sci(sw), sci(dh)),
            format!("-> 0 at order 2 (exact: {} rad)", sci(exact_swing)),
        ]);
    }
    let hs: Vec<f64> = swings.iter().map(|r| r.1).collect();
    let sws: Vec<f64> = swings.iter().map(|r| r.2).collect();
    let k = sws.len();
    let p_sw = ls_order(&hs[k - 3..], &sws[k - 3..]);
    rep.check(
        "(ii) level, strung at one H0: swing -> 0",
        "order 2 ± 0.1 (exact swing < 1e-10 rad)",
        format!("order {p_sw:.3}, finest {} rad; exact {} rad", sci(sws[k - 1]), sci(exact_swing)),
        (p_sw - 2.0).abs() < 0.1 && exact_swing < 1e-10,
    );
    let swing_panel = Chart {
        title: "(ii) level section strung at one H0: swing".into(),
        x_label: "largest segment length h [m]".into(),
        y_label: "largest string swing [rad]".into(),
        series: vec![
            Series::new("library", hs.iter().copied().zip(sws.iter().copied()).collect(), Style::LineMarkers, 0),
            Series::new(
                "slope 2",
                vec![(hs[0], 2.0 * sws[0]), (hs[k - 1], 2.0 * sws[0] * (hs[k - 1] / hs[0]).powi(2))],
                Style::Dashed,
                7,
            ),
        ],
        log_x: true,
        log_y: true,
        ..Default::default()
    };
    panels.push(swing_panel);

    // ---- limit (iii): ruling span after icing all spans ----
    let mut rtable = Table::new(
        "section_statics_ruling",
        "Ruling-span tension after ice (w x 1.5) on all spans vs the exact section",
        &["section", "span", "l [m]", "exact H [N]", "ruling H [N]", "(ruling - exact) / exact"],
    );
    for case in [Case::LevelUnequal, Case::Inclined] {
        let label = if case == Case::Inclined { "inclined spans of (b)" } else { "level spans 350/420/380/300 m" };
        let mut sec = ex::string_section(exact_supports(case, Some(STRING)), EA, RHO * G, H0, G)?;
        for s in &mut sec.spans {
            s.w_n_per_m = RHO * G * ICE_FACTOR;
        }
        let sol = ex::solve(&sec)?;
        let towers = case.towers();
        let ls: Vec<f64> = towers.windows(2).map(|p| p[1][0] - p[0][0]).collect();
        let ruling = ex::ruling_span_tension(&ls, EA, RHO * G, H0, RHO * G * ICE_FACTOR)?;
        let hs: Vec<f64> = sol.spans.iter().map(|s| s.h_n).collect();
        let (lo, hi) = hs.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), h| (a.min(*h), b.max(*h)));
        let mut worst: f64 = 0.0;
        for (k, &hk) in hs.iter().enumerate() {
            let e = ruling.h_n / hk - 1.0;
            worst = worst.max(e.abs());
            rtable.row(vec![
                format!("{label} (L_r = {:.1} m)", ruling.length_m),
                k.to_string(),
                format!("{:.0}", ls[k]),
                format!("{hk:.3}"),
                format!("{:.3}", ruling.h_n),
                format!("{e:+.3e}"),
            ]);
        }
        let lmax = ls.iter().copied().fold(0.0, f64::max);
        let neglected = (RHO * G * ICE_FACTOR * lmax / ruling.h_n).powi(2) / 24.0;
        let spread = (hi - lo) / lo;
        let tol = spread + neglected;
        rep.check(
            format!("(iii) ruling span, {label}"),
            format!("|H_r/H_k - 1| <= exact spread {} + (w l_max/H)^2/24 {}", sci(spread), sci(neglected)),
            format!("{} (largest over spans)", sci(worst)),
            worst <= tol,
        );
    }

    // ---- figures ----
    rep.figure(
        &panels,
        2,
        (640, 460),
        "section_statics: exact statics of ACSR Drake sections on suspension strings (EA = 2.9e7 N, 1.628 kg/m)",
        dir,
        "section_statics_convergence",
    )?;
    let mut shape = vec![];
    for case in [Case::Inclined, Case::Broken] {
        let idx = solved
            .iter()
            .position(|g| g.0.case == case && g.0.segments == case.segments(ns[0]))
            .ok_or("coarsest grid missing")?;
        let (_, s, layout, sec, sol) = &solved[idx];
        shape.push(shape_chart(case, s, layout, sec, sol, None));
    }
    // A close-up of the broken section's left clamp on the second grid: the string swung away from the break.
    let idx = solved
        .iter()
        .position(|g| g.0.case == Case::Broken && g.0.segments == Case::Broken.segments(ns[1]))
        .ok_or("second grid missing")?;
    let (_, s, layout, sec, sol) = &solved[idx];
    let c = sol.supports[1].clamp;
    let window = ([c[0] - 25.0, c[0] + 10.0], [c[1] - 22.0, PIVOT_Z + 2.0]);
    shape.push(shape_chart(Case::Broken, s, layout, sec, sol, Some(window)));
    rep.figure(
        &shape,
        1,
        (1100, 460),
        "section_statics: exact statics of ACSR Drake sections on suspension strings (EA = 2.9e7 N, 1.628 kg/m)",
        dir,
        "section_statics_shape",
    )?;

    rep.tables.push(table);
    rep.tables.push(otable);
    rep.tables.push(ntable);
    rep.tables.push(ltable);
    rep.tables.push(rtable);
    let fine = |case: Case| results.iter().rfind(|r| r.case == case).map(|r| r.errors.clone());
    let (ea, eb, ec) = (fine(Case::Level), fine(Case::Inclined), fine(Case::Broken));
    let (ea, eb, ec) = (ea.unwrap_or_default(), eb.unwrap_or_default(), ec.unwrap_or_default());
    let stall = &limit_costs[0];
    rep.discussion = format!(
        "**Agreement.** The library's section converges to the exact one at order 2 in every quantity, with no \
         offset: on the finest grid the mid-span points are off by {} m (a), {} m (b) and {} m (c), the clamps by \
         {} m (b) and {} m (c), the string forces by {} N (b) and {} N (c), and the pairwise orders approach \
         2.000 from above. The library's stringing agrees with the reference's own stringing to {} m, so giving \
         the reference the library's unstretched lengths hides nothing. In case (a) the discrete spans are \
         congruent, so the library's clamps and string forces are exact on every grid ({} m, {} N: the \
         reference's rounding); only the shape inside the spans carries the O(ds^2) error. The nodal sag (largest \
         vertical node-chord distance) is tabulated but not fitted: where the maximum falls between nodes its \
         sampling error is O(ds^2) with an erratic constant (case (b)).\n\n\
         **Newton vs explicit.** On case (b) the settled explicit run and Newton agree to {} of the clamps' \
         displacement or better on every grid (worst N = {}: {} m); on N = {} the explicit run took {} steps \
         ({:.1} s simulated, {:.3} s wall) against Newton's {} iterations ({:.4} s).\n\n\
         **Findings on the library.** (1) `ohl::statics::solve` with its default options does not converge with \
         short strings: its rounding floor (`rounding_floor_n`) counts the conductor segments' EA/l0 but not the \
         strings' EA_i/l_i, so with 1 mm strings the default tolerance {} N lies below the rounding of the clamp \
         forces; it runs to its {} iteration limit and reports `NotConverged` at {} N although its iterate is the \
         equilibrium (off the clamps the residual meets the tolerance, and the gap to the rigid section is linear \
         in l_i to 0.1 %). The study accepts such an iterate only under that condition. (2) The explicit scheme \
         without smoothing is unstable after a conductor break next to suspension strings at Courant 0.9 (and \
         0.8; 0.6 on 41 segments per span; at 0.9 also with dead-ends on 41 segments per span): as the unbalanced \
         clamps swing out, segments of the outer spans go slack and snap taut, the total energy grows by orders of \
         magnitude and the speed bound stops the run within seconds. The library's default smoothing b = 0.02 \
         removed it in every case tried; this study relaxes (c) at Courant 0.5 from pieces placed plumb (the \
         step and the start do not change the equilibrium).\n\n\
         **Ruling span.** After icing all spans (w x 1.5) the ruling-span tension differs from the exact span \
         tensions by up to a few 1e-3 (table): the strings do not equalise H (the exact spread is of the same \
         size), and the change-of-state equation is parabolic with T = H and uses horizontal span lengths, so it \
         is worst on the short, steep span of the inclined section.",
        sci(ea.mid_m),
        sci(eb.mid_m),
        sci(ec.mid_m),
        sci(eb.clamp_m),
        sci(ec.clamp_m),
        sci(eb.force_n),
        sci(ec.force_n),
        sci(results.iter().map(|r| r.stringing_gap_m).fold(0.0, f64::max)),
        sci(ea.clamp_m),
        sci(ea.force_n),
        sci(rel),
        n_cmp,
        sci(gap_c),
        coarse.n,
        coarse.explicit.steps,
        coarse.explicit.simulated_s,
        coarse.explicit.wall_s,
        coarse.newton.iterations,
        coarse.newton.wall_s,
        sci(stall.tolerance_n),
        stall.iterations,
        sci(stall.residual_n),
    );
    Ok(rep)
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The section's shape: library nodes (markers) against the exact catenaries and hanging pieces, with the
/// strings; `window` (`[x range], [z range]` \[m\]) makes a close-up.
fn shape_chart(
    case: Case,
    s: &Explicit,
    layout: &Layout,
    sec: &ex::Section,
    sol: &ex::SectionSolution,
    window: Option<([f64; 2], [f64; 2])>,
) -> Chart {
    let keep = |p: &(f64, f64)| window.is_none_or(|(x, z)| p.0 >= x[0] && p.0 <= x[1] && p.1 >= z[0] && p.1 <= z[1]);
    let w = s.wire();
    let mut series = vec![];
    for (k, span) in sec.spans.iter().enumerate() {
        let label = if k == 0 { "exact section" } else { "" };
        let dense = 2000;
        if span.broken.is_some() {
            let half = 0.5 * span.length_m;
            for (i, clamp) in [sol.spans[k].left_clamp, sol.spans[k].right_clamp].into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = (0..=dense)
                    .map(|j| hanging_point(clamp, half, half * j as f64 / dense as f64, span.w_n_per_m))
                    .map(|p| (p[0], p[1]))
                    .filter(keep)
                    .collect();
                series.push(Series::new(if i == 0 { label } else { "" }, pts, Style::Line, 0));
            }
        } else {
            let pts: Vec<(f64, f64)> = (0..=dense)
                .map(|i| sol.point(sec, k, span.length_m * i as f64 / dense as f64))
                .map(|p| (p[0], p[1]))
                .filter(keep)
                .collect();
            series.push(Series::new(label, pts, Style::Line, 0));
        }
    }
    let mut first = true;
    for (i, st) in sol.supports.iter().enumerate() {
        if let ex::Support::Suspension { pivot, .. } = sec.supports[i] {
            let label = if first { "exact strings (pivot to clamp)" } else { "" };
            first = false;
            let pts: Vec<(f64, f64)> =
                [(pivot[0], pivot[1]), (st.clamp[0], st.clamp[1])].into_iter().filter(keep).collect();
            series.push(Series::new(label, pts, Style::Line, 2));
        }
    }
    let nodes: Vec<(f64, f64)> = (0..w.nodes()).map(|i| (w.x[1][i], w.x[2][i])).filter(keep).collect();
    series.push(Series::new(format!("library nodes, N = {} per span", layout.first_node[1]), nodes, Style::Markers, 1));
    let title = match window {
        None => format!("{}: section shape", case.name()),
        Some(_) => format!("{}: close-up of the left clamp of the broken span", case.name()),
    };
    Chart {
        title,
        x_label: "x2, along the line [m]".into(),
        y_label: "x3, height [m]".into(),
        series,
        x_range: window.map(|(x, _)| (x[0], x[1])),
        y_range: window.map(|(_, z)| (z[0], z[1])),
        ..Default::default()
    }
}
