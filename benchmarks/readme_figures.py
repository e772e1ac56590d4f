#!/usr/bin/env python3
"""Re-derives the repair figures of benchmarks/README.md from the committed
runs (issue 32), the differential tester's (issue 42), the test-set ledger
and the fleet study of home/README.md (issue 43): the READMEs' figures must
match their files. Quantiles are nearest ranks, computed here on their own
(nearest_rank, the definition of stats/quantile.h). The blocks are made in
benchmarks/figures/, a module per study; this script lists them and checks
or writes the READMEs.

Each block of figures in the README stands between
    <!-- figures:NAME -->  and  <!-- /figures:NAME -->
and is exactly what this script prints for NAME, computed from the runs.json
files under benchmarks/results/ alone (the differential blocks: a run's
report.txt and counts.json) (not from summary.md, which the same
program wrote with the numbers). Two blocks are not re-derived: study-wins
and study-switch read the verdicts, intervals and Holm p-values of the
study's summary.json, which alplan wrote (the bootstrap and the tests are
stats/'s, tested there); they check that the README shows what the
committed summary says, not the statistics themselves. Usage:

    benchmarks/readme_figures.py             print every block
    benchmarks/readme_figures.py NAME        print one
    benchmarks/readme_figures.py --check     exit 1 naming each block of the
                                             READMEs that differs (a test runs it)
    benchmarks/readme_figures.py --write     rewrite the READMEs' blocks
    benchmarks/readme_figures.py --home-fleet DIR   the fleet table of a
                                             benchmarks/home_fleet.sh run
"""
import os
import re
import sys

from figures.common import HERE, check_nearest_rank
from figures.differential import FUZZ_SEEDS, differential_block, oracle_against_val_block
from figures.home_fleet import home_fleet_block
from figures.ledger import test_set_ledger_block
from figures.quality import (COVERAGE_6_10_AFTER, COVERAGE_6_10_BEFORE, OPENSTACKS_NEIGHBOURHOOD, QUALITY_FIRST, QUALITY_FIRST_BEFORE, TIES_ADOPTED, anytime_block,
                             first_plans_block, openstacks_block, openstacks_test_block, suite_pair_block,
                             variants_block)
from figures.pddl3 import (PDDL3_ISSUE44_ANYTIME, PDDL3_ISSUE44_ANYTIME_D11691A, PDDL3_ISSUE44_FIRST,
                           pddl3_against_optic_block, pddl3_classical_block)
from figures.repair_study import HELD_OUT, SCATTERED, camera_search, study_mix, study_switch, study_wins, tags_by_scatter
from figures.stability import (CROSS_CHECK_FIRST, STABILITY, STABILITY_6_10_ADAPT_REMOVALS, STABILITY_ADAPT_REMOVALS,
                               cross_check_block,
                               proof_search_block, stability_block, stability_by_domain, stability_itt_block)

README = os.path.join(HERE, "README.md")
HOME_README = os.path.join(HERE, "..", "home", "README.md")


