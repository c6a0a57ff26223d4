//! Benchmark of the explicit kernel (3.1), (3.3), (3.6): the measurements and the machine description,
//! shared by `ohl bench` and the criterion bench (`cargo bench -p ohl-app`). The workloads are the
//! library's kernel configurations ([`ohl::scheme::configs`]) and the sections and lines of
//! [`workload`].
//!
//! Throughput is counted in node-steps per CPU second, `nodes * steps / CPU time`, for one thread. The
//! clock is the thread's CPU time ([`ohl::output::cpu_time`], `CLOCK_THREAD_CPUTIME_ID`): on a loaded
//! machine wall time also counts the time the thread waited for a processor, CPU time does not. Every
//! measurement is the median over several repetitions (the fastest is kept beside it), and the load
//! average is recorded with it. Instruction counts per node-step (`app/benches/instructions.sh`,
//! valgrind's callgrind) are the load-independent measure; [`run_fixed_steps`] is the entry point they
//! time.

/// `vector_copies!(m)`: `m!(module, features, vector type, doubles per vector, set1, setzero, mul, add,
/// div, sqrt, or, loadu, storeu)` once for the AVX2 copy and once for the AVX-512 copy (the kernel's
/// instruction sets), with their intrinsics: the throughput loops of [`pipes`] and [`mix`] are written
/// once for both.
macro_rules! vector_copies {
    ($m:ident) => {
        $m!(
            avx2,
            "avx2",
            __m256d,
            4,
            _mm256_set1_pd,
            _mm256_setzero_pd,
            _mm256_mul_pd,
            _mm256_add_pd,
            _mm256_div_pd,
            _mm256_sqrt_pd,
            _mm256_or_pd,
            _mm256_loadu_pd,
            _mm256_storeu_pd
        );
        $m!(
            avx512,
            "avx2,avx512f,avx512dq,avx512vl",
            __m512d,
            8,
            _mm512_set1_pd,
            _mm512_setzero_pd,
            _mm512_mul_pd,
            _mm512_add_pd,
            _mm512_div_pd,
            _mm512_sqrt_pd,
            _mm512_or_pd,
            _mm512_loadu_pd,
            _mm512_storeu_pd
        );
    };
}

pub mod limit;
pub mod mix;
pub mod pipes;
pub mod workload;

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Instant;

use ohl::run::{RunError, RunOptions, run};
use ohl::scenario;
pub use ohl::scheme::configs::Config;
use ohl::scheme::configs::{EA_N, RHO_KG_PER_M, SPAN_M};
use ohl::scheme::{Explicit, Instability};
pub use workload::{Solver, Workload};

use crate::plot::{self, Chart, Series, Style};

/// Grid sizes `N` [segments] of the kernel table (issue 5).
pub const SIZES: [usize; 4] = [50, 200, 1000, 5000];
/// Segments per span `N` of the section and line workloads ([`workload::LINE`]).
pub const LINE_SIZES: [usize; 3] = [50, 100, 200];
/// Grid sizes `N` of the `ohl run` timing (issue 5).
pub const RUN_SIZES: [usize; 4] = [50, 100, 200, 400];
/// Target throughput of the 3D wind configuration at N = 1000 and 5000 [node-steps/s] (issue 5).
pub const TARGET_NODE_STEPS_PER_S: f64 = 2.0e8;

/// Steps per repetition for `nodes` nodes: about `node_steps` node-steps, at least 100 steps (timer
/// resolution).
pub fn steps_per_rep(nodes: usize, node_steps: f64) -> usize {
    ((node_steps / nodes as f64) as usize).max(100)
}

/// The calling thread's CPU time [s] ([`ohl::output::cpu_time`]); where the system has no thread clock,
/// the wall time since the first call.
pub fn cpu_clock_s() -> f64 {
    static START: OnceLock<Instant> = OnceLock::new();
    ohl::output::cpu_time::thread_cpu_time_s()
        .unwrap_or_else(|| START.get_or_init(Instant::now).elapsed().as_secs_f64())
}

/// Longest CPU time of one repetition [s] ([`measure_kernel`] takes fewer steps than the node-step budget
/// asks for a workload slower than that).
pub const MAX_REP_S: f64 = 0.5;

/// Longest stretch of steps timed from one initial state: 4000 steps are 13 s simulated at N = 50
/// (longer undamped tension-only runs can go unstable, docs/paper_notes.md) and 0.1 s at N = 5000.
pub const EPISODE_STEPS: usize = 4000;

