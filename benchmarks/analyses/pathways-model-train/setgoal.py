import sys,re
src,out,goal=sys.argv[1:4]
s=open(src).read()
i=s.index('(:goal'); j=s.index('(:metric')
extra_init=sys.argv[4:]  # facts to add to init / replacements 'old=>new'
head=s[:i]
for e in extra_init:
    if '=>' in e:
        a,b=e.split('=>'); assert a in head,(a); head=head.replace(a,b)
    else:
        k=head.index('(:init')+len('(:init'); head=head[:k]+'\n    '+e+head[k:]
open(out,'w').write(head+'(:goal (and '+goal+'))\n  '+s[j:])
