#!/usr/bin/env bash
# Side-by-side physics benchmark: our simulator (rapier3d) vs PyBullet on the
# same scene.
#
# Usage (from anywhere; runs from the repository root):
#   bench/physics_side_by_side.sh [ARGS...]
#
# ARGS go unchanged to our side (examples/physics_bench); --quick, if among
# them, is also passed to the PyBullet side.
#
# Our side writes the scene to target/physics-scene.json and prints its
# timings; bench/pybullet/pybullet_bench.py then times PyBullet on that scene.
# Both report ns per action step (substeps_per_step physics steps), with the
# scene at rest and asleep (idle) and with sleeping disabled (awake).
#
# Environment:
#   PYTHON           interpreter used to create the venv (default: python3)
#   PYBULLET_VENV    venv location (default: target/pybullet-venv)
#
# Outputs target/physics-ours.json and target/physics-pybullet.json, then
# prints a table with the ratios pybullet / ours (> 1: we are faster).
#
# pybullet 3.2.7 ships a manylinux wheel for CPython 3.11 on x86_64 (~100 MB,
# installs in seconds, no compiling). Its extension imports numpy without
# declaring it as a dependency, hence numpy here. The pins are the versions
# verified with Python 3.11.
set -euo pipefail

cd "$(dirname "$0")/.."

PYTHON=${PYTHON:-python3}
VENV=${PYBULLET_VENV:-target/pybullet-venv}
SCENE=target/physics-scene.json
OURS_JSON=target/physics-ours.json
PB_JSON=target/physics-pybullet.json

# Only --quick is understood by the PyBullet side.
PB_ARGS=()
for arg in "$@"; do
    if [ "$arg" = "--quick" ]; then PB_ARGS+=(--quick); fi
done

if ! "$VENV/bin/python" -c 'import pybullet' 2>/dev/null; then
    echo "== setting up pybullet venv in $VENV" >&2
    [ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
    "$VENV/bin/pip" install -q --disable-pip-version-check numpy==2.4.6 pybullet==3.2.7
    "$VENV/bin/python" -c 'import pybullet' 2>/dev/null
fi

echo "== ours (behavior-sim, rapier3d)" >&2
cargo run --release -p behavior-sim --example physics_bench -- --scene "$SCENE" --json "$@" > "$OURS_JSON"

echo "== pybullet" >&2
"$VENV/bin/python" bench/pybullet/pybullet_bench.py "$SCENE" ${PB_ARGS[@]+"${PB_ARGS[@]}"} > "$PB_JSON"

python3 - "$OURS_JSON" "$PB_JSON" <<'EOF'
import json
import sys

ours, pb = (json.load(open(path)) for path in sys.argv[1:3])

if (ours.get("objects"), ours.get("dynamic")) != (pb.get("objects"), pb.get("dynamic")):
    print(f"warning: scene sizes differ: ours {ours.get('objects')}/{ours.get('dynamic')}, "
          f"pybullet {pb.get('objects')}/{pb.get('dynamic')} (objects/dynamic)")

print(f"scene: {pb['objects']} objects, {pb['dynamic']} dynamic; "
      f"pybullet {pb['version']}: {pb['sleeping_after_settle']} asleep after settling")
print()
print(f"{'ns per action step':<20}{'ours':>14}{'pybullet':>14}{'pybullet/ours':>16}")
for key in ("idle_ns", "awake_ns"):
    a, b = ours[key], pb[key]
    ratio = f"{b / a:.2f}x" if a > 0 else "inf"
    print(f"{key:<20}{a:>14,.0f}{b:>14,.0f}{ratio:>16}")
extra = {k: v for k, v in ours.items() if k.endswith("_ns") and k not in ("idle_ns", "awake_ns")}
if extra:
    print("ours, also: " + ", ".join(f"{k} {v:,.0f}" for k, v in extra.items()))
EOF