/// Run `steps` nominal steps of `config` at `n` segments from its initial state and return the solver
/// (the fixed workload that instruction counting differences). Within one episode ([`EPISODE_STEPS`])
/// the configurations stay stable; longer undamped runs can go unstable, which is returned.
pub fn run_fixed_steps(config: Config, n: usize, steps: usize) -> Result<Explicit, Instability> {
    let mut s = config.solver(n);
    let dt = s.params().dt_s;
    for _ in 0..steps {
        s.step(dt)?;
    }
    Ok(s)
}

/// Run `steps` nominal steps of the workload `w` at `n` segments (per span for a section or line) from
/// its initial state and return the solver: [`run_fixed_steps`] for every workload of `ohl bench`
/// (`ohl bench --fixed`, the workload `app/benches/executed_limit.py` counts). An instability is
/// returned as its message.
pub fn run_fixed_workload(w: Workload, n: usize, steps: usize) -> Result<workload::Solver, String> {
    if let Workload::Kernel(c) = w {
        return run_fixed_steps(c, n, steps).map(workload::Solver::Wire).map_err(|e| e.to_string());
    }
    let mut s = w.solver(n);
    for _ in 0..steps {
        s.try_step()?;
    }
    Ok(s)
}

/// FNV-1a hash of the bit patterns of every position and velocity: equal hashes mean (up to a 2^-64
/// chance) bitwise identical states, the check that an optimised kernel computes what the old one did.
pub fn state_hash(s: &Explicit) -> u64 {
    wires_hash(&[s.wire()])
}

/// [`state_hash`] of several wires, one after the other (every conductor of a line).
pub fn wires_hash(wires: &[&ohl::wire::Wire]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for w in wires {
        for a in w.x.iter().chain(&w.v) {
            for v in a {
                for b in v.to_bits().to_le_bytes() {
                    h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
                }
            }
        }
    }
    h
}

/// One row of the kernel table.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelResult {
    /// configuration name
    pub config: String,
    /// segments `N` (per span for a section or line)
    pub n: usize,
    /// nodes stepped per step (every conductor's)
    pub nodes: usize,
    /// steps per repetition
    pub steps: usize,
    /// repetitions
    pub reps: usize,
    /// fastest repetition [CPU s]
    pub best_s: f64,
    /// median repetition [CPU s]
    pub median_s: f64,
}

