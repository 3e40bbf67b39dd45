#!/usr/bin/env bash
# Main job: install what is missing, build, and run it.
# Today the main job translates the paper's formula (1) (three objects rearranged
# counterclockwise) into a Büchi automaton, prints it with its statistics, and prints the
# action plan the mission controller derives from it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_SANITIZE=OFF -DREARM_BUILD_TESTS=OFF \
  -DREARM_BUILD_BENCH=OFF
cmake --build "$BUILD" --target rearm -j"$(nproc)"
# Paper Eq. (1): grasp M1, release it in l2, then M2 to l3, then M3 to l1.
EQ1='<>(grasp(M1) && <>(release(M1,l2) && <>(grasp(M2) && <>(release(M2,l3) && <>(grasp(M3) && <>release(M3,l1))))))'
echo "== formula (1): $EQ1"
echo "== Büchi automaton, one action at a time (HOA)"
"$BUILD/bin/rearm" translate --alphabet actions --format hoa "$EQ1"
echo "== statistics"
"$BUILD/bin/rearm" translate --alphabet actions --format stats "$EQ1"
echo "== action plan of the mission controller (perfect executor)"
"$BUILD/bin/rearm" plan --formula "$EQ1"
