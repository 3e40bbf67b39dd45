#!/usr/bin/env bash
# House checks of the text (docs/architecture.md, "House style"), run first by scripts/test.sh:
#  - every docs/<name>.md that code, tests, benchmarks, scripts or the README cite exists;
#  - no comment or script cites this project's issue numbers ("issue 7"): they cite the paper's
#    sections and equations, or docs/ (an upstream bug is cited with its project and '#': "CGAL
#    issue #9322").
# Prints each offending file:line and exits 1 when there is one.
set -euo pipefail
cd "$(dirname "$0")/.."

dirs=(framework experiments tests bench baselines scripts README.md CMakeLists.txt)
status=0
while IFS= read -r path; do
  if [[ ! -f $path ]]; then
    grep -rnF --exclude-dir=corpus "$path" "${dirs[@]}" | sed "s|\$| (cites $path, which does not exist)|" >&2
    status=1
  fi
done < <(grep -rhoE --exclude-dir=corpus 'docs/[A-Za-z0-9_/-]+\.md' "${dirs[@]}" | sort -u)

if grep -rnE --exclude-dir=corpus --exclude=check_docs.sh '[Ii]ssues? [0-9]+' "${dirs[@]}" docs >&2; then
  echo "check_docs.sh: the lines above cite issue numbers; cite the paper or docs/ instead" >&2
  status=1
fi
if ((status == 0)); then echo "check_docs.sh: docs citations and issue references clean"; fi
exit $status
