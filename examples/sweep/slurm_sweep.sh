#!/usr/bin/env bash
# A sweep on a Slurm cluster (docs/sweeps.md, "Shards and Slurm"): a job array runs the shards, one array
# task per shard (`--shard $SLURM_ARRAY_TASK_ID/N`, tasks numbered 0 to N-1), and a job that waits for the
# whole array merges their tables into OUT/sweep.csv.
#
# Run it on the login node, from the repository root, after building the binary once:
#   cargo build --release --bin ohl
#   SHARDS=20 THREADS=8 OUT=/scratch/$USER/wind_sweep examples/sweep/slurm_sweep.sh
# Settings (environment variables, defaults below): OHL the binary, BASE the base scenario, OUT the output
# directory (on a file system the compute nodes share), SHARDS the number N of array tasks, THREADS the
# cores of each task (its --cpus-per-task and the sweep's --threads), TIME each task's time limit, and the
# varied fields in VARY below (edit them; values with spaces belong in a cases file, --cases FILE).
#
# Each task writes OUT/sweep.K-of-N.csv and OUT/sweep.K-of-N.json and its log OUT/logs/shard_K.out. The
# merge runs when every task has ended, whatever their exit (afterany): if a task failed or ran out of
# time, the merge exits 2 and lists the missing cases in OUT/logs/merge.out; resubmit that task alone,
#   sbatch --array=K OUT/logs/shards.sh
# then merge again: `ohl sweep merge OUT`. A shard writes its table when all its cases are done, so give
# TIME room (about cases/N x the time of one case / THREADS, which a short local run shows).
set -euo pipefail

OHL=${OHL:-$PWD/target/release/ohl}
BASE=${BASE:-$PWD/examples/sweep/drake_400m_wind.toml}
OUT=${OUT:-$PWD/out/sweep_slurm}
SHARDS=${SHARDS:-10}
THREADS=${THREADS:-4}
TIME=${TIME:-01:00:00}
VARY=(--vary loads.wind.speed_m_per_s=10:29.5:0.5 --vary numerics.mu=0:0.96:0.04)

mkdir -p "$OUT/logs"
# The array job's script, kept in OUT/logs so that a task can be resubmitted alone. $SLURM_ARRAY_TASK_ID
# and $SLURM_CPUS_PER_TASK are read when the task runs; everything else is filled in now.
cat > "$OUT/logs/shards.sh" <<EOF
#!/usr/bin/env bash
#SBATCH --job-name=ohl-sweep
#SBATCH --array=0-$((SHARDS - 1))
#SBATCH --cpus-per-task=$THREADS
#SBATCH --ntasks=1
#SBATCH --time=$TIME
#SBATCH --output=$OUT/logs/shard_%a.out
set -euo pipefail
$(printf '%q ' "$OHL" sweep "$BASE" "${VARY[@]}") \\
  --shard "\$SLURM_ARRAY_TASK_ID/$SHARDS" --threads "\${SLURM_CPUS_PER_TASK:-1}" --out $(printf '%q' "$OUT")
EOF
cat > "$OUT/logs/merge.sh" <<EOF
#!/usr/bin/env bash
#SBATCH --job-name=ohl-sweep-merge
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
#SBATCH --time=00:10:00
#SBATCH --output=$OUT/logs/merge.out
set -euo pipefail
$(printf '%q ' "$OHL" sweep merge "$OUT")
EOF

array=$(sbatch --parsable "$OUT/logs/shards.sh")
array=${array%%;*}   # --parsable prints JOBID or JOBID;CLUSTER
merge=$(sbatch --parsable --dependency="afterany:$array" "$OUT/logs/merge.sh")
echo "submitted the array job $array ($SHARDS shards, $THREADS core(s) each) and the merge job ${merge%%;*}"
echo "results: $OUT/sweep.csv once the merge has run (log: $OUT/logs/merge.out)"
