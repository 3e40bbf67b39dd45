#!/usr/bin/env bash
# LTL translation benchmark (docs/symbolic.md "Speed and size" and "Our targets").
#
# Builds and runs bench/ltl/translate_bench (JSON into results/$MACHINE/ltl_translate.json),
# then times `spin -f` on the same formula families where spin is plausible (30 s timeout
# per call; larger n of a family are not run once spin timed out), and writes
# results/$MACHINE/ltl_vs_spin.md: rearm vs spin vs the ltl2ba numbers of docs/symbolic.md,
# and a MET/MISSED line per target.
#
# Environment: MACHINE (default debian12-2core), BUILD (default build). Other arguments go to
# translate_bench, e.g. --benchmark_filter=fseq. Runs in about 5 minutes on 2 cores.
set -euo pipefail
source "$(dirname "$0")/lib/bench_common.sh"
bench_parse "$@"
set -- ${BENCH_ARGS[@]+"${BENCH_ARGS[@]}"}
bench_prepare translate_bench
bench_run translate_bench ltl_translate.json "$@"

SPIN_DIR=$(mktemp -d)  # spin may write files into its working directory
trap 'rm -rf "$SPIN_DIR" "$OUT"' EXIT
CPU=$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')

python3 - "$(bench_bin translate_bench)" "$OUT" "$SPIN_DIR" "$MACHINE" "$(nproc)" "$CPU" "$REV" \
  "$LOAD" <<'PYTHON'
import datetime
import json
import re
import subprocess
import sys
import time

bench, out, spin_dir, machine, nproc, cpu, rev, load = sys.argv[1:9]
SPIN_TIMEOUT_S = 30

FAMILIES = [  # (key, label, n values for spin)
    ("fseq", "F-sequencing `F(p1 & F(p2 & ... F pn))`", [5, 10, 15]),
    ("eq1", "paper Eq. (1), n objects (2n actions)", [3, 4, 5, 6, 7, 8]),
    ("patrol", "patrol `GF p1 & ... & GF pn`", [2, 3, 4, 5]),
    ("seqpatrol", "sequenced patrol `GF(p1 & F(p2 & ... F pn))`", [2, 3, 4]),
    ("conjf", "`F p1 & ... & F pn`", [2, 3, 4, 5, 6]),
]
# docs/symbolic.md, "Speed and size, measured here on the reference tools" (ltl2ba 1.3).
LTL2BA = {
    ("fseq", 20): (21, "21 states, 1.7 ms"),
    ("fseq", 100): (None, "0.46 s"),
    ("eq1", 10): (21, "21 states, 1.1 ms"),
    ("eq1", 50): (None, "0.41 s"),
    ("patrol", 8): (9, "9 states, 2.2 s"),
    ("patrol", 9): (None, "19.3 s"),
    ("patrol", 10): (None, "> 30 s"),
    ("seqpatrol", 8): (448, "448 states, 5.3 s"),
    ("conjf", 10): (1024, "1024 states, 0.72 s"),
}

# --- rearm: Google Benchmark JSON, names <family>/<alphabet>/<n> ---------------------------
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
rearm = {}  # (family, alphabet, n) -> {"ms", "states", "edges"} or {"error"}
with open(f"{out}/ltl_translate.json") as f:
    for b in json.load(f)["benchmarks"]:
        family, alphabet, n = b["name"].split("/")[:3]
        key = (family, alphabet, int(n))
        if b.get("error_occurred"):
            rearm[key] = {"error": b.get("error_message", "error")}
        else:
            rearm[key] = {"ms": b["real_time"] * TO_MS[b["time_unit"]],
                          "states": int(b["states"]), "edges": int(b["edges"])}


def fmt_ms(ms):
    if ms >= 1000:
        return f"{ms / 1000:.2f} s"
    return f"{ms:.3g} ms" if ms >= 0.1 else f"{ms * 1000:.3g} µs"


# --- spin ----------------------------------------------------------------------------------
def spin_states(never_claim):
    """Counts the states of a never claim: its labels, where consecutive labels with no
    statement between them (`accept_init:` then `T0_init:`) name one state; `accept_all:`
    (the accepting sink that `assert(!(g))` jumps to) is a state."""
    states, previous_was_label = 0, False
    for line in never_claim.splitlines():
        line = line.strip()
        if not line or line.startswith("never") or line.startswith("/*"):
            continue
        is_label = re.fullmatch(r"[A-Za-z_]\w*\s*:", line) is not None
        if is_label and not previous_was_label:
            states += 1
        previous_was_label = is_label
    return states


def spin_formula(family, n):
    text = subprocess.run([bench, f"--formula={family}:{n}"], check=True,
                          capture_output=True, text=True).stdout.strip()
    # spin reads `grasp(M1)` as a call: action predicates become identifiers (grasp_M1).
    return re.sub(r"(\w+)\(([\w,]*)\)",
                  lambda m: m.group(1) + "_" + m.group(2).replace(",", "_"), text)


spin = {}  # (family, n) -> (states or None, time text)
for family, _, spin_ns in FAMILIES:
    timed_out_at = None
    for n in spin_ns:
        if timed_out_at is not None:
            spin[(family, n)] = (None, f"> {SPIN_TIMEOUT_S} s (not run)")
            continue
        formula = spin_formula(family, n)
        start = time.perf_counter()
        run = subprocess.run(["timeout", str(SPIN_TIMEOUT_S), "spin", "-f", formula],
                             cwd=spin_dir, capture_output=True, text=True)
        seconds = time.perf_counter() - start
        if run.returncode == 124:
            spin[(family, n)] = (None, f"> {SPIN_TIMEOUT_S} s")
            timed_out_at = n
        elif run.returncode != 0 or "never" not in run.stdout:
            spin[(family, n)] = (None, "error: " + (run.stderr.strip() or "no never claim"))
        else:
            spin[(family, n)] = (spin_states(run.stdout), fmt_ms(seconds * 1000))
        print(f"spin {family} n={n}: {spin[(family, n)]}", flush=True)


