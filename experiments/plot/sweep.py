#!/usr/bin/env python3
"""Tables and figures of one `rearm sweep` folder (called by `rearm sweep report DIR`).

usage: sweep.py DIR

Reads DIR/trials.csv (one row per trial) and DIR/sweep.yaml (only its `name:` line), writes

  DIR/report.md               per class x method x N x target density: trials, successes,
                              success rate with its Wilson 95% interval, median and IQR of the
                              time, median achieved density, actions and robot path; the status
                              breakdown per method; and "what the numbers say", computed
  DIR/success_vs_n.png        success rate vs N (rows: goal class, columns: target density)
  DIR/time_vs_n.png           median and IQR of the time vs N, log axis
  DIR/success_vs_density.png  success rate vs achieved density, binned
  DIR/actions_vs_n.png        median and IQR of the actions vs N
  DIR/path_vs_n.png           median and IQR of the robot path length vs N
  DIR/solved_within_t.png     fraction of trials solved within t, per method, log axis

The time of a trial is its planning time where the row has one (the offline baselines) and its
compute time otherwise (rearm: mission + topology + rebuilds + control). Medians of time,
actions and path are over the successful trials of a cell (no success: no point, "-" in the
table); the achieved density's median is over all trials. Only python3's standard library and
matplotlib are used. A cut last line of the CSV and rows of the wrong width are skipped with a
warning; empty or non-numeric fields count as missing.
"""
import csv
import math
import os
import sys
import textwrap
from collections import Counter, defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

Z95 = 1.959963984540054  # two-sided 95% normal quantile
KNOWN_METHODS = ["rearm", "mrs", "birrt", "replan"]
KNOWN_CLASSES = ["random", "cyclic", "sealed"]
METHOD_COLORS = {"rearm": "#1f5fbf", "mrs": "#d62728", "birrt": "#2ca02c", "replan": "#ff7f0e"}
EXTRA_COLORS = ["#9467bd", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"]
MARKERS = {"rearm": "o", "mrs": "s", "birrt": "^", "replan": "D"}
TIME_FLOOR_S = 1e-6  # a time of 0 is drawn here on the log axes


# ----------------------------------------------------------------------------- reading


def warn(msg):
    print("sweep.py: warning: " + msg, file=sys.stderr)


def number(text):
    """A finite float, or None for an empty, non-numeric or non-finite field."""
    if text is None:
        return None
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def read_trials(path):
    """The rows of trials.csv as dicts; a cut last line and damaged rows are dropped."""
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        text = f.read()
    if text and not text.endswith("\n"):
        cut = text.rfind("\n")
        warn("%s: dropping a cut last line" % path)
        text = text[: cut + 1] if cut >= 0 else ""
    reader = csv.reader(text.splitlines(keepends=True))
    header = next(reader, None)
    if not header:
        return [], []
    rows = []
    for line_no, fields in enumerate(reader, start=2):
        if not fields:
            continue
        if len(fields) != len(header):
            warn("%s: line %d has %d fields, the header %d: skipped"
                 % (path, line_no, len(fields), len(header)))
            continue
        rows.append(dict(zip(header, fields)))
    return header, rows


def sweep_name(dir_path, rows):
    """The sweep's name: sweep.yaml's top-level `name:`, else the rows' sweep column."""
    path = os.path.join(dir_path, "sweep.yaml")
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("name:"):
                    value = line[len("name:"):].split(" #")[0].strip().strip("'\"")
                    if value:
                        return value
    except OSError:
        warn("%s: cannot read; naming the sweep from the CSV" % path)
    names = sorted({r.get("sweep", "") for r in rows} - {""})
    return ", ".join(names) if names else os.path.basename(os.path.abspath(dir_path))


class Trial:
    """The fields of one row that the report uses, parsed."""

    def __init__(self, r):
        self.method = r.get("method", "") or "?"
        self.cls = r.get("class", "") or "?"
        n = number(r.get("objects"))
        self.n = int(n) if n is not None else None
        self.density = number(r.get("target_density"))
        self.achieved = number(r.get("achieved_density"))
        self.status = r.get("status", "") or "?"
        self.success = r.get("success", "").strip() == "1"
        planning = number(r.get("planning_time_s"))
        self.time = planning if planning is not None else number(r.get("compute_time_s"))
        self.time_limit = number(r.get("time_limit_s"))
        self.actions = number(r.get("actions"))
        self.path = number(r.get("robot_path_m"))
        self.reason = r.get("reason", "")
        self.revision = r.get("revision", "")
        self.host = r.get("host", "")
        self.cpu = r.get("cpu_model", "")
        # Settings that may vary in a sweep beyond class x N x density: pooled in the figures,
        # kept apart in the table when they do vary.
        self.variant = (r.get("unknown_fraction", ""), r.get("unknown_shapes", ""),
                        r.get("workspace_rule", ""))


# ----------------------------------------------------------------------------- statistics


def wilson(k, n, z=Z95):
    """Wilson score interval of k successes in n trials: (low, high); (nan, nan) for n = 0."""
    if n == 0:
        return float("nan"), float("nan")
    p = k / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, centre - half), min(1.0, centre + half)


