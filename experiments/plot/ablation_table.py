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
import csv
import math
import sys


def wilson(k, n, z=1.96):
    if n == 0:
        return (0.0, 0.0)
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (max(0.0, c - h), min(1.0, c + h))


def cell(k, n):
    lo, hi = wilson(k, n)
    return f"{k}/{n} ({100 * k / n:.0f}%, {100 * lo:.0f}–{100 * hi:.0f})" if n else "–"


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    classes = sorted({r["class"] for r in rows})
    methods = list(dict.fromkeys(r["method"] for r in rows))
    tally = collections.defaultdict(lambda: [0, 0])
    rec = collections.defaultdict(lambda: collections.Counter())
    collisions = collections.Counter()
    for r in rows:
        for c in (r["class"], "all"):
            t = tally[(r["method"], c)]
            t[0] += int(r["success"])
            t[1] += 1
        for k in ("guides", "back_outs", "singular_switches", "convex_fallbacks", "restores",
                  "early_releases", "withdrawals", "release_points",
                  "early_docks", "faces", "narrows", "fragment_fixes", "pocket_drops",
                  "redrops"):
            rec[r["method"]][k] += int(r.get(k) or 0)
        collisions[r["method"]] += int(r["collisions"]) > 0
    keys = {(r["class"], r["objects"], r["target_density"], r["instance_seed"]) for r in rows}
    if len(sys.argv) > 2:
        for r in csv.DictReader(open(sys.argv[2])):
            if r["method"].startswith("rearm"):
                continue
            if (r["class"], r["objects"], r["target_density"], r["instance_seed"]) not in keys:
                continue
            name = r["method"] + " (committed sweep)"
            if name not in methods:
                methods.append(name)
            for c in (r["class"], "all"):
                t = tally[(name, c)]
                t[0] += int(r["success"])
                t[1] += 1
    print("| method | " + " | ".join(classes) + " | all |")
    print("|---|" + "---|" * (len(classes) + 1))
    for m in methods:
        print(f"| {m} | " + " | ".join(cell(*tally[(m, c)]) for c in classes + ["all"]) + " |")
    print()
    print("| method | trials with a collision | guides | back-ups | singular switches | "
          "convex fallbacks | restores | early releases | withdrawals | release points | early docks | "
          "turns to the goal | narrow passages | ways beside unknown obstacles | pocket drops | redrops |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for m in methods:
        if m in rec:
            r = rec[m]
            print(f"| {m} | {collisions[m]} | {r['guides']} | {r['back_outs']} | "
                  f"{r['singular_switches']} | {r['convex_fallbacks']} | {r['restores']} | "
                  f"{r['early_releases']} | {r['withdrawals']} | {r['release_points']} | {r['early_docks']} | "
                  f"{r['faces']} | {r['narrows']} | {r['fragment_fixes']} | {r['pocket_drops']} | "
                  f"{r['redrops']} |")


if __name__ == "__main__":
    main()
