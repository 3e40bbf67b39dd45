#!/bin/bash
# A rearm Monte Carlo sweep in K deterministic shards with GNU parallel, on this machine or on
# ssh hosts, then merged (experiments/parallel/README.md).
#
# usage: experiments/parallel/run.sh SWEEP.yaml OUT K [--check] [PARALLEL_OPTION...]
#   SWEEP.yaml  the sweep file
#   OUT         output folder: shards in OUT/shard_<i>, merged rows in OUT/merged, GNU
#               parallel's job log in OUT/parallel.log
#   K           number of shards (shard i runs the instances whose index is i mod K)
#   --check     also run the sweep unsharded into OUT/unsharded and compare its rows with the
#               merged ones (experiments/slurm/compare_rows.py); for small sweeps
#   PARALLEL_OPTION...  passed to GNU parallel as they are, e.g. --jobs 2, --sshlogin 4/hostA,
#               --sshloginfile hosts.txt, --resume-failed. With ssh hosts, every host needs the
#               rearm program, the sweep file and OUT at the same paths (a shared file system).
# environment:
#   REARM       the rearm program (default build/bin/rearm of this checkout, else `rearm` on PATH)
#   THREADS     rearm threads per shard (default 1; GNU parallel runs one shard per core)
#   REPORT=1    also run `rearm sweep report OUT/merged` (tables, plots, OMPL logs)
#   LENIENT=1   with --check, compare rows that ended in timeout on their settings only
# Rerunning the same command resumes: each shard runs only the trials missing from its CSV.
# Exit status: 0 when every shard ran every trial and (with --check) the rows agree.
set -euo pipefail

usage() { sed -n '4,22p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[[ $# -ge 3 ]] || usage
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
sweep=$(realpath "$1")
out=$(realpath -m "$2")
shards=$3
shift 3
[[ $shards =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: K must be a positive integer" >&2; exit 2; }
check=0
if [[ ${1:-} == --check ]]; then
  check=1
  shift
fi
if [[ -n ${REARM:-} ]]; then
  rearm=$REARM
elif [[ -x $repo/build/bin/rearm ]]; then
  rearm=$repo/build/bin/rearm
else
  rearm=rearm
fi
[[ $rearm == */* ]] && rearm=$(realpath "$rearm")
threads=${THREADS:-1}
[[ -f $sweep ]] || { echo "run.sh: no sweep file $sweep" >&2; exit 2; }
mkdir -p "$out"

# One job per shard. {} is the shard index; --quote keeps each argument whole (also on ssh).
# --line-buffer keeps the shards' progress lines whole; --tagstring prefixes them with the shard.
t0=$SECONDS
status=0
seq 0 $((shards - 1)) |
  parallel --will-cite --quote --line-buffer --tagstring "shard {}/$shards" \
    --joblog "$out/parallel.log" "$@" \
    "$rearm" sweep "$sweep" --out "$out/shard_{}" --shard "{}/$shards" --threads "$threads" ||
  status=$?
echo "run.sh: $shards shards ended in $((SECONDS - t0)) s (GNU parallel exit $status)"

# Merge whatever the shards wrote (a shard whose trial ended in `error` still wrote its rows).
shard_dirs=()
for ((i = 0; i < shards; i++)); do
  if [[ -f $out/shard_$i/trials.csv ]]; then
    shard_dirs+=("$out/shard_$i")
  else
    echo "run.sh: shard $i wrote no trials.csv" >&2
    status=1
  fi
done
[[ ${#shard_dirs[@]} -gt 0 ]] || exit 1
"$rearm" sweep merge "${shard_dirs[@]}" --out "$out/merged"
if [[ ${REPORT:-0} == 1 ]]; then
  "$rearm" sweep report "$out/merged"
fi

if [[ $check == 1 ]]; then
  t0=$SECONDS
  "$rearm" sweep "$sweep" --out "$out/unsharded" --threads "$(nproc)" --quiet || status=$?
  echo "run.sh: unsharded sweep ran in $((SECONDS - t0)) s"
  compare_opts=()
  [[ ${LENIENT:-0} == 1 ]] && compare_opts=(--lenient-timeouts)
  if result=$(python3 "$repo/experiments/slurm/compare_rows.py" "${compare_opts[@]}" \
                "$out/merged/trials.csv" "$out/unsharded/trials.csv"); then
    echo "parallel check: $result"
  else
    echo "$result" >&2
    echo "parallel check: FAILED: merged shards differ from the unsharded run" >&2
    exit 1
  fi
fi
exit "$status"
