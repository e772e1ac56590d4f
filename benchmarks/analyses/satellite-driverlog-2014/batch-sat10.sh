for i in 3 4; do
./run.sh sat$i-useful-nopower-gbfs sat-domain-useful-nopowershare.pddl sat$i-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat$i-useful-offdecal-gbfs sat-domain-useful-offdecal.pddl sat$i-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
