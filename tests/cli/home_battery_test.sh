#!/usr/bin/env bash
# `alplan home --battery` as users run it: the default home with batteries
# low enough that a robot must recharge; the log carries the batteries, the
# summary and the report say each robot's lowest level and that none went
# below its reserve, replay reproduces the run; `gen home --battery` makes
# a problem the battery domain plans; bad battery values and battery values
# without --battery are refused.
# Usage: home_battery_test.sh ALPLAN WORKDIR
set -euo pipefail
alplan=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
. "$here/expect.sh"

expect 0 "robot1's battery: lowest" "$alplan" home --battery --battery-initial 30 --until 900 --log run.jsonl --quiet
"$python" - run.jsonl <<'PY'
import json, sys
events = [json.loads(line) for line in open(sys.argv[1])]
settings = events[0]["settings"]
assert settings["battery"]["initial"] == 30 and settings["battery"]["reserve"] == 20, settings.get("battery")
ends = [e for e in events if e["type"] == "action_end" and e.get("robot")]
assert ends and all("battery" in e for e in ends), "an action_end without the robot's battery"
assert any(e["type"] == "action_start" and e["action"].startswith("(recharge ") for e in events), "no recharge"
batteries = {e["robot"]: e for e in events if e["type"] == "battery"}
assert set(batteries) == {"robot1", "robot2"}, batteries
for robot, b in batteries.items():
    assert b["lowest"] >= b["reserve"] - 1e-4 and not b["below_reserve"], (robot, b)
assert batteries["robot1"]["lowest"] < 30, "robot1, who fetched senior1's water, never drained"
# Every level an action_end reports is at or above the reserve too.
assert all(e["battery"] >= 20 - 1e-4 for e in ends), [e for e in ends if e["battery"] < 20 - 1e-4]
PY
expect 0 "the same" "$alplan" replay run.jsonl
expect 0 "report/index.html" "$alplan" report run.jsonl --out report
grep -q 'id="batteries"' report/index.html || fail "the report has no battery table"

# A run without --battery logs no battery (its log and summary as before).
expect 0 "summary:" "$alplan" home --until 60 --log plain.jsonl --quiet
! grep -q '"battery"' plain.jsonl || fail "a run without --battery logged a battery"

# A generated home for the battery domain: a dock, batteries, and the planner plans it.
"$alplan" gen home --battery --seniors 8 --robots 2 --seed 3 --out gen.pddl 2>/dev/null
grep -q "(dock " gen.pddl && grep -q "(= (battery robot2) 100)" gen.pddl || fail "gen home --battery: no dock or battery"
expect 0 "status: solved" "$alplan" plan "$here/../../domains/assisted_living/battery/domain.pddl" gen.pddl

expect 2 "reserve" "$alplan" home --battery --battery-reserve 150 --until 60
set +e
"$alplan" home --battery-initial 50 --until 60 >needs.out 2>&1
code=$?
set -e
[ "$code" -ne 0 ] && grep -q -- "--battery" needs.out || fail "--battery-initial without --battery: exit $code: $(cat needs.out)"
echo "home --battery: ok"
