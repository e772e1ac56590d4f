import re,sys
# usage: cutgoal.py PROBLEM K OUT  -- keep the first K conjuncts of the goal's (and ...)
src=open(sys.argv[1]).read(); k=int(sys.argv[2])
i=src.index('(:goal')
j=src.index('(and',i)+4
# parse top-level conjuncts
depth=0; conj=[]; start=None; p=j
while True:
    c=src[p]
    if c=='(':
        if depth==0: start=p
        depth+=1
    elif c==')':
        if depth==0: end=p; break
        depth-=1
        if depth==0: conj.append(src[start:p+1])
    p+=1
new=src[:j]+'\n  '+'\n  '.join(conj[:k])+'\n '+src[end:]
open(sys.argv[3],'w').write(new)
print(len(conj), conj[:k])
