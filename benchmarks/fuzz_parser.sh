#!/usr/bin/env bash
# Fuzzes the PDDL parser, checker and writer with libFuzzer under ASan and
# UBSan for SECONDS seconds (default 60). Seeds: the IPC files and the
# project's test data. Exit status is non-zero on any finding; a crashing
# input is left in build-fuzz/ for replay: build-fuzz/fuzz_parser FILE
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${ALPLAN_SHARED_DIR:-$root/../shared}
out=${ALPLAN_FUZZ_DIR:-$root/build-fuzz}
mkdir -p "$out/corpus"

sources=("$root"/pddl_parser/*.cpp "$root/planner/plan.cpp" "$root/planner/search_configuration.cpp"
         "$root/benchmarks/fuzz_parser.cpp")
binary="$out/fuzz_parser"
newest=$(ls -t "${sources[@]}" "$root"/pddl_parser/*.h "$root"/planner/plan.h "$root"/planner/search_configuration.h | head -1)
if [ ! -x "$binary" ] || [ "$newest" -nt "$binary" ]; then
  echo "fuzz: building $binary"
  # One compiler per source, as many at once as there are cores: one clang++
  # for them all compiled them one after another on one core (about 3 minutes
  # of scripts/test, 2026-11-28). Objects are named by their path.
  mkdir -p "$out/objects"
  flags=(-std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -I "$root")
  objects=()
  for s in "${sources[@]}"; do objects+=("$out/objects/$(echo "${s#"$root"/}" | tr / _).o"); done
  pids=()
  for i in "${!sources[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do sleep 0.2; done
    clang++ "${flags[@]}" -c "${sources[$i]}" -o "${objects[$i]}" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done  # set -e: a failed compile stops here
  clang++ "${flags[@]}" "${objects[@]}" -o "$binary"
fi

seeds="$out/seeds"
if [ ! -d "$seeds" ]; then
  mkdir -p "$seeds"
  # Every domain, and the smaller problems (libFuzzer truncates at -max_len).
  find "$shared/benchmarks/ipc" -name '*.pddl' -size -24k -print0 |
    while IFS= read -r -d '' f; do cp "$f" "$seeds/$(echo "$f" | md5sum | cut -c1-16).pddl"; done
  find "$root/tests/data" -name '*.pddl' -exec cp {} "$seeds/" \;
  # Search configurations (alplan plan --search).
  i=0
  for c in 'then(ehc(trpg, expansions=20000, time_share=0.25, goal_orders=true), portfolio(gbfs(trpg), wastar(trpg, w=3)), complete(wastar(trpg, w=3)))' \
           'anytime(gbfs(trpg(helpful=false), queue=typed, novelty=2), weights=[5, 3, 1.5], expansions=10)' \
           'complete(wastar(blind, w=1))' 'portfolio(gbfs(trpg, deferred=true), ehc, turns=evaluations)' default; do
    i=$((i + 1))
    printf '%s' "$c" > "$seeds/configuration-$i.txt"
  done
fi

echo "fuzz: running for ${seconds}s"
cd "$out"
"$binary" -max_total_time="$seconds" -max_len=24576 -timeout=10 -rss_limit_mb=2048 \
  -dict="$root/benchmarks/pddl.dict" -print_final_stats=1 corpus "$seeds" 2>&1 | tail -n 25
