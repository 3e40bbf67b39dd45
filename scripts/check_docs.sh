#!/usr/bin/env bash
# House checks of the text (docs/architecture.md, "House style"), run first by scripts/test.sh:
#  - every docs/<name>.md that code, tests, benchmarks, scripts, the README, the changelog or the
#    results' READMEs cite exists;
#  - no comment or script cites this project's issue numbers ("issue 7"): they cite the paper's
#    sections and equations, or docs/ (an upstream bug is cited with its project and '#': "CGAL
#    issue #9322");
#  - README.md is the five-minute page: at most 150 lines, and no revision history (no "since
#    then", no revision hash outside the headline table of its "## Results" section; the history
#    is CHANGELOG.md's and the study folders' under results/).
# Prints each offending file:line and exits 1 when there is one.
set -euo pipefail
shopt -s nullglob
cd "$(dirname "$0")/.."

dirs=(framework experiments tests bench baselines scripts README.md CMakeLists.txt CHANGELOG.md
  results/*/README.md results/*/*/README.md)
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
readme_max_lines=150
readme_lines=$(wc -l < README.md)
if ((readme_lines > readme_max_lines)); then
  echo "README.md: $readme_lines lines, more than $readme_max_lines: move detail to docs/," \
    "a study README under results/ or CHANGELOG.md" >&2
  status=1
fi
if grep -niF "since then" README.md | sed 's|^|README.md:|' >&2; then
  echo "check_docs.sh: the README lines above tell revision history ('since then'); it belongs in" \
    "CHANGELOG.md or a study README" >&2
  status=1
fi
# Revision hashes (7-12 hex digits as a word) are allowed only in the table rows ('|' lines) of the
# section headed '## Results', where each headline result names the revision it comes from.
hashes=$(awk '/^## / { in_results = /^## Results/ }
  in_results && /^\|/ { next }
  {
    n = split($0, words, /[^0-9A-Za-z_]+/)
    for (i = 1; i <= n; i++) {
      w = words[i]
      if (length(w) >= 7 && length(w) <= 12 && w ~ /^[0-9a-f]+$/) {
        print "README.md:" NR ": " $0
        break
      }
    }
  }' README.md)
if [[ -n $hashes ]]; then
  echo "$hashes" >&2
  echo "check_docs.sh: the README lines above name a revision outside the '## Results' table;" \
    "revision history belongs in CHANGELOG.md or a study README" >&2
  status=1
fi
if ((status == 0)); then
  echo "check_docs.sh: docs citations, issue references and the README's length and history clean"
fi
exit $status
