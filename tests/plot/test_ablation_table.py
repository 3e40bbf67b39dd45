"""Tests of experiments/plot/ablation_table.py on synthetic CSVs, standard library only.

run: python3 -m unittest discover -s tests/plot
"""
import contextlib
import io
import os
import sys
import tempfile
import unittest

PLOT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "experiments",
                        "plot")
sys.path.insert(0, os.path.normpath(PLOT_DIR))

import ablation_table  # noqa: E402

HEADER = "method,class,objects,target_density,instance_seed,success,fix_mode_entries,replans," \
         "guides,back_outs,a_new_counter,collisions\n"
ABLATION = HEADER + (
    "rearm,random,2,0.1,11,1,0,5,2,1,0,0\n"
    "rearm,sealed,2,0.1,12,0,0,0,1,0,4,1\n"
    "rearm-future,random,2,0.1,11,1,0,0,0,0,0,0\n"
    "rearm-future,sealed,2,0.1,12,1,0,0,0,3,,0\n")
SWEEP = HEADER + (
    "fmrs,random,2,0.1,11,1,0,0,0,0,0,0\n"
    "fmrs,sealed,2,0.1,12,0,0,0,0,0,0,0\n"
    "fmrs,sealed,2,0.1,99,1,0,0,0,0,0,0\n"  # not an ablation instance
    "rearm,random,2,0.1,11,0,0,0,0,0,0,0\n")  # rearm's rows are the ablation's own


class AblationTableTest(unittest.TestCase):
    def run_table(self, *texts):
        with tempfile.TemporaryDirectory() as d:
            paths = []
            for i, text in enumerate(texts):
                paths.append(os.path.join(d, "trials%d.csv" % i))
                with open(paths[-1], "w") as f:
                    f.write(text)
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                code = ablation_table.main(["ablation_table.py"] + paths)
        self.assertEqual(code, 0)
        return out.getvalue().splitlines()

    def test_counters_come_from_the_header(self):
        lines = self.run_table(ABLATION)
        head = lines.index("| method | trials with a collision | guides | back-ups | "
                           "a new counter |")
        self.assertEqual(lines[head + 1], "|---|---|---|---|---|")
        self.assertEqual(lines[head + 2:], ["| rearm | 1 | 3 | 1 | 4 |",
                                            "| rearm-future | 0 | 0 | 3 | 0 |"])

    def test_success_table(self):
        lines = self.run_table(ABLATION)
        self.assertEqual(lines[:4], [
            "| method | random | sealed | all |",
            "|---|---|---|---|",
            # Wilson 95% of 1/2: 0.5 -+ 0.4055 (closed form), 2/2: [0.3424, 1].
            "| rearm | 1/1 (100%, 21–100) | 0/1 (0%, 0–79) | 1/2 (50%, 9–91) |",
            "| rearm-future | 1/1 (100%, 21–100) | 1/1 (100%, 21–100) | 2/2 (100%, 34–100) |"])

    def test_sweep_baselines_on_the_same_instances(self):
        lines = self.run_table(ABLATION, SWEEP)
        self.assertIn("| fmrs (committed sweep) | 1/1 (100%, 21–100) | 0/1 (0%, 0–79) | "
                      "1/2 (50%, 9–91) |", lines)
        self.assertFalse(any(line.startswith("| rearm (committed sweep)") for line in lines))
        # The sweep's methods have success rows only: the counters are the ablation's.
        self.assertEqual(lines[-2:], ["| rearm | 1 | 3 | 1 | 4 |",
                                      "| rearm-future | 0 | 0 | 3 | 0 |"])


if __name__ == "__main__":
    unittest.main()
