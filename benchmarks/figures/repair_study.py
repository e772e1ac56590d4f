"""The repair study's blocks (bench repair: benchmarks/README.md, issues 32 and 43)."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

from figures.common import HERE, RESULTS, load, nearest_rank, table, strategies_of  # noqa: F401
STUDY = "repair-study-40-homes-2026-12-07"
SCATTERED = "repair-study-scatter-2026-12-07"
# The study once on the held-out homes, seeds 1001-1040 (the test-set ledger's entry 6).
HELD_OUT = "repair-study-held-out-homes-1001-1040-2026-12-07"
TAGS = "tags-by-scatter-2026-12-07"
# Folder under TAGS, and the row's label: the scatter, and the repairs'
# search when it is not the study's (anytime down to weight 3).
SCATTERS = [("scatter-0", "0"), ("scatter-0.5", "0.5"), ("scatter-1", "1"),
            ("scatter-1-min-weight-1", "1, repairs to weight 1"),
            ("scatter-1-min-weight-1-adapt-1", "1, repairs and adapt to weight 1")]
MODELS = ["full", "iot", "camera"]


# Strategies the study ran but its tables leave out, each with the block
# that says why (issue 43: switch's outcomes are replan's; study-switch).
OUT_OF_TABLES = frozenset({"switch"})


def tabled(strategies):
    return [s for s in strategies if s not in OUT_OF_TABLES]


def study_mix(folder=STUDY):
    """The failure mix and what each strategy comforted, per model."""
    by_model = {m: load(f"{folder}/{m}/runs.json") for m in MODELS}
    iot = by_model["iot"]
    strategies = tabled(strategies_of(iot))
    mix = Counter(r["kind"] for r in iot if r["strategy"] == strategies[0])
    out = [f"Runs per strategy: {sum(mix.values())} in {len({r['home'] for r in iot})} homes. Failure kinds drawn: "
           + ", ".join(f"{n} {k}" for k, n in sorted(mix.items(), key=lambda kv: (-kv[1], kv[0]))) + ".", ""]
    rows = []
    for s in strategies:
        row = [s]
        for m in MODELS:
            runs = [r for r in by_model[m] if r["strategy"] == s]
            row.append(f"{sum(r['comforted'] for r in runs)}/{len(runs)}")
        latencies = [x for r in iot if r["strategy"] == s for x in r["latency_ms"]]
        row.append(f"{nearest_rank(latencies, 0.5):.1f}" if latencies else "-")
        rows.append(row)
    out.append(table(["strategy"] + [f"comforted, {m}" for m in MODELS] + ["median repair ms (iot)"], rows))
    return "\n".join(out)


KINDS = ["arrival", "iot", "sibling", "moves", "emotion", "overrun", "two", "all"]
WIN_METRICS = [("success", "success"), ("metric", "metric (time + cost)"), ("cost", "cost"), ("delay", "delay"),
               ("stability", "stability"), ("latency_ms", "latency ms")]


def signed(x):
    return f"{x:+.0f}" if abs(x) >= 1000 else f"{x:+.3g}"


def verdict_cell(against, metric, strategies):
    """Better (bold) and worse strategies against replan on one metric, each
    with its mean difference; strategies with the same printed mean share it."""
    parts = []
    for verdict in ("better", "worse"):
        groups = []  # (printed mean, [strategies]) in the order of the strategies
        for s in strategies:
            m = against.get(s, {}).get(metric)
            if not m or m["verdict"] != verdict:
                continue
            mean = signed(m["mean_difference"])
            for g in groups:
                if g[0] == mean:
                    g[1].append(s)
                    break
            else:
                groups.append((mean, [s]))
        if not groups:
            continue
        text = ", ".join(f"{', '.join(names)} ({mean})" for mean, names in groups)
        parts.append(f"**{text}**" if verdict == "better" else f"worse: {text}")
    return "; ".join(parts) if parts else "tie"


def study_wins(folder=STUDY, model="iot"):
    """Where each strategy wins against replan: the verdicts of summary.json
    (cluster interval excluding zero and Holm-adjusted p below 0.05)."""
    summary = load(f"{folder}/{model}/summary.json")
    strategies = [s for s in tabled(strategies_of(load(f"{folder}/{model}/runs.json"))) if s != "replan"]
    rows = []
    for kind in KINDS:
        against = summary["kinds"].get(kind, {}).get("against_replan")
        if against is None:
            continue
        rows.append([kind] + [verdict_cell(against, m, strategies) for m, _ in WIN_METRICS])
    return table(["failure kind"] + [label for _, label in WIN_METRICS], rows)


def same_outcome(a, b):
    """Two runs of one failure end alike: comforted or not, and the same
    delay and cost (within rounding)."""
    if a["comforted"] != b["comforted"]:
        return False
    close = lambda x, y: (x is None and y is None) or (x is not None and y is not None and abs(x - y) <= 1e-6 * max(1, abs(x), abs(y)))
    return close(a.get("delay"), b.get("delay")) and close(a.get("cost"), b.get("cost"))


def study_switch(model="iot"):
    """Why switch is out of the study's tables: per failure kind, how often
    it took an alternative, how often its run ended as replan's did, and its
    net benefit on the metric against replan (every run counted), from
    summary.json."""
    runs = load(f"{STUDY}/{model}/runs.json")
    summary = load(f"{STUDY}/{model}/summary.json")
    replan = {(r["home"], r["run"]): r for r in runs if r["strategy"] == "replan"}
    mine = [r for r in runs if r["strategy"] == "switch"]
    rows = []
    for kind in [k for k in KINDS if k != "all"] + ["all"]:
        of_kind = [r for r in mine if kind == "all" or r["kind"] == kind]
        if not of_kind:
            continue
        repairs = sum(r["repairs"] for r in of_kind)
        fallbacks = sum(r.get("fallbacks", 0) for r in of_kind)
        same = sum(same_outcome(r, replan[(r["home"], r["run"])]) for r in of_kind)
        m = summary["kinds"][kind]["against_replan"]["switch"]["metric"]
        rows.append([kind, len(of_kind), repairs - fallbacks, f"{same} of {len(of_kind)}",
                     f"{m['mean_difference']:+.3f} [{m['ci_low']:+.3f}, {m['ci_high']:+.3f}]",
                     f"{m['wilcoxon_p_holm']:.2g}", m["verdict"]])
    return table(["failure kind", "runs", "repairs that switched to an alternative", "ended as replan's run",
                  "metric: net benefit against replan [95% CI]", "Holm p", "verdict"], rows)


def tags_by_scatter():
    """What the tags are worth on iot failures: the same runs under iot and
    camera, in homes whose objects are scattered over rooms or not."""
    rows = []
    for folder, scatter in SCATTERS:
        runs = {m: {(r["home"], r["run"], r["strategy"]): r for r in load(f"{TAGS}/{folder}/{m}/runs.json")
                    if r["kind"] == "iot"} for m in ("iot", "camera")}
        for s in tabled(("replan", "adapt", "switch")):
            both = [(runs["iot"][k], runs["camera"][k]) for k in runs["iot"]
                    if k[2] == s and k in runs["camera"] and runs["iot"][k]["comforted"] and runs["camera"][k]["comforted"]]
            d = [a["delay"] - b["delay"] for a, b in both]
            homes = len({a["home"] for a, _ in both})
            rows.append([scatter, s, f"{len(both)} in {homes} homes",
                         f"{statistics.mean(a['delay'] for a, _ in both):.1f}",
                         f"{statistics.mean(b['delay'] for _, b in both):.1f}", f"{statistics.mean(d):.1f}",
                         f"{sum(x < -1e-6 for x in d)} / {sum(abs(x) <= 1e-6 for x in d)} / {sum(x > 1e-6 for x in d)}"])
    return table(["scatter", "strategy", "iot failures, comforted under both", "delay, iot", "delay, camera",
                  "iot minus camera", "tags sooner / same / later"], rows)


def camera_search(folder=STUDY):
    """The seniors who moved: comforted under iot and under camera, and the
    places the camera-only robot looked in to find them (person_search.h)."""
    by_model = {m: load(f"{folder}/{m}/runs.json") for m in MODELS}
    steps_elsewhere = sum(r.get("search_steps", 0) for m in ("full", "iot") for r in by_model[m])
    runs_elsewhere = sum(len(by_model[m]) for m in ("full", "iot"))
    rows = []
    for s in tabled(strategies_of(by_model["iot"])):
        iot = [r for r in by_model["iot"] if r["strategy"] == s and r["kind"] == "moves"]
        camera = [r for r in by_model["camera"] if r["strategy"] == s and r["kind"] == "moves"]
        found = [r["search_steps"] for r in camera if r["comforted"]]
        rows.append([s, f"{sum(r['comforted'] for r in iot)}/{len(iot)}", f"{len(found)}/{len(camera)}",
                     f"{statistics.mean(found):.1f}" if found else "-", str(max(found)) if found else "-"])
    return (f"Search steps under full and iot: {steps_elsewhere} in {runs_elsewhere} runs.\n\n"
            + table(["strategy", "moves comforted, iot", "moves comforted, camera",
                     "places looked in (comforted, camera)", "most"], rows))
