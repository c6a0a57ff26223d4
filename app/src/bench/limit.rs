//! The compute limit of the explicit kernel on the machine `ohl bench` runs on: the throughput
//! [node-steps/s] at which the busiest execution unit would be saturated, from the operations one
//! node-step performs ([`budget`], counted from the source) and the cost of each operation on this core
//! ([`super::Primitives`], measured in the kernel's instruction set):
//!
//! ```text
//! cycles of a set of operations  c(o) = max( (mul + cmp) c_mul,  add c_add,  div c_div + sqrt c_sqrt,
//!                                           loads c_load,  stores c_store )
//! limit of the core    = clock / c(segment + node)        (every unit busy all the time)
//! bound of the passes  = clock / (c(segment) + c(node))   (each pass saturates its own busiest unit)
//! fraction of the limit = measured node-steps/s / limit of the core
//! ```
//!
//! The limit of the core is what the issue's goal is measured against. Whether a core reaches it with
//! these operations at all is measured, not assumed: [`super::mix`] runs each budget's operations in a
//! loop of independent iterations (on the Zen 5 of issue 27's thirteenth round: 104-113 % of the limit
//! with every access within a cache line, 62-99 % with every access across two). The bound of the passes is how
//! far the kernel's structure lets it go: the segment pass and the node pass are separate loops, so the
//! divider, busy in the segment pass, idles through the node pass, whose multiplications and additions
//! cannot fill the segment pass's idle pipes. Between the two lies the cost of running the passes one
//! after the other; below the bound, everything else (latency chains longer than the scheduler can
//! cover, the caches, loop overhead, the front end).
//!
//! `c_mul`, `c_add`, `c_div`, `c_sqrt` [cycles per double] are measured throughputs (independent
//! operations, data in L1); comparisons and `max` are taken on the multiply pipes, as AMD family 19h
//! executes them (the Software Optimization Guide for family 19h; LLVM's Znver4 scheduling model). A
//! division and a square root also take `o_div`, `o_sqrt` cycles of a multiply pipe per instruction,
//! measured ([`super::pipes`]): the multiply pipes count `mul + cmp + div o_div + sqrt o_sqrt`
//! multiplications' worth.
//! Loads and stores are not measured: a core of AMD family 17h-1Ah or Intel since Haswell issues two
//! vector loads and one vector store per cycle, so `c_load = 1 / (2 w)`, `c_store = 1 / w` for `w`
//! doubles per access ([`super::access_doubles`]: 8 for AVX-512, but 4 on Zen 4, which splits a 512-bit
//! access in two; 4 for AVX2; 2 for the SSE2 baseline). Everything outside the core (L2, L3, memory bandwidth,
//! latency chains, loop overhead) is what the fraction measures the kernel's distance by: the limit is
//! the core's, the same at every `N`.
//!
//! The counts (per node-step, one segment and one node; for the kernel of `src/scheme/explicit.rs`,
//! `segment_pass_body` and `kick_drift`, and the element `src/element/segment.rs` with the wind laws of
//! `src/element/aero.rs`), tabulated and derived in `figures/bench/README.md` ("Compute limit on this
//! processor"):
//!
//! | config | pass | mul + cmp | add | div | sqrt | loads | stores |
//! |---|---|---|---|---|---|---|---|
//! | plane_weight | segment (no load, planar) | 12 + 2 | 5 | 1 | 1 | 7 | 3 |
//! | | node (no load, planar) | 9 + 1 | 11 | 0 | 0 | 10 | 4 |
//! | wind_3d | segment | 48 + 3 | 24 | 2 | 2 | 21 | 10 |
//! | | node | 16 + 1 | 20 | 0 | 0 | 21 | 6 |
//! | kv_smoothing_3d | segment | 45 + 3 | 25 | 2 | 2 | 29 | 10 |
//! | | node (with smoothing) | 23 + 1 | 29 | 0 | 0 | 38 | 12 |
//!
//! (Totals: plane_weight 24, 16, 1, 1, 17, 7 (until issue 27's eighth round, which stopped writing and
//! reading the shares of a pass without a load and the `x1` component of a wire in its plane, 35, 27, 1,
//! 1, 30, 12: the write-up's); wind_3d 68, 44,
//! 2, 2, 42, 16; kv_smoothing_3d 72, 54, 2, 2, 67, 22. The node pass without smoothing: per component the force
//! `f_hi - f_lo + (e_hi + e_lo) ex` (3 additions, 1 multiplication), `F m^-1 + g` (1, 1),
//! `v + (kick free) a` (1, 1), `x + dt v` (1, 1); `kick free` (1 multiplication); the speed check
//! `v.v <= bound^2` (3, 2 and a comparison). With smoothing (3.3): the kick (10, 15), the differences
//! `intact (v_{i+1} - v_i)` (3, 3), `b free` and per component `v + bf (d_{i+1} - d_i)` (4 multiplications
//! in all, 6 additions), the drift and the check (6, 5, 1). Without a load the shares `e` are `+0.0`:
//! the force is `f_hi - f_lo + 0` (2 additions, no multiplication) and neither `e` nor the exposure is
//! loaded; the segment pass does not form or store its zero shares (2 multiplications and 3 stores fewer).
//! In the plane `x1 = c` (every `x1` the same, every `v1` `+0`) the node pass leaves the `x1` component out
//! (4 multiplications, 6 additions, 4 loads and 2 stores fewer; `0 + v^2` is folded by the compiler) and
//! the segment pass takes the `x1` differences as the constant `+0` (2 loads, 2 additions and a
//! multiplication fewer; it still forms and stores `T (0 / l)`). The counts agree with those of the
//! compiled loops executed per node-step, by callgrind and `llvm-objdump` (`app/benches/executed_limit.py`'s
//! counting; plane_weight at N = 5000: segment pass 14.1 on the multiply pipes, 5 additions, 7.0 doubles
//! loaded, 3.0 stored; node pass 10.25, 11, 10.0, 4.0).)
//!
//! The workloads this table does not cover (the two-material law, the ground, the sections, bundles and
//! the short circuit's line) have their limit from the instructions they execute instead:
//! `app/benches/executed_limit.py` counts every instruction a step executes (callgrind) and charges it
//! with LLVM's model of the core (`llvm-mca -mcpu=znver3`), for every workload (the three above
//! included, where it agrees with this table within 5 %).
//!
//! The two-material law's pass is scalar with the law's branches, and the section and line workloads
//! add scalar loops over links: no limit of this kind is given for them ([`budget`] is `None`).

