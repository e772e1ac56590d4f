#!/usr/bin/python3
"""Coverage per domain of several `alplan bench planners` runs, side by side (issue 29: instances 6-10 beside 1-5).

    benchmarks/coverage_side_by_side.py LABEL=DIR [LABEL=DIR ...]

Each DIR is a run's output folder (its runs.csv). Prints a markdown table with a column per run: solved/tried per
domain, then the totals, the invalid plans (status `invalid`) and the problems that changed status between the
first two runs.
"""
import csv
import os
import sys
from collections import OrderedDict


def runs(folder):
    with open(os.path.join(folder, 'runs.csv')) as f:
        return list(csv.DictReader(f))


def main(args):
    columns = []
    for a in args:
        label, _, folder = a.partition('=')
        if not folder:
            print(__doc__, file=sys.stderr)
            return 2
        columns.append((label, runs(folder)))
    domains = OrderedDict()
    for _, rows in columns:
        for r in rows:
            domains.setdefault(r['domain'], None)
    print('| domain | ' + ' | '.join(label for label, _ in columns) + ' |')
    print('|---|' + '---|' * len(columns))
    totals = [[0, 0, 0] for _ in columns]
    for d in domains:
        cells = []
        for i, (_, rows) in enumerate(columns):
            mine = [r for r in rows if r['domain'] == d]
            solved = sum(r['status'] == 'solved' for r in mine)
            totals[i][0] += solved
            totals[i][1] += len(mine)
            totals[i][2] += sum(r['status'] == 'invalid' for r in mine)
            cells.append(f'{solved}/{len(mine)}' if mine else '-')
        print(f'| {d} | ' + ' | '.join(cells) + ' |')
    print('| **total** | ' + ' | '.join(f'**{s}/{n}**' for s, n, _ in totals) + ' |')
    print('| invalid plans | ' + ' | '.join(str(i) for _, _, i in totals) + ' |')
    if len(columns) >= 2:
        first = {(r['domain'], r['problem']): r['status'] for r in columns[0][1]}
        changed = [(k, first[k], r['status']) for r in columns[1][1]
                   for k in [(r['domain'], r['problem'])] if k in first and first[k] != r['status']]
        print(f'\n{columns[0][0]} -> {columns[1][0]}: {len(changed)} changed status')
        for (d, p), a, b in changed:
            print(f'- {d} {p}: {a} -> {b}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
