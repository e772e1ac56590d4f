#!/usr/bin/env bash
# Runs `alplan serve`, `alplan wristband tokens` and `alplan wristband
# simulate` as users would: exit codes, messages, a live run with stress
# events on stdout, and a simulator that cannot reach the service.
# Usage: service_command_test.sh ALPLAN WORKDIR
set -euo pipefail
alplan=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "FAIL: $*" >&2; [ -f serve.err ] && cat serve.err >&2; exit 1; }
# expect CODE TEXT COMMAND...: exit code CODE and TEXT somewhere in the output.
expect() {
  local code=$1 text=$2 out got
  shift 2
  set +e
  out=$("$@" 2>&1)
  got=$?
  set -e
  [ "$got" -eq "$code" ] || fail "$* exited $got, expected $code: $out"
  grep -qF -- "$text" <<<"$out" || fail "$* output lacks '$text': $out"
}

expect 0 "" "$alplan" wristband tokens --devices 3 --out tokens.txt
[ "$(grep -c '^wb-0[123] [0-9a-f]\{32\} senior-0[123]$' tokens.txt)" -eq 3 ] || fail "tokens.txt: $(cat tokens.txt)"
[ "$(stat -c %a tokens.txt)" = 600 ] || fail "tokens.txt has mode $(stat -c %a tokens.txt), expected 600"
expect 2 "tokens.txt: error: the file exists; remove it or give --force" "$alplan" wristband tokens --devices 3 --out tokens.txt
cp tokens.txt tokens-before.txt
expect 0 "" "$alplan" wristband tokens --devices 3 --out tokens.txt --force
[ "$(stat -c %a tokens.txt)" = 600 ] && ! cmp -s tokens.txt tokens-before.txt || fail "--force did not rewrite tokens.txt 0600"
# A tokens file others can read is refused, naming the file and the fix.
cp tokens.txt open.txt && chmod 644 open.txt
expect 2 "open.txt: error: the tokens file is readable by others (mode 0644); run: chmod 600 open.txt" \
  "$alplan" serve --port 0 --db s.db --tokens open.txt --no-stress
printf 'wb-01 short senior\n' > short.txt && chmod 600 short.txt

expect 2 "error: missing.txt: error: cannot open the file" "$alplan" serve --port 0 --db s.db --tokens missing.txt
expect 2 "short.txt:1: error: token too short" "$alplan" serve --port 0 --db s.db --tokens short.txt
expect 2 "--db is required" "$alplan" serve --port 0 --tokens tokens.txt
expect 2 "error: cannot listen on 203.0.113.1:0" "$alplan" serve --bind 203.0.113.1 --port 0 --db s.db --tokens tokens.txt --no-stress
expect 2 "--devices 9 but the tokens file lists only 3" \
  "$alplan" wristband simulate --devices 9 --rate 0.2 --url http://127.0.0.1:9 --tokens tokens.txt
expect 2 "--rate must be between" \
  "$alplan" wristband simulate --devices 1 --rate 5 --url http://127.0.0.1:9 --tokens tokens.txt
expect 2 "URL 'ftp://x': expected http://host:port[/path]" \
  "$alplan" wristband simulate --devices 1 --rate 0.2 --url ftp://x --tokens tokens.txt

"$alplan" serve --port 0 --db s.db --tokens tokens.txt --events-out - >serve.out 2>serve.err &
pid=$!
for _ in $(seq 100); do grep -q "serving on" serve.out && break; sleep 0.2; done
url=$(grep -o 'http://[0-9.]*:[0-9]*' serve.out) || fail "no 'serving on' line"

[ "$(curl -s -o /dev/null -w '%{http_code}' "$url/healthz")" = 200 ] || fail "healthz"
admin=$(grep -o 'serve: admin on http://127.0.0.1:[0-9]*' serve.err | grep -o 'http://.*') || fail "no admin line"
[ "$(curl -s -o /dev/null -w '%{http_code}' "$admin/metrics")" = 200 ] || fail "admin metrics"
[ "$(curl -s -o /dev/null -w '%{http_code}' "$admin/v1/readings")" = 404 ] || fail "readings on the admin port"
answer=$(curl -s -w ' %{http_code}' -H 'Content-Type: application/json' -d '[]' "$url/v1/readings")
[ "$answer" = '{"error":"missing Authorization: Bearer <device token>","reason":"unauthorized"} 401' ] || fail "$answer"

expect 0 "complete: every reading acknowledged" "$alplan" wristband simulate --devices 3 --rate 0.2 --url "$url" \
  --tokens tokens.txt --duration 90 --speed 30 --stressed 1 --typical-subjects
curl -s "$url/metrics" | grep -qx 'alplan_readings_stored_total 36' || fail "metrics: $(curl -s "$url/metrics")"

kill -TERM "$pid"
wait "$pid" || fail "serve exited $? after SIGTERM"
grep -q '"event":"stressed","senior":"senior-01"' serve.out || fail "no stress event: $(cat serve.out)"
[ "$(grep -c '"event"' serve.out)" -eq 1 ] || fail "events for calm seniors: $(cat serve.out)"
grep -q "serve: stopped; stored 36 readings" serve.err || fail "$(cat serve.err)"
for f in s.db s.db-wal s.db-shm; do
  [ ! -e "$f" ] || [ "$(stat -c %a "$f")" = 600 ] || fail "$f has mode $(stat -c %a "$f"), expected 600"
done

# Nothing listens any more: the readings stay queued, the run is incomplete.
expect 1 "INCOMPLETE: some readings not acknowledged" "$alplan" wristband simulate --devices 1 --rate 0.2 \
  --url "$url" --tokens tokens.txt --duration 40 --speed 40 --drain-timeout 0.5
# The service as the deliberation loop's source: a stressed senior's event
# runs emotion -> goal -> plan -> act for that senior, in the same process.
expect 2 "--deliberate: give the seniors' face" "$alplan" serve --port 0 --db d.db --tokens tokens.txt --deliberate
sed 's/senior-01$/senior1/' tokens.txt > tokens-home.txt && chmod 600 tokens-home.txt
"$alplan" serve --port 0 --db d.db --tokens tokens-home.txt --deliberate --emotion terrified >deliberate.out 2>serve.err &
pid=$!
for _ in $(seq 100); do grep -q "serving on" deliberate.out && break; sleep 0.2; done
url=$(grep -o 'http://[0-9.]*:[0-9]*' deliberate.out) || fail "no 'serving on' line with --deliberate"
expect 0 "complete: every reading acknowledged" "$alplan" wristband simulate --devices 2 --rate 0.2 --url "$url" \
  --tokens tokens-home.txt --duration 90 --speed 30 --stressed 1 --typical-subjects
for _ in $(seq 100); do grep -q "deliberation for senior1 ended" deliberate.out && break; sleep 0.2; done
kill -TERM "$pid"
wait "$pid" || fail "serve --deliberate exited $? after SIGTERM"
grep -q "\[service\] senior1 is stressed (wb-01): deliberating" deliberate.out || fail "$(cat deliberate.out)"
grep -q "Outcome: the goal (soothed senior1) holds" deliberate.out || fail "no comforted senior: $(cat deliberate.out)"
grep -q "deliberation for senior1 ended with exit 0" deliberate.out || fail "$(cat deliberate.out)"

echo "service CLI: all checks passed"
