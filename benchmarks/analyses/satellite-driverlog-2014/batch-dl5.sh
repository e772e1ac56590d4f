D=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing/domain.pddl
./run.sh dl1-pkgonly-ehc $D dl1-packagesonly.pddl --time-limit 30 -q --json --search 'ehc(trpg)'
./run.sh dl1-notruck-ehc $D dl1-notruckgoals.pddl --time-limit 30 -q --json --search 'ehc(trpg)'
./run.sh dl1-pkgonly-gbfs $D dl1-packagesonly.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh dl1-notruck-gbfs $D dl1-notruckgoals.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
