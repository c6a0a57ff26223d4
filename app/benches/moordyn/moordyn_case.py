"""Side by side: the paper's weight release (paper_cases/fig2b_catenary.toml) in ohl and in MoorDyn.

The physical problem (paper section 4.2, Fig. 2b): a wire of span l = 160 m between two supports at the
same height, unstretched length equal to the span (straight start), 1.0 kg/m, EA = 792000.54 N,
Kelvin-Voigt friction eta = 316.76 N s, released at rest under gravity g = 9.81 m/s^2; 260.8 s simulated.

For each number of segments N this script
  1. computes a reference of the first --window-s seconds: the same chain integrated by MoorDyn RK4 at
     Courant 0.05, every step recorded (and ohl at Courant 0.05 against it: the two discretise the same
     ODE system);
  2. runs `OHL run` on a copy of the case with `segments = N` and `smoothing = 0` (MoorDyn has no velocity
     smoothing), and on the case as written, reading `cpu_time_s` (CPU time of the step loop); and
     once more without the time series' rows (`sample_interval_s` = the whole run), the counterpart of
     MoorDyn's timed run, which records nothing (the `*_no_rows` columns; the others keep the rows every
     0.02 s, as the case writes them);
  2b. runs ohl again (with and without rows) at its own largest stable Courant number: the derived Kelvin-Voigt limit
     sqrt(1 + z^2) - z (src/scheme/courant.rs, computed with the same operations), times --ohl-margin,
     checked on the whole run with the stability/energy criterion MoorDyn's step is held to, bisected
     below it if that fails;
  3. writes the problem as a MoorDyn v2 input (figures/bench/README.md: the mapping), finds MoorDyn's
     largest stable step dtM on this grid by bisection on the whole run, and times MoorDyn's step loop
     in-process (time.process_time around one Step call over the run);
  4. measures the mid-span sag error of both against the reference, finds the MoorDyn step that is as
     accurate as ohl (at Courant 0.5, and at ohl's limit) and times it too, and writes one CSV row.

Usage (run.sh calls it): python moordyn_case.py --ohl BIN --segments 50 100 200 --out DIR --csv FILE
"""

import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import moordyn

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
CASE = os.path.join(ROOT, "paper_cases", "fig2b_catenary.toml")

# The case's data (paper_cases/fig2b_catenary.toml; the script checks them against the file).
SPAN_M = 160.0
RHO_KG_PER_M = 1.0
EA_N = 792000.54
ETA_N_S = 316.76
G = 9.81
T_END_S = 260.8
# MoorDyn needs a diameter for its hydrodynamic terms, which are all switched off here (rho = 0, Cd =
# Ca = 0); any positive value gives the same motion. The value of README.md's example wire.
DIAMETER_M = 0.01553
# Output interval [s] (the case's sample_interval_s): the recorded MoorDyn run calls Step once per interval.
DT_OUT_S = 0.02


def check_case():
    """Fail loudly if the case file no longer holds the numbers this comparison assumes."""
    text = open(CASE).read()
    want = {
        "axial_stiffness_n": EA_N,
        "linear_density_kg_per_m": RHO_KG_PER_M,
        "gravity_m_per_s2": G,
        "eta_n_s": ETA_N_S,
        "end_time_s": T_END_S,
    }
    for key, value in want.items():
        m = re.search(r"^%s\s*=\s*([0-9.eE+-]+)" % key, text, re.M)
        if m is None or float(m.group(1)) != value:
            sys.exit("moordyn_case.py: %s: %s is not %r any more; update the script" % (CASE, key, value))
    if "right_support_m = [0.0, 160.0, 0.0]" not in text:
        sys.exit("moordyn_case.py: %s: the span is not 160 m along x2 any more" % CASE)


