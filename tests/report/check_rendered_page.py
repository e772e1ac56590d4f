#!/usr/bin/python3
"""Checks that the charts of a rendered report page were drawn.

Reads the DOM Chromium dumped after running the page's scripts and, for each
chart given, counts the marks vega drew inside its div: the children of each
`<g class="mark-TYPE role-mark ...">` group (a bar is a path in a mark-rect
group, a point a path in a mark-symbol group, a rule a line in a mark-rule
group). Axes and legends have other roles and do not count.

Usage: check_rendered_page.py DOM CHART=TYPE:MIN[,TYPE:MIN...] ...
  e.g. gantt=rect:10,rule:1  -- #gantt holds an svg with at least 10 bars
Exit 0 when every chart has its marks; 1 with what is missing otherwise.
"""
import collections
import sys
from html.parser import HTMLParser

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


class ChartMarks(HTMLParser):
    """Per chart div: svg count, marks drawn per type, errors shown."""

    def __init__(self, charts):
        super().__init__()
        self.charts = set(charts)
        self.stack = []  # (tag, chart id or None, mark type or None)
        self.svgs = collections.Counter()
        self.marks = collections.defaultdict(collections.Counter)
        self.errors = collections.defaultdict(str)
        self.in_error = None

    def chart(self):
        for _, chart, _ in reversed(self.stack):
            if chart:
                return chart
        return None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        chart = a.get("id") if tag == "div" and a.get("id") in self.charts else None
        inside = chart or self.chart()
        parent_mark = self.stack[-1][2] if self.stack else None
        if inside and parent_mark:
            self.marks[inside][parent_mark] += 1
        classes = (a.get("class") or "").split()
        mark = None
        if tag == "g" and "role-mark" in classes:
            mark = next((c[len("mark-"):] for c in classes if c.startswith("mark-")), "unknown")
        if inside and tag in ("svg", "canvas"):
            self.svgs[inside] += 1
        if inside and tag == "p" and "error" in classes:
            self.in_error = inside
        if tag not in VOID:
            self.stack.append((tag, chart, mark))

    def handle_endtag(self, tag):
        if tag in VOID:
            return
        while self.stack:
            if self.stack.pop()[0] == tag:
                break
        if tag == "p":
            self.in_error = None

    def handle_data(self, data):
        if self.in_error:
            self.errors[self.in_error] += data


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    wanted = {}
    for arg in sys.argv[2:]:
        chart, _, needs = arg.partition("=")
        wanted[chart] = {t: int(n) for t, n in (need.split(":") for need in needs.split(",") if need)}
    parser = ChartMarks(wanted)
    with open(sys.argv[1], encoding="utf-8") as dom:
        parser.feed(dom.read())
    failed = False
    for chart, needs in wanted.items():
        drawn = dict(parser.marks[chart])
        print(f"#{chart}: {parser.svgs[chart]} svg, marks drawn {drawn}")
        problems = []
        if parser.svgs[chart] == 0:
            problems.append("no svg or canvas")
        if parser.errors[chart]:
            problems.append(f"the page says: {parser.errors[chart].strip()}")
        problems += [f"{drawn.get(t, 0)} {t} marks, expected at least {n}" for t, n in needs.items()
                     if drawn.get(t, 0) < n]
        if problems:
            failed = True
            print(f"FAIL: #{chart}: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
