P=../shared/benchmarks/ipc/ipc-2006/pathways-metric-time
for i in 2 3 5; do
 ./run.sh "pw$i default" 30 $P/domain.pddl $P/instances/instance-$i.pddl
 ./run.sh "pw$i ehc(trpg)" 30 $P/domain.pddl $P/instances/instance-$i.pddl --search 'ehc(trpg)'
 ./run.sh "pw$i gbfs(trpg)" 30 $P/domain.pddl $P/instances/instance-$i.pddl --search 'gbfs(trpg)'
 ./run.sh "pw$i gbfs(typed,novelty=2)" 30 $P/domain.pddl $P/instances/instance-$i.pddl --search 'gbfs(trpg, queue=typed, novelty=2)'
 ./run.sh "pw$i wastar(w=3)" 30 $P/domain.pddl $P/instances/instance-$i.pddl --search 'wastar(trpg, w=3)'
done
