#!/usr/bin/env bash
# The issue's chain as users run it, on the default home (a shortened run):
# alplan home --log, alplan replay, alplan report, the report drawn by
# headless Chromium from the real log; then bad input: a damaged log line is
# named by replay and report (which still uses the rest), an unknown name in
# --home is exit 2.
# Usage: home_command_test.sh ALPLAN WORKDIR
set -euo pipefail
alplan=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
. "$here/expect.sh"

expect 0 "summary:" "$alplan" home --until 1500 --log run.jsonl
"$python" - run.jsonl <<'PY'
import json, sys
types = {"stress", "emotion", "goal", "plan", "action_start", "action_end", "observation", "failure", "repair",
         "explanation", "comforted", "window_missed"}
seen = set()
for n, line in enumerate(open(sys.argv[1]), 1):
    e = json.loads(line)
    assert e["type"] in types, f"line {n}: type {e['type']}"
    assert isinstance(e["time"], (int, float)), f"line {n}: time"
    seen.add(e["type"])
for t in ("stress", "emotion", "goal", "plan", "action_start", "action_end", "failure", "repair", "explanation",
          "comforted"):
    assert t in seen, f"no {t} event in the default home's first 1500 s"
PY
expect 0 "the same" "$alplan" replay run.jsonl
expect 0 "report/index.html" "$alplan" report run.jsonl --out report

# The real log's report, drawn: the Gantt chart, the map, the timelines.
flags=(--headless --disable-gpu --no-sandbox --user-data-dir="$work/chromium-profile" --virtual-time-budget=10000
       --hide-scrollbars)
timeout 120 chromium "${flags[@]}" --dump-dom "file://$work/report/index.html" >dom.html 2>chromium.err ||
  fail "chromium could not render the report: $(tail -5 chromium.err)"
"$python" "$here/../report/check_rendered_page.py" dom.html gantt=rect:5 map=line:1,symbol:14 timeline=symbol:5
timeout 120 chromium "${flags[@]}" --window-size=1400,3000 --screenshot="$work/home-report.png" \
  "file://$work/report/index.html" >/dev/null 2>>chromium.err || fail "no screenshot"
echo "screenshot: $work/home-report.png"

# A damaged line: replay names it and differs; report warns and uses the rest.
sed '12s/.*/{"type":"plan","time":/' run.jsonl >damaged.jsonl
expect 1 "damaged.jsonl:12" "$alplan" replay damaged.jsonl
expect 0 "damaged.jsonl:12" "$alplan" report damaged.jsonl --out damaged-report
expect 2 "cannot open" "$alplan" replay missing.jsonl

# An unknown senior in a home file: named, exit 2.
sed 's/(be senior8 dinning_room1)/(be senior9 dinning_room1)/' "$here/../../domains/assisted_living/home.pddl" >home9.pddl
expect 2 "senior9" "$alplan" home --home home9.pddl --until 60
# A held-out home (seeds 1001-2000) is a test set: without --reason, refused
# before anything runs or is written to the ledger.
expect 2 "held-out homes (seeds 1001-2000)" "$alplan" bench home --seed 1500 --hours 0.01 --out held-out
test ! -e held-out
echo "home, replay and report: ok"