def quantile(sorted_xs, q):
    """Linear-interpolation quantile (numpy's default) of a sorted, non-empty list."""
    pos = q * (len(sorted_xs) - 1)
    lo = math.floor(pos)
    hi = min(lo + 1, len(sorted_xs) - 1)
    return sorted_xs[lo] + (sorted_xs[hi] - sorted_xs[lo]) * (pos - lo)


def summary(values):
    """(median, q1, q3) of the non-missing values, or None when there are none."""
    xs = sorted(v for v in values if v is not None)
    if not xs:
        return None
    return quantile(xs, 0.5), quantile(xs, 0.25), quantile(xs, 0.75)


class Cell:
    """The trials of one method in one cell (class, N, target density[, variant])."""

    def __init__(self, trials):
        self.trials = trials
        self.n = len(trials)
        self.k = sum(t.success for t in trials)
        self.rate = self.k / self.n if self.n else float("nan")
        self.ci = wilson(self.k, self.n)
        ok = [t for t in trials if t.success]
        self.time = summary(t.time for t in ok)
        self.time_all = summary(t.time for t in trials)
        self.actions = summary(t.actions for t in ok)
        self.path = summary(t.path for t in ok)
        self.achieved = summary(t.achieved for t in trials)


# ----------------------------------------------------------------------------- ordering


def ordered(values, known):
    """The known names first in their order, then the others sorted."""
    values = set(values)
    return [v for v in known if v in values] + sorted(values - set(known))


def sort_numbers(values):
    return sorted({v for v in values if v is not None})


def method_color(method, methods):
    if method in METHOD_COLORS:
        return METHOD_COLORS[method]
    others = [m for m in methods if m not in METHOD_COLORS]
    return EXTRA_COLORS[others.index(method) % len(EXTRA_COLORS)]


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return "%.*g" % (digits, x)


def fmt_density(d):
    return "-" if d is None else "%g" % d


