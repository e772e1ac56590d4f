#!/usr/bin/python3
"""Our anytime plans against OPTIC's anytime plans (issue 15: "with --anytime, IPC quality against
optic_anytime_60s at least OPTIC anytime's own").

    benchmarks/anytime_against_optic.py suite BASELINE > SUITE
        the problems of BASELINE/quality_ref.csv with an optic_anytime_60s value, as a suite list for
        `alplan bench planners --suite SUITE` (paths absolute, read from BASELINE/..)
    benchmarks/anytime_against_optic.py table BASELINE RUNS.csv [OUT.json]
        per domain, the IPC quality score of our best plan and of OPTIC anytime's (60 s) against the better of
        the two (a problem counts 1 for the better plan, best/value for the other, 0 unsolved); a markdown table
        on stdout, the same as JSON in OUT.json.

RUNS.csv is the runs.csv that `alplan bench planners --anytime` writes (its `value` is the best plan's).
"""
import csv
import json
import os
import sys
from collections import defaultdict


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def anytime_rows(baseline):
    rows = []
    with open(os.path.join(baseline, 'quality_ref.csv')) as f:
        for r in csv.DictReader(f):
            if number(r['optic_anytime_60s']) is not None:
                rows.append(r)
    return rows


def key(domain_file, problem_file):
    # ipc/ipc-2004/<domain>/domain.pddl and .../instances/instance-1.pddl -> (ipc-2004/<domain>, instance-1.pddl)
    parts = domain_file.split('/')
    return '/'.join(parts[1:3]), os.path.basename(problem_file)


def print_suite(baseline):
    root = os.path.abspath(os.path.join(baseline, '..'))
    for r in anytime_rows(baseline):
        print(os.path.join(root, r['domain_file']), os.path.join(root, r['problem_file']))


def domain_of(run_domain):
    # runs.csv names a domain by its folder relative to the suite: keep the last two parts.
    return '/'.join(run_domain.rstrip('/').split('/')[-2:])


def table(baseline, runs_csv, out_json=None):
    ours = {}
    with open(runs_csv) as f:
        for r in csv.DictReader(f):
            value = number(r['value']) if r['status'] == 'solved' else None
            ours[(domain_of(r['domain']), r['problem'])] = value
    domains = defaultdict(lambda: {'problems': 0, 'ours': 0.0, 'optic_anytime': 0.0, 'better': 0, 'worse': 0,
                                   'missing': 0})
    for r in anytime_rows(baseline):
        k = key(r['domain_file'], r['problem_file'])
        d = domains[k[0]]
        d['problems'] += 1
        theirs = number(r['optic_anytime_60s'])
        if k not in ours:
            d['missing'] += 1
            d['optic_anytime'] += 1.0
            continue
        mine = ours[k]
        best = min(v for v in (mine, theirs) if v is not None)
        d['optic_anytime'] += best / theirs
        if mine is None:
            continue
        d['ours'] += best / mine
        # Plans print times on a 0.001 grid: closer than that is a tie.
        if mine < theirs - 1e-3:
            d['better'] += 1
        elif mine > theirs + 1e-3:
            d['worse'] += 1
    print('| domain | problems | quality ours | OPTIC anytime | ours better | ours worse |')
    print('|---|---|---|---|---|---|')
    for name in sorted(domains):
        d = domains[name]
        print(f"| {name} | {d['problems']} | {d['ours']:.2f} | {d['optic_anytime']:.2f} | {d['better']} | {d['worse']} |")
    total = {f: sum(d[f] for d in domains.values()) for f in ('problems', 'ours', 'optic_anytime', 'better', 'worse',
                                                                'missing')}
    print(f"| **total** | {total['problems']} | {total['ours']:.2f} | {total['optic_anytime']:.2f} | "
          f"{total['better']} | {total['worse']} |")
    if total['missing']:
        print(f"\n{total['missing']} problems are not in {runs_csv}; they count as unsolved for us.")
    if out_json:
        with open(out_json, 'w') as f:
            json.dump({'domains': domains, 'total': total}, f, indent=2)


def main(argv):
    if len(argv) >= 3 and argv[1] == 'suite':
        print_suite(argv[2])
    elif len(argv) >= 4 and argv[1] == 'table':
        table(argv[2], argv[3], argv[4] if len(argv) > 4 else None)
    else:
        sys.stderr.write(__doc__)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
