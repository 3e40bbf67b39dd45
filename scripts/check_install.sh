#!/usr/bin/env bash
# The package check of the test command (cmake/install.cmake): installs BUILD (default build)
# into a fresh prefix, builds examples/downstream against it with find_package(rearm) and runs
# it on fig3; then runs the installed rearm from another working directory and checks that it
# found its plotting scripts (run.png written). About 30 s.
#   bash scripts/check_install.sh [BUILD]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
build=${1:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S examples/downstream -B "$work/downstream" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/downstream" >/dev/null
"$work/downstream/downstream" "$repo/experiments/scenarios/fig3.yaml"
mkdir -p "$work/elsewhere"
cd "$work/elsewhere"
"$work/prefix/bin/rearm" run "$repo/experiments/scenarios/fig3.yaml" --out out --no-animation \
  >/dev/null
if [[ ! -f out/run.png ]]; then
  echo "check_install.sh: the installed rearm run wrote no out/run.png" >&2
  exit 1
fi
echo "check_install.sh: downstream example built and ran against the installed package;" \
  "installed rearm run wrote run.png from another directory"
