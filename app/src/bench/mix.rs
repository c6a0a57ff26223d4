//! The measured throughput of a workload's instruction mix: the operations one node-step performs
//! ([`super::limit::budget`]), issued in a loop whose iterations are independent of each other, with no
//! latency chain longer than the pipes can cover and every access in L1, in the kernel's instruction set
//! (one vector of `w` doubles per operation: `w` node-steps per iteration).
//!
//! Per iteration, with the counts `mul`, `add`, `div`, `sqrt`, `loads`, `stores` of [`super::limit::Ops`]
//! (`p` the loads, `q` the stores, in a window of the input and the output):
//!
//! ```text
//! a[j] += k / m[j]                         (div times)
//! a[div + j] += sqrt(m[6 + j])             (sqrt times)
//! a[l] += p[...]  then  a[l] += k          (the rest of the add additions: loads first, l = 0..8 in turn)
//! m[l] *= p[...]  then  m[l] *= k          (mul multiplications: the loads left, l = 0..12 in turn)
//! q[...] = m[l]                            (stores times)
//! ```
//!
//! `m` holds 12 accumulators and `a` 8, written out by lane (registers, not memory), so that the carried
//! chains (`mul / 12` multiplications of 3 cycles, `add / 8` additions) stay shorter than an iteration's
//! issue time; the quotients and roots are added once and feed nothing else. Every accumulator is
//! written out at the end, so no operation is dead. The loads and stores go to one of two 8 KiB windows
//! in turn (the compiler can neither hoist nor drop them), `offset` doubles past a cache line's start.
//! Every value stays near 1 (the factor `k = 1 + 2^-40` and loads of `1`), finite and normal.
//!
//! This is the rate at which this processor runs exactly the kernel's operation counts when nothing
//! else limits them. [`super::limit`] derives the limit from each unit's throughput, assuming every
//! unit busy at once; this loop checks that assumption on the core itself. The offset shows what the
//! stencil's shifted accesses (`x[j + 1]`, `f[i + 1]`) can cost: on the Zen 5 of issue 27's thirteenth
//! round, a 512-bit load or store across two lines takes about twice an aligned one's slot
//! (`figures/bench/README.md`). The kernel's distance to the mix is its own: the chains through the
//! square root and the division within an iteration, loop overhead, the caches beyond L1.

/// A cache line [bytes]: the alignment of the windows, and the span a vector access must not cross to be
/// taken as one access.
const LINE: usize = 64;

