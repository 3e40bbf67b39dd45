#!/usr/bin/env bash
# Main job: install what is missing, build, and reproduce the paper's Fig. 5 — three objects
# rearranged counterclockwise (formula (1)) in a Box2D world with familiar and unknown
# obstacles discovered by a range-limited sensor.
# Output: results/debian12-2core/fig5/{metrics.json,trajectory.json,run.png,run.gif}
# (OUT=DIR to write elsewhere).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD=${BUILD:-build}
OUT=${OUT:-results/debian12-2core/fig5}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF -DREARM_BUILD_TESTS=OFF \
  -DREARM_BUILD_BENCH=OFF
cmake --build "$BUILD" --target rearm -j"$(nproc)"
echo "== Fig. 5: formula (1) in experiments/scenarios/fig5.yaml"
"$BUILD/bin/rearm" run experiments/scenarios/fig5.yaml --out "$OUT" --snapshots 4
echo "== the figure: $OUT/run.png, the animation: $OUT/run.gif, the metrics: $OUT/metrics.json"
