D=../shared/benchmarks/ipc/ipc-2006/pathways-metric-time/domain.pddl
for v in pw2-p107 v-p107-E2g4 v-p107-X2 v-p107-E4g8 v-p107-allchosen v-p107-only; do
 for c in 'ehc(trpg)' 'gbfs(trpg)'; do
  ./run.sh "$v $c" 10 $D $v.pddl --search "$c"
 done
done
