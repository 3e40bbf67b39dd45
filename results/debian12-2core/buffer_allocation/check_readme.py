#!/usr/bin/env python3
"""Prints every number README.md quotes, recomputed from this folder's trials.csv and, for
BiRRT@10000 on the same instances, from ../crowded/trials.csv (standard library only).

run: python3 results/debian12-2core/buffer_allocation/check_readme.py
"""
import csv
import os
import sys
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "experiments", "plot"))
from sweep_data import sign_test  # noqa: E402  (the report's own test, checked by tests/plot)
FOOTPRINT = "footprint 0.08"


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["workspace_rule"].startswith(FOOTPRINT)]


def solved(rs, method):
    """instance -> success of the method's row."""
    return {r["instance"]: r["success"] == "1" for r in rs if r["method"] == method}


def paired(a, b):
    both = [i for i in a if i in b]
    counts = (sum(a[i] and b[i] for i in both), sum(a[i] and not b[i] for i in both),
              sum(b[i] and not a[i] for i in both), sum(not a[i] and not b[i] for i in both))
    return counts + (sign_test(counts[1], counts[2]),)


def main():
    here = rows(os.path.join(HERE, "trials.csv"))
    crowded = rows(os.path.join(HERE, "..", "crowded", "trials.csv"))
    methods = {"buffer@10000": solved(here, "buffer@10000"),
               "buffer-strict@10000": solved(here, "buffer-strict@10000"),
               "birrt@10000": solved(here, "birrt@10000"),
               "birrt@10000 (crowded study)": solved(crowded, "birrt@10000"),
               "buffer@10000 (crowded study)": solved(crowded, "buffer@10000")}
    by_class = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for r in here:
        c = by_class[r["method"]][r["class"]]
        c[0] += r["success"] == "1"
        c[1] += 1
    for m, s in methods.items():
        print("%-30s %d/%d" % (m, sum(s.values()), len(s)))
    for m in ("buffer@10000", "buffer-strict@10000", "birrt@10000"):
        print("  %s by class: %s" % (m, ", ".join("%s %d/%d" % (k, v[0], v[1])
                                                   for k, v in sorted(by_class[m].items()))))
    for a, b in (("buffer@10000", "buffer-strict@10000"),
                 ("buffer@10000", "birrt@10000"),
                 ("birrt@10000", "birrt@10000 (crowded study)"),
                 ("buffer-strict@10000", "buffer@10000 (crowded study)")):
        both, only_a, only_b, neither, p = paired(methods[a], methods[b])
        print("%s vs %s: both %d, only the first %d, only the second %d, neither %d, "
              "sign test p = %.3g" % (a, b, both, only_a, only_b, neither, p))
    cpu = defaultdict(float)
    for r in here:
        cpu[r["method"]] += float(r["planning_time_s"] or 0)
    for m, s in sorted(cpu.items()):
        print("%s planning CPU: %.1f min" % (m, s / 60))


if __name__ == "__main__":
    main()
