#!/bin/bash
# One engine alone on a list of problems: status, search seconds, expansions.
# usage: ALPLAN=path/to/alplan LIST=problems.txt scan.sh OUT LIMIT [plan flags...]
# (problems.txt: "DOMAIN PROBLEM" per line). 4 GiB address space per run.
out=$1; lim=$2; shift 2
: > "$out"
while read -r d p; do
  r=$( (ulimit -v 4194304; timeout $((lim + 10)) "$ALPLAN" plan "$@" --time-limit "$lim" --json -q "$d" "$p" 2>/dev/null) |
      /usr/bin/python3 -c "
import json, sys
try:
  j = json.load(sys.stdin); s = j.get('statistics', {})
  print(j.get('status'), round(j['seconds']['search'], 2), s.get('expanded'))
except Exception:
  print('no-output')")
  echo "$(basename "$(dirname "$d")") $(basename "$p") $r" >> "$out"
done < "$LIST"
