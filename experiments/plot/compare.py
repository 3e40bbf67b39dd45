#!/usr/bin/env python3
"""Table and plot of `rearm compare` (issue 7): rearm against the OMPL rearrangement baselines.

usage: compare.py COMPARISON.csv OUTDIR

Writes OUTDIR/comparison.md (per goal class, method and object count: success rate, median and
interquartile range of planning/compute time over successful trials, median actions and path
length) and OUTDIR/planning_time.png (top: median planning time vs objects on a log axis, with
the IQR as bars; bottom: success rate), one column per goal class.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHOD_LABEL = {"rearm": "rearm (reactive, online map)", "mrs": "B1 mRS (full map)",
                "birrt": "B2 BiRRT (full map)", "replan": "B2 replanning on discovery"}
METHOD_ORDER = ["rearm", "mrs", "birrt", "replan"]


def quantile(xs, q):
    xs = sorted(xs)
    if not xs:
        return float("nan")
    pos = q * (len(xs) - 1)
    lo = int(pos)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (pos - lo)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, out = sys.argv[1], sys.argv[2]
    rows = list(csv.DictReader(open(path)))
    if not rows:
        sys.exit("compare.py: no rows in " + path)
    # One panel per goal class and setting (target density, unknown obstacle shapes): rows of
    # several settings in one file are never pooled.
    def panel(r):
        return (r["class"], r["density"], r["unknown_shapes"])
    cells = defaultdict(list)
    for r in rows:
        cells[(panel(r), r["method"], int(r["objects"]))].append(r)
    classes = sorted({panel(r) for r in rows}, key=lambda c: (c[1], c[2], c[0] != "random", c[0]))

    def title(c):
        return "goal class: %s, density %s, unknown obstacles: %s" % c
    methods = [m for m in METHOD_ORDER if any(r["method"] == m for r in rows)]
    counts = sorted({int(r["objects"]) for r in rows})

    lines = ["# rearm vs the OMPL rearrangement baselines", "",
             "Source: `%s` (%d rows). Success: the task completed in Box2D with every object "
             "inside its goal region and 0 collisions. Times: rearm's compute time "
             "(controller_time_s: mission controller, topology checks, diffeomorphism "
             "rebuilds, control) and the baselines' planning time, median [IQR] over "
             "successful trials, in seconds. Statuses of failures in the last column." %
             (path, len(rows)), ""]
    for c in classes:
        lines += ["## " + title(c)[0].upper() + title(c)[1:], "",
                  "| method | N | success | time median [IQR] (s) | actions | robot path (m) "
                  "| failures |",
                  "|---|---|---|---|---|---|---|"]
        for m in methods:
            for n in counts:
                rs = cells.get((c, m, n), [])
                if not rs:
                    continue
                ok = [r for r in rs if r["success"] == "1"]
                t = [float(r["planning_time_s"]) for r in ok]
                acts = [float(r["actions"]) for r in ok]
                path_m = [float(r["robot_path_m"]) for r in ok]
                fails = defaultdict(int)
                for r in rs:
                    if r["success"] != "1":
                        fails[r["status"]] += 1
                ftxt = ", ".join("%s %d" % kv for kv in sorted(fails.items())) or "-"
                if t:
                    ttxt = "%.3g [%.3g, %.3g]" % (quantile(t, .5), quantile(t, .25),
                                                  quantile(t, .75))
                    atxt = "%.0f" % quantile(acts, .5)
                    ptxt = "%.1f" % quantile(path_m, .5)
                else:
                    ttxt = atxt = ptxt = "-"
                lines.append("| %s | %d | %d/%d | %s | %s | %s | %s |" %
                             (m, n, len(ok), len(rs), ttxt, atxt, ptxt, ftxt))
        lines.append("")
    with open(out + "/comparison.md", "w") as f:
        f.write("\n".join(lines) + "\n")

    fig, axes = plt.subplots(2, len(classes), figsize=(5.5 * len(classes), 7), squeeze=False,
                             sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    for col, c in enumerate(classes):
        ax, ax2 = axes[0][col], axes[1][col]
        for k, m in enumerate(methods):
            xs, med, lo, hi, sx, sr = [], [], [], [], [], []
            for n in counts:
                rs = cells.get((c, m, n), [])
                if not rs:
                    continue
                ok = [float(r["planning_time_s"]) for r in rs if r["success"] == "1"]
                sx.append(n + 0.06 * (k - 1.5))
                sr.append(len(ok) / len(rs))
                if ok:
                    xs.append(n + 0.06 * (k - 1.5))
                    q = quantile(ok, .5)
                    med.append(q)
                    lo.append(q - quantile(ok, .25))
                    hi.append(quantile(ok, .75) - q)
            if xs:
                ax.errorbar(xs, med, yerr=[lo, hi], marker="o", capsize=3,
                            label=METHOD_LABEL.get(m, m))
            ax2.plot(sx, sr, marker="o", label=METHOD_LABEL.get(m, m))
        ax.set_yscale("log")
        ax.set_title(title(c), fontsize=9)
        ax.set_ylabel("planning / compute time (s), median and IQR")
        ax.grid(True, which="both", alpha=0.3)
        ax2.set_ylim(-0.05, 1.05)
        ax2.set_xlabel("objects N")
        ax2.set_ylabel("success rate")
        ax2.set_xticks(counts)
        ax2.grid(True, alpha=0.3)
        if col == 0:
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out + "/planning_time.png", dpi=120)
    print("wrote %s/comparison.md and %s/planning_time.png" % (out, out))


if __name__ == "__main__":
    main()