impl KernelResult {
    /// Throughput of the median repetition [node-steps per CPU second].
    pub fn node_steps_per_s(&self) -> f64 {
        self.nodes as f64 * self.steps as f64 / self.median_s
    }
    /// Time per node-step of the median repetition [CPU ns].
    pub fn ns_per_node_step(&self) -> f64 {
        1e9 / self.node_steps_per_s()
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Time the explicit step of `config` at `n` segments: `reps` repetitions of [`steps_per_rep`] steps
/// (in episodes of at most [`EPISODE_STEPS`] from the initial state; the clones are not timed), after one
/// untimed warm-up repetition, on the thread's CPU clock ([`cpu_clock_s`]).
pub fn measure_kernel(config: Workload, n: usize, node_steps: f64, reps: usize) -> KernelResult {
    let initial = config.solver(n);
    let nodes = initial.nodes();
    // A slow workload (the short circuit's pair forces cost about 100 kernels) would take minutes at the
    // budget of the kernel's: 100 probe steps (untimed) bound a repetition to about MAX_REP_S.
    let what = format!("{} N = {n}", config.name());
    let mut probe = initial.clone();
    let t0 = cpu_clock_s();
    for _ in 0..100 {
        probe.step(&what);
    }
    let per_step = (cpu_clock_s() - t0) / 100.0;
    let affordable = if per_step > 0.0 { (MAX_REP_S / per_step) as usize } else { usize::MAX };
    let steps = steps_per_rep(nodes, node_steps).min(affordable.max(100));
    let mut times = Vec::with_capacity(reps);
    for rep in 0..=reps {
        // Episodes of at most EPISODE_STEPS steps, each from a fresh (untimed) clone of the initial state.
        let (mut left, mut t) = (steps, 0.0);
        while left > 0 {
            let k = left.min(EPISODE_STEPS);
            let mut s = initial.clone();
            let t0 = cpu_clock_s();
            for _ in 0..k {
                s.step(&what);
            }
            t += cpu_clock_s() - t0;
            std::hint::black_box(&s);
            left -= k;
        }
        if rep > 0 {
            times.push(t);
        }
    }
    KernelResult {
        config: config.name().into(),
        n,
        nodes,
        steps,
        reps,
        best_s: times.iter().copied().fold(f64::INFINITY, f64::min),
        median_s: median(times),
    }
}

/// The paper's weight release (section 4.2) as a scenario: the test wire released from the straight
/// chord under its weight, Courant 0.9, smoothing `b = 0.02` (paper range 0.015-0.03), 10 s simulated,
/// a time-series row every 0.05 s (the default).
pub fn weight_release_scenario(n: usize) -> String {
    format!(
        r#"
name = "weight release N = {n}"
[conductor]
axial_stiffness_n = {EA_N}
linear_density_kg_per_m = {RHO_KG_PER_M}
[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, {SPAN_M}, 0.0]
segments = {n}
[numerics]
courant = 0.9
smoothing = 0.02
[duration]
end_time_s = 10.0
"#
    )
}

/// Timing of a whole run of the weight release.
#[derive(Clone, Debug, PartialEq)]
pub struct RunTiming {
    /// segments `N`
    pub n: usize,
    /// steps of the run
    pub steps: u64,
    /// fastest wall time of the whole run (driver, diagnostics, output files) [s]
    pub run_s: f64,
    /// fastest wall time of the same number of bare steps [s]
    pub steps_only_s: f64,
    /// number of `diagnostics()` calls the driver made (one per time-series row)
    pub diagnostics_calls: usize,
    /// time of one `diagnostics()` call [s]
    pub diagnostics_each_s: f64,
}

impl RunTiming {
    /// Share of the run spent outside the bare steps [-].
    pub fn overhead_share(&self) -> f64 {
        1.0 - self.steps_only_s / self.run_s
    }
}

/// Time `ohl run` on [`weight_release_scenario`] at `n` segments (fastest of `reps`), writing its
/// output files into `out_dir` (the files a real run writes), and the same steps without the driver.
pub fn measure_run(n: usize, reps: usize, out_dir: &Path) -> Result<RunTiming, RunError> {
    let sc = scenario::parse(&weight_release_scenario(n), "<bench>")
        .unwrap_or_else(|e| panic!("built-in benchmark scenario rejected: {e}"));
    let plan = scenario::build(&sc).unwrap_or_else(|e| panic!("built-in benchmark scenario rejected: {e:?}"));
    let opts = RunOptions { out_dir: Some(out_dir.to_path_buf()), record: false };
    let (mut run_s, mut steps, mut rows) = (f64::INFINITY, 0, 0);
    for _ in 0..reps.max(1) {
        let t0 = cpu_clock_s();
        let o = run(plan.clone(), &opts)?;
        run_s = run_s.min(cpu_clock_s() - t0);
        steps = o.solver.steps();
        rows = (o.summary.final_time_s / plan.sample_interval_s).round() as usize + 1;
    }
    let dt = plan.solver.params().dt_s;
    let mut steps_only_s = f64::INFINITY;
    for _ in 0..reps.max(1) {
        let mut s = plan.solver.clone();
        let t0 = cpu_clock_s();
        for _ in 0..steps {
            s.step(dt).unwrap_or_else(|e| panic!("weight release N = {n}: {e}"));
        }
        steps_only_s = steps_only_s.min(cpu_clock_s() - t0);
        std::hint::black_box(&s);
    }
    let mut s = plan.solver.clone();
    let calls = 200;
    let t0 = cpu_clock_s();
    for _ in 0..calls {
        std::hint::black_box(s.diagnostics());
    }
    let diagnostics_each_s = (cpu_clock_s() - t0) / calls as f64;
    Ok(RunTiming { n, steps, run_s, steps_only_s, diagnostics_calls: rows, diagnostics_each_s })
}

/// Measured costs of the primitive operations on this core, for the limit estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Primitives {
    /// core clock [Hz], from a chain of dependent integer additions of two registers ([`add_chain`]:
    /// latency 1 cycle on every x86-64 core, Agner Fog's instruction tables; a double addition's latency
    /// is not the same everywhere: 3 cycles on AMD Zen 2-4, 2 on Zen 5, 4 on Intel Skylake)
    pub clock_hz: f64,
    /// the instruction set the square roots and divisions were compiled for: the kernel's
    /// ([`ohl::scheme::explicit::kernel_instruction_set`])
    pub isa: &'static str,
    /// square root of a double, throughput, in the kernel's instruction set (packed) [cycles]
    pub sqrt_cycles: f64,
    /// division of doubles, throughput, in the kernel's instruction set (packed) [cycles]
    pub div_cycles: f64,
    /// multiplication of doubles, throughput, in the kernel's instruction set (packed) [cycles]
    pub mul_cycles: f64,
    /// addition of doubles, throughput, in the kernel's instruction set (packed) [cycles]
    pub add_cycles: f64,
    /// multiply-pipe cycles a packed division takes from the multiplications beside it ([`pipes`]; 0
    /// where not measured) [cycles per instruction]
    pub div_mul_cycles: f64,
    /// multiply-pipe cycles a packed square root takes ([`pipes`]; 0 where not measured) [cycles]
    pub sqrt_mul_cycles: f64,
    /// doubles one load or store instruction of the kernel's instruction set moves at the core's full
    /// rate of two loads and one store per cycle ([`access_doubles`]) [doubles]
    pub access_doubles: f64,
}

/// Doubles per load or store at full rate in the instruction set `isa`: a vector's (8 for AVX-512, 4
/// for AVX2, 2 for SSE2), except that AMD family 19h (Zen 4) executes a 512-bit access as two 256-bit
/// ones (AMD's Software Optimization Guide for family 19h), so 4 there; Zen 5 (family 1Ah) and Intel's
/// AVX-512 cores move 512 bits per access. Read from `/proc/cpuinfo`'s vendor and family.
pub fn access_doubles(isa: &str) -> f64 {
    access_doubles_of(isa, &std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default())
}

/// The value of the first `name : value` line of a `/proc/cpuinfo` text, trimmed.
fn cpuinfo_field<'a>(cpuinfo: &'a str, name: &str) -> Option<&'a str> {
    cpuinfo.lines().find_map(|l| l.split_once(':').filter(|(k, _)| k.trim() == name)).map(|(_, v)| v.trim())
}

