#!/usr/bin/env bash
# Baseline benchmarks (docs/experiments.md): builds and runs bench/baselines/baselines_bench
# (JSON into results/$MACHINE/baselines_bench.json): the wall time B2 (BiRRT) and B1 (mRS) take
# when given 1 s on the unsolvable pocket instance (acceptance: within 1.2 s; counter
# overrun_s), the planning time of B1 and B2 on the monotone and the Fig. 5 instances, and of
# every planner on crowded rooms at N = 4, 8, 16 (Crowded/<method>/<N>). About 10 minutes.
#
# With an earlier revision, `bash scripts/bench_baselines.sh OLD_REVISION`, it also compares the
# crowded family side by side in the same run: this benchmark source is built against the old
# revision's planners (a git worktree under build-old/, about 15 min on 2 cores the first time;
# planners the old revision lacks are left out) and old and new binaries alternate method by
# method, so both see the same load. Writes results/$MACHINE/baselines_compare/{old.json,
# new.json,compare.md}. Environment: MACHINE (default debian12-2core), BUILD (default build),
# OLD_BUILD (an existing build of the old revision with this benchmark, skips the worktree).
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
OLD_REV=${1:-}
bench_prepare baselines_bench
bench_run baselines_bench baselines_bench.json
if [ -z "$OLD_REV" ]; then
  bench_publish
  exit 0
fi

if [ -z "${OLD_BUILD:-}" ]; then
  WORK=build-old
  [ -d "$WORK/src" ] || git worktree add -f "$WORK/src" "$OLD_REV"
  git -C "$WORK/src" checkout -q -- bench/baselines/baselines_bench.cpp
  git -C "$WORK/src" checkout -q --detach "$OLD_REV"
  cp bench/baselines/baselines_bench.cpp "$WORK/src/bench/baselines/baselines_bench.cpp"
  cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF \
    -DREARM_BUILD_BENCH=ON -DREARM_BUILD_TESTS=OFF > /dev/null
  cmake --build "$WORK/build" --target baselines_bench -j"$(nproc)"
  OLD_BUILD="$WORK/build"
fi
CMP="$OUT/baselines_compare"
mkdir -p "$CMP"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP" "$OUT"' EXIT
OLD_NAME=$(git rev-parse --short "$OLD_REV")
for m in mrs birrt buffer fmrs birrt_fmrs; do
  for side in old new; do
    bin=$(bench_bin baselines_bench)
    [ "$side" = old ] && bin="$OLD_BUILD/bin/baselines_bench"
    rev="$REV"
    [ "$side" = old ] && rev="$OLD_NAME"
    "$bin" --benchmark_filter="^Crowded/$m/" --benchmark_out="$TMP/$side-$m.json" \
      --benchmark_out_format=json --benchmark_context=revision="$rev" \
      --benchmark_context=load_at_start="$(cut -d' ' -f1-3 /proc/loadavg)" > /dev/null 2>&1 ||
      true  # the old revision may lack the planner: no benchmark matches
  done
done
python3 - "$TMP" "$CMP" "$OLD_NAME" "$REV" <<'PY'
import glob, json, sys
tmp, out, old_rev, new_rev = sys.argv[1:5]
runs = {}
for side in ("old", "new"):
    merged = None
    for f in sorted(glob.glob(f"{tmp}/{side}-*.json")):
        text = open(f).read()
        if not text.strip():  # a planner this revision lacks: no benchmark matched
            continue
        d = json.loads(text)
        if merged is None:
            merged = d
        else:
            merged["benchmarks"] += d["benchmarks"]
    json.dump(merged, open(f"{out}/{side}.json", "w"), indent=1)
    runs[side] = {b["name"]: b for b in merged["benchmarks"]}
date = json.load(open(f"{out}/new.json"))["context"]["date"]
lines = [f"# Crowded planning times: {old_rev} (old) against {new_rev} (new), one run, {date}", "",
         "Mean planning time per instance (ms) over the four instances of each N; solved: "
         "fraction of them; queries: mean motion queries. '-': the revision lacks the planner.", "",
         "| benchmark | old ms | new ms | new/old | old solved | new solved | old queries | new queries |",
         "|---|---|---|---|---|---|---|---|"]
for name, b in runs["new"].items():
    o = runs["old"].get(name)
    ratio = f"{b['real_time'] / o['real_time']:.2f}" if o else "-"
    def cell(x, key, fmt):
        return fmt.format(x[key]) if x else "-"
    lines.append(f"| {name} | {cell(o, 'real_time', '{:.1f}')} | {b['real_time']:.1f} | {ratio} | "
                 f"{cell(o, 'solved', '{:.2f}')} | {b['solved']:.2f} | {cell(o, 'queries', '{:.0f}')} | "
                 f"{b['queries']:.0f} |")
open(f"{out}/compare.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
bench_publish
