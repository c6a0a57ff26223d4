//! A fuzzer for the arguments of `ohl sweep`, as a property test over the library functions the command
//! calls (`ohl_app::sweep`): for any `--vary FIELD=VALUES` arguments, cases file, `--shard K/N` and base
//! file, [`Shard`]'s parser, [`Spec::new`], [`Sweep::new`] and the case expansion ([`scenario_text`] of
//! a few case ids, then the scenario's parse and plan, as a case does before it runs) return a value or a
//! typed error whose message names the offending argument (the field, the values as written, the cases
//! file, the shard, the base file); never a panic, and never an allocation above [`PEAK_BYTES`] (a sweep
//! of 1e12 cases is refused, not materialised: the allocator of this test binary counts the bytes).
//! Nothing runs: no case is stepped.
//!
//! Inputs are generated structurally ([`gen_args`]), then sometimes mutated (characters replaced,
//! inserted or deleted, `=`, `:`, `,`, `[`, `]`, `/` among them):
//!
//! - field paths drawn from the real fields of the two base files (a single span,
//!   `examples/sweep/drake_400m_wind.toml`, and a line, `cases/e_three_phases_wind.toml`: indices, names
//!   `[name=A]`, a field the base does not set, the fields that name a line's columns) and invalid ones
//!   (empty, `a..b`, an unclosed bracket, an unknown key or name, an index past the end or above `u64`, a
//!   key into a number);
//! - values: lists of plausible numbers, extreme ones (`nan`, `inf`, `1e300`, `1e-300`, `-0`), text,
//!   TOML literals and empty items; ranges `START:STOP:STEP` well formed, malformed (`0:1:0`, `1:0:-1`,
//!   `a:b`, `1:2`, four parts) and huge (`0:1e12:1`, `0:999999:1` on two axes: 1e12 cases);
//! - a cases file (a header of those paths, rows of those values, sometimes a row of the wrong length, an
//!   empty file or a header alone);
//! - `--shard K/N`: plausible, `0/0`, `3/2`, `-1/2`, `1/18446744073709551616`, text;
//! - the base file: the single span, the line, a mutated copy of the single span, or a missing file.
//!
//! Budget: `OHL_FUZZ_SWEEP_CASES`, default [`DEFAULT_CASES`], 2 to 8 s in release on a shared 2-core
//! machine (5000 inputs, then the two longest ranges once: [`the_longest_ranges_are_bounded`]); the
//! wall time of each stage is printed. The seed is `OHL_FUZZ_SEED` (default fixed);
//! `OHL_FUZZ_VERBOSE=1` prints each refusal.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

use ohl_app::sweep::case::scenario_text;
use ohl_app::sweep::spec::{MAX_CASES, SpecError};
use ohl_app::sweep::{Kind, Shard, Spec, Sweep, SweepError};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};

/// Inputs tried by default.
const DEFAULT_CASES: u32 = 5_000;

/// The most bytes one input may hold allocated at once (above what was allocated before it): a range
/// has at most 1e6 values (`MAX_RANGE_VALUES`), about 100 bytes each as an axis row.
const PEAK_BYTES: usize = 400 << 20;

// ---------------------------------------------------------------------------------------------------
// An allocator that counts the bytes in use and their peak.

struct Counting;

static IN_USE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded to the system allocator unchanged; only counters are updated.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as the caller's contract.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = IN_USE.fetch_add(layout.size(), Relaxed) + layout.size();
            PEAK.fetch_max(now, Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as the caller's contract.
        unsafe { System.dealloc(ptr, layout) };
        IN_USE.fetch_sub(layout.size(), Relaxed);
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: as the caller's contract.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                let now = IN_USE.fetch_add(new_size - layout.size(), Relaxed) + new_size - layout.size();
                PEAK.fetch_max(now, Relaxed);
            } else {
                IN_USE.fetch_sub(layout.size() - new_size, Relaxed);
            }
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

// ---------------------------------------------------------------------------------------------------
// Generated arguments