/// Doubles aligned to a cache line (read and written through raw pointers only).
#[derive(Clone, Copy)]
#[repr(align(64))]
struct Line(#[allow(dead_code)] [f64; LINE / 8]);

/// A compiled mix: `iters`, the input window, the output window.
#[cfg(target_arch = "x86_64")]
type Mix = unsafe fn(usize, *const f64, *mut f64);

/// `mix_of!(module, BUDGET)`: the module's `mix` compiled with the counts of the budget constant
/// `BUDGET` of [`super::limit`] (constants, so that the loop is straight-line code).
#[cfg(target_arch = "x86_64")]
macro_rules! mix_of {
    ($m:ident, $b:path) => {
        $m::mix::<
            { $b.total().mul_pipe as usize },
            { $b.total().add as usize },
            { $b.total().div as usize },
            { $b.total().sqrt as usize },
            { $b.total().loads as usize },
            { $b.total().stores as usize },
        > as Mix
    };
}

/// The mix of workload `w`'s budget in the instruction set `isa` (`"avx512"` or `"avx2"`) and its
/// doubles per vector (node-steps per iteration); `None` for another instruction set or a workload
/// without a budget.
#[cfg(target_arch = "x86_64")]
fn instance(isa: &str, w: super::workload::Workload) -> Option<(Mix, usize)> {
    use super::limit::{KV_SMOOTHING_3D, PLANE_WEIGHT, WIND_3D};
    use super::workload::Workload;
    use ohl::scheme::configs::Config;
    macro_rules! pick {
        ($m:ident) => {
            match w {
                Workload::Kernel(Config::PlaneWeight) => (mix_of!($m, PLANE_WEIGHT), $m::W),
                Workload::Kernel(Config::Wind3d) => (mix_of!($m, WIND_3D), $m::W),
                Workload::Kernel(Config::ViscousSmoothed) => (mix_of!($m, KV_SMOOTHING_3D), $m::W),
                _ => return None,
            }
        };
    }
    Some(match isa {
        "avx512" => pick!(avx512),
        "avx2" => pick!(avx2),
        _ => return None,
    })
}

/// Node-steps per CPU second of the instruction mix of `config`'s budget in the kernel's instruction set
/// `isa` (`"avx512"` or `"avx2"`), with every load and store `offset` doubles past a cache line's start
/// (0: each vector access within one line; 1 to 7: each 512-bit access across two lines, as the kernel's
/// accesses at `j + 1` are); `None` for the baseline, for workloads without a budget, and off x86-64. The
/// median of 7 runs of about 20 ms each.
pub fn mix_node_steps_per_s(isa: &str, config: &str, offset: usize) -> Option<f64> {
    #[cfg(target_arch = "x86_64")]
    {
        let (f, width) = instance(isa, super::workload::Workload::from_name(config)?)?;
        assert!(offset < LINE / 8, "an offset within a line");
        // Two windows of 1024 doubles in, two out (8 KiB each, 32 KiB in all: L1-resident), aligned to a
        // line, and one line more for the offset.
        let input = vec![Line([1.0; LINE / 8]); 2 * 1024 / (LINE / 8) + 1];
        let mut out = vec![Line([0.0; LINE / 8]); 2 * 1024 / (LINE / 8) + 1];
        // SAFETY: `offset` doubles into the first line, `2 * 1024` doubles before the end.
        let (src, dst) =
            unsafe { (input.as_ptr().cast::<f64>().add(offset), out.as_mut_ptr().cast::<f64>().add(offset)) };
        let iters = 200_000;
        let t = super::median_of(7, || {
            // SAFETY: the kernel reports "avx512" or "avx2" only where the processor has them; the
            // windows hold `2 * 1024` doubles from `src` and `dst`, and `mix` reads and writes within them.
            unsafe { f(iters, std::hint::black_box(src), std::hint::black_box(dst)) };
        });
        std::hint::black_box(&out);
        Some((iters * width) as f64 / t)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (isa, config, offset);
        None
    }
}

// `each!(n, [lanes], |r, l| body)`: `body` for `r` in `0..n` and each literal lane `l`
// (the lanes written out, so that the accumulators are registers), `r * lanes + l < n`.
macro_rules! each {
    ($n:expr, [$($lane:literal),*], |$r:ident, $l:ident| $body:block) => {
        let width = [$($lane),*].len();
        for $r in 0..$n.div_ceil(width) {
            $(
                if $r * width + $lane < $n {
                    let $l: usize = $lane;
                    $body
                }
            )*
        }
    };
}

/// `mix::<MUL, ADD, DIV, SQRT, LOADS, STORES>(iters, input, output)` (module docs), in the module `$m`
/// compiled for `$features` with the vector type `$v` of `$w` doubles and its intrinsics (of which it
/// uses `set1`, `mul`, `add`, `div`, `sqrt`, `loadu` and `storeu`; `vector_copies!` in the parent module).
macro_rules! mix_loop_copy {
    ($m:ident, $features:literal, $v:ty, $w:literal, $set1:ident, $setzero:ident, $mul:ident, $add:ident,
     $div:ident, $sqrt:ident, $or:ident, $loadu:ident, $storeu:ident) => {
        #[cfg(target_arch = "x86_64")]
        mod $m {
            use std::arch::x86_64::*;

            /// Doubles per vector: node-steps per iteration.
            pub const W: usize = $w;

            /// See the module docs.
            ///
            /// # Safety
            /// Only where the processor has the module's instruction set; `input` and `output` point to
            /// `2 * 1024` doubles each.
            #[target_feature(enable = $features)]
            #[inline(never)]
            pub unsafe fn mix<
                const MUL: usize,
                const ADD: usize,
                const DIV: usize,
                const SQRT: usize,
                const LOADS: usize,
                const STORES: usize,
            >(
                iters: usize,
                input: *const f64,
                output: *mut f64,
            ) {
                const { assert!(LOADS * $w <= 1024 && STORES * $w <= 1024 && DIV + SQRT <= ADD && DIV + SQRT <= 8) };
                // The additions that take a load, and those that take `k`; the multiplications that take
                // the other loads, and those that take `k`.
                const fn least(a: usize, b: usize) -> usize {
                    if a < b { a } else { b }
                }
                let load_adds = const { least(LOADS, ADD - DIV - SQRT) };
                let k_adds = const { ADD - DIV - SQRT - least(LOADS, ADD - DIV - SQRT) };
                let load_muls = const { least(LOADS - least(LOADS, ADD - DIV - SQRT), MUL) };
                let k_muls = const { MUL - least(LOADS - least(LOADS, ADD - DIV - SQRT), MUL) };
                let k = $set1(1.0 + f64::EPSILON * 4096.0);
                let mut m: [$v; 12] = [$set1(1.0); 12];
                let mut a: [$v; 8] = [$set1(0.0); 8];
                for it in 0..iters {
                    // SAFETY: `(it & 1) * 1024 + LOADS * W <= 2 * 1024` (the assertion above).
                    let (src, dst) = unsafe { (input.add((it & 1) * 1024), output.add((it & 1) * 1024)) };
                    for j in 0..DIV {
                        a[j] = $add(a[j], $div(k, m[j]));
                    }
                    for j in 0..SQRT {
                        a[DIV + j] = $add(a[DIV + j], $sqrt(m[6 + j]));
                    }
                    // SAFETY (the loads and stores): within the window (the assertion above).
                    each!(load_adds, [0, 1, 2, 3, 4, 5, 6, 7], |r, l| {
                        a[l] = $add(a[l], unsafe { $loadu(src.add((r * 8 + l) * $w)) });
                    });
                    each!(k_adds, [0, 1, 2, 3, 4, 5, 6, 7], |r, l| {
                        a[l] = $add(a[l], k);
                    });
                    each!(load_muls, [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], |r, l| {
                        m[l] = $mul(m[l], unsafe { $loadu(src.add((load_adds + r * 12 + l) * $w)) });
                    });
                    each!(k_muls, [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], |r, l| {
                        m[l] = $mul(m[l], k);
                    });
                    each!(STORES, [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], |r, l| {
                        unsafe { $storeu(dst.add((r * 12 + l) * $w), m[l]) };
                    });
                }
                // Every accumulator is written out, so that no operation is dead.
                for (j, x) in a.iter().chain(&m).enumerate() {
                    // SAFETY: 20 vectors, within the first window.
                    unsafe { $storeu(output.add(j * $w), *x) };
                }
            }
        }
    };
}

vector_copies!(mix_loop_copy);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::limit::budget;
    use crate::bench::workload::{COSTS, LINE as LINE_WORKLOADS, WIRE};

    /// Every workload with a budget has its mix in both vector instruction sets (compiled with that
    /// budget's counts by `mix_of!`), and no other workload has one: a budget added without a mix would
    /// print no mix under its limit.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn every_budget_has_its_mix() {
        for w in WIRE.into_iter().chain(LINE_WORKLOADS).chain(COSTS) {
            for isa in ["avx512", "avx2"] {
                let got = instance(isa, w).map(|(_, width)| width);
                let want = budget(w).map(|_| if isa == "avx512" { 8 } else { 4 });
                assert_eq!(got, want, "{} {isa}", w.name());
            }
            assert!(instance("baseline", w).is_none(), "{}", w.name());
        }
    }
}
