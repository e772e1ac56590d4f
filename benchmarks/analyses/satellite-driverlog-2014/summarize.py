import json,re,sys
lines=open('benchmarks/analyses/satellite-driverlog-2014/log.txt').read().split('\n')
rows=[]
i=0
while i<len(lines):
    l=lines[i]
    if l.startswith('### '):
        tag=l[4:].split(' :: ')[0]; cmd=l.split(' :: ')[1]
        try: d=json.loads(lines[i+1])
        except Exception: d={}
        rows.append((tag,cmd,d))
        i+=2
    else: i+=1
sel=sys.argv[1] if len(sys.argv)>1 else ''
print('| run | status | search s | setup s | expanded | generated | evaluated | dup | evals/s | children/exp | plan actions | makespan |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|')
for tag,cmd,d in rows:
    if not re.search(sel,tag): continue
    s=d.get('seconds.search',0) or 0
    ev=d.get('statistics.evaluated',0); ex=d.get('statistics.expanded',0); ge=d.get('statistics.generated',0)
    st=d.get('status','?')
    steps=d.get('best.steps','-'); steps=steps.replace('list[','').replace(']','') if isinstance(steps,str) else steps
    print(f"| {tag} | {st} | {s:.1f} | {d.get('seconds.setup',0):.2f} | {ex:,} | {ge:,} | {ev:,} | {d.get('statistics.duplicates',0):,} | {ev/s if s else 0:,.0f} | {ge/ex if ex else 0:.0f} | {steps} | {d.get('best.makespan','-')} |")