# ---------------------------------------------------------------------------------------------------
# ohl
# ---------------------------------------------------------------------------------------------------
def run_ohl(ohl, n, work, tag, smoothing=None, courant=None, end_time_s=None, rows=True, may_fail=False):
    """`ohl run` on a copy of the case with N segments (and the given smoothing, Courant number, end).

    rows=False: the time series' interval set to the whole run (its first and last rows only), the
    counterpart of MoorDyn's timed run, which records nothing; the peaks are still tracked every step.
    may_fail: return None instead of raising when ohl exits with an error (a stability probe)."""
    text = open(CASE).read()
    subs = [(r"^segments\s*=\s*\S+", "segments = %d" % n)]
    if not rows:
        subs.append((r"^sample_interval_s\s*=\s*\S+", "sample_interval_s = %r" % (end_time_s or T_END_S)))
    if smoothing is not None:
        subs.append((r"^smoothing\s*=\s*\S+", "smoothing = %r" % smoothing))
    if courant is not None:
        subs.append((r"^courant\s*=\s*\S+", "courant = %r" % courant))
    if end_time_s is not None:
        subs.append((r"^end_time_s\s*=\s*\S+", "end_time_s = %r" % end_time_s))
    for pattern, repl in subs:
        text, count = re.subn(pattern, repl, text, flags=re.M)
        assert count == 1, pattern
    toml = os.path.join(work, "%s_N%d.toml" % (tag, n))
    open(toml, "w").write(text)
    out = os.path.join(work, "%s_N%d" % (tag, n))
    done = subprocess.run([ohl, "run", toml, "--out", out, "--quiet"], check=not may_fail,
                          stdout=subprocess.DEVNULL if may_fail else None,
                          stderr=subprocess.DEVNULL if may_fail else None)
    if done.returncode != 0:
        return None
    summary = json.load(open(os.path.join(out, "summary.json")))
    ts = np.genfromtxt(os.path.join(out, "timeseries.csv"), delimiter=",", names=True)
    return summary, ts


# ---------------------------------------------------------------------------------------------------
# MoorDyn
# ---------------------------------------------------------------------------------------------------
MOORDYN_INPUT = """--------------------- MoorDyn Input File ------------------------------------
ohl paper_cases/fig2b_catenary.toml (paper 4.2, weight release) with {n} segments
---------------------- LINE TYPES -----------------------------------------------------
TypeName   Diam    Mass/m   EA        BA/-zeta  EI       Cd   Ca   CdAx  CaAx
(name)     (m)     (kg/m)   (N)       (N-s/-)   (N-m^2)  (-)  (-)  (-)   (-)
wire       {d}  {rho}  {ea}  {ba}  0.0  0.0  0.0  0.0  0.0
---------------------- POINTS ---------------------------------------------------------
ID  Attachment  X      Y    Z    Mass  Volume  CdA  Ca
(#) (word/ID)   (m)    (m)  (m)  (kg)  (m^3)   (m^2) (-)
1   Fixed       0.0    0.0  0.0  0.0   0.0     0.0  0.0
2   Fixed       {span}  0.0  0.0  0.0   0.0     0.0  0.0
---------------------- LINES ----------------------------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#) (name)    (ID)     (ID)     (m)       (-)      (-)
1   wire      1        2        {span}     {n}      -
---------------------- OPTIONS --------------------------------------------------------
0        writeLog
{scheme}  tScheme
{dtm!r}  dtM
{g}     g
0.0      rho
10000.0  WtrDpth
1        disableOutput
1        disableOutTime
------------------------- need this line ----------------------------------------------
"""


def write_moordyn_input(path, n, dtm, scheme):
    text = MOORDYN_INPUT.format(
        n=n, d=DIAMETER_M, rho=RHO_KG_PER_M, ea=EA_N, ba=ETA_N_S, span=SPAN_M, dtm=dtm, g=G, scheme=scheme
    )
    open(path, "w").write(text)


