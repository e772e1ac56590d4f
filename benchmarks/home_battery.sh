#!/bin/bash
# Planning time of the running home with and without robot batteries
# (`alplan home` against `alplan home --battery`, issue 15): the same homes,
# seeds and settings, one run each, one log each. Prints a Markdown table:
# plans made, planning seconds per plan (p50, p95, max, sum; wall clock,
# initial, merge and repair plans and calls that found none), goals comforted
# within their windows, recharges started and the lowest battery over the
# run. home/README.md quotes it.
# Usage: benchmarks/home_battery.sh [ALPLAN] [OUT_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
alplan=${1:-$here/../build/cli/alplan}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
runs=(
  "paper-1h|--until 3600"
  "paper-1h-low|--until 3600 --battery-initial 30"
  "gen8-s1|--seniors 8 --robots 2 --rooms 12 --objects 30 --until 7200 --seed 1"
  "gen8-s2|--seniors 8 --robots 2 --rooms 12 --objects 30 --until 7200 --seed 2"
  "gen8-s3|--seniors 8 --robots 2 --rooms 12 --objects 30 --until 7200 --seed 3"
  "gen8-s1-first|--seniors 8 --robots 2 --rooms 12 --objects 30 --until 7200 --seed 1 --planner-expansions 0"
  "gen40-s1|--seniors 40 --robots 4 --rooms 50 --objects 400 --until 7200 --seed 1"
  "gen40-s2|--seniors 40 --robots 4 --rooms 50 --objects 400 --until 7200 --seed 2"
  "gen40-s1-first|--seniors 40 --robots 4 --rooms 50 --objects 400 --until 7200 --seed 1 --planner-expansions 0"
)
printf '| home | batteries | plans | p50 s | p95 s | max s | sum s | within window / goals | recharges | lowest battery |\n'
printf '|---|---|---|---|---|---|---|---|---|---|\n'
for run in "${runs[@]}"; do
  name=${run%%|*}
  flags=${run#*|}
  for battery in no yes; do
    extra=""
    if [ "$battery" = yes ]; then extra="--battery"
    elif [[ "$flags" == *--battery-* ]]; then continue  # battery values need batteries
    fi
    log="$out/$name-$battery.jsonl"
    # shellcheck disable=SC2086
    "$alplan" home $flags $extra --quiet --log "$log" >"$out/$name-$battery.txt" 2>/dev/null
    /usr/bin/python3 - "$log" "$name" "$battery" <<'PY'
import json, sys
log, name, battery = sys.argv[1:]
events = [json.loads(line) for line in open(log)]
seconds = sorted(e["planning_seconds"] for e in events if e["type"] == "plan")
# Nearest rank, ceil(q n) (stats/quantile.h), every call counted.
nearest = lambda q: seconds[min(len(seconds), max(1, -(-round(q * len(seconds) * 1e9) // 10**9))) - 1] if seconds else 0.0
goals = sum(e["type"] == "goal" for e in events)
within = sum(e["type"] == "comforted" and e.get("within_window", False) for e in events)
recharges = sum(e["type"] == "action_start" and e["action"].startswith("(recharge ") for e in events)
lows = [e["lowest"] for e in events if e["type"] == "battery"]
below = any(e.get("below_reserve") for e in events if e["type"] == "battery")
lowest = "-" if not lows else f"{min(lows):.2f}" + (" (below reserve)" if below else "")
print(f"| {name} | {battery} | {len(seconds)} | {nearest(0.5):.3f} | {nearest(0.95):.3f} | "
      f"{(seconds[-1] if seconds else 0):.3f} | {sum(seconds):.2f} | {within} / {goals} | "
      f"{recharges if battery == 'yes' else '-'} | {lowest} |")
PY
  done
done