def md_cell(text):
    """Text safe inside a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


# ----------------------------------------------------------------------------- the data set


class Sweep:
    def __init__(self, dir_path):
        self.dir = dir_path
        csv_path = os.path.join(dir_path, "trials.csv")
        header, rows = read_trials(csv_path)
        self.header = header
        self.name = sweep_name(dir_path, rows)
        self.trials = [Trial(r) for r in rows]
        t = self.trials
        self.methods = ordered((x.method for x in t), KNOWN_METHODS)
        self.classes = ordered((x.cls for x in t), KNOWN_CLASSES)
        self.ns = sort_numbers(x.n for x in t)
        self.densities = sort_numbers(x.density for x in t)
        self.variants = sorted({x.variant for x in t})
        self.revisions = sorted({x.revision for x in t} - {""})
        self.hosts = sorted({x.host for x in t} - {""})
        self.cpus = sorted({x.cpu for x in t} - {""})
        self.time_limits = sort_numbers(x.time_limit for x in t)
        # (class, method, N, density) -> Cell; the variant pooled.
        groups = defaultdict(list)
        for x in t:
            groups[(x.cls, x.method, x.n, x.density)].append(x)
        self.cells = {k: Cell(v) for k, v in groups.items()}
        # The same with the variant kept apart, for the table when variants differ.
        vgroups = defaultdict(list)
        for x in t:
            vgroups[(x.cls, x.method, x.n, x.density, x.variant)].append(x)
        self.vcells = {k: Cell(v) for k, v in vgroups.items()}

    def cell(self, cls, method, n, density):
        return self.cells.get((cls, method, n, density))

    def pooled(self, cls=None, method=None, n=None, density=None):
        """A Cell of every trial matching the given settings (None: any)."""
        return Cell([x for x in self.trials
                     if (cls is None or x.cls == cls) and (method is None or x.method == method)
                     and (n is None or x.n == n) and (density is None or x.density == density)])

    def footer(self):
        revs = ", ".join(self.revisions) if self.revisions else "unknown"
        label = "revision" if len(self.revisions) <= 1 else "revisions"
        return "sweep %s (%s)   %s %s   %d trials" % (
            self.name, os.path.join(os.path.basename(os.path.abspath(self.dir)), "sweep.yaml"),
            label, revs, len(self.trials))


# ----------------------------------------------------------------------------- report.md


def write_report(s, path):
    lines = []
    add = lines.append
    add("# Sweep `%s`" % s.name)
    add("")
    add("- folder: `%s`, %d trials, methods: %s" % (s.dir, len(s.trials), ", ".join(s.methods)))
    add("- classes: %s; N: %s; target densities: %s"
        % (", ".join(s.classes), ", ".join(str(n) for n in s.ns),
           ", ".join(fmt_density(d) for d in s.densities)))
    add("- time limit per trial: %s s" % (", ".join("%g" % x for x in s.time_limits) or "-"))
    add("- revision: %s; host: %s; CPU: %s"
        % (", ".join(s.revisions) or "-", ", ".join(s.hosts) or "-", ", ".join(s.cpus) or "-"))
    add("- time = planning_time_s for the offline baselines, compute_time_s (mission + topology "
        "+ rebuilds + control) for rearm; medians of time, actions and path are over the "
        "successful trials; success = completed, every goal reached, no collision; "
        "95% intervals are Wilson score intervals.")
    add("")
    if not s.trials:
        add("No complete trial rows in trials.csv.")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        return

    add("## What the numbers say")
    add("")
    for line in findings(s):
        add("- " + line)
    add("")

    add("## Success and cost per cell")
    add("")
    vary = len(s.variants) > 1
    head = ["class", "method", "N", "density"]
    if vary:
        head += ["unknown", "shapes", "workspace"]
    head += ["trials", "successes", "success (95% CI)", "time s: median [IQR]",
             "time s, all trials: median", "achieved density", "actions", "path m"]
    add("| " + " | ".join(head) + " |")
    add("|" + "|".join("---" for _ in head) + "|")
    source = s.vcells if vary else s.cells
    for cls in s.classes:
        for method in s.methods:
            keys = sorted((k for k in source if k[0] == cls and k[1] == method),
                          key=lambda k: (k[2] is None, k[2] or 0, k[3] is None, k[3] or 0, k[4:]))
            for k in keys:
                c = source[k]
                row = [cls, method, "-" if k[2] is None else str(k[2]), fmt_density(k[3])]
                if vary:
                    row += [md_cell(v) or "-" for v in k[4]]
                row += [str(c.n), str(c.k),
                        "%.2f [%.2f, %.2f]" % (c.rate, c.ci[0], c.ci[1]),
                        iqr_text(c.time), fmt(c.time_all[0] if c.time_all else None),
                        fmt(c.achieved[0] if c.achieved else None),
                        fmt(c.actions[0] if c.actions else None),
                        fmt(c.path[0] if c.path else None)]
                add("| " + " | ".join(md_cell(x) for x in row) + " |")
    add("")

    add("## Status per method")
    add("")
    statuses = ordered((x.status for x in s.trials),
                       ["completed", "infeasible", "stuck", "timeout", "unsolved",
                        "invalid_plan", "failed", "error"])
    head = ["method", "trials", "successes"] + statuses
    add("| " + " | ".join(head) + " |")
    add("|" + "|".join("---" for _ in head) + "|")
    for method in s.methods:
        mine = [x for x in s.trials if x.method == method]
        counts = Counter(x.status for x in mine)
        row = [method, str(len(mine)), str(sum(x.success for x in mine))]
        row += [str(counts.get(st, 0)) for st in statuses]
        add("| " + " | ".join(md_cell(x) for x in row) + " |")
    add("")
    completed_not_success = [x for x in s.trials if x.status == "completed" and not x.success]
    if completed_not_success:
        add("%d trial(s) ended `completed` without counting as a success (a goal missed or a "
            "collision)." % len(completed_not_success))
        add("")

    add("## Most frequent reasons of the unsuccessful trials")
    add("")
    any_reason = False
    for method in s.methods:
        reasons = Counter(x.reason or "(no reason given)" for x in s.trials
                          if x.method == method and not x.success)
        if not reasons:
            continue
        any_reason = True
        top = ", ".join('%d x "%s"' % (k, md_cell(r)) for r, k in reasons.most_common(3))
        add("- %s: %s" % (method, top))
    if not any_reason:
        add("Every trial succeeded.")
    add("")

    add("## Figures")
    add("")
    for name, what in FIGURES:
        add("- `%s`: %s" % (name, what))
    add("")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def iqr_text(stat):
    if stat is None:
        return "-"
    return "%s [%s, %s]" % (fmt(stat[0]), fmt(stat[1]), fmt(stat[2]))


def rate_text(c):
    return "%d/%d = %.2f [%.2f, %.2f]" % (c.k, c.n, c.rate, c.ci[0], c.ci[1])


def ratio_text(r):
    return "%.0f" % r if r >= 10 else "%.2g" % r


def cell_name(n, d):
    return "(N=%s, d=%s)" % ("-" if n is None else n, fmt_density(d))


MAX_LISTED = 4  # cells named in one finding
MIN_BIN_TRIALS = 5  # trials a density bin needs to be quoted in the findings


def failure_name(trial):
    """The status of an unsuccessful trial, `completed` told apart from a success."""
    return "completed without success" if trial.status == "completed" else trial.status


def findings(s):
    """Plain facts computed from the cells: who leads each class, where each method loses."""
    out = []
    for cls in s.classes:
        pooled = {m: s.pooled(cls=cls, method=m) for m in s.methods}
        pooled = {m: c for m, c in pooled.items() if c.n > 0}
        if not pooled:
            continue
        best_rate = max(c.rate for c in pooled.values())
        leaders = [m for m, c in pooled.items() if c.rate == best_rate]
        ranking = sorted(pooled, key=lambda m: -pooled[m].rate)
        text = "**%s goals**: highest success %s (%s)" % (
            cls, " and ".join(leaders), rate_text(pooled[leaders[0]]))
        rest = [m for m in ranking if m not in leaders]
        if rest:
            text += "; then " + "; ".join("%s %s" % (m, rate_text(pooled[m])) for m in rest)
        absent = [m for m in s.methods if m not in pooled]
        if absent:
            text += "; no rows for " + ", ".join(absent)
        out.append(text + ".")
        # Cells where one method's interval lies wholly below another's.
        for m in ranking:
            beaten = []
            for n in s.ns:
                for d in s.densities:
                    mine = s.cell(cls, m, n, d)
                    if mine is None or mine.n == 0:
                        continue
                    for other in ranking:
                        theirs = s.cell(cls, other, n, d)
                        if other != m and theirs and theirs.n and theirs.ci[0] > mine.ci[1]:
                            beaten.append("%s: %.2f vs %s %.2f)"
                                          % (cell_name(n, d)[:-1], mine.rate, other, theirs.rate))
                            break
            mine = [s.cell(cls, m, n, d) for n in s.ns for d in s.densities if s.cell(cls, m, n, d)]
            low = min((c.rate for c in mine), default=None)
            worst = [c for c in mine if c.rate == low]
            fails = Counter(failure_name(x) for x in pooled[m].trials if not x.success)
            parts = []
            if beaten:
                shown = beaten[:MAX_LISTED]
                more = len(beaten) - len(shown)
                parts.append("its 95% interval wholly below another method's at "
                             + ", ".join(shown) + (" and %d more cells" % more if more else ""))
            if worst and low < 1 and len(worst) == len(mine) > 1:
                parts.append("success %.2f in all its %d cells" % (low, len(mine)))
            elif worst and low < 1:
                names = [cell_name(c.trials[0].n, c.trials[0].density) for c in worst]
                more = len(names) - MAX_LISTED
                parts.append("lowest success %.2f at %s%s" % (
                    low, ", ".join(names[:MAX_LISTED]),
                    " and %d more cells" % more if more > 0 else ""))
            if fails:
                parts.append("failures: " + ", ".join("%d %s" % (k, st)
                                                     for st, k in fails.most_common()))
            if parts:
                out.append("%s / %s: %s." % (cls, m, "; ".join(parts)))
            else:
                out.append("%s / %s: every trial succeeded." % (cls, m))
    # Time growth with N and the fastest method at the largest N.
    if len(s.ns) > 1:
        lo, hi = s.ns[0], s.ns[-1]
        for m in s.methods:
            a = s.pooled(method=m, n=lo).time
            b = s.pooled(method=m, n=hi).time
            if a and b and a[0] > 0:
                out.append("%s: median time of the solved trials (all classes and densities) "
                           "%s s at N=%s, %s s at N=%s (x%s)."
                           % (m, fmt(a[0]), lo, fmt(b[0]), hi, ratio_text(b[0] / a[0])))
            elif a or b:
                out.append("%s: median time of the solved trials (all classes and densities) "
                           "%s s at N=%s, %s s at N=%s."
                           % (m, fmt(a[0] if a else None), lo, fmt(b[0] if b else None), hi))
    top_n = s.ns[-1] if s.ns else None
    timed = [(s.pooled(method=m, n=top_n).time, m) for m in s.methods]
    timed = [(t[0], m) for t, m in timed if t]
    if timed:
        t, m = min(timed)
        out.append("Fastest median time of the solved trials at N=%s (all classes and densities): "
                   "%s (%s s)." % (top_n, m, fmt(t)))
    # Success in the sparsest and the densest achieved-density bin holding enough trials.
    edges = density_bins([x.achieved for x in s.trials])
    if len(edges) > 2:
        for m in s.methods:
            bins = defaultdict(list)
            for x in s.trials:
                if x.method == m and x.achieved is not None:
                    bins[bin_index(x.achieved, edges)].append(x)
            full = sorted(b for b, v in bins.items() if len(v) >= MIN_BIN_TRIALS)
            if len(full) < 2:
                continue
            lo, hi = full[0], full[-1]
            a, b = Cell(bins[lo]), Cell(bins[hi])
            out.append("%s: success %.2f (n=%d) at achieved density %.3g-%.3g, %.2f (n=%d) "
                       "at %.3g-%.3g." % (m, a.rate, a.n, edges[lo], edges[lo + 1], b.rate, b.n,
                                          edges[hi], edges[hi + 1]))
    errors = sum(x.status == "error" for x in s.trials)
    if errors:
        out.append("%d trial(s) ended in `error` (an exception in the trial)." % errors)
    return out


# ----------------------------------------------------------------------------- figures

FIGURES = [
    ("success_vs_n.png", "success rate vs N with Wilson 95% intervals; rows: goal class, "
                         "columns: target density"),
    ("time_vs_n.png", "median (IQR bars) time of the solved trials vs N, log axis"),
    ("success_vs_density.png", "success rate vs achieved obstacle density (binned), per class"),
    ("actions_vs_n.png", "median (IQR bars) actions of the solved trials vs N"),
    ("path_vs_n.png", "median (IQR bars) robot path length of the solved trials vs N"),
    ("solved_within_t.png", "fraction of all trials solved within time t, per class, log axis"),
]


def offsets(methods, spread):
    """Small horizontal offsets so that the methods' error bars do not overlap."""
    k = len(methods)
    return {m: (i - (k - 1) / 2) * spread for i, m in enumerate(methods)}


