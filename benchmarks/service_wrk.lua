-- wrk script for the signal service: every request POSTs a valid batch of 12
-- readings (the firmware's JSON, firmware/README.md) for this wrk thread's
-- device, with fresh sequence numbers, so every reading is new and must be
-- stored. Devices and tokens come from WRK_DEVICES="id:token,id:token,...",
-- one per wrk thread (benchmarks/service_wrk.sh sets it up).
local thread_count = 0

function setup(thread)
  thread_count = thread_count + 1
  thread:set("thread_index", thread_count)
end

function init(args)
  local devices = {}
  for id, token in string.gmatch(os.getenv("WRK_DEVICES") or "", "([^:,]+):([^,]+)") do
    table.insert(devices, {id = id, token = token})
  end
  local mine = devices[thread_index]
  if mine == nil then error("WRK_DEVICES lists fewer devices than wrk threads") end
  device = mine.id
  seq = 0
  wrk.headers["Content-Type"] = "application/json"
  wrk.headers["Authorization"] = "Bearer " .. mine.token
end

local reading = '{"device":"%s","boot":0,"seq":%d,"t_ms":%d,"window_ms":30000,"hr_bpm":72.3,"ibi_ms":830.0,'
             .. '"sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,"rejected_fraction":0.063,"motion":false}'

function request()
  local parts = {}
  for i = 1, 12 do
    parts[i] = string.format(reading, device, seq, 1700000000000 + 1000 * seq)
    seq = seq + 1
  end
  return wrk.format("POST", "/v1/readings", nil, "[" .. table.concat(parts, ",") .. "]")
end

function done(summary, latency, requests)
  local e = summary.errors
  io.write(string.format("wrk-summary requests=%d non2xx=%d connect=%d read=%d write=%d timeout=%d "
                         .. "p50_ms=%.3f p99_ms=%.3f seconds=%.3f\n",
                         summary.requests, e.status, e.connect, e.read, e.write, e.timeout,
                         latency:percentile(50) / 1000, latency:percentile(99) / 1000,
                         summary.duration / 1e6))
end
