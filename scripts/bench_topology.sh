#!/usr/bin/env bash
# Topology-check benchmarks (docs/executive.md "Benchmarks required").
#
# Builds and runs bench/topology/topology_bench (JSON into topology.json):
# check_topology swept over movable objects 1, 2, 4, 8, 16, 32 × familiar obstacles 0, 4, 16,
# 64 (plus the target point 10 × 20), robot alone and carrying, with x* in the far corner
# (usually reachable) and x* inside the farthest object (every step runs), each without a cache
# (cold: bound − ∪fixed computed in every call) and with a warm TopologyCache (the familiar
# obstacles unchanged, objects, x and x* moving); make_input and a whole warm re-check at
# 10 × 20. Then writes topology.md (tables, the ≤ 1 ms target at 10 objects ×
# 20 obstacles cold and warm, the fitted log-log growth rates) and, when matplotlib is
# available, topology.png (time vs objects, one line per obstacle count,
# log-log, cold and warm).
#
# Environment: MACHINE (default debian12-2core), BUILD (default build). Other arguments go to
# topology_bench, e.g. --benchmark_filter=FarCorner. Runs in about two minutes on 2 cores.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
bench_prepare topology_bench
bench_run topology_bench topology.json "$@"
LOAD_END=$(cut -d" " -f1-3 /proc/loadavg)
CPU=$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')

# A Python with matplotlib if there is one (pyenv shims often lack it; Debian's has it).
PY=python3
if ! python3 -c "import matplotlib" 2>/dev/null && [ -x /usr/bin/python3 ] &&
  /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  PY=/usr/bin/python3
fi

"$PY" - "$OUT" "$MACHINE" "$(nproc)" "$CPU" "$REV" "$LOAD" "$LOAD_END" <<'PYTHON'
import datetime
import json
import math
import sys

out, machine, nproc, cpu, rev, load, load_end = sys.argv[1:8]
TO_US = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}

