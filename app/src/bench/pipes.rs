//! How many cycles of the multiply pipes a packed division and a packed square root take from the
//! multiplications issued beside them (measured, in AVX2 instructions).
//!
//! AMD family 19h has one divide / square-root unit beside its two multiply pipes; LLVM's scheduling
//! model (`X86ScheduleZnver3.td`) charges a division's whole occupancy (5 cycles for `vdivpd` ymm, 9 for
//! `vsqrtpd`) to a multiply pipe, AMD's guide lists the unit on its own. The two readings give compute
//! limits 40 % apart, so the cost is measured instead: a loop of `M` independent `vmulpd` (8
//! accumulators, the multiply pipes' throughput) beside `D` independent divisions (or square roots) takes
//!
//! ```text
//! t_mix = max( t_div,  (M + D o) / 2 )      (two multiply pipes, one slot per vmulpd)
//! =>  o = (2 t_mix - M) / D                 [multiply-pipe cycles per vdivpd or vsqrtpd]
//! ```
//!
//! with `M` large enough that the multiplications bind (`M / 2 > t_div`): `M = 128`, `D = 8` divisions
//! or 4 square roots. `o = 0` means the unit runs beside the pipes, `o = 4.5` or `9` LLVM's reading.
//! The limit ([`super::limit`]) then counts a division as `o_div` multiplications' worth of the multiply
//! pipes and a square root as `o_sqrt`.

/// Multiply-pipe cycles taken by one packed division and by one packed square root, `(o_div, o_sqrt)`,
/// from the thread's CPU time and the clock `clock_hz`; `None` without AVX2 (the kernel's baseline copy
/// runs there, and no such measurement is made).
pub fn occupancy(clock_hz: f64) -> Option<(f64, f64)> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        let cycles = |f: &dyn Fn(usize) -> f64| {
            let iters = 100_000;
            super::median_of(7, || {
                std::hint::black_box(f(iters));
            }) * clock_hz
                / iters as f64
        };
        // SAFETY: AVX2 was detected above.
        let mul = cycles(&|n| unsafe { avx2::mix::<0, 0, 128>(n) });
        let div = cycles(&|n| unsafe { avx2::mix::<8, 0, 0>(n) });
        let div_mul = cycles(&|n| unsafe { avx2::mix::<8, 0, 128>(n) });
        let sqrt = cycles(&|n| unsafe { avx2::mix::<0, 4, 0>(n) });
        let sqrt_mul = cycles(&|n| unsafe { avx2::mix::<0, 4, 128>(n) });
        // The multiplications bind only where they alone take longer than the divider alone; the
        // formula's occupancy is then the pipes' extra time over the multiplications' own.
        let o = |mix: f64, alone: f64, d: f64| {
            if mul > alone { ((2.0 * mix - 2.0 * mul) / d).max(0.0) } else { f64::NAN }
        };
        return Some((o(div_mul, div, 8.0), o(sqrt_mul, sqrt, 4.0)));
    }
    let _ = clock_hz;
    None
}

#[cfg(target_arch = "x86_64")]
mod avx2 {
    use std::arch::x86_64::*;

    /// `iters` times: `D` divisions and `S` square roots of a value the compiler cannot see (each
    /// independent of the others), and `M / 8` rounds of `vmulpd` on 8 independent accumulators.
    ///
    /// # Safety
    /// Only where the processor has AVX2.
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    pub unsafe fn mix<const D: usize, const S: usize, const M: usize>(iters: usize) -> f64 {
        let k = _mm256_set1_pd(std::hint::black_box(1.0 + 1e-15));
        let x = _mm256_set1_pd(std::hint::black_box(2.0));
        let mut acc = [_mm256_set1_pd(1.0); 8];
        let mut sink = _mm256_setzero_pd();
        for _ in 0..iters {
            for _ in 0..D {
                sink = _mm256_or_pd(sink, _mm256_div_pd(k, std::hint::black_box(x)));
            }
            for _ in 0..S {
                sink = _mm256_or_pd(sink, _mm256_sqrt_pd(std::hint::black_box(x)));
            }
            for _ in 0..M / 8 {
                for a in acc.iter_mut() {
                    *a = _mm256_mul_pd(*a, k);
                }
            }
        }
        let mut out = [0.0; 4];
        for a in acc {
            sink = _mm256_add_pd(sink, a);
        }
        // SAFETY: `out` holds 4 doubles.
        unsafe { _mm256_storeu_pd(out.as_mut_ptr(), sink) };
        out[0]
    }
}