def bars(mid, lo, hi):
    """errorbar's yerr from the centres and the interval ends (rounding never goes negative)."""
    return [[max(0.0, m - a) for m, a in zip(mid, lo)], [max(0.0, b - m) for m, b in zip(mid, hi)]]


def n_gap(s):
    """The smallest step between two object counts of the sweep (1 for a single N)."""
    gaps = [b - a for a, b in zip(s.ns, s.ns[1:])]
    return min(gaps) if gaps else 1


def grid(s, title):
    """A figure with a panel per class (rows) and per target density (columns)."""
    rows = max(1, len(s.classes))
    cols = max(1, len(s.densities))
    fig, axes = plt.subplots(rows, cols, figsize=(3.3 * cols + 0.8, 2.6 * rows + 1.0),
                             squeeze=False, sharex=True)
    suptitle(fig, title)
    return fig, axes


def suptitle(fig, title):
    """The figure's title at its top, wrapped to the figure's width."""
    lines = textwrap.wrap(title, width=int(fig.get_figwidth() * 9))
    fig.suptitle("\n".join(lines), fontsize=12, y=1 - 0.08 / fig.get_figheight(), va="top")
    fig.title_lines = len(lines)  # for finish(): the legend goes under the title


def finish(s, fig, path, handles=None):
    """The methods' legend under the title, the provenance footer, then save and close."""
    height = fig.get_figheight()
    top_in = 0.04  # tight_layout already keeps room for the title
    if handles:
        below_title = 0.14 + 0.22 * getattr(fig, "title_lines", 1)
        fig.legend(handles, [h.get_label() for h in handles], loc="upper center",
                   ncol=min(6, len(handles)), fontsize=9, frameon=False,
                   bbox_to_anchor=(0.5, 1 - below_title / height))
        top_in += 0.3
    fig.text(0.01, 0.006, s.footer(), fontsize=7.5, color="#444444", ha="left", va="bottom")
    fig.tight_layout(rect=(0, 0.28 / height, 1, 1 - top_in / height))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def legend_handles(s, ax_lines):
    """One handle per method in the sweep's order (the first line drawn for each)."""
    return [ax_lines[m] for m in s.methods if m in ax_lines]


