./run.sh dl1-selfdrive-ehc dl-domain-selfdriving.pddl ../shared/benchmarks/ipc/ipc-2014/driver-log-temporal-satisficing/instances/instance-1.pddl --time-limit 30 -q --json --search 'ehc(trpg)'
