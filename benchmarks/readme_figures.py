#!/usr/bin/env python3
"""Re-derives the repair figures of benchmarks/README.md from the committed
runs (issue 32), the differential tester's (issue 42), the test-set ledger
and the fleet study of home/README.md (issue 43): the READMEs' figures must
match their files. Quantiles are nearest ranks, computed here on their own
(nearest_rank, the definition of stats/quantile.h).

Each block of figures in the README stands between
    <!-- figures:NAME -->  and  <!-- /figures:NAME -->
and is exactly what this script prints for NAME, computed from the runs.json
files under benchmarks/results/ alone (the differential blocks: a run's
report.txt and counts.json) (not from summary.md, which the same
program wrote with the numbers). Two blocks are not re-derived: study-wins
and study-switch read the verdicts, intervals and Holm p-values of the
study's summary.json, which alplan wrote (the bootstrap and the tests are
stats/'s, tested there); they check that the README shows what the
committed summary says, not the statistics themselves. Usage:

    benchmarks/readme_figures.py             print every block
    benchmarks/readme_figures.py NAME        print one
    benchmarks/readme_figures.py --check     exit 1 naming each block of the
                                             READMEs that differs (a test runs it)
    benchmarks/readme_figures.py --write     rewrite the READMEs' blocks
    benchmarks/readme_figures.py --home-fleet DIR   the fleet table of a
                                             benchmarks/home_fleet.sh run
"""
import json
import math
import os
import re
import statistics
import sys
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
README = os.path.join(HERE, "README.md")
HOME_README = os.path.join(HERE, "..", "home", "README.md")
FLEET = "home-fleet-40-seniors-8h-2026-12-07"
FLEET_RUNS = ["dispatch-hard", "allocate-hard", "allocate-soft"]
FAILED_CALLS = ("none", "merge_failed", "repair_failed")
STUDY = "repair-study-40-homes-2026-11-28"
SCATTERED = "repair-study-scatter-2026-11-28"
TAGS = "tags-by-scatter-2026-11-28"
# Folder under TAGS, and the row's label: the scatter, and the repairs'
# search when it is not the study's (anytime down to weight 3).
SCATTERS = [("scatter-0", "0"), ("scatter-0.5", "0.5"), ("scatter-1", "1"),
            ("scatter-1-min-weight-1", "1, repairs to weight 1"),
            ("scatter-1-min-weight-1-adapt-1", "1, repairs and adapt to weight 1")]
STABILITY = ["stability-ipc2002-1-5-2026-11-28", "stability-ipc2002-6-10-2026-11-28",
             "stability-ipc2002-6-10-2026-11-28-first-run"]
LEDGER = os.path.join(HERE, "test_set_ledger.jsonl")
MODELS = ["full", "iot", "camera"]
FUZZ = "fuzz-planner-2000-issue42-2026-12-02"
FUZZ_SEEDS = ["fuzz-planner-seed1-issue42-2026-12-06", "fuzz-planner-seed2-issue42-2026-12-06",
              "fuzz-planner-seed1-issue42-2026-12-07", "fuzz-planner-seed2-issue42-2026-12-07",
              "fuzz-planner-seed1-issue42-final-2026-12-07", "fuzz-planner-seed2-issue42-final-2026-12-07",
              "fuzz-planner-seed3-issue42-final-2026-12-07", "fuzz-planner-seed3-issue42-subepsilon-2026-12-07"]
ORACLE_VAL = "oracle-against-val-300-2026-12-02"
# Instances 1-5 at 976ad7b: adapt counting removals, stable cross-checked.
STABILITY_ADAPT_REMOVALS = "stability-ipc2002-1-5-adapt-removals-2026-12-07"
CROSS_CHECK_FIRST = "stability-ipc2002-1-5-cross-check-2026-12-07"


def load(path):
    with open(os.path.join(RESULTS, path)) as f:
        return json.load(f)


def nearest_rank(values, q):
    """The value at rank ceil(q n) of the sorted values (Hyndman & Fan's
    definition 1), as stats/quantile.h defines it for the C++ studies; a
    share within 1e-9 of a whole rank is that rank. Written here on its own:
    this script checks figures the C++ side printed and shares no code with
    it. None for no values."""
    if not values:
        return None
    ordered = sorted(values)
    position = q * len(ordered)
    rank = round(position) if abs(position - round(position)) <= 1e-9 else math.ceil(position)
    return ordered[min(max(rank, 1), len(ordered)) - 1]


def check_nearest_rank():
    """Hand-computed ranks, the same cases as tests/stats/quantile_test.cpp."""
    twenty = list(range(20, 0, -1))
    assert nearest_rank(twenty, 0.95) == 19 and nearest_rank(twenty, 0.5) == 10
    assert nearest_rank(twenty, 1.0) == 20 and nearest_rank(twenty, 0.0) == 1 and nearest_rank(twenty, 0.96) == 20
    assert nearest_rank([0.05] * 11 + [0.9], 0.95) == 0.9
    assert nearest_rank(list(range(1, 101)), 0.07) == 7 and nearest_rank(list(range(1, 101)), 0.29) == 29
    assert nearest_rank([3.0, 1.0, 2.0, 2.0], 0.76) == 3.0 and nearest_rank([], 0.5) is None


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def strategies_of(runs):
    seen = []
    for r in runs:
        if r["strategy"] not in seen:
            seen.append(r["strategy"])
    return seen


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


