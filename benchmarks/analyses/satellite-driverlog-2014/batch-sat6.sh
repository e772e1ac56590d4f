D=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/domain.pddl
./run.sh sat1-g13only-gbfs $D sat1-g13only.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
./run.sh sat1-first12plus14-gbfs $D sat1-first12plus14.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
./run.sh sat1-no13-gbfs $D sat1-no13.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
