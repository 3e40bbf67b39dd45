#!/usr/bin/env python3
"""Compare two trials.csv files of one sweep, ignoring the timing and provenance columns.

usage: compare_rows.py [--lenient-timeouts] A.csv B.csv

Rows are matched by their `trial` index. Every other column must hold the same text, except
those that legitimately differ between two runs of the same build: the measured times and the
provenance (revision, host, CPU model, when the trial ended). Used to check that a sharded run (Slurm array, GNU
parallel) merged with `rearm sweep merge` gives the rows of the unsharded `rearm sweep`.

Every row is compared in full. A sweep whose baselines are bounded by `query_limit` (a
deterministic budget) gives identical rows. A trial that ended in `timeout` ran out of its
wall-clock budget (the baselines' time_limit_s): whether it got there, and how far its search
went, depends on the machine's speed and load; with --lenient-timeouts such a row (timeout in
either file) is compared on its settings only (the columns up to query_limit, and instance:
the same trial with the same seeds) and counted apart.

Prints "N rows identical" (and, when there were any, how many time-limited rows agreed on their
settings) and exits 0 when they agree; otherwise prints what differs (headers, trials present
in only one file, per-trial differing columns; at most MAX_SHOWN lines of each) and exits 1.
Exit 2 for bad usage or an unreadable file.
"""
import csv
import sys

# The columns `rearm sweep merge` also ignores when it checks two copies of a trial.
IGNORED = {
    "planning_time_s", "planning_wall_s", "mission_time_s", "topology_time_s", "rebuild_time_s",
    "control_time_s",
    "compute_time_s", "first_action_time_s", "wall_time_s", "cpu_time_s", "revision", "host",
    "cpu_model", "finished_utc",
}
# The columns that define a trial (its cell, instance and seeds), in the header's order up to
# this one, plus the instance's name: all that a time-limited row is compared on.
LAST_SETTING = "query_limit"
INSTANCE = "instance"
MAX_SHOWN = 20


def read(path):
    """(header, {trial index: row}) of a CSV file; duplicate trial indices are an error."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError("%s: empty file" % path)
    header, body = rows[0], rows[1:]
    if "trial" not in header:
        raise ValueError("%s: no `trial` column" % path)
    at = header.index("trial")
    by_trial = {}
    for n, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise ValueError("%s: line %d has %d fields, the header %d"
                             % (path, n, len(row), len(header)))
        if row[at] in by_trial:
            raise ValueError("%s: trial %s appears twice" % (path, row[at]))
        by_trial[row[at]] = row
    return header, by_trial


def trial_order(key):
    return (0, int(key)) if key.isdigit() else (1, key)


def show(lines, what):
    """Print at most MAX_SHOWN of the lines under a heading."""
    print("%s: %d" % (what, len(lines)))
    for line in lines[:MAX_SHOWN]:
        print("  " + line)
    if len(lines) > MAX_SHOWN:
        print("  ... and %d more" % (len(lines) - MAX_SHOWN))


def main(argv):
    lenient = "--lenient-timeouts" in argv[1:]
    argv = [x for x in argv if x != "--lenient-timeouts"]
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    try:
        header_a, a = read(argv[1])
        header_b, b = read(argv[2])
    except (OSError, ValueError, csv.Error) as e:
        print("compare_rows: %s" % e, file=sys.stderr)
        return 2
    if header_a != header_b:
        print("headers differ:\n  %s: %s\n  %s: %s"
              % (argv[1], ",".join(header_a), argv[2], ",".join(header_b)))
        return 1
    compared = [i for i, name in enumerate(header_a) if name not in IGNORED]
    settings = compared
    if LAST_SETTING in header_a:
        settings = [i for i in compared if i <= header_a.index(LAST_SETTING)
                    or header_a[i] == INSTANCE]
    status = header_a.index("status") if "status" in header_a else None
    only_a = sorted(set(a) - set(b), key=trial_order)
    only_b = sorted(set(b) - set(a), key=trial_order)
    differing = []
    identical = time_limited = 0
    for key in sorted(set(a) & set(b), key=trial_order):
        limited = (lenient and status is not None
                   and "timeout" in (a[key][status], b[key][status]))
        cols = [i for i in (settings if limited else compared) if a[key][i] != b[key][i]]
        if cols:
            differing.append("trial %s: %s" % (key, "; ".join(
                "%s: %r vs %r" % (header_a[i], a[key][i], b[key][i]) for i in cols)))
        elif limited:
            time_limited += 1
        else:
            identical += 1
    if not (only_a or only_b or differing):
        note = ""
        if time_limited:
            note = (", %d time-limited rows (timeout in either run) agree on their settings"
                    % time_limited)
        print("%d rows identical%s" % (identical, note))
        return 0
    print("%s and %s differ (ignoring %s)" % (argv[1], argv[2], ", ".join(sorted(IGNORED))))
    if only_a:
        show(["trial " + k for k in only_a], "trials only in " + argv[1])
    if only_b:
        show(["trial " + k for k in only_b], "trials only in " + argv[2])
    if differing:
        show(differing, "trials whose results differ")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
