DL=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing
S=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing
./run.sh cal-dl5-gbfs $DL/domain.pddl $DL/instances/instance-5.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
./run.sh cal-dl5-hasdriver-gbfs dl-domain-hasdriver.pddl $DL/instances/instance-5.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
./run.sh cal-dl1-gbfs $DL/domain.pddl $DL/instances/instance-1.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh cal-sat1-gbfs $S/domain.pddl $S/instances/instance-1.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
./run.sh cal-sat1-useful-gbfs sat-domain-useful.pddl sat1-useful.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