def n_axis(ax, s):
    ns = s.ns or [0]
    ax.set_xticks(ns)
    pad = 0.5 if len(ns) == 1 else 0.06 * (ns[-1] - ns[0]) + 0.3
    ax.set_xlim(ns[0] - pad, ns[-1] + pad)


def label_panel(ax, s, i, j, cls, d, ylabel):
    ax.set_title("%s, density %s" % (cls, fmt_density(d)), fontsize=9.5)
    if j == 0:
        ax.set_ylabel(ylabel, fontsize=9)
    if i == len(s.classes) - 1:
        ax.set_xlabel("objects N", fontsize=9)
    ax.grid(True, alpha=0.3)
    n_axis(ax, s)


def plot_success_vs_n(s, path):
    fig, axes = grid(s, "Success rate vs number of objects (Wilson 95% intervals)")
    off = offsets(s.methods, 0.06 * n_gap(s))
    handles = {}
    for i, cls in enumerate(s.classes):
        for j, d in enumerate(s.densities):
            ax = axes[i][j]
            for m in s.methods:
                pts = [(n, s.cell(cls, m, n, d)) for n in s.ns]
                pts = [(n, c) for n, c in pts if c is not None and c.n > 0]
                if not pts:
                    continue
                xs = [n + off[m] for n, _ in pts]
                ys = [c.rate for _, c in pts]
                err = bars(ys, [c.ci[0] for _, c in pts], [c.ci[1] for _, c in pts])
                h = ax.errorbar(xs, ys, yerr=err, color=method_color(m, s.methods),
                                marker=MARKERS.get(m, "v"), markersize=4, capsize=2.5,
                                linewidth=1.3, label=m)
                handles.setdefault(m, h)
            ax.set_ylim(-0.05, 1.05)
            label_panel(ax, s, i, j, cls, d, "success rate")
    finish(s, fig, path, legend_handles(s, handles))