use super::Primitives;
use super::workload::Workload;
use ohl::scheme::configs::Config;

/// Operations of one pass over one node or segment, by execution unit (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ops {
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

impl Ops {
    /// The operations of `self` and `o` together (a `const fn`, for the counts the operation mix is
    /// compiled with, [`super::mix`]).
    pub const fn plus(self, o: Ops) -> Ops {
        Ops {
            mul_pipe: self.mul_pipe + o.mul_pipe,
            add: self.add + o.add,
            div: self.div + o.div,
            sqrt: self.sqrt + o.sqrt,
            loads: self.loads + o.loads,
            stores: self.stores + o.stores,
        }
    }
}

impl std::ops::Add for Ops {
    type Output = Ops;
    fn add(self, o: Ops) -> Ops {
        self.plus(o)
    }
}

/// Operations of one node-step: the segment pass on one segment and the node pass on one node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OpBudget {
    /// the segment pass (`segment_pass_body`), per segment
    pub segment: Ops,
    /// the node pass (`kick_drift`), per node
    pub node: Ops,
}

impl OpBudget {
    /// One node-step's operations, both passes together.
    pub const fn total(self) -> Ops {
        self.segment.plus(self.node)
    }
}

const fn ops(mul_pipe: u32, add: u32, div: u32, sqrt: u32, loads: u32, stores: u32) -> Ops {
    Ops { mul_pipe, add, div, sqrt, loads, stores }
}

/// The node pass without smoothing (module doc).
const NODE: Ops = ops(17, 20, 0, 0, 21, 6);

/// The node pass without smoothing and without a distributed load, for a wire in its plane `x1 = c`: the
/// shares, the exposure and the `x1` component left out (module doc).
const NODE_PLANAR: Ops = ops(10, 11, 0, 0, 10, 4);

/// plane_weight's node-step (module doc).
pub const PLANE_WEIGHT: OpBudget = OpBudget { segment: ops(14, 5, 1, 1, 7, 3), node: NODE_PLANAR };
/// wind_3d's node-step (module doc).
pub const WIND_3D: OpBudget = OpBudget { segment: ops(51, 24, 2, 2, 21, 10), node: NODE };
/// kv_smoothing_3d's node-step (module doc).
pub const KV_SMOOTHING_3D: OpBudget = OpBudget { segment: ops(48, 25, 2, 2, 29, 10), node: ops(24, 29, 0, 0, 38, 12) };

/// The operations of one node-step of `w` (module doc), or `None` where no vector limit applies.
pub fn budget(w: Workload) -> Option<OpBudget> {
    match w {
        Workload::Kernel(Config::PlaneWeight) => Some(PLANE_WEIGHT),
        Workload::Kernel(Config::Wind3d) => Some(WIND_3D),
        Workload::Kernel(Config::ViscousSmoothed) => Some(KV_SMOOTHING_3D),
        _ => None,
    }
}

/// The busiest unit of a node-step and its cycles, for the core and for the two passes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// cycles per node-step of the busiest unit, all operations together
    pub cycles: f64,
    /// which unit: "multiply pipes", "add pipes", "divider", "loads" or "stores"
    pub unit: &'static str,
    /// the limit of the core [node-steps/s]: the clock over `cycles`
    pub node_steps_per_s: f64,
    /// cycles per node-step with each pass on its own busiest unit, one pass after the other
    pub passes_cycles: f64,
    /// the bound of the passes [node-steps/s]: the clock over `passes_cycles`
    pub passes_node_steps_per_s: f64,
}

