"""Plan a shared IPC problem with alplan and draw the plan as a Gantt chart.

    PYTHONPATH=build/python python3 python/examples/gantt.py [DOMAIN PROBLEM] [--out plan.png]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")  # files, not windows
import matplotlib.pyplot as plt  # noqa: E402

import alplan  # noqa: E402

SHARED = os.environ.get("ALPLAN_SHARED_DIR", "../shared")
MATCH = os.path.join(SHARED, "benchmarks", "ipc", "ipc-2014", "match-cellar-temporal-satisficing")


def gantt(result, title, out):
    steps = sorted(result.steps, key=lambda s: s.time)
    fig, ax = plt.subplots(figsize=(9, 0.3 * len(steps) + 1.2))
    for row, step in enumerate(steps):
        ax.barh(row, step.duration or 0.05, left=step.time, color="#4a7ab5")
    ax.set_yticks(range(len(steps)), [s.name for s in steps], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("time")
    ax.set_title("%s: makespan %.3f, %d steps" % (title, result.makespan, len(steps)))
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("domain", nargs="?", default=os.path.join(MATCH, "domain.pddl"))
    parser.add_argument("problem", nargs="?", default=os.path.join(MATCH, "instances", "instance-1.pddl"))
    parser.add_argument("--out", default="plan.png")
    args = parser.parse_args()
    result = alplan.plan(args.domain, args.problem, time_limit=30, anytime=True, anytime_expansions=2000)
    if not result.solved:
        raise SystemExit("no plan: %s (%s)" % (result.status, result.message))
    checked = alplan.validate(args.domain, args.problem, result)
    print("%s: %d steps, makespan %.3f, valid: %s" % (result.status, len(result.steps), result.makespan, checked.valid))
    gantt(result, os.path.basename(args.problem), args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
