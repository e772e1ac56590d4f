#!/bin/sh
# A stand-in for an anytime planner in `bench planners --planner` tests: it
# writes its plan, then goes on until the time limit stops it. The plan
# counts. Usage: anytime-planner.sh DOMAIN PROBLEM PLAN
printf '(switch-a)\n(switch-b)\n' > "$3"
exec sleep 600
