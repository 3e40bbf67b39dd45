#!/usr/bin/env python3
"""The behaviour gate: proves that a refactor of the executive changed nothing.

usage: behaviour_gate.py [--rearm BIN] [--jobs N] [--work DIR] [--record] [--only SUBSTR]

Runs `rearm run` on a fixed set of cases and compares the sha256 of each run's trajectory.json
and of its metrics.json without the wall-clock fields against tests/gate/hashes.txt:
  (a) the five paper scenes (fig3, fig4, fig5, patrol, four_objects) under both variants;
  (b) every corpus instance under tests/corpus, in checked mode (as it is, robust variant);
  (c) for each switch of the robust variant, the two shortest trials of the committed scaling
      sweep (results/debian12-2core/sweep, by simulated time) where the switch's counter fired,
      and fires again in this `rearm run` (switches without a counter of their own: the counter of the recovery
      they shape, see EVIDENCE), each with the switch on and with it off.
The case list is fixed when the hashes are recorded (--record) and read back from the hashes
file afterwards, so a check runs exactly the recorded cases. Hashes change only in a commit
that says why. Exit 0: every case matches; 1: a mismatch or a failed run (each named).
"""
import argparse
import concurrent.futures as cf
import csv
import hashlib
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HASHES = os.path.join(ROOT, "tests", "gate", "hashes.txt")
SWEEP = os.path.join(ROOT, "results", "debian12-2core", "sweep")
SCENES = ["fig3", "fig4", "fig5", "patrol", "four_objects"]
# metrics.json keys measured by the wall clock (differ run to run; everything else must not).
WALL_CLOCK = {"wall_time_s", "controller_time_s", "real_time_factor", "compute_time_s",
              "mission_time_s", "topology_time_s", "rebuild_time_s", "control_time_s",
              "cpu_time_s", "planning_time_s", "planning_wall_s", "compute_times", "first_action_time_s"}
# switch key -> the metrics.json recovery counter that shows its code ran, read from the switch
# registry (framework/core/switches.h: key, kind, home, evidence). Switches with no counter of
# their own name the recovery they shape (track, widen, persist, memory: the guide; escape: the
# back-up); policies that act in every run (bevel, scan, defer) take the guide's trials.
def registry_evidence():
    text = open(os.path.join(ROOT, "framework", "core", "switches.h")).read()
    rows = re.findall(r'\{"(\w+)", SwitchKind::k\w+, SwitchHome::k\w+, "(\w+)",', text)
    if not rows:
        raise RuntimeError("no switch found in framework/core/switches.h")
    return dict(rows)


EVIDENCE = registry_evidence()
TRIALS_PER_SWITCH = 2
CANDIDATES_PER_SWITCH = 12  # shortest sweep trials tried per switch before giving up on it


def strip_wall_clock(x):
    if isinstance(x, dict):
        return {k: strip_wall_clock(v) for k, v in x.items() if k not in WALL_CLOCK}
    if isinstance(x, list):
        return [strip_wall_clock(v) for v in x]
    return x


def sha(data):
    return hashlib.sha256(data).hexdigest()


def scenario_for(case, work):
    """The scenario file and extra flags of a case id."""
    kind, rest = case.split(":", 1)
    if kind == "scene":
        name, variant = rest.split("@")
        return os.path.join("experiments", "scenarios", name + ".yaml"), ["--variant", variant]
    if kind == "corpus":
        return os.path.join("tests", "corpus", rest + ".yaml"), ["--checked"]
    instance, switch = rest.split("@")
    src = os.path.join(SWEEP, "instances", instance + ".yaml")
    if switch.startswith("on-"):
        return os.path.relpath(src, ROOT), []
    key = switch[len("off-"):]
    text = open(src).read()
    off, n = re.subn(r"\b%s: true\b" % re.escape(key), "%s: false" % key, text)
    if n != 1:
        raise RuntimeError("%s: switch %s not found once in the controller line" % (src, key))
    path = os.path.join(work, "cases", "%s-no%s.yaml" % (instance, key))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(off)
    return os.path.relpath(path, ROOT), []


