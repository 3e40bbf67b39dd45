#!/usr/bin/env python3
"""Figure and animation of one `rearm run` in the paper's style (Figs. 3-5).

usage: run.py TRAJECTORY.json OUT_DIR [--no-animation] [--frames=N] [--snapshots=K]
              [--format=png|pdf|svg]

Writes OUT_DIR/run.FORMAT (default png): axes in metres; the workspace, familiar obstacles (dark
grey, black once localized), unknown obstacles (light grey), regions of interest, each object at
its start (dashed circle) and end (filled, named), in its own colour, its path dashed and the
stretches it was carried drawn solid; the robot's path, its end pose and its sensor range
(dotted); every action numbered in the order it ended at the robot's position then (LTL actions
in circles, Fix-mode actions in red squares); a legend of what is drawn and the formula under
the title. With --snapshots=K, K panels side by side as the paper's Figs. 3-5: the run cut at
action ends into K successive stretches, each panel the path of its stretch and the objects
where they stood at its end. OUT_DIR/run_figure.json lists what was marked (number, action,
Fix mode, time, position, panel), for tests and captions. Unless --no-animation, also OUT_DIR/run.gif: the
same scene over time (at most N frames, default 200), familiar obstacles turning black when
localized, with the current action (Fix-mode actions marked *); and, when the trajectory holds
the spaces (`rearm run --spaces`), OUT_DIR/spaces.gif: the semantic, mapped and model spaces
side by side as in the paper's video (mapped: the freespace F_k of the robot's, or the pair's,
centre, light, inside the convex enclosure F_e; model: F_e with the model disks of the familiar
clusters and objects and the unknown convex obstacles, and the law's model point h(x)).
"""
import bisect
import json
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Patch, Polygon  # noqa: E402

DARK_GREY = "#555555"
LIGHT_GREY = "#c8c8c8"
ROBOT = "#1f5fbf"
OBJECT_COLORS = ["#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]
REGION_COLORS = ["#ffd54f", "#81d4fa", "#a5d6a7", "#f48fb1", "#ce93d8", "#ffcc80"]


def load(path):
    with open(path) as f:
        return json.load(f)


def draw_static(ax, t, localized):
    ws = t["workspace"]
    ax.add_patch(Polygon(ws, closed=True, fill=False, edgecolor="black", linewidth=1.5))
    for i, r in enumerate(t["regions"]):
        c = REGION_COLORS[i % len(REGION_COLORS)]
        ax.add_patch(Polygon(r["polygon"], closed=True, facecolor=c, alpha=0.55, edgecolor=c))
        xs = [p[0] for p in r["polygon"]]
        ys = [p[1] for p in r["polygon"]]
        ax.text(min(xs) + 0.05, max(ys) - 0.05, r["name"], ha="left", va="top", fontsize=9,
                style="italic")
    patches = []
    for f in t["familiar"]:
        color = "black" if localized(f) else DARK_GREY
        p = Polygon(f["polygon"], closed=True, facecolor=color, edgecolor=color)
        ax.add_patch(p)
        patches.append((f, p))
    for u in t["unknown"]:
        ax.add_patch(Polygon(u["polygon"], closed=True, facecolor=LIGHT_GREY, edgecolor="grey"))
    xs = [p[0] for p in ws]
    ys = [p[1] for p in ws]
    pad = 0.2
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)", fontsize=8)
    ax.set_ylabel("y (m)", fontsize=8)
    ax.tick_params(labelsize=7)
    return patches


def title(t, status=True, width=95):
    """The scene's name (and outcome) over its formula, wrapped at spaces to `width`."""
    head = f"{t['scenario']}: {t['status']}" if status else t["scenario"]
    return head + "\n" + "\n".join(textwrap.wrap(t["task"], width=width))


