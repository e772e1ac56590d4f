D=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/domain.pddl
./run.sh sat1-nopointing-gbfs $D sat1-nopointing.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat1-nopointing-default $D sat1-nopointing.pddl --time-limit 30 -q --json
