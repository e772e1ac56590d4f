#!/bin/sh
# A stand-in for another planner in `bench planners --planner` tests: it
# reads no file and writes the same two steps for every problem, valid for
# instance-1 and invalid for instance-2 (switch-b locks).
# Usage: scripted-planner.sh DOMAIN PROBLEM PLAN
printf '(switch-a)\n(switch-b)\n' > "$3"