def set_straight(system, line, n):
    """Put the line's inner nodes on the straight chord, at rest.

    MoorDyn starts a line on its quasi-static catenary (Line::initialize, FAST v7's catenary routine)
    and has no call to set node positions; the paper's release starts from the straight chord. The
    state is serialized, every occurrence of an inner node's catenary position (in the time integrator's
    state and the line's own copy) replaced by the straight position, and the state restored. The
    serialized reals are IEEE-754 doubles (MoorDyn's io::IO pack754_64), little-endian.
    """
    words = np.frombuffer(moordyn.Serialize(system), dtype="<f8").copy()
    replaced = 0
    for i in range(1, n):
        old = np.asarray(moordyn.GetLineNodePos(line, i), dtype=float)
        new = np.array([SPAN_M * i / n, 0.0, 0.0])
        tol = 1e-9 * SPAN_M
        hits = np.where(
            (np.abs(words[:-2] - old[0]) < tol)
            & (np.abs(words[1:-1] - old[1]) < tol)
            & (np.abs(words[2:] - old[2]) < tol)
        )[0]
        for k in hits:
            words[k : k + 3] = new
        replaced += len(hits)
    moordyn.Deserialize(system, words.tobytes())
    for i in range(n + 1):
        p = np.asarray(moordyn.GetLineNodePos(line, i))
        if np.max(np.abs(p - [SPAN_M * i / n, 0.0, 0.0])) > 1e-12 * SPAN_M:
            raise RuntimeError("node %d is not on the chord after the state was restored: %s" % (i, p))
    return replaced


class quiet_stdout:
    """Sends file descriptor 1 (and 2 if asked) to /dev/null: MoorDyn prints its input echo from C++ on
    Create/Init, and every node on a NaN (which the stability probes provoke on purpose)."""

    def __init__(self, fds=(1,)):
        self.fds = fds

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = [os.dup(fd) for fd in self.fds]
        null = os.open(os.devnull, os.O_WRONLY)
        for fd in self.fds:
            os.dup2(null, fd)
        os.close(null)

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        for fd, saved in zip(self.fds, self.saved):
            os.dup2(saved, fd)
            os.close(saved)


def line_energy(line, n):
    """Kinetic + elastic + gravitational energy of the line [J], zero for the straight chord at rest.

    Lumped node masses rho ds0 (end nodes: fixed), tension-only segments EA eps^2 ds0 / 2 (MoorDyn's
    Line: no compression), weight at the nodes; the same terms as ohl's total_j.
    """
    ds0 = SPAN_M / n
    r = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
    v = np.array([moordyn.GetLineNodeVel(line, i) for i in range(1, n)])
    kinetic = 0.5 * RHO_KG_PER_M * ds0 * np.sum(v * v)
    eps = np.maximum(np.linalg.norm(np.diff(r, axis=0), axis=1) / ds0 - 1.0, 0.0)
    elastic = 0.5 * EA_N * ds0 * np.sum(eps * eps)
    gravity = RHO_KG_PER_M * ds0 * G * np.sum(r[1:-1, 2])
    return kinetic + elastic + gravity


def run_moordyn(n, dtm, t_end, work, scheme, record, out_dt=DT_OUT_S, energy_dt=0.1):
    """One MoorDyn release from the straight chord with steps of dtm [s] for about t_end seconds.

    record=False (the timed run): one Step call over K dtm, K = round(t_end / dtm): MoorDyn's own loop
    of K steps (MoorDyn::Step steps dtM until the interval is covered), so the CPU time measured is its
    step loop alone, without Python between steps. record=True: Step calls of m dtm each, m =
    round(out_dt / dtm), the mid-span node read after each and the energy every energy_dt (not timed).

    Returns a dict: cpu [s] (process time of the Step calls), simulated [s], steps, times and mid (the
    mid-span node's z at each output), energy_max [J] (largest sampled energy, the final one when not
    recording), ok (finite, bounded, in the vertical plane).
    """
    path = os.path.join(work, "moordyn_N%d.txt" % n)
    write_moordyn_input(path, n, dtm, scheme)
    big_k = int(round(t_end / dtm))
    m = max(1, int(round(out_dt / dtm))) if record else big_k
    chunks = big_k // m
    every = max(1, int(round(energy_dt / (m * dtm))))
    cwd = os.getcwd()
    os.chdir(work)  # MoorDyn writes its (disabled) outputs next to the input
    try:
        x = np.zeros(0)
        v = np.zeros(0)
        with quiet_stdout():
            system = moordyn.Create(path)
            moordyn.Init_NoIC(system, x, v)
        line = moordyn.GetLine(system, 1)
        set_straight(system, line, n)
        mid = np.full(chunks + 1, np.nan)
        mid[0] = 0.0
        energy_max = 0.0
        ok = True
        cpu0 = time.process_time()
        try:
            for k in range(chunks):
                moordyn.Step(system, x, v, k * m * dtm, m * dtm)
                if record:
                    mid[k + 1] = moordyn.GetLineNodePos(line, n // 2)[2]
                    if (k + 1) % every == 0:
                        energy_max = max(energy_max, line_energy(line, n))
        except RuntimeError:
            # MoorDyn stops with "MoorDyn reported an error integrating" when a state is not finite
            ok = False
        cpu = time.process_time() - cpu0
        try:
            nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])
            energy_max = max(energy_max, line_energy(line, n))
        except RuntimeError:
            nodes = np.full((n + 1, 3), np.nan)
            ok = False
        with quiet_stdout():
            moordyn.Close(system)
    finally:
        os.chdir(cwd)
    if not ok or not np.all(np.isfinite(nodes)) or not math.isfinite(energy_max):
        ok = False
    elif record and not np.all(np.isfinite(mid)):
        ok = False
    elif np.max(np.abs(nodes[:, 2])) > 0.5 * SPAN_M or np.max(np.abs(nodes[:, 1])) > 1e-6 * SPAN_M:
        ok = False
    return {
        "cpu": cpu,
        "simulated": chunks * m * dtm,
        "steps": chunks * m,
        "times": np.arange(chunks + 1) * m * dtm,
        "mid": mid,
        "energy_max": energy_max,
        "ok": ok,
    }


