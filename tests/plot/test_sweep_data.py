"""Tests of experiments/plot/sweep_data.py (and the report text built on it), standard library only.

run: python3 -m unittest discover -s tests/plot
"""
import contextlib
import io
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import unittest

PLOT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "experiments",
                        "plot")
sys.path.insert(0, os.path.normpath(PLOT_DIR))

import sweep_data  # noqa: E402
import sweep_report  # noqa: E402

# Phi^-1(0.975) to 21 significant digits (tables of the normal quantile).
Z_TRUE = 1.95996398454005423552

# Columns of a synthetic trials.csv: the ones Trial reads, the counters and their bounds.
HEADER = ["trial", "sweep", "method", "class", "objects", "target_density", "achieved_density",
          "status", "success", "reason", "planning_time_s", "compute_time_s", "time_limit_s",
          "actions", "fix_mode_entries", "replans", "guides", "redrops", "collisions",
          "robot_path_m", "revision"]


def csv_line(method, cls="random", n=2, success=1):
    fields = {"trial": "0", "sweep": "t", "method": method, "class": cls, "objects": str(n),
              "target_density": "0.1", "achieved_density": "0.12",
              "status": "completed" if success else "timeout", "success": str(success),
              "reason": "", "planning_time_s": "", "compute_time_s": "0.5", "time_limit_s": "60",
              "actions": "4", "fix_mode_entries": "0", "replans": "0", "guides": "1",
              "redrops": "0", "collisions": "0", "robot_path_m": "3.5", "revision": "abc"}
    return ",".join(fields[c] for c in HEADER) + "\n"


def score_root(k, n, z, lo, hi):
    """The p in [lo, hi] where (k/n - p)^2 - z^2 p (1 - p) / n changes sign, by bisection."""
    p_hat = k / n

    def f(p):
        return (p_hat - p) ** 2 - z * z * p * (1 - p) / n

    f_lo = f(lo)
    for _ in range(200):
        mid = (lo + hi) / 2
        if (f(mid) > 0) == (f_lo > 0):
            lo, f_lo = mid, f(mid)
        else:
            hi = mid
    return (lo + hi) / 2


class Z95Test(unittest.TestCase):
    def test_is_the_normal_quantile(self):
        self.assertAlmostEqual(sweep_data.Z95, Z_TRUE, delta=1e-15)
        self.assertAlmostEqual(sweep_data.Z95, statistics.NormalDist().inv_cdf(0.975),
                               delta=1e-15)

    def test_is_the_default_of_wilson(self):
        self.assertEqual(sweep_data.wilson(7, 20), sweep_data.wilson(7, 20, z=sweep_data.Z95))
        self.assertNotEqual(sweep_data.wilson(7, 20), sweep_data.wilson(7, 20, z=1.96))


