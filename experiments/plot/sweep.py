#!/usr/bin/env python3
"""Tables and figures of one `rearm sweep` folder (called by `rearm sweep report DIR`).

usage: sweep.py DIR [OUT]

Reads DIR/trials.csv (one row per trial) and DIR/sweep.yaml (only its `name:` line), writes
into OUT (default DIR; DIR itself is only read, so a committed or read-only sweep is analysed
elsewhere):

  OUT/report.md               per class x method x N x target density: trials, successes,
                              success rate with its Wilson 95% interval, median and IQR of the
                              time, median achieved density, actions and robot path; the status
                              breakdown per method; "what the numbers say", computed; and
                              what the study cost (total CPU time, one-thread estimates per
                              method and per cell)
  OUT/answer_CLASS.png        one per goal class: success rate vs N per method, everything
                              else pooled, Wilson 95% bands (answer_figures.py)
  OUT/success_vs_n.png        success rate vs N (rows: goal class, columns: target density)
  OUT/time_vs_n.png           median and IQR of the time vs N, log axis
  OUT/success_vs_density.png  success rate vs achieved density, binned
  OUT/actions_vs_n.png        median and IQR of the actions vs N
  OUT/path_vs_n.png           median and IQR of the robot path length vs N
  OUT/solved_within_t.png     fraction of trials solved within t, per method, log axis

and, when the sweep has more than one footprint (crowded rooms, crowded_figures.py):

  OUT/success_vs_footprint.png    success rate vs footprint, a panel per N
  OUT/time_vs_n_by_footprint.png  median and IQR of the time vs N, a panel per footprint
  OUT/success_vs_difficulty.png   success rate vs each difficulty column

The time of a trial is its planning time where the row has one (the offline baselines) and its
compute time otherwise (rearm: mission + topology + rebuilds + control). Medians of time,
actions and path are over the successful trials of a cell (no success: no point, "-" in the
table); the achieved density's median is over all trials. Only python3's standard library and
matplotlib are used. A cut last line of the CSV and rows of the wrong width are skipped with a
warning; empty or non-numeric fields count as missing.
"""
import os
import sys

# The modules sit beside this file, which is sys.path[0] when it runs as a script (from
# experiments/plot or installed in share/rearm/plot): the data and statistics, report.md, the
# figures, the crowded-room figures.
import answer_figures
import crowded_figures
import sweep_data
import sweep_figures
import sweep_report


def main(argv):
    if len(argv) not in (2, 3) or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    d = argv[1]
    out = argv[2] if len(argv) == 3 else d
    if not os.path.isfile(os.path.join(d, "trials.csv")):
        print("sweep.py: %s has no trials.csv" % d, file=sys.stderr)
        return 1
    os.makedirs(out, exist_ok=True)
    s = sweep_data.Sweep(d)
    figures = answer_figures.figures(s) + list(sweep_figures.FIGURES)
    if s.trials and crowded_figures.applies(s):
        figures += crowded_figures.FIGURES
    sweep_report.write_report(s, os.path.join(out, "report.md"), figures)
    if s.trials:
        order = sweep_figures.presentation_order(s.methods)
        answer_figures.write_figures(s, order, lambda name: os.path.join(out, name))
        sweep_figures.write_figures(s, out)
        crowded_figures.write_figures(s, order, lambda name: os.path.join(out, name))
        print("wrote %s/report.md and %d figures (%d trials)" % (out, len(figures), len(s.trials)))
    else:
        print("wrote %s/report.md (no trials: no figures)" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