# Energy tolerance [J]: the release starts at E = 0 and Kelvin-Voigt friction only removes energy, so a
# sampled energy above 1e-3 of w l sag (w l sag = 11.4 kJ, the scale of the potential energy released)
# is energy put in by the time integration: an unstable step.
ENERGY_TOL_J = 1e-3 * RHO_KG_PER_M * G * SPAN_M * 7.26


def md_stable(n, dtm, work, scheme):
    with quiet_stdout((1, 2)):
        r = run_moordyn(n, dtm, T_END_S, work, scheme, record=False)
    return r["ok"] and r["energy_max"] <= ENERGY_TOL_J


def stable_dtm(n, work, scheme):
    """Largest dtM [s] for which the whole release (T_END_S) stays stable, by bisection.

    MoorDyn's explicit schemes have no fixed Courant limit here: RK2 amplifies an undamped oscillation
    by sqrt(1 + (w dt)^4 / 4) per step, so its short waves are held only by the internal damping BA,
    and a step that looks stable for 10 s may blow up after 16 s or grow for 200 s without a NaN (seen
    at N = 50). A step is therefore called stable when the whole run stays finite (MoorDyn raises an
    error on a NaN), within 0.5 span of the chord vertically and in the vertical plane, and ends with an
    energy at most ENERGY_TOL_J (an unstable mode pumps energy in). Bisection on the Courant number
    c dt / ds between 0.1 and 2, 8 halvings (resolution 0.0074). The caller then checks the energy
    along the whole recorded run.
    """
    c = math.sqrt(EA_N / RHO_KG_PER_M)
    ds = SPAN_M / n
    lo, hi = 0.1, 2.0
    assert md_stable(n, lo * ds / c, work, scheme)
    for _ in range(8):
        mid = 0.5 * (lo + hi)
        stable = md_stable(n, mid * ds / c, work, scheme)
        print("  N=%d MoorDyn %s Courant %.4f: %s" % (n, scheme, mid, "stable" if stable else "unstable"),
              flush=True)
        if stable:
            lo = mid
        else:
            hi = mid
    return lo * ds / c, lo


def ohl_courant_limit(n):
    """ohl's derived stability limit C_max = sqrt(1 + z^2) - z for this chain (src/scheme/courant.rs).

    The same IEEE operations in the same order as validate.rs: c = sqrt(EA / rho0), ds = l / N,
    z = eta c / (EA ds), C_max = 1 / (sqrt(1 + z^2) + z); so a Courant number of exactly C_max is
    accepted by ohl's validation (it refuses C > C_max).
    """
    c = math.sqrt(EA_N / RHO_KG_PER_M)
    ds = SPAN_M / n
    z = ETA_N_S * c / (EA_N * ds)
    return 1.0 / (math.sqrt(1.0 + z * z) + z)