class WilsonTest(unittest.TestCase):
    z = sweep_data.Z95

    def test_no_success_closed_form(self):
        # p_hat = 0: the score equation p^2 = z^2 p (1 - p) / n gives p = z^2 / (n + z^2).
        lo, hi = sweep_data.wilson(0, 10)
        self.assertEqual(lo, 0.0)
        self.assertAlmostEqual(hi, self.z ** 2 / (10 + self.z ** 2), delta=1e-12)
        self.assertAlmostEqual(hi, 0.2775, delta=5e-5)

    def test_all_successes_closed_form(self):
        # p_hat = 1: (1 - p)^2 = z^2 p (1 - p) / n gives p = n / (n + z^2).
        lo, hi = sweep_data.wilson(10, 10)
        self.assertAlmostEqual(lo, 10 / (10 + self.z ** 2), delta=1e-12)
        self.assertAlmostEqual(lo, 0.7225, delta=5e-5)
        self.assertEqual(hi, 1.0)

    def test_seven_of_twenty_quadratic(self):
        # (1 + z^2/n) p^2 - (2 p_hat + z^2/n) p + p_hat^2 = 0, solved by the quadratic formula.
        n, p_hat, z2 = 20, 7 / 20, self.z ** 2
        a, b, c = 1 + z2 / n, -(2 * p_hat + z2 / n), p_hat ** 2
        root = math.sqrt(b * b - 4 * a * c)
        lo, hi = sweep_data.wilson(7, 20)
        self.assertAlmostEqual(lo, (-b - root) / (2 * a), delta=1e-12)
        self.assertAlmostEqual(hi, (-b + root) / (2 * a), delta=1e-12)
        self.assertAlmostEqual(lo, 0.1812, delta=5e-5)
        self.assertAlmostEqual(hi, 0.5671, delta=5e-5)

    def test_published_values(self):
        # Newcombe, Statistics in Medicine 17 (1998) 857-872, Table II, Wilson score method.
        for k, n, want_lo, want_hi in [(81, 263, 0.2553, 0.3662), (15, 148, 0.0624, 0.1605),
                                       (0, 20, 0.0, 0.1611), (1, 29, 0.0061, 0.1718)]:
            lo, hi = sweep_data.wilson(k, n)
            self.assertAlmostEqual(lo, want_lo, delta=5e-5, msg="%d/%d" % (k, n))
            self.assertAlmostEqual(hi, want_hi, delta=5e-5, msg="%d/%d" % (k, n))

    def test_bounds_solve_the_score_equation(self):
        rng = random.Random(20240601)
        cases = [(0, 1), (1, 1), (0, 3), (3, 3), (1, 2), (5, 12), (36, 36)]
        for _ in range(300):
            n = rng.randint(1, 3000)
            cases.append((rng.randint(0, n), n))
        for k, n in cases:
            p_hat = k / n
            lo, hi = sweep_data.wilson(k, n)
            msg = "%d/%d" % (k, n)
            self.assertLessEqual(lo, p_hat, msg)
            self.assertGreaterEqual(hi, p_hat, msg)
            want_lo = 0.0 if k == 0 else score_root(k, n, self.z, 0.0, p_hat)
            want_hi = 1.0 if k == n else score_root(k, n, self.z, p_hat, 1.0)
            self.assertAlmostEqual(lo, want_lo, delta=1e-9, msg=msg)
            self.assertAlmostEqual(hi, want_hi, delta=1e-9, msg=msg)
            for p in (lo, hi):
                gap = abs(p_hat - p) - self.z * math.sqrt(p * (1 - p) / n)
                self.assertAlmostEqual(gap, 0.0, delta=1e-9, msg=msg)

    def test_no_trials(self):
        self.assertTrue(all(math.isnan(x) for x in sweep_data.wilson(0, 0)))


class MethodOrderTest(unittest.TestCase):
    # Methods the figures' colour defaults do not name, and names that share a prefix with them.
    order = ["buffer", "rearm-noguide", "mrs", "fmrs", "rearm", "birrt-fmrs", "rearm-paper"]

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        lines = [",".join(HEADER) + "\n"]
        for i, m in enumerate(self.order + ["mrs", "buffer", "rearm"]):
            lines.append(csv_line(m, cls=["sealed", "random"][i % 2], success=i % 3 != 0))
        with open(os.path.join(self.dir, "trials.csv"), "w") as f:
            f.writelines(lines)
        with open(os.path.join(self.dir, "sweep.yaml"), "w") as f:
            f.write("name: synthetic\n")

    def tearDown(self):
        self.tmp.cleanup()

    def test_first_seen(self):
        self.assertEqual(sweep_data.first_seen(["b", "a", "b", "c", "a"]), ["b", "a", "c"])

    def test_sweep_methods_in_csv_order(self):
        s = sweep_data.Sweep(self.dir)
        self.assertEqual(s.methods, self.order)
        self.assertEqual(s.name, "synthetic")
        self.assertEqual(len(s.trials), 10)
        self.assertEqual({k[1] for k in s.cells}, set(self.order))

    def test_report_keeps_every_method(self):
        s = sweep_data.Sweep(self.dir)
        path = os.path.join(self.dir, "report.md")
        sweep_report.write_report(s, path, [("x.png", "a figure")])
        with open(path) as f:
            text = f.read()
        self.assertIn("methods: " + ", ".join(self.order), text)
        section = text.split("## Status per method\n\n")[1].split("\n\n")[0].splitlines()
        self.assertEqual([line.split(" | ")[0][2:] for line in section[2:]], self.order)


