#!/usr/bin/env bash
# `alplan home --live` as users run it: the home serves the wristbands in
# the same process; a simulated wristband whose senior becomes stressed
# posts to it; the home hears the stress, reads the face (--emotion: there is
# no camera), makes a goal, plans and executes in real time until the senior
# is comforted. Checked: the log's events for that senior, the same events in
# the service's SQLite database (kept 0600), exit 0 at --until and after
# SIGTERM, replay refusing the live log, report drawing it; bad input exit 2.
# Usage: home_live_test.sh ALPLAN WORKDIR DATA
set -euo pipefail
alplan=$1
work=$2
data=$3
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
FAIL_LOG=home.err
. "$here/expect.sh"
home=$data/home/live-home.pddl

"$alplan" wristband tokens --devices 2 --out tokens-service.txt
# The wristbands belong to the home's seniors.
sed -e 's/senior-01$/senior1/' -e 's/senior-02$/senior2/' tokens-service.txt >tokens.txt && chmod 600 tokens.txt

expect 2 "--live needs --tokens FILE" "$alplan" home --live --port 0 --db bad.db --emotion terrified
expect 2 "--live needs --db FILE" "$alplan" home --live --port 0 --tokens tokens.txt --emotion terrified
expect 2 "--live needs the seniors' face (--face IMAGE) or their emotion (--emotion NAME)" \
  "$alplan" home --live --port 0 --db bad.db --tokens tokens.txt
expect 2 "go with --live" "$alplan" home --db bad.db --until 10
expect 2 "a wristband belongs to senior-01, not a senior of the home" \
  "$alplan" home --live --port 0 --db bad.db --tokens tokens-service.txt --emotion terrified --home "$home"
chmod 644 tokens.txt
expect 2 "tokens.txt: error: the tokens file is readable by others" \
  "$alplan" home --live --port 0 --db bad.db --tokens tokens.txt --emotion terrified --home "$home"
chmod 600 tokens.txt

start=$(date +%s)
"$alplan" home --live --port 0 --db live.db --tokens tokens.txt --emotion terrified --home "$home" --until 35 \
  --planning-time 3 --log live.jsonl >home.out 2>home.err &
pid=$!
for _ in $(seq 150); do grep -q "serving on" home.out && break; sleep 0.2; done
head -1 home.out | grep -q '^serving on http://127.0.0.1:[0-9]* (database live.db' || fail "first line: $(head -3 home.out)"
url=$(head -1 home.out | grep -o 'http://[0-9.]*:[0-9]*')
# senior1's wristband says stressed; senior2's stays calm.
expect 0 "complete: every reading acknowledged" "$alplan" wristband simulate --devices 2 --rate 0.2 --url "$url" \
  --tokens tokens.txt --duration 90 --speed 30 --stressed 1 --typical-subjects
wait "$pid" || fail "home --live exited $? at --until"
elapsed=$(( $(date +%s) - start ))
[ "$elapsed" -ge 34 ] || fail "--until 35 ended after ${elapsed} s of wall time: not real time"
grep -q "comforted" home.out || fail "no comforted line: $(cat home.out)"
grep -q "home: stopped; stored 24 readings" home.err || fail "$(cat home.err)"
for f in live.db live.db-wal live.db-shm; do
  [ ! -e "$f" ] || [ "$(stat -c %a "$f")" = 600 ] || fail "$f has mode $(stat -c %a "$f"), expected 600"
done

"$python" - live.jsonl live.db <<'PY'
import json, sqlite3, sys
events = [json.loads(line) for line in open(sys.argv[1])]
first = events[0]
assert first["type"] == "observation" and first["settings"]["live"] is True, first
mine = [e for e in events if e.get("senior") == "senior1"]
kinds = [e["type"] for e in mine]
for t in ("stress", "emotion", "goal", "comforted"):
    assert t in kinds, f"no {t} event for senior1: {kinds}"
stress = next(e for e in mine if e["type"] == "stress")
assert stress["stressed"] is True and stress["device"] == "wb-01", stress
goal = next(e for e in mine if e["type"] == "goal")
assert goal["goal"] == "(soothed senior1)" and goal["emotion"] == "terrified", goal
comforted = next(e for e in mine if e["type"] == "comforted")
assert comforted["within_window"] is True, comforted
plans = [e for e in events if e["type"] == "plan"]
assert plans and "senior1" in plans[0]["plan"], plans
assert plans[0]["time"] >= goal["time"], (plans[0], goal)
# Real time: the plan's first step waits for the planning budget (3 s).
assert plans[0]["steps"][0]["start"] >= goal["time"] + 3.0 - 1e-6, plans[0]["steps"]
assert not [e for e in events if e.get("senior") == "senior2" and e["type"] == "goal"], "a goal for calm senior2"
for e in events:
    assert e["time"] <= 35.0 + 1e-6, f"an event after --until: {e}"
# The same events, in order, in the service's database.
db = sqlite3.connect(f"file:{sys.argv[2]}?mode=ro", uri=True)
rows = db.execute("SELECT time, type, senior, robot, payload_json FROM home_events ORDER BY id").fetchall()
assert len(rows) == len(events), (len(rows), len(events))
for e, (time, type_, senior, robot, payload) in zip(events, rows):
    assert (e["type"], e["time"], e.get("senior"), e.get("robot")) == (type_, time, senior, robot), (e, rows)
    fields = {k: v for k, v in e.items() if k not in ("type", "time", "senior", "robot")}
    assert json.loads(payload) == fields, (e, payload)
assert db.execute("SELECT COUNT(*) FROM readings").fetchone()[0] == 24
assert db.execute("SELECT COUNT(*) FROM stress_events WHERE senior = 'senior1' AND stressed = 1").fetchone()[0] == 1
PY

expect 2 "a live run cannot be replayed: its inputs came from wristbands" "$alplan" replay live.jsonl
expect 0 "report/index.html" "$alplan" report live.jsonl --out report
grep -q "senior1" report/index.html || fail "the report lacks senior1"

# No --until: it runs until SIGTERM, then stops cleanly on the same database.
"$alplan" home --live --port 0 --db live.db --tokens tokens.txt --emotion terrified --home "$home" --quiet \
  >again.out 2>home.err &
pid=$!
for _ in $(seq 150); do grep -q "serving on" again.out && break; sleep 0.2; done
grep -q "serving on" again.out || fail "no 'serving on' line: $(cat again.out)"
sleep 1
kill -TERM "$pid"
wait "$pid" || fail "home --live exited $? after SIGTERM"
grep -q "summary:" again.out || fail "no summary after SIGTERM: $(cat again.out)"
[ "$("$python" -c "import sqlite3; print(sqlite3.connect('live.db').execute('SELECT COUNT(*) FROM home_events WHERE type = \"observation\"').fetchone()[0])")" = 2 ] ||
  fail "the second run's events are not in the database"
