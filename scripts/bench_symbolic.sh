#!/usr/bin/env bash
# Mission-controller benchmarks (bench/symbolic): builds in Release and writes Google
# Benchmark JSON (medians of 3 repetitions) to symbolic_mission.json.
# Environment: MACHINE (default debian12-2core), BUILD (default build). Other arguments go to
# mission_bench.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
bench_prepare mission_bench
bench_run mission_bench symbolic_mission.json --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true "$@"
bench_publish
