D=../shared/benchmarks/ipc/ipc-2014/satellite-temporal-satisficing/domain.pddl
for k in 8 12 13; do
./run.sh sat1-first$k-def $D sat1-first$k.pddl --time-limit 20 -q --json --search 'gbfs(trpg, deferred=true)'
done
./run.sh sat1-first8-deftyped $D sat1-first8.pddl --time-limit 20 -q --json --search 'gbfs(trpg, queue=typed, deferred=true)'
