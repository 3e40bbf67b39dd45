#!/usr/bin/env bash
# The benchmark scripts never mislabel numbers (scripts/lib/bench_common.sh): each scripts/bench_*.sh
# is fed a benchmark program that writes nothing (BENCH_PROGRAM, and as every program of a fake
# build for the scripts that run several), with and without --commit, in a throw-away git copy of
# the repository's scripts, results and inputs; each must fail, say that no fresh results came,
# and leave the copy exactly as committed (no file changed, none added, no scratch folder). Then
# --help: each prints its header and the common options, exits 0 and writes nothing.
set -euo pipefail
REPO=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
COPY="$WORK/repo"
mkdir -p "$COPY/experiments"
cp -R "$REPO/scripts" "$REPO/results" "$COPY/"
cp -R "$REPO/experiments/sweeps" "$REPO/experiments/scenarios" "$COPY/experiments/"
git -C "$COPY" init -q
git -C "$COPY" -c user.name=t -c user.email=t@t add -A
git -C "$COPY" -c user.name=t -c user.email=t@t commit -q -m copy

FAKE="$WORK/fake/bin"  # a build whose every program exits 0 and writes nothing
mkdir -p "$FAKE"
for p in silent rearm reactive_bench topology_bench baselines_bench translate_bench mission_bench; do
  printf '#!/bin/sh\nexit 0\n' > "$FAKE/$p"
  chmod +x "$FAKE/$p"
done
export BENCH_PROGRAM="$FAKE/silent" BUILD="$WORK/fake" OLD_BUILD="$WORK/fake" \
  BENCH_SCRATCH="$WORK/scratch" MACHINE=debian12-2core

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
unchanged() {  # the copy is exactly as committed and no scratch folder appeared
  [ -z "$(git -C "$COPY" status --porcelain --untracked-files=all)" ] && [ ! -e "$WORK/scratch" ]
}

for script in "$COPY"/scripts/bench_*.sh; do
  name=$(basename "$script")
  args=()
  [ "$name" = bench_speed.sh ] && args=(HEAD)
  for commit in "" --commit; do
    set +e
    out=$(bash "$script" $commit ${args[@]+"${args[@]}"} 2>&1)
    rc=$?
    set -e
    [ "$rc" -ne 0 ] || fail "$name $commit exited 0 with a benchmark that wrote nothing"
    unchanged || fail "$name $commit changed the copy: $(git -C "$COPY" status --porcelain | head -5)"
    case "$name" in
      bench_speed.sh | bench_sweep.sh) ;;  # their programs are not Google Benchmark's: any failure
      *)
        grep -q "produced no fresh results" <<< "$out" ||
          fail "$name $commit did not say that no fresh results came: $(tail -2 <<< "$out")"
        ;;
    esac
    git -C "$COPY" checkout -q -- . && git -C "$COPY" clean -qfd && rm -rf "$WORK/scratch"
  done
  help=$(bash "$script" --help 2>&1) || fail "$name --help exited non-zero"
  grep -q "Options of every scripts/bench_\*.sh" <<< "$help" || fail "$name --help: no options text"
  [ "$(head -c 1 <<< "$help")" != "#" ] || fail "$name --help printed comment marks"
  unchanged || fail "$name --help wrote something"
done
count=$(ls "$COPY"/scripts/bench_*.sh | wc -l)
if [ "$failures" -gt 0 ]; then
  echo "bench_scripts_test: $failures failures over $count scripts"
  exit 1
fi
echo "bench_scripts_test: $count scripts fail on a silent benchmark with nothing written, and print --help"
