"""Tests of experiments/plot/run.py's figure: on the committed runs of the paper's scenes
(results/debian12-2core/fig3, fig4, fig5), every action that metrics.json records appears in the
figure's data (run_figure.json), numbered in the order the actions ended, each Fix-mode action
marked as one, each in the panel whose stretch holds its end. Skipped where python3 has no
matplotlib.

run: python3 -m unittest discover -s tests/plot
"""
import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RUN_PY = os.path.join(ROOT, "experiments", "plot", "run.py")
RESULTS = os.path.join(ROOT, "results", "debian12-2core")
HAS_MATPLOTLIB = importlib.util.find_spec("matplotlib") is not None


def draw(scene, out, *flags):
    run = subprocess.run([sys.executable, RUN_PY, os.path.join(RESULTS, scene, "trajectory.json"),
                          out, "--no-animation", *flags], capture_output=True, text=True)
    return run


@unittest.skipUnless(HAS_MATPLOTLIB, "no matplotlib")
class RunFigureTest(unittest.TestCase):
    def check_scene(self, scene, snapshots):
        with open(os.path.join(RESULTS, scene, "metrics.json")) as f:
            metrics = json.load(f)
        with tempfile.TemporaryDirectory() as d:
            run = draw(scene, d, "--snapshots=%d" % snapshots)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertGreater(os.path.getsize(os.path.join(d, "run.png")), 0)
            with open(os.path.join(d, "run_figure.json")) as f:
                fig = json.load(f)
        marks = fig["actions"]
        expected = sorted(metrics["actions"], key=lambda a: a["t_end_s"])
        self.assertEqual([m["action"] for m in marks], [a["action"] for a in expected], scene)
        self.assertEqual([m["fix_mode"] for m in marks], [a["fix_mode"] for a in expected], scene)
        self.assertEqual([m["number"] for m in marks], list(range(1, len(expected) + 1)))
        self.assertTrue(any(m["fix_mode"] for m in marks), scene + " has Fix-mode actions")
        self.assertEqual(fig["snapshots"], min(snapshots, len({round(a["t_end_s"], 6)
                                                              for a in expected})))
        panels = fig["panels"]
        for m in marks:
            lo, hi = panels[m["panel"]]
            self.assertLessEqual(lo - 0.1, m["t_end"], m)
            self.assertLessEqual(m["t_end"], hi + 0.1, m)

    def test_fig3(self):
        self.check_scene("fig3", 2)

    def test_fig4(self):
        self.check_scene("fig4", 3)

    def test_fig5(self):
        self.check_scene("fig5", 4)

    def test_formats_and_bad_options(self):
        with tempfile.TemporaryDirectory() as d:
            for fmt in ("pdf", "svg"):
                run = draw("fig3", d, "--format=" + fmt)
                self.assertEqual(run.returncode, 0, run.stderr)
                self.assertGreater(os.path.getsize(os.path.join(d, "run." + fmt)), 0)
            self.assertEqual(draw("fig3", d, "--format=jpg").returncode, 2)
            self.assertEqual(draw("fig3", d, "--snapshots=0").returncode, 2)


if __name__ == "__main__":
    unittest.main()