def ohl_stable(ohl, n, courant, work):
    """The whole ohl release (smoothing 0, T_END_S) at `courant` passes MoorDyn's criterion: it runs to
    the end, every output row is finite, the mid-span node stays within 0.5 span of the chord vertically
    and in the vertical plane (x1 = 0), and the energy total_j (sampled every 0.02 s, every row) never
    exceeds ENERGY_TOL_J. Returns (stable, largest energy [J])."""
    got = run_ohl(ohl, n, work, "ohl_probe", smoothing=0.0, courant=courant, may_fail=True)
    if got is None:
        return False, math.inf
    summary, ts = got
    cols = [ts["mid_dx1_m"], ts["mid_dx3_m"], ts["total_j"]]
    if not all(np.all(np.isfinite(col)) for col in cols) or summary["final_time_s"] < T_END_S - 1e-6:
        return False, math.inf
    energy_max = float(np.max(ts["total_j"]))
    ok = (np.max(np.abs(ts["mid_dx3_m"])) <= 0.5 * SPAN_M and np.max(np.abs(ts["mid_dx1_m"])) <= 1e-6 * SPAN_M
          and energy_max <= ENERGY_TOL_J)
    return bool(ok), energy_max


def ohl_stable_courant(ohl, n, work, margin):
    """ohl's largest stable Courant number on the whole run: margin * C_max when that passes
    ohl_stable, else a bisection between the paper's 0.5 and it (8 halvings), as for MoorDyn's step.
    Returns (Courant number used, derived C_max, energy max of the check [J])."""
    c_max = ohl_courant_limit(n)
    top = margin * c_max
    ok, energy = ohl_stable(ohl, n, top, work)
    print("  N=%d ohl Courant %.6f (%.4g x the derived limit %.6f): %s, energy max %.3g J"
          % (n, top, margin, c_max, "stable" if ok else "unstable", energy), flush=True)
    if ok:
        return top, c_max, energy
    lo, hi = 0.5, top
    assert ohl_stable(ohl, n, lo, work)[0]
    for _ in range(8):
        mid = 0.5 * (lo + hi)
        ok, _ = ohl_stable(ohl, n, mid, work)
        print("  N=%d ohl Courant %.4f: %s" % (n, mid, "stable" if ok else "unstable"), flush=True)
        if ok:
            lo = mid
        else:
            hi = mid
    return lo, c_max, ohl_stable(ohl, n, lo, work)[1]


# Order of accuracy of MoorDyn's explicit schemes (docs/tschemes.rst of MoorDyn)
ORDER = {"EULER": 1, "HEUN": 2, "RK2": 2, "RK3": 3, "RK4": 4, "AB2": 2, "AB3": 3, "AB4": 4}


