#!/usr/bin/env bash
# `pip install .` into a fresh virtual environment, offline (Debian's
# setuptools, no build isolation), reusing the configured build tree; then
# the installed module plans from outside the source tree.
set -euo pipefail
python=$1 root=$2 build=$3 work=$4 shared=$5
rm -rf "$work" && mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/venv"
ALPLAN_BUILD_DIR="$build" "$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$root"
cd "$work"
"$work/venv/bin/python" - "$shared" <<'PY'
import os, sys
import alplan
assert "venv" in alplan.__file__, alplan.__file__
match = os.path.join(sys.argv[1], "benchmarks", "ipc", "ipc-2014", "match-cellar-temporal-satisficing")
result = alplan.plan(os.path.join(match, "domain.pddl"), os.path.join(match, "instances", "instance-1.pddl"), time_limit=30)
assert result.status == "solved", result.status
print("installed module at", alplan.__file__, "planned", len(result.steps), "steps")
PY
