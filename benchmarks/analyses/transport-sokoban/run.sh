#!/bin/bash
# usage: run.sh DOMAIN PROBLEM TIMELIMIT [extra args...]
D=$1; P=$2; T=$3; shift 3
s=$(date +%s.%N)
timeout $((T+15)) nice -n 19 build/cli/alplan plan "$D" "$P" --time-limit $T -q --json "$@" 2>&1
echo "rc=$? wall=$(echo "$(date +%s.%N) - $s" | bc)"
