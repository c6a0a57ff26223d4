#!/usr/bin/env python3
"""CPU time of `ohl bench --fixed` workloads, binaries alternating: node-steps per CPU second, best of REPS.

Usage: app/benches/fixed_cpu.py BIN[,BIN...] CONFIG[,CONFIG...] N[,N...] REPS

Each cell runs `BIN bench --fixed CONFIG:N:STEPS` (STEPS = 4e7 node-steps / (N + 1), at most 4000 steps:
one episode of `ohl bench`, within which the undamped configurations stay stable) REPS times per binary,
the binaries one after the other in each repetition, and prints the best (least CPU time, user + system
from the child's rusage; set-up included, a few ms) as node-steps per second, with its ratio to the first
binary. Used for the 4K-aliasing sweep of issue 27's seventh round (figures/bench/README.md).
"""
import os
import subprocess
import sys

bins = sys.argv[1].split(",")
configs = sys.argv[2].split(",")
ns = [int(n) for n in sys.argv[3].split(",")]
reps = int(sys.argv[4])
for config in configs:
    for n in ns:
        steps = min(int(4e7 / (n + 1)), 4000)
        cpu = {b: [] for b in bins}
        for _ in range(reps):
            for b in bins:
                p = subprocess.Popen([b, "bench", "--fixed", f"{config}:{n}:{steps}"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                _, status, usage = os.wait4(p.pid, 0)
                if status != 0:
                    sys.exit(f"{b} bench --fixed {config}:{n}:{steps} failed (status {status})")
                cpu[b].append(usage.ru_utime + usage.ru_stime)
        first = min(cpu[bins[0]])
        cells = "".join(f"  {os.path.basename(b)} {steps * (n + 1) / min(cpu[b]):.3e} ({first / min(cpu[b]):.2f})"
                        for b in bins)
        print(f"{config:16s} N={n:5d} steps {steps:5d}{cells}", flush=True)