/// [`access_doubles`] of a processor whose `/proc/cpuinfo` is `cpuinfo`.
fn access_doubles_of(isa: &str, cpuinfo: &str) -> f64 {
    let field = |name| cpuinfo_field(cpuinfo, name);
    let amd_family_19h = field("vendor_id") == Some("AuthenticAMD") && field("cpu family") == Some("25");
    match isa {
        "avx512" if amd_family_19h => 4.0,
        "avx512" => 8.0,
        "avx2" => 4.0,
        _ => 2.0,
    }
}

#[inline(always)]
fn sqrt_body(a: &[f64], out: &mut [f64]) {
    for (o, x) in out.iter_mut().zip(a) {
        *o = x.sqrt();
    }
}

#[inline(always)]
fn div_body(a: &[f64], out: &mut [f64]) {
    for (o, x) in out.iter_mut().zip(a) {
        *o = 1.0 / x;
    }
}

/// `body` compiled for the baseline, AVX2 and AVX-512 (F, DQ, VL), as the kernel's passes are
/// (`src/scheme/explicit.rs`), and a function running the copy of the instruction set named; with a
/// third argument the AVX-512 copy runs that body instead (more accumulators, [`lanes`]).
macro_rules! isa_copies {
    ($name:ident, $body:ident) => {
        isa_copies!($name, $body, $body);
    };
    ($name:ident, $body:expr, $wide:expr) => {
        fn $name(isa: &str, a: &[f64], out: &mut [f64]) {
            #[inline(never)]
            fn baseline(a: &[f64], out: &mut [f64]) {
                $body(a, out)
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(never)]
            #[target_feature(enable = "avx2")]
            fn avx2(a: &[f64], out: &mut [f64]) {
                $body(a, out)
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(never)]
            #[target_feature(enable = "avx2,avx512f,avx512dq,avx512vl")]
            fn avx512(a: &[f64], out: &mut [f64]) {
                $wide(a, out)
            }
            #[cfg(target_arch = "x86_64")]
            match isa {
                // SAFETY: the kernel reports "avx512" or "avx2" only where the processor has them.
                "avx512" => return unsafe { avx512(a, out) },
                "avx2" => return unsafe { avx2(a, out) },
                _ => {}
            }
            baseline(a, out)
        }
    };
}

/// Independent accumulators of the multiply and add throughput loops [doubles]: 8 vectors of 4 (AVX2)
/// or of 8 (AVX-512; 64 doubles), at least the pipes' latency (2-4 cycles) times their number (2) in
/// vectors in flight, so that the loop is bound by throughput, not by the dependent chain of each
/// accumulator. (Four 512-bit accumulators were enough on Zen 4, whose pipes take a 512-bit operation in
/// two halves; on Zen 5's full-width pipes they held the multiplications to 4 per 3 cycles, 2/3 of
/// the throughput.)
fn lanes(isa: &str) -> usize {
    if isa == "avx512" { WIDE_LANES } else { LANES }
}

