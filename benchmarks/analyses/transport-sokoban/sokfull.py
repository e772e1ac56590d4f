import sys
sys.argv=['x','../shared/benchmarks/ipc/ipc-2008/sokoban-temporal-satisficing-strips/instances/instance-3.pddl']
src=open('benchmarks/analyses/transport-sokoban/sokbfs.py').read().split('random.seed(1)')[0]
exec(src.replace("    for s in path: print(s[0], sorted(s[1]))","    pass"))
import collections
c=collections.Counter()
for s in seen:
    if s in alive: continue
    c[(len(s[1]&goals), relaxed_dead(s))]+=1
print('dead states by (stones on goals, flagged by relaxed reachability):', sorted(c.items()))
print('unflagged dead total', sum(v for (k,f),v in c.items() if not f))
