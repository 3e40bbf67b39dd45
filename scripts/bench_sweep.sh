#!/usr/bin/env bash
# Thread scaling of the Monte Carlo runner: the smoke sweep (experiments/sweeps/smoke.yaml)
# run from scratch with 1 thread and with 2 threads, REPEATS times each, alternating;
# trials per second from the wall time of each whole run. Writes
# sweep_threads.json (every run) and sweep_threads.md (medians, the ratio and
# the target: 2 threads give >= 1.8x the trials per second of 1 thread).
# Environment: MACHINE (default debian12-2core), BUILD (default build), REPEATS (default 3).
# About 4 minutes per repeat on 2 cores.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
bench_prepare rearm
REPEATS=${REPEATS:-3}
SWEEP=experiments/sweeps/smoke.yaml
WORK=$(mktemp -d)
trap 'rm -rf "$WORK" "$OUT"' EXIT
RUNS="$WORK/runs.txt"
for r in $(seq 1 "$REPEATS"); do
  for t in 1 2; do
    dir="$WORK/t${t}_r${r}"
    start=$(date +%s.%N)
    "$(bench_bin rearm)" sweep "$SWEEP" --out "$dir" --threads "$t" --quiet > /dev/null
    end=$(date +%s.%N)
    trials=$(($(wc -l < "$dir/trials.csv") - 1))
    echo "$t $r $trials $start $end" >> "$RUNS"
    echo "threads $t repeat $r: $trials trials in $(awk "BEGIN {print $end - $start}") s"
  done
done
python3 - "$RUNS" "$OUT" "$REV" "$LOAD" "$(nproc)" "$SWEEP" <<'PYTHON'
import json, statistics, sys, datetime
runs_file, out, rev, load, nproc, sweep = sys.argv[1:7]
runs = []
for line in open(runs_file):
    t, r, trials, start, end = line.split()
    wall = float(end) - float(start)
    runs.append({"threads": int(t), "repeat": int(r), "trials": int(trials), "wall_s": wall,
                 "trials_per_s": int(trials) / wall})
med = {t: statistics.median(x["trials_per_s"] for x in runs if x["threads"] == t) for t in (1, 2)}
ratio = med[2] / med[1]
doc = {"sweep": sweep, "revision": rev, "load_at_start": load, "cores": int(nproc),
       "date": datetime.date.today().isoformat(), "runs": runs,
       "median_trials_per_s": {str(k): v for k, v in med.items()}, "ratio_2_over_1": ratio,
       "target": ">= 1.8", "met": ratio >= 1.8}
json.dump(doc, open(f"{out}/sweep_threads.json", "w"), indent=2)
lines = [
    "# Monte Carlo runner: thread scaling on the smoke sweep", "",
    f"{doc['date']}, {nproc} cores, revision `{rev}`, load average {load} at the start; "
    f"`{sweep}` run from scratch, alternating 1 and 2 threads, {len(runs) // 2} times each. "
    "Trials per second = trials / wall time of the whole run (instance generation included).", "",
    "| threads | runs | median trials/s |", "|---|---|---|",
]
for t in (1, 2):
    lines.append(f"| {t} | {sum(1 for x in runs if x['threads'] == t)} | {med[t]:.3f} |")
lines += ["", f"Ratio 2 threads / 1 thread: **{ratio:.2f}** (target >= 1.8: "
          f"{'MET' if ratio >= 1.8 else 'MISSED'})."]
open(f"{out}/sweep_threads.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PYTHON
bench_publish