def legend(ax, t, fix_marked):
    items = [Line2D([], [], color=ROBOT, linewidth=1.2, label="robot path"),
             Line2D([], [], color=ROBOT, marker="o", linestyle="none", markersize=4,
                    label="robot start"),
             Line2D([], [], color=ROBOT, marker="o", markeredgecolor="black", linestyle="none",
                    markersize=9, label="robot at the end"),
             Line2D([], [], color=ROBOT, linestyle=":", linewidth=1.0,
                    label=f"sensor range ({t['sensor_range']:g} m)")]
    for i, o in enumerate(t["objects"][:len(OBJECT_COLORS)]):
        c = OBJECT_COLORS[i % len(OBJECT_COLORS)]
        items.append(Line2D([], [], color=c, marker="o", markersize=8, linewidth=2.0,
                            label=f"{o['name']}: start (dashed), carried (solid), end"))
    items.append(Line2D([], [], color="black", marker="o", markerfacecolor="white",
                        linestyle="none", markersize=9, label="action n ended here"))
    if fix_marked:
        items.append(Line2D([], [], color="#b71c1c", marker="s", markerfacecolor="#ffcdd2",
                            linestyle="none", markersize=9, label="Fix-mode action n"))
    if t["familiar"]:
        items.append(Patch(facecolor="black", label="familiar obstacle"))
    if t["unknown"]:
        items.append(Patch(facecolor=LIGHT_GREY, edgecolor="grey", label="unknown obstacle"))
    if t["regions"]:
        items.append(Patch(facecolor=REGION_COLORS[0], alpha=0.55, label="region of interest"))
    ax.legend(handles=items, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5,
              frameon=False)


def sample(t, time):
    """The trajectory's sample index at `time` (the samples are t['dt'] apart)."""
    return max(0, min(len(t["robot"]) - 1, int(round(time / t["dt"]))))


def panels_of(t, k):
    """K successive stretches [i0, i1] of sample indices, cut at action ends as evenly as the
    actions allow (every action ends in exactly one stretch)."""
    n = len(t["robot"])
    ends = sorted({sample(t, a["t_end"]) for a in t["actions"]})
    k = max(1, min(k, len(ends))) if ends else 1
    cuts = [ends[min(len(ends) - 1, math.ceil((j + 1) * len(ends) / k) - 1)] for j in range(k)]
    cuts[-1] = n - 1
    out, first = [], 0
    for c in cuts:
        if c >= first:
            out.append((first, c))
            first = c
    return out


def marked_actions(t, stretches):
    """Every action, numbered in the order it ended, with where the robot was then and the
    panel whose stretch holds that moment."""
    order = sorted(range(len(t["actions"])), key=lambda i: (t["actions"][i]["t_end"], i))
    out = []
    for number, i in enumerate(order, start=1):
        a = t["actions"][i]
        k = sample(t, a["t_end"])
        panel = next((p for p, (lo, hi) in enumerate(stretches) if lo <= k <= hi),
                     len(stretches) - 1)
        x, y = t["robot"][k][0], t["robot"][k][1]
        out.append({"number": number, "action": a["action"], "fix_mode": a["fix_mode"],
                    "outcome": a.get("outcome", ""), "t_end": a["t_end"], "x": x, "y": y,
                    "panel": panel})
    return out


def draw_objects(ax, t, lo, hi):
    for i, (o, path) in enumerate(zip(t["objects"], t["object_paths"])):
        c = OBJECT_COLORS[i % len(OBJECT_COLORS)]
        seg = path[lo:hi + 1]
        ax.plot([p[0] for p in seg], [p[1] for p in seg], color=c, linewidth=1.0, linestyle="--")
        # Carried: the stretches where the object moves between samples, one line broken (NaN)
        # where it stands still.
        xs, ys = [], []
        for a, b in zip(seg, seg[1:]):
            if math.dist(a, b) > 1e-6:
                xs += [a[0], b[0], math.nan]
                ys += [a[1], b[1], math.nan]
        if xs:
            ax.plot(xs, ys, color=c, linewidth=2.6, solid_capstyle="round")
        ax.add_patch(Circle(path[0], o["radius"], fill=False, edgecolor=c, linestyle="--"))
        end = path[min(hi, len(path) - 1)]
        ax.add_patch(Circle(end, o["radius"], facecolor=c, edgecolor=c, alpha=0.85))
        ax.text(end[0], end[1], o["name"], ha="center", va="center", fontsize=7.5,
                color="white", weight="bold")


