#!/usr/bin/env python3
"""The reference semantics (alplan validate --reference) against VAL on generated tasks and plans.

    benchmarks/oracle_against_val.py TASKS_DIR ALPLAN VALIDATE [--mutations N] [--seed S] [--out FILE]

TASKS_DIR is a folder `alplan fuzz planner --write-tasks DIR` wrote: one folder per task with
domain.pddl, problem.pddl and, where there is one, planner.plan (the planner's) and witness.plan
(the brute force's). Each such plan, and N mutations of it (a step dropped, a step moved by
half an epsilon, an epsilon or half a time unit, a duration stretched, a step repeated), is judged
by the reference semantics (VAL's comparisons, -t 0.001) and by VAL (KCL-Planning/VAL's Validate
binary, built from its public source; it is not part of alplan). Prints the counts and every
plan where the verdicts, or the values of a valid plan (to 1e-3), differ; exits 1 if any does.
Plans VAL cannot judge (it errs or crashes, or reads undefined memory: a plan of no steps in a
task with timed literals) are counted apart and never as agreement.
"""
import argparse
import json
import random
import re
import subprocess
import sys
from pathlib import Path

STEP = re.compile(r"^\s*([0-9.]+)\s*:\s*\(([^)]*)\)\s*(?:\[([0-9.]+)\])?")


def read_plan(text):
    steps = []
    for line in text.splitlines():
        m = STEP.match(line.split(";")[0])
        if m:
            steps.append([float(m.group(1)), m.group(2).strip(), float(m.group(3)) if m.group(3) else None])
    return steps


def write_plan(steps):
    lines = []
    for t, action, d in sorted(steps, key=lambda s: s[0]):
        lines.append(f"{t:.4f}: ({action})" + (f" [{d:.4f}]" if d is not None else ""))
    return "\n".join(lines) + "\n"


def mutations(steps, rng, n):
    out = []
    for _ in range(n):
        s = [list(x) for x in steps]
        if not s:
            break
        k = rng.randrange(len(s))
        kind = rng.choice(["drop", "move", "move", "stretch", "repeat"])
        if kind == "drop":
            del s[k]
        elif kind == "move":
            s[k][0] = max(0.0, s[k][0] + rng.choice([-0.5, -0.001, -0.0005, 0.0005, 0.001, 0.5]))
        elif kind == "stretch" and s[k][2] is not None:
            s[k][2] = s[k][2] + rng.choice([-0.5, 0.5, 0.001])
        else:
            s.append(list(s[k]))
        out.append((kind, s))
    return out


def oracle(alplan, domain, problem, plan):
    r = subprocess.run([alplan, "validate", "--reference", "--json", str(domain), str(problem), str(plan)],
                       capture_output=True, text=True)
    if r.returncode == 2:
        return ("error", r.stdout.strip() or r.stderr.strip())
    j = json.loads(r.stdout)
    if not j["judged"]:
        return ("error", j.get("reason", ""))
    return ("valid", j["value"]) if j["valid"] else ("invalid", j["failure"] + ": " + j["reason"])


def val(validate, domain, problem, plan):
    try:
        r = subprocess.run([validate, "-t", "0.001", str(domain), str(problem), str(plan)],
                           capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return ("error", "timeout")
    out = r.stdout
    if r.returncode < 0 or r.returncode > 200 or "Error occurred in validation attempt" in out or \
            "Bad plan description" in out or "Problem in domain definition" in out:
        return ("error", out.strip().splitlines()[-1] if out.strip() else f"exit {r.returncode}")
    if "Plan valid" in out:
        m = re.search(r"Final value:\s*(\S+)", out)
        return ("valid", float(m.group(1)) if m else None)
    return ("invalid", "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tasks")
    parser.add_argument("alplan")
    parser.add_argument("validate")
    parser.add_argument("--mutations", type=int, default=4)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", help="write the counts here as JSON (readme_figures.py reads them)")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    counts = {"plans": 0, "agree_valid": 0, "agree_invalid": 0, "val_cannot_judge": 0,
              "oracle_cannot_judge": 0, "disagree": 0}
    scratch = Path(args.tasks) / "_mutated.plan"
    for folder in sorted(p for p in Path(args.tasks).iterdir() if p.is_dir()):
        domain, problem = folder / "domain.pddl", folder / "problem.pddl"
        plans = []
        for name in ("planner.plan", "witness.plan"):
            if (folder / name).exists():
                steps = read_plan((folder / name).read_text())
                plans.append((name, steps))
                plans += [(f"{name}:{kind}", m) for kind, m in mutations(steps, rng, args.mutations)]
        has_literals = "(at " in problem.read_text()
        for name, steps in plans:
            scratch.write_text(write_plan(steps))
            counts["plans"] += 1
            if not steps and has_literals:
                counts["val_cannot_judge"] += 1  # VAL's bound on the plan's end is read out of range
                continue
            v, o = val(args.validate, domain, problem, scratch), oracle(args.alplan, domain, problem, scratch)
            if v[0] == "error":
                counts["val_cannot_judge"] += 1
                continue
            if o[0] == "error":
                counts["oracle_cannot_judge"] += 1
                print(f"{folder.name} {name}: the oracle cannot judge ({o[1]}); VAL {v[0]}")
                continue
            same = v[0] == o[0] and (v[0] != "valid" or v[1] is None or abs(v[1] - o[1]) <= 1e-3)
            if same:
                counts["agree_" + v[0]] += 1
            else:
                counts["disagree"] += 1
                print(f"{folder.name} {name}: VAL {v[0]} {v[1]}, oracle {o[0]} {o[1]}\n{scratch.read_text()}")
    scratch.unlink(missing_ok=True)
    print(json.dumps(counts))
    if args.out:
        Path(args.out).write_text(json.dumps(counts, indent=1) + "\n")
    return 1 if counts["disagree"] else 0


if __name__ == "__main__":
    sys.exit(main())
