#!/usr/bin/env bash
# Runs `alplan serve`, `alplan wristband tokens` and `alplan wristband
# simulate` as users would: exit codes, messages, a live run with stress
# events on stdout, and a simulator that cannot reach the service.
# Usage: service_command_test.sh ALPLAN WORKDIR
set -euo pipefail
alplan=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"

FAIL_LOG=serve.err
. "$here/expect.sh"

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

# HTTPS: a self-signed certificate for 127.0.0.1; curl and the simulator trust it with --cacert.
openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 2 -subj /CN=localhost \
  -addext subjectAltName=DNS:localhost,IP:127.0.0.1 -keyout key.pem -out cert.pem 2>/dev/null
chmod 644 key.pem
expect 2 "key.pem: error: the TLS key is readable by others (mode 0644); run: chmod 600 key.pem" \
  "$alplan" serve --port 0 --db t.db --tokens tokens.txt --tls-cert cert.pem --tls-key key.pem
chmod 600 key.pem
expect 2 "--tls-cert and --tls-key go together" "$alplan" serve --port 0 --db t.db --tokens tokens.txt --tls-cert cert.pem
expect 2 "error: cannot listen on 0.0.0.0:0: plain HTTP off loopback would carry tokens and readings in clear; give --tls-cert and --tls-key, or --insecure-http" \
  "$alplan" serve --bind 0.0.0.0 --port 0 --db t.db --tokens tokens.txt --no-stress
expect 2 "error: cannot listen on 0.0.0.0:0: plain HTTP off loopback" \
  "$alplan" serve --admin-bind 0.0.0.0 --port 0 --db t.db --tokens tokens.txt --no-stress
"$alplan" serve --bind 0.0.0.0 --port 0 --db t.db --tokens tokens.txt --no-stress --insecure-http --duration 0.5 >insecure.out 2>&1 \
  || fail "--insecure-http: $(cat insecure.out)"
grep -q "serving on http://127.0.0.1:" insecure.out || fail "--insecure-http: $(cat insecure.out)"
"$alplan" serve --port 0 --db t.db --tokens tokens.txt --tls-cert cert.pem --tls-key key.pem >tls.out 2>serve.err &
pid=$!
for _ in $(seq 100); do grep -q "serving on" tls.out && break; sleep 0.2; done
url=$(grep -o 'https://[0-9.]*:[0-9]*' tls.out) || fail "no https 'serving on' line: $(cat tls.out)"
token=$(awk '$1 == "wb-01" {print $2}' tokens.txt)
reading='{"device":"wb-01","boot":9,"seq":0,"t_ms":1700000000000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,"sdnn_ms":null,"rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true}'
answer=$(curl -s --cacert cert.pem -H "Authorization: Bearer $token" -H 'Content-Type: application/json' \
  -d "$reading" -w ' %{http_code}' "$url/v1/readings")
[ "$answer" = '{"duplicates":0,"results":[{"boot":9,"seq":0,"status":"stored"}],"stored":1} 200' ] || fail "https POST: $answer"
curl -s -o /dev/null "$url/healthz" && fail "curl without --cacert trusted the self-signed certificate"
expect 0 "complete: every reading acknowledged" "$alplan" wristband simulate --devices 3 --rate 0.2 --url "$url" \
  --cacert cert.pem --tokens tokens.txt --duration 40 --speed 20
kill -TERM "$pid"
wait "$pid" || fail "serve --tls-cert exited $? after SIGTERM"
# bench service over HTTPS: its wristbands trust the certificate it serves with; zero loss.
expect 0 "| yes |" "$alplan" bench service --devices 3 --rate 0.2 --duration 40 --speed 20 \
  --tls-cert cert.pem --tls-key key.pem --work-dir bench-tls

# Killed (SIGKILL) while wristbands post, then started again on the same port
# and database: every reading acknowledged, none lost, none stored twice, and
# each stressed senior's event stored once.
"$alplan" wristband tokens --devices 4 --out kill-tokens.txt
serve_kill() {
  "$alplan" serve --port "$1" --db k.db --tokens kill-tokens.txt --events-out events.jsonl >>kill.out 2>>kill.err &
  pid=$!
  for _ in $(seq 100); do [ "$(grep -c "serving on" kill.out)" -ge "$2" ] && break; sleep 0.2; done
}
serve_kill 0 1
url=$(grep -o 'http://[0-9.]*:[0-9]*' kill.out | head -1) || fail "no 'serving on' line: $(cat kill.err)"
"$alplan" wristband simulate --devices 4 --rate 1 --duration 60 --speed 6 --stressed 2 --typical-subjects \
  --url "$url" --tokens kill-tokens.txt --drain-timeout 30 --json >simulate.json 2>&1 &
simulate=$!
# Killed once readings flow (about 24 a second), the stress events already raised.
for _ in $(seq 150); do
  [ "$(sqlite3 k.db 'SELECT COUNT(*) FROM readings' 2>/dev/null || echo 0)" -ge 40 ] && break
  sleep 0.1
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
sleep 1
serve_kill "${url##*:}" 2
wait "$simulate" || fail "simulate after the kill: $(cat simulate.json)"
kill -TERM "$pid"
wait "$pid" || fail "serve after the kill exited $?"
made=$(python3 -c 'import json,sys; print(json.load(open("simulate.json"))["made"])')
retries=$(python3 -c 'import json,sys; print(json.load(open("simulate.json"))["retries"])')
[ "$retries" -gt 0 ] || fail "the kill fell outside the run (no retries): $(cat simulate.json)"
stored=$(sqlite3 k.db 'SELECT COUNT(*) FROM readings')
[ "$stored" -eq "$made" ] || fail "after the kill: $made readings made, $stored stored"
[ "$(sqlite3 k.db 'SELECT COUNT(*) FROM stress_events')" -eq 2 ] || fail "events: $(sqlite3 k.db 'SELECT * FROM stress_events')"
[ "$(sqlite3 k.db 'SELECT COUNT(DISTINCT senior) FROM stress_events WHERE stressed = 1')" -eq 2 ] || fail "events"
[ "$(stat -c %a events.jsonl)" = 600 ] || fail "events.jsonl has mode $(stat -c %a events.jsonl), expected 600"
# Printed events: never one twice (one may be missing if the kill fell between commit and print).
[ "$(sort events.jsonl | uniq -d | wc -l)" -eq 0 ] || fail "an event printed twice: $(cat events.jsonl)"

echo "service CLI: all checks passed"
