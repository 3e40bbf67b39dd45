"""The data of a `rearm sweep` folder: trials.csv read and grouped, and its statistics.

Shared by sweep.py (report.md and the figures) and ablation_table.py. Only python3's standard
library is used, so that the tables and the tests run without matplotlib.

Method names are the CSV's own, in the order of their first row: nothing here knows the C++
method list, so a new method (or an ablation variant) appears without a change here.
"""
import csv
import math
import os
import re
import sys
from collections import Counter, defaultdict

# The two-sided 95% standard normal quantile Phi^-1(0.975) = 1.95996398454005423552..., to 16
# significant digits; every 95% interval of the scripts (sweep report, figures, ablation table)
# uses it.
Z95 = 1.959963984540054

# The goal classes in the order of the paper's study; a class not listed still appears, after.
KNOWN_CLASSES = ["random", "cyclic", "sealed", "constructive"]

# Columns the C++ writer places between `fix_mode_entries` and the recovery counters that are
# not recoveries: `replans` counts the replan baseline's replanning (baselines/).
NOT_RECOVERIES = {"replans"}


# ----------------------------------------------------------------------------- reading


FOOTPRINT_DIGITS = 4
DIFFICULTY_COLUMNS = ("goal_cycle_objects", "goals_occupied", "walled_in")


def warn(msg):
    prog = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "sweep_data"
    print("%s: warning: %s" % (prog, msg), file=sys.stderr)


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
    """(header, rows as dicts) of trials.csv; a cut last line and damaged rows are dropped."""
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


def recovery_columns(header):
    """The recovery-counter columns of a trials.csv header, in the header's order.

    The C++ writer (framework/experiment, the trials CSV columns) writes `fix_mode_entries`,
    `replans`, then the robust variant's recovery counters, then `collisions`: the counters are
    the columns between `fix_mode_entries` and `collisions`, NOT_RECOVERIES left out. A header
    without both bounds (an older CSV) has none.
    """
    try:
        first = header.index("fix_mode_entries") + 1
        end = header.index("collisions")
    except ValueError:
        return []
    return [c for c in header[first:end] if c not in NOT_RECOVERIES]


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


# How the rows of rearm (the methods that follow the task's order, the rows' goal_order
# column) are named in every table and figure: the chain's rows are rearm bound to that order
# while the baselines choose theirs; rows of logs before the column (goal_order empty) keep the
# method's name.
CHAIN_LABEL = " (bound to the chain's order; baselines free)"
ANY_LABEL = " (any order)"


def method_label(r):
    method = r.get("method", "") or "?"
    if not method.startswith("rearm"):
        return method
    order = r.get("goal_order", "")
    if order == "chain":
        return method + CHAIN_LABEL
    if order == "any":
        return method + ANY_LABEL
    return method


def nominal_footprint(achieved, goal_class, n):
    """The sweep file's footprint of a row (Trial.footprint), rounded to FOOTPRINT_DIGITS."""
    if achieved is None:
        return None
    if goal_class == "sealed" and n:
        achieved *= n / (n + 1)
    return round(achieved, FOOTPRINT_DIGITS)