def plot_median_vs_n(s, path, attr, title, ylabel, log):
    fig, axes = grid(s, title)
    off = offsets(s.methods, 0.06 * n_gap(s))
    handles = {}
    for i, cls in enumerate(s.classes):
        for j, d in enumerate(s.densities):
            ax = axes[i][j]
            drawn = False
            for m in s.methods:
                pts = []
                for n in s.ns:
                    c = s.cell(cls, m, n, d)
                    stat = getattr(c, attr) if c is not None else None
                    if stat is not None:
                        pts.append((n, stat))
                if not pts:
                    continue
                floor = TIME_FLOOR_S if log else -math.inf
                med = [max(st[0], floor) for _, st in pts]
                lo = [max(st[1], floor) for _, st in pts]
                hi = [max(st[2], floor) for _, st in pts]
                err = bars(med, lo, hi)
                h = ax.errorbar([n + off[m] for n, _ in pts], med, yerr=err,
                                color=method_color(m, s.methods), marker=MARKERS.get(m, "v"),
                                markersize=4, capsize=2.5, linewidth=1.3, label=m)
                handles.setdefault(m, h)
                drawn = True
            if log and drawn:
                log_axis(ax)
            if not drawn:
                ax.text(0.5, 0.5, "no successful trial", transform=ax.transAxes, ha="center",
                        va="center", fontsize=8.5, color="#888888")
            label_panel(ax, s, i, j, cls, d, ylabel)
    finish(s, fig, path, legend_handles(s, handles))