PROOF = "stable-proof-search-1-5-2026-11-28"


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


def ledger_result(result):
    """A ledger entry's result in a line: statuses, or per strategy valid
    repairs and mean distance."""
    if result is None:
        return "never finished"
    if "statuses" in result:
        return (f"{result['problems']} problems: "
                + ", ".join(f"{n} {s}" for s, n in result["statuses"].items()) + f"; {result['invalid']} invalid")
    if "strategies" in result:
        return "; ".join(f"{name} {s['valid']}/{s['runs']} valid (mean distance of those {s['mean_distance_valid']:.2f})"
                         for name, s in result["strategies"].items())
    return ", ".join(f"{k}: {v}" for k, v in result.items())


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
                     "yes" if "backfilled" in run else "-"])
    return (f"{len(started)} runs on test sets, {len(finished)} finished.\n\n"
            + table(["#", "harness", "test set", "commit", "the change it measures", "a repeat: why", "result",
                     "results", "written after the fact"], rows))


BLOCKS = {
    "differential": differential_block,
    "differential-seed1": lambda: differential_block(FUZZ_SEEDS[0]),
    "differential-seed2": lambda: differential_block(FUZZ_SEEDS[1]),
    "differential-seed1-happenings": lambda: differential_block(FUZZ_SEEDS[2]),
    "differential-seed2-happenings": lambda: differential_block(FUZZ_SEEDS[3]),
    "differential-seed1-final": lambda: differential_block(FUZZ_SEEDS[4]),
    "differential-seed2-final": lambda: differential_block(FUZZ_SEEDS[5]),
    "differential-seed3-final": lambda: differential_block(FUZZ_SEEDS[6]),
    "differential-seed3-subepsilon": lambda: differential_block(FUZZ_SEEDS[7]),
    "oracle-against-val": oracle_against_val_block,
    "study-mix": study_mix,
    "study-switch": study_switch,
    "study-wins": study_wins,
    "scatter-mix": lambda: study_mix(SCATTERED),
    "tags-by-scatter": tags_by_scatter,
    "stability-1-5": lambda: stability_block(STABILITY[0]),
    "stability-6-10": lambda: stability_block(STABILITY[1]),
    "stability-6-10-first-run": lambda: stability_block(STABILITY[2]),
    "stability-itt-1-5": lambda: stability_itt_block(STABILITY[0]),
    "stability-itt-6-10-first-run": lambda: stability_itt_block(STABILITY[2]),
    "stability-itt-6-10": lambda: stability_itt_block(STABILITY[1]),
    "stability-itt-adapt-removals": lambda: stability_itt_block(STABILITY_ADAPT_REMOVALS),
    "stable-cross-check-first": lambda: cross_check_block(CROSS_CHECK_FIRST),
    "stable-cross-check": lambda: cross_check_block(STABILITY_ADAPT_REMOVALS),
    "pddl3-classical": pddl3_classical_block,
    "test-set-ledger": test_set_ledger_block,
    "stability-domains-1-5": lambda: stability_by_domain(STABILITY[0]),
    "stable-proof-search": proof_search_block,
    "camera-search": camera_search,
}

# The blocks of home/README.md.
HOME_BLOCKS = {
    "home-fleet": home_fleet_block,
}
READMES = [(README, BLOCKS), (HOME_README, HOME_BLOCKS)]


def readme_blocks(text):
    return {m.group(1): m.group(2).strip("\n")
            for m in re.finditer(r"<!-- figures:([\w-]+) -->\n(.*?)<!-- /figures:\1 -->", text, re.S)}


def main(argv):
    check_nearest_rank()
    if len(argv) > 2 and argv[1] == "--home-fleet":
        print(home_fleet_block(os.path.basename(os.path.normpath(argv[2])), os.path.dirname(os.path.abspath(argv[2]))))
        return 0
    if len(argv) > 1 and argv[1] in ("--check", "--write"):
        bad = []
        for readme, blocks in READMES:
            with open(readme) as f:
                text = f.read()
            found = readme_blocks(text)
            if argv[1] == "--write":
                for name, make in blocks.items():
                    text = re.sub(rf"(<!-- figures:{name} -->\n).*?(<!-- /figures:{name} -->)",
                                  lambda m: m.group(1) + make() + "\n" + m.group(2), text, flags=re.S)
                with open(readme, "w") as f:
                    f.write(text)
                continue
            shown = os.path.relpath(readme, os.path.join(HERE, ".."))
            for n, make in blocks.items():
                if found.get(n) != make():
                    bad.append(n)
                    print(f"{shown}: the figures of block '{n}' differ from what {os.path.basename(__file__)} derives "
                          f"from the results" if n in found else f"{shown}: no block '{n}'", file=sys.stderr)
        return 1 if bad else 0
    every = {**BLOCKS, **HOME_BLOCKS}
    names = argv[1:] or list(every)
    for name in names:
        if name not in every:
            print(f"unknown block '{name}'; blocks: {', '.join(every)}", file=sys.stderr)
            return 2
        print(f"<!-- figures:{name} -->\n{every[name]()}\n<!-- /figures:{name} -->\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
