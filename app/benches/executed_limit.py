#!/usr/bin/env python3
"""The compute limit of every `ohl bench` workload, from the instructions it executes and LLVM's model of
this processor: the load-independent ceiling against which `ohl bench`'s node-steps per CPU second are a
fraction.

Usage: app/benches/executed_limit.py BIN WORKLOAD:N[,WORKLOAD:N...] [--csv OUT] [--measured CSV[,CSV...]]
                                     [--clock-ghz G] [--div C --sqrt C --div-mul C --sqrt-mul C] [--mcpu CPU]
       app/benches/executed_limit.py - - --limits CSV[,CSV] --measured 'GLOB[;GLOB]'   (no counting: a markdown
           table of the limits and the fractions the measured CSVs reach, two binaries side by side)
e.g.   app/benches/executed_limit.py target/release/ohl plane_weight:1000,short_circuit:100
           --measured 'figures/bench/issue27_r8_kernel_now_*.csv'

Needs valgrind, llvm-objdump and llvm-mca (Debian: `apt-get install valgrind llvm`; LLVM 14 was used).

Derivation (stated in figures/bench/README.md, "Issue 27, eighth round"):

1. Instruction counts. `valgrind --tool=callgrind --dump-instr=yes BIN bench --fixed WORKLOAD:N:S` for two
   step counts S1 < S2; the difference of each instruction's execution count is what S2 - S1 steps execute
   (set-up cancels), divided by the node-steps `nodes (S2 - S1)`: executions per node-step of every
   instruction of the binary (those of the C library, a few `memcpy`s, are counted and reported apart).
2. What each instruction occupies. Every distinct instruction (from `llvm-objdump -d`) is given alone to
   `llvm-mca -mcpu=znver3 -iterations=1000` (LLVM's scheduling model of AMD family 19h, from AMD's Software
   Optimization Guide): its pressure on each execution unit per execution, spread evenly over the units
   that can take it, and its micro-ops. A division and a square root are charged instead as `ohl bench`
   measures them on this core (the divider's cycles per packed instruction `4 c_div`, `4 c_sqrt`, and
   `o_div`, `o_sqrt` cycles of a multiply pipe; scalar forms as the packed ones: the model gives the divider
   the same occupancy for both).
3. The bound. Units of one kind (the four ALUs and the branch unit, the three address units, the four FP
   pipes, the two FP store-data pipes, the load and store queues) form a pool; an instruction that may use
   any unit of a set `A` needs `d` cycles of one of them. The cycles per node-step of a pool are at least
   `max over unit sets S of (sum of n d over instructions with A in S) / |S|` (all the work that must go to
   `S`, spread over it; the bound is reached where the scheduler balances perfectly). Dispatch issues six
   macro-ops per cycle (a compare or test fused with its conditional jump is one). The busiest pool sets the
   limit: `limit = clock / (cycles per node-step)`.

Nothing else is charged: no latency chain, no cache miss, no branch misprediction, no front-end stall. The
limit is what the executed instructions would reach on a core busy every cycle on its busiest unit, so the
fraction `measured / limit` says how far the code is from saturating this core with the instructions it
issues (the limit `ohl bench` prints counts the kernel's essential operations instead, read from the source).

--measured takes `ohl bench` kernel CSVs (a glob or a comma list): the median of their node-steps per second
per workload and N is divided by the limit. Clock and divider costs default to the primitives `ohl bench`
measured in those CSVs' run if given as options, else to round 7's values on this Zen 3 (3.19 GHz; 1.11,
2.23 cycles per double; 3.22, 4.13 multiply-pipe cycles).
"""
import argparse
import collections
import csv
import glob
import itertools
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

FAMILIES = [  # (family, regex of llvm-mca's resource names)
    ("ALU+branch", r"Zn3(ALU\d|BRU\d)$"),
    ("AGU", r"Zn3AGU\d$"),
    ("FP pipes", r"Zn3FPP[0-3]$"),
    ("FP store data", r"Zn3FPP45$"),
    ("FP store", r"Zn3FPSt$"),
    ("load-store", r"Zn3LSU$"),
    ("loads", r"Zn3Load$"),
    ("stores", r"Zn3Store$"),
]
DISPATCH_WIDTH = 6
FUSIBLE = re.compile(r"^(cmp|test|and|add|sub|inc|dec)[bwlq]?$")


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw)


