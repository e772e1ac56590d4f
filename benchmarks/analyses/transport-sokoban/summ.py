import json,sys
t=open(sys.argv[1]).read()
rc=t[t.rfind('rc='):].strip()
t=t[:t.rfind('rc=')]
try:
    d=json.loads(t)
except Exception as e:
    print("unparsable", t[:500], rc); sys.exit()
b=d.get('best') or {}
print(d['status'], json.dumps(d['statistics']), 'search_s=%.1f'%d['seconds'].get('search',0), 'found=%s'%b.get('found_after_seconds'), 'by=%s'%b.get('search'), 'makespan=%s'%b.get('makespan'), rc, d.get('message','')[:200])
