//! `ohl bench`: throughput of the explicit kernel (node-steps per CPU second, one thread, median of the
//! repetitions) in the wire workloads of [`ohl_app::bench::workload`] at N = 50, 200, 1000, 5000 and its
//! section and line workloads at N = 50, 100, 200 segments per span (with each multi-conductor element's
//! cost per node-step, the difference of a pair), the CPU time of `ohl run` on the weight release at
//! N = 50, 100, 200, 400, and the measured cost of a square root, a division, a multiplication and an
//! addition on this core in the kernel's instruction set, from which it derives the compute limit of the
//! vectorised configurations on this core and the fraction of it each reaches
//! ([`ohl_app::bench::limit`]), beside the rate of the same operations in a loop with nothing else to
//! limit them, with every access within a cache line and with every access across two
//! ([`ohl_app::bench::mix`]).
//! Writes `<out>/<label>.csv`, `<out>/<label>_run.csv`, `<out>/<label>_primitives.csv` and the plot
//! `<out>/throughput.png` / `.svg` (against `--baseline` if given).

use std::path::PathBuf;
use std::process::ExitCode;

use ohl_app::bench::{self, Config};

/// Arguments of `ohl bench`.
#[derive(clap::Args)]
pub struct BenchArgs {
    /// output directory for the CSV files and the plot
    #[arg(long, default_value = "figures/bench")]
    out: PathBuf,
    /// label of this measurement (file name of the CSV, legend of the plot), e.g. `before`, `after`
    #[arg(long, default_value = "current")]
    label: String,
    /// an earlier kernel CSV to draw dashed beside this one
    #[arg(long)]
    baseline: Option<PathBuf>,
    /// repetitions per measurement (the median counts, CPU time of the thread)
    #[arg(long, default_value_t = 7, allow_negative_numbers = true)]
    reps: usize,
    /// node-steps per repetition
    #[arg(long, default_value_t = 1.0e7, allow_negative_numbers = true)]
    node_steps: f64,
    /// a quick look: 3 repetitions of 2e6 node-steps, no run timing, nothing written
    #[arg(long)]
    quick: bool,
    /// skip the `ohl run` timing
    #[arg(long)]
    no_run: bool,
    /// only run `STEPS` steps of `CONFIG` at `N` segments and exit (the fixed workload of
    /// `app/benches/instructions.sh`), e.g. `wind_3d:1000:2000`
    #[arg(long, value_name = "CONFIG:N:STEPS")]
    fixed: Option<String>,
    /// measure nothing: draw `OUT/throughput.png` from this kernel CSV (and `--baseline`), e.g. to redraw
    /// the committed figure from the committed CSVs
    #[arg(long, value_name = "CSV")]
    replot: Option<PathBuf>,
    /// measure the constants of the `--dry-run` estimate of a line (case j's three phases at N = 50,
    /// 100, 200: the kernel, the contact, the pair forces, the clearances), print them beside the
    /// compiled-in ones and exit; nothing written
    #[arg(long)]
    costs: bool,
}

/// Reads a kernel CSV with its label (the file stem).
fn labelled_rows(path: &std::path::Path) -> Result<(Vec<bench::ThroughputRow>, String), String> {
    let rows = bench::read_kernel_csv(path)?;
    let label = path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_else(|| "baseline".into());
    Ok((rows, label))
}