/// Accumulators of the baseline and AVX2 copies ([`lanes`]) [doubles].
const LANES: usize = 32;
/// Accumulators of the AVX-512 copy ([`lanes`]) [doubles].
const WIDE_LANES: usize = 64;

/// `rounds` times `a *= k` on each of `L` accumulators (`out` holds them; `a[0]` is the factor).
#[inline(always)]
fn mul_body<const L: usize>(a: &[f64], out: &mut [f64]) {
    let (k, rounds) = (a[0], a.len());
    let mut acc = [1.0; L];
    for _ in 0..rounds {
        for x in acc.iter_mut() {
            *x *= k;
        }
    }
    out[..L].copy_from_slice(&acc);
}

/// `rounds` times `a += k` on each of `L` accumulators (as [`mul_body`]).
#[inline(always)]
fn add_body<const L: usize>(a: &[f64], out: &mut [f64]) {
    let (k, rounds) = (a[0], a.len());
    let mut acc = [0.0; L];
    for _ in 0..rounds {
        for x in acc.iter_mut() {
            *x += k;
        }
    }
    out[..L].copy_from_slice(&acc);
}

isa_copies!(sqrt_array, sqrt_body);
isa_copies!(div_array, div_body);
isa_copies!(mul_lanes, mul_body::<LANES>, mul_body::<WIDE_LANES>);
isa_copies!(add_lanes, add_body::<LANES>, add_body::<WIDE_LANES>);

/// Cycles per step of [`add_chain`]'s chain.
#[cfg(target_arch = "x86_64")]
const CHAIN_LATENCY: f64 = 1.0;
#[cfg(not(target_arch = "x86_64"))]
const CHAIN_LATENCY: f64 = 3.0;

/// A chain of `n` (a multiple of 8) dependent additions. On x86-64 integer additions of two registers,
/// eight per iteration in `asm!` so that the compiler can neither fold nor reorder them: one cycle
/// each on every core (no core eliminates `add r, r` at renaming), and the loop's counter and branch run
/// on other ALUs beside the chain. Elsewhere double additions, taken as 3 cycles ([`CHAIN_LATENCY`]).
#[inline(never)]
fn add_chain(n: usize, y: u64) -> u64 {
    let mut x = 0u64;
    for _ in 0..n / 8 {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: register arithmetic only (the flags are clobbered, which `asm!` assumes by default).
        unsafe {
            std::arch::asm!(
                "add {x}, {y}", "add {x}, {y}", "add {x}, {y}", "add {x}, {y}",
                "add {x}, {y}", "add {x}, {y}", "add {x}, {y}", "add {x}, {y}",
                x = inout(reg) x, y = in(reg) y, options(nomem, nostack),
            );
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let mut f = f64::from_bits(x);
            for _ in 0..8 {
                f += y as f64;
            }
            x = f.to_bits();
        }
    }
    x
}

/// The median CPU time of `reps` runs of `f` [s].
pub(crate) fn median_of(reps: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..reps)
            .map(|_| {
                let t0 = cpu_clock_s();
                f();
                cpu_clock_s() - t0
            })
            .collect(),
    )
}

/// Measure [`Primitives`] (about 0.2 s) on the thread's CPU clock, the square roots and divisions in the
/// copy compiled for the kernel's instruction set.
pub fn measure_primitives() -> Primitives {
    let chain = 20_000_000;
    let t_add = median_of(7, || {
        std::hint::black_box(add_chain(std::hint::black_box(chain), std::hint::black_box(1)));
    });
    let clock_hz = CHAIN_LATENCY * chain as f64 / t_add;
    // 1024 doubles: 8 KiB in and out, resident in L1, so the divider is the bottleneck.
    let a: Vec<f64> = (0..1024).map(|i| 1.0 + i as f64 * 1e-3).collect();
    let mut out = vec![0.0; a.len()];
    let rounds = 2000;
    let isa = ohl::scheme::explicit::kernel_instruction_set();
    let per = |t: f64| t * clock_hz / (rounds * a.len()) as f64;
    let t_sqrt = median_of(7, || {
        for _ in 0..rounds {
            sqrt_array(isa, std::hint::black_box(&a), &mut out);
        }
    });
    let t_div = median_of(7, || {
        for _ in 0..rounds {
            div_array(isa, std::hint::black_box(&a), &mut out);
        }
    });
    // Multiply and add throughput: `lanes(isa)` accumulators, `a.len()` rounds each (the factor 1 + 2^-40 and
    // the increment 1 keep every value finite and normal).
    let k = vec![1.0 + f64::EPSILON * 4096.0; 1024];
    let t_mul = median_of(7, || {
        for _ in 0..rounds {
            mul_lanes(isa, std::hint::black_box(&k), &mut out);
        }
    });
    let ones = vec![1.0; k.len()];
    let t_sum = median_of(7, || {
        for _ in 0..rounds {
            add_lanes(isa, std::hint::black_box(&ones), &mut out);
        }
    });
    let per_lane = |t: f64| t * clock_hz / (rounds * k.len() * lanes(isa)) as f64;
    std::hint::black_box(&out);
    let (div_mul_cycles, sqrt_mul_cycles) = match pipes::occupancy(isa) {
        Some((d, s)) if d.is_finite() && s.is_finite() => (d, s),
        _ => (0.0, 0.0),
    };
    Primitives {
        div_mul_cycles,
        sqrt_mul_cycles,
        clock_hz,
        isa,
        sqrt_cycles: per(t_sqrt),
        div_cycles: per(t_div),
        mul_cycles: per_lane(t_mul),
        add_cycles: per_lane(t_sum),
        access_doubles: access_doubles(isa),
    }
}

