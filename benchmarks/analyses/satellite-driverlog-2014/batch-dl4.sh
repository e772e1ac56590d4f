DL=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing
for i in 1 2 3 4 5; do
  echo "### ground hasdriver dl$i" >> log-ground.txt; nice -n 19 build/cli/alplan ground dl-domain-hasdriver.pddl $DL/instances/instance-$i.pddl >> log-ground.txt 2>&1
done
for i in 1 2 3 4 5; do
./run.sh dl$i-hasdriver-gbfs dl-domain-hasdriver.pddl $DL/instances/instance-$i.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