BLOCKS = {
    "differential": differential_block,
    "differential-seed1": lambda: differential_block(FUZZ_SEEDS[0]),
    "differential-seed2": lambda: differential_block(FUZZ_SEEDS[1]),
    "differential-seed1-happenings": lambda: differential_block(FUZZ_SEEDS[2]),
    "differential-seed2-happenings": lambda: differential_block(FUZZ_SEEDS[3]),
    "differential-seed1-final": lambda: differential_block(FUZZ_SEEDS[4]),
    "differential-seed2-final": lambda: differential_block(FUZZ_SEEDS[5]),
    "differential-seed3-final": lambda: differential_block(FUZZ_SEEDS[6]),
    "differential-seed3-subepsilon": lambda: differential_block(FUZZ_SEEDS[7]),
    "oracle-against-val": oracle_against_val_block,
    "study-mix": study_mix,
    "study-switch": study_switch,
    "study-wins": study_wins,
    "scatter-mix": lambda: study_mix(SCATTERED),
    "held-out-mix": lambda: study_mix(HELD_OUT),
    "held-out-wins": lambda: study_wins(HELD_OUT),
    "tags-by-scatter": tags_by_scatter,
    "stability-1-5": lambda: stability_block(STABILITY[0]),
    "stability-6-10": lambda: stability_block(STABILITY[1]),
    "stability-6-10-first-run": lambda: stability_block(STABILITY[2]),
    "stability-itt-1-5": lambda: stability_itt_block(STABILITY[0]),
    "stability-itt-6-10-first-run": lambda: stability_itt_block(STABILITY[2]),
    "stability-itt-6-10": lambda: stability_itt_block(STABILITY[1]),
    "stability-itt-adapt-removals": lambda: stability_itt_block(STABILITY_ADAPT_REMOVALS),
    "stability-6-10-adapt-removals": lambda: stability_block(STABILITY_6_10_ADAPT_REMOVALS),
    "stability-itt-6-10-adapt-removals": lambda: stability_itt_block(STABILITY_6_10_ADAPT_REMOVALS),
    "stable-cross-check-first": lambda: cross_check_block(CROSS_CHECK_FIRST),
    "stable-cross-check": lambda: cross_check_block(STABILITY_ADAPT_REMOVALS),
    "pddl3-classical": pddl3_classical_block,
    "pddl3-issue44-first": lambda: pddl3_against_optic_block(PDDL3_ISSUE44_FIRST),
    "pddl3-issue44-anytime": lambda: pddl3_against_optic_block(PDDL3_ISSUE44_ANYTIME),
    "pddl3-issue44-anytime-d11691a": lambda: pddl3_against_optic_block(PDDL3_ISSUE44_ANYTIME_D11691A),
    "test-set-ledger": test_set_ledger_block,
    "stability-domains-1-5": lambda: stability_by_domain(STABILITY[0]),
    "stable-proof-search": proof_search_block,
    "camera-search": camera_search,
    "quality-first-before": lambda: first_plans_block(QUALITY_FIRST_BEFORE),
    "quality-first": lambda: first_plans_block(QUALITY_FIRST),
    "quality-suite": suite_pair_block,
    "quality-anytime": anytime_block,
    "quality-openstacks": openstacks_block,
    "quality-ties-variants": variants_block,
    "coverage-6-10-issue48": lambda: suite_pair_block(COVERAGE_6_10_BEFORE, COVERAGE_6_10_AFTER),
    "quality-first-ties": lambda: first_plans_block(TIES_ADOPTED),
    "quality-openstacks-neighbourhood": lambda: openstacks_block(OPENSTACKS_NEIGHBOURHOOD, OPENSTACKS_NEIGHBOURHOOD),
    "quality-openstacks-test": openstacks_test_block,
}

# The blocks of home/README.md.
HOME_BLOCKS = {
    "home-fleet": home_fleet_block,
}
READMES = [(README, BLOCKS), (HOME_README, HOME_BLOCKS)]


def readme_blocks(text):
    return {m.group(1): m.group(2).strip("\n")
            for m in re.finditer(r"<!-- figures:([\w-]+) -->\n(.*?)<!-- /figures:\1 -->", text, re.S)}


def main(argv):
    check_nearest_rank()
    if len(argv) > 2 and argv[1] == "--home-fleet":
        print(home_fleet_block(os.path.basename(os.path.normpath(argv[2])), os.path.dirname(os.path.abspath(argv[2]))))
        return 0
    if len(argv) > 1 and argv[1] in ("--check", "--write"):
        bad = []
        for readme, blocks in READMES:
            with open(readme) as f:
                text = f.read()
            found = readme_blocks(text)
            if argv[1] == "--write":
                for name, make in blocks.items():
                    text = re.sub(rf"(<!-- figures:{name} -->\n).*?(<!-- /figures:{name} -->)",
                                  lambda m: m.group(1) + make() + "\n" + m.group(2), text, flags=re.S)
                with open(readme, "w") as f:
                    f.write(text)
                continue
            shown = os.path.relpath(readme, os.path.join(HERE, ".."))
            for n, make in blocks.items():
                if found.get(n) != make():
                    bad.append(n)
                    print(f"{shown}: the figures of block '{n}' differ from what {os.path.basename(__file__)} derives "
                          f"from the results" if n in found else f"{shown}: no block '{n}'", file=sys.stderr)
        return 1 if bad else 0
    every = {**BLOCKS, **HOME_BLOCKS}
    names = argv[1:] or list(every)
    for name in names:
        if name not in every:
            print(f"unknown block '{name}'; blocks: {', '.join(every)}", file=sys.stderr)
            return 2
        print(f"<!-- figures:{name} -->\n{every[name]()}\n<!-- /figures:{name} -->\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
