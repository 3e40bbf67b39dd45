#!/usr/bin/env bash
# Mission-controller benchmarks (bench/symbolic): builds in Release and writes Google
# Benchmark JSON to results/$MACHINE/symbolic_mission.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD=${BUILD:-build}
MACHINE=${MACHINE:-debian12-2core}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF -DREARM_BUILD_BENCH=ON
cmake --build "$BUILD" --target mission_bench -j"$(nproc)"
mkdir -p "results/$MACHINE"
"$BUILD/bin/mission_bench" --benchmark_out="results/$MACHINE/symbolic_mission.json" \
  --benchmark_out_format=json --benchmark_repetitions=3 --benchmark_report_aggregates_only=true "$@"