class WorkspaceRuleFootprintTest(unittest.TestCase):
    """The sweep's workspace rule names the footprint a row's room was sized for; a room held at
    its minimum side (the scaling sweep's 10 m) holds less than that share."""

    def test_rule_wins_over_the_achieved_share(self):
        row = {"class": "random", "objects": "4", "footprint_density": "0.0019634954",
               "workspace_rule": "footprint 0.01 (>= 10 m)"}
        self.assertEqual(sweep_data.Trial(row).footprint, 0.01)
        row = {"class": "sealed", "objects": "16", "footprint_density": "0.053125",
               "workspace_rule": "footprint 0.05"}
        self.assertEqual(sweep_data.Trial(row).footprint, 0.05)
        row = {"class": "sealed", "objects": "16", "footprint_density": "0.053125"}
        self.assertEqual(sweep_data.Trial(row).footprint, 0.05)  # inferred: F (N + 1) / N


class GoalOrderLabelTest(unittest.TestCase):
    """rearm's rows are named by the order they ran in (goal_order); the baselines' and the rows
    of logs before the column keep the method's name."""

    def test_labels(self):
        base = {"method": "rearm", "class": "random", "objects": "4"}
        label = lambda **kw: sweep_data.Trial(dict(base, **kw)).method
        self.assertEqual(label(goal_order="chain"),
                         "rearm (bound to the chain's order; baselines free)")
        self.assertEqual(label(goal_order="any"), "rearm (any order)")
        self.assertEqual(label(goal_order=""), "rearm")
        self.assertEqual(label(), "rearm")
        self.assertEqual(label(method="rearm-paper", goal_order="any"), "rearm-paper (any order)")
        self.assertEqual(label(method="birrt@10000", goal_order="any"), "birrt@10000")


class EqualTermsTimeTest(unittest.TestCase):
    """A baseline's time on equal terms is its wall time (planning and execution in Box2D), its
    planning kept apart; rearm's is its online compute, with no offline planning."""

    def test_baseline_and_rearm_rows(self):
        base = sweep_data.Trial({"method": "birrt", "planning_time_s": "0.5",
                                 "compute_time_s": "0.5", "wall_time_s": "2.0"})
        self.assertEqual((base.total, base.planning, base.time), (2.0, 0.5, 0.5))
        rearm = sweep_data.Trial({"method": "rearm", "planning_time_s": "",
                                  "compute_time_s": "1.5", "wall_time_s": "30"})
        self.assertEqual((rearm.total, rearm.planning, rearm.time), (1.5, None, 1.5))

    def test_first_action(self):
        """The column as written, None where empty, non-numeric or absent (an older log)."""
        def first(row):
            return sweep_data.Trial(dict(row, method="rearm")).first_action

        self.assertEqual(first({"first_action_time_s": "0.0125"}), 0.0125)
        self.assertIsNone(first({"first_action_time_s": ""}))
        self.assertIsNone(first({"first_action_time_s": "nan"}))
        self.assertIsNone(first({}))


class CostTest(unittest.TestCase):
    """The report's cost section against hand sums: 3 trials of 600 s, 1,200 s and 1,800 s of
    wall time (1 h in all) and 360 s of CPU each, two methods, two cells."""

    def test_totals_per_method_and_per_cell(self):
        header = HEADER + ["wall_time_s", "cpu_time_s"]
        rows = [("rearm", 2, "600", "360"), ("rearm", 4, "1200", "360"), ("birrt", 2, "1800", "360")]
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "trials.csv"), "w") as f:
                f.write(",".join(header) + "\n")
                for m, n, wall, cpu in rows:
                    f.write(csv_line(m, n=n).rstrip("\n") + ",%s,%s\n" % (wall, cpu))
            with open(os.path.join(d, "sweep.yaml"), "w") as f:
                f.write("name: cost\n")
            path = os.path.join(d, "report.md")
            sweep_report.write_report(sweep_data.Sweep(d), path, [])
            with open(path) as f:
                text = f.read()
        section = text.split("## What the study cost\n\n")[1]
        self.assertIn("Total CPU time 0.30 h; on one thread about 1.00 h", section)
        self.assertIn("| rearm | 2 | 0.50 h | 0.20 h |", section)
        self.assertIn("| birrt | 1 | 0.50 h | 0.10 h |", section)
        self.assertIn("| random | 2 | 0.1 | - | 2400 s |", section)  # rearm 600 + birrt 1800
        self.assertIn("| random | 4 | 0.1 | - | 1200 s |", section)


