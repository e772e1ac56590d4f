B=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing
P=$B/instances/instance-1.pddl
./run.sh sat1-offdecal-default sat-domain-offdecal.pddl $P --time-limit 30 -q --json
./run.sh sat1-nopower-default sat-domain-nopowershare.pddl $P --time-limit 30 -q --json
./run.sh sat1-offdecal-gbfs sat-domain-offdecal.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg)'
