//! How many cycles of the multiply pipes a packed division and a packed square root take from the
//! multiplications issued beside them (measured, in the kernel's instruction set: AVX-512 or AVX2).
//!
//! AMD family 19h has one divide / square-root unit beside its two multiply pipes; LLVM's scheduling
//! model (`X86ScheduleZnver3.td`) charges a division's whole occupancy (5 cycles for `vdivpd` ymm, 9 for
//! `vsqrtpd`) to a multiply pipe, AMD's guide lists the unit on its own. The two readings give compute
//! limits 40 % apart, so the cost is measured instead: a loop of `M` independent `vmulpd` (8
//! accumulators, the multiply pipes' throughput) beside `D` independent divisions (or square roots) takes
//!
//! ```text
//! t_mix = max( t_div,  (M + D o) / 2 )      (two multiply pipes, one slot per vmulpd)
//! =>  o = (2 t_mix - M) / D = M (t_mix - t_mul) / (D t_mul)
//!                                           [multiply-pipe cycles per vdivpd or vsqrtpd]
//! ```
//!
//! with `M` large enough that the multiplications bind (`M / 2 > t_div`): `M = 128`, `D = 8` divisions
//! or 4 square roots. The second form takes the cycle from the multiplications alone (`t_mul = M / 2`
//! cycles), so no clock enters. `o = 0` means the unit runs beside the pipes, `o = 4.5` or `9` LLVM's
//! reading. The limit ([`super::limit`]) then counts a division as `o_div` multiplications' worth of the
//! multiply pipes and a square root as `o_sqrt`.

/// Multiply-pipe cycles taken by one packed division and by one packed square root, `(o_div, o_sqrt)`,
/// in the copy of the instruction set `isa` names (`"avx512"` or `"avx2"`, the kernel's,
/// [`ohl::scheme::explicit::kernel_instruction_set`]), from the thread's CPU time; `None` for the
/// baseline (its kernel copy runs without AVX2, and no such measurement is made).
pub fn occupancy(isa: &str) -> Option<(f64, f64)> {
    #[cfg(target_arch = "x86_64")]
    if isa == "avx512" || isa == "avx2" {
        // mul, div, div + mul, sqrt, sqrt + mul
        type Mix = unsafe fn(usize) -> f64;
        macro_rules! copies {
            ($m:ident) => {
                [
                    $m::mix::<0, 0, 128>,
                    $m::mix::<8, 0, 0>,
                    $m::mix::<8, 0, 128>,
                    $m::mix::<0, 4, 0>,
                    $m::mix::<0, 4, 128>,
                ]
            };
        }
        let copies: [Mix; 5] = if isa == "avx512" { copies!(avx512) } else { copies!(avx2) };
        // SAFETY: the kernel reports "avx512" or "avx2" only where the processor has them.
        let [mul, div, div_mul, sqrt, sqrt_mul] = copies.map(|f| {
            super::median_of(7, || {
                std::hint::black_box(unsafe { f(100_000) });
            })
        });
        // The multiplications bind only where they alone take longer than the divider alone; the
        // formula's occupancy is then the pipes' extra time over the multiplications' own.
        let o = |with: f64, alone: f64, d: f64| {
            if mul > alone { (128.0 * (with - mul) / (d * mul)).max(0.0) } else { f64::NAN }
        };
        return Some((o(div_mul, div, 8.0), o(sqrt_mul, sqrt, 4.0)));
    }
    let _ = isa;
    None
}

/// `mix::<D, S, M>(iters)`, `iters` times: `D` divisions and `S` square roots of a value the compiler
/// cannot see (each independent of the others), and `M / 8` rounds of multiplications on 8 independent
/// accumulators; in the module `$m`, compiled for `$features` with the vector type `$v` of `$w` doubles
/// and its intrinsics.
macro_rules! mix_copy {
    ($m:ident, $features:literal, $v:ty, $w:literal, $set1:ident, $setzero:ident, $mul:ident, $add:ident,
     $div:ident, $sqrt:ident, $or:ident, $loadu:ident, $storeu:ident) => {
        #[cfg(target_arch = "x86_64")]
        mod $m {
            use std::arch::x86_64::*;

            /// See `mix_copy!`.
            ///
            /// # Safety
            /// Only where the processor has the module's instruction set.
            #[target_feature(enable = $features)]
            #[inline(never)]
            pub unsafe fn mix<const D: usize, const S: usize, const M: usize>(iters: usize) -> f64 {
                let k = $set1(std::hint::black_box(1.0 + 1e-15));
                let x = $set1(std::hint::black_box(2.0));
                let mut acc: [$v; 8] = [$set1(1.0); 8];
                let mut sink = $setzero();
                for _ in 0..iters {
                    for _ in 0..D {
                        sink = $or(sink, $div(k, std::hint::black_box(x)));
                    }
                    for _ in 0..S {
                        sink = $or(sink, $sqrt(std::hint::black_box(x)));
                    }
                    for _ in 0..M / 8 {
                        for a in acc.iter_mut() {
                            *a = $mul(*a, k);
                        }
                    }
                }
                let mut out = [0.0; $w];
                for a in acc {
                    sink = $add(sink, a);
                }
                // SAFETY: `out` holds one vector's doubles.
                unsafe { $storeu(out.as_mut_ptr(), sink) };
                out[0]
            }
        }
    };
}

vector_copies!(mix_copy);