def window_error(t, sag, ref_t, ref_sag, t_win):
    """max over t <= t_win of |sag - reference| [m], the reference interpolated to t (it is dense)."""
    keep = t <= t_win + 1e-9
    return float(np.max(np.abs(sag[keep] - np.interp(t[keep], ref_t, ref_sag))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ohl", required=True, help="the ohl binary to compare")
    ap.add_argument("--segments", type=int, nargs="+", default=[50, 100, 200, 300])
    ap.add_argument("--scheme", default="RK2", help="MoorDyn tScheme (default RK2, MoorDyn's default)")
    ap.add_argument("--margin", type=float, default=1.0,
                    help="dtM = margin * the largest stable dtM found (default 1: the fastest MoorDyn)")
    ap.add_argument("--ohl-margin", type=float, default=1.0,
                    help="ohl's Courant number = margin * its derived limit sqrt(1 + z^2) - z, checked on "
                         "the whole run (default 1: at the limit)")
    ap.add_argument("--reps", type=int, default=3, help="timed repetitions of each run; the fastest counts")
    ap.add_argument("--window-s", type=float, default=8.0,
                    help="window of the trajectory error: the fall, the first peak, a few swings [s]")
    ap.add_argument("--out", required=True, help="work directory")
    ap.add_argument("--csv", required=True, help="CSV to write")
    args = ap.parse_args()

    check_case()
    os.makedirs(args.out, exist_ok=True)
    from importlib.metadata import version

    cpu_model = "unknown"
    if os.path.exists("/proc/cpuinfo"):
        for cpu_line in open("/proc/cpuinfo"):
            if cpu_line.startswith("model name"):
                cpu_model = cpu_line.split(":", 1)[1].strip()
                break
    ohl_sha = subprocess.run(["sha256sum", args.ohl], capture_output=True, text=True).stdout.split(" ")[0]
    context = {"moordyn_version": version("moordyn"), "ohl_sha256": ohl_sha[:16], "cpu": cpu_model}
    print("MoorDyn %s, ohl %s (sha256 %s), %s" % (context["moordyn_version"], args.ohl, ohl_sha[:16], cpu_model))
    c = math.sqrt(EA_N / RHO_KG_PER_M)
    rows = []
    for n in args.segments:
        assert n % 2 == 0, "an even number of segments has a mid-span node"
        ds = SPAN_M / n

        # Reference of the window: the same semi-discrete chain, MoorDyn RK4 at Courant 0.05, every step
        # recorded; and ohl at Courant 0.05 as a check that both codes discretise the same ODE system.
        ref = run_moordyn(n, 0.05 * ds / c, args.window_s, args.out, "RK4", record=True, out_dt=0.0)
        ref_t, ref_sag = ref["times"], -ref["mid"]
        ref_peak = float(np.max(ref_sag))
        _, ts_fine = run_ohl(args.ohl, n, args.out, "ohl_fine", smoothing=0.0, courant=0.05,
                             end_time_s=args.window_s)
        ohl_fine_err = window_error(ts_fine["t_s"], -ts_fine["mid_dx3_m"], ref_t, ref_sag, args.window_s)

        # ohl: the equivalent scenario (smoothing 0: MoorDyn has no such term) and the paper's case as
        # written; fastest of reps (cpu_time_s: the step loop)
        def fastest(**kw):
            best = None
            for _ in range(args.reps):
                summary, ts = run_ohl(args.ohl, n, args.out, **kw)
                if best is None or summary["cpu_time_s"] < best[0]["cpu_time_s"]:
                    best = (summary, ts)
            return best

        def fastest_moordyn(dtm):
            """MoorDyn's whole run at step `dtm`, the fastest of the repetitions."""
            best = None
            for _ in range(args.reps):
                r = run_moordyn(n, dtm, T_END_S, args.out, args.scheme, record=False)
                assert r["ok"]
                if best is None or r["cpu"] < best["cpu"]:
                    best = r
            return best

        summary, ts = fastest(tag="ohl", smoothing=0.0)
        quiet_summary, _ = fastest(tag="ohl_quiet", smoothing=0.0, rows=False)
        paper_summary, _ = fastest(tag="ohl_paper")
        ohl_cpu = summary["cpu_time_s"]
        ohl_node_steps = summary["steps"] * (n + 1)
        ohl_err = window_error(ts["t_s"], -ts["mid_dx3_m"], ref_t, ref_sag, args.window_s)
        ohl_energy_max = float(np.max(ts["total_j"]))

        # ohl at its own largest stable Courant number (checked on the whole run like MoorDyn's step)
        lim_courant, lim_derived, lim_check_energy = ohl_stable_courant(args.ohl, n, args.out, args.ohl_margin)
        lim_summary, lim_ts = fastest(tag="ohl_limit", smoothing=0.0, courant=lim_courant)
        lim_quiet, _ = fastest(tag="ohl_limit_quiet", smoothing=0.0, courant=lim_courant, rows=False)
        assert quiet_summary["steps"] == summary["steps"] and lim_quiet["steps"] == lim_summary["steps"]
        lim_err = window_error(lim_ts["t_s"], -lim_ts["mid_dx3_m"], ref_t, ref_sag, args.window_s)

        # MoorDyn: the largest stable step; the recorded run must keep the energy down too
        dtm_max, courant_max = stable_dtm(n, args.out, args.scheme)
        dtm = args.margin * dtm_max
        while True:
            rec = run_moordyn(n, dtm, T_END_S, args.out, args.scheme, record=True)
            if rec["ok"] and rec["energy_max"] <= ENERGY_TOL_J:
                break
            print("  N=%d MoorDyn dtM %.4g s: energy %.3g J along the run; step lowered by 3 %%"
                  % (n, dtm, rec["energy_max"]), flush=True)
            dtm *= 0.97
        md = fastest_moordyn(dtm)
        md_cpu = md["cpu"]
        md_per_sim = md_cpu / md["simulated"]
        md_err = window_error(rec["times"], -rec["mid"], ref_t, ref_sag, args.window_s)

        # MoorDyn at ohl's error: a step smaller by (target / md_err)^(1/order), lowered by 10 % until
        # its window error is at most the target, then timed on the whole run. When MoorDyn is already
        # at least as accurate its stable step stands.
        def moordyn_at_error(target):
            eq_dtm, eq_err, eq = dtm, md_err, md
            if md_err > target:
                eq_dtm = dtm * (target / md_err) ** (1.0 / ORDER.get(args.scheme.upper(), 1)) * 0.98
                while True:
                    w = run_moordyn(n, eq_dtm, args.window_s, args.out, args.scheme, record=True)
                    eq_err = window_error(w["times"], -w["mid"], ref_t, ref_sag, args.window_s)
                    if w["ok"] and eq_err <= target:
                        break
                    eq_dtm *= 0.9
                eq = fastest_moordyn(eq_dtm)
            return eq_dtm, eq_err, eq["cpu"] / eq["simulated"]

        eq_dtm, eq_err, eq_per_sim = moordyn_at_error(ohl_err)
        if lim_err == ohl_err:
            lim_eq_dtm, lim_eq_err, lim_eq_per_sim = eq_dtm, eq_err, eq_per_sim
        else:
            lim_eq_dtm, lim_eq_err, lim_eq_per_sim = moordyn_at_error(lim_err)
        lim_per_sim = lim_summary["cpu_time_s"] / T_END_S

        row = {
            "segments": n,
            "simulated_s": T_END_S,
            "ohl_dt_s": summary["dt_s"],
            "ohl_courant": summary["courant"],
            "ohl_steps": summary["steps"],
            "ohl_cpu_s": ohl_cpu,
            "ohl_cpu_s_per_simulated_s": ohl_cpu / T_END_S,
            "ohl_node_steps_per_cpu_s": ohl_node_steps / ohl_cpu,
            "ohl_paper_case_cpu_s": paper_summary["cpu_time_s"],
            "moordyn_scheme": args.scheme,
            "moordyn_courant_stable_max": courant_max,
            "moordyn_dt_s": dtm,
            "moordyn_courant": dtm * c / ds,
            "moordyn_steps": md["steps"],
            "moordyn_simulated_s": md["simulated"],
            "moordyn_cpu_s": md_cpu,
            "moordyn_cpu_s_per_simulated_s": md_per_sim,
            "moordyn_node_steps_per_cpu_s": md["steps"] * (n + 1) / md_cpu,
            "ratio_cpu_per_simulated_s": md_per_sim / (ohl_cpu / T_END_S),
            "moordyn_equal_error_dt_s": eq_dtm,
            "moordyn_equal_error_window_rel_err": eq_err / ref_peak,
            "moordyn_equal_error_cpu_s_per_simulated_s": eq_per_sim,
            "ratio_at_equal_error": eq_per_sim / (ohl_cpu / T_END_S),
            "window_s": args.window_s,
            "reference_peak_sag_m": ref_peak,
            "ohl_window_err_m": ohl_err,
            "moordyn_window_err_m": md_err,
            "ohl_window_rel_err": ohl_err / ref_peak,
            "moordyn_window_rel_err": md_err / ref_peak,
            "ohl_fine_window_err_m": ohl_fine_err,
            "ohl_energy_max_j": ohl_energy_max,
            "moordyn_energy_max_j": rec["energy_max"],
            "ohl_limit_courant_derived": lim_derived,
            "ohl_limit_courant": lim_summary["courant"],
            "ohl_limit_dt_s": lim_summary["dt_s"],
            "ohl_limit_steps": lim_summary["steps"],
            "ohl_limit_cpu_s": lim_summary["cpu_time_s"],
            "ohl_limit_cpu_s_per_simulated_s": lim_per_sim,
            "ohl_limit_node_steps_per_cpu_s": lim_summary["steps"] * (n + 1) / lim_summary["cpu_time_s"],
            "ohl_limit_window_rel_err": lim_err / ref_peak,
            "ohl_limit_energy_max_j": float(np.max(lim_ts["total_j"])),
            "ratio_at_own_limits": md_per_sim / lim_per_sim,
            "moordyn_equal_error_limit_dt_s": lim_eq_dtm,
            "moordyn_equal_error_limit_window_rel_err": lim_eq_err / ref_peak,
            "moordyn_equal_error_limit_cpu_s_per_simulated_s": lim_eq_per_sim,
            "ratio_at_equal_error_limit": lim_eq_per_sim / lim_per_sim,
            # Without the time series' rows (every 0.02 s: the energies and the CSV formatting), as
            # MoorDyn's timed run records nothing.
            "ohl_cpu_s_no_rows": quiet_summary["cpu_time_s"],
            "ratio_cpu_per_simulated_s_no_rows": md_per_sim / (quiet_summary["cpu_time_s"] / T_END_S),
            "ohl_limit_cpu_s_no_rows": lim_quiet["cpu_time_s"],
            "ratio_at_own_limits_no_rows": md_per_sim / (lim_quiet["cpu_time_s"] / T_END_S),
            "load_avg_1min": os.getloadavg()[0],
            **context,
        }
        rows.append(row)
        print(
            "N=%d  ohl %.4f s (%.3g node-steps/s, paper case %.4f s)  MoorDyn %s Courant %.3f (stable max "
            "%.3f) %.3f s (%.3g node-steps/s)  ratio %.1f  window error ohl %.2e MoorDyn %.2e (ohl fine "
            "%.1e m)  energy max ohl %.3g J MoorDyn %.3g J  at ohl's error: MoorDyn dt %.3g s, ratio %.1f"
            % (n, ohl_cpu, row["ohl_node_steps_per_cpu_s"], paper_summary["cpu_time_s"], args.scheme,
               row["moordyn_courant"], courant_max, md_cpu, row["moordyn_node_steps_per_cpu_s"],
               row["ratio_cpu_per_simulated_s"], row["ohl_window_rel_err"], row["moordyn_window_rel_err"],
               ohl_fine_err, ohl_energy_max, rec["energy_max"], eq_dtm, row["ratio_at_equal_error"]),
            flush=True,
        )
        print(
            "N=%d  ohl at its limit: Courant %.4f (derived %.4f) %.4f s (%.3g node-steps/s)  error %.2e  "
            "ratio at own limits %.1f  MoorDyn at this error: dt %.3g s, ratio %.1f"
            % (n, row["ohl_limit_courant"], lim_derived, row["ohl_limit_cpu_s"],
               row["ohl_limit_node_steps_per_cpu_s"], row["ohl_limit_window_rel_err"],
               row["ratio_at_own_limits"], lim_eq_dtm, row["ratio_at_equal_error_limit"]),
            flush=True,
        )
        print(
            "N=%d  ohl without the time series' rows (as MoorDyn's timed run): Courant 0.5 %.4f s, ratio %.1f;"
            "  at its limit %.4f s, ratio at own limits %.1f"
            % (n, row["ohl_cpu_s_no_rows"], row["ratio_cpu_per_simulated_s_no_rows"],
               row["ohl_limit_cpu_s_no_rows"], row["ratio_at_own_limits_no_rows"]),
            flush=True,
        )
        # Written after every N, so that a run stopped before the largest N keeps the rows it has.
        write_csv(args.csv, rows)
    print("wrote", args.csv)


def write_csv(path, rows):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        wr.writeheader()
        for row in rows:
            wr.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in row.items()})


if __name__ == "__main__":
    main()