class Trial:
    """The fields of one row that the report uses, parsed."""

    def __init__(self, r):
        self.method = method_label(r)
        self.cls = r.get("class", "") or "?"
        n = number(r.get("objects"))
        self.n = int(n) if n is not None else None
        self.density = number(r.get("target_density"))
        self.achieved = number(r.get("achieved_density"))
        self.status = r.get("status", "") or "?"
        # The sweep's one success rule (completed, every goal reached, no collision) is the
        # C++ writer's `success` column; nothing here recomputes it.
        self.success = r.get("success", "").strip() == "1"
        # The time of a trial: planning time for the offline baselines, compute time otherwise.
        planning = number(r.get("planning_time_s"))
        self.time = planning if planning is not None else number(r.get("compute_time_s"))
        # On equal terms (answer_figures.py): what a trial cost to carry the task out, planning
        # and execution in Box2D for a baseline (its wall time), the online compute for rearm;
        # and the offline planning alone (None for rearm, which plans as it goes).
        self.planning = planning
        self.total = (number(r.get("wall_time_s")) if planning is not None else
                      number(r.get("compute_time_s")))
        # The compute before the first act (first_action_time_s): a baseline's planning until
        # its first plan was complete, rearm's set-up and control until its first command. None
        # where the trial never acted or the log predates the column.
        self.first_action = number(r.get("first_action_time_s"))
        self.time_limit = number(r.get("time_limit_s"))
        # What the trial cost: its wall time on one worker thread, and the process CPU time.
        self.wall_time = number(r.get("wall_time_s"))
        self.cpu_time = number(r.get("cpu_time_s"))
        self.actions = number(r.get("actions"))
        self.path = number(r.get("robot_path_m"))
        self.reason = r.get("reason", "")
        self.revision = r.get("revision", "")
        self.finished = r.get("finished_utc", "")  # ISO 8601 UTC; "" in logs before the column
        self.host = r.get("host", "")
        self.cpu = r.get("cpu_model", "")
        # Settings that may vary in a sweep beyond class x N x density: pooled in the figures,
        # kept apart in the table when they do vary.
        self.variant = (r.get("unknown_fraction", ""), r.get("unknown_shapes", ""),
                        r.get("workspace_rule", ""))
        # The objects' share of the floor as the sweep file names the cell (the room sized from
        # N and it), rounded. The column holds the achieved share, which differs from the sweep
        # file's by rounding, except for sealed goals: their pocket's blocker is an (N + 1)-th
        # object on a floor sized for N, so the column holds F (N + 1) / N.
        # The sweep's workspace rule names it ("footprint 0.01 (>= 10 m)": a room of at least
        # 10 m holds less), else it is inferred from the achieved share.
        rule = re.match(r"footprint ([0-9.eE+-]+)", r.get("workspace_rule", "") or "")
        self.footprint = (round(float(rule.group(1)), FOOTPRINT_DIGITS) if rule else
                          nominal_footprint(number(r.get("footprint_density")), self.cls, self.n))
        # Difficulty of the instance (experiments/sweeps/README.md): objects on a cycle of the
        # goal-on-start dependency graph, objects whose goal another object occupies, objects
        # walled in by other objects at the start.
        self.difficulty = {k: number(r.get(k)) for k in DIFFICULTY_COLUMNS}
        # The instance's geometry, shared by its chain and any-order rows (one instance seed,
        # one room), and whether a witness plan that solves it came with it (class constructive).
        self.geometry = (self.cls, self.n, self.density, self.variant,
                         r.get("instance_seed", ""), r.get("scatter_moves", "") or "")
        self.witness = (r.get("witness", "") or "").strip() == "1"


# ----------------------------------------------------------------------------- statistics


def wilson(k, n, z=Z95):
    """Wilson score interval of k successes in n trials: (low, high); (nan, nan) for n = 0.

    The bounds are the two p with |k/n - p| = z sqrt(p (1 - p) / n). For k = 0 the low one is
    exactly 0 and for k = n the high one exactly 1, which the closed form misses by rounding.
    """
    if n == 0:
        return float("nan"), float("nan")
    p = k / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    low = 0.0 if k == 0 else max(0.0, centre - half)
    high = 1.0 if k == n else min(1.0, centre + half)
    return low, high


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
    """Successes and cost of a set of trials (one method in one cell, or any pooled set).

    Medians of time, actions and path are over the successful trials, the achieved density's
    over all of them.
    """

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


def density_cells(trials, edges):
    """{bin index: Cell} of the trials with an achieved density, binned by edges."""
    bins = defaultdict(list)
    for x in trials:
        if x.achieved is not None:
            bins[bin_index(x.achieved, edges)].append(x)
    return {b: Cell(v) for b, v in bins.items()}


# ----------------------------------------------------------------------------- ordering


def first_seen(values):
    """The distinct values in the order of their first appearance."""
    return list(dict.fromkeys(values))


def ordered(values, known):
    """The known names first in their order, then the others sorted."""
    values = set(values)
    return [v for v in known if v in values] + sorted(values - set(known))


def sort_numbers(values):
    return sorted({v for v in values if v is not None})


# ----------------------------------------------------------------------------- the data set



def pooled(s, method, **match):
    """The Cell of a method's trials in sweep s whose fields equal `match` (e.g. cls, n,
    footprint), every other dimension pooled."""
    return Cell([t for t in s.trials if t.method == method
                 and all(getattr(t, k) == v for k, v in match.items())])