/// Fields of the single-span base (`examples/sweep/drake_400m_wind.toml`) and of the line base
/// (`cases/e_three_phases_wind.toml`), valid and not, as a user might write them.
const FIELDS: &[&str] = &[
    "loads.wind.speed_m_per_s",
    "numerics.mu",
    "numerics.courant",
    "section.tension_fraction_of_rts",
    "section.segments_per_span",
    "section.supports[1].point_m[2]",
    "section.supports[1].point_m",
    "section.supports[0].kind",
    "duration.end_time_s",
    "conductor.catalog",
    "initial.shape",
    "events[0].time_s",
    "events[0].scale",
    "loads.wind.direction[0]",
    "ground.height_m",
    "output.sample_interval_s",
    "line.conductors[0].section.tension_fraction_of_rts",
    "line.conductors[name=A].section.segments_per_span",
    "line.conductors[name=earth wire].conductor.diameter_m",
    "line.conductors[name=B].section.supports[1].insulator_mass_kg",
    "line.towers[0].position_m[2]",
    "line.towers[name=T3].position_m",
    "line.conductors[name=A].name",
    "line.conductors[3].bundle.sub_conductors",
    "line.conductors[name=Z].section.segments_per_span",
    "line.conductors[9].name",
    "line.string_damping_n_s",
    "",
    "a..b",
    "events[",
    "events[x].time_s",
    "[0]",
    "loads.wind.speed m",
    "loads.wind.no_such_field",
    "no_such_table.x",
    "line.conductors[name=]",
    "events[18446744073709551616].time_s",
    "section.supports[99].point_m",
    "conductor.catalog.name",
    "numerics.mu[0]",
    "duration",
    "é",
];

/// Single values: plausible numbers, whole numbers, extreme literals, text and TOML literals.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => (0.01f64..60.0).prop_map(|x| format!("{x}")),
        4 => (0i64..80).prop_map(|n| n.to_string()),
        3 => prop::sample::select(vec![
            "nan", "inf", "-inf", "1e300", "-1e300", "1e-300", "-0", "0", "-1", "1e309", "0x10", "+5", "5.", ".5",
        ])
        .prop_map(String::from),
        2 => prop::sample::select(vec![
            "ACSR Drake", "linear", "equilibrium", "abc", "true", "[1.0, 2.0, 3.0]", "{ a = 1 }", "[", "\"q\"", " ",
        ])
        .prop_map(String::from),
        1 => any::<f64>().prop_map(|x| format!("{x:?}")),
    ]
}

/// The values of one `--vary`: a list, a range (well formed, malformed or huge).
fn values() -> impl Strategy<Value = String> {
    let number = prop_oneof![
        6 => (-5i32..50).prop_map(|n| n.to_string()),
        3 => (0.01f64..10.0).prop_map(|x| format!("{x:.3}")),
        1 => prop::sample::select(vec!["nan", "inf", "-inf", "1e300", "1e-300", "-0", "a", "", "1e12"]).prop_map(String::from),
    ];
    prop_oneof![
        24 => prop::collection::vec(value(), 1..5).prop_map(|v| v.join(",")),
        4 => prop::collection::vec(value(), 2..4).prop_map(|v| v.join(", ,")),
        16 => (number.clone(), number.clone(), number).prop_map(|(a, b, c)| format!("{a}:{b}:{c}")),
        6 => prop::sample::select(vec![
            "0:1:0", "1:0:-1", "a:b", "1:2", "1:2:3:4", ":", "::", "0:1e12:1", "0:1:1e-300", "-1e300:1e300:1e294",
            "0:1:nan", "10:30:5", "0.1:0.3:0.1", "5:5:1", "1:10:-1",
        ])
        .prop_map(String::from),
        // The longest ranges allowed (1e6 values; 2e5 values of 301 digits each) take a tenth of a second
        // to seconds each: [`the_longest_ranges_are_bounded`] tries them once.
    ]
}

/// One `--vary` argument.
fn vary() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (prop::sample::select(FIELDS), values()).prop_map(|(f, v)| format!("{f}={v}")),
        1 => prop::sample::select(FIELDS).prop_map(String::from),
        1 => (prop::sample::select(FIELDS), values()).prop_map(|(f, v)| format!(" {f} = {v} ")),
    ]
}

