"""The stability study's blocks (bench stability: IPC 2002, issues 32 and 43), the cross-check's among them."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401
STABILITY = ["stability-ipc2002-1-5-2026-11-28", "stability-ipc2002-6-10-2026-11-28",
             "stability-ipc2002-6-10-2026-11-28-first-run"]
# Instances 1-5 at 976ad7b: adapt counting removals, stable cross-checked.
STABILITY_ADAPT_REMOVALS = "stability-ipc2002-1-5-adapt-removals-2026-12-07"
CROSS_CHECK_FIRST = "stability-ipc2002-1-5-cross-check-2026-12-07"
# Instances 6-10 once with adapt counting removals (the test-set ledger's entry 8).
STABILITY_6_10_ADAPT_REMOVALS = "stability-ipc2002-6-10-2026-12-07"


PROOF = "stable-proof-search-1-5-2026-11-28"


def paired_set(runs, strategies):
    valid = Counter()
    for r in runs:
        valid[(r["domain"], r["problem"], r["kind"], r["perturbation"])] += 1 if r["valid"] else 0
    return {k for k, n in valid.items() if n == len(strategies)}


def stability_block(folder):
    data = load(f"{folder}/runs.json")
    runs = data["runs"]
    strategies = strategies_of(runs)
    paired = paired_set(runs, strategies)
    rows = []
    for s in strategies:
        mine = [r for r in runs if r["strategy"] == s]
        on_paired = [r for r in mine if (r["domain"], r["problem"], r["kind"], r["perturbation"]) in paired]
        n = len(on_paired)
        proven = sum("proven minimal by" in r.get("how", "") for r in mine)
        rows.append([
            s, f"{sum(r['valid'] for r in mine)}/{len(mine)}",
            f"{statistics.mean(r['distance'] for r in on_paired):.2f}" if n else "-",
            f"{100.0 * sum(r['same_first'] for r in on_paired) / n:.1f}%" if n else "-",
            f"{statistics.mean(r['makespan'] for r in on_paired):.1f}" if n else "-",
            f"{nearest_rank([r['seconds'] for r in mine], 0.5):.3f}",
            str(proven) if s == "stable" else "-"])
    kinds = Counter(r["kind"] for r in runs if r["strategy"] == strategies[0])
    head = (f"{len(runs) // len(strategies)} perturbations ("
            + ", ".join(f"{n} {k}" for k, n in sorted(kinds.items())) + f"), {len(paired)} repaired validly by every "
            f"strategy, {len(data['skipped'])} draws skipped.")
    return head + "\n\n" + table(["strategy", "valid", "distance (paired)", "same first step", "makespan (paired)",
                                  "median s (all runs)", "proven minimal"], rows)


def prioritized(reference, other, key):
    """+1 where `other` wins, -1 where the reference wins, 0 for a tie: a
    valid repair beats none, then the lower value (stats/prioritized_comparison.h,
    written here on its own)."""
    if reference["valid"] != other["valid"]:
        return 1 if other["valid"] else -1
    if not reference["valid"]:
        return 0
    a, b = reference[key], other[key]
    if abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b)):
        return 0
    return 1 if b < a else -1


def stability_itt_block(folder):
    """Every perturbation, each strategy against replan, success first, then
    the distance and the makespan: wins / ties / losses and the net benefit
    (Buyse 2010); the intervals and tests are in the folder's summary.md."""
    runs = load(f"{folder}/runs.json")["runs"]
    strategies = strategies_of(runs)
    by_key = defaultdict(dict)
    for r in runs:
        by_key[(r["domain"], r["problem"], r["kind"], r["perturbation"])][r["strategy"]] = r
    rows = []
    for s in strategies[1:]:
        for key in ("distance", "makespan"):
            scores = [prioritized(v[strategies[0]], v[s], key) for v in by_key.values() if strategies[0] in v and s in v]
            wins, losses = scores.count(1), scores.count(-1)
            rows.append([s, key, str(len(scores)), f"{wins} / {scores.count(0)} / {losses}",
                         f"{(wins - losses) / len(scores):+.3f}"])
    return table(["strategy", "against replan on", "perturbations", "wins / ties / losses", "net benefit"], rows)


def cross_check_block(folder):
    """stable against the classical compilation's proven minimum
    (`bench stability --cross-check`), per perturbation: counted from
    runs.json, never from summary.md."""
    runs = [r for r in load(f"{folder}/runs.json")["runs"] if r["strategy"] == "stable"]
    counts = Counter()
    different = []
    for r in runs:
        status = r.get("cross_check_status", "")
        stable = r["proven"] and r["valid"]
        if status == "not comparable":
            counts["not comparable"] += 1
        elif status == "proven" and stable:
            same = r["cross_check_distance"] == r["distance"]
            counts["both proven, equal" if same else "both proven, different"] += 1
            if not same:
                different.append(f"{r['domain']} {r['problem']} {r['kind']} {r['perturbation']}")
        elif status == "proven":
            counts["only the classical task proven"] += 1
        elif stable:
            counts["only stable proven"] += 1
        else:
            counts["neither proven"] += 1
    heads = ["both proven, equal", "both proven, different", "only stable proven", "only the classical task proven",
             "neither proven", "not comparable"]
    out = table(["perturbations"] + heads, [[str(len(runs))] + [str(counts[h]) for h in heads]])
    return out + ("\n\nBoth proven, different: " + "; ".join(different) if different else "")


def stability_by_domain(folder):
    runs = load(f"{folder}/runs.json")["runs"]
    strategies = strategies_of(runs)
    paired = paired_set(runs, strategies)
    distance = defaultdict(list)
    for r in runs:
        if (r["domain"], r["problem"], r["kind"], r["perturbation"]) in paired:
            distance[(r["domain"].split("-")[0], r["strategy"])].append(r["distance"])
    domains = sorted({d for d, _ in distance})
    rows = [[d] + [f"{statistics.mean(distance[(d, s)]):.2f}" if distance[(d, s)] else "-" for s in strategies]
            for d in domains]
    return table(["mean distance"] + strategies, rows)


def proof_search_block():
    """stable alone on instances 1-5 under each proof search, the same
    perturbations: what each proves, and how close the plans are."""
    by = {}
    for search in ("blind", "lmcut"):
        by[search] = {(r["domain"], r["problem"], r["kind"], r["perturbation"]): r
                      for r in load(f"{PROOF}/{search}/runs.json")["runs"]}
    both = [k for k in by["blind"] if k in by["lmcut"] and by["blind"][k]["valid"] and by["lmcut"][k]["valid"]]
    rows = []
    for search, label in (("blind", "uniform-cost (blind)"), ("lmcut", "A* (lmcut)")):
        runs = list(by[search].values())
        other = by["lmcut" if search == "blind" else "blind"]
        rows.append([label, f"{sum(r['valid'] for r in runs)}/{len(runs)}",
                     str(sum("proven minimal by" in r["how"] for r in runs)),
                     f"{statistics.mean(by[search][k]['distance'] for k in both):.2f}",
                     str(sum(by[search][k]["distance"] < other[k]["distance"] for k in both)),
                     f"{nearest_rank([r['seconds'] for r in runs], 0.5):.3f}"])
    return (f"{len(by['blind'])} perturbations, {len(both)} repaired validly under both.\n\n"
            + table(["proof search", "valid", "proven minimal", "distance (paired)", "closer than the other",
                     "median s"], rows))
