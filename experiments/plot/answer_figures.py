"""The one-glance figures of a sweep (drawn by sweep.py): for each goal class, one panel with the
success rate against N, a line per method, every other dimension of the sweep (target density,
footprint, unknown-obstacle mix) pooled, and the Wilson 95% interval as a shaded band. They
answer "does rearm beat the sampling planners as N grows?" without reading twelve panels; the
report's table keeps every cell apart.
"""
from sweep_data import Cell
from sweep_figures import draw_method, finish, legend_handles, method_color, n_axis, suptitle

import matplotlib.pyplot as plt  # noqa: E402  (sweep_figures selected the Agg backend)


def file_name(cls):
    return "answer_%s.png" % cls


def figures(s):
    """(file name, caption) of each figure, one per goal class of the sweep."""
    return [(file_name(c), "%s goals: success rate vs N per method, every other dimension "
                           "pooled, Wilson 95%% band" % c) for c in s.classes]


def points(s, cls, method):
    """(N, Cell) of the method's trials of class cls, one per N with trials."""
    out = []
    for n in s.ns:
        c = Cell([t for t in s.trials if t.cls == cls and t.method == method and t.n == n])
        if c.n > 0:
            out.append((n, c))
    return out


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


def write_figures(s, methods, path_of):
    """Every figure of figures(s); path_of(file name) gives where it goes."""
    for cls in s.classes:
        plot_class(s, methods, cls, path_of(file_name(cls)))