fn replot(args: &BenchArgs, current: &std::path::Path) -> ExitCode {
    let (rows, label) = match labelled_rows(current) {
        Ok(x) => x,
        Err(e) => {
            err!("error: --replot: {e}");
            return ExitCode::from(2);
        }
    };
    let baseline = match args.baseline.as_deref().map(labelled_rows).transpose() {
        Ok(b) => b,
        Err(e) => {
            err!("error: --baseline: {e}");
            return ExitCode::from(2);
        }
    };
    let stem = args.out.join("throughput");
    let base = baseline.as_ref().map(|(r, l)| (r.as_slice(), l.as_str()));
    match bench::plot_throughput(&rows, &label, base, &stem) {
        Ok(()) => {
            out!("drawn {}.png and .svg from {}", stem.display(), current.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            err!("error: {e}");
            ExitCode::from(1)
        }
    }
}

fn fixed(spec: &str) -> ExitCode {
    let parts: Vec<&str> = spec.split(':').collect();
    let parsed = match parts.as_slice() {
        [c, n, s] => bench::Workload::from_name(c).zip(n.parse::<usize>().ok()).zip(s.parse::<usize>().ok()),
        _ => None,
    };
    let Some(((w, n), steps)) = parsed.filter(|((_, n), _)| *n >= 2) else {
        let mut names: Vec<&str> = Vec::new();
        for w in bench::workload::WIRE.into_iter().chain(bench::workload::LINE).chain(bench::workload::COSTS) {
            if !names.contains(&w.name()) {
                names.push(w.name());
            }
        }
        err!(
            "error: --fixed {spec}: expected CONFIG:N:STEPS with CONFIG one of {}, N >= 2 and STEPS >= 0",
            names.join(", ")
        );
        return ExitCode::from(2);
    };
    let s = match bench::run_fixed_workload(w, n, steps) {
        Ok(s) => s,
        Err(e) => {
            err!(
                "error: --fixed {spec}: {e} (undamped runs longer than one episode of `ohl bench`, {} steps, can go \
                 unstable)",
                bench::EPISODE_STEPS
            );
            return ExitCode::from(1);
        }
    };
    let wires = s.wires();
    // (One wire: the line the instruction and CPU scripts have always printed; a line adds its nodes.)
    let nodes = if wires.len() > 1 || !matches!(w, bench::Workload::Kernel(_)) {
        format!(", {} nodes", s.nodes())
    } else {
        String::new()
    };
    out!(
        "{} N = {n}: {} steps{nodes}, t = {:.6e} s, x3[N/2] = {:.15e} m, state hash {:016x}",
        w.name(),
        s.steps(),
        s.time_s(),
        wires[0].x[2][n / 2],
        bench::wires_hash(&wires)
    );
    ExitCode::SUCCESS
}

/// `ohl bench --costs`: the constants of the line's cost model ([`ohl::scenario::work`]) on this core,
/// from the differences of the [`bench::workload::COSTS`] workloads at each N, per step (median CPU
/// time of the repetitions): kernel = bare / nodes; contact = (contact - bare) / its pair nodes;
/// clearances = (clearances - bare) / their pair nodes; pair forces = (forces - contact), fitted by least
/// squares over the N to `k1 (n_a + n_b) + k2 n_a n_b` summed over the carrier pairs.
fn costs(reps: usize, node_steps: f64) -> ExitCode {
    use ohl::scenario::work;
    let machine = bench::machine();
    out!("ohl bench --costs: {}, load {}, {}, git {}", machine.cpu, machine.load, machine.date, machine.git);
    out!(
        "{:>5} {:>6} {:>13} {:>13} {:>13} {:>13} {:>11} {:>11} {:>11} {:>11}",
        "N",
        "nodes",
        "bare [us]",
        "contact [us]",
        "forces [us]",
        "clear. [us]",
        "kernel ns/n",
        "contact ns",
        "clear. ns",
        "forces [us]"
    );
    let (mut kernel, mut contact, mut clear) = (Vec::new(), Vec::new(), Vec::new());
    let mut em = Vec::new(); // (pair nodes, pair products, us per step)
    for n in bench::LINE_SIZES {
        let mut per_step = [0.0; 4];
        let mut sizes = [Default::default(); 4];
        let mut nodes = 0;
        for (k, w) in bench::workload::COSTS.into_iter().enumerate() {
            let r = bench::measure_kernel(w, n, node_steps, reps);
            per_step[k] = r.median_s / r.steps as f64;
            sizes[k] = w.solver(n).line_sizes().expect("a line workload");
            nodes = r.nodes;
        }
        let [bare, with_contact, with_forces, with_clear] = per_step;
        let k_node = 1e9 * bare / nodes as f64;
        let k_contact = 1e9 * (with_contact - bare) / sizes[1].contact_pair_nodes;
        let k_clear = 1e9 * (with_clear - bare) / sizes[3].clearance_pair_nodes;
        let forces = with_forces - with_contact;
        out!(
            "{n:>5} {nodes:>6} {:>13.3} {:>13.3} {:>13.3} {:>13.3} {k_node:>11.3} {k_contact:>11.3} {k_clear:>11.3} {:>11.3}",
            1e6 * bare,
            1e6 * with_contact,
            1e6 * with_forces,
            1e6 * with_clear,
            1e6 * forces
        );
        kernel.push(k_node);
        contact.push(k_contact);
        clear.push(k_clear);
        em.push((sizes[2].em_pair_nodes, sizes[2].em_pair_products, 1e9 * forces));
    }
    // Least squares of y = k1 L + k2 Q over the sizes: the 2 x 2 normal equations.
    let (mut ll, mut lq, mut qq, mut ly, mut qy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &(l, q, y) in &em {
        (ll, lq, qq, ly, qy) = (ll + l * l, lq + l * q, qq + q * q, ly + l * y, qy + q * y);
    }
    let det = ll * qq - lq * lq;
    let (k1, k2) = ((ly * qq - qy * lq) / det, (qy * ll - ly * lq) / det);
    let med = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    out!("\nconstant                         measured (median over N)   compiled in (ohl::scenario::work)");
    for (what, measured, compiled) in [
        ("kernel [ns per node-step]", med(&mut kernel), work::LINE_NS_PER_NODE_STEP),
        ("contact [ns per pair node]", med(&mut contact), work::CONTACT_NS_PER_PAIR_NODE),
        ("clearances [ns per pair node]", med(&mut clear), work::CLEARANCE_NS_PER_PAIR_NODE),
        ("pair forces k1 [ns per pair node]", k1, work::EM_NS_PER_PAIR_NODE),
        ("pair forces k2 [ns per n_a n_b]", k2, work::EM_NS_PER_PAIR_PRODUCT),
    ] {
        out!("{what:<34} {measured:>12.4}   {compiled:>12.4}");
    }
    for &(l, q, y) in &em {
        out!(
            "  pair forces fit: L = {l}, Q = {q}: measured {:.3} us, fitted {:.3} us",
            1e-3 * y,
            1e-3 * (k1 * l + k2 * q)
        );
    }
    ExitCode::SUCCESS
}

/// Run the benchmark; exit 0 on success, 1 if a file could not be written or a run failed, 2 on bad
/// arguments.
pub fn main(args: BenchArgs) -> ExitCode {
    if let Some(spec) = &args.fixed {
        return fixed(spec);
    }
    if let Some(current) = &args.replot {
        return replot(&args, current);
    }
    if args.reps == 0 || args.node_steps.is_nan() || args.node_steps < 1.0e3 {
        err!("error: --reps must be >= 1 and --node-steps >= 1000 (got {} and {})", args.reps, args.node_steps);
        return ExitCode::from(2);
    }
    let (reps, node_steps) = if args.quick { (3, 2.0e6) } else { (args.reps, args.node_steps) };
    if args.costs {
        return costs(reps, node_steps);
    }
    let machine = bench::machine();
    let build = match (cfg!(target_feature = "avx2"), ohl::scheme::explicit::kernel_instruction_set()) {
        (true, _) => "release, built for avx2",
        (false, "avx512") => "release, baseline build, kernel passes in their avx512 copies (runtime detected)",
        (false, "avx2") => "release, baseline build, kernel passes in their avx2 copies (runtime detected)",
        _ => "release, baseline build (sse2), kernel passes in their baseline copies",
    };
    out!("ohl bench: {} ({build}), load {}, {}, git {}", machine.cpu, machine.load, machine.date, machine.git);

    let p = bench::measure_primitives();
    out!(
        "core clock ~{:.2} GHz (dependent adds, CPU time); throughput in cycles per double ({} copy): sqrt {:.3}, division {:.3}, multiplication {:.3}, addition {:.3}; multiply-pipe cycles taken by a packed division {:.2}, by a square root {:.2}",
        p.clock_hz * 1e-9,
        p.isa,
        p.sqrt_cycles,
        p.div_cycles,
        p.mul_cycles,
        p.add_cycles,
        p.div_mul_cycles,
        p.sqrt_mul_cycles
    );
    for c in [Config::PlaneWeight, Config::Wind3d, Config::ViscousSmoothed] {
        if let Some(b) = bench::limit::budget(bench::Workload::Kernel(c)) {
            let l = bench::limit::limit(&b, &p);
            out!(
                "compute limit of {} on this core: {:.3e} node-steps/s ({:.2} cycles per node-step on the {}); \
                 bound of its two passes one after the other: {:.3e} ({:.2} cycles)",
                c.name(),
                l.node_steps_per_s,
                l.cycles,
                l.unit,
                l.passes_node_steps_per_s,
                l.passes_cycles
            );
            let mix = |offset| bench::mix::mix_node_steps_per_s(p.isa, c.name(), offset);
            if let (Some(within), Some(across)) = (mix(0), mix(1)) {
                out!(
                    "  its operations alone, iterations independent, data in L1 (bench::mix): {:.3e} node-steps/s \
                     ({:.0} % of the limit) with every access within a cache line, {:.3e} ({:.0} %) with every access across two",
                    within,
                    100.0 * within / l.node_steps_per_s,
                    across,
                    100.0 * across / l.node_steps_per_s
                );
            }
        }
    }

    out!(
        "\n{:<18} {:>6} {:>7} {:>8} {:>14} {:>10} {:>8} {:>9}  load",
        "config",
        "N",
        "nodes",
        "steps",
        "node-steps/s",
        "ns/node",
        "cycles",
        "of limit"
    );
    let mut rows = Vec::new();
    let sized = |ws: &'static [bench::Workload], ns: &'static [usize]| {
        ws.iter().flat_map(move |&w| ns.iter().map(move |&n| (w, n)))
    };
    for (c, n) in sized(&bench::workload::WIRE, &bench::SIZES).chain(sized(&bench::workload::LINE, &bench::LINE_SIZES))
    {
        {
            let load = bench::load_average();
            let r = bench::measure_kernel(c, n, node_steps, reps);
            let frac = bench::fraction_of_limit(&r.config, r.node_steps_per_s(), &p)
                .map_or("-".to_string(), |(_, f)| format!("{:.0} %", 100.0 * f));
            out!(
                "{:<18} {:>6} {:>7} {:>8} {:>14.4e} {:>10.3} {:>8.1} {:>9}  {load}",
                r.config,
                r.n,
                r.nodes,
                r.steps,
                r.node_steps_per_s(),
                r.ns_per_node_step(),
                r.ns_per_node_step() * 1e-9 * p.clock_hz,
                frac
            );
            rows.push((r, load));
        }
    }
    out!("\ncost of an element per node-step [CPU ns] (the difference of a pair of workloads):");
    for (with, without, what) in [
        ("ground_contact", "plane_weight", "ground contact, every node on the ground"),
        ("bundle_spacers", "bundle_bare", "case g's 18 spacers (6 arms each)"),
        ("short_circuit", "short_circuit_bare", "case j's short-circuit pair forces (3 phases)"),
    ] {
        for (r, _) in rows.iter().filter(|(r, _)| r.config == with) {
            if let Some((o, _)) = rows.iter().find(|(o, _)| o.config == without && o.n == r.n) {
                let (a, b) = (r.ns_per_node_step(), o.ns_per_node_step());
                out!("  {what}, N = {}: {a:.3} - {b:.3} = {:.3} ns per node-step", r.n, a - b);
            }
        }
    }
    if args.quick {
        return ExitCode::SUCCESS;
    }

    let mut failed = false;
    let kernel_csv = args.out.join(format!("{}.csv", args.label));
    if let Err(e) = bench::write_kernel_csv(&kernel_csv, &args.label, &machine, &rows, build, &p) {
        err!("error: cannot write {}: {e}", kernel_csv.display());
        failed = true;
    }
    let prim_csv = args.out.join(format!("{}_primitives.csv", args.label));
    let prim = format!(
        "clock_hz,isa,sqrt_cycles_per_double,div_cycles_per_double,mul_cycles_per_double,add_cycles_per_double,div_mul_pipe_cycles,sqrt_mul_pipe_cycles,cpu,build,load_1_5_15,date_utc\n{:.4e},{},{:.3},{:.3},{:.4},{:.4},{:.3},{:.3},\"{}\",\"{build}\",{},{}\n",
        p.clock_hz,
        p.isa,
        p.sqrt_cycles,
        p.div_cycles,
        p.mul_cycles,
        p.add_cycles,
        p.div_mul_cycles,
        p.sqrt_mul_cycles,
        machine.cpu,
        machine.load,
        machine.date
    );
    if let Err(e) = std::fs::write(&prim_csv, prim) {
        err!("error: cannot write {}: {e}", prim_csv.display());
        failed = true;
    }

    if !args.no_run {
        out!("\nohl run, weight release (section 4.2), 10 s simulated, Courant 0.9, a row every 0.05 s:");
        out!(
            "{:>5} {:>7} {:>12} {:>14} {:>10} {:>14}",
            "N",
            "steps",
            "run wall [s]",
            "bare steps [s]",
            "overhead",
            "diagnostics [s]"
        );
        let scratch = bench::scratch_dir();
        let mut timings = Vec::new();
        for n in bench::RUN_SIZES {
            match bench::measure_run(n, reps.min(5), &scratch) {
                Ok(t) => {
                    out!(
                        "{:>5} {:>7} {:>12.4e} {:>14.4e} {:>9.1}% {:>7} x {:.2e}",
                        t.n,
                        t.steps,
                        t.run_s,
                        t.steps_only_s,
                        100.0 * t.overhead_share(),
                        t.diagnostics_calls,
                        t.diagnostics_each_s
                    );
                    timings.push(t);
                }
                Err(e) => {
                    err!("error: weight release N = {n}: {e}");
                    failed = true;
                }
            }
        }
        let _ = std::fs::remove_dir_all(&scratch);
        let run_csv = args.out.join(format!("{}_run.csv", args.label));
        if let Err(e) = bench::write_run_csv(&run_csv, &args.label, &machine, &timings) {
            err!("error: cannot write {}: {e}", run_csv.display());
            failed = true;
        }
    }

    let current: Vec<bench::ThroughputRow> =
        rows.iter().map(|(r, _)| (r.config.clone(), r.n, r.node_steps_per_s())).collect();
    let baseline = match args.baseline.as_deref().map(labelled_rows).transpose() {
        Ok(b) => b,
        Err(e) => {
            err!("error: baseline: {e}");
            return ExitCode::from(2);
        }
    };
    let stem = args.out.join("throughput");
    let base = baseline.as_ref().map(|(r, l)| (r.as_slice(), l.as_str()));
    match bench::plot_throughput(&current, &args.label, base, &stem) {
        Ok(()) => out!("\nwritten to {} ({}.csv, throughput.png)", args.out.display(), args.label),
        Err(e) => {
            err!("error: {e}");
            failed = true;
        }
    }
    if failed { ExitCode::from(1) } else { ExitCode::SUCCESS }
}
