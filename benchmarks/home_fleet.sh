#!/bin/bash
# The home as a fleet against the home of one mission at a time (issue 31):
# `alplan bench home` (40 seniors, 4 robots, 50 rooms, 400 objects, 8 h) on
# seeds 1-3, one run after another, in three settings: dispatch (one
# mission at a time, windows that close: the home before issue 31),
# allocate with windows that close, and allocate with windows as weighted
# preferences (the default); then the side-by-side table home/README.md
# quotes, made from the runs' bench-home.json files.
# Usage: benchmarks/home_fleet.sh OUT_DIR [ALPLAN]   (about 10 minutes)
#        benchmarks/home_fleet.sh --table OUT_DIR    (the table again)
#        RUNS="allocate-soft" benchmarks/home_fleet.sh OUT_DIR   (some of the settings)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
table_only=0
if [ "${1:-}" = --table ]; then table_only=1; shift; fi
out=${1:?usage: home_fleet.sh [--table] OUT_DIR [ALPLAN]}
alplan=${2:-$here/../build/cli/alplan}
if [ "$table_only" = 0 ]; then
  for run in ${RUNS:-dispatch-hard allocate-hard allocate-soft}; do
    flags=(--fleet "${run%-*}")
    [ "${run#*-}" = hard ] && flags+=(--hard-windows)
    for seed in 1 2 3; do
      dir=$out/$run/seed-$seed
      mkdir -p "$dir"
      "$alplan" bench home --seed "$seed" "${flags[@]}" --out "$dir" 2>/dev/null > "$dir/table.txt"
    done
  done
fi
python3 - "$out" <<'PY'
import json, sys, pathlib
out = pathlib.Path(sys.argv[1])
print("| seed | run | goals | within window | meetable alone: within | never served | in course at end "
      "| weighted lateness s | robots at work | replanning p50 / p95 / max s, failed included | initial p95 s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for seed in (1, 2, 3):
    for run in ("dispatch-hard", "allocate-hard", "allocate-soft"):
        f = out / run / f"seed-{seed}" / "bench-home.json"
        if not f.exists():
            continue
        r = json.loads(f.read_text())
        s, rp = r["summary"], r["replanning"]
        initial = r["planning_by_reason"].get("initial", {}).get("p95_s", 0.0)
        print(f"| {seed} | {run} | {s['goals']} | {s['within_window']} ({100 * r['comforted_within_window_share']:.1f}%) "
              f"| {round(r['meetable_within_window_share'] * r['meetable_goals'])} of {r['meetable_goals']} "
              f"({100 * r['meetable_within_window_share']:.1f}%) | {r['never_served']} | {r['in_course_at_end']} "
              f"| {r['weighted_lateness_s']:.0f} | {100 * r['robot_utilisation']:.1f}% "
              f"| {rp['p50_s']:.3f} / {rp['p95_s']:.3f} / {rp['max_s']:.3f} | {initial:.2f} |")
PY
