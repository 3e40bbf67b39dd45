#!/usr/bin/env bash
# Every test program under AddressSanitizer + UndefinedBehaviorSanitizer, at reduced size
# (REARM_TEST_SCALE: fewer random cases, a twentieth of the corpus instances, a 12-trial smoke
# sweep; tests/support/scale.h). About 16 minutes of a 2-core machine (build 12:26, tests 3:14,
# measured uncontended). It was a stage of scripts/test.sh until the CI run took 3210 s of its
# 45 minutes; the fuzz stage there still runs each parser and loader under both sanitizers.
# Run it before an issue is resolved (its result goes into the closing note).
#   bash scripts/sanitize.sh            # build-asan/ (ASAN_BUILD overrides)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  -h | --help)
    sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  "") ;;
  *)
    echo "sanitize.sh: unknown argument '$1' (try --help)" >&2
    exit 2
    ;;
esac
stage() { printf 'sanitize.sh: [%02d:%02d] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$1"; }
stage "setup"
bash scripts/setup.sh
JOBS=$(nproc)
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja >/dev/null; then export CMAKE_GENERATOR=Ninja; fi
ASAN_BUILD=${ASAN_BUILD:-build-asan}
# At -O1 (the level the sanitizers' documentation recommends): at -O0, CGAL's uninlined templates
# made the sanitized tests take 728 s on 2 cores; at -O1 they took 370 s after a 958 s build (a
# CGAL file compiles about 40% slower). Without debug information (-g0: stack traces name
# functions, not lines; rebuild with -g1 to locate a report): topology/freespace.cpp compiled in
# 303 s instead of 340 s, its object half the size, and the build took 19.6 min at -g1.
cmake -S . -B "$ASAN_BUILD" -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g0" \
  -DREARM_SANITIZE=ON -DREARM_WERROR=ON \
  -DREARM_BUILD_TESTS=ON -DREARM_BUILD_BENCH=OFF -DREARM_TESTS=
stage "sanitizer build"
cmake --build "$ASAN_BUILD" -j"$JOBS"
stage "sanitizer tests"
REARM_TEST_SCALE=0.05 ctest --test-dir "$ASAN_BUILD" --no-tests=error --output-on-failure -j"$JOBS"

stage "done"
