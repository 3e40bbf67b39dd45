#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (AddressSanitizer, UndefinedBehavior-
# Sanitizer, coverage feedback) and runs each on its seed corpus (tests/fuzz/README.md).
#   bash scripts/fuzz.sh [--seconds S | --runs N] [--jobs J] [--seed S] [--keep] [--ubsan-only]
#                         [--report F] [TARGET...]
# --seconds S  each target for S seconds (default 60: the test command's short runs)
# --runs N     each target for N executions instead (the campaigns: 10000000)
# --jobs J     targets fuzzed at once (default: the number of cores)
# --report F   a Markdown table of the runs (executions, time, rate, coverage, findings) in F
# --seed S     libFuzzer's random seed (default 1: a rerun mutates the same way)
# --keep       start from the scratch corpus a previous run left (a campaign resumed in parts)
# --ubsan-only UndefinedBehaviorSanitizer without AddressSanitizer (build-fuzz-ubsan): several
#              times the rate, for long campaigns; replay their corpus afterwards under both
#              (the default build) with --keep --runs 0, which executes every input once
# New inputs go to a scratch corpus (FUZZ_WORK, default /tmp/rearm-fuzz), never into the
# repository; a finding is written there as crash-*, timeout-* or oom-* and the script exits 1.
# Every finding, once fixed, is copied into tests/fuzz/corpus/<target>/ (found_<what>.<ext>), where
# the ordinary test build replays it (ctest -R _corpus).
set -euo pipefail
cd "$(dirname "$0")/.."
# Stopping the script stops the targets it started (xargs would start the next ones).
trap 'trap - INT TERM; kill 0' INT TERM

seconds=60 runs="" jobs=$(nproc) report="" seed=1 keep=0 ubsan_only=0 targets=()
while (($#)); do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --report) report=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    --ubsan-only) ubsan_only=1; shift ;;
    -h|--help) sed -n 2,19p "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
if ((${#targets[@]} == 0)); then
  for f in tests/fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi

FUZZ_WORK=${FUZZ_WORK:-/tmp/rearm-fuzz}
sanitizers=(-DREARM_SANITIZE=ON)
if [[ $ubsan_only == 1 ]]; then
  FUZZ_BUILD=${FUZZ_BUILD:-build-fuzz-ubsan}
  ub="-fsanitize=undefined -fno-sanitize-recover=undefined"
  sanitizers=(-DREARM_SANITIZE=OFF "-DCMAKE_CXX_FLAGS=$ub" "-DCMAKE_EXE_LINKER_FLAGS=$ub")
fi
FUZZ_BUILD=${FUZZ_BUILD:-build-fuzz}
CC=clang CXX=clang++ cmake -S . -B "$FUZZ_BUILD" -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DREARM_FUZZ=ON "${sanitizers[@]}" \
  -DREARM_BUILD_TESTS=OFF -DREARM_BUILD_BENCH=OFF >/dev/null
cmake --build "$FUZZ_BUILD" -j"$(nproc)" --target fuzz_all

# One target: a fresh scratch corpus first (libFuzzer writes new inputs into the first
# directory), the seeds second. -timeout: an input that takes 5 s is a finding (hangs count).
fuzz_one() {
  local t=$1
  local work=$FUZZ_WORK/$t
  [[ -n $t && -n $FUZZ_WORK ]] || return 2
  if [[ $keep == 1 ]]; then
    rm -f "$work/log" "$work/rc" && mkdir -p "$work/corpus"
  else
    rm -rf "$work" && mkdir -p "$work/corpus"
  fi
  local budget=(-max_total_time="$seconds")
  [[ -n $runs ]] && budget=(-runs="$runs")
  local rc=0
  "$FUZZ_BUILD/bin/$t" "${budget[@]}" -seed="$seed" -timeout=5 -rss_limit_mb=2048 -max_len=8192 \
    -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "tests/fuzz/corpus/$t" \
    >"$work/log" 2>&1 || rc=$?
  echo "$rc" >"$work/rc"
}
export -f fuzz_one
export FUZZ_BUILD FUZZ_WORK seconds runs seed keep
printf '%s\n' "${targets[@]}" | xargs -P "$jobs" -I{} bash -c 'fuzz_one {}'

status=0
rows=""
for t in "${targets[@]}"; do
  work=$FUZZ_WORK/$t
  rc=$(cat "$work/rc")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$work/log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$work/log" | tail -1 | cut -d' ' -f2)
  found=$(find "$work" -maxdepth 1 -name 'crash-*' -o -maxdepth 1 -name 'timeout-*' \
    -o -maxdepth 1 -name 'oom-*' -o -maxdepth 1 -name 'leak-*' | wc -l)
  result="0 findings"
  if [[ $rc != 0 || $found != 0 ]]; then
    result="**exit $rc, $found finding(s)**: $(grep -m1 -E 'ERROR|property broken' "$work/log" || true)"
    status=1
    echo "fuzz.sh: $t: exit $rc; log $work/log" >&2
    grep -m1 -B2 -A12 -E 'ERROR|property broken' "$work/log" >&2 || true
    for input in "$work"/crash-* "$work"/timeout-* "$work"/oom-* "$work"/leak-*; do
      [[ -f $input ]] || continue
      echo "fuzz.sh: the input $input (first 4 KiB):" >&2
      head -c 4096 "$input" | od -A d -t x1z -v >&2
    done
  fi
  rate=""
  [[ -n ${secs:-} && ${secs:-0} -gt 0 ]] && rate=$((execs / secs))
  printf 'fuzz.sh: %-26s %12s executions in %6s s (%s/s), coverage %s, %s\n' \
    "$t" "${execs:-?}" "${secs:-?}" "${rate:-?}" "${cov:-?}" "$result"
  rows+="| \`$t\` | ${execs:-?} | ${secs:-?} | ${rate:-?} | ${cov:-?} | $(ls "$work/corpus" | wc -l) | $result |"$'\n'
done
if [[ -n $report ]]; then
  {
    echo "| target | executions | seconds | per second | coverage (edges) | new corpus inputs | result |"
    echo "|---|---:|---:|---:|---:|---:|---|"
    printf '%s' "$rows"
  } >"$report"
fi
exit $status
