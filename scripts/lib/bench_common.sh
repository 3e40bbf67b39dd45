# Shared preamble of the scripts/bench_*.sh programs. Source it, then:
#   bench_parse "$@"; set -- "${BENCH_ARGS[@]}"   # --help, --commit; the rest stays in "$@"
#   bench_prepare TARGET...                        # build (or not), MACHINE, BUILD, OUT, DEST, ...
#   bench_run PROGRAM FILE.json [args]             # a Google Benchmark run into $OUT, checked fresh
#   ... write the script's tables and figures into $OUT ...
#   bench_publish                                  # only now is anything written to $DEST
#
# Every file is written first into OUT, a fresh staging folder, and copied to DEST only by
# bench_publish, at the script's successful end: a benchmark that produced no fresh results (no
# JSON, or one without a benchmark) fails the script with nothing written, and so does any
# failing step after it. DEST is results/$MACHINE with --commit, else a scratch folder
# ($BENCH_SCRATCH, default $BUILD/bench-results/$MACHINE) that the build folder's .gitignore
# covers. Every JSON names its revision (--benchmark_context=revision=...) and date (Google
# Benchmark's context), every table the revision and date of its run.
#
# Set-up is skipped when the build exists: a build folder configured with the benchmarks
# (REARM_BUILD_BENCH=ON in its CMakeCache.txt) is only built, without scripts/setup.sh and
# without configuring again. BENCH_PROGRAM (a program's path) replaces every benchmark program
# and skips the build altogether (tests/scripts/bench_scripts_test.sh feeds the scripts a
# program that writes nothing).
#
# Environment: MACHINE (default debian12-2core), BUILD (default build), BENCH_SCRATCH,
# BENCH_PROGRAM.

# bench_parse "$@": --help prints the calling script's header and exits; --commit writes into
# results/$MACHINE. Everything else is left, in order, in the array BENCH_ARGS.
bench_parse() {
  COMMIT=0
  BENCH_ARGS=()
  local a
  for a in "$@"; do
    case "$a" in
      -h | --help)
        bench_help
        exit 0
        ;;
      --commit) COMMIT=1 ;;
      *) BENCH_ARGS+=("$a") ;;
    esac
  done
}

# The calling script's header comment (after the shebang), then the common options.
bench_help() {
  local script=$0
  sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$script"
  cat <<EOF

Options of every scripts/bench_*.sh:
  --help     this text; nothing is built, run or written
  --commit   write into results/\$MACHINE (the committed results); without it the results go
             to a scratch folder (\$BENCH_SCRATCH, default \$BUILD/bench-results/\$MACHINE)
Nothing is written when the benchmark produces no fresh results or a step fails.
EOF
}

# bench_prepare TARGET...: set-up (unless the build exists), build the targets, and set MACHINE,
# BUILD, DEST, OUT (the staging folder, removed at exit), REV (the revision measured, "+
# uncommitted changes" when the tree outside results/ differs) and LOAD (1, 5, 15 min load
# average as the benchmark starts).
bench_prepare() {
  cd "$(dirname "${BASH_SOURCE[0]}")/../.."
  MACHINE=${MACHINE:-debian12-2core}
  BUILD=${BUILD:-build}
  if [ "${COMMIT:-0}" = 1 ]; then
    DEST="results/$MACHINE"
  else
    DEST="${BENCH_SCRATCH:-$BUILD/bench-results/$MACHINE}"
  fi
  if [ -n "${BENCH_PROGRAM:-}" ]; then
    echo "bench: BENCH_PROGRAM=$BENCH_PROGRAM replaces the benchmark programs; nothing is built"
  else
    if grep -qs '^REARM_BUILD_BENCH:BOOL=ON' "$BUILD/CMakeCache.txt"; then
      echo "bench: $BUILD is configured with the benchmarks; set-up skipped"
    else
      bash scripts/setup.sh
      cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF -DREARM_BUILD_BENCH=ON
    fi
    cmake --build "$BUILD" --target "$@" -j"$(nproc)"
  fi
  OUT=$(mktemp -d)
  trap 'rm -rf "$OUT"' EXIT
  # The revision measured: taken before the script writes its own results.
  REV=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  if [ -n "$(git status --porcelain -- . ':!results' 2>/dev/null)" ]; then
    REV="$REV + uncommitted changes"
  fi
  LOAD=$(cut -d" " -f1-3 /proc/loadavg)
}

# The program to run for benchmark TARGET.
bench_bin() {
  echo "${BENCH_PROGRAM:-$BUILD/bin/$1}"
}

# bench_run TARGET NAME.json [ARGS...]: runs the benchmark program into $OUT/NAME.json with the
# revision and the load in its context, then checks that it wrote fresh results.
bench_run() {
  local target=$1 file=$2
  shift 2
  "$(bench_bin "$target")" --benchmark_out="$OUT/$file" --benchmark_out_format=json \
    --benchmark_context=revision="$REV" --benchmark_context=load_at_start="$LOAD" "$@"
  bench_fresh "$OUT/$file" "$target"
}

# bench_fresh FILE PROGRAM: FILE (written in the staging folder by this run) exists and holds
# at least one benchmark; else the script fails, nothing written.
bench_fresh() {
  if ! python3 - "$1" <<'PY'; then
import json, sys
try:
    with open(sys.argv[1]) as f:
        doc = json.load(f)
    ok = isinstance(doc, dict) and len(doc.get("benchmarks", [])) > 0
except (OSError, ValueError):
    ok = False
sys.exit(0 if ok else 1)
PY
    echo "bench: $2 produced no fresh results ($(basename "$1") missing, empty or without a" \
      "benchmark); nothing written to $DEST" >&2
    exit 1
  fi
}

# Copies the staging folder's files into DEST: the only write outside the staging folder.
bench_publish() {
  mkdir -p "$DEST"
  cp -R "$OUT"/. "$DEST"/
  echo "bench: wrote $(cd "$OUT" && find . -type f | sed 's|^\./||' | sort | tr '\n' ' ')into $DEST"
}
