#!/usr/bin/env bash
# Install what is missing, build everything (warnings are errors), run every test; then
# rebuild the input-facing tests with AddressSanitizer + UndefinedBehaviorSanitizer and
# run them again.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=$(nproc)
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_WERROR=ON
cmake --build "$BUILD" -j"$JOBS"
ctest --test-dir "$BUILD" --output-on-failure -j"$JOBS"

# Sanitized run of the tests that feed arbitrary input (parser fuzzing, automaton readers)
# and of the translator's oracle tests at reduced size (REARM_TEST_SCALE).
ASAN_BUILD=${ASAN_BUILD:-build-asan}
ASAN_TESTS="parser_test;formula_test;bdd_test;letter_set_test;automaton_io_test;translate_lasso_test"
cmake -S . -B "$ASAN_BUILD" -DCMAKE_BUILD_TYPE=Debug -DREARM_SANITIZE=ON -DREARM_WERROR=ON \
  -DREARM_BUILD_BENCH=OFF "-DREARM_TESTS=$ASAN_TESTS"
cmake --build "$ASAN_BUILD" -j"$JOBS"
REARM_TEST_SCALE=0.05 ctest --test-dir "$ASAN_BUILD" --output-on-failure -j"$JOBS"