class Sweep:
    """The trials of one sweep folder, its settings and its cells."""

    def __init__(self, dir_path):
        self.dir = dir_path
        header, rows = read_trials(os.path.join(dir_path, "trials.csv"))
        self.header = header
        self.name = sweep_name(dir_path, rows)
        self.trials = t = [Trial(r) for r in rows]
        self.methods = first_seen(x.method for x in t)
        self.classes = ordered((x.cls for x in t), KNOWN_CLASSES)
        self.ns = sort_numbers(x.n for x in t)
        self.densities = sort_numbers(x.density for x in t)
        self.footprints = sort_numbers(x.footprint for x in t)
        self.variants = sorted({x.variant for x in t})
        self.revisions = sorted({x.revision for x in t} - {""})
        # When the trials ended (UTC): the first and the last, or None before finished_utc.
        ended = sorted(x.finished for x in t if x.finished)
        self.ended = (ended[0], ended[-1]) if ended else None
        self.hosts = sorted({x.host for x in t} - {""})
        self.cpus = sorted({x.cpu for x in t} - {""})
        self.time_limits = sort_numbers(x.time_limit for x in t)
        # (class, method, N, density) -> Cell, the variant pooled; vcells keep it apart (the
        # table's rows when variants differ).
        self.cells = group_cells(t, lambda x: (x.cls, x.method, x.n, x.density))
        # Per instance geometry: solved by some method of the sweep (the oracle), and known
        # solvable (that, or a witness plan came with the instance).
        self.solved_by_any, self.known_solvable = defaultdict(bool), defaultdict(bool)
        for x in t:
            self.solved_by_any[x.geometry] |= x.success
            self.known_solvable[x.geometry] |= x.success or x.witness
        self.vcells = group_cells(t, lambda x: (x.cls, x.method, x.n, x.density, x.variant))

    def cell(self, cls, method, n, density):
        return self.cells.get((cls, method, n, density))

    def pooled(self, cls=None, method=None, n=None, density=None):
        """A Cell of every trial matching the given settings (None: any)."""
        return Cell([x for x in self.trials
                     if (cls is None or x.cls == cls) and (method is None or x.method == method)
                     and (n is None or x.n == n) and (density is None or x.density == density)])


def sign_test(b, c):
    """Two-sided exact sign test of b against c discordant pairs: the probability, with each
    discordant pair a fair coin, of a split at least as uneven as b : c (1 when b + c = 0)."""
    n = b + c
    if n == 0:
        return 1.0
    tail = sum(math.comb(n, i) for i in range(min(b, c) + 1)) / 2.0 ** n
    return min(1.0, 2 * tail)


def is_rearm(method):
    """rearm's rows (every variant, either goal order) as the report labels them."""
    return method.startswith("rearm")


def paired(s, rearm, baseline, trials):
    """(both, only rearm, only the baseline, neither) over the instance geometries of `trials`
    that both methods ran: a geometry counts as solved by a method when one of its rows
    succeeded."""
    ok = defaultdict(dict)
    for x in trials:
        if x.method in (rearm, baseline):
            ok[x.geometry][x.method] = ok[x.geometry].get(x.method, False) or x.success
    counts = [0, 0, 0, 0]
    for g in ok.values():
        if rearm in g and baseline in g:
            a, b = g[rearm], g[baseline]
            counts[0 if a and b else 1 if a else 2 if b else 3] += 1
    return tuple(counts)


def best_baseline(trials):
    """The baseline (not rearm) with the most successful rows in `trials`, ties by name."""
    wins = Counter()
    for x in trials:
        if not is_rearm(x.method):
            wins[x.method] += x.success
    return min(wins, key=lambda m: (-wins[m], m)) if wins else None


def solvable_counts(s, trials):
    """(solved by some method, known solvable, instances) over the geometries of `trials`."""
    geometries = {x.geometry for x in trials}
    return (sum(s.solved_by_any[g] for g in geometries),
            sum(s.known_solvable[g] for g in geometries), len(geometries))


def group_cells(trials, key):
    groups = defaultdict(list)
    for x in trials:
        groups[key(x)].append(x)
    return {k: Cell(v) for k, v in groups.items()}
