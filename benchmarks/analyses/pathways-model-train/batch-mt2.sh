M=../shared/benchmarks/ipc/ipc-2008/model-train-temporal-satisficing-numeric-fluents
for v in A B C D E; do
 ./run.sh "mt2-$v default orig" 10 $M/domain.pddl mt2-$v.pddl
 ./run.sh "mt2-$v default nozero" 10 mt-domain-nozero.pddl mt2-$v.pddl
done
./run.sh "mt2 full default nozero" 30 mt-domain-nozero.pddl $M/instances/instance-2.pddl
