#!/usr/bin/env python3
"""Draws the output of `rearm diffeo` (DIR/diffeo.json) in the visual style of the paper and
its reference [7]: familiar obstacles dark grey, unknown ones light grey, collars as thin
outlines, model disks, paths in colour.

usage: diffeo.py DIR/diffeo.json DIR

Writes DIR/semantic.png (the scene), DIR/mapped.png (the mapped space: freespace F_k, the
enclosing freespace F_e, the convex pieces, collars, purge centres and pocket lids, and the
grid of freespace lines), DIR/model.png (the model space with the grid lines and the familiar
obstacles' boundaries mapped through h, and the path images) and DIR/path.png (the
closed-loop paths in the workspace).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, PathPatch, Polygon  # noqa: E402
from matplotlib.path import Path  # noqa: E402

FAMILIAR = "#4d4d4d"
UNKNOWN = "#bdbdbd"
MOVABLE = "#c9a66b"
BLOCKED = "#e3e3e3"
GRID = "#6f9fd8"
COLLAR = "#d9822b"
PIECE = "#202020"
LID = "#c0392b"
PATH_COLOURS = ["#1f77b4", "#2ca02c", "#9467bd", "#e377c2", "#17becf", "#bcbd22", "#8c564b"]


def closed(points):
    return list(points) + [points[0]] if points else []


def poly(ax, points, **kw):
    if len(points) >= 3:
        ax.add_patch(Polygon(points, closed=True, **kw))


def outline(ax, points, **kw):
    if len(points) >= 2:
        xs, ys = zip(*closed(points))
        ax.plot(xs, ys, **kw)


def region(ax, outer, holes, **kw):
    """A polygon with holes, filled with the even-odd rule."""
    verts, codes = [], []
    for ring in [outer] + holes:
        if len(ring) < 3:
            continue
        verts += closed(ring)
        codes += [Path.MOVETO] + [Path.LINETO] * (len(ring) - 1) + [Path.CLOSEPOLY]
    if verts:
        ax.add_patch(PathPatch(Path(verts, codes), **kw))


def disk(ax, d, **kw):
    ax.add_patch(Circle(d["center"], d["radius"], **kw))


def line(ax, points, **kw):
    pts = [p for p in points if p is not None and None not in p]
    if len(pts) >= 2:
        xs, ys = zip(*pts)
        ax.plot(xs, ys, **kw)


def markers(ax, start, goal):
    ax.plot(*start, "o", color="#2ca02c", markersize=7, zorder=10, label="start")
    ax.plot(*goal, "*", color="#d62728", markersize=13, zorder=10, label="goal")


def new_axes(title, polygon, pad=0.5):
    fig, ax = plt.subplots(figsize=(7, 7))
    xs = [p[0] for p in polygon]
    ys = [p[1] for p in polygon]
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return fig, ax


def semantic_obstacles(ax, sem):
    outline(ax, sem["workspace"], color="black", linewidth=1.5)
    for p in sem["familiar"]:
        poly(ax, p, facecolor=FAMILIAR, edgecolor="black", linewidth=0.8)
    for p in sem["unknown"]:
        poly(ax, p, facecolor=UNKNOWN, edgecolor="#7f7f7f", linewidth=0.8)
    for d in sem["movable"]:
        disk(ax, d, facecolor=MOVABLE, edgecolor="#7a5c2e", linewidth=0.8)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        data = json.load(f)
    out = argv[2]
    os.makedirs(out, exist_ok=True)
    sem, mapped, model = data["semantic"], data["mapped"], data["model"]
    robot = data["robot"]

    # Semantic space.
    fig, ax = new_axes("semantic space", sem["workspace"])
    semantic_obstacles(ax, sem)
    markers(ax, robot["start"], robot["goal"])
    ax.legend(loc="upper left", fontsize=8)
    save(fig, os.path.join(out, "semantic.png"))

    # Mapped space.
    fig, ax = new_axes(
        "mapped space (r = %g): pieces, collars, centres" % mapped["radius"], sem["workspace"]
    )
    poly(ax, mapped["enclosing"], facecolor=BLOCKED, edgecolor="none")
    region(ax, mapped["freespace"]["outer"], mapped["freespace"]["holes"],
           facecolor="white", edgecolor="black", linewidth=1.0)
    outline(ax, mapped["enclosing"], color="black", linewidth=0.8, linestyle="--")
    outline(ax, sem["workspace"], color="#7f7f7f", linewidth=0.8, linestyle=":")
    for run in data["grid"]:
        line(ax, run["mapped"], color=GRID, linewidth=0.4)
    for c in mapped["familiar"]:
        poly(ax, c["polygon"], facecolor=FAMILIAR, edgecolor="black", linewidth=0.8, alpha=0.85)
        if c["lid"]:
            line(ax, c["lid"], color=LID, linewidth=2.5)
    for p in mapped["unknown"]:
        poly(ax, p, facecolor=UNKNOWN, edgecolor="#7f7f7f", linewidth=0.8)
    for d in mapped["movable"]:
        disk(ax, d, facecolor=MOVABLE, edgecolor="#7a5c2e", linewidth=0.8)
    for p in data["purges"]:
        outline(ax, p["piece"], color="white", linewidth=0.6)
        outline(ax, p["collar"], color=COLLAR, linewidth=0.7)
        marker = "s" if p["kind"] != "child" else "."
        ax.plot(*p["center"], marker, color=COLLAR, markersize=4, zorder=5)
    markers(ax, robot["start"], robot["goal"])
    save(fig, os.path.join(out, "mapped.png"))

    # Model space.
    fig, ax = new_axes("model space: h(grid), h(obstacle boundaries), h(path)", model["boundary"])
    outline(ax, model["boundary"], color="black", linewidth=1.2)
    for run in data["grid"]:
        line(ax, run["model"], color=GRID, linewidth=0.4)
    for d in model["disks"]:
        disk(ax, d, facecolor=FAMILIAR, edgecolor="black", linewidth=0.8, alpha=0.85)
    for p in model["convex"]:
        poly(ax, p, facecolor=UNKNOWN, edgecolor="#7f7f7f", linewidth=0.8)
    for b in data["boundary_images"]:
        line(ax, closed(b["model"]), color=LID, linewidth=0.8)
    for i, p in enumerate(data["paths"]):
        line(ax, p["model"], color=PATH_COLOURS[i % len(PATH_COLOURS)], linewidth=1.6, zorder=8)
    markers(ax, model["start"], model["goal"])
    save(fig, os.path.join(out, "model.png"))

    # Paths in the workspace.
    fig, ax = new_axes("closed-loop paths (%s)" % robot["model"], sem["workspace"])
    semantic_obstacles(ax, sem)
    for c in mapped["familiar"]:
        outline(ax, c["polygon"], color="black", linewidth=0.6, linestyle="--")
    for p in mapped["unknown"]:
        outline(ax, p, color="#7f7f7f", linewidth=0.6, linestyle="--")
    for i, p in enumerate(data["paths"]):
        colour = PATH_COLOURS[i % len(PATH_COLOURS)]
        line(ax, p["mapped"], color=colour, linewidth=1.6, zorder=8)
        ax.plot(*p["start"], "o", color=colour, markersize=5, zorder=9)
        if p["status"] != "reached" and p["mapped"]:
            ax.plot(*p["mapped"][-1], "x", color="#d62728", markersize=9, zorder=9)
    markers(ax, robot["start"], robot["goal"])
    save(fig, os.path.join(out, "path.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