# Google Benchmark JSON, names BM_<what>/objects:<n>/obstacles:<m>/carrying:<c>/min_time:<t>.
runs = {}  # (what, n, m, c) -> {"wall", "cpu" (µs), "verdict", "counts", "blocking"} or {"error"}
with open(f"{out}/topology.json") as f:
    for b in json.load(f)["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue
        parts = b["name"].split("/")
        what = parts[0].removeprefix("BM_")
        args = dict(p.split(":") for p in parts[1:4])
        key = (what, int(args["objects"]), int(args["obstacles"]), int(args["carrying"]))
        if b.get("error_occurred"):
            runs[key] = {"error": b.get("error_message", "error")}
            continue
        runs[key] = {"wall": b["real_time"] * TO_US[b["time_unit"]],
                     "cpu": b["cpu_time"] * TO_US[b["time_unit"]],
                     "verdict": int(b.get("verdict", -1)),
                     "counts": (int(b.get("reachable", 0)), int(b.get("by_objects", 0)),
                                int(b.get("by_fixed", 0))),
                     "blocking": int(b.get("blocking", 0))}

VERDICT = "ROF"
TARGET = {"FarCorner": "x* in the far corner", "InsideObject": "x* inside the farthest object"}
MODE = {"": "no cache (cold)", "Cached": "warm cache"}
CARRY = {0: "robot alone (radius 0.2 m)", 1: "carrying (radius 0.5 m)"}


def fmt(us):
    if us is None:
        return "–"
    if us >= 1000:
        return f"{us / 1000:.3g} ms"
    return f"{us:.3g} µs"


def verdicts(r):
    """R, O, F for the variants' verdicts: one letter when they agree, else counts."""
    nonzero = [(VERDICT[k], n) for k, n in enumerate(r["counts"]) if n]
    if len(nonzero) == 1:
        return nonzero[0][0]
    return " ".join(f"{c}{n}" for c, n in nonzero) or "?"


def slope(points):
    """Least-squares slope of log(time) against log(size)."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else None


def wall(what, n, m, c):
    r = runs.get((what, n, m, c))
    return r["wall"] if r and "wall" in r else None


objects = sorted({k[1] for k in runs if k[1] != 10})
obstacles = sorted({k[2] for k in runs if k[2] != 20})
lines = [
    "# Topology check speed",
    "",
    f"{datetime.date.today().isoformat()}, machine `{machine}` ({nproc} cores, {cpu}), "
    f"git `{rev}`, load average {load} as the benchmark started and {load_end} as it ended "
    "(a machine shared with other jobs: treat the times as upper bounds; CPU time, also "
    "given, suffers less from other jobs than wall time).",
    "",
    "`bench/topology/topology_bench` (Release), wall clock (`real_time`) per "
    "`check_topology` call, at least 0.2 s per point; raw numbers (CPU time too) in "
    "`topology.json`. Scene (seed 42): a square room of 2.5 m cells, side "
    "ceil(sqrt(objects + obstacles + 2)) cells (≥ 4), one shape per cell: familiar obstacles "
    "are rotated rectangles or star polygons (extent ≤ 1.2 m, dilated with miter joins), "
    "objects disks of radius 0.3 m (circumscribed 32-gons); robot radius 0.2 m, carrying = "
    "the pair, radius 0.5 m, the carried object left out. Each point cycles through 8 variants "
    "of its scene with the same familiar obstacles and the objects, x and x* moved within "
    "their cells (±0.3 m; variant 0 is the scene of the earlier single-input runs). "
    "*Far corner*: x* in the top-right cell (steps 1–2 when reachable); *inside object*: x* at "
    "the centre of the object farthest from x, so steps 1–4 all run (F_list, then the "
    "clusters and the graph search). *No cache (cold)*: `check_topology(in)`, which computes "
    "bound − ∪fixed in every call (the cost after the familiar obstacles changed); *warm "
    "cache*: `check_topology(in, cache)` with a `TopologyCache` that has seen the familiar "
    "obstacles (the executive's loop: objects, x and x* change between calls). Verdict "
    "letters over the 8 variants: R reachable, O blocked by objects, F blocked by fixed "
    "obstacles (e.g. `R7 O1`). Google Benchmark's \"Library was built as DEBUG\" warning is "
    "about Debian's libbenchmark package, not rearm's build.",
    "",
]
for target in ("FarCorner", "InsideObject"):
    for carrying in (0, 1):
        lines += [f"## {TARGET[target]}, {CARRY[carrying]}: cold / warm", "",
                  "| objects \\ obstacles | " + " | ".join(str(m) for m in obstacles) + " |",
                  "|---" * (len(obstacles) + 1) + "|"]
        for n in objects:
            cells = []
            for m in obstacles:
                cold = runs.get((f"Topology{target}", n, m, carrying))
                warm = runs.get((f"Topology{target}Cached", n, m, carrying))
                if cold is None or warm is None:
                    cells.append("–")
                elif "error" in cold or "error" in warm:
                    cells.append(cold.get("error") or warm.get("error"))
                else:
                    cells.append(f"{fmt(cold['wall'])} / {fmt(warm['wall'])} {verdicts(cold)}")
            lines.append(f"| {n} | " + " | ".join(cells) + " |")
        lines.append("")

# The target point, every mode.
lines += ["## 10 objects × 20 obstacles (the target point of docs/executive.md)", "",
          "| case | no cache (cold) wall | CPU | warm cache wall | CPU | verdicts |",
          "|---|---|---|---|---|---|"]
for target in ("FarCorner", "InsideObject"):
    for carrying in (0, 1):
        cold = runs.get((f"Topology{target}", 10, 20, carrying), {})
        warm = runs.get((f"Topology{target}Cached", 10, 20, carrying), {})
        lines.append(f"| {TARGET[target]}, {CARRY[carrying]} | {fmt(cold.get('wall'))} | "
                     f"{fmt(cold.get('cpu'))} | {fmt(warm.get('wall'))} | {fmt(warm.get('cpu'))} | "
                     f"{verdicts(cold) if 'counts' in cold else '–'} |")
lines += ["", "| executive step at 10 × 20 | robot alone wall (CPU) | carrying wall (CPU) |",
          "|---|---|---|"]
for what, label in (("MakeInput", "`make_input`, no cache (dilates everything)"),
                    ("MakeInputCached", "`make_input(…, cache)`, warm (objects moved)"),
                    ("TopologyTickCached",
                     "`make_input(…, cache)` + `check_topology(…, cache)`, warm, x* far corner")):
    cells = []
    for carrying in (0, 1):
        r = runs.get((what, 10, 20, carrying), {})
        cells.append(f"{fmt(r.get('wall'))} ({fmt(r.get('cpu'))})")
    lines.append(f"| {label} | " + " | ".join(cells) + " |")
lines.append("")

# Growth: slope of log time vs log objects per obstacle count, vs log obstacles per object
# count (obstacles > 0), and vs log(total shapes) over the whole sweep.
lines += ["## Growth rate (least-squares log-log slope of time)", "",
          "| case | vs objects (per obstacle count: 0, 4, 16, 64) | vs obstacles 4–64 "
          "(per object count) | vs objects + obstacles (all points) |", "|---|---|---|---|"]
for target in ("FarCorner", "InsideObject"):
    for mode in ("", "Cached"):
        for carrying in (0, 1):
            what = f"Topology{target}{mode}"
            vs_n = []
            for m in obstacles:
                s = slope([(n, wall(what, n, m, carrying)) for n in objects
                           if wall(what, n, m, carrying) is not None])
                vs_n.append("–" if s is None else f"{s:.2f}")
            vs_m = []
            for n in objects:
                s = slope([(m, wall(what, n, m, carrying)) for m in obstacles
                           if m > 0 and wall(what, n, m, carrying) is not None])
                vs_m.append("–" if s is None else f"{s:.2f}")
            total = slope([(k[1] + k[2], r["wall"]) for k, r in runs.items()
                           if k[0] == what and k[3] == carrying and "wall" in r])
            lines.append(f"| {TARGET[target]}, {'carrying' if carrying else 'robot'}, "
                         f"{MODE[mode]} | {', '.join(vs_n)} | {', '.join(vs_m)} | "
                         f"{'–' if total is None else f'{total:.2f}'} |")


def check(description, what, carrying):
    r = runs.get((what, 10, 20, carrying))
    if r is None or "error" in r:
        return f"- MISSED — {description}: no measurement"
    ok = r["wall"] <= 1000
    return f"- {'MET' if ok else 'MISSED'} — {description}: {fmt(r['wall'])} (CPU {fmt(r['cpu'])})"


targets = []
for mode in ("Cached", ""):
    for target, steps in (("FarCorner", "x* reachable"), ("InsideObject", "all four steps")):
        for carrying in (0, 1):
            targets.append(check(f"≤ 1 ms at 10 objects, 20 obstacles, "
                                 f"{'carrying' if carrying else 'robot alone'}, {steps}, "
                                 f"{MODE[mode]}", f"Topology{target}{mode}", carrying))
lines += ["", "## Target (docs/executive.md: ≤ 1 ms at 10 objects and 20 obstacles)", ""] + targets
lines += ["", "How (topology/freespace.h): bound − ∪fixed is computed once per familiar-obstacle "
          "map and kept exact (TopologyCache); per call, an object whose bounding box meets no "
          "other object's and no edge of bound − ∪fixed becomes a hole after one exact point "
          "location, without any overlay (all objects in the robot-alone scenes, which is why "
          "those cost tens of µs), and the other objects are subtracted inside small windows "
          "around each group of them: the freespace's loops are cut at the window, the part "
          "inside is subtracted there (traced along the boundaries' crossings, "
          "geometry/crossing_difference.cpp, when they meet only in proper crossings; else one "
          "small CGAL overlay), and the outside chains are spliced back. Loops given in doubles "
          "(the bound, familiar obstacles, objects) build their exact cycles only when an "
          "overlay needs them and locate points given in doubles by exact predicates on the "
          "doubles (geometry::side_of); the programs link rearm's own pthread_once "
          "(docs/architecture.md, \"Process-wide runtime\"), without the futex wake system call "
          "that glibc's makes on each lazy exact number CGAL settles. "
          "The same localization computes bound − ∪fixed (cold) and step 4's clusters. Results "
          "are the exact sets of one global overlay (tests/topology/freespace_test compares "
          "them), and a cached call is bit for bit the uncached one "
          "(tests/topology/topology_cache_test). Same-run ratios against earlier revisions are "
          "in speed/trials.md (scripts/bench_speed.sh): this file's absolute times drift with "
          "the machine (1.5x between two runs in one session). valgrind/callgrind cannot run CGAL's interval "
          "arithmetic (it does not emulate the rounding-mode "
          "changes; the sweep crashes), so there are no instruction counts."]

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for row, target in enumerate(("FarCorner", "InsideObject")):
        for col, carrying in enumerate((0, 1)):
            ax = axes[row][col]
            for mode, style in (("", "-"), ("Cached", "--")):
                what = f"Topology{target}{mode}"
                for m, color in zip(obstacles, colors):
                    pts = [(n, wall(what, n, m, carrying) / 1000) for n in objects
                           if wall(what, n, m, carrying) is not None]
                    if pts:
                        ax.plot(*zip(*pts), marker="o", markersize=3, linestyle=style,
                                color=color,
                                label=f"{m} obstacles, {'warm' if mode else 'cold'}")
                w = wall(what, 10, 20, carrying)
                if w is not None:
                    ax.plot([10], [w / 1000], marker="*" if mode else "P", markersize=11,
                            linestyle="none", color="black",
                            label=f"10 objects, 20 obstacles, {'warm' if mode else 'cold'}")
            ax.axhline(1.0, color="red", linestyle=":", linewidth=1, label="target 1 ms")
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_title(f"{TARGET[target]}, {'carrying' if carrying else 'robot alone'}",
                         fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            if row == 1:
                ax.set_xlabel("movable objects")
            if col == 0:
                ax.set_ylabel("check_topology time (ms)")
    axes[0][0].legend(fontsize=6, ncol=2)
    fig.suptitle(f"rearm topology check, {machine}, load {load}; solid: no cache, dashed: warm cache")
    fig.tight_layout()
    fig.savefig(f"{out}/topology.png", dpi=110)
    lines += ["", "Plot: `topology.png` (time vs objects, one line per obstacle count, log-log; "
              "solid no cache, dashed warm cache)."]
except ImportError:
    lines += ["", "No plot: matplotlib is not installed for this Python."]

with open(f"{out}/topology.md", "w") as f:
    f.write("\n".join(lines) + "\n")
print("\n".join(lines))
missed = sum(t.startswith("- MISSED") for t in targets)
print(f"bench_topology: {len(targets) - missed} targets met, {missed} missed")
PYTHON
bench_publish