def run_case(rearm, case, work):
    """(trajectory hash, metrics hash, metrics dict) of one case, or raises."""
    scenario, flags = scenario_for(case, work)
    out = os.path.join(work, "out", re.sub(r"[^A-Za-z0-9_.-]", "_", case))
    cmd = [rearm, "run", scenario, "--out", out, "--no-plot"] + flags
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if p.returncode not in (0, 1):
        raise RuntimeError("%s exited %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()))
    traj = open(os.path.join(out, "trajectory.json"), "rb").read()
    metrics = json.load(open(os.path.join(out, "metrics.json")))
    stable = strip_wall_clock(metrics)
    # The scenario path depends on --work for the switched-off copies: hash its file name only.
    stable["source"] = os.path.basename(stable.get("source", ""))
    stable = json.dumps(stable, sort_keys=True).encode()
    return sha(traj), sha(stable), metrics


def fixed_cases():
    cases = ["scene:%s@%s" % (s, v) for s in SCENES for v in ("paper", "robust")]
    corpus = os.path.join(ROOT, "tests", "corpus")
    for d in sorted(os.listdir(corpus)):
        if not os.path.isdir(os.path.join(corpus, d)):
            continue
        for f in sorted(os.listdir(os.path.join(corpus, d))):
            if f.endswith(".yaml"):
                cases.append("corpus:%s/%s" % (d, f[:-5]))
    return cases


def sweep_candidates(counter):
    """The committed sweep's rearm trials whose row shows `counter` fired, shortest simulated
    time first."""
    rows = [r for r in csv.DictReader(open(os.path.join(SWEEP, "trials.csv")))
            if r["method"] == "rearm" and r["sim_time_s"] and int(r.get(counter) or 0) > 0]
    rows.sort(key=lambda r: (float(r["sim_time_s"]), r["instance"]))
    return list(dict.fromkeys(r["instance"] for r in rows))


def select_switch_cases(rearm, work, jobs):
    """For each switch, the two shortest sweep trials where its evidence counter fired, checked
    by running them now (the counter must fire in this run too)."""
    fired = {}  # instance -> metrics of its run as it is (robust variant)

    def metrics_of(batch):
        todo = [i for i in batch if i not in fired]
        with cf.ThreadPoolExecutor(jobs) as ex:
            for i, (_, _, m) in zip(todo, ex.map(
                    lambda i: run_case(rearm, "sweep:%s@on-probe" % i, work), todo)):
                fired[i] = m
    cases = []
    for key, counter in EVIDENCE.items():
        instances = sweep_candidates(counter)[:CANDIDATES_PER_SWITCH]
        chosen = []
        for start in range(0, len(instances), 4):
            batch = instances[start:start + 4]
            metrics_of(batch)
            chosen += [i for i in batch if fired[i]["recoveries"].get(counter, 0) > 0]
            if len(chosen) >= TRIALS_PER_SWITCH:
                break
        chosen = chosen[:TRIALS_PER_SWITCH]
        if len(chosen) < TRIALS_PER_SWITCH:
            print("gate: %s: only %d of the %d shortest trials where %s fired fire it now" %
                  (key, len(chosen), len(instances), counter), file=sys.stderr)
        for i in chosen:
            cases += ["sweep:%s@on-%s" % (i, key), "sweep:%s@off-%s" % (i, key)]
    return list(dict.fromkeys(cases))


def read_hashes():
    out = {}
    for line in open(HASHES):
        if line.startswith("#") or not line.strip():
            continue
        case, traj, metrics = line.split()
        out[case] = (traj, metrics)
    return out


def run_all(rearm, cases, work, jobs):
    results, failures = {}, []
    with cf.ThreadPoolExecutor(jobs) as ex:
        futures = {ex.submit(run_case, rearm, c, work): c for c in cases}
        for f in cf.as_completed(futures):
            c = futures[f]
            try:
                t, m, _ = f.result()
                results[c] = (t, m)
            except Exception as e:  # a failed run is reported with its case, not raised
                failures.append("%s: %s" % (c, e))
    return results, failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rearm", default=os.path.join(ROOT, "build", "bin", "rearm"))
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "gate"))
    ap.add_argument("--record", action="store_true", help="select the cases, write the hashes")
    ap.add_argument("--only", default="", help="check only the cases containing this text")
    a = ap.parse_args()
    rearm = os.path.abspath(a.rearm)
    if not os.access(rearm, os.X_OK):
        sys.exit("gate: no rearm program at %s (build it, or pass --rearm)" % rearm)
    work = os.path.abspath(a.work)
    if a.record:
        cases = fixed_cases() + select_switch_cases(rearm, work, a.jobs)
    else:
        expected = read_hashes()
        cases = [c for c in expected if a.only in c]
    results, failures = run_all(rearm, cases, work, a.jobs)
    if a.record:
        if failures:
            sys.exit("gate: not recorded, runs failed:\n  " + "\n  ".join(failures))
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                             capture_output=True, text=True).stdout.strip()
        if subprocess.run(["git", "diff", "--quiet", "HEAD"], cwd=ROOT).returncode != 0:
            rev += " with uncommitted changes"
        os.makedirs(os.path.dirname(HASHES), exist_ok=True)
        with open(HASHES, "w") as f:
            f.write("# behaviour gate (scripts/behaviour_gate.py): case, sha256 of trajectory.json,"
                    " sha256 of metrics.json without wall-clock fields\n")
            f.write("# recorded at revision %s, %d cases\n" % (rev, len(cases)))
            for c in cases:
                f.write("%s %s %s\n" % (c, *results[c]))
        print("gate: recorded %d cases in %s" % (len(cases), os.path.relpath(HASHES, ROOT)))
        return 0
    bad = list(failures)
    for c in cases:
        if c in results and results[c] != expected[c]:
            which = [n for n, x, y in zip(("trajectory", "metrics"), results[c], expected[c])
                     if x != y]
            bad.append("%s: %s changed" % (c, " and ".join(which)))
    for line in sorted(bad):
        print("gate: MISMATCH " + line, file=sys.stderr)
    print("gate: %d of %d cases identical" % (len(cases) - len(bad), len(cases)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
