#!/usr/bin/env bash
# Side-by-side goal-evaluation benchmark: our Rust BDDL vs the reference
# Python implementation (PyPI bddl==1.0.1) on the 100 official activities.
#
# Usage (from the repository root):
#   bench/side_by_side.sh [ARGS...]
#
# ARGS (e.g. --quick) are passed unchanged to both sides:
#   target/release/behavior bddl bench --json --reference-counting ARGS...
#   bench/reference/bddl_reference_bench.py ARGS...
# Ours counts options as the reference does (a literal repeated in an option counts each time),
# so that the Q values compared are the same quantity; by default ours counts them as sets.
#
# Environment:
#   PYTHON      interpreter used to create the venv (default: python3)
#   BENCH_VENV  venv location (default: target/bench-venv)
#
# Outputs target/bench-ours.json and target/bench-reference.json, then prints
# a per-activity table and summary (bench/reference/join.py).
#
# The reference needs bddl plus only what it actually imports: `future`
# (logic_base), `numpy` (condition_evaluation), `networkx` and `IPython`
# (object_taxonomy, imported by bddl.activity). bddl's own setup.py also pulls
# pytest and jupytext, which are never imported, hence --no-deps. The pins are
# the versions verified with Python 3.11.
set -euo pipefail

cd "$(dirname "$0")/.."

PYTHON=${PYTHON:-python3}
VENV=${BENCH_VENV:-target/bench-venv}
OURS_JSON=target/bench-ours.json
REF_JSON=target/bench-reference.json

if ! "$VENV/bin/python" -c 'import bddl.activity' 2>/dev/null; then
    echo "== setting up reference venv in $VENV" >&2
    [ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
    # Runtime imports first, bddl last: installing bddl before them makes pip
    # complain about its unused pytest/jupytext requirements.
    "$VENV/bin/pip" install -q --disable-pip-version-check \
        future==1.0.0 numpy==2.4.6 networkx==3.6.1 ipython==9.18.1
    "$VENV/bin/pip" install -q --disable-pip-version-check --no-deps bddl==1.0.1
    "$VENV/bin/python" -c 'import bddl.activity'
fi

echo "== building behavior (release)" >&2
cargo build --release -p behavior-cli

echo "== ours" >&2
target/release/behavior bddl bench --json --reference-counting "$@" > "$OURS_JSON"

echo "== reference (bddl 1.0.1)" >&2
"$VENV/bin/python" bench/reference/bddl_reference_bench.py "$@" > "$REF_JSON"

python3 bench/reference/join.py "$OURS_JSON" "$REF_JSON"
