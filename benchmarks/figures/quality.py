"""Plan quality against OPTIC (issue 48): first plans and anytime plans of a
`bench planners` run beside ../shared/benchmarks/baseline/quality_ref.csv,
re-derived from the run's runs.json (each run's plans with their times and
values) and the reference file alone; the IPC quality score computed here on
its own (best known / ours, the metric minimised in every baseline domain),
sharing no code with the harness's quality report. A difference within 0.001
per problem is a tie (one epsilon of a temporal plan)."""
import csv
import os
from collections import defaultdict

from figures.common import HERE, load, table

QUALITY_REF = os.path.join(HERE, "..", "..", "shared", "benchmarks", "baseline", "quality_ref.csv")
OPTIC_POPF = os.path.join(HERE, "..", "..", "shared", "benchmarks", "baseline", "optic_popf_60s.csv")
OPENSTACKS_OPTIC = os.path.join(HERE, "..", "..", "shared", "benchmarks", "baseline", "optic_first_openstacks_2011.csv")
TIE = 0.001

# The runs of issue 48 (results/, each with the command in its README.md).
QUALITY_FIRST_BEFORE = "ipc-first5-60s-66d37ef-2026-12-07"
QUALITY_FIRST = "ipc-first5-60s-issue48-2026-12-07"
QUALITY_ANYTIME = "quality-anytime-issue48-2026-12-07"
OPENSTACKS_FIRST = "openstacks-1-5-first-issue48-2026-12-07"
OPENSTACKS_ANYTIME = "openstacks-1-5-anytime-issue48-2026-12-07"


def reference():
    """quality_ref.csv by problem (ipc/...): OPTIC first, OPTIC anytime, POPF, best; None where empty."""
    out = {}
    with open(QUALITY_REF) as f:
        for row in csv.DictReader(f):
            out[row["problem_file"]] = {k: (float(v) if v else None) for k, v in row.items()
                                        if k not in ("domain_file", "problem_file")}
    return out


def baseline_domains():
    """The 13 domains OPTIC and POPF were run on (optic_popf_60s.csv), as bench planners names them."""
    with open(OPTIC_POPF) as f:
        return {row["domain_file"].split("/", 1)[1].rsplit("/", 1)[0] for row in csv.DictReader(f)}


def runs_of(folder):
    """The runs of a folder in the baseline's 13 domains."""
    runs = load(f"{folder}/runs.json")
    runs = runs["runs"] if isinstance(runs, dict) else runs
    domains = baseline_domains()
    return [r for r in runs if r["domain"] in domains]


def all_runs_of(folder):
    runs = load(f"{folder}/runs.json")
    return runs["runs"] if isinstance(runs, dict) else runs


def values(run):
    """(first, best) values of a solved run from its plans, or (None, None)."""
    if run["status"] != "solved":
        return None, None
    plans = run.get("plans") or [{"value": run["value"]}]
    return plans[0]["value"], min(p["value"] for p in plans)


def best_known(ours, q):
    """The least of our values and quality_ref.csv's for the problem (None when there is none)."""
    known = [v for v in list(ours) + ([q["best"], q["optic_first"], q["optic_anytime_60s"], q["popf"]] if q else [])
             if v is not None]
    return min(known) if known else None


def score(value, best):
    if value is None or best is None:
        return 0.0
    return best / value if value > 0 else 1.0


def first_plans_block(folder=QUALITY_FIRST):
    """Per domain: first plans against OPTIC's first plans where both solve
    (better, equal, worse beyond a tie), and the summed IPC quality score of
    our first plans and of OPTIC's against the best known."""
    ref = reference()
    rows, total = [], defaultdict(float)
    by_domain = defaultdict(list)
    for r in runs_of(folder):
        by_domain[r["domain"]].append(r)
    for domain in sorted(by_domain):
        better = equal = worse = 0
        ours_score = optic_score = 0.0
        for r in by_domain[domain]:
            q = ref.get(r["problem"])
            first, _ = values(r)
            known = best_known([first], q)
            ours_score += score(first, known)
            optic = q["optic_first"] if q else None
            optic_score += score(optic, known)
            if first is None or optic is None:
                continue
            if first < optic - TIE:
                better += 1
            elif first > optic + TIE:
                worse += 1
            else:
                equal += 1
        rows.append([domain, better, equal, worse, f"{ours_score:.2f}", f"{optic_score:.2f}"])
        for k, v in (("better", better), ("equal", equal), ("worse", worse), ("ours", ours_score),
                     ("optic", optic_score)):
            total[k] += v
    both = total["better"] + total["equal"] + total["worse"]
    rows.append(["total", int(total["better"]), int(total["equal"]), int(total["worse"]), f"{total['ours']:.2f}",
                 f"{total['optic']:.2f}"])
    share = (total["better"] + total["equal"]) / both if both else 0.0
    return (table(["domain", "first plan better", "equal", "worse", "quality ours first", "OPTIC first"], rows) +
            f"\n\nBetter or equal to OPTIC's first plan on {int(total['better'] + total['equal'])} of the {int(both)} "
            f"problems both solve ({100 * share:.0f} %).")


