M=../shared/benchmarks/ipc/ipc-2008/model-train-temporal-satisficing-numeric-fluents
for i in 2 3 4 5; do
 ./run.sh "mt$i default" 30 $M/domain.pddl $M/instances/instance-$i.pddl
 ./run.sh "mt$i ehc(trpg)" 20 $M/domain.pddl $M/instances/instance-$i.pddl --search 'ehc(trpg)'
 ./run.sh "mt$i gbfs(trpg)" 20 $M/domain.pddl $M/instances/instance-$i.pddl --search 'gbfs(trpg)'
 ./run.sh "mt$i gbfs(typed,novelty=2)" 20 $M/domain.pddl $M/instances/instance-$i.pddl --search 'gbfs(trpg, queue=typed, novelty=2)'
 ./run.sh "mt$i wastar(w=3)" 20 $M/domain.pddl $M/instances/instance-$i.pddl --search 'wastar(trpg, w=3)'
done