/// Where and when a measurement was taken.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    /// CPU model from /proc/cpuinfo
    pub cpu: String,
    /// /proc/loadavg (1, 5, 15 min) when the measurement started
    pub load: String,
    /// UTC date and time
    pub date: String,
    /// `git describe --always --dirty` of the working tree, or "unknown" (no git, not a checkout)
    pub git: String,
}

fn command_output(cmd: &str, args: &[&str]) -> Option<String> {
    let o = std::process::Command::new(cmd).args(args).output().ok()?;
    o.status.success().then(|| String::from_utf8_lossy(&o.stdout).trim().to_string())
}

/// The current load average (first three fields of /proc/loadavg), or "unknown".
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

/// UTC date `YYYY-MM-DDThh:mm:ssZ` from the system clock (civil-from-days, H. Hinnant's algorithm).
fn utc_now() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_secs()).unwrap_or(0);
    let (days, rem) = ((secs / 86_400) as i64, secs % 86_400);
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z", rem / 3600, rem / 60 % 60, rem % 60)
}

/// Describe this machine now.
pub fn machine() -> Machine {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| cpuinfo_field(&s, "model name").map(String::from))
        .unwrap_or_else(|| "unknown".into());
    let git = command_output("git", &["describe", "--always", "--dirty"]).unwrap_or_else(|| "unknown".into());
    Machine { cpu, load: load_average(), date: utc_now(), git }
}

/// One point of a throughput plot: configuration name, segments `N`, node-steps per second.
pub type ThroughputRow = (String, usize, f64);

/// Columns of the kernel CSV.
pub const KERNEL_HEADER: [&str; 19] = [
    "label",
    "config",
    "n",
    "nodes",
    "steps_per_rep",
    "reps",
    "best_s",
    "median_s",
    "node_steps_per_s",
    "ns_per_node_step",
    "load_1_5_15",
    "cpu",
    "date_utc",
    "git",
    "build",
    "limit_node_steps_per_s",
    "of_limit",
    "limit_unit",
    "passes_bound_node_steps_per_s",
];

/// The compute limit of the workload named `config` on a core with the primitives `p`, and the fraction
/// of it `node_steps_per_s` reaches ([`limit`]); `None` where no limit applies.
pub fn fraction_of_limit(config: &str, node_steps_per_s: f64, p: &Primitives) -> Option<(limit::Limit, f64)> {
    let b = Workload::from_name(config).and_then(limit::budget)?;
    let l = limit::limit(&b, p);
    Some((l, node_steps_per_s / l.node_steps_per_s))
}

/// Write the kernel table to `path` (one row per result, each with the machine description and the
/// load average measured just before it, and the compute limit from the primitives `p` where one
/// applies).
pub fn write_kernel_csv(
    path: &Path,
    label: &str,
    m: &Machine,
    rows: &[(KernelResult, String)],
    build: &str,
    p: &Primitives,
) -> std::io::Result<()> {
    let mut w = csv_writer(path)?;
    w.write_record(KERNEL_HEADER)?;
    for (r, load) in rows {
        let (lim, frac, unit, passes) = match fraction_of_limit(&r.config, r.node_steps_per_s(), p) {
            Some((l, f)) => (
                format!("{:.4e}", l.node_steps_per_s),
                format!("{f:.4}"),
                l.unit.to_string(),
                format!("{:.4e}", l.passes_node_steps_per_s),
            ),
            None => Default::default(),
        };
        w.write_record([
            label.to_string(),
            r.config.clone(),
            r.n.to_string(),
            r.nodes.to_string(),
            r.steps.to_string(),
            r.reps.to_string(),
            format!("{:.6e}", r.best_s),
            format!("{:.6e}", r.median_s),
            format!("{:.6e}", r.node_steps_per_s()),
            format!("{:.4}", r.ns_per_node_step()),
            load.clone(),
            m.cpu.clone(),
            m.date.clone(),
            m.git.clone(),
            build.to_string(),
            lim,
            frac,
            unit,
            passes,
        ])?;
    }
    w.flush()
}