def anytime_block(folder=QUALITY_ANYTIME):
    """Per domain: the summed IPC quality score of our first and best plans
    within the limit, OPTIC's first and anytime plans; and our best summed
    against the number of problems with a best known value."""
    ref = reference()
    by_domain = defaultdict(list)
    for r in runs_of(folder):
        by_domain[r["domain"]].append(r)
    rows = []
    totals = [0.0] * 4
    known_total = 0
    for domain in sorted(by_domain):
        sums = [0.0] * 4
        known_here = 0
        for r in by_domain[domain]:
            q = ref.get(r["problem"])
            first, best = values(r)
            known = best_known([first, best], q)
            known_here += known is not None
            for i, v in enumerate((first, best, q["optic_first"] if q else None,
                                   q["optic_anytime_60s"] if q else None)):
                sums[i] += score(v, known)
        rows.append([domain, known_here] + [f"{s:.2f}" for s in sums])
        totals = [a + b for a, b in zip(totals, sums)]
        known_total += known_here
    rows.append(["total", known_total] + [f"{s:.2f}" for s in totals])
    # The best known includes our own plans; against the references' best
    # alone (quality_ref.csv's `best`), a plan better than it scores 1.
    against_ref = referenced = 0
    for runs in by_domain.values():
        for r in runs:
            q = ref.get(r["problem"])
            if q and q["best"] is not None:
                referenced += 1
                against_ref += min(1.0, score(values(r)[1], q["best"]))
    return (table(["domain", "problems with a known value", "ours first", "ours best at 60 s", "OPTIC first",
                   "OPTIC anytime"], rows) +
            f"\n\nOur best plans sum to {totals[1]:.2f} of {known_total} ({100 * totals[1] / known_total:.1f} % of "
            f"the best known per problem, ours included). Against the references' best alone (quality_ref.csv's "
            f"`best`, a plan better than it scoring 1): {against_ref:.2f} of {referenced} "
            f"({100 * against_ref / referenced:.1f} %).")


def openstacks_block(first=OPENSTACKS_FIRST, anytime=OPENSTACKS_ANYTIME):
    """openstacks 2011, instances 1-5: our first and anytime makespans against
    OPTIC's first plans (optic_first_openstacks_2011.csv)."""
    optic = {}
    with open(OPENSTACKS_OPTIC) as f:
        for row in csv.DictReader(f):
            optic[row["problem_file"]] = float(row["optic_first_makespan"])
    firsts = {r["problem"]: r for r in all_runs_of(first)}
    anys = {r["problem"]: r for r in all_runs_of(anytime)}
    rows = []
    for problem in sorted(optic, key=lambda p: int(p.rsplit("-", 1)[1].split(".")[0])):
        f_value = values(firsts[problem])[0] if problem in firsts else None
        a_value = values(anys[problem])[1] if problem in anys else None
        rows.append([os.path.basename(problem), f"{optic[problem]:.3f}",
                     f"{f_value:.3f}" if f_value is not None else "-",
                     f"{f_value / optic[problem]:.2f}" if f_value is not None else "-",
                     f"{a_value:.3f}" if a_value is not None else "-"])
    return table(["problem", "OPTIC first", "ours first", "ours / OPTIC", "ours anytime 60 s"], rows)


def first_plan_changes(a, b):
    """(better, equal, worse): problems both runs solve whose first plan in b
    is better, within a tie, or worse than in a (runs by problem)."""
    better = worse = equal = 0
    for p in a:
        if p in b and a[p]["status"] == b[p]["status"] == "solved":
            d = b[p]["value"] - a[p]["value"]
            better += d < -TIE
            worse += d > TIE
            equal += abs(d) <= TIE
    return better, equal, worse


