"""The figures of a `rearm sweep` folder (sweep.py): success, time, actions and path vs N,
success vs achieved density, and the fraction solved within t. matplotlib, drawn off-screen.

Every method of the CSV is drawn. PREFERRED_ORDER, METHOD_COLORS and MARKERS are presentation
defaults only: the named methods come first with their own colour and marker, and every other
method follows in the CSV's order with a colour of EXTRA_COLORS and the default marker.
"""
import math
import os
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from sweep_data import density_bins, density_cells  # noqa: E402
from sweep_report import fmt_density  # noqa: E402

PREFERRED_ORDER = ["rearm", "mrs", "birrt", "replan"]
METHOD_COLORS = {"rearm": "#1f5fbf", "mrs": "#d62728", "birrt": "#2ca02c", "replan": "#ff7f0e"}
EXTRA_COLORS = ["#9467bd", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"]
MARKERS = {"rearm": "o", "mrs": "s", "birrt": "^", "replan": "D"}
DEFAULT_MARKER = "v"
TIME_FLOOR_S = 1e-6  # a time of 0 is drawn here on the log axes

# The figures' file names and captions (report.md lists them).
FIGURES = [
    ("success_vs_n.png", "success rate vs N with Wilson 95% intervals; rows: goal class, "
                         "columns: target density"),
    ("time_vs_n.png", "median (IQR bars) time of the solved trials vs N, log axis"),
    ("success_vs_density.png", "success rate vs achieved obstacle density (binned), per class"),
    ("actions_vs_n.png", "median (IQR bars) actions of the solved trials vs N"),
    ("path_vs_n.png", "median (IQR bars) robot path length of the solved trials vs N"),
    ("solved_within_t.png", "fraction of all trials solved within time t, per class, log axis"),
]


# ----------------------------------------------------------------------------- methods


def presentation_order(methods):
    """Every method of `methods` once: PREFERRED_ORDER's first, then the rest in their order."""
    return ([m for m in PREFERRED_ORDER if m in methods]
            + [m for m in methods if m not in PREFERRED_ORDER])


def method_color(method, methods):
    """METHOD_COLORS' colour, else EXTRA_COLORS by the method's place among the unnamed ones."""
    if method in METHOD_COLORS:
        return METHOD_COLORS[method]
    others = [m for m in methods if m not in METHOD_COLORS]
    return EXTRA_COLORS[others.index(method) % len(EXTRA_COLORS)]


def draw_method(ax, m, methods, xs, ys, err):
    """One method's points with error bars: its colour, its marker, labelled with its name."""
    return ax.errorbar(xs, ys, yerr=err, color=method_color(m, methods),
                       marker=MARKERS.get(m, DEFAULT_MARKER), markersize=4, capsize=2.5,
                       linewidth=1.3, label=m)


def offsets(methods, spread):
    """Small horizontal offsets so that the methods' error bars do not overlap."""
    k = len(methods)
    return {m: (i - (k - 1) / 2) * spread for i, m in enumerate(methods)}


def bars(mid, lo, hi):
    """errorbar's yerr from the centres and the interval ends (rounding never goes negative)."""
    return [[max(0.0, m - a) for m, a in zip(mid, lo)], [max(0.0, b - m) for m, b in zip(mid, hi)]]


# ----------------------------------------------------------------------------- layout


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


def class_row(s, title):
    """A figure with a panel per class side by side, sharing the y axis."""
    cols = max(1, len(s.classes))
    fig, axes = plt.subplots(1, cols, figsize=(max(7.0, 4.0 * cols + 0.6), 3.9), squeeze=False,
                             sharey=True)
    suptitle(fig, title)
    return fig, axes


def suptitle(fig, title):
    """The figure's title at its top, wrapped to the figure's width."""
    lines = textwrap.wrap(title, width=int(fig.get_figwidth() * 9))
    fig.suptitle("\n".join(lines), fontsize=12, y=1 - 0.08 / fig.get_figheight(), va="top")
    fig.title_lines = len(lines)  # for finish(): the legend goes under the title


def footer(s):
    """The provenance line at the foot of every figure."""
    revs = ", ".join(s.revisions) if s.revisions else "unknown"
    label = "revision" if len(s.revisions) <= 1 else "revisions"
    return "sweep %s (%s)   %s %s   %d trials" % (
        s.name, os.path.join(os.path.basename(os.path.abspath(s.dir)), "sweep.yaml"),
        label, revs, len(s.trials))


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
    fig.text(0.01, 0.006, footer(s), fontsize=7.5, color="#444444", ha="left", va="bottom")
    fig.tight_layout(rect=(0, 0.28 / height, 1, 1 - top_in / height))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def legend_handles(methods, ax_lines):
    """One handle per method in the presentation order (the first line drawn for each)."""
    return [ax_lines[m] for m in methods if m in ax_lines]


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


# ----------------------------------------------------------------------------- figures


def plot_success_vs_n(s, methods, path):
    fig, axes = grid(s, "Success rate vs number of objects (Wilson 95% intervals)")
    off = offsets(methods, 0.06 * n_gap(s))
    handles = {}
    for i, cls in enumerate(s.classes):
        for j, d in enumerate(s.densities):
            ax = axes[i][j]
            for m in methods:
                pts = [(n, s.cell(cls, m, n, d)) for n in s.ns]
                pts = [(n, c) for n, c in pts if c is not None and c.n > 0]
                if not pts:
                    continue
                ys = [c.rate for _, c in pts]
                err = bars(ys, [c.ci[0] for _, c in pts], [c.ci[1] for _, c in pts])
                h = draw_method(ax, m, methods, [n + off[m] for n, _ in pts], ys, err)
                handles.setdefault(m, h)
            ax.set_ylim(-0.05, 1.05)
            label_panel(ax, s, i, j, cls, d, "success rate")
    finish(s, fig, path, legend_handles(methods, handles))


def median_points(s, cls, m, d, attr):
    """(N, (median, q1, q3)) of one method's cells in one panel that have the statistic."""
    pts = []
    for n in s.ns:
        c = s.cell(cls, m, n, d)
        stat = getattr(c, attr) if c is not None else None
        if stat is not None:
            pts.append((n, stat))
    return pts


def plot_median_vs_n(s, methods, path, attr, title, ylabel, log):
    fig, axes = grid(s, title)
    off = offsets(methods, 0.06 * n_gap(s))
    floor = TIME_FLOOR_S if log else -math.inf
    handles = {}
    for i, cls in enumerate(s.classes):
        for j, d in enumerate(s.densities):
            ax = axes[i][j]
            drawn = False
            for m in methods:
                pts = median_points(s, cls, m, d, attr)
                if not pts:
                    continue
                med, lo, hi = ([max(st[q], floor) for _, st in pts] for q in range(3))
                h = draw_method(ax, m, methods, [n + off[m] for n, _ in pts], med,
                                bars(med, lo, hi))
                handles.setdefault(m, h)
                drawn = True
            if log and drawn:
                log_axis(ax)
            if not drawn:
                ax.text(0.5, 0.5, "no successful trial", transform=ax.transAxes, ha="center",
                        va="center", fontsize=8.5, color="#888888")
            label_panel(ax, s, i, j, cls, d, ylabel)
    finish(s, fig, path, legend_handles(methods, handles))


def plot_success_vs_density(s, methods, path):
    edges = density_bins([x.achieved for x in s.trials])
    fig, axes = class_row(
        s, "Success rate vs achieved obstacle density (binned; Wilson 95% intervals)")
    width = (edges[1] - edges[0]) if len(edges) > 1 else 0.01
    off = offsets(methods, 0.08 * width)
    handles = {}
    for j, cls in enumerate(s.classes):
        ax = axes[0][j]
        for m in methods:
            cells = density_cells([x for x in s.trials if x.cls == cls and x.method == m], edges)
            if not cells:
                continue
            idx = sorted(cells)
            xs = [(edges[b] + edges[b + 1]) / 2 + off[m] for b in idx]
            ys = [cells[b].rate for b in idx]
            err = bars(ys, [cells[b].ci[0] for b in idx], [cells[b].ci[1] for b in idx])
            handles.setdefault(m, draw_method(ax, m, methods, xs, ys, err))
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
    finish(s, fig, path, legend_handles(methods, handles))


def plot_solved_within_t(s, methods, path):
    fig, axes = class_row(s, "Fraction of trials solved within time t (all N and densities)")
    solved_times = [x.time for x in s.trials if x.success and x.time is not None]
    t_min = max(TIME_FLOOR_S, min([t for t in solved_times if t > 0], default=1e-3) / 2)
    t_max = 1.4 * max(s.time_limits + solved_times + [t_min * 10])
    for j, cls in enumerate(s.classes):
        ax = axes[0][j]
        drawn = False
        for m in methods:
            mine = [x for x in s.trials if x.cls == cls and x.method == m]
            if not mine:
                continue
            times = sorted(max(x.time, t_min) for x in mine if x.success and x.time is not None)
            ys = [0.0] + [(i + 1) / len(mine) for i in range(len(times))]
            ax.step([t_min] + times + [t_max], ys + ys[-1:], where="post",
                    color=method_color(m, methods), linewidth=1.5,
                    label="%s (%d trials)" % (m, len(mine)))
            drawn = True
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
        if drawn:
            ax.legend(fontsize=7.5, loc="upper left", frameon=False)
    finish(s, fig, path)


def write_figures(s, d=None):
    """Every figure of FIGURES into folder d (default the sweep's folder)."""
    d = s.dir if d is None else d
    methods = presentation_order(s.methods)
    plot_success_vs_n(s, methods, os.path.join(d, "success_vs_n.png"))
    plot_median_vs_n(s, methods, os.path.join(d, "time_vs_n.png"), "time",
                     "Time vs number of objects: median and IQR of the solved trials "
                     "(rearm: compute, baselines: planning)", "time (s)", log=True)
    plot_success_vs_density(s, methods, os.path.join(d, "success_vs_density.png"))
    plot_median_vs_n(s, methods, os.path.join(d, "actions_vs_n.png"), "actions",
                     "Actions vs number of objects: median and IQR of the solved trials",
                     "actions", log=False)
    plot_median_vs_n(s, methods, os.path.join(d, "path_vs_n.png"), "path",
                     "Robot path length vs number of objects: median and IQR of the solved trials",
                     "robot path (m)", log=False)
    plot_solved_within_t(s, methods, os.path.join(d, "solved_within_t.png"))
