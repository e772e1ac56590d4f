"""Helpers every block shares: where the results are, reading them, nearest ranks (stats/quantile.h's
definition, computed here on their own) and Markdown tables."""
import json
import math
import os
import re
import statistics
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(HERE, "results")


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
