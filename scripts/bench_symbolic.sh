#!/usr/bin/env bash
# Mission-controller benchmarks (bench/symbolic): builds in Release and writes Google
# Benchmark JSON: symbolic_mission.json (mission_bench, medians of 3 repetitions: G and d_F,
# one decision) and symbolic_any_order.json (any_order_bench, one run: the any-order task
# <>release(M1,l1) && ... && <>release(MN,lN) at N = 4..24, the whole formula's automaton
# against the product form of docs/symbolic.md in the same run: set-up time and memory, time
# per decision).
# Environment: MACHINE (default debian12-2core), BUILD (default build). Other arguments go to
# mission_bench.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
bench_prepare mission_bench any_order_bench
bench_run mission_bench symbolic_mission.json --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true "$@"
bench_run any_order_bench symbolic_any_order.json
bench_publish
