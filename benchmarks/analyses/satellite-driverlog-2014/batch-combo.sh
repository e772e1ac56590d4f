./run.sh dl1-selfdrive-ehc dl-domain-selfdriving.pddl ../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing/instances/instance-1.pddl --time-limit 30 -q --json --search 'ehc(trpg)'
DL=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing
for i in 1 2 3 4 5; do
  echo "### ground hasdriver dl$i" >> log-ground.txt; nice -n 19 build/cli/alplan ground dl-domain-hasdriver.pddl $DL/instances/instance-$i.pddl >> log-ground.txt 2>&1
done
for i in 1 2 3 4 5; do
./run.sh dl$i-hasdriver-gbfs dl-domain-hasdriver.pddl $DL/instances/instance-$i.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
for i in 3 4; do
./run.sh sat$i-useful-nopower-gbfs sat-domain-useful-nopowershare.pddl sat$i-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh sat$i-useful-offdecal-gbfs sat-domain-useful-offdecal.pddl sat$i-useful.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
bash batch-dl5.sh
