#!/usr/bin/python3
"""Our first plans against OPTIC's first plans (issue 29: "better or equal on at least two thirds of the
problems both solve").

    benchmarks/first_plans_against_optic.py BASELINE RUNS.csv [OUT.json]

BASELINE/quality_ref.csv gives OPTIC's first plan's value (optic_first) for each baseline problem; RUNS.csv is
the runs.csv of `alplan bench planners` without --anytime (its `value` is the first plan's metric, makespan
where the problem has no metric). A problem counts where both solved it: better, equal or worse by the metric
(lower is better), equal within 0.0005 (half the plans' printed precision of 0.001: one epsilon more is worse)
or 1e-6 of the value, whichever is larger.
Prints a markdown table per domain and the totals; the same as JSON in OUT.json.
"""
import csv
import json
import os
import sys
from collections import defaultdict

from anytime_against_optic import domain_of, key, number  # the same files, read the same way


def compare(ours, optic):
    tolerance = max(5e-4, 1e-6 * abs(optic))
    if abs(ours - optic) <= tolerance:
        return 'equal'
    return 'better' if ours < optic else 'worse'


def main(baseline, runs_csv, out_json=None):
    ours = {}
    with open(runs_csv) as f:
        for r in csv.DictReader(f):
            if r['status'] == 'solved':
                ours[(domain_of(r['domain']), r['problem'])] = number(r['value'])
    per_domain = defaultdict(lambda: defaultdict(int))
    problems = []
    with open(os.path.join(baseline, 'quality_ref.csv')) as f:
        for r in csv.DictReader(f):
            k = key(r['domain_file'], r['problem_file'])
            optic = number(r['optic_first'])
            mine = ours.get(k)
            if optic is None or mine is None:
                per_domain[k[0]]['not both'] += 1
                continue
            verdict = compare(mine, optic)
            per_domain[k[0]][verdict] += 1
            problems.append({'domain': k[0], 'problem': k[1], 'ours': mine, 'optic_first': optic,
                             'verdict': verdict})
    totals = defaultdict(int)
    print('| domain | better | equal | worse | not both solved |')
    print('|---|---|---|---|---|')
    for domain in sorted(per_domain):
        c = per_domain[domain]
        for v in ('better', 'equal', 'worse', 'not both'):
            totals[v] += c[v]
        print(f"| {domain} | {c['better']} | {c['equal']} | {c['worse']} | {c['not both']} |")
    both = totals['better'] + totals['equal'] + totals['worse']
    at_least = totals['better'] + totals['equal']
    print(f"| **all** | {totals['better']} | {totals['equal']} | {totals['worse']} | {totals['not both']} |")
    share = at_least / both if both else 0.0
    print(f"\nbetter or equal on {at_least} of {both} problems both solved ({share:.1%})")
    if out_json:
        with open(out_json, 'w') as f:
            json.dump({'totals': dict(totals), 'both_solved': both, 'better_or_equal': at_least,
                       'problems': problems}, f, indent=1)
    return 0


if __name__ == '__main__':
    if len(sys.argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
