#!/usr/bin/env bash
# Install what is missing, build everything (warnings are errors), run every test, the behaviour
# gate, the package and the Slurm recipe; then fuzz each parser and loader for 5 s under
# AddressSanitizer + UndefinedBehaviorSanitizer (tests/fuzz/README.md). Each stage prints its
# start time since the script began. CI has 45 minutes; the sanitized build of every test
# program (about 16 minutes of a 2-core machine, half of the old CI run, which took 1818-3210 s
# on the CI machine) is scripts/sanitize.sh, run before an issue is resolved.
set -euo pipefail
cd "$(dirname "$0")/.."
stage() { printf 'test.sh: [%02d:%02d] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$1"; }
stage "setup"
bash scripts/setup.sh
# The text's house checks: every cited docs/ file exists, no issue numbers in comments.
stage "house checks"
bash scripts/check_docs.sh
# The layering of docs/architecture.md: no include a module may not make, third-party headers
# in their modules' .cpp files.
python3 scripts/check_layering.py
# Every C++ file clang-formatted; no function of the library over 100 lines.
bash scripts/check_style.sh
JOBS=$(nproc)
# Ninja for new build folders (an existing folder keeps the generator it was made with).
if [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja >/dev/null; then export CMAKE_GENERATOR=Ninja; fi
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_WERROR=ON -DREARM_SANITIZE=OFF \
  -DREARM_BUILD_TESTS=ON -DREARM_BUILD_BENCH=ON -DREARM_TESTS=
stage "release build"
cmake --build "$BUILD" -j"$JOBS"
stage "release tests"
ctest --test-dir "$BUILD" --no-tests=error --output-on-failure -j"$JOBS"
# The package: cmake --install to a fresh prefix, examples/downstream built against it with
# find_package(rearm) and run, and the installed rearm run from another directory draws run.png.
# The behaviour gate (scripts/behaviour_gate.py): the paper scenes under both variants, the corpus
# in checked mode and each switch's shortest sweep trials with and without it, hashed against
# tests/gate/hashes.txt (about 40 s). A change of behaviour re-records them and says why.
stage "behaviour gate"
python3 scripts/behaviour_gate.py --rearm "$BUILD/bin/rearm" --jobs "$JOBS" --work "$BUILD/gate"
stage "package"
bash scripts/check_install.sh "$BUILD"

# The Slurm recipe on a real single-node Slurm (slurm-wlm and munge, started and stopped by the
# script): the smoke sweep as a 3-task job array, merged, equal row for row to the unsharded
# run. About 40 s.
stage "slurm recipe"
REARM="$BUILD/bin/rearm" bash experiments/slurm/check_local.sh

# The fuzz targets (libFuzzer, clang, both sanitizers): 5 s each from the seed corpora, two at a
# time (about 2 minutes of build and 1 of fuzzing; the campaigns of
# results/debian12-2core/fuzz ran 10^7 executions each). A finding fails the run; its input is
# printed in hex.
stage "fuzz"
bash scripts/fuzz.sh --seconds 5
stage "done"