/// The busiest unit of `o` and its cycles on a core with the primitives `p`.
fn busiest(o: &Ops, p: &Primitives) -> (&'static str, f64) {
    let w = p.access_doubles;
    let units = [
        (
            "multiply pipes",
            (o.mul_pipe as f64 + o.div as f64 * p.div_mul_cycles + o.sqrt as f64 * p.sqrt_mul_cycles) * p.mul_cycles,
        ),
        ("add pipes", o.add as f64 * p.add_cycles),
        ("divider", o.div as f64 * p.div_cycles + o.sqrt as f64 * p.sqrt_cycles),
        ("loads", o.loads as f64 / (2.0 * w)),
        ("stores", o.stores as f64 / w),
    ];
    units.into_iter().fold(("", 0.0), |a, u| if u.1 > a.1 { u } else { a })
}

/// The limit of `b` on a core with the measured primitives `p` (module doc).
pub fn limit(b: &OpBudget, p: &Primitives) -> Limit {
    let (unit, cycles) = busiest(&b.total(), p);
    let passes_cycles = busiest(&b.segment, p).1 + busiest(&b.node, p).1;
    Limit {
        cycles,
        unit,
        node_steps_per_s: p.clock_hz / cycles,
        passes_cycles,
        passes_node_steps_per_s: p.clock_hz / passes_cycles,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Zen 4 derivation of `figures/bench/README.md`: 8 doubles per cycle on each pair of pipes
    /// (0.125 cycles per double), a division 1.25 and a square root 2.25 cycles per double, 3.656 GHz:
    /// wind_3d 4.30e8 (multiply pipes, 8.5 cycles), kv_smoothing_3d 4.06e8 (9.0), from the totals
    /// tabulated there; plane_weight (8.36e8, 4.38 cycles on the multiply pipes there) now without its
    /// zero shares and its `x1` component: 24 multiplications' worth (3 cycles), so the divider's 3.5
    /// cycles bound it, 1.045e9.
    #[test]
    fn reproduces_the_zen4_limits_of_the_write_up() {
        let p = Primitives {
            clock_hz: 3.656e9,
            isa: "avx512",
            sqrt_cycles: 2.25,
            div_cycles: 1.25,
            mul_cycles: 0.125,
            add_cycles: 0.125,
            // The write-up's derivation takes the divider as a unit of its own.
            div_mul_cycles: 0.0,
            sqrt_mul_cycles: 0.0,
            access_doubles: 4.0,
        };
        for (c, total, unit, cycles, expect) in [
            (Config::PlaneWeight, ops(24, 16, 1, 1, 17, 7), "divider", 3.5, 1.0446e9),
            (Config::Wind3d, ops(68, 44, 2, 2, 42, 16), "multiply pipes", 8.5, 4.30e8),
            (Config::ViscousSmoothed, ops(72, 54, 2, 2, 67, 22), "multiply pipes", 9.0, 4.06e8),
        ] {
            let b = budget(Workload::Kernel(c)).unwrap();
            assert_eq!(b.segment + b.node, total, "{}: the passes add up to the tabulated totals", c.name());
            let l = limit(&b, &p);
            assert_eq!((l.unit, l.cycles), (unit, cycles), "{}", c.name());
            // The write-up prints 3 digits.
            assert!((l.node_steps_per_s / expect - 1.0).abs() < 1e-3, "{}: {:e}", c.name(), l.node_steps_per_s);
            // One pass after the other can only be slower than every unit busy at once.
            assert!(l.passes_cycles >= l.cycles, "{}", c.name());
        }
        // plane_weight's passes: the segment pass on the divider (1.25 + 2.25), the node pass on the add
        // pipes (11 additions, 1.375 cycles; its 10 doubles loaded take 1.25).
        let l = limit(&budget(Workload::Kernel(Config::PlaneWeight)).unwrap(), &p);
        assert_eq!(l.passes_cycles, 3.5 + 1.375);
        // A slow divider moves the limit there: plane_weight's division and square root.
        let slow = Primitives { div_cycles: 4.0, sqrt_cycles: 6.0, ..p };
        let l = limit(&budget(Workload::Kernel(Config::PlaneWeight)).unwrap(), &slow);
        assert_eq!((l.unit, l.cycles), ("divider", 10.0));
        // A division and a square root taking 2.5 cycles of a multiply pipe each: plane_weight's multiply
        // pipes count 24 + 2.5 + 2.5 multiplications' worth, 3.625 cycles, above the divider's 3.5.
        let shared = Primitives { div_mul_cycles: 2.5, sqrt_mul_cycles: 2.5, ..p };
        let l = limit(&budget(Workload::Kernel(Config::PlaneWeight)).unwrap(), &shared);
        assert_eq!((l.unit, l.cycles), ("multiply pipes", 3.625));
        assert!(budget(Workload::Kernel(Config::TwoMaterialPlane)).is_none());
        assert!(budget(Workload::SectionStrings).is_none());
    }
}
