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
            self.assertIn("report.md and 6 figures (24 trials)", run.stdout)
            for name, _ in sweep_figures.FIGURES:
                self.assertGreater(os.path.getsize(os.path.join(d, name)), 0, name)
            with open(os.path.join(d, "report.md")) as f:
                report = f.read()
            self.assertIn("methods: " + ", ".join(METHODS), report)

    def test_usage(self):
        script = os.path.join(PLOT_DIR, "sweep.py")
        self.assertEqual(subprocess.run([sys.executable, script], capture_output=True).returncode,
                         2)
        with tempfile.TemporaryDirectory() as d:
            run = subprocess.run([sys.executable, script, d], capture_output=True, text=True)
        self.assertEqual(run.returncode, 1)
        self.assertIn("has no trials.csv", run.stderr)


if __name__ == "__main__":
    unittest.main()