/// A cases file: a header of fields, rows of values (an empty cell keeps the base value), sometimes a
/// row of the wrong length.
fn cases_file() -> impl Strategy<Value = String> {
    let header = prop::collection::vec(prop::sample::select(FIELDS), 1..4);
    let cell = prop_oneof![5 => value(), 1 => Just(String::new())];
    let rows = prop::collection::vec(prop::collection::vec(cell, 1..4), 0..5);
    prop_oneof![
        20 => (header, rows, any::<bool>()).prop_map(|(h, rows, comment)| {
            let mut t = if comment { "# generated\n".to_string() } else { String::new() };
            t += &h.join(",");
            t.push('\n');
            for r in rows {
                // Mostly one cell per field; otherwise as generated.
                let cells: Vec<String> = if r.len() >= h.len() || r.len() == 1 && h.len() > 1 {
                    r.iter().take(h.len().max(r.len().min(1))).cloned().collect()
                } else {
                    r.clone()
                };
                let cells: Vec<String> =
                    cells.iter().map(|c| if c.contains(',') { format!("\"{c}\"") } else { c.clone() }).collect();
                t += &cells.join(",");
                t.push('\n');
            }
            t
        }),
        1 => Just(String::new()),
        1 => Just("\n\n".to_string()),
    ]
}

/// A `--shard` argument.
fn shard() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (0u64..8, 1u64..8).prop_map(|(k, n)| format!("{k}/{n}")),
        3 => prop::sample::select(vec![
            "0/0", "3/2", "-1/2", "1/18446744073709551616", "18446744073709551615/18446744073709551615",
            "0/18446744073709551615", "1", "/", "a/b", " 1 / 2 ", "1/2/3", "", "0x1/2", "1.0/2", "+1/2",
        ])
        .prop_map(String::from),
        1 => (any::<u64>(), any::<u64>()).prop_map(|(k, n)| format!("{k}/{n}")),
    ]
}

/// One input: the base file (0 single span, 1 line, 2 a mutated single span, 3 missing), the `--vary`
/// arguments, a cases file, a shard, the case ids to expand and the mutations.
#[derive(Clone, Debug)]
struct Args {
    base: u8,
    vary: Vec<String>,
    cases: Option<String>,
    shard: Option<String>,
    ids: Vec<u64>,
    mutations: Vec<(u8, usize, char)>,
}

impl std::fmt::Display for Args {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "base {} (0 single, 1 line, 2 mutated single, 3 missing)", self.base)?;
        for v in &self.vary {
            writeln!(f, "--vary {v:?}")?;
        }
        if let Some(c) = &self.cases {
            writeln!(f, "--cases file:\n{c}")?;
        }
        if let Some(s) = &self.shard {
            writeln!(f, "--shard {s:?}")?;
        }
        write!(f, "case ids (modulo the count) {:?}, mutations {:?}", self.ids, self.mutations)
    }
}

fn gen_args() -> impl Strategy<Value = Args> {
    let mutation = (
        0u8..8,
        any::<usize>(),
        prop::sample::select(vec!['=', ':', ',', '[', ']', '/', '.', '0', '9', '-', 'e', ' ', 'é', '"']),
    );
    (
        prop_oneof![6 => Just(0u8), 4 => Just(1u8), 1 => Just(2u8), 1 => Just(3u8)],
        prop_oneof![1 => Just(Vec::new()), 12 => prop::collection::vec(vary(), 1..3)],
        prop::option::weighted(0.3, cases_file()),
        prop::option::weighted(0.5, shard()),
        prop::collection::vec(any::<u64>(), 1..3),
        prop_oneof![3 => Just(Vec::new()), 1 => prop::collection::vec(mutation, 1..4)],
    )
        .prop_map(|(base, vary, cases, shard, ids, mutations)| {
            let mut a = Args { base, vary, cases, shard, ids, mutations };
            a.mutate();
            a
        })
}

