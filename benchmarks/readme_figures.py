#!/usr/bin/env python3
"""Re-derives the repair figures of benchmarks/README.md from the committed
runs (issue 32), and the differential tester's (issue 42): the README's
figures must match their files.

Each block of figures in the README stands between
    <!-- figures:NAME -->  and  <!-- /figures:NAME -->
and is exactly what this script prints for NAME, computed from the runs.json
files under benchmarks/results/ alone (the differential blocks: a run's
report.txt and counts.json) (not from summary.md, which the same
program wrote with the numbers). Usage:

    benchmarks/readme_figures.py             print every block
    benchmarks/readme_figures.py NAME        print one
    benchmarks/readme_figures.py --check     exit 1 naming each block of the
                                             README that differs (a test runs it)
    benchmarks/readme_figures.py --write     rewrite the README's blocks
"""
import json
import os
import re
import statistics
import sys
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
README = os.path.join(HERE, "README.md")
STUDY = "repair-study-40-homes-2026-11-28"
SCATTERED = "repair-study-scatter-2026-11-28"
TAGS = "tags-by-scatter-2026-11-28"
# Folder under TAGS, and the row's label: the scatter, and the repairs'
# search when it is not the study's (anytime down to weight 3).
SCATTERS = [("scatter-0", "0"), ("scatter-0.5", "0.5"), ("scatter-1", "1"),
            ("scatter-1-min-weight-1", "1, repairs to weight 1"),
            ("scatter-1-min-weight-1-adapt-1", "1, repairs and adapt to weight 1")]
STABILITY = ["stability-ipc2002-1-5-2026-11-28", "stability-ipc2002-6-10-2026-11-28"]
MODELS = ["full", "iot", "camera"]
FUZZ = "fuzz-planner-2000-issue42-2026-12-02"
FUZZ_SEEDS = ["fuzz-planner-seed1-issue42-2026-12-06", "fuzz-planner-seed2-issue42-2026-12-06",
              "fuzz-planner-seed1-issue42-2026-12-07", "fuzz-planner-seed2-issue42-2026-12-07"]
ORACLE_VAL = "oracle-against-val-300-2026-12-02"


def load(path):
    with open(os.path.join(RESULTS, path)) as f:
        return json.load(f)


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


def study_mix(folder=STUDY):
    """The failure mix and what each strategy comforted, per model."""
    by_model = {m: load(f"{folder}/{m}/runs.json") for m in MODELS}
    iot = by_model["iot"]
    strategies = strategies_of(iot)
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
        row.append(f"{statistics.median(latencies):.1f}" if latencies else "-")
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
    strategies = [s for s in strategies_of(load(f"{folder}/{model}/runs.json")) if s != "replan"]
    rows = []
    for kind in KINDS:
        against = summary["kinds"].get(kind, {}).get("against_replan")
        if against is None:
            continue
        rows.append([kind] + [verdict_cell(against, m, strategies) for m, _ in WIN_METRICS])
    return table(["failure kind"] + [label for _, label in WIN_METRICS], rows)


def study_switch():
    """How often switch took one of its alternatives instead of replanning."""
    runs = [r for r in load(f"{STUDY}/iot/runs.json") if r["strategy"] == "switch"]
    rows = []
    for kind in sorted({r["kind"] for r in runs}):
        mine = [r for r in runs if r["kind"] == kind]
        repairs = sum(r["repairs"] for r in mine)
        fallbacks = sum(r.get("fallbacks", 0) for r in mine)
        rows.append([kind, repairs, repairs - fallbacks, fallbacks,
                     f"{statistics.mean(r['planner_calls'] for r in mine):.2f}"])
    return table(["failure kind", "repairs", "switched to an alternative", "replanned", "planner calls a run"], rows)


def tags_by_scatter():
    """What the tags are worth on iot failures: the same runs under iot and
    camera, in homes whose objects are scattered over rooms or not."""
    rows = []
    for folder, scatter in SCATTERS:
        runs = {m: {(r["home"], r["run"], r["strategy"]): r for r in load(f"{TAGS}/{folder}/{m}/runs.json")
                    if r["kind"] == "iot"} for m in ("iot", "camera")}
        for s in ("replan", "adapt", "switch"):
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
            f"{statistics.median(r['seconds'] for r in mine):.3f}",
            str(proven) if s == "stable" else "-"])
    kinds = Counter(r["kind"] for r in runs if r["strategy"] == strategies[0])
    head = (f"{len(runs) // len(strategies)} perturbations ("
            + ", ".join(f"{n} {k}" for k, n in sorted(kinds.items())) + f"), {len(paired)} repaired validly by every "
            f"strategy, {len(data['skipped'])} draws skipped.")
    return head + "\n\n" + table(["strategy", "valid", "distance (paired)", "same first step", "makespan (paired)",
                                  "median s (all runs)", "proven minimal"], rows)


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
    for s in strategies_of(by_model["iot"]):
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
                     f"{statistics.median(r['seconds'] for r in runs):.3f}"])
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
            if name not in ("undecided", "missed_val_order_only")]
    rows.append(["undecided (never agreement)", str(report["undecided"]), ""])
    if report["missed_val_order_only"]:
        rows.append(["missed, a plan only by VAL's order of claims (neither)", str(report["missed_val_order_only"]), ""])
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


BLOCKS = {
    "differential": differential_block,
    "differential-seed1": lambda: differential_block(FUZZ_SEEDS[0]),
    "differential-seed2": lambda: differential_block(FUZZ_SEEDS[1]),
    "differential-seed1-happenings": lambda: differential_block(FUZZ_SEEDS[2]),
    "differential-seed2-happenings": lambda: differential_block(FUZZ_SEEDS[3]),
    "oracle-against-val": oracle_against_val_block,
    "study-mix": study_mix,
    "study-switch": study_switch,
    "study-wins": study_wins,
    "scatter-mix": lambda: study_mix(SCATTERED),
    "tags-by-scatter": tags_by_scatter,
    "stability-1-5": lambda: stability_block(STABILITY[0]),
    "stability-6-10": lambda: stability_block(STABILITY[1]),
    "stability-domains-1-5": lambda: stability_by_domain(STABILITY[0]),
    "stable-proof-search": proof_search_block,
    "camera-search": camera_search,
}


def readme_blocks(text):
    return {m.group(1): m.group(2).strip("\n")
            for m in re.finditer(r"<!-- figures:([\w-]+) -->\n(.*?)<!-- /figures:\1 -->", text, re.S)}


def main(argv):
    if len(argv) > 1 and argv[1] in ("--check", "--write"):
        with open(README) as f:
            text = f.read()
        found = readme_blocks(text)
        if argv[1] == "--write":
            for name, make in BLOCKS.items():
                text = re.sub(rf"(<!-- figures:{name} -->\n).*?(<!-- /figures:{name} -->)",
                              lambda m: m.group(1) + make() + "\n" + m.group(2), text, flags=re.S)
            with open(README, "w") as f:
                f.write(text)
            return 0
        bad = [n for n, make in BLOCKS.items() if found.get(n) != make()]
        for n in bad:
            print(f"README.md: the figures of block '{n}' differ from what {os.path.basename(__file__)} derives "
                  f"from the results" if n in found else f"README.md: no block '{n}'", file=sys.stderr)
        return 1 if bad else 0
    names = argv[1:] or list(BLOCKS)
    for name in names:
        if name not in BLOCKS:
            print(f"unknown block '{name}'; blocks: {', '.join(BLOCKS)}", file=sys.stderr)
            return 2
        print(f"<!-- figures:{name} -->\n{BLOCKS[name]()}\n<!-- /figures:{name} -->\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