def log_axis(ax):
    """A log y axis spanning at least a decade and a bit, so that a power of ten is labelled."""
    ax.set_yscale("log")
    lo, hi = math.inf, 0.0
    for line in ax.get_lines():
        for y in line.get_ydata():
            if y > 0 and math.isfinite(y):
                lo, hi = min(lo, y), max(hi, y)
    if hi <= 0:
        return
    ratio = hi / lo
    grow = math.sqrt(12 / ratio) if ratio < 12 else 1.3
    ax.set_ylim(lo / grow, hi * grow)


def nice_width(span):
    for w in (0.005, 0.01, 0.02, 0.025, 0.05, 0.1, 0.2, 0.25, 0.5):
        if span / w <= 8:
            return w
    return span / 8


def density_bins(values):
    """Bin edges over the achieved densities: round widths, at most about 8 bins."""
    xs = [v for v in values if v is not None]
    if not xs:
        return []
    lo, hi = min(xs), max(xs)
    if hi - lo < 1e-9:
        return [lo - 0.005, hi + 0.005]
    w = nice_width(hi - lo)
    start = math.floor(lo / w + 1e-9) * w
    edges = [start]
    while edges[-1] <= hi + 1e-12:
        edges.append(round(edges[-1] + w, 10))
    return edges


def bin_index(x, edges):
    for i in range(len(edges) - 1):
        if x < edges[i + 1] or i == len(edges) - 2:
            return i
    return len(edges) - 2


def plot_success_vs_density(s, path):
    edges = density_bins([x.achieved for x in s.trials])
    cols = max(1, len(s.classes))
    fig, axes = plt.subplots(1, cols, figsize=(max(7.0, 4.0 * cols + 0.6), 3.9), squeeze=False,
                             sharey=True)
    suptitle(fig, "Success rate vs achieved obstacle density (binned; Wilson 95% intervals)")
    width = (edges[1] - edges[0]) if len(edges) > 1 else 0.01
    off = offsets(s.methods, 0.08 * width)
    handles = {}
    for j, cls in enumerate(s.classes):
        ax = axes[0][j]
        for m in s.methods:
            bins = defaultdict(list)
            for x in s.trials:
                if x.cls == cls and x.method == m and x.achieved is not None:
                    bins[bin_index(x.achieved, edges)].append(x)
            if not bins:
                continue
            idx = sorted(bins)
            cells = [Cell(bins[b]) for b in idx]
            xs = [(edges[b] + edges[b + 1]) / 2 + off[m] for b in idx]
            ys = [c.rate for c in cells]
            err = bars(ys, [c.ci[0] for c in cells], [c.ci[1] for c in cells])
            h = ax.errorbar(xs, ys, yerr=err, color=method_color(m, s.methods),
                            marker=MARKERS.get(m, "v"), markersize=4, capsize=2.5,
                            linewidth=1.3, label=m)
            handles.setdefault(m, h)
        ax.set_title("%s goals" % cls, fontsize=10)
        ax.set_xlabel("achieved density (bins of %g)" % width, fontsize=9)
        if edges:
            ax.set_xlim(edges[0], edges[-1])
            ax.set_xticks(edges if len(edges) <= 10 else edges[::2])
            ax.tick_params(axis="x", labelsize=8)
        ax.set_ylim(-0.05, 1.05)
        ax.grid(True, alpha=0.3)
        if j == 0:
            ax.set_ylabel("success rate", fontsize=9)
    finish(s, fig, path, legend_handles(s, handles))