impl Args {
    /// Apply the mutations to the `--vary` arguments and the shard: (what: replace, insert, delete or
    /// truncate; where; the character).
    fn mutate(&mut self) {
        for &(what, at, ch) in &self.mutations {
            let targets = self.vary.len() + usize::from(self.shard.is_some());
            if targets == 0 {
                return;
            }
            let k = at % targets;
            let s = if k < self.vary.len() { &mut self.vary[k] } else { self.shard.as_mut().expect("a shard") };
            let mut chars: Vec<char> = s.chars().collect();
            let i = (at / targets) % (chars.len() + 1);
            match what {
                0..=2 if i < chars.len() => chars[i] = ch,
                3 | 4 => chars.insert(i, ch),
                5 | 6 if i < chars.len() => {
                    chars.remove(i);
                }
                _ => chars.truncate(i),
            }
            *s = chars.into_iter().collect();
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// The property

thread_local! {
    static PANIC: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
    static GUARDING: Cell<bool> = const { Cell::new(false) };
    static STAGE_S: std::cell::RefCell<std::collections::BTreeMap<String, f64>> = const { std::cell::RefCell::new(std::collections::BTreeMap::new()) };
}

/// `f()`, or the panic's message; and the peak of bytes it held allocated beyond those in use before.
fn guarded<T>(stage: &str, f: impl FnOnce() -> T) -> Result<T, String> {
    let before = IN_USE.load(Relaxed);
    PEAK.store(before, Relaxed);
    GUARDING.with(|g| g.set(true));
    let t0 = std::time::Instant::now();
    let result = catch_unwind(AssertUnwindSafe(f));
    STAGE_S.with(|m| *m.borrow_mut().entry(stage.to_string()).or_insert(0.0) += t0.elapsed().as_secs_f64());
    GUARDING.with(|g| g.set(false));
    let peak = PEAK.load(Relaxed).saturating_sub(before);
    MAX_PEAK.fetch_max(peak, Relaxed);
    let value = result.map_err(|_| {
        let what = PANIC.with(|p| p.borrow_mut().take()).unwrap_or_else(|| "(no message)".into());
        format!("panic in {stage}: {what}")
    })?;
    if peak > PEAK_BYTES {
        return Err(format!("{stage} held {peak} bytes at once (limit {PEAK_BYTES})"));
    }
    Ok(value)
}

/// The largest peak of any stage [bytes].
static MAX_PEAK: AtomicUsize = AtomicUsize::new(0);

fn install_panic_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if GUARDING.with(Cell::get) {
                PANIC.with(|p| *p.borrow_mut() = Some(info.to_string()));
            } else {
                previous(info);
            }
        }));
    });
}

fn verbose(what: &str, e: &dyn std::fmt::Display) {
    if std::env::var_os("OHL_FUZZ_VERBOSE").is_some() {
        println!("{what}: {e}");
    }
}

#[derive(Default)]
struct Counts {
    tried: Cell<u64>,
    shard_refused: Cell<u64>,
    spec_refused: Cell<u64>,
    sweep_refused: Cell<u64>,
    sweeps: Cell<u64>,
    expanded: Cell<u64>,
    case_invalid: Cell<u64>,
    planned: Cell<u64>,
}

/// Whether `message` names one of `names` (non-empty, trimmed).
fn names_one(message: &str, names: &[String]) -> bool {
    names
        .iter()
        .map(|n| n.trim())
        .any(|n| !n.is_empty() && (message.contains(n) || message.contains(&format!("{n:?}"))))
}

/// The field part of a `--vary` argument (before its first `=` outside brackets, as the parser reads it).
fn field_of(arg: &str) -> String {
    let mut depth = 0_i32;
    for (i, c) in arg.char_indices() {
        depth += match c {
            '[' => 1,
            ']' => -1,
            _ => 0,
        };
        if c == '=' && depth <= 0 {
            return arg[..i].to_string();
        }
    }
    arg.to_string()
}

struct Files {
    dir: PathBuf,
    single: PathBuf,
    line: PathBuf,
    single_text: String,
}