class RecoveryColumnsTest(unittest.TestCase):
    def test_between_fix_mode_entries_and_collisions(self):
        header = ["trial", "actions", "fix_mode_entries", "replans", "guides", "back_outs",
                  "a_new_counter", "redrops", "collisions", "min_clearance_m"]
        self.assertEqual(sweep_data.recovery_columns(header),
                         ["guides", "back_outs", "a_new_counter", "redrops"])

    def test_no_counters(self):
        self.assertEqual(sweep_data.recovery_columns(["fix_mode_entries", "collisions"]), [])
        self.assertEqual(sweep_data.recovery_columns(["fix_mode_entries", "replans",
                                                      "collisions"]), [])

    def test_missing_bounds(self):
        self.assertEqual(sweep_data.recovery_columns(["guides", "collisions"]), [])
        self.assertEqual(sweep_data.recovery_columns(["fix_mode_entries", "guides"]), [])
        self.assertEqual(sweep_data.recovery_columns([]), [])


class ReadTrialsTest(unittest.TestCase):
    def test_cut_line_and_wrong_width_dropped(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "trials.csv")
            with open(path, "w") as f:
                f.write("method,success\nrearm,1\nmrs,0,extra\nbirrt,1\nreplan,")
            err = io.StringIO()
            with contextlib.redirect_stderr(err):
                header, rows = sweep_data.read_trials(path)
        self.assertEqual(header, ["method", "success"])
        self.assertEqual([r["method"] for r in rows], ["rearm", "birrt"])
        self.assertIn("cut last line", err.getvalue())
        self.assertIn("line 3 has 3 fields", err.getvalue())

    def test_number(self):
        self.assertEqual(sweep_data.number("2.5"), 2.5)
        for text in (None, "", "x", "nan", "inf"):
            self.assertIsNone(sweep_data.number(text))


class NoMatplotlibTest(unittest.TestCase):
    def test_data_and_report_import_without_matplotlib(self):
        code = ("import sys; sys.path.insert(0, %r); import sweep_data, sweep_report; "
                "sys.exit('matplotlib' in sys.modules)" % os.path.normpath(PLOT_DIR))
        self.assertEqual(subprocess.run([sys.executable, "-c", code]).returncode, 0)


class NominalFootprintTest(unittest.TestCase):
    """A row's footprint is the sweep file's: the room's side is sqrt(N pi rho^2 / F) for N
    objects, and a sealed instance adds its pocket's blocker, an (N + 1)-th object of the same
    radius, to the share the column records."""

    def test_sealed_and_other_classes_map_back_to_the_sweep_files_value(self):
        rho = 0.25
        for n in (4, 8, 12, 16):
            for f in (0.01, 0.03, 0.05, 0.08, 0.12):
                side = math.sqrt(n * math.pi * rho * rho / f)
                plain = n * math.pi * rho * rho / (side * side)
                sealed = (n + 1) * math.pi * rho * rho / (side * side)
                self.assertEqual(sweep_data.nominal_footprint(plain, "random", n), f)
                self.assertEqual(sweep_data.nominal_footprint(plain, "cyclic", n), f)
                self.assertEqual(sweep_data.nominal_footprint(sealed, "sealed", n), f)
                self.assertNotEqual(sweep_data.nominal_footprint(sealed, "random", n), f)
        self.assertIsNone(sweep_data.nominal_footprint(None, "sealed", 4))