/// A CSV writer on `path`, creating its directory.
fn csv_writer(path: &Path) -> std::io::Result<csv::Writer<std::fs::File>> {
    if let Some(d) = path.parent() {
        std::fs::create_dir_all(d)?;
    }
    Ok(csv::Writer::from_path(path)?)
}

/// Read `(config, n, node_steps_per_s)` back from a kernel CSV written by [`write_kernel_csv`].
pub fn read_kernel_csv(path: &Path) -> Result<Vec<ThroughputRow>, String> {
    let mut r = csv::Reader::from_path(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let h = r.headers().map_err(|e| format!("{}: {e}", path.display()))?.clone();
    let col =
        |name: &str| h.iter().position(|c| c == name).ok_or_else(|| format!("{}: no column '{name}'", path.display()));
    let (c, n, t) = (col("config")?, col("n")?, col("node_steps_per_s")?);
    let mut out = Vec::new();
    for rec in r.records() {
        let rec = rec.map_err(|e| format!("{}: {e}", path.display()))?;
        let bad = |what: &str| format!("{}: bad {what} in row {:?}", path.display(), rec);
        let nn = rec[n].parse().map_err(|_| bad("n"))?;
        let tt = rec[t].parse().map_err(|_| bad("node_steps_per_s"))?;
        out.push((rec[c].to_string(), nn, tt));
    }
    Ok(out)
}

/// Write the run timings to `path`.
pub fn write_run_csv(path: &Path, label: &str, m: &Machine, rows: &[RunTiming]) -> std::io::Result<()> {
    let mut w = csv_writer(path)?;
    w.write_record([
        "label",
        "n",
        "steps",
        "run_wall_s",
        "steps_only_s",
        "overhead_share",
        "diagnostics_calls",
        "diagnostics_each_s",
        "load_1_5_15",
        "cpu",
        "date_utc",
        "git",
    ])?;
    for r in rows {
        w.write_record([
            label.to_string(),
            r.n.to_string(),
            r.steps.to_string(),
            format!("{:.6e}", r.run_s),
            format!("{:.6e}", r.steps_only_s),
            format!("{:.4}", r.overhead_share()),
            r.diagnostics_calls.to_string(),
            format!("{:.4e}", r.diagnostics_each_s),
            m.load.clone(),
            m.cpu.clone(),
            m.date.clone(),
            m.git.clone(),
        ])?;
    }
    w.flush()
}

/// Plot throughput against N (log-log), one colour per configuration: solid lines for `current`,
/// dashed for the optional `baseline`, and the issue's target as markers.
pub fn plot_throughput(
    current: &[ThroughputRow],
    current_label: &str,
    baseline: Option<(&[ThroughputRow], &str)>,
    stem: &Path,
) -> Result<(), plot::PlotError> {
    let mut series = Vec::new();
    for (ci, c) in workload::WIRE.iter().enumerate() {
        let pts = |rows: &[ThroughputRow]| -> Vec<(f64, f64)> {
            rows.iter().filter(|r| r.0 == c.name()).map(|r| (r.1 as f64, r.2)).collect()
        };
        series.push(Series::new(format!("{} ({current_label})", c.name()), pts(current), Style::LineMarkers, ci));
        if let Some((b, bl)) = baseline {
            series.push(Series::new(format!("{} ({bl})", c.name()), pts(b), Style::Dashed, ci));
        }
    }
    series.push(Series::new(
        "target, wind_3d (issue 5)",
        vec![(1000.0, TARGET_NODE_STEPS_PER_S), (5000.0, TARGET_NODE_STEPS_PER_S)],
        Style::Markers,
        workload::WIRE.len(),
    ));
    let chart = Chart {
        title: "Explicit step, one thread".into(),
        x_label: "segments N [-]".into(),
        y_label: "throughput [node-steps per CPU second]".into(),
        series,
        log_x: true,
        log_y: true,
        ..Default::default()
    };
    plot::render(&[chart], 1, (900, 600), stem)
}

/// A scratch directory for the output files of the timed runs.
pub fn scratch_dir() -> PathBuf {
    std::env::temp_dir().join(format!("ohl-bench-{}", std::process::id()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Zen 4 (family 19h, 25) moves a 512-bit access in two halves, Zen 5 (1Ah, 26) and Intel in one;
    /// AVX2 and SSE2 move their vector's 4 and 2 doubles everywhere.
    #[test]
    fn doubles_per_access_follow_the_processor() {
        let cpu =
            |vendor: &str, family: u32| format!("processor\t: 0\nvendor_id\t: {vendor}\ncpu family\t: {family}\n");
        assert_eq!(access_doubles_of("avx512", &cpu("AuthenticAMD", 25)), 4.0);
        assert_eq!(access_doubles_of("avx512", &cpu("AuthenticAMD", 26)), 8.0);
        assert_eq!(access_doubles_of("avx512", &cpu("GenuineIntel", 6)), 8.0);
        assert_eq!(access_doubles_of("avx2", &cpu("AuthenticAMD", 26)), 4.0);
        assert_eq!(access_doubles_of("baseline", &cpu("AuthenticAMD", 25)), 2.0);
        assert_eq!(access_doubles_of("avx512", ""), 8.0);
    }

    /// The primitives of this core are positive and finite, and the clock is a processor's (0.5-7 GHz):
    /// the integer chain's latency of one cycle is what every x86-64 core has.
    #[test]
    fn primitives_are_plausible() {
        let p = measure_primitives();
        assert!(p.clock_hz > 0.5e9 && p.clock_hz < 7e9, "{:e}", p.clock_hz);
        for c in [p.sqrt_cycles, p.div_cycles, p.mul_cycles, p.add_cycles] {
            assert!(c.is_finite() && c > 0.0, "{p:?}");
        }
    }

    #[test]
    fn configurations_run_and_stay_in_their_planes() {
        // A short run of every configuration: the plane case keeps x1 = 0 exactly (no force along x1),
        // the 3D cases move across the span (the wind blows along +x1).
        for c in Config::ALL {
            let s = run_fixed_steps(c, 20, 200).unwrap();
            let max_x1 = s.wire().x[0].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            match c {
                Config::PlaneWeight | Config::TwoMaterialPlane => assert_eq!(max_x1, 0.0),
                _ => assert!(max_x1 > 0.0, "{}", c.name()),
            }
            assert_eq!(Config::from_name(c.name()), Some(c));
        }
    }

    /// `ohl bench --fixed` on every workload: a kernel configuration is `run_fixed_steps` (the hash the
    /// scripts have always printed), a section or a line steps its solver; the line's hash covers every
    /// conductor, in order, so it differs from the first conductor's alone, and 0 steps leaves the
    /// initial state.
    #[test]
    fn fixed_workloads_step_the_solver_of_every_workload() {
        let k = run_fixed_workload(Workload::Kernel(Config::Wind3d), 20, 50).unwrap();
        let direct = run_fixed_steps(Config::Wind3d, 20, 50).unwrap();
        assert_eq!(wires_hash(&k.wires()), state_hash(&direct));
        let w = Workload::ShortCircuit { forces: false };
        let (start, stepped) = (run_fixed_workload(w, 10, 0).unwrap(), run_fixed_workload(w, 10, 30).unwrap());
        assert_eq!(wires_hash(&start.wires()), wires_hash(&w.solver(10).wires()));
        assert_eq!((stepped.nodes(), stepped.steps()), (33, 30));
        // (30 additions of dt: equal to 30 dt up to their roundings, a few eps each.)
        assert!((stepped.time_s() - 30.0 * stepped.dt_s()).abs() <= 1e-13 * stepped.time_s());
        let wires = stepped.wires();
        assert_eq!(wires.len(), 3);
        assert_ne!(wires_hash(&wires), wires_hash(&wires[..1]));
        assert_ne!(wires_hash(&wires), wires_hash(&start.wires()));
    }

    #[test]
    fn utc_date_has_the_iso_shape() {
        let d = utc_now();
        assert_eq!(d.len(), 20, "{d}");
        assert!(d.starts_with("20") && d.ends_with('Z'));
    }

    #[test]
    fn weight_release_scenario_is_valid() {
        for n in RUN_SIZES {
            scenario::parse(&weight_release_scenario(n), "<bench>").expect("valid");
        }
    }
}
