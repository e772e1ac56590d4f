"""The PDDL 3 suite's non-temporal tracks (bench planners, issue 44)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401


PDDL3_FIRST = "pddl3-60s-first-2026-12-07"


def pddl3_classical_block(folder=PDDL3_FIRST):
    """IPC 2006's simple- and qualitative-preferences tracks in a `bench
    planners` run: coverage and the summed metric per domain (there is no
    reference planner's result for them in ../shared), and VAL's verdicts
    from the folder's val-check.txt (benchmarks/val_check.py)."""
    runs = load(f"{folder}/runs.json")
    runs = runs["runs"] if isinstance(runs, dict) else runs
    with open(os.path.join(RESULTS, folder, "val-check.txt")) as f:
        val = f.read()
    rows = []
    for domain in sorted({r["domain"] for r in runs if r["domain"].startswith("ipc-2006-classical/")}):
        mine = [r for r in runs if r["domain"] == domain]
        solved = [r for r in mine if r["status"] == "solved"]
        accepted = sum(f"{r['problem']}: VAL valid" in val for r in solved)
        instance = os.path.join(HERE, "..", "..", "shared", "benchmarks", mine[0]["problem"])
        with open(instance) as f:
            direction = "maximised" if re.search(r"\(:metric\s+maximize", f.read(), re.I) else "minimised"
        rows.append([domain.split("/", 1)[1], f"{len(solved)}/{len(mine)}", f"{accepted}/{len(solved)}", direction,
                     f"{sum(r['value'] for r in solved):.1f}"])
    return table(["domain", "coverage", "VAL accepts", "metric", "summed metric"], rows)
