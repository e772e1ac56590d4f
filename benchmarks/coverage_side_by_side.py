#!/usr/bin/python3
"""Coverage per domain of several `alplan bench planners` runs, side by side (issue 29: instances 6-10 beside 1-5).

    benchmarks/coverage_side_by_side.py LABEL=DIR [LABEL=DIR ...]

Each DIR is a run's output folder (its runs.csv). Prints a markdown table with a column per run: solved/tried per
domain, then the totals, the invalid plans (status `invalid`) and the problems that changed status between the
runs next to each other that share problems, with how many first plans got better or worse.
"""
import csv
import os
import sys
from collections import OrderedDict


def runs(folder):
    with open(os.path.join(folder, 'runs.csv')) as f:
        return list(csv.DictReader(f))


def compare(label_a, rows_a, label_b, rows_b):
    """Two runs of the same problems: what changed status, and whether the first plans of the problems both
    solved got better or worse (lower value is better; within 0.0005, half the printed precision, equal)."""
    first = {(r['domain'], r['problem']): r for r in rows_a}
    common = [(first[k], r) for r in rows_b for k in [(r['domain'], r['problem'])] if k in first]
    if not common:
        return
    changed = [(a, b) for a, b in common if a['status'] != b['status']]
    both = [(float(a['value']), float(b['value'])) for a, b in common
            if a['status'] == 'solved' and b['status'] == 'solved']
    better = sum(y < x - 5e-4 for x, y in both)
    worse = sum(y > x + 5e-4 for x, y in both)
    print(f'\n{label_a} -> {label_b}: {len(changed)} changed status; of the {len(both)} both solve, '
          f'{better} first plans better, {worse} worse')
    for a, b in changed:
        print(f"- {b['domain']} {b['problem']}: {a['status']} -> {b['status']}")


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
    for (label_a, a), (label_b, b) in zip(columns, columns[1:]):
        compare(label_a, a, label_b, b)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