class KnownSolvableTest(unittest.TestCase):
    """An instance is solved by the sweep when some method's row of its geometry succeeded (the
    chain and any-order rows of one instance seed are one geometry), and known solvable when it
    also carried a witness plan; counted once per instance whatever its rows."""

    def test_counts_per_geometry(self):
        head = ["method", "class", "objects", "target_density", "instance_seed", "goal_order",
                "scatter_moves", "witness", "success", "status"]
        rows = [  # (method, class, seed, order, K, witness, success)
            ("rearm", "random", "1", "chain", "", "0", "0"),
            ("rearm", "random", "1", "any", "", "0", "0"),
            ("birrt", "random", "1", "any", "", "0", "1"),   # seed 1 solved by a baseline
            ("rearm", "random", "2", "chain", "", "0", "0"),
            ("birrt", "random", "2", "any", "", "0", "0"),   # seed 2 by nobody
            ("rearm", "constructive", "1", "chain", "8", "1", "0"),
            ("birrt", "constructive", "1", "any", "8", "1", "0"),  # witness, unsolved
            ("rearm", "constructive", "1", "chain", "16", "1", "1"),  # another K: its own
        ]
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "trials.csv"), "w") as f:
                f.write(",".join(head) + "\n")
                for m, c, seed, order, k, w, ok in rows:
                    f.write(",".join([m, c, "4", "0.1", seed, order, k, w, ok,
                                      "completed" if ok == "1" else "timeout"]) + "\n")
            s = sweep_data.Sweep(d)
            counts = lambda cls: sweep_data.solvable_counts(
                s, [x for x in s.trials if x.cls == cls and x.method.startswith("rearm")])
            self.assertEqual(counts("random"), (1, 1, 2))
            self.assertEqual(counts("constructive"), (1, 2, 2))
            path = os.path.join(d, "report.md")
            sweep_report.write_report(s, path, [])
            with open(path) as f:
                text = f.read()
            self.assertIn("| instances solved by any method | known solvable |", text)


class PairedTest(unittest.TestCase):
    """The sign test against enumeration of every coin sequence; the paired counts by instance
    (a rearm row set against a baseline, chain and any rows of one instance one geometry)."""

    def test_sign_test_is_the_enumerated_two_sided_probability(self):
        for n in range(0, 11):
            for b in range(n + 1):
                c = n - b
                extreme = abs(b - c)
                hits = sum(1 for seq in range(2 ** n)
                           if abs(2 * bin(seq).count("1") - n) >= extreme)
                self.assertAlmostEqual(sweep_data.sign_test(b, c), hits / 2 ** n, places=12,
                                       msg="%d:%d" % (b, c))

    def test_counts_and_best_baseline(self):
        head = ["method", "class", "objects", "target_density", "instance_seed", "goal_order",
                "success", "status", "workspace_rule"]
        rows = [  # (method, seed, order, success, footprint)
            ("rearm", "1", "chain", "1", "0.05"), ("birrt", "1", "any", "1", "0.05"),
            ("mrs", "1", "any", "0", "0.05"),
            ("rearm", "2", "chain", "1", "0.05"), ("birrt", "2", "any", "0", "0.05"),
            ("mrs", "2", "any", "0", "0.05"),
            ("rearm", "3", "chain", "0", "0.05"), ("birrt", "3", "any", "1", "0.05"),
            ("mrs", "3", "any", "1", "0.05"),
            ("rearm", "4", "chain", "0", "0.05"), ("birrt", "4", "any", "0", "0.05"),
            ("mrs", "4", "any", "0", "0.05"),
            ("rearm", "5", "chain", "1", "0.08"),  # no baseline row: not paired
            ("birrt", "6", "any", "1", "0.08"), ("rearm", "6", "chain", "0", "0.08"),
        ]
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "trials.csv"), "w") as f:
                f.write(",".join(head) + "\n")
                for m, seed, order, ok, fp in rows:
                    f.write(",".join([m, "random", "4", "0.05", seed, order, ok,
                                      "completed" if ok == "1" else "timeout",
                                      "footprint " + fp]) + "\n")
            s = sweep_data.Sweep(d)
            rearm = "rearm (bound to the chain's order; baselines free)"
            at = lambda fp: [x for x in s.trials if x.footprint == fp]
            self.assertEqual(sweep_data.paired(s, rearm, "birrt", at(0.05)), (1, 1, 1, 1))
            self.assertEqual(sweep_data.paired(s, rearm, "mrs", at(0.05)), (0, 2, 1, 1))
            self.assertEqual(sweep_data.paired(s, rearm, "birrt", at(0.08)), (0, 0, 1, 0))
            self.assertEqual(sweep_data.best_baseline(at(0.05)), "birrt")
            path = os.path.join(d, "report.md")
            sweep_report.write_report(s, path, [])
            with open(path) as f:
                text = f.read()
            self.assertIn("| 0.05 | all classes | %s | birrt (best) | 4 | 1 | 1 | 1 | 1 | 1 |"
                          % rearm, text)
            self.assertIn("| 0.05 | all classes | mrs | 4 | 1/4 = 0.25", text)


if __name__ == "__main__":
    unittest.main()
