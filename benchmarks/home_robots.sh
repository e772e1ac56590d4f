#!/bin/bash
# The planner on one goal of the 40-senior home (a problem `alplan bench home
# --unplanned-dir` wrote at 2026-11-25 before robots were dispatched: one
# terrified senior, 4 robots, 400 objects), with 1 to 4 of its robots and
# with and without the relevance analysis. Prints expansions, evaluations
# and seconds per run; home/README.md and planner/README.md quote it.
# Usage: benchmarks/home_robots.sh [ALPLAN] [TIME_LIMIT]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
alplan=${1:-$here/../build/cli/alplan}
limit=${2:-60}
data=$here/data/home-one-goal
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '| robots | relevance | status | expanded | evaluated | search s |\n|---|---|---|---|---|---|\n'
for robots in 1 2 3 4; do
  # Keep robot1..robotN: drop the others' objects and facts.
  drop=$(seq $((robots + 1)) 4 | sed 's/^/robot/' | paste -sd'|')
  if [ -n "$drop" ]; then grep -Ev "\b($drop)\b" "$data/problem.pddl" > "$work/p$robots.pddl"
  else cp "$data/problem.pddl" "$work/p$robots.pddl"; fi
  for relevance in on off; do
    flag=(); [ "$relevance" = off ] && flag=(--no-relevance)
    # The last line: "; status: S; expanded E, evaluated V, grounding G s, search T s"
    line=$("$alplan" plan "$data/domain.pddl" "$work/p$robots.pddl" --time-limit "$limit" -q "${flag[@]}" | tail -1 || true)
    echo "$line" | sed -E 's/^; status: ([a-z_]+); expanded ([0-9]+), evaluated ([0-9]+), grounding [0-9.e-]+ s, search ([0-9.e-]+) s$/\1 \2 \3 \4/' |
      awk -v r="$robots" -v rel="$relevance" '{printf "| %s | %s | %s | %s | %s | %.2f |\n", r, rel, $1, $2, $3, $4}'
  done
done