fn check(a: &Args, files: &Files, counts: &Counts) -> Result<(), String> {
    counts.tried.set(counts.tried.get() + 1);
    // --shard
    let shard = match &a.shard {
        None => None,
        Some(text) => match guarded("Shard::from_str", || text.parse::<Shard>())? {
            Ok(s) => {
                if s.index >= s.count {
                    return Err(format!("shard {text:?} accepted as {s:?}"));
                }
                Some(s)
            }
            Err(e) => {
                if !e.to_string().contains(text.as_str()) {
                    return Err(format!("the shard error does not name {text:?}: {e}"));
                }
                verbose("shard refused", &e);
                counts.shard_refused.set(counts.shard_refused.get() + 1);
                None
            }
        },
    };
    // --cases and --vary
    let cases_path = files.dir.join("cases.csv");
    if let Some(c) = &a.cases {
        std::fs::write(&cases_path, c).map_err(|e| format!("cannot write the cases file: {e}"))?;
    }
    let cases = a.cases.as_ref().map(|_| cases_path.as_path());
    let spec = match guarded("Spec::new", || Spec::new(cases, &a.vary))? {
        Ok(spec) => spec,
        Err(e) => {
            let m = e.to_string();
            let named = match &e {
                SpecError::NoAxes => a.vary.is_empty() && a.cases.is_none(),
                SpecError::TooMany(_) => true,
                SpecError::CasesFile { .. } => m.contains(&cases_path.display().to_string()),
                SpecError::NoEquals(arg) | SpecError::Path { arg, .. } => {
                    // named as written or quoted (`{:?}`)
                    a.vary.contains(arg) && (m.contains(arg.as_str()) || m.contains(&format!("{arg:?}")))
                }
                _ => {
                    let mut names: Vec<String> = a.vary.iter().map(|v| field_of(v)).collect();
                    names.extend(a.cases.iter().flat_map(|c| c.lines().flat_map(|l| l.split(',')).map(String::from)));
                    names_one(&m, &names)
                }
            };
            if !named {
                return Err(format!("the specification's error names no argument: {m}"));
            }
            verbose("spec refused", &e);
            counts.spec_refused.set(counts.spec_refused.get() + 1);
            return Ok(());
        }
    };
    if spec.cases == 0 || spec.cases > MAX_CASES {
        return Err(format!("a specification of {} cases", spec.cases));
    }
    if let Some(s) = shard {
        let mine = guarded("Shard::ids", || s.ids(spec.cases).len())?;
        let expected = spec.cases.saturating_sub(s.index).div_ceil(s.count);
        if mine != expected {
            return Err(format!("shard {s} of {} cases holds {mine}, expected {expected}", spec.cases));
        }
    }
    // The base file and the fields.
    let base = match a.base {
        0 => files.single.clone(),
        1 => files.line.clone(),
        2 => {
            let p = files.dir.join("mutated.toml");
            let mut text = files.single_text.clone();
            for &(what, at, ch) in &a.mutations {
                let mut chars: Vec<char> = text.chars().collect();
                let i = at % (chars.len() + 1);
                match what {
                    0..=2 | 7 if i < chars.len() => chars[i] = ch,
                    5 | 6 if i < chars.len() => {
                        chars.remove(i);
                    }
                    _ => chars.insert(i, ch),
                }
                text = chars.into_iter().collect();
            }
            std::fs::write(&p, text).map_err(|e| format!("cannot write the base file: {e}"))?;
            p
        }
        _ => files.dir.join("no_such_base.toml"),
    };
    let base_name = base.display().to_string();
    let sweep = match guarded("Sweep::new", || Sweep::new(&base, spec.clone(), false))? {
        Ok(s) => s,
        Err(e) => {
            let m = e.to_string();
            let named = match &e {
                SweepError::Base(_) => m.contains(&base_name),
                SweepError::Field { source, .. } => {
                    m.contains(&base_name) && spec.fields().any(|f| f.to_string() == source.field)
                        || source.field.starts_with("line.conductors")
                }
                SweepError::Spec(_) => true,
                _ => false,
            };
            if !named {
                return Err(format!("the sweep's error names no argument or file: {m}"));
            }
            verbose("sweep refused", &e);
            counts.sweep_refused.set(counts.sweep_refused.get() + 1);
            return Ok(());
        }
    };
    counts.sweeps.set(counts.sweeps.get() + 1);
    // A few cases: their scenario text (the values set), then parse and plan as a case does.
    let names: Vec<String> = sweep.spec.fields().map(|f| f.to_string()).collect();
    for &id in &a.ids {
        let id = (id % sweep.spec.cases as u64) as usize;
        let text = match guarded("scenario_text", || scenario_text(&sweep, id))? {
            Ok(t) => t,
            Err(m) => {
                if !names_one(&m, &names) {
                    return Err(format!("case {id}'s error names no field: {m}"));
                }
                verbose("case invalid", &m);
                counts.case_invalid.set(counts.case_invalid.get() + 1);
                continue;
            }
        };
        counts.expanded.set(counts.expanded.get() + 1);
        let file = format!("case {id}");
        let planned = guarded("parse and plan", || match &sweep.kind {
            Kind::Single => ohl::scenario::parse(&text, &file).and_then(|s| ohl::scenario::plan(&s, &file)).map(|_| ()),
            Kind::Line { .. } => {
                ohl::scenario::line::parse(&text, &file).and_then(|s| ohl::scenario::line::plan(&s, &file)).map(|_| ())
            }
        })?;
        match planned {
            Ok(()) => counts.planned.set(counts.planned.get() + 1),
            Err(e) => {
                verbose("case refused", &e);
                counts.case_invalid.set(counts.case_invalid.get() + 1);
            }
        }
    }
    Ok(())
}

