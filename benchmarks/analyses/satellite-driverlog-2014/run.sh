#!/bin/bash
# usage: run.sh TAG DOMAIN PROBLEM [args...]  -- logs command and JSON to benchmarks/analyses/satellite-driverlog-2014/log.txt
tag=$1; shift
echo "### $tag :: nice -n 19 build/cli/alplan plan $*" >> benchmarks/analyses/satellite-driverlog-2014/log.txt
s=$(date +%s.%N)
out=$(nice -n 19 build/cli/alplan plan "$@" 2>&1)
e=$(date +%s.%N)
echo "$out" | grep -v '^[0-9.]*: (' > benchmarks/analyses/satellite-driverlog-2014/out-$tag.txt
echo "$out" > benchmarks/analyses/satellite-driverlog-2014/full-$tag.txt
echo "$out" | python3 -c '
import sys,json
t=sys.stdin.read()
i=t.find("{")
try:
  d=json.loads(t[i:])
  def flat(d,p=""):
    r={}
    for k,v in d.items():
      if isinstance(v,dict): r.update(flat(v,p+k+"."))
      elif isinstance(v,list): r[p+k]="list[%d]"%len(v)
      else: r[p+k]=v
    return r
  print(json.dumps(flat(d)))
except Exception as ex: print("RAW", t[-1500:])
' >> benchmarks/analyses/satellite-driverlog-2014/log.txt
echo "wall $(echo "$e - $s" | bc)" >> benchmarks/analyses/satellite-driverlog-2014/log.txt
tail -2 benchmarks/analyses/satellite-driverlog-2014/log.txt
