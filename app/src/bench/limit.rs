//! The compute limit of the explicit kernel on the machine `ohl bench` runs on: the throughput
//! [node-steps/s] at which the busiest execution unit would be saturated, from the operations one
//! node-step performs ([`budget`], counted from the source) and the cost of each operation on this core
//! ([`super::Primitives`], measured in the kernel's instruction set):
//!
//! ```text
//! cycles per node-step  c = max( (mul + cmp) c_mul,  add c_add,  div c_div + sqrt c_sqrt,
//!                                loads c_load,  stores c_store )
//! limit = clock / c,     fraction of the limit = measured node-steps/s / limit
//! ```
//!
//! `c_mul`, `c_add`, `c_div`, `c_sqrt` [cycles per double] are measured throughputs (independent
//! operations, data in L1); comparisons and `max` are taken on the multiply pipes, as AMD family 19h
//! executes them (the Software Optimization Guide for family 19h; LLVM's Znver4 scheduling model).
//! Loads and stores are not measured: a core of AMD family 17h-19h or Intel since Haswell issues two
//! vector loads and one vector store per cycle, so `c_load = 1 / (2 w)`, `c_store = 1 / w` for `w`
//! doubles per vector of the instruction set (4 for AVX2 and for AVX-512 on Zen 4, which splits a 512-bit
//! access in two; 2 for the SSE2 baseline). Everything outside the core (L2, L3, memory bandwidth,
//! latency chains, loop overhead) is what the fraction measures the kernel's distance by: the limit is
//! the core's, the same at every `N`.
//!
//! The counts (per node-step, one segment and one node; for the kernel of `src/scheme/explicit.rs`,
//! `segment_pass_body` and `kick_drift`, and the element `src/element/segment.rs` with the wind laws of
//! `src/element/aero.rs`), tabulated and derived in `figures/bench/README.md` ("Compute limit on this
//! processor"):
//!
//! | config | mul + cmp | add | div | sqrt | loads | stores |
//! |---|---|---|---|---|---|---|
//! | plane_weight | 32 + 3 | 27 | 1 | 1 | 30 | 12 |
//! | wind_3d | 64 + 4 | 44 | 2 | 2 | 42 | 16 |
//! | kv_smoothing_3d | 68 + 4 | 54 | 2 | 2 | 67 | 22 |
//!
//! The two-material law's pass is scalar with the law's branches, and the section and line workloads
//! add scalar loops over links: no limit of this kind is given for them ([`budget`] is `None`).

use super::Primitives;
use super::workload::Workload;
use ohl::scheme::configs::Config;

/// Operations of one node-step of a kernel configuration, by execution unit (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OpBudget {
    /// multiplications and comparisons (the multiply pipes)
    pub mul_pipe: u32,
    /// additions and subtractions (the add pipes)
    pub add: u32,
    /// divisions (the divide / square-root unit)
    pub div: u32,
    /// square roots (the divide / square-root unit)
    pub sqrt: u32,
    /// doubles loaded
    pub loads: u32,
    /// doubles stored
    pub stores: u32,
}

/// The operations of one node-step of `w` (module doc), or `None` where no vector limit applies.
pub fn budget(w: Workload) -> Option<OpBudget> {
    match w {
        Workload::Kernel(Config::PlaneWeight) => {
            Some(OpBudget { mul_pipe: 35, add: 27, div: 1, sqrt: 1, loads: 30, stores: 12 })
        }
        Workload::Kernel(Config::Wind3d) => {
            Some(OpBudget { mul_pipe: 68, add: 44, div: 2, sqrt: 2, loads: 42, stores: 16 })
        }
        Workload::Kernel(Config::ViscousSmoothed) => {
            Some(OpBudget { mul_pipe: 72, add: 54, div: 2, sqrt: 2, loads: 67, stores: 22 })
        }
        _ => None,
    }
}

/// The busiest unit of a node-step and its cycles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// cycles per node-step of the busiest unit
    pub cycles: f64,
    /// which unit: "multiply pipes", "add pipes", "divider", "loads" or "stores"
    pub unit: &'static str,
    /// the limit [node-steps/s]: the clock over `cycles`
    pub node_steps_per_s: f64,
}

/// Doubles per vector of the kernel's instruction set (`"avx512"`, `"avx2"` or the baseline's SSE2).
fn doubles_per_access(isa: &str) -> f64 {
    match isa {
        // Zen 4 executes a 512-bit load or store as two 256-bit ones.
        "avx512" | "avx2" => 4.0,
        _ => 2.0,
    }
}

/// The limit of `b` on a core with the measured primitives `p` (module doc).
pub fn limit(b: &OpBudget, p: &Primitives) -> Limit {
    let w = doubles_per_access(p.isa);
    let units = [
        ("multiply pipes", b.mul_pipe as f64 * p.mul_cycles),
        ("add pipes", b.add as f64 * p.add_cycles),
        ("divider", b.div as f64 * p.div_cycles + b.sqrt as f64 * p.sqrt_cycles),
        ("loads", b.loads as f64 / (2.0 * w)),
        ("stores", b.stores as f64 / w),
    ];
    let (unit, cycles) = units.into_iter().fold(("", 0.0), |a, u| if u.1 > a.1 { u } else { a });
    Limit { cycles, unit, node_steps_per_s: p.clock_hz / cycles }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Zen 4 derivation of `figures/bench/README.md`: 8 doubles per cycle on each pair of pipes
    /// (0.125 cycles per double), a division 1.25 and a square root 2.25 cycles per double, 3.656 GHz:
    /// plane_weight 8.36e8 (multiply pipes, 4.38 cycles), wind_3d 4.30e8 (8.5), kv_smoothing_3d 4.06e8
    /// (9.0).
    #[test]
    fn reproduces_the_zen4_limits_of_the_write_up() {
        let p = Primitives {
            clock_hz: 3.656e9,
            isa: "avx512",
            sqrt_cycles: 2.25,
            div_cycles: 1.25,
            mul_cycles: 0.125,
            add_cycles: 0.125,
        };
        for (c, cycles, expect) in [
            (Config::PlaneWeight, 4.375, 8.36e8),
            (Config::Wind3d, 8.5, 4.30e8),
            (Config::ViscousSmoothed, 9.0, 4.06e8),
        ] {
            let l = limit(&budget(Workload::Kernel(c)).unwrap(), &p);
            assert_eq!((l.unit, l.cycles), ("multiply pipes", cycles), "{}", c.name());
            // The write-up prints 3 digits.
            assert!((l.node_steps_per_s / expect - 1.0).abs() < 1e-3, "{}: {:e}", c.name(), l.node_steps_per_s);
        }
        // A slow divider moves the limit there: plane_weight's division and square root.
        let slow = Primitives { div_cycles: 4.0, sqrt_cycles: 6.0, ..p };
        let l = limit(&budget(Workload::Kernel(Config::PlaneWeight)).unwrap(), &slow);
        assert_eq!((l.unit, l.cycles), ("divider", 10.0));
        assert!(budget(Workload::Kernel(Config::TwoMaterialPlane)).is_none());
        assert!(budget(Workload::SectionStrings).is_none());
    }
}