#[test]
fn sweep_arguments_never_panic_and_never_allocate_without_bound() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let dir = std::env::temp_dir().join(format!("ohl_fuzz_sweep_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let single = root.join("examples/sweep/drake_400m_wind.toml");
    let files = Files {
        single_text: std::fs::read_to_string(&single).expect("the single-span base"),
        single,
        line: root.join("cases/e_three_phases_wind.toml"),
        dir: dir.clone(),
    };
    let cases = std::env::var("OHL_FUZZ_SWEEP_CASES").map_or(DEFAULT_CASES, |v| v.trim().parse().expect("a count"));
    let seed: u64 = std::env::var("OHL_FUZZ_SEED").map_or(0x0b1, |v| v.trim().parse().expect("a seed"));
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let config = Config { cases, failure_persistence: None, max_shrink_iters: 2048, ..Config::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &bytes));
    install_panic_hook();
    let counts = Counts::default();
    let started = std::time::Instant::now();
    let result = runner.run(&gen_args(), |a| check(&a, &files, &counts).map_err(TestCaseError::fail));
    println!(
        "fuzz_sweep: {cases} cases (seed {seed}) in {:.1} s: {} inputs tried: {} shards refused, {} specifications \
         refused, {} sweeps refused (base file or field), {} sweeps built: {} cases expanded, {} cases planned, {} \
         invalid (value or plan refused with a message); largest peak of one stage {:.1} MB",
        started.elapsed().as_secs_f64(),
        counts.tried.get(),
        counts.shard_refused.get(),
        counts.spec_refused.get(),
        counts.sweep_refused.get(),
        counts.sweeps.get(),
        counts.expanded.get(),
        counts.planned.get(),
        counts.case_invalid.get(),
        MAX_PEAK.load(Relaxed) as f64 / 1e6,
    );
    STAGE_S.with(|m| println!("wall time by stage [s]: {:?}", m.borrow()));
    the_longest_ranges_are_bounded();
    let _ = std::fs::remove_dir_all(&dir);
    match result {
        Ok(()) => {}
        Err(TestError::Fail(why, a)) => panic!("finding: {why}\nminimal input:\n{a}"),
        Err(TestError::Abort(why)) => panic!("fuzzer aborted: {why}"),
    }
}

/// The longest ranges a `--vary` takes, once each (too slow for every input of the fuzzer): two axes of
/// 1e6 values (1e12 cases) are refused with `TooMany` within [`PEAK_BYTES`]; 2e5 values of 301 digits
/// each (`1e300:-1e300:-1e296`) are allowed, within [`PEAK_BYTES`]. Called by the fuzz test after its
/// inputs (the allocator's counters are shared by the threads of parallel tests).
fn the_longest_ranges_are_bounded() {
    install_panic_hook();
    let args = ["a=0:999999:1".to_string(), "b=0:999999:1".to_string()];
    let t0 = std::time::Instant::now();
    MAX_PEAK.store(0, Relaxed);
    let spec = guarded("Spec::new", || Spec::new(None, &args)).expect("bounded, no panic");
    println!(
        "1e12 cases: refused in {:.2} s, at most {:.1} MB held (the two axes' values)",
        t0.elapsed().as_secs_f64(),
        MAX_PEAK.load(Relaxed) as f64 / 1e6
    );
    assert!(matches!(spec, Err(SpecError::TooMany(ref n)) if n == "at least 1000000000000"), "{spec:?}");
    // 2e4 values of 301 digits (2e5 of them, `1e300:-1e300:-1e295`, take about 6 s: see the report).
    let args = ["a=1e300:-1e300:-1e296".to_string()];
    let t0 = std::time::Instant::now();
    MAX_PEAK.store(0, Relaxed);
    let spec = guarded("Spec::new", || Spec::new(None, &args)).expect("bounded, no panic").expect("allowed");
    println!(
        "2e4 values of 301 digits: {:.2} s, at most {:.1} MB held",
        t0.elapsed().as_secs_f64(),
        MAX_PEAK.load(Relaxed) as f64 / 1e6
    );
    assert_eq!(spec.cases, 20_001);
    assert_eq!(spec.case(0)[0].map(str::len), Some(301));
}
