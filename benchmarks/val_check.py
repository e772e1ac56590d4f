#!/usr/bin/env python3
"""Checks every plan of a `bench planners` run with VAL, as an outside opinion.

    benchmarks/val_check.py RESULTS_DIR VALIDATE [--benchmarks ../shared/benchmarks]

RESULTS_DIR is a folder `alplan bench planners --out` wrote (runs.json, plans/N.plan);
VALIDATE is VAL's Validate binary (KCL-Planning/VAL, built from its public source; it
is not part of alplan). Prints, per solved problem, VAL's verdict and value beside
ours, and marks a disagreement; exits 1 if VAL refuses any of our plans.
"""
import argparse
import json
import re
import subprocess
import sys
from pathlib import Path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("validate")
    parser.add_argument("--benchmarks", default=str(Path(__file__).resolve().parents[2] / "shared" / "benchmarks"))
    args = parser.parse_args()
    runs = json.loads((Path(args.results) / "runs.json").read_text())["runs"]
    refused = 0
    for index, run in enumerate(runs):
        if run["status"] != "solved":
            continue
        problem = Path(args.benchmarks) / run["problem"]
        # One domain for the folder, or (airport, promela, parc-printer,
        # openstacks 2008 and 2011) domains/domain-N.pddl beside instance-N.
        own = problem.parent.parent / "domains" / problem.name.replace("instance-", "domain-")
        domain = own if own.exists() else problem.parent.parent / "domain.pddl"
        plan = Path(args.results) / "plans" / f"{index}.plan"
        out = subprocess.run([args.validate, "-t", "0.001", str(domain), str(problem), str(plan)],
                             capture_output=True, text=True).stdout
        valid = "Plan valid" in out
        match = re.search(r"Final value: (\S+)", out)
        value = float(match.group(1)) if match else None
        agrees = valid and value is not None and abs(value - run["value"]) < 1e-3
        refused += not valid
        print(f"{run['problem']}: VAL {'valid' if valid else 'INVALID'} {value} ours {run['value']:.6g}"
              f"{'' if agrees else '  <-- differs'}")
    return 1 if refused else 0


if __name__ == "__main__":
    sys.exit(main())
