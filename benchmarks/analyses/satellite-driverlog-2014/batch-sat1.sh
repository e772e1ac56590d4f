B=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing
for i in 1; do
P=$B/instances/instance-$i.pddl
./run.sh sat$i-default $B/domain.pddl $P --time-limit 30 -q --json
./run.sh sat$i-ehc $B/domain.pddl $P --time-limit 30 -q --json --search 'ehc(trpg)'
./run.sh sat$i-gbfs $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat$i-gbfsdef $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg, deferred=true)'
./run.sh sat$i-gbfsdeftyped $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg, queue=typed, deferred=true)'
./run.sh sat$i-nov $B/domain.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg, queue=typed, novelty=2)'
done
