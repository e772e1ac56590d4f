D=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/domain.pddl
S=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/instances
./run.sh sat1-gbfs-60s $D $S/instance-1.pddl --time-limit 60 -q --json --search 'gbfs(trpg)'
for k in 13 14 15; do
./run.sh sat1-first$k-gbfs $D sat1-first$k.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
done
