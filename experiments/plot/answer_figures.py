"""The one-glance figures of a sweep (drawn by sweep.py): for each goal class, one panel with the
success rate against N, a line per method, every other dimension of the sweep (target density,
footprint, unknown-obstacle mix) pooled, and the Wilson 95% interval as a shaded band. They
answer "does rearm beat the sampling planners as N grows?" without reading twelve panels; the
report's table keeps every cell apart. And time_equal_terms.png: per class, the median over the
solved trials of what a trial cost to carry the task out (a baseline's planning plus its
execution in Box2D; rearm's whole online compute) against N, solid; the baselines' offline
planning alone, dashed; and each method's time to a first action (the compute before its
first motion or grip: a planner's planning until its plan is complete, rearm's mission set-up
and control steps until its first command), dotted; for a planner that plans offline the dotted
line lies on the dashed one. The usual time figure sets rearm's whole
run against the baselines' planning only. A trial log written before first_action_time_s
existed has no dotted lines, and the title says so.
"""
import statistics

from sweep_data import pooled
from sweep_figures import (class_row, draw_method, finish, legend_handles, method_color,
                           n_axis, suptitle)

import matplotlib.pyplot as plt  # noqa: E402  (sweep_figures selected the Agg backend)
from matplotlib.lines import Line2D  # noqa: E402


def file_name(cls):
    return "answer_%s.png" % cls


EQUAL_TERMS = "time_equal_terms.png"


def figures(s):
    """(file name, caption) of each figure: one per goal class, then the time on equal terms."""
    return [(file_name(c), "%s goals: success rate vs N per method, every other dimension "
                           "pooled, Wilson 95%% band" % c) for c in s.classes] + [
        (EQUAL_TERMS, "median time of the solved trials vs N on equal terms: planning and "
                      "execution (baselines) or online compute (rearm), solid; the baselines' "
                      "offline planning alone, dashed; the time to a first action, dotted; "
                      "log axis")]


def points(s, cls, method):
    """(N, Cell) of the method's trials of class cls, one per N with trials."""
    cells = [(n, pooled(s, method, cls=cls, n=n)) for n in s.ns]
    return [(n, c) for n, c in cells if c.n > 0]


def plot_class(s, methods, cls, path):
    fig, ax = plt.subplots(figsize=(9.0, 4.8))
    suptitle(fig, "%s goals: success rate vs number of objects (all densities and footprints "
                  "pooled; shaded: Wilson 95%%)" % cls)
    lines = {}
    for m in methods:
        pts = points(s, cls, m)
        if not pts:
            continue
        xs = [n for n, _ in pts]
        ys = [c.rate for _, c in pts]
        ax.fill_between(xs, [c.ci[0] for _, c in pts], [c.ci[1] for _, c in pts],
                        color=method_color(m, methods), alpha=0.12, linewidth=0)
        lines[m] = draw_method(ax, m, methods, xs, ys, None)
        ax.annotate("%d/%d" % (pts[-1][1].k, pts[-1][1].n), (xs[-1], ys[-1]),
                    textcoords="offset points", xytext=(6, 0), fontsize=7,
                    color=method_color(m, methods), va="center")
    ax.set_ylim(-0.03, 1.03)
    ax.set_xlabel("objects N", fontsize=9)
    ax.set_ylabel("success rate", fontsize=9)
    ax.grid(True, alpha=0.3)
    n_axis(ax, s)
    handles = legend_handles(methods, lines)
    ax.legend(handles, [h.get_label() for h in handles], loc="center left",
              bbox_to_anchor=(1.08, 0.5), fontsize=8.5, frameon=False)
    finish(s, fig, path)


def medians(s, cls, method, attr):
    """(N, median of attr over the solved trials) where there is one."""
    out = []
    for n in s.ns:
        xs = [getattr(t, attr) for t in pooled(s, method, cls=cls, n=n).trials
              if t.success and getattr(t, attr) is not None]
        if xs:
            out.append((n, max(statistics.median(xs), 1e-5)))
    return out


# Line styles of time_equal_terms.png: (attribute of sweep_data.Trial, style, legend text).
EQUAL_TERMS_LINES = [
    ("total", "-", "carrying the task out: planning + execution, or online compute"),
    ("planning", "--", "offline planning alone (baselines)"),
    ("first_action", ":", "time to a first action"),
]


def equal_terms_title(s):
    title = ("Time of the solved trials vs N on equal terms (median): solid, planning + "
             "execution (baselines) or online compute (rearm); dashed, the baselines' offline "
             "planning alone; dotted, the time to a first action")
    if all(t.first_action is None for t in s.trials):
        title += ("\n(no time to a first action in these rows: their trial log predates the "
                  "first_action_time_s column)")
    return title


def plot_equal_terms(s, methods, path):
    fig, axes = class_row(s, equal_terms_title(s))
    lines, ys = {}, []
    for ax, cls in zip(axes[0], s.classes):
        for m in methods:
            for attr, style, _ in EQUAL_TERMS_LINES:
                pts = medians(s, cls, m, attr)
                if not pts:
                    continue
                xy = ([n for n, _ in pts], [y for _, y in pts])
                if style == "-":
                    lines.setdefault(m, draw_method(ax, m, methods, *xy, None))
                else:
                    ax.plot(*xy, linestyle=style, linewidth=1.1, color=method_color(m, methods))
                ys += xy[1]
        ax.set_title("%s goals" % cls, fontsize=9.5)
        ax.set_xlabel("objects N", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        n_axis(ax, s)
    if ys:
        for ax in axes[0]:
            ax.set_yscale("log")
            ax.set_ylim(min(ys) / 1.6, max(ys) * 1.6)
    axes[0][0].set_ylabel("time (s)", fontsize=9)
    handles = legend_handles(methods, lines) + [
        Line2D([], [], color="0.3", linestyle=style, label=text)
        for _, style, text in EQUAL_TERMS_LINES]
    axes[0][-1].legend(handles, [h.get_label() for h in handles], loc="center left",
                       bbox_to_anchor=(1.02, 0.5), fontsize=8, frameon=False)
    finish(s, fig, path)


def write_figures(s, methods, path_of):
    """Every figure of figures(s); path_of(file name) gives where it goes."""
    for cls in s.classes:
        plot_class(s, methods, cls, path_of(file_name(cls)))
    plot_equal_terms(s, methods, path_of(EQUAL_TERMS))
