"""The figures of a sweep over the objects' footprint (experiments/sweeps/README.md, "Crowded
rooms"), drawn by sweep.py when a sweep has more than one footprint: success against the
footprint with a panel per N, the time of the solved trials against N with a panel per
footprint (log axis), and success against each difficulty column. Goal classes and obstacle
densities are pooled in all three (the report's table keeps every cell apart).
"""
import math

from sweep_data import DIFFICULTY_COLUMNS, Cell, pooled
from sweep_figures import (TIME_FLOOR_S, bars, draw_method, finish, legend_handles, log_axis,
                           n_axis, offsets, suptitle)

import matplotlib.pyplot as plt  # noqa: E402  (sweep_figures selected the Agg backend)

FIGURES = [
    ("success_vs_footprint.png", "success rate vs the objects' footprint (share of the floor), "
                                 "Wilson 95% intervals; a panel per N; classes and densities "
                                 "pooled"),
    ("time_vs_n_by_footprint.png", "median (IQR bars) time of the solved trials vs N, a panel "
                                   "per footprint, log axis"),
    ("success_vs_difficulty.png", "success rate vs each difficulty column (objects on a goal "
                                  "cycle, goals occupied, objects walled in), all cells pooled"),
]

# Difficulty values from this one up are pooled into one point ("4+").
DIFFICULTY_CAP = 4
DIFFICULTY_LABELS = {"goal_cycle_objects": "objects on a goal cycle",
                     "goals_occupied": "goals another object occupies",
                     "walled_in": "objects walled in at the start"}


def applies(s):
    return len(s.footprints) > 1


def panels(title, count):
    fig, axes = plt.subplots(1, count, figsize=(max(10.0, 3.4 * count + 0.6), 3.9),
                             squeeze=False, sharey=True)
    suptitle(fig, title)
    return fig, axes[0]


def draw_rates(ax, methods, m, points, handles, off):
    """Success rates with Wilson bars at the points' x (x, Cell), empty cells left out."""
    pts = [(x, c) for x, c in points if c.n > 0]
    if not pts:
        return
    ys = [c.rate for _, c in pts]
    err = bars(ys, [c.ci[0] for _, c in pts], [c.ci[1] for _, c in pts])
    handles.setdefault(m, draw_method(ax, m, methods, [x + off for x, _ in pts], ys, err))


def plot_success_vs_footprint(s, methods, path):
    fig, axes = panels("Success rate vs the objects' footprint (Wilson 95% intervals)",
                       max(1, len(s.ns)))
    gaps = [b - a for a, b in zip(s.footprints, s.footprints[1:])]
    off = offsets(methods, 0.05 * min(gaps))
    handles = {}
    for ax, n in zip(axes, s.ns):
        for m in methods:
            draw_rates(ax, methods, m, [(f, pooled(s, m, n=n, footprint=f)) for f in s.footprints],
                       handles, off[m])
        ax.set_title("N = %d" % n, fontsize=9.5)
        ax.set_xlabel("footprint (share of the floor)", fontsize=9)
        ax.set_xticks(s.footprints)
        ax.tick_params(axis="x", labelsize=7.5)
        ax.set_ylim(-0.05, 1.05)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("success rate", fontsize=9)
    finish(s, fig, path, legend_handles(methods, handles))


def plot_time_vs_n(s, methods, path):
    fig, axes = panels("Time of the solved trials vs number of objects, per footprint "
                       "(median, IQR bars)", len(s.footprints))
    gaps = [b - a for a, b in zip(s.ns, s.ns[1:])]
    off = offsets(methods, 0.06 * (min(gaps) if gaps else 1))
    handles = {}
    for ax, f in zip(axes, s.footprints):
        for m in methods:
            pts = [(n, pooled(s, m, n=n, footprint=f).time) for n in s.ns]
            pts = [(n, st) for n, st in pts if st is not None]
            if not pts:
                continue
            mid = [max(TIME_FLOOR_S, st[0]) for _, st in pts]
            err = bars(mid, [max(TIME_FLOOR_S, st[1]) for _, st in pts],
                       [max(TIME_FLOOR_S, st[2]) for _, st in pts])
            handles.setdefault(m, draw_method(ax, m, methods, [n + off[m] for n, _ in pts], mid,
                                              err))
        ax.set_title("footprint %g" % f, fontsize=9.5)
        ax.set_xlabel("objects N", fontsize=9)
        ax.grid(True, alpha=0.3)
        n_axis(ax, s)
    shared_log_axis(axes)
    axes[0].set_ylabel("time s (log)", fontsize=9)
    finish(s, fig, path, legend_handles(methods, handles))


def shared_log_axis(axes):
    """One log y range for panels that share their y axis: log_axis over every panel's points."""
    ys = [y for ax in axes for line in ax.get_lines() for y in line.get_ydata()
          if y > 0 and math.isfinite(y)]
    if not ys:
        return
    ax = axes[0]
    ax.plot([axes[0].get_xlim()[0]] * 2, [min(ys), max(ys)], alpha=0)  # the range, invisible
    log_axis(ax)


def difficulty_value(t, column):
    v = t.difficulty.get(column)
    return None if v is None or math.isnan(v) else min(int(v), DIFFICULTY_CAP)


def plot_success_vs_difficulty(s, methods, path):
    fig, axes = panels("Success rate vs the instance's difficulty (Wilson 95% intervals)",
                       len(DIFFICULTY_COLUMNS))
    off = offsets(methods, 0.06)
    handles = {}
    for ax, col in zip(axes, DIFFICULTY_COLUMNS):
        xs = range(DIFFICULTY_CAP + 1)
        for m in methods:
            points = [(x, Cell([t for t in s.trials if t.method == m
                                and difficulty_value(t, col) == x])) for x in xs]
            draw_rates(ax, methods, m, points, handles, off[m])
        ax.set_xticks(list(xs))
        ax.set_xticklabels([str(x) for x in xs[:-1]] + ["%d+" % DIFFICULTY_CAP])
        ax.set_xlabel(DIFFICULTY_LABELS[col], fontsize=9)
        ax.set_ylim(-0.05, 1.05)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("success rate", fontsize=9)
    finish(s, fig, path, legend_handles(methods, handles))


def write_figures(s, methods, path_of):
    """The three figures, when the sweep has more than one footprint; their names."""
    if not applies(s):
        return []
    plot_success_vs_footprint(s, methods, path_of(FIGURES[0][0]))
    plot_time_vs_n(s, methods, path_of(FIGURES[1][0]))
    plot_success_vs_difficulty(s, methods, path_of(FIGURES[2][0]))
    return FIGURES
