"""report.md of a `rearm sweep` folder: the tables and "what the numbers say" (sweep.py).

Every number comes from sweep_data; this module only words and lays it out. Only python3's
standard library is used.
"""
import math
from collections import Counter

from sweep_data import (Cell, best_baseline, density_bins, density_cells, is_rearm, ordered,
                        paired, pooled, sign_test, solvable_counts)

# The statuses in the order of a trial's life; a status not listed still gets a column, after.
STATUS_ORDER = ["completed", "infeasible", "stuck", "timeout", "unsolved", "invalid_plan",
                "failed", "error", "timeout_wall"]
MAX_LISTED = 4  # cells named in one finding
MIN_BIN_TRIALS = 5  # trials a density bin needs to be quoted in the findings


# ----------------------------------------------------------------------------- text helpers


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return "%.*g" % (digits, x)


def fmt_density(d):
    return "-" if d is None else "%g" % d


def md_cell(text):
    """Text safe inside a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def md_row(cells):
    return "| " + " | ".join(md_cell(x) for x in cells) + " |"


def md_head(head):
    return ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]


def median_text(stat):
    return fmt(stat[0] if stat else None)


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


def failure_name(trial):
    """The status of an unsuccessful trial, `completed` told apart from a success."""
    return "completed without success" if trial.status == "completed" else trial.status


def listed(names):
    """At most MAX_LISTED names, then how many more."""
    more = len(names) - MAX_LISTED
    return ", ".join(names[:MAX_LISTED]) + (" and %d more cells" % more if more > 0 else "")


# ----------------------------------------------------------------------------- report.md


def write_report(s, path, figures):
    """report.md of sweep s; figures: the (file name, caption) of each figure drawn beside."""
    lines = header_lines(s)
    if not s.trials:
        lines.append("No complete trial rows in trials.csv.")
    else:
        lines += ["## What the numbers say", ""]
        lines += ["- " + line for line in findings(s)] + [""]
        lines += cell_table(s) + footprint_lines(s) + paired_lines(s)
        lines += status_table(s) + reason_lines(s) + cost_lines(s)
        lines += ["## Figures", ""]
        lines += ["- `%s`: %s" % (name, what) for name, what in figures] + [""]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def header_lines(s):
    return [
        "# Sweep `%s`" % s.name,
        "",
        "- folder: `%s`, %d trials, methods: %s" % (s.dir, len(s.trials), ", ".join(s.methods)),
        "- classes: %s; N: %s; target densities: %s"
        % (", ".join(s.classes), ", ".join(str(n) for n in s.ns),
           ", ".join(fmt_density(d) for d in s.densities)),
        "- time limit per trial: %s s" % (", ".join("%g" % x for x in s.time_limits) or "-"),
        "- revision: %s; host: %s; CPU: %s"
        % (", ".join(s.revisions) or "-", ", ".join(s.hosts) or "-", ", ".join(s.cpus) or "-"),
        "- trials ended %s" % ("from %s to %s (UTC)" % s.ended if s.ended else
                               "on dates not recorded (the trial log predates finished_utc)"),
        "- time = planning_time_s for the offline baselines, compute_time_s (mission + topology "
        "+ rebuilds + control) for rearm; medians of time, actions and path are over the "
        "successful trials; success = completed, every goal reached, no collision; "
        "95% intervals are Wilson score intervals.",
        "",
    ]


def cell_table(s):
    """One row per class x method x N x density (x variant, when the variants differ)."""
    vary = len(s.variants) > 1
    head = ["class", "method", "N", "density"]
    if vary:
        head += ["unknown", "shapes", "workspace"]
    head += ["trials", "successes", "success (95% CI)", "instances solved by any method",
             "known solvable", "time s: median [IQR]", "time s, all trials: median",
             "achieved density", "actions", "path m"]
    lines = ["## Success and cost per cell", ""] + md_head(head)
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
                oracle, known, instances = solvable_counts(s, c.trials)
                row += [str(c.n), str(c.k), "%.2f [%.2f, %.2f]" % (c.rate, c.ci[0], c.ci[1]),
                        "%d/%d" % (oracle, instances), "%d/%d" % (known, instances),
                        iqr_text(c.time), median_text(c.time_all), median_text(c.achieved),
                        median_text(c.actions), median_text(c.path)]
                lines.append(md_row(row))
    return lines + [""]


# Baselines every paired table names beside the best one, when the sweep ran them.
PAIRED_BASELINES = ["birrt@10000", "buffer@10000"]


def footprint_groups(s):
    """(footprint, class or "all classes", trials) for a sweep with several footprints."""
    if len(s.footprints) < 2:
        return []
    out = []
    for f in s.footprints:
        at = [x for x in s.trials if x.footprint == f]
        out.append((f, "all classes", at))
        out += [(f, c, [x for x in at if x.cls == c]) for c in s.classes if len(s.classes) > 1]
    return out


def footprint_lines(s):
    """Success per footprint, class and method, pooled over N, with the instances known
    solvable (a witness, or solved by some method of the sweep)."""
    groups = footprint_groups(s)
    if not groups:
        return []
    head = ["footprint", "class", "method", "trials", "success (95% CI)",
            "instances solved by any method", "known solvable"]
    lines = ["## Success per footprint", "",
             "Pooled over N (and obstacle densities); an instance is one geometry, its chain and "
             "any-order rows together.", ""] + md_head(head)
    for f, cls, trials in groups:
        oracle, known, instances = solvable_counts(s, trials)
        for m in s.methods:
            c = Cell([x for x in trials if x.method == m])
            if c.n:
                lines.append(md_row([fmt_density(f), cls, m, str(c.n), rate_text(c),
                                     "%d/%d" % (oracle, instances), "%d/%d" % (known, instances)]))
    return lines + [""]


def paired_lines(s):
    """Each rearm row set paired by instance against the best baseline of its footprint and
    class, and against PAIRED_BASELINES, with a two-sided exact sign test."""
    groups = footprint_groups(s)
    rearms = [m for m in s.methods if is_rearm(m)]
    if not groups or not rearms:
        return []
    head = ["footprint", "class", "rearm", "baseline", "pairs", "both", "only rearm",
            "only the baseline", "neither", "sign test p"]
    lines = ["## rearm paired against the baselines", "",
             "Per instance: solved by both, by rearm only, by the baseline only, by neither; the "
             "best baseline is the one with the most successes at that footprint and class; p: "
             "two-sided exact sign test on the pairs only one solved.", ""] + md_head(head)
    for f, cls, trials in groups:
        best = best_baseline(trials)
        others = [b for b in PAIRED_BASELINES if b != best and b in s.methods]
        for r in rearms:
            for b in ([best] if best else []) + others:
                both, only_r, only_b, neither = paired(s, r, b, trials)
                if both + only_r + only_b + neither == 0:
                    continue
                name = b + (" (best)" if b == best else "")
                lines.append(md_row([fmt_density(f), cls, r, name,
                                     str(both + only_r + only_b + neither), str(both),
                                     str(only_r), str(only_b), str(neither),
                                     "%.3g" % sign_test(only_r, only_b)]))
    return lines + [""]


def hours(seconds):
    return "%.2f h" % (seconds / 3600.0)


def cost_lines(s):
    """What the study cost: its total CPU time, and per method and per cell the one-thread
    estimate (the sum of the trials' wall times: a worker thread runs one trial at a time)."""
    cpu = sum(t.cpu_time or 0 for t in s.trials)
    wall = sum(t.wall_time or 0 for t in s.trials)
    lines = ["## What the study cost", "",
             "Total CPU time %s; on one thread about %s (the trials' wall times summed), on T "
             "threads about that divided by T when nothing else runs. Per method:" %
             (hours(cpu), hours(wall)), ""]
    lines += md_head(["method", "trials", "one thread", "CPU"])
    for m in s.methods:
        ts = pooled(s, m).trials
        lines.append(md_row([m, str(len(ts)), hours(sum(t.wall_time or 0 for t in ts)),
                             hours(sum(t.cpu_time or 0 for t in ts))]))
    per = {}
    for t in s.trials:
        key = (t.cls, t.n, t.density, t.footprint)
        per[key] = per.get(key, 0) + (t.wall_time or 0)
    lines += ["", "One-thread estimate per cell (every method):", ""]
    lines += md_head(["class", "N", "density", "footprint", "one thread"])
    for (cls, n, d, f), w in sorted(per.items(), key=lambda kv: (kv[0][0], kv[0][1] or 0,
                                                                   kv[0][2] or 0, kv[0][3] or 0)):
        lines.append(md_row([cls, "-" if n is None else str(n), fmt_density(d),
                             "-" if f is None else "%g" % f, "%.0f s" % w]))
    return lines + [""]


def status_table(s):
    statuses = ordered((x.status for x in s.trials), STATUS_ORDER)
    lines = ["## Status per method", ""] + md_head(["method", "trials", "successes"] + statuses)
    for method in s.methods:
        mine = [x for x in s.trials if x.method == method]
        counts = Counter(x.status for x in mine)
        row = [method, str(len(mine)), str(sum(x.success for x in mine))]
        row += [str(counts.get(st, 0)) for st in statuses]
        lines.append(md_row(row))
    lines.append("")
    completed_not_success = [x for x in s.trials if x.status == "completed" and not x.success]
    if completed_not_success:
        lines += ["%d trial(s) ended `completed` without counting as a success (a goal missed "
                  "or a collision)." % len(completed_not_success), ""]
    return lines


def reason_lines(s):
    lines = ["## Most frequent reasons of the unsuccessful trials", ""]
    any_reason = False
    for method in s.methods:
        reasons = Counter(x.reason or "(no reason given)" for x in s.trials
                          if x.method == method and not x.success)
        if not reasons:
            continue
        any_reason = True
        top = ", ".join('%d x "%s"' % (k, md_cell(r)) for r, k in reasons.most_common(3))
        lines.append("- %s: %s" % (method, top))
    if not any_reason:
        lines.append("Every trial succeeded.")
    return lines + [""]


# ----------------------------------------------------------------------------- findings


def findings(s):
    """Plain facts computed from the cells: who leads each class, where each method loses."""
    out = []
    for cls in s.classes:
        out += class_findings(s, cls)
    out += time_findings(s)
    out += density_findings(s)
    errors = sum(x.status == "error" for x in s.trials)
    if errors:
        out.append("%d trial(s) ended in `error` (an exception in the trial)." % errors)
    return out


def class_findings(s, cls):
    """The methods of one class ranked by pooled success, then where each one loses."""
    pooled = {m: s.pooled(cls=cls, method=m) for m in s.methods}
    pooled = {m: c for m, c in pooled.items() if c.n > 0}
    if not pooled:
        return []
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
    out = [text + "."]
    for m in ranking:
        parts = method_losses(s, cls, m, ranking, pooled[m])
        if parts:
            out.append("%s / %s: %s." % (cls, m, "; ".join(parts)))
        else:
            out.append("%s / %s: every trial succeeded." % (cls, m))
    return out


def beaten_cells(s, cls, m, ranking):
    """The cells where m's 95% interval lies wholly below another method's, named."""
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
    return beaten


def method_losses(s, cls, m, ranking, pooled):
    """The phrases of where method m loses in class cls (none: every trial succeeded)."""
    beaten = beaten_cells(s, cls, m, ranking)
    mine = [s.cell(cls, m, n, d) for n in s.ns for d in s.densities if s.cell(cls, m, n, d)]
    low = min((c.rate for c in mine), default=None)
    worst = [c for c in mine if c.rate == low]
    fails = Counter(failure_name(x) for x in pooled.trials if not x.success)
    parts = []
    if beaten:
        parts.append("its 95% interval wholly below another method's at " + listed(beaten))
    if worst and low < 1 and len(worst) == len(mine) > 1:
        parts.append("success %.2f in all its %d cells" % (low, len(mine)))
    elif worst and low < 1:
        names = [cell_name(c.trials[0].n, c.trials[0].density) for c in worst]
        parts.append("lowest success %.2f at %s" % (low, listed(names)))
    if fails:
        parts.append("failures: " + ", ".join("%d %s" % (k, st) for st, k in fails.most_common()))
    return parts


def time_findings(s):
    """Time growth from the smallest to the largest N, and the fastest method at the largest."""
    out = []
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
                           % (m, median_text(a), lo, median_text(b), hi))
    top_n = s.ns[-1] if s.ns else None
    timed = [(s.pooled(method=m, n=top_n).time, m) for m in s.methods]
    timed = [(t[0], m) for t, m in timed if t]
    if timed:
        t, m = min(timed)
        out.append("Fastest median time of the solved trials at N=%s (all classes and densities): "
                   "%s (%s s)." % (top_n, m, fmt(t)))
    return out


def density_findings(s):
    """Success in the sparsest and the densest achieved-density bin holding enough trials."""
    out = []
    edges = density_bins([x.achieved for x in s.trials])
    if len(edges) <= 2:
        return out
    for m in s.methods:
        cells = density_cells([x for x in s.trials if x.method == m], edges)
        full = sorted(b for b, c in cells.items() if c.n >= MIN_BIN_TRIALS)
        if len(full) < 2:
            continue
        lo, hi = full[0], full[-1]
        a, b = cells[lo], cells[hi]
        out.append("%s: success %.2f (n=%d) at achieved density %.3g-%.3g, %.2f (n=%d) "
                   "at %.3g-%.3g." % (m, a.rate, a.n, edges[lo], edges[lo + 1], b.rate, b.n,
                                      edges[hi], edges[hi + 1]))
    return out
