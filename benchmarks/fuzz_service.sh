#!/usr/bin/env bash
# Fuzzes the signal service's request path (HTTP parser, handler, reading
# JSON, SQLite store) with libFuzzer under ASan and UBSan for SECONDS seconds
# (default 60). Seeds: valid readings and batches. Exit status is non-zero on
# any finding; a crashing input is left in build-fuzz-service/ for replay:
# build-fuzz-service/fuzz_service FILE
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
out=${ALPLAN_FUZZ_DIR:-$root/build-fuzz-service}
mkdir -p "$out/corpus"

service="$root/perception/service"
sources=("$service"/{raw_request,request_handler,reading_message,device_registry,reading_ingest,reading_store}.cpp
         "$service"/{sqlite_database,private_file,service_metrics,latency_histogram,stress_event_queue}.cpp
         "$root/benchmarks/fuzz_service.cpp")
binary="$out/fuzz_service"
newest=$(ls -t "${sources[@]}" "$service"/*.h | head -1)
if [ ! -x "$binary" ] || [ "$newest" -nt "$binary" ]; then
  echo "fuzz: building $binary"
  clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
    -I "$root" "${sources[@]}" -lsqlite3 -lpthread -o "$binary"
fi

seeds="$out/seeds"
if [ ! -d "$seeds" ]; then
  mkdir -p "$seeds"
  reading='{"device":"wb-07","boot":3,"seq":42,"t_ms":1700000030000,"window_ms":30000,"hr_bpm":72.3,"ibi_ms":830.0,"sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,"rejected_fraction":0.063,"motion":false}'
  empty='{"device":"wb-07","boot":3,"seq":43,"t_ms":1700000035000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,"sdnn_ms":null,"rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true}'
  # First byte even: the rest is a body posted with a valid token; odd: a whole request.
  printf '\x00%s' "$reading" > "$seeds/single"
  printf '\x00[%s,%s]' "$reading" "$empty" > "$seeds/batch"
  printf '\x01GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n' > "$seeds/healthz"
  printf '\x01POST /v1/readings HTTP/1.1\r\nHost: x\r\nAuthorization: Bearer fuzz-token-0123456789\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n4\r\n[%s\r\n0\r\n\r\n' "$reading" > "$seeds/chunked"
fi

echo "fuzz: running for ${seconds}s"
cd "$out"
"$binary" -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
  -dict="$root/benchmarks/service.dict" -print_final_stats=1 corpus "$seeds" 2>&1 | tail -n 25
