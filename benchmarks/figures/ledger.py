"""The test-set ledger's block (benchmarks/test_set_ledger.jsonl, issue 43)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401
LEDGER = os.path.join(HERE, "test_set_ledger.jsonl")


def ledger_result(result):
    """A ledger entry's result in a line: statuses, or per strategy valid
    repairs and mean distance."""
    if result is None:
        return "never finished"
    if "statuses" in result:
        return (f"{result['problems']} problems: "
                + ", ".join(f"{n} {s}" for s, n in result["statuses"].items()) + f"; {result['invalid']} invalid")
    if "strategies" in result:
        return "; ".join(f"{name} {s['valid']}/{s['runs']} valid"
                         + (f" (mean distance of those {s['mean_distance_valid']:.2f})" if "mean_distance_valid" in s else "")
                         for name, s in result["strategies"].items())
    if result and all(isinstance(v, dict) and all(isinstance(c, dict) and "comforted" in c for c in v.values())
                      for v in result.values()):
        # bench repair: per observation model and strategy, runs and comforted runs
        return "; ".join(f"{model}: " + ", ".join(f"{name} {c['comforted']}/{c['runs']}" for name, c in strategies.items())
                         + " comforted" for model, strategies in result.items())
    return ", ".join(f"{k}: {v}" for k, v in result.items())


def test_set_ledger_block():
    """Every run the test-set ledger holds (benchmarks/test_set_ledger.jsonl),
    in order, the ones that never finished and the repeats included."""
    with open(LEDGER) as f:
        lines = [json.loads(line) for line in f if line.strip()]
    started = [l for l in lines if l["status"] == "started"]
    finished = {l["id"]: l for l in lines if l["status"] == "finished"}
    rows = []
    for n, run in enumerate(started, 1):
        end = finished.get(run["id"])
        rows.append([n, run["harness"], run["test_set"], run["commit"][:7], run["reason"],
                     run.get("repeat", "-"), ledger_result(end["result"] if end else None),
                     f"`{os.path.relpath(run['out'], 'benchmarks')}`" if run["out"].startswith("benchmarks/") else f"`{run['out']}`",
                     "yes" if "backfilled" in run else
                     f"its result: {end['after_the_fact']}" if end and "after_the_fact" in end else "-"])
    return (f"{len(started)} runs on test sets, {len(finished)} finished.\n\n"
            + table(["#", "harness", "test set", "commit", "the change it measures", "a repeat: why", "result",
                     "results", "written after the fact"], rows))
