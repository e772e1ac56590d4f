DL=../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing
D=$DL/domain.pddl
P=$DL/instances/instance-1.pddl
./run.sh dl1-default $D $P --time-limit 30 -q --json
./run.sh dl1-ehc $D $P --time-limit 30 -q --json --search 'ehc(trpg)'
./run.sh dl1-gbfs $D $P --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh dl1-gbfsdef $D $P --time-limit 30 -q --json --search 'gbfs(trpg, deferred=true)'
./run.sh dl1-gbfsdeftyped $D $P --time-limit 30 -q --json --search 'gbfs(trpg, queue=typed, deferred=true)'
./run.sh dl1-nov $D $P --time-limit 30 -q --json --search 'gbfs(trpg, queue=typed, novelty=2)'
./run.sh dl1-wastar3 $D $P --time-limit 30 -q --json --search 'wastar(trpg, w=3)'
./run.sh dl1-gbfs-nohelp $D $P --time-limit 30 -q --json --search 'gbfs(trpg(helpful=false))'
./run.sh dl1-nodrv-default $D dl1-nodrivergoals.pddl --time-limit 30 -q --json
./run.sh dl1-nodrv-gbfs $D dl1-nodrivergoals.pddl --time-limit 30 -q --json --search 'gbfs(trpg)'
./run.sh dl1-selfdrive-default dl-domain-selfdriving.pddl $P --time-limit 30 -q --json
./run.sh dl1-selfdrive-gbfs dl-domain-selfdriving.pddl $P --time-limit 30 -q --json --search 'gbfs(trpg)'
