#!/usr/bin/env bash
# Google Benchmark, one commit against another, in one run: builds
# planner_benchmark (or BENCH) at BASE in a worktree beside this checkout's
# build, then runs the two binaries in turns, REPS times each, and prints the
# ratio of their medians (HEAD / BASE; above 1 is slower) per benchmark,
# writing the table to OUT/compare.json.
#   benchmarks/compare_commits.sh BASE [OUT] [FILTER] [REPS] [BENCH]
# The binary for HEAD is build/benchmarks/BENCH (build it first).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
base=${1:?usage: compare_commits.sh BASE [OUT] [FILTER] [REPS] [BENCH]}
out=${2:-/tmp/compare-commits}
filter=${3:-.}
reps=${4:-5}
bench=${5:-planner_benchmark}
sha=$(git -C "$root" rev-parse --short "$base")
tree=/tmp/alplan-base-$sha
mkdir -p "$out"
if [ ! -d "$tree" ]; then git -C "$root" worktree add --detach "$tree" "$base" >/dev/null; fi
# The worktree sits outside the checkout's parent: point it at the same shared data.
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DALPLAN_SHARED_DIR="$(cd "$root/../shared" && pwd)" \
  >"$out/base-configure.log"
cmake --build "$tree/build" --target "$bench" -j2 >"$out/base-build.log"
head_bin=$root/build/benchmarks/$bench
base_bin=$tree/build/benchmarks/$bench
for ((r = 1; r <= reps; ++r)); do
  for side in base head; do
    bin=$base_bin; [ $side = head ] && bin=$head_bin
    "$bin" --benchmark_filter="$filter" --benchmark_format=json >"$out/$side-$r.json" 2>/dev/null
  done
done
/usr/bin/python3 - "$out" "$reps" "$sha" "$(git -C "$root" rev-parse --short HEAD)" <<'PY'
import json, statistics, sys
out, reps, base, head = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
times = {"base": {}, "head": {}}
for side in times:
    for r in range(1, reps + 1):
        for b in json.load(open(f"{out}/{side}-{r}.json"))["benchmarks"]:
            times[side].setdefault(b["name"], []).append(b["real_time"])
rows = []
for name in times["head"]:
    if name not in times["base"]:
        continue
    b, h = statistics.median(times["base"][name]), statistics.median(times["head"][name])
    rows.append({"benchmark": name, "base": b, "head": h, "ratio": h / b})
print(f"| benchmark | {base} (median) | {head} (median) | ratio |")
print("|---|---|---|---|")
for r in rows:
    print(f"| {r['benchmark']} | {r['base']:.4g} | {r['head']:.4g} | {r['ratio']:.3f} |")
gm = statistics.geometric_mean([r["ratio"] for r in rows])
print(f"geometric mean of the ratios: {gm:.3f} ({len(rows)} benchmarks, {reps} runs each, in turns)")
json.dump({"base": base, "head": head, "repetitions": reps, "rows": rows, "geometric_mean_ratio": gm},
          open(f"{out}/compare.json", "w"), indent=1)
PY