def plot_solved_within_t(s, path):
    cols = max(1, len(s.classes))
    fig, axes = plt.subplots(1, cols, figsize=(max(7.0, 4.0 * cols + 0.6), 3.9), squeeze=False,
                             sharey=True)
    suptitle(fig, "Fraction of trials solved within time t (all N and densities)")
    solved_times = [x.time for x in s.trials if x.success and x.time is not None]
    t_min = max(TIME_FLOOR_S, min([t for t in solved_times if t > 0], default=1e-3) / 2)
    t_max = 1.4 * max(s.time_limits + solved_times + [t_min * 10])
    handles = {}
    for j, cls in enumerate(s.classes):
        ax = axes[0][j]
        for m in s.methods:
            mine = [x for x in s.trials if x.cls == cls and x.method == m]
            if not mine:
                continue
            times = sorted(max(x.time, t_min) for x in mine if x.success and x.time is not None)
            xs = [t_min] + times + [t_max]
            ys = [0.0] + [(i + 1) / len(mine) for i in range(len(times))]
            ys.append(ys[-1])
            (h,) = ax.step(xs, ys, where="post", color=method_color(m, s.methods),
                           linewidth=1.5, label="%s (%d trials)" % (m, len(mine)))
            handles.setdefault(m, h)
        for limit in s.time_limits:
            ax.axvline(limit, color="#888888", linestyle="--", linewidth=0.9)
        ax.set_xscale("log")
        ax.set_xlim(t_min, t_max)
        ax.set_ylim(0, 1.02)
        ax.set_title("%s goals" % cls, fontsize=10)
        ax.set_xlabel("time t (s); dashed: time limit", fontsize=9)
        ax.grid(True, which="both", alpha=0.25)
        if j == 0:
            ax.set_ylabel("fraction solved", fontsize=9)
        if handles:
            ax.legend(fontsize=7.5, loc="upper left", frameon=False)
    finish(s, fig, path)


def write_figures(s):
    d = s.dir
    plot_success_vs_n(s, os.path.join(d, "success_vs_n.png"))
    plot_median_vs_n(s, os.path.join(d, "time_vs_n.png"), "time",
                     "Time vs number of objects: median and IQR of the solved trials "
                     "(rearm: compute, baselines: planning)", "time (s)", log=True)
    plot_success_vs_density(s, os.path.join(d, "success_vs_density.png"))
    plot_median_vs_n(s, os.path.join(d, "actions_vs_n.png"), "actions",
                     "Actions vs number of objects: median and IQR of the solved trials",
                     "actions", log=False)
    plot_median_vs_n(s, os.path.join(d, "path_vs_n.png"), "path",
                     "Robot path length vs number of objects: median and IQR of the solved trials",
                     "robot path (m)", log=False)
    plot_solved_within_t(s, os.path.join(d, "solved_within_t.png"))


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    d = argv[1]
    if not os.path.isfile(os.path.join(d, "trials.csv")):
        print("sweep.py: %s has no trials.csv" % d, file=sys.stderr)
        return 1
    s = Sweep(d)
    write_report(s, os.path.join(d, "report.md"))
    if s.trials:
        write_figures(s)
        print("wrote %s/report.md and %d figures (%d trials)" % (d, len(FIGURES), len(s.trials)))
    else:
        print("wrote %s/report.md (no trials: no figures)" % d)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