def disassemble(binary):
    """address -> (mnemonic, operands) of every instruction of the binary."""
    out = run(["llvm-objdump", "-d", "--no-show-raw-insn", binary]).stdout
    ins = {}
    for line in out.splitlines():
        m = re.match(r"^\s*([0-9a-f]+):\s+(\S+)\s*(.*)$", line)
        if m:
            ins[int(m.group(1), 16)] = (m.group(2), m.group(3).split("<")[0].split("#")[0].strip())
    return ins


def executions(binary, spec, steps, work):
    """(per-address executions in the binary, executions elsewhere, output line of --fixed)."""
    out_file = os.path.join(work, "cg.out")
    p = subprocess.run(["valgrind", "--tool=callgrind", "--dump-instr=yes", f"--callgrind-out-file={out_file}",
                        binary, "bench", "--fixed", f"{spec}:{steps}"], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{binary} bench --fixed {spec}:{steps} failed:\n{p.stderr[-2000:]}")
    binary_real = os.path.realpath(binary)
    counts, other = collections.Counter(), 0
    objects, ob, addr, skip = {}, "", 0, False
    for line in open(out_file):
        if line.startswith(("ob=", "cob=")):
            m = re.match(r"c?ob=\((\d+)\)(?: (.*))?", line.strip())
            if m.group(2):
                objects[m.group(1)] = m.group(2)
            if line.startswith("ob="):
                ob = objects[m.group(1)]
            continue
        if line.startswith("calls="):
            skip = True
            continue
        m = re.match(r"^(0x[0-9a-f]+|\+\d+|-\d+|\*)\s+\S+\s+(\d+)", line)
        if not m:
            continue
        a = m.group(1)
        if a.startswith("0x"):
            addr = int(a, 16)
        elif a[0] == "+":
            addr += int(a[1:])
        elif a[0] == "-":
            addr -= int(a[1:])
        if skip:  # the inclusive cost of a call, not an execution
            skip = False
            continue
        if os.path.realpath(ob) == binary_real:
            counts[addr] += int(m.group(2))
        else:
            other += int(m.group(2))
    return counts, other, p.stdout.strip()


def normalise(mnemonic, operands):
    """The instruction as llvm-mca reads it: jump and call targets to a label."""
    if mnemonic.startswith(("j", "call")) and not operands.startswith("*"):
        return f"{mnemonic}\tL0"
    if "nop" in mnemonic or mnemonic.startswith(("data16", "cs")):
        return "nop"
    return f"{mnemonic}\t{operands}" if operands else mnemonic


def model(texts, mcpu, cache):
    """text -> (uops, {resource: pressure per execution}) from llvm-mca, each instruction alone."""
    todo = [t for t in texts if t not in cache]
    for t in todo:
        p = subprocess.run(["llvm-mca", "-mtriple=x86_64", f"-mcpu={mcpu}", "-iterations=1000",
                            "-resource-pressure", "-instruction-info", "-timeline=false"],
                           input="L0:\n" + t + "\n", capture_output=True, text=True)
        if p.returncode != 0:
            cache[t] = None
            continue
        lines = p.stdout.splitlines()
        names = {}
        for ln in lines:
            m = re.match(r"^\[([\d.]+)\]\s+-\s+(\S+)$", ln.strip())
            if m:
                names[m.group(1)] = m.group(2)
        uops = 1
        for i, ln in enumerate(lines):
            if ln.startswith("[1]    [2]"):
                uops = int(lines[i + 1].split()[0])
                break
        per = {}
        for i, ln in enumerate(lines):
            if ln.startswith("Resource pressure per iteration"):
                cols = re.findall(r"\[([\d.]+)\]", lines[i + 1])
                vals = lines[i + 2].split()
                for c, v in zip(cols, vals):
                    if v != "-" and float(v) > 0:
                        key = f"{names[c]}#{c}"
                        per[key] = float(v)
                break
        cache[t] = (uops, per)
    return cache


def pool_bound(demands, units):
    """Least cycles in which the unit pool `units` serves `demands` [(allowed set, cycles)]."""
    best = 0.0
    for r in range(1, len(units) + 1):
        for s in itertools.combinations(units, r):
            s = set(s)
            w = sum(d for a, d in demands if a <= s)
            best = max(best, w / len(s))
    return best


def limit(counts, node_steps, ins, mcpu, prim, cache):
    """(cycles per node-step, busiest pool, every pool's cycles, instructions per node-step)."""
    per_text = collections.Counter()
    fused = 0.0
    addrs = sorted(counts)
    order = sorted(ins)
    index = {a: i for i, a in enumerate(order)}
    for a in addrs:
        if a not in ins:
            continue
        mn, ops = ins[a]
        n = counts[a] / node_steps
        per_text[normalise(mn, ops)] += n
        if mn.startswith("j") and mn != "jmp" and index.get(a, 0) > 0:
            pm = ins[order[index[a] - 1]][0]
            if FUSIBLE.match(pm):
                fused += n
    model(per_text.keys(), mcpu, cache)
    demands = collections.defaultdict(list)
    uops = 0.0
    for t, n in per_text.items():
        m = cache.get(t)
        if m is None:
            demands["ALU+branch"].append(("generic", n))
            uops += n
            continue
        u, per = m
        uops += n * u
        mn = t.split("\t")[0]
        div = re.match(r"^v?div[sp]d$", mn)
        sqrt = re.match(r"^v?sqrt[sp]d$", mn)
        fam_units = collections.defaultdict(dict)
        for key, v in per.items():
            name = key.split("#")[0]
            for fam, rx in FAMILIES:
                if re.match(rx, name):
                    fam_units[fam][key] = v
        for fam, us in fam_units.items():
            if fam == "FP pipes" and (div or sqrt):
                # measured: the divider's own cycles, and the multiply-pipe cycles it takes
                demands["divider"].append((frozenset(["divider"]), n * 4 * (prim["div"] if div else prim["sqrt"])))
                fpp1 = [k for k in us if k.startswith("Zn3FPP1#")]
                demands[fam].append((frozenset(fpp1 or us), n * (prim["div_mul"] if div else prim["sqrt_mul"])))
                continue
            demands[fam].append((frozenset(us), n * sum(us.values())))
    pools = {}
    for fam, ds in demands.items():
        if fam == "divider":
            pools[fam] = sum(d for _, d in ds)
            continue
        ds = [(a, d) for a, d in ds if a != "generic"] + [(frozenset(), d) for a, d in ds if a == "generic"]
        units = sorted(set().union(*[a for a, _ in ds]))
        # generic (unknown to the model): one ALU cycle
        ds = [(a if a else frozenset(u for u in units if "ALU" in u), d) for a, d in ds]
        pools[fam] = pool_bound(ds, units)
    pools["dispatch"] = (uops - fused) / DISPATCH_WIDTH
    busiest = max(pools, key=pools.get)
    return pools[busiest], busiest, pools, sum(per_text.values())


def measured(patterns):
    cells = collections.defaultdict(list)
    for pat in patterns.split(","):
        for f in sorted(glob.glob(pat)):
            for r in csv.DictReader(open(f)):
                cells[(r["config"], int(r["n"]))].append(float(r["node_steps_per_s"]))
    return {k: statistics.median(v) for k, v in cells.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("binary")
    ap.add_argument("cells", help="WORKLOAD:N[,WORKLOAD:N...]")
    ap.add_argument("--csv")
    ap.add_argument("--measured", help="ohl bench kernel CSVs (globs, comma-separated)")
    ap.add_argument("--clock-ghz", type=float, default=3.19)
    ap.add_argument("--div", type=float, default=1.109, help="divider cycles per double of a packed division")
    ap.add_argument("--sqrt", type=float, default=2.234, help="divider cycles per double of a packed square root")
    ap.add_argument("--div-mul", type=float, default=3.22, help="multiply-pipe cycles of a division")
    ap.add_argument("--sqrt-mul", type=float, default=4.13, help="multiply-pipe cycles of a square root")
    ap.add_argument("--mcpu", default="znver3")
    ap.add_argument("--node-steps", type=float, default=2e6, help="node-steps counted per cell")
    ap.add_argument("--limits", help="CSVs this script wrote (one, or before,after): count nothing, tabulate")
    a = ap.parse_args()
    if a.limits:
        # One or two limit CSVs (before,after) with as many --measured sets (separated by ';'): a markdown
        # table, before and after side by side.
        lims = [list(csv.DictReader(open(f))) for f in a.limits.split(",")]
        meas = [measured(m) for m in (a.measured or "").split(";")] if a.measured else [{} for _ in lims]
        cols = ["instructions per node-step", "busiest unit", "limit [node-steps/s]", "measured", "of limit"]
        head = ["workload", "N", "nodes"] + [c + (f" ({k + 1})" if len(lims) > 1 else "") for k in range(len(lims))
                                              for c in cols]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for i, r in enumerate(lims[-1]):
            cells = [r["workload"], r["n"], r["nodes"]]
            for rows, m in zip(lims, meas):
                q = rows[i]
                lim, mv = float(q["limit_node_steps_per_s"]), m.get((q["workload"], int(q["n"])))
                cells += [f"{float(q['instructions_per_node_step']):.2f}", q["busiest"], f"{lim:.3e}",
                          f"{mv:.3e}" if mv else "-", f"{100 * mv / lim:.0f} %" if mv else "-"]
            print("| " + " | ".join(cells) + " |")
        return
    for tool in ("valgrind", "llvm-objdump", "llvm-mca"):
        if shutil.which(tool) is None:
            sys.exit(f"{tool} is not installed (Debian: apt-get install valgrind llvm)")
    prim = {"div": a.div, "sqrt": a.sqrt, "div_mul": a.div_mul, "sqrt_mul": a.sqrt_mul}
    ins = disassemble(a.binary)
    meas = measured(a.measured) if a.measured else {}
    cache = {}
    rows = []
    header = ["workload", "n", "nodes", "instructions_per_node_step", "outside_binary_share", "cycles_per_node_step",
              "busiest", "limit_node_steps_per_s", "measured_node_steps_per_s", "of_limit"] + \
             ["cycles_" + f.replace(" ", "_").replace("+", "_") for f, _ in FAMILIES] + ["cycles_divider", "cycles_dispatch"]
    print(f"{'workload':<20} {'N':>5} {'nodes':>6} {'instr/ns':>9} {'cycles':>7} {'busiest':<14} {'limit':>10} "
          f"{'measured':>10} {'of limit':>8}")
    with tempfile.TemporaryDirectory() as work:
        for cell in a.cells.split(","):
            name, n = cell.rsplit(":", 1)
            n = int(n)
            # nodes from a run of 0 steps (the line prints them; one wire has N + 1)
            line = run([a.binary, "bench", "--fixed", f"{name}:{n}:0"]).stdout
            m = re.search(r", (\d+) nodes", line)
            nodes = int(m.group(1)) if m else n + 1
            s1 = 20
            # (at most one episode of `ohl bench`, 4000 steps: longer undamped runs can go unstable)
            s2 = min(4000, s1 + max(20, int(a.node_steps / nodes)))
            c1, o1, _ = executions(a.binary, f"{name}:{n}", s1, work)
            c2, o2, _ = executions(a.binary, f"{name}:{n}", s2, work)
            ns = nodes * (s2 - s1)
            diff = {k: c2[k] - c1.get(k, 0) for k in c2 if c2[k] - c1.get(k, 0) > 0}
            cycles, busiest, pools, ipn = limit(diff, ns, ins, a.mcpu, prim, cache)
            outside = (o2 - o1) / ns
            lim = a.clock_ghz * 1e9 / cycles
            mv = meas.get((name, n))
            frac = mv / lim if mv else None
            print(f"{name:<20} {n:>5} {nodes:>6} {ipn + outside:>9.2f} {cycles:>7.2f} {busiest:<14} {lim:>10.4g} "
                  f"{(f'{mv:.4g}' if mv else '-'):>10} {(f'{100 * frac:.0f} %' if frac else '-'):>8}", flush=True)
            print("    cycles per node-step by pool: " + ", ".join(f"{k} {v:.2f}" for k, v in
                                                             sorted(pools.items(), key=lambda x: -x[1])), flush=True)
            rows.append([name, n, nodes, f"{ipn + outside:.4f}", f"{outside / (ipn + outside):.4f}", f"{cycles:.4f}",
                         busiest, f"{lim:.4e}", f"{mv:.4e}" if mv else "", f"{frac:.4f}" if frac else ""] +
                        [f"{pools.get(f, 0.0):.4f}" for f, _ in FAMILIES] +
                        [f"{pools.get('divider', 0.0):.4f}", f"{pools['dispatch']:.4f}"])
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)


if __name__ == "__main__":
    main()
