./run.sh sat1-useful-gbfs sat-domain-useful.pddl sat1-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat1-nopower-gbfs sat-domain-nopowershare.pddl ../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/instances/instance-1.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
