"""The differential tester's blocks and the reference semantics against VAL (issue 42)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401
FUZZ = "fuzz-planner-2000-issue42-2026-12-02"
FUZZ_SEEDS = ["fuzz-planner-seed1-issue42-2026-12-06", "fuzz-planner-seed2-issue42-2026-12-06",
              "fuzz-planner-seed1-issue42-2026-12-07", "fuzz-planner-seed2-issue42-2026-12-07",
              "fuzz-planner-seed1-issue42-final-2026-12-07", "fuzz-planner-seed2-issue42-final-2026-12-07",
              "fuzz-planner-seed3-issue42-final-2026-12-07", "fuzz-planner-seed3-issue42-subepsilon-2026-12-07"]
ORACLE_VAL = "oracle-against-val-300-2026-12-02"


def differential_block(folder=FUZZ):
    """The differential tester's run: each class, with the non-trivial
    tasks, from `report.json` (`alplan fuzz planner --json`), or from the
    printed report of runs made before the JSON existed."""
    path = os.path.join(RESULTS, folder, "report.json")
    if os.path.exists(path):
        return differential_block_json(load(f"{folder}/report.json"))
    with open(os.path.join(RESULTS, folder, "report.txt")) as f:
        text = f.read()
    head = re.search(r"tasks: (\d+) in ([\d.]+) s; (\d+) plans judged", text)
    classes = re.findall(r"^  (\w+): (\d+) \((\d+) non-trivial\)$", text.split("by planted structure")[0], re.M)
    undecided = re.search(r"^undecided: (\d+)", text, re.M)
    non_trivial = re.search(r"^non-trivial: (\d+)", text, re.M)
    tasks = int(head.group(1))
    rows = [[name, count, trivial] for name, count, trivial in classes if name != "undecided"]
    rows.append(["undecided (never agreement)", undecided.group(1), ""])
    disagreements = re.search(r"^disagreements: (\d+)", text, re.M)
    rows.append(["**disagreements**", f"**{disagreements.group(1)}**", ""])
    return (f"{tasks} tasks in {float(head.group(2)):.0f} s, {int(head.group(3)):,} plans judged by the reference "
            f"semantics; non-trivial {non_trivial.group(1)} ({100 * int(non_trivial.group(1)) / tasks:.1f} %), "
            f"undecided {undecided.group(1)} ({100 * int(undecided.group(1)) / tasks:.1f} %).\n\n"
            + table(["class", "tasks", "non-trivial"], rows))


def differential_block_json(report):
    tasks = report["tasks"]
    rows = [[name, str(c["tasks"]), str(c["non_trivial"])] for name, c in sorted(report["classes"].items())
            if name not in ("undecided", "missed_val_order_only", "missed_sub_epsilon_only")]
    rows.append(["undecided (never agreement)", str(report["undecided"]), ""])
    if report["missed_val_order_only"]:
        rows.append(["missed, a plan only by VAL's order of claims (neither)", str(report["missed_val_order_only"]), ""])
    if report.get("missed_sub_epsilon_only"):
        rows.append(["missed, a plan only with interfering happenings closer than epsilon (neither)",
                     str(report["missed_sub_epsilon_only"]), ""])
    rows.append(["**disagreements**", f"**{report['disagreements']}**", ""])
    return (f"{tasks} tasks in {report['seconds']:.0f} s, {report['judgements']:,} plans judged by the reference "
            f"semantics; non-trivial {report['non_trivial']} ({100 * report['non_trivial'] / tasks:.1f} %), "
            f"undecided {report['undecided']} ({100 * report['undecided'] / tasks:.1f} %).\n\n"
            + table(["class", "tasks", "non-trivial"], rows))


def oracle_against_val_block(folder=ORACLE_VAL):
    """The reference semantics against VAL on the tester's tasks and plans."""
    counts = load(f"{folder}/counts.json")
    return table(["plans judged", "agree (valid)", "agree (invalid)", "disagree", "VAL cannot judge",
                  "oracle cannot judge"],
                 [[counts["plans"], counts["agree_valid"], counts["agree_invalid"], counts["disagree"],
                   counts["val_cannot_judge"], counts["oracle_cannot_judge"]]])
