#!/usr/bin/env bash
# Saturates the signal service with wrk (Debian's wrk, benchmarks/service_wrk.lua):
# starts `alplan serve` on a free loopback port with a fresh database, lets
# wrk POST valid batches of 12 readings as fast as CONNECTIONS connections on
# WRK_THREADS threads can (one device per wrk thread), then checks zero loss:
# every reading wrk saw acknowledged is stored (the service counts a reading
# only after its commit), and the count the service reports when it stops
# cleanly agrees. Prints one Markdown table row:
# | client | requests | stored readings/s | acknowledged | stored | p50 ms | p99 ms | zero loss |
# Usage: service_wrk.sh [SECONDS=20] [CONNECTIONS=16] [WRK_THREADS=2] [SERVE_THREADS=4] [SYNC=full]
# ALPLAN=path/to/alplan overrides build/cli/alplan.
set -euo pipefail
seconds=${1:-20}
connections=${2:-16}
wrk_threads=${3:-2}
serve_threads=${4:-4}
sync=${5:-full}
root=$(cd "$(dirname "$0")/.." && pwd)
alplan=${ALPLAN:-$root/build/cli/alplan}
work=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null || true; rm -rf "$work"' EXIT

"$alplan" wristband tokens --devices "$wrk_threads" --prefix wrk- --out "$work/tokens.txt"
"$alplan" serve --port 0 --db "$work/wrk.db" --tokens "$work/tokens.txt" --threads "$serve_threads" \
  --sync "$sync" --max-connections 4096 >"$work/serve.out" 2>"$work/serve.err" &
pid=$!
for _ in $(seq 100); do grep -q "serving on" "$work/serve.out" && break; sleep 0.2; done
url=$(grep -o 'http://[0-9.]*:[0-9]*' "$work/serve.out")

export WRK_DEVICES
WRK_DEVICES=$(awk '!/^#/ {printf "%s%s:%s", sep, $1, $2; sep=","}' "$work/tokens.txt")
summary=$(wrk -t"$wrk_threads" -c"$connections" -d"${seconds}s" --timeout 10s -s "$root/benchmarks/service_wrk.lua" "$url" |
          grep '^wrk-summary')
field() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p" <<<"$summary"; }
requests=$(field requests)
non2xx=$(field non2xx)
errors=$(( $(field connect) + $(field read) + $(field write) + $(field timeout) ))
stored=$(curl -s "$url/metrics" | sed -n 's/^alplan_readings_stored_total //p')
kill -TERM "$pid"
wait "$pid"
pid=
in_db=$(sed -n 's/^serve: stopped; stored \([0-9]*\) readings.*/\1/p' "$work/serve.err")

acknowledged=$(( (requests - non2xx) * 12 ))
# wrk drops the requests in flight when time is up; the service may have
# stored those too, so stored may exceed acknowledged by up to a batch per connection.
lossless=no
if [ "$non2xx" -eq 0 ] && [ "$stored" -ge "$acknowledged" ] && [ "$stored" -le $(( acknowledged + 12 * connections )) ] &&
   [ "$in_db" -eq "$stored" ]; then
  lossless=yes
fi
rate=$(awk -v s="$stored" -v t="$(field seconds)" 'BEGIN {printf "%.0f", s / t}')
printf '| wrk -t%s -c%s, %s s | %s | %s | %s | %s | %s | %s | %s |\n' "$wrk_threads" "$connections" "$seconds" \
  "$(( requests ))" "$rate" "$acknowledged" "$stored" "$(field p50_ms)" "$(field p99_ms)" "$lossless"
[ "$lossless" = yes ] && [ "$errors" -eq 0 ]
