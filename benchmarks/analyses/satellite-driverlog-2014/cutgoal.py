import sys,re
# usage: cutgoal.py IN OUT k   -> keep first k goal conjuncts; or IN OUT idx1,idx2,...  (0-based indices)
src=open(sys.argv[1]).read()
i=src.find('(:goal')
j=src.find('(and',i)+4
# find matching close of (and
depth=1;p=j
while depth>0:
    if src[p]=='(':depth+=1
    elif src[p]==')':depth-=1
    p+=1
body=src[j:p-1]
atoms=re.findall(r'\([^()]*\)',body)
sel=sys.argv[3]
if ',' in sel or sel.startswith('i'):
    idx=[int(x) for x in sel.lstrip('i').split(',') if x]
    keep=[atoms[x] for x in idx]
else:
    keep=atoms[:int(sel)]
out=src[:j]+'\n\t'+'\n\t'.join(keep)+'\n'+src[p-1:]
open(sys.argv[2],'w').write(out)
print(len(atoms),'->',len(keep))