# --- markdown ------------------------------------------------------------------------------
def rearm_cells(family, alphabet, n):
    r = rearm.get((family, alphabet, n))
    if r is None:
        return ["–", "–"]
    if "error" in r:
        return ["error", r["error"]]
    return [str(r["states"]), fmt_ms(r["ms"])]


lines = [
    "# LTL → Büchi translation: rearm vs spin vs ltl2ba",
    "",
    f"{datetime.date.today().isoformat()}, machine `{machine}` ({nproc} cores, {cpu}), "
    f"git `{rev}`, load average {load} as the benchmark started.",
    "",
    "rearm: `bench/ltl/translate_bench` (Release), wall-clock (`real_time`) per translation; "
    "*general* = guards over the propositions (what spin and ltl2ba build), *actions* = one "
    "action at a time (N+1 letters). spin 6.5.2 `spin -f`, one run, wall clock including "
    f"process start, {SPIN_TIMEOUT_S} s timeout; states = state labels of its never claim "
    "(`accept_init:` + `T0_init:` is one state, `accept_all:` counts). ltl2ba 1.3: the "
    "numbers of docs/symbolic.md's table (not rerun by this script). "
    "Eq. (1)'s action predicates are renamed for spin (`release(M1,l2)` → `release_M1_l2`).",
    "",
    "| family | n | rearm general states | rearm general time | rearm actions states "
    "| rearm actions time | spin states | spin time | ltl2ba |",
    "|---|---|---|---|---|---|---|---|---|",
]
for family, label, _ in FAMILIES:
    ns = sorted({k[2] for k in rearm if k[0] == family} | {k[1] for k in spin if k[0] == family})
    for n in ns:
        s_states, s_time = spin.get((family, n), (None, "–"))
        cells = [label, str(n)] + rearm_cells(family, "general", n) + \
            rearm_cells(family, "actions", n) + \
            [str(s_states) if s_states is not None else "–", s_time,
             LTL2BA.get((family, n), (None, "–"))[1]]
        lines.append("| " + " | ".join(cells) + " |")


# --- targets -------------------------------------------------------------------------------
def check(description, family, alphabet, n, max_ms=None, states=None, max_states=None,
          max_edges=None):
    r = rearm.get((family, alphabet, n))
    if r is None or "error" in r:
        return f"- MISSED — {description}: no measurement ({r['error'] if r else 'not run'})"
    ok = ((max_ms is None or r["ms"] <= max_ms) and (states is None or r["states"] == states)
          and (max_states is None or r["states"] <= max_states)
          and (max_edges is None or r["edges"] <= max_edges))
    return (f"- {'MET' if ok else 'MISSED'} — {description}: {r['states']} states, "
            f"{r['edges']} edges, {fmt_ms(r['ms'])}")


targets = [
    check("F-sequencing n=20 ≤ 1 ms with 21 states (actions)", "fseq", "actions", 20,
          max_ms=1, states=21),
    check("F-sequencing n=20 ≤ 1 ms with 21 states (general)", "fseq", "general", 20,
          max_ms=1, states=21),
    check("F-sequencing n=100 ≤ 50 ms with 101 states (actions)", "fseq", "actions", 100,
          max_ms=50, states=101),
    check("F-sequencing n=100 ≤ 50 ms with 101 states (general)", "fseq", "general", 100,
          max_ms=50, states=101),
    check("F-sequencing n=20 ≤ 2n+1 = 41 feasible edges (actions)", "fseq", "actions", 20,
          max_edges=41),
    check("F-sequencing n=100 ≤ 2n+1 = 201 feasible edges (actions)", "fseq", "actions", 100,
          max_edges=201),
    check("patrol n=20 ≤ 10 ms with 21 states (actions)", "patrol", "actions", 20,
          max_ms=10, states=21),
    check("patrol n=8 faster than ltl2ba's 2.2 s (general)", "patrol", "general", 8,
          max_ms=2200),
    check("Eq. (1) for 10 objects ≤ 2 ms (actions)", "eq1", "actions", 10, max_ms=2),
    check("Eq. (1) for 10 objects ≤ 2 ms (general)", "eq1", "general", 10, max_ms=2),
    check("sequenced patrol n=8 ≤ 9 states (actions)", "seqpatrol", "actions", 8,
          max_states=9),
    check("sequenced patrol n=8 ≤ 9 states (general)", "seqpatrol", "general", 8,
          max_states=9),
    check("∧F n=10 in 1024 states ≤ 0.5 s (general)", "conjf", "general", 10,
          max_ms=500, states=1024),
    check("∧F n=10 in 1024 states ≤ 0.5 s (actions)", "conjf", "actions", 10,
          max_ms=500, states=1024),
]
for (family, n), (states, text) in sorted(LTL2BA.items()):
    if states is not None:
        targets.append(check(f"never more states than ltl2ba ({text}): {family} n={n} "
                             "(general)", family, "general", n, max_states=states))

lines += ["", "## Targets", "",
          "docs/symbolic.md \"Our targets\", checked against the measurements above.", ""]
lines += targets
with open(f"{out}/ltl_vs_spin.md", "w") as f:
    f.write("\n".join(lines) + "\n")
print("\n".join(lines))
missed = sum(t.startswith("- MISSED") for t in targets)
print(f"bench_ltl: {len(targets) - missed} targets met, {missed} missed")
PYTHON
bench_publish
