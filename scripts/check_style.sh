#!/usr/bin/env bash
# House checks of the code (docs/architecture.md, "House style"), run by scripts/test.sh:
#  - every C++ file that git tracks is formatted as .clang-format says (Debian 12's
#    clang-format 14); `git ls-files '*.cpp' '*.h' | xargs clang-format -i` mends it;
#  - no function of framework/, baselines/ or experiments/ is longer than 100 lines (universal
#    ctags' start and end lines of every function, lambdas included).
# Prints each offence and exits 1 when there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
max_lines=100
status=0
if ! git ls-files '*.cpp' '*.h' | xargs clang-format --dry-run --Werror 2>/tmp/check_style.$$; then
  # clang-format 14 reports each offence as "error:" under --Werror ("warning:" without it).
  { grep -E "(warning|error):" /tmp/check_style.$$ || true; } | cut -d: -f1,2 | sort -u |
    sed 's/$/: not clang-formatted/' >&2
  status=1
fi
rm -f /tmp/check_style.$$
long=$(ctags -R --languages=C++ --kinds-C++=f --fields=+ne -o - framework baselines experiments |
  awk -F'\t' -v max="$max_lines" '{
    l = ""; e = ""
    for (i = 4; i <= NF; i++) {
      if ($i ~ /^line:/) l = substr($i, 6)
      if ($i ~ /^end:/) e = substr($i, 5)
    }
    if (l != "" && e != "" && e - l + 1 > max) print $2 ":" l ": " $1 " has " e - l + 1 " lines"
  }')
if [[ -n $long ]]; then
  echo "$long" | sed "s/\$/ (at most $max_lines: split it along its phases)/" >&2
  status=1
fi
if ((status == 0)); then
  echo "check_style.sh: every C++ file clang-formatted, no function over $max_lines lines"
fi
exit $status
