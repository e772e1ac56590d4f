P=../shared/benchmarks/ipc/ipc-2006/pathways-metric-time; D=$P/domain.pddl; I=$P/instances/instance-5.pddl
python3 - <<'PY'
import re
s=open('../shared/benchmarks/ipc/ipc-2006/pathways-metric-time/instances/instance-5.pddl').read()
g=s[s.index('(:goal'):s.index('(:metric')]
gs=re.findall(r'\(>= \(\+ [^)]*\) [^)]*\)\) \d+\)',g)
open('benchmarks/analyses/pathways-model-train/pw5-goals.txt','w').write('\n'.join(gs)+'\n')
PY
n=0
while read -r g; do n=$((n+1)); python3 mkvar.py $I v5-g$n.pddl "$g"; ./run.sh "pw5 goal$n only default" 10 $D v5-g$n.pddl; done < pw5-goals.txt
