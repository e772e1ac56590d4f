#!/bin/bash
# usage: run.sh LABEL TIMELIMIT DOMAIN PROBLEM [extra args...]; appends a line to results.tsv
L=$1; T=$2; D=$3; Pr=$4; shift 4
out=$(nice -n 19 timeout $((${T%.*}+15)) build/cli/alplan plan "$D" "$Pr" --time-limit $T -q --json "$@" 2>/dev/null)
python3 - "$L" "$out" <<'PY'
import sys,json
L=sys.argv[1]
try:
  j=json.loads(sys.argv[2])
except Exception as e:
  print(L, "PARSE-ERROR", sys.argv[2][:200]); sys.exit()
s=j.get('statistics',{})
best=j.get('best')
mk=''
if best:
  pass
  mk=f"steps={len(best['steps'])} makespan={best['makespan']} found={best['found_after_seconds']:.2f}s by={best['search']}"
print(f"{L}\t{j['status']}\tsearch={j['seconds']['search']:.1f}s\texp={s.get('expanded')}\teval={s.get('evaluated')}\tgen={s.get('generated')}\tdup={s.get('duplicates')}\tdead={s.get('dead_ends')}\tunsched={s.get('unschedulable')}\t{mk}")
PY
