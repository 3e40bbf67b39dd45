"""Tests of experiments/plot/sweep_figures.py and the sweep.py entry point; skipped where
python3 has no matplotlib (the report and data tests run without it).

run: python3 -m unittest discover -s tests/plot
"""
import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

PLOT_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                         "experiments", "plot"))
sys.path.insert(0, PLOT_DIR)

HAS_MATPLOTLIB = importlib.util.find_spec("matplotlib") is not None
METHODS = ["buffer", "mrs", "rearm-noguide", "fmrs", "rearm", "birrt-fmrs"]


def write_sweep(d):
    header = ("method,class,objects,target_density,achieved_density,status,success,reason,"
              "planning_time_s,compute_time_s,time_limit_s,actions,robot_path_m,revision\n")
    lines = [header]
    for i, m in enumerate(METHODS * 4):
        n = [1, 2, 4][i % 3]
        ok = i % 5 != 0
        lines.append("%s,%s,%d,0.1,%.3f,%s,%d,,,%.3f,60,%d,%.1f,abc\n" % (
            m, ["random", "sealed"][i % 2], n, 0.08 + 0.01 * (i % 7),
            "completed" if ok else "timeout", ok, 0.01 * (i + 1), 2 * n, 3.0 * n))
    with open(os.path.join(d, "trials.csv"), "w") as f:
        f.writelines(lines)
    with open(os.path.join(d, "sweep.yaml"), "w") as f:
        f.write("name: synthetic\n")


@unittest.skipUnless(HAS_MATPLOTLIB, "no matplotlib")
class PresentationTest(unittest.TestCase):
    def test_order_keeps_every_method(self):
        import sweep_figures
        order = sweep_figures.presentation_order(METHODS)
        self.assertEqual(sorted(order), sorted(METHODS))
        self.assertEqual(order, ["rearm", "mrs", "buffer", "rearm-noguide", "fmrs", "birrt-fmrs"])

    def test_unnamed_methods_get_distinct_colours(self):
        import sweep_figures
        order = sweep_figures.presentation_order(METHODS)
        colours = [sweep_figures.method_color(m, order) for m in order]
        self.assertEqual(len(set(colours)), len(order))


@unittest.skipUnless(HAS_MATPLOTLIB, "no matplotlib")
class EntryPointTest(unittest.TestCase):
    def test_report_and_every_figure(self):
        import sweep_figures
        with tempfile.TemporaryDirectory() as d:
            write_sweep(d)
            run = subprocess.run([sys.executable, os.path.join(PLOT_DIR, "sweep.py"), d],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertIn("report.md and 9 figures (24 trials)", run.stdout)
            for name in [n for n, _ in sweep_figures.FIGURES] + [
                    "answer_random.png", "answer_sealed.png", "time_equal_terms.png"]:
                self.assertGreater(os.path.getsize(os.path.join(d, name)), 0, name)
            with open(os.path.join(d, "report.md")) as f:
                report = f.read()
            self.assertIn("methods: " + ", ".join(METHODS), report)

    def test_answer_points_are_the_pooled_counts(self):
        # rearm is METHODS[4]: rows 4, 10, 16, 22, all random goals at N = 2 (i % 3 == 1), row
        # 10 failed (i % 5 == 0): 3 of 4; sealed goals have no rearm row.
        import answer_figures
        import sweep_data
        with tempfile.TemporaryDirectory() as d:
            write_sweep(d)
            s = sweep_data.Sweep(d)
        pts = answer_figures.points(s, "random", "rearm")
        self.assertEqual([(n, c.k, c.n) for n, c in pts], [(2, 3, 4)])
        self.assertEqual(answer_figures.points(s, "sealed", "rearm"), [])
        self.assertEqual([f for f, _ in answer_figures.figures(s)],
                         ["answer_random.png", "answer_sealed.png", "time_equal_terms.png"])

    def test_first_action_medians_and_an_older_log(self):
        """The dotted line: the median over a method's solved trials of first_action_time_s,
        rows without one left out; a log without the column draws none and the title says so."""
        import answer_figures
        import sweep_data
        header = "method,class,objects,status,success,first_action_time_s,compute_time_s\n"
        rows = ["rearm,random,4,completed,1,0.02,1\n", "rearm,random,4,completed,1,0.04,1\n",
                "rearm,random,4,completed,1,0.09,1\n", "rearm,random,4,stuck,0,0.5,1\n",
                "rearm,random,4,completed,1,,1\n", "rearm,random,8,completed,1,0.3,1\n"]
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "trials.csv"), "w") as f:
                f.writelines([header] + rows)
            s = sweep_data.Sweep(d)
            self.assertEqual(answer_figures.medians(s, "random", "rearm", "first_action"),
                             [(4, 0.04), (8, 0.3)])
            self.assertNotIn("predates", answer_figures.equal_terms_title(s))
            with open(os.path.join(d, "trials.csv"), "w") as f:
                for line in [header] + rows:
                    fields = line.split(",")
                    f.write(",".join(fields[:5] + fields[6:]))
            old = sweep_data.Sweep(d)
            self.assertEqual(answer_figures.medians(old, "random", "rearm", "first_action"), [])
            self.assertIn("predates the first_action_time_s column",
                          answer_figures.equal_terms_title(old))

    def test_usage(self):
        script = os.path.join(PLOT_DIR, "sweep.py")
        self.assertEqual(subprocess.run([sys.executable, script], capture_output=True).returncode,
                         2)
        with tempfile.TemporaryDirectory() as d:
            run = subprocess.run([sys.executable, script, d], capture_output=True, text=True)
        self.assertEqual(run.returncode, 1)
        self.assertIn("has no trials.csv", run.stderr)


