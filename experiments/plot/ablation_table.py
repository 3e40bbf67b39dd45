#!/usr/bin/env python3
"""The ablation table of rearm's robust variant (experiments/sweeps/ablation.yaml).

usage: ablation_table.py ABLATION/trials.csv [SWEEP/trials.csv] > summary.md

Success (completed in Box2D, every object in its goal region, 0 collisions: the sweep's one
rule, the `success` column) per method and goal class, with Wilson 95% intervals; the recoveries
each method used; and, when the committed sweep's rows are given, the baselines on the very same
instances (the ablation draws its instances from the same seeds as the committed sweep, so
rows are matched by class, N, target density and instance seed).
"""
import collections
import sys

# sweep_data.py sits beside this file, which is sys.path[0] when it runs as a script.
from sweep_data import Trial, first_seen, number, read_trials, recovery_columns, wilson

# Headings of the counters whose column name, underscores read as spaces, would not say what
# it counts; any other counter (a new one too) is headed by its column name with spaces.
RECOVERY_LABELS = {"back_outs": "back-ups", "faces": "turns to the goal",
                   "narrows": "narrow passages", "fragment_fixes": "ways beside unknown obstacles"}


def label(column):
    return RECOVERY_LABELS.get(column, column.replace("_", " "))


def cell(k, n):
    lo, hi = wilson(k, n)
    return f"{k}/{n} ({100 * k / n:.0f}%, {100 * lo:.0f}–{100 * hi:.0f})" if n else "–"


def instance_key(r):
    return (r["class"], r["objects"], r["target_density"], r["instance_seed"])


def count(tally, name, r):
    """Adds row r's trial and success to method `name` in its class and in all classes."""
    success = Trial(r).success
    for c in (r["class"], "all"):
        t = tally[(name, c)]
        t[0] += success
        t[1] += 1


def tally_ablation(rows, columns):
    """(methods, success tally, recovery counts, trials with a collision) of the ablation."""
    methods = first_seen(r["method"] for r in rows)
    tally = collections.defaultdict(lambda: [0, 0])
    rec = collections.defaultdict(collections.Counter)
    collisions = collections.Counter()
    for r in rows:
        count(tally, r["method"], r)
        counts = rec[r["method"]]  # a row per ablation method, counters or not
        for k in columns:
            counts[k] += int(number(r.get(k)) or 0)
        collisions[r["method"]] += (number(r.get("collisions")) or 0) > 0
    return methods, tally, rec, collisions


def add_sweep(path, keys, methods, tally):
    """The committed sweep's baselines on the ablation's instances, as methods of their own."""
    _, rows = read_trials(path)
    for r in rows:
        # rearm and its variants are the ablation's own rows.
        if r["method"].startswith("rearm") or instance_key(r) not in keys:
            continue
        name = r["method"] + " (committed sweep)"
        if name not in methods:
            methods.append(name)
        count(tally, name, r)


def print_success(classes, methods, tally):
    print("| method | " + " | ".join(classes) + " | all |")
    print("|---|" + "---|" * (len(classes) + 1))
    for m in methods:
        print(f"| {m} | " + " | ".join(cell(*tally[(m, c)]) for c in classes + ["all"]) + " |")
    print()


def print_recoveries(methods, rec, collisions, columns):
    head = ["method", "trials with a collision"] + [label(k) for k in columns]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for m in methods:
        if m in rec:
            row = [m, str(collisions[m])] + [str(rec[m][k]) for k in columns]
            print("| " + " | ".join(row) + " |")


def main(argv):
    if len(argv) not in (2, 3) or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    header, rows = read_trials(argv[1])
    columns = recovery_columns(header)
    methods, tally, rec, collisions = tally_ablation(rows, columns)
    if len(argv) > 2:
        add_sweep(argv[2], {instance_key(r) for r in rows}, methods, tally)
    print_success(sorted({r["class"] for r in rows}), methods, tally)
    print_recoveries(methods, rec, collisions, columns)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
