"""The fleet study's block of home/README.md (benchmarks/home_fleet.sh, issues 31 and 43)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401
FLEET = "home-fleet-40-seniors-8h-2026-12-07"
FLEET_RUNS = ["dispatch-hard", "allocate-hard", "allocate-soft"]
FAILED_CALLS = ("none", "merge_failed", "repair_failed")


def fleet_row_cells(r):
    """One bench-home.json's cells: outcomes, and planning latency as nearest
    ranks over every call, failed ones included (computed here from the
    calls' seconds, not taken from the file's own quantiles)."""
    s = r["summary"]
    by_reason = r["planning_seconds_by_reason"]
    every = [x for seconds in by_reason.values() for x in seconds]
    failed = [x for reason in FAILED_CALLS for x in by_reason.get(reason, [])]
    replanning = [x for reason in ("merge", "repair", "merge_failed", "repair_failed") for x in by_reason.get(reason, [])]
    def q(values, share):
        v = nearest_rank(values, share)
        return "-" if v is None else f"{v:.3f}"
    return [str(s["robots_down"]), str(s["goals"]),
            f"{s['within_window']} ({100 * r['comforted_within_window_share']:.1f}%)",
            f"{round(r['meetable_within_window_share'] * r['meetable_goals'])} of {r['meetable_goals']}",
            str(r["never_served"]), str(r["in_course_at_end"]), f"{r['weighted_lateness_s']:.0f}",
            f"{100 * r['robot_utilisation']:.1f}%",
            f"{len(every)}: {q(every, 0.5)} / {q(every, 0.95)} / {q(every, 1.0)}",
            f"{len(failed)}", q(replanning, 0.95)]


def home_fleet_block(folder=FLEET, root=RESULTS):
    """The fleet study (benchmarks/home_fleet.sh): every run, then what
    breakdowns cost, paired by seed and setting."""
    if not os.path.isdir(os.path.join(root, folder)):
        raise FileNotFoundError(f"no fleet study in {os.path.join(root, folder)}")
    def read(run, seed):
        path = os.path.join(root, folder, run, f"seed-{seed}", "bench-home.json")
        if not os.path.exists(path):
            return None
        with open(path) as f:
            return json.load(f)
    rows, cost = [], []
    for seed in (1, 2, 3):
        for run in FLEET_RUNS:
            for variant in ("", "-breakdowns"):
                r = read(run + variant, seed)
                if r is not None:
                    rows.append([str(seed), run + variant] + fleet_row_cells(r))
    for run in FLEET_RUNS:
        pairs = [(read(run, seed), read(run + "-breakdowns", seed)) for seed in (1, 2, 3)]
        pairs = [(a, b) for a, b in pairs if a is not None and b is not None]
        if not pairs:
            continue
        within = [100 * (b["comforted_within_window_share"] - a["comforted_within_window_share"]) for a, b in pairs]
        lateness = [b["weighted_lateness_s"] - a["weighted_lateness_s"] for a, b in pairs]
        dropped = [b["never_served"] - a["never_served"] for a, b in pairs]
        downs = [b["summary"]["robots_down"] for a, b in pairs]
        cost.append([run, str(len(pairs)), " / ".join(str(d) for d in downs),
                     " / ".join(f"{x:+.1f}" for x in within) + f" (mean {sum(within) / len(within):+.1f})",
                     " / ".join(f"{x:+.0f}" for x in lateness), " / ".join(f"{x:+d}" for x in dropped)])
    head = ["seed", "run", "breakdowns", "goals", "within window", "meetable alone: within", "never served",
            "in course at end", "weighted lateness s", "robots at work",
            "planner calls: p50 / p95 / max s, every call", "calls that found no plan", "replanning p95 s"]
    return (table(head, rows) + "\n\nWhat breakdowns cost (with minus without, the same seed and setting; seeds 1 / 2 / 3):\n\n"
            + table(["setting", "seeds", "breakdowns", "within window, points", "weighted lateness s",
                     "never served"], cost))
