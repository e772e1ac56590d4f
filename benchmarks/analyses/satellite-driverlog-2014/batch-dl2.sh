DL=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing
D=$DL/domain.pddl
./run.sh dl1-nodrv-ehc $D dl1-nodrivergoals.pddl --time-limit 30 -q --json --search 'ehc(trpg)'
./run.sh dl1-gbfs-go $D $DL/instances/instance-1.pddl --time-limit 30 -q --json --search 'gbfs(trpg, goal_orders=true)'
for i in 2 3 4 5; do
  echo "### ground dl$i" >> log-ground.txt; nice -n 19 build/cli/alplan ground $D $DL/instances/instance-$i.pddl >> log-ground.txt 2>&1
done
for i in 2 3 4 5; do
P=$DL/instances/instance-$i.pddl
./run.sh dl$i-gbfs $D $P --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh dl$i-default $D $P --time-limit 30 -q --json
./run.sh dl$i-nodrv-gbfs $D dl$i-nodrivergoals.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
done
./run.sh sat3-useful-gbfs-60 sat-domain-useful.pddl sat3-useful.pddl --time-limit 60 -q --json --search 'gbfs(trpg)'
./run.sh sat4-useful-gbfs-60 sat-domain-useful.pddl sat4-useful.pddl --time-limit 60 -q --json --search 'gbfs(trpg)'
