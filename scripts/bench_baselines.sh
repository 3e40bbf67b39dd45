#!/usr/bin/env bash
# Baseline benchmarks (docs/experiments.md): builds and runs bench/baselines/baselines_bench
# (JSON into results/$MACHINE/baselines_bench.json): the wall time B2 (BiRRT) and B1 (mRS) take
# when given 1 s on the unsolvable pocket instance (acceptance: within 1.2 s; counter
# overrun_s), and the planning time of B1 and B2 on the monotone and the Fig. 5 instances.
# Environment: MACHINE (default debian12-2core), BUILD (default build). About 20 s.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_prepare baselines_bench
"$BUILD/bin/baselines_bench" --benchmark_out="$OUT/baselines_bench.json" \
  --benchmark_out_format=json --benchmark_context=revision="$REV" \
  --benchmark_context=load_at_start="$LOAD" "$@"
echo "wrote $OUT/baselines_bench.json (revision $REV)"
