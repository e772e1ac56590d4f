#!/usr/bin/env python3
"""The include graph of the project's C++ sources, by module (a header and
its .cpp are one module), and its loops.

    scripts/include_graph.py [FOLDER ...]          loops, and edges per folder
    scripts/include_graph.py --dot [FOLDER ...]    the graph in Graphviz dot
    scripts/include_graph.py --check [FOLDER ...]  exit 1 when a loop exists

A module is a path without its extension (planner/validator for
planner/validator.h and planner/validator.cpp). An edge A -> B is an
`#include "B.h"` in A.h or A.cpp. A loop is a strongly connected component
of more than one module (Tarjan 1972), printed with one cycle through it.
Only quoted includes of files in the tree count; FOLDERs (default: every
top-level folder with sources) restrict the modules shown, not the edges
followed.
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SKIP = {"build", "third_party", ".git", "node_modules", "experiments"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def modules():
    """Every module of the tree and the modules it includes."""
    graph = {}
    for folder, dirs, files in os.walk(ROOT):
        dirs[:] = [d for d in dirs if d not in SKIP and not d.startswith("build")]
        for name in files:
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(folder, name)
            module = os.path.splitext(os.path.relpath(path, ROOT))[0]
            with open(path, errors="replace") as f:
                text = f.read()
            edges = graph.setdefault(module, set())
            for included in INCLUDE.findall(text):
                target = os.path.splitext(included)[0]
                if target != module and os.path.exists(os.path.join(ROOT, included)):
                    edges.add(target)
    for edges in list(graph.values()):
        for target in edges:
            graph.setdefault(target, set())
    return graph


def strongly_connected(graph):
    """Tarjan's components, iteratively (the graph has thousands of edges)."""
    index, low, on_stack, stack, out = {}, {}, set(), [], []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                out.append(sorted(component))
    return out


def cycle_through(graph, component):
    """One cycle inside a component, from its first module back to it."""
    members = set(component)
    start = component[0]
    path, seen = [start], {start}
    node = start
    while True:
        nexts = sorted(t for t in graph[node] if t in members)
        if start in nexts and len(path) > 1:
            return path + [start]
        unseen = [t for t in nexts if t not in seen]
        if not unseen:
            return path + [nexts[0]] if nexts else path
        node = unseen[0]
        seen.add(node)
        path.append(node)


def main(argv):
    dot = "--dot" in argv
    check = "--check" in argv
    folders = [a.rstrip("/") for a in argv[1:] if not a.startswith("--")]
    graph = modules()

    def shown(module):
        return not folders or any(module == f or module.startswith(f + "/") for f in folders)

    loops = [c for c in strongly_connected(graph) if len(c) > 1 and any(shown(m) for m in c)]
    if dot:
        print("digraph includes {")
        for module in sorted(m for m in graph if shown(m)):
            for target in sorted(graph[module]):
                if shown(target):
                    print(f'  "{module}" -> "{target}";')
        print("}")
        return 0
    for component in loops:
        print("loop: " + " -> ".join(cycle_through(graph, component))
              + (f"  ({len(component)} modules: {', '.join(component)})" if len(component) > 2 else ""))
    folder_edges = {}
    for module, targets in graph.items():
        if not shown(module):
            continue
        for target in targets:
            a, b = module.split("/")[0], target.split("/")[0]
            if a != b:
                folder_edges.setdefault(a, set()).add(b)
    if not check:
        for a in sorted(folder_edges):
            print(f"{a} includes {', '.join(sorted(folder_edges[a]))}")
    print(f"{len(loops)} include loop{'s' if len(loops) != 1 else ''}")
    return 1 if check and loops else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
