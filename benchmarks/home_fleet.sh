#!/bin/bash
# The home as a fleet against the home of one mission at a time (issues 31
# and 43): `alplan bench home` (40 seniors, 4 robots, 50 rooms, 400 objects,
# 8 h) on seeds 1-3, one run after another, in three settings: dispatch (one
# mission at a time, windows that close: the home before issue 31), allocate
# with windows that close, and allocate with windows as weighted preferences
# (the default); each once without breakdowns and once with robots breaking
# down at random (--breakdown-rate, per robot and hour; out 30 minutes each),
# so that what breakdowns cost is a paired difference on the same seed.
# home/README.md's table is `benchmarks/readme_figures.py home-fleet`, made
# from the runs' bench-home.json files.
# Usage: benchmarks/home_fleet.sh OUT_DIR [ALPLAN]   (about 20 minutes)
#        RUNS="allocate-soft" benchmarks/home_fleet.sh OUT_DIR   (some of the settings)
#        BREAKDOWN_RATE=0.25 benchmarks/home_fleet.sh OUT_DIR    (default 0.125)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:?usage: home_fleet.sh OUT_DIR [ALPLAN]}
alplan=${2:-$here/../build/cli/alplan}
rate=${BREAKDOWN_RATE:-0.125}
mkdir -p "$out"
for run in ${RUNS:-dispatch-hard allocate-hard allocate-soft}; do
  flags=(--fleet "${run%-*}")
  [ "${run#*-}" = hard ] && flags+=(--hard-windows)
  for seed in 1 2 3; do
    for down in none "$rate"; do
      dir=$out/$run/seed-$seed
      extra=()
      if [ "$down" != none ]; then
        dir=$out/$run-breakdowns/seed-$seed
        extra=(--breakdown-rate "$down")
      fi
      mkdir -p "$dir"
      echo "$alplan bench home --seed $seed ${flags[*]} ${extra[*]} --out $dir" > "$dir/command.txt"
      /usr/bin/time -v "$alplan" bench home --seed "$seed" "${flags[@]}" "${extra[@]}" --out "$dir" \
        2> "$dir/time.txt" > "$dir/table.txt"
    done
  done
done
python3 "$here/readme_figures.py" --home-fleet "$out"
