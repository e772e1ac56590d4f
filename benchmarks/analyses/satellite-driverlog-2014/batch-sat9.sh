B=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing
for i in 3 4 5; do
./run.sh sat$i-useful-gbfs sat-domain-useful.pddl sat$i-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
for i in 3 4 5; do
P=$B/instances/instance-$i.pddl
./run.sh sat$i-default $B/domain.pddl $P --time-limit 30 -q --json
./run.sh sat$i-gbfs $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat$i-gbfsdef $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg, deferred=true)'
./run.sh sat$i-gbfsdeftyped $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg, queue=typed, deferred=true)'
done
bash batch-dl1.sh