def write_crowded_sweep(d):
    """rearm and birrt at N = 4 and 8, footprints written as the sweep writes them (0.05 off by
    rounding), goal-cycle counts 0 to 6; rearm succeeds where the trial index is not 0 mod 4."""
    header = ("method,class,objects,target_density,footprint_density,goal_cycle_objects,"
              "goals_occupied,walled_in,status,success,planning_time_s,compute_time_s,revision\n")
    lines = [header]
    for i in range(32):
        m = ["rearm", "birrt"][i % 2]
        n = [4, 8][(i // 2) % 2]
        f = ["0.049999999999999996", "0.08000000000000002"][(i // 4) % 2]
        ok = m == "birrt" or i % 8 != 0
        lines.append("%s,random,%d,0.05,%s,%d,0,0,%s,%d,,%.3f,abc\n" % (
            m, n, f, i % 7, "completed" if ok else "stuck", ok, 0.1 * (i + 1)))
    with open(os.path.join(d, "trials.csv"), "w") as f:
        f.writelines(lines)
    with open(os.path.join(d, "sweep.yaml"), "w") as f:
        f.write("name: crowded-synthetic\n")


@unittest.skipUnless(HAS_MATPLOTLIB, "no matplotlib")
class CrowdedFiguresTest(unittest.TestCase):
    def test_footprints_grouped_and_counted(self):
        import crowded_figures
        import sweep_data
        with tempfile.TemporaryDirectory() as d:
            write_crowded_sweep(d)
            s = sweep_data.Sweep(d)
        self.assertEqual(s.footprints, [0.05, 0.08])
        # rearm, N = 4, footprint 0.05: trials 0 and 8 and 16 and 24 (i % 8 == 0: failed) only.
        c = crowded_figures.pooled(s, "rearm", n=4, footprint=0.05)
        self.assertEqual((c.n, c.k), (4, 0))
        c = crowded_figures.pooled(s, "rearm", n=8, footprint=0.05)  # i = 2, 10, 18, 26
        self.assertEqual((c.n, c.k), (4, 4))
        # Goal-cycle counts 4, 5 and 6 fall into the "4+" point.
        capped = [t for t in s.trials if crowded_figures.difficulty_value(
            t, "goal_cycle_objects") == crowded_figures.DIFFICULTY_CAP]
        self.assertEqual(len(capped), sum(1 for i in range(32) if i % 7 >= 4))

    def test_three_more_figures_only_with_two_footprints(self):
        import crowded_figures
        with tempfile.TemporaryDirectory() as d:
            write_crowded_sweep(d)
            run = subprocess.run([sys.executable, os.path.join(PLOT_DIR, "sweep.py"), d],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            # 6 of every sweep, 1 answer figure (random goals only), the time on equal terms, 3
            # crowded ones.
            self.assertIn("report.md and 11 figures (32 trials)", run.stdout)
            for name, _ in crowded_figures.FIGURES:
                self.assertGreater(os.path.getsize(os.path.join(d, name)), 0, name)
        with tempfile.TemporaryDirectory() as d:
            write_sweep(d)  # no footprint column
            run = subprocess.run([sys.executable, os.path.join(PLOT_DIR, "sweep.py"), d],
                                 capture_output=True, text=True)
            self.assertIn("report.md and 9 figures", run.stdout)
            for name, _ in crowded_figures.FIGURES:
                self.assertFalse(os.path.exists(os.path.join(d, name)), name)


if __name__ == "__main__":
    unittest.main()
