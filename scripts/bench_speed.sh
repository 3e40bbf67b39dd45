#!/usr/bin/env bash
# Side by side with an earlier revision, in one run (docs/reactive.md §2): the rearm command on
# a fixed set of scaling-sweep instances and fig5, the reactive benchmarks and the topology
# check at 10 objects x 20 obstacles (cold and warm cache), each alternating old and new binaries
# so that both see the same machine load. Writes results/$MACHINE/speed/{trials.csv,trials.md,
# reactive_old.json,reactive_new.json,topology_old.json,topology_new.json}.
#
# Usage: bash scripts/bench_speed.sh OLD_REVISION   (e.g. b353188)
# The old revision is built in a git worktree under build-old/ (Release, rearm and
# reactive_bench only; about 15 min on 2 cores the first time). Environment: MACHINE (default
# debian12-2core), BUILD (default build), OLD_BUILD (an existing build of the old revision,
# skips the worktree; it needs bin/rearm, bin/reactive_bench and bin/topology_bench). The instances are results/$MACHINE/speed/instances/,
# nine of the scaling sweep's (experiments/sweeps/scaling.yaml) across N and density; the
# old binary takes about 1 min on them (three runs each: about 6 min in all).
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
OLD_REV=${1:?usage: bench_speed.sh [--commit] OLD_REVISION}
bench_prepare reactive_bench rearm topology_bench
SPEED="$OUT/speed"
mkdir -p "$SPEED"
INSTANCES="results/$MACHINE/speed/instances"  # committed inputs, read in place
if [ -z "${OLD_BUILD:-}" ]; then  # OLD_BUILD: an existing Release build of OLD_REVISION
  WORK=build-old
  if [ ! -d "$WORK/src" ]; then
    git worktree add -f "$WORK/src" "$OLD_REV"
  fi
  git -C "$WORK/src" checkout -q --detach "$OLD_REV"
  cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF \
    -DREARM_BUILD_BENCH=ON > /dev/null
  cmake --build "$WORK/build" --target rearm reactive_bench topology_bench -j"$(nproc)"
  OLD_BUILD="$WORK/build"
fi
OLD="$OLD_BUILD/bin"
NEW="$BUILD/bin"

TMP=$(mktemp -d)
trap 'rm -rf "$TMP" "$OUT"' EXIT
echo "instance,version,status,sim_time_s,rebuilds,controller_time_s,trajectory_sha256" \
  > "$SPEED/trials.csv"
run() {  # version binary scenario-file name
  "$2/rearm" run "$3" --out "$TMP/$1/$4" --no-animation --no-plot > /dev/null
  python3 - "$TMP/$1/$4" "$4" "$1" >> "$SPEED/trials.csv" <<'PY'
import hashlib, json, sys
d, name, version = sys.argv[1:4]
m = json.load(open(f"{d}/metrics.json"))
h = hashlib.sha256(open(f"{d}/trajectory.json", "rb").read()).hexdigest()[:16]
print(f"{name},{version},{m['status']},{m['sim_time_s']:.2f},{m['rebuilds']},"
      f"{m['controller_time_s']:.4f},{h}")
PY
}
# Three alternating runs of each (the table takes the fastest): single runs on a shared VM
# varied by up to 1.4x between two invocations.
for k in 1 2 3; do
  for f in "$INSTANCES"/*.yaml experiments/scenarios/fig5.yaml; do
    n=$(basename "$f" .yaml)
    run old "$OLD" "$f" "$n"
    run new "$NEW" "$f" "$n"
  done
done

# bench_pair PROGRAM NAME FILTER: PROGRAM of the old then the new build, medians of 3 repetitions
# into $SPEED/NAME_{old,new}.json.
bench_pair() {
  for v in old new; do
    bin=$([ "$v" = old ] && echo "$OLD" || echo "$NEW")
    "$bin/$1" --benchmark_filter="$3" --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true --benchmark_out="$SPEED/$2_$v.json" \
      --benchmark_out_format=json --benchmark_context=revision="$([ "$v" = old ] && echo "$OLD_REV" || echo "$REV")" > /dev/null
    bench_fresh "$SPEED/$2_$v.json" "$bin/$1"
  done
}
bench_pair reactive_bench reactive \
  '(MappedSpace|DiffeoConstruction|ReactiveRebuild|UnicycleCommand)/K:(10|20)/'
bench_pair topology_bench topology \
  'BM_Topology(FarCorner|InsideObject)(Cached)?/objects:10/obstacles:20/'

python3 - "$SPEED" "$OLD_REV" "$REV" "$LOAD" <<'PY'
import csv, json, sys
speed, old_rev, rev, load = sys.argv[1:5]
rows = list(csv.DictReader(open(f"{speed}/trials.csv")))
by = {}
for r in rows:
    by.setdefault(r["instance"], {}).setdefault(r["version"], []).append(r)
out = [f"# Side by side: {old_rev} (old) and {rev} (new), one run (load {load})", "",
       "`bash scripts/bench_speed.sh " + old_rev + "`. Controller time: the fastest of the runs.", "",
       "| instance | status old / new | simulated s | rebuilds | controller old | new | ratio | same trajectory |",
       "|---|---|---|---|---|---|---|---|"]
for name, v in by.items():
    o, n = v["old"], v["new"]
    to = min(float(r["controller_time_s"]) for r in o)
    tn = min(float(r["controller_time_s"]) for r in n)
    same = o[0]["trajectory_sha256"] == n[0]["trajectory_sha256"]
    out.append(f"| {name} | {o[0]['status']} / {n[0]['status']} | {o[0]['sim_time_s']} / "
               f"{n[0]['sim_time_s']} | {o[0]['rebuilds']} / {n[0]['rebuilds']} | {to:.3f} s | "
               f"{tn:.3f} s | {to / tn:.2f} | {'yes' if same else 'no'} |")
def med(path):
    res = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") == "median":
            res[b["run_name"]] = (b["real_time"], b["time_unit"])
    return res
out += ["", "| benchmark (median of 3) | old | new | ratio |", "|---|---|---|---|"]
for part in ("reactive", "topology"):
    old, new = med(f"{speed}/{part}_old.json"), med(f"{speed}/{part}_new.json")
    for name in new:
        if name in old:
            (a, u), (b, _) = old[name], new[name]
            out.append(f"| {name} | {a:.4g} {u} | {b:.4g} {u} | {a / b:.2f} |")
open(f"{speed}/trials.md", "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
bench_publish
