# Shared preamble of the scripts/bench_*.sh programs (source it, then call bench_prepare):
# installs what is missing, configures a Release build with the benchmarks, builds one
# benchmark target, and sets MACHINE, BUILD, OUT (results/$MACHINE, created), REV (the
# revision measured, "+ uncommitted changes" when the tree outside results/ differs) and LOAD
# (1, 5, 15 min load average as the benchmark starts).
# Environment: MACHINE (default debian12-2core), BUILD (default build).
bench_prepare() {
  local target=$1
  cd "$(dirname "${BASH_SOURCE[0]}")/../.."
  bash scripts/setup.sh
  MACHINE=${MACHINE:-debian12-2core}
  BUILD=${BUILD:-build}
  OUT="results/$MACHINE"
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF -DREARM_BUILD_BENCH=ON
  cmake --build "$BUILD" --target "$target" -j"$(nproc)"
  mkdir -p "$OUT"
  # The revision measured: taken before the script writes its own results.
  REV=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  if [ -n "$(git status --porcelain -- . ':!results' 2>/dev/null)" ]; then
    REV="$REV + uncommitted changes"
  fi
  LOAD=$(cut -d" " -f1-3 /proc/loadavg)
}
