"""The PDDL 3 suite's non-temporal tracks (bench planners, issue 44)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401


PDDL3_FIRST = "pddl3-60s-first-2026-12-07"


def folder_runs(folder):
    """A `bench planners` folder's runs and VAL's verdicts on its plans
    (val-check.txt, benchmarks/val_check.py)."""
    runs = load(f"{folder}/runs.json")
    runs = runs["runs"] if isinstance(runs, dict) else runs
    with open(os.path.join(RESULTS, folder, "val-check.txt")) as f:
        return runs, f.read()


def maximised(run):
    """Whether the run's problem maximises its metric (read from the problem file)."""
    with open(os.path.join(HERE, "..", "..", "shared", "benchmarks", run["problem"])) as f:
        return re.search(r"\(:metric\s+maximize", f.read(), re.I) is not None


def pddl3_classical_block(folder=PDDL3_FIRST):
    """IPC 2006's simple- and qualitative-preferences tracks in a `bench
    planners` run: coverage and the summed metric per domain (there is no
    reference planner's result for them in ../shared), and VAL's verdicts
    from the folder's val-check.txt (benchmarks/val_check.py)."""
    runs, val = folder_runs(folder)
    rows = []
    for domain in sorted({r["domain"] for r in runs if r["domain"].startswith("ipc-2006-classical/")}):
        mine = [r for r in runs if r["domain"] == domain]
        solved = [r for r in mine if r["status"] == "solved"]
        accepted = sum(f"{r['problem']}: VAL valid" in val for r in solved)
        direction = "maximised" if maximised(mine[0]) else "minimised"
        rows.append([domain.split("/", 1)[1], f"{len(solved)}/{len(mine)}", f"{accepted}/{len(solved)}", direction,
                     f"{sum(r['value'] for r in solved):.1f}"])
    return table(["domain", "coverage", "VAL accepts", "metric", "summed metric"], rows)


PDDL3_ISSUE44_FIRST = "pddl3-60s-first-2026-12-07-final"
PDDL3_ISSUE44_ANYTIME = "pddl3-60s-anytime-2026-12-07"
PDDL3_ISSUE44_ANYTIME_D11691A = "pddl3-60s-anytime-d11691a-2026-12-07"
OPTIC = os.path.join(HERE, "..", "..", "shared", "benchmarks", "pddl3", "baseline", "optic_60s.csv")


def optic_runs():
    """OPTIC's two runs per temporal problem (first plan, anytime): the value
    of each valid plan, keyed by (domain, instance number)."""
    import csv
    out = {}
    with open(OPTIC) as f:
        for row in csv.DictReader(f):
            values = [float(row[f"{run}_value"]) for run in ("first", "anytime")
                      if row[f"{run}_valid"] == "1" and row[f"{run}_value"]]
            out[(row["domain"], int(row["problem"]))] = values
    return out


def pddl3_against_optic_block(folder):
    """The temporal tracks in a `bench planners` run against OPTIC's two runs
    (../shared/benchmarks/pddl3/baseline): coverage, VAL's verdicts
    (val-check.txt), and on the problems both solve the summed metric, ours
    beside OPTIC's better run per problem, in the metric's direction."""
    runs, val = folder_runs(folder)
    optic = optic_runs()

    def optic_values(run):
        return optic.get((run["domain"], int(re.search(r"instance-(\d+)", run["problem"]).group(1))), [])

    rows = []
    for domain in sorted({r["domain"] for r in runs if r["domain"].startswith("ipc-2006/")}):
        mine = [r for r in runs if r["domain"] == domain]
        solved = [r for r in mine if r["status"] == "solved"]
        accepted = sum(f"{r['problem']}: VAL valid" in val for r in solved)
        maximise = maximised(mine[0])
        optic_solved = sum(1 for r in mine if optic_values(r))
        ours, theirs, both = 0.0, 0.0, 0
        for r in solved:
            values = optic_values(r)
            if values:
                both += 1
                ours += r["value"]
                theirs += max(values) if maximise else min(values)
        # Within one epsilon (0.001, the plans' separation) per problem: a
        # tie, since a schedule an epsilon shorter is no better plan.
        slack = 0.001 * both + 1e-9
        better = "-" if not both else ("ours" if (ours > theirs + slack if maximise else ours < theirs - slack)
                                       else "OPTIC" if (ours < theirs - slack if maximise else ours > theirs + slack)
                                       else "tie")
        rows.append([domain.split("/", 1)[1], f"{len(solved)}/{len(mine)}", f"{optic_solved}/{len(mine)}",
                     f"{accepted}/{len(solved)}", "maximised" if maximise else "minimised", both,
                     f"{ours:.3f}" if both else "-", f"{theirs:.3f}" if both else "-", better])
    total = sum(int(r[1].split("/")[0]) for r in rows)
    return (f"Solved: {total}/{sum(int(r[1].split('/')[1]) for r in rows)}, OPTIC (either run) "
            f"{sum(int(r[2].split('/')[0]) for r in rows)}.\n\n"
            + table(["domain", "coverage", "OPTIC either", "VAL accepts", "metric", "both solved", "ours (summed)",
                     "OPTIC's better run (summed)", "better"], rows))