def draw_marks(ax, marks, panel):
    for m in marks:
        if m["panel"] != panel:
            continue
        if m["fix_mode"]:
            box = dict(boxstyle="square,pad=0.2", facecolor="#ffcdd2", edgecolor="#b71c1c")
        else:
            box = dict(boxstyle="circle,pad=0.2", facecolor="white", edgecolor="black")
        ax.text(m["x"], m["y"], str(m["number"]), ha="center", va="center", fontsize=6.5,
                bbox=box, zorder=5)


def draw_panel(ax, t, lo, hi, marks, panel):
    draw_static(ax, t, lambda f: 0 <= f["localized_at"] <= hi * t["dt"])
    robot = t["robot"][lo:hi + 1]
    ax.plot([p[0] for p in robot], [p[1] for p in robot], color=ROBOT, linewidth=1.2)
    draw_objects(ax, t, lo, hi)
    x, y, psi = t["robot"][hi]
    r = t["robot_radius"]
    ax.add_patch(Circle((x, y), r, facecolor=ROBOT, edgecolor="black", alpha=0.9))
    ax.plot([x, x + r * math.cos(psi)], [y, y + r * math.sin(psi)], color="white")
    ax.add_patch(Circle((x, y), t["sensor_range"], fill=False, edgecolor=ROBOT, linestyle=":",
                        linewidth=1.0))
    ax.plot(robot[0][0], robot[0][1], marker="o", color=ROBOT, markersize=4)
    draw_marks(ax, marks, panel)


