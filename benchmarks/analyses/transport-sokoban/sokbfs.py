# Sequential state space of a temporal Sokoban instance (durations 1, no concurrency needed:
# a move/push needs (clear to) at start, which another player's end gives back, so overlap buys nothing).
# State: (player positions tuple, frozenset of stone positions). Stones are interchangeable for the goal.
import re,sys,collections,time
f=sys.argv[1]; cap=int(sys.argv[2]) if len(sys.argv)>2 else 10**7
t=open(f).read()
adj=collections.defaultdict(dict)
for a,b,d in re.findall(r'\(MOVE-DIR (\S+) (\S+) (\S+)\)',t): adj[a][d]=b
goals=frozenset(re.findall(r'\(IS-GOAL (\S+)\)',t))
init=t[t.index('(:init'):t.index('(:goal')]
players=tuple(l for p,l in sorted(re.findall(r'\(at (player-\d+) (\S+)\)',init)))
stones=frozenset(l for s,l in re.findall(r'\(at (stone-\d+) (\S+)\)',init))
def succ(s):
    ps,st=s
    occ=set(ps)|st
    for i,p in enumerate(ps):
        for d,q in adj[p].items():
            if q not in occ:
                yield (ps[:i]+(q,)+ps[i+1:],st)
            elif q in st:
                r=adj[q].get(d)
                if r and r not in occ:
                    yield (ps[:i]+(q,)+ps[i+1:], (st-{q})|{r})
s0=(players,stones)
seen={s0:None}; q=collections.deque([s0]); depth={s0:0}; goal=None; edges=collections.defaultdict(list)
t0=time.time()
while q:
    s=q.popleft()
    for n in succ(s):
        edges[n].append(s)
        if n not in seen:
            seen[n]=s; depth[n]=depth[s]+1; q.append(n)
            if goal is None and n[1]<=goals: goal=n
    if len(seen)>cap: print('cap reached'); break
print('reachable states',len(seen),'bfs s %.1f'%(time.time()-t0))
goalstates=[s for s in seen if s[1]<=goals]
print('goal states',len(goalstates),'shortest plan (sequential steps)',depth[goal] if goal else None)
# backward: states from which a goal is reachable
alive=set(goalstates); q=collections.deque(goalstates)
while q:
    s=q.popleft()
    for p in edges[s]:
        if p not in alive: alive.add(p); q.append(p)
print('alive',len(alive),'dead',len(seen)-len(alive))
# dead states by the number of stones on goals
c=collections.Counter((len(s[1]&goals), s in alive) for s in seen)
print('by stones on goals (k, alive): count', sorted(c.items()))
# path
if goal:
    path=[];s=goal
    while s: path.append(s); s=seen[s]
    path.reverse()
    for s in path: print(s[0], sorted(s[1]))

# Which dead states does delete-relaxed reachability (what the TRPG's dead-end test can see, read as classical) flag?
import random
cells=set(adj)|{b for a in adj for b in adj[a].values()}
def relaxed_dead(s):
    ps,st=s
    occ=set(ps)|st
    clear={c for c in cells if c not in occ}
    pl=set(ps)  # players interchangeable for reachability of cells
    stones=[{x} for x in st]
    changed=True
    while changed:
        changed=False
        for c in list(pl):
            for d,q in adj[c].items():
                if q in clear and q not in pl: pl.add(q); changed=True
        for S in stones:
            for x in list(S):
                for d,q in adj[x].items():
                    # push from ppos (behind x, direction d) to q
                    pp=[c for c in pl if adj[c].get(d)==x]
                    if pp and q in clear and q not in S:
                        S.add(q); changed=True
                        if x not in pl: pl.add(x)
                        for c in pp: clear.add(c)
                    if pp and x not in pl: pl.add(x); changed=True
        # clear grows: a cell a player or stone could leave
        for c in list(pl):
            if c not in clear and any(adj[c].get(d) in pl for d in adj[c]): clear.add(c); changed=True
    return any(not (S & goals) for S in stones)
random.seed(1)
dead=[s for s in seen if s not in alive]
sample=random.sample(dead,min(5000,len(dead)))
flag=sum(relaxed_dead(s) for s in sample)
print('dead states sampled',len(sample),'flagged by relaxed reachability',flag)
al=random.sample(sorted(alive,key=str),min(2000,len(alive)))
print('alive states sampled',len(al),'wrongly flagged',sum(relaxed_dead(s) for s in al))
