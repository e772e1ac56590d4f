D=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/domain.pddl
for k in 4 8 12 16 20; do
./run.sh sat1-first$k-gbfs $D sat1-first$k.pddl --time-limit 20 -q --json --search 'gbfs(trpg)'
done
