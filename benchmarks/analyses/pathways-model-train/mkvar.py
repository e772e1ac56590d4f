import re,sys
# mkvar.py SRC OUT GOAL [set:var=value ...] [chosen:x ...] [allchosen] [keeponly:pattern ...]
src,out,goal=sys.argv[1:4]
s=open(src).read()
init_start=s.index('(:init'); goal_start=s.index('(:goal')
head=s[:init_start]; init=s[init_start:goal_start]; 
# strip closing paren of init: init block ends with ')' before (:goal
init=init.rstrip()
assert init.endswith(')')
init=init[:-1]
lines=init.split('\n')
extra=[]
for a in sys.argv[4:]:
    if a.startswith('set:'):
        var,val=a[4:].split('=')
        pat=re.compile(r'\(=\s*\(available\s+'+re.escape(var)+r'\)\s*[0-9.]+\)',re.I)
        n=0
        for i,l in enumerate(lines):
            if pat.search(l): lines[i]=pat.sub(f'(= (available {var}) {val})',l); n+=1
        assert n==1,(var,n)
    elif a.startswith('chosen:'):
        extra.append(f'\t(chosen {a[7:]})')
    elif a=='allchosen':
        for l in list(lines):
            m=re.search(r'\(possible\s+(\S+)\)',l)
            if m: extra.append(f'\t(chosen {m.group(1)})')
    elif a.startswith('drop:'):
        # drop reaction facts (and their numeric facts are harmless) matching regex
        pat=re.compile(a[5:],re.I)
        lines=[l for l in lines if not (re.search(r'^\s*\((association-reaction|catalyzed-association-reaction|synthesis-reaction)',l) and pat.search(l))]
    elif a.startswith('keep:'):
        pat=re.compile(a[5:],re.I)
        lines=[l for l in lines if not (re.search(r'^\s*\((association-reaction|catalyzed-association-reaction|synthesis-reaction)',l) and not pat.search(l))]
init='\n'.join(lines+extra)+')\n\n'
metric=s[s.index('(:metric'):] if '(:metric' in s else ')\n'
open(out,'w').write(head+init+f'(:goal (and {goal}))\n'+metric)