def figure(t, out_dir, fmt="png", snapshots=1):
    stretches = panels_of(t, snapshots) if t["robot"] else [(0, 0)]
    marks = marked_actions(t, stretches) if t["robot"] else []
    k = len(stretches)
    rows = 1 if k <= 3 else 2
    cols = math.ceil(k / rows)
    width = 10 if k == 1 else 5.0 * cols + 2.5
    fig, axes = plt.subplots(rows, cols, squeeze=False,
                             figsize=(width, rows * (8 if k == 1 else 4.6) * aspect(t) + 0.8))
    for extra in range(k, rows * cols):
        axes[extra // cols][extra % cols].set_visible(False)
    for p, (lo, hi) in enumerate(stretches):
        ax = axes[p // cols][p % cols]
        if t["robot"]:
            draw_panel(ax, t, lo, hi, marks, p)
        else:
            draw_static(ax, t, lambda f: False)
        if k > 1:
            ax.set_title(f"({chr(ord('a') + p)}) t = {lo * t['dt']:.0f}-{hi * t['dt']:.0f} s",
                         fontsize=8)
    fig.suptitle(title(t), fontsize=9)
    legend(axes[0][cols - 1], t, any(m["fix_mode"] for m in marks))
    fig.tight_layout()
    path = os.path.join(out_dir, "run." + fmt)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    with open(os.path.join(out_dir, "run_figure.json"), "w") as f:
        json.dump({"figure": os.path.basename(path), "snapshots": k,
                   "panels": [[lo * t["dt"], hi * t["dt"]] for lo, hi in stretches],
                   "actions": marks}, f, indent=1)
    print(f"wrote {path}")


def aspect(t):
    xs = [p[0] for p in t["workspace"]]
    ys = [p[1] for p in t["workspace"]]
    return (max(ys) - min(ys)) / max(1e-9, (max(xs) - min(xs)))


def action_at(t, time):
    for a in t["actions"]:
        if a["t_start"] <= time <= a["t_end"]:
            return a["action"] + ("*" if a["fix_mode"] else "")
    return ""


def animation(t, out_dir, max_frames):
    robot = t["robot"]
    frames = frame_indices(len(robot), max_frames)
    dt = t["dt"]
    fig, ax = plt.subplots(figsize=(6, 6 * aspect(t)))
    patches = draw_static(ax, t, lambda f: False)
    r = t["robot_radius"]
    trail, = ax.plot([], [], color=ROBOT, linewidth=1.0)
    body = Circle(robot[0][:2], r, facecolor=ROBOT, edgecolor="black")
    ax.add_patch(body)
    nose, = ax.plot([], [], color="white")
    objs = []
    for i, o in enumerate(t["objects"]):
        c = OBJECT_COLORS[i % len(OBJECT_COLORS)]
        circle = Circle(t["object_paths"][i][0], o["radius"], facecolor=c, edgecolor=c)
        ax.add_patch(circle)
        objs.append(circle)
    label = ax.text(0.01, 0.99, "", transform=ax.transAxes, ha="left", va="top", fontsize=8,
                    bbox=dict(facecolor="white", alpha=0.7, edgecolor="none"))
    ax.set_title(title(t, status=False, width=80), fontsize=8)

    def update(k):
        time = k * dt
        for f, p in patches:
            loc = f["localized_at"]
            color = "black" if 0 <= loc <= time else DARK_GREY
            p.set_facecolor(color)
            p.set_edgecolor(color)
        trail.set_data([p[0] for p in robot[: k + 1]], [p[1] for p in robot[: k + 1]])
        x, y, psi = robot[k]
        body.center = (x, y)
        nose.set_data([x, x + r * math.cos(psi)], [y, y + r * math.sin(psi)])
        for circle, path in zip(objs, t["object_paths"]):
            circle.center = path[min(k, len(path) - 1)]
        label.set_text(f"t = {time:6.1f} s  {action_at(t, time)}")
        return []

    anim = FuncAnimation(fig, update, frames=frames, blit=False)
    path = os.path.join(out_dir, "run.gif")
    anim.save(path, writer=PillowWriter(fps=20), dpi=80)
    plt.close(fig)
    print(f"wrote {path}")


def polygon_patch(points, **kw):
    return Polygon(points, closed=True, **kw)


def frame_panel(ax, lim, name):
    ax.set_xlim(*lim[0])
    ax.set_ylim(*lim[1])
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(name, fontsize=8)


def frame_indices(n, max_frames):
    """At most about max_frames evenly spaced samples of 0..n-1, the last one included."""
    step = max(1, math.ceil(n / max_frames))
    frames = list(range(0, n, step))
    if frames[-1] != n - 1:
        frames.append(n - 1)
    return frames


def draw_mapped(ax, snap, lim):
    ax.clear()
    ax.add_patch(polygon_patch(snap["enclosing"], fill=False, edgecolor="black", linewidth=1.0))
    fs = snap["freespace"]
    ax.add_patch(polygon_patch(fs["outer"], facecolor="#e8f1fb", edgecolor=ROBOT, linewidth=0.8))
    for h in fs["holes"]:
        ax.add_patch(polygon_patch(h, facecolor=DARK_GREY, edgecolor=DARK_GREY))
    frame_panel(ax, lim, "mapped space (F_k in F_e)")


def draw_model(ax, snap, lim):
    ax.clear()
    m = snap["model"]
    ax.add_patch(polygon_patch(m["boundary"], facecolor="#e8f1fb", edgecolor="black",
                               linewidth=1.0))
    for x, y, r in m["disks"]:
        ax.add_patch(Circle((x, y), r, facecolor=DARK_GREY, edgecolor=DARK_GREY))
    for c in m["convex"]:
        ax.add_patch(polygon_patch(c, facecolor=LIGHT_GREY, edgecolor="grey"))
    frame_panel(ax, lim, "model space (disks and convex obstacles)")


def spaces_animation(t, out_dir, max_frames):
    """Three panels: the semantic space (as run.gif), the mapped space of the build in use and
    the model space with the law's model point."""
    robot, spaces, model_path = t["robot"], t["spaces"], t["model_path"]
    frames = frame_indices(len(robot), max_frames)
    dt = t["dt"]
    times = [s["t"] for s in spaces]
    xs = [p[0] for p in t["workspace"]]
    ys = [p[1] for p in t["workspace"]]
    lim = ((min(xs) - 0.2, max(xs) + 0.2), (min(ys) - 0.2, max(ys) + 0.2))
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.6 * aspect(t) + 0.8))
    patches = draw_static(axes[0], t, lambda f: False)
    axes[0].set_title("semantic space", fontsize=8)
    r = t["robot_radius"]
    body = Circle(robot[0][:2], r, facecolor=ROBOT, edgecolor="black")
    axes[0].add_patch(body)
    trail, = axes[0].plot([], [], color=ROBOT, linewidth=1.0)
    objs = []
    for i, o in enumerate(t["objects"]):
        c = OBJECT_COLORS[i % len(OBJECT_COLORS)]
        circle = Circle(t["object_paths"][i][0], o["radius"], facecolor=c, edgecolor=c)
        axes[0].add_patch(circle)
        objs.append(circle)
    fig.suptitle(title(t, status=False, width=150), fontsize=8)
    label = fig.text(0.01, 0.01, "", fontsize=8)
    drawn = {"snap": None}

    def update(k):
        time = k * dt
        for f, p in patches:
            color = "black" if 0 <= f["localized_at"] <= time else DARK_GREY
            p.set_facecolor(color)
            p.set_edgecolor(color)
        trail.set_data([p[0] for p in robot[: k + 1]], [p[1] for p in robot[: k + 1]])
        body.center = tuple(robot[k][:2])
        for circle, path in zip(objs, t["object_paths"]):
            circle.center = path[min(k, len(path) - 1)]
        i = bisect.bisect_right(times, time + 1e-9) - 1
        if i >= 0:
            if drawn["snap"] != i:
                draw_mapped(axes[1], spaces[i], lim)
                draw_model(axes[2], spaces[i], lim)
                drawn["snap"] = i
            axes[1].plot(robot[k][0], robot[k][1], "o", color=ROBOT, markersize=3)
            y = model_path[k] if k < len(model_path) else None
            if y is not None:
                axes[2].plot(y[0], y[1], "o", color=ROBOT, markersize=3)
        label.set_text(f"t = {time:6.1f} s  {action_at(t, time)}")
        return []

    anim = FuncAnimation(fig, update, frames=frames, blit=False)
    path = os.path.join(out_dir, "spaces.gif")
    fig.tight_layout(rect=(0, 0.03, 1, 0.95))
    anim.save(path, writer=PillowWriter(fps=20), dpi=80)
    plt.close(fig)
    print(f"wrote {path}")


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    flags = [a for a in argv[1:] if a.startswith("--")]
    if len(args) != 2:
        sys.stderr.write(__doc__)
        return 2
    max_frames, snapshots, fmt = 200, 1, "png"
    for f in flags:
        if f.startswith("--frames="):
            max_frames = int(f.split("=", 1)[1])
        elif f.startswith("--snapshots="):
            snapshots = int(f.split("=", 1)[1])
        elif f.startswith("--format="):
            fmt = f.split("=", 1)[1]
        elif f != "--no-animation":
            sys.stderr.write(f"run.py: unknown option {f}\n")
            return 2
    if fmt not in ("png", "pdf", "svg") or snapshots < 1 or max_frames < 1:
        sys.stderr.write("run.py: --format is png, pdf or svg; --snapshots and --frames >= 1\n")
        return 2
    t = load(args[0])
    os.makedirs(args[1], exist_ok=True)
    figure(t, args[1], fmt, snapshots)
    if "--no-animation" not in flags and t["robot"]:
        animation(t, args[1], max_frames)
        if t.get("spaces"):
            spaces_animation(t, args[1], max_frames)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
