#!/usr/bin/env bash
# Runs `alplan report` as users would: exit codes and messages on bad input,
# then renders the page of a sample log in headless Chromium and checks that
# the Gantt chart, the map and the timelines were drawn (marks inside each
# chart's div), and that a broken spec is caught. Leaves a screenshot,
# WORKDIR/report.png, to look at.
# Usage: report_command_test.sh ALPLAN WORKDIR
set -euo pipefail
alplan=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work" && cd "$work"

. "$here/../cli/expect.sh"
command -v chromium >/dev/null || fail "chromium is not installed; run scripts/setup"

# Bad input: named, exit 2.
expect 2 "missing.jsonl: error: cannot open the file" "$alplan" report missing.jsonl --out out
printf 'not json\n{"type":"stress"}\n' >useless.jsonl
expect 2 "useless.jsonl: error: no usable event in the log" "$alplan" report useless.jsonl --out out
expect 2 "useless.jsonl:1: warning: not JSON" "$alplan" report useless.jsonl --out out
"$python" "$here/make_sample_log.py" run.jsonl
expect 2 "nowhere/vega.min.js: error: cannot read the charting library the report inlines; run scripts/setup" \
  "$alplan" report run.jsonl --out out --vega-dir nowhere
[ ! -e out/index.html ] || fail "a failed report wrote out/index.html"

# A crashed run's log: the bad lines are named, the rest is reported.
"$python" "$here/make_sample_log.py" damaged.jsonl --damage
expect 0 "damaged.jsonl:18: warning: not JSON" "$alplan" report damaged.jsonl --out damaged
expect 0 "damaged.jsonl:$(wc -l <damaged.jsonl): warning: not JSON" "$alplan" report damaged.jsonl --out damaged

expect 0 "report: report/index.html" "$alplan" report run.jsonl --out report
! grep -q '<script src=\|<link ' report/index.html || fail "the page loads something from outside"

# render PAGE DOM [PNG]: the DOM after the page's scripts ran, and a screenshot.
render() {
  local flags=(--headless --disable-gpu --no-sandbox --user-data-dir="$work/chromium-profile"
               --virtual-time-budget=10000 --hide-scrollbars)
  timeout 120 chromium "${flags[@]}" --dump-dom "file://$work/$1" >"$2" 2>chromium.err ||
    fail "chromium could not render $1: $(tail -5 chromium.err)"
  if [ $# -gt 2 ]; then
    timeout 120 chromium "${flags[@]}" --window-size=1400,3000 --screenshot="$work/$3" "file://$work/$1" \
      2>>chromium.err >/dev/null || fail "chromium could not take a screenshot of $1: $(tail -5 chromium.err)"
  fi
}

# The sample has 25 steps in 4 plans (bars, and ticks for the 2 failures,
# are rects), 2 repairs (rules and diamonds); 7 rooms (squares and labels),
# 7 connections, 2 routes; 3 seniors with a stress line each, 3 goal windows,
# 2 comforted and 1 missed, 123 stress and 63 emotion points.
charts=(gantt=rect:27,rule:2,symbol:4 map=rule:7,line:2,symbol:7,text:7
        timeline=line:3,rect:3,rule:3,symbol:186)
render report/index.html dom.html report.png
"$python" "$here/check_rendered_page.py" dom.html "${charts[@]}"
[ -s report.png ] || fail "no screenshot"

# A spec vega-embed refuses must fail the check: break the Gantt chart's.
sed 's/"type":"bar"/"type":"no-such-mark"/' report/index.html >report/broken.html
cmp -s report/index.html report/broken.html && fail "could not break the Gantt spec"
render report/broken.html broken-dom.html
if "$python" "$here/check_rendered_page.py" broken-dom.html "${charts[@]}" 2>broken.err; then
  fail "a broken Gantt spec passed the check"
fi
grep -q "FAIL: #gantt" broken.err || fail "the broken Gantt spec failed for another reason: $(cat broken.err)"
! grep -q "FAIL: #map\|FAIL: #timeline" broken.err || fail "breaking the Gantt spec broke the others: $(cat broken.err)"

echo "screenshot: $work/report.png"
