./run.sh sat1-useful-default-60 sat-domain-useful.pddl sat1-useful.pddl --time-limit 60 -q --json
./run.sh sat3-useful-offdecal-default-60 sat-domain-useful-offdecal.pddl sat3-useful.pddl --time-limit 60 -q --json