def suite_pair_block(before=QUALITY_FIRST_BEFORE, after=QUALITY_FIRST):
    """Two runs of the whole suite: coverage, invalid plans, problems whose
    status changed, and first plans better or worse beyond a tie."""
    a = {r["problem"]: r for r in all_runs_of(before)}
    b = {r["problem"]: r for r in all_runs_of(after)}
    changed = sorted(p for p in a if p in b and a[p]["status"] != b[p]["status"])
    better, equal, worse = first_plan_changes(a, b)
    rows = [[before, f"{sum(r['status'] == 'solved' for r in a.values())}/{len(a)}",
             sum(r["status"] == "invalid" for r in a.values())],
            [after, f"{sum(r['status'] == 'solved' for r in b.values())}/{len(b)}",
             sum(r["status"] == "invalid" for r in b.values())]]
    return (table(["run", "coverage", "invalid plans"], rows) +
            f"\n\nStatus changed on {len(changed)} problems{': ' + ', '.join(changed) if changed else ''}. "
            f"Of the problems both solve, the later run's first plan is better on {better}, equal on {equal} "
            f"and worse on {worse}.")


OPENSTACKS_TEST_FIRST = "openstacks-6-10-first-issue48-2026-12-07"
OPENSTACKS_TEST_ANYTIME = "openstacks-6-10-anytime-issue48-2026-12-07"


def openstacks_test_block(first=OPENSTACKS_TEST_FIRST, anytime=OPENSTACKS_TEST_ANYTIME):
    """openstacks 2011, instances 6-10 (the test set, run once): our first
    and anytime makespans; ../shared has no OPTIC run on them."""
    firsts = {r["problem"]: r for r in all_runs_of(first)}
    anys = {r["problem"]: r for r in all_runs_of(anytime)}
    rows = []
    for problem in sorted(firsts, key=lambda p: int(p.rsplit("-", 1)[1].split(".")[0])):
        f_value = values(firsts[problem])[0]
        a_value = values(anys[problem])[1] if problem in anys else None
        rows.append([os.path.basename(problem), firsts[problem]["status"],
                     f"{f_value:.3f}" if f_value is not None else "-",
                     f"{a_value:.3f}" if a_value is not None else "-"])
    return table(["problem", "status", "ours first", "ours anytime 60 s"], rows)


# Ties by makespan (2026-12-08): three variants of the default's fallback
# on instances 1-5, each against the default of issue48 (tuning runs).
TIES_VARIANTS = [("A: every member", "ipc-first5-60s-ties-A-2026-12-08"),
                 ("B: all but the novelty member", "ipc-first5-60s-ties-B-2026-12-08"),
                 ("C: plain GBFS and weighted A* (adopted)", "ipc-first5-60s-ties-C-2026-12-08")]
TIES_ADOPTED = "ipc-first5-60s-ties-C-2026-12-08"
OPENSTACKS_NEIGHBOURHOOD = "openstacks-1-5-anytime-neighbourhood-2026-12-08"


def variants_block(before=QUALITY_FIRST, variants=TIES_VARIANTS):
    """Runs of the whole suite against one before: coverage, problems that
    changed status, and first plans better, equal or worse beyond a tie."""
    a = {r["problem"]: r for r in all_runs_of(before)}
    rows = [[f"before ({before})", f"{sum(r['status'] == 'solved' for r in a.values())}/{len(a)}", "", "", "", "", ""]]
    for name, folder in variants:
        b = {r["problem"]: r for r in all_runs_of(folder)}
        lost = sorted(os.path.basename(os.path.dirname(os.path.dirname(p))).split("-")[0] + " " +
                      os.path.basename(p).split(".")[0].replace("instance-", "")
                      for p in a if p in b and a[p]["status"] == "solved" != b[p]["status"])
        gained = sum(1 for p in a if p in b and b[p]["status"] == "solved" != a[p]["status"])
        better, equal, worse = first_plan_changes(a, b)
        rows.append([name, f"{sum(r['status'] == 'solved' for r in b.values())}/{len(b)}", gained,
                     ", ".join(lost) or "-", better, equal, worse])
    return table(["fallback with ties=makespan in", "coverage", "gained", "lost", "first plan better", "equal",
                  "worse"], rows)


# The test set's coverage check for issue 48 (instances 6-10, whole suite,
# each run once: the planner before the issue and after its changes).
COVERAGE_6_10_BEFORE = "ipc-6-10-60s-before48-66d37ef-2026-12-08"
COVERAGE_6_10_AFTER = "ipc-6-10-60s-after48-42f053b-2026-12-08"
