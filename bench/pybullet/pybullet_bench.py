#!/usr/bin/env python3
"""Time PyBullet on a scene file written by our Rust physics benchmark.

Usage: pybullet_bench.py SCENE.json [--quick]

Scene JSON: {"gravity", "dt", "substeps_per_step", "objects": [{"name", "fixed",
"position", "orientation_xyzw", "density", "friction", "parts": [...]}]}, with
parts {"type": "box", "half_extents"}, {"type": "cylinder", "radius",
"half_height"} (standing along z) or {"type": "sphere", "radius"}, each with an
"offset" in the object's frame. z is up.

Every object becomes one multibody with a compound collision shape (no visual
shape). A dynamic object's mass is density x total part volume; fixed objects
get mass 0.

One *action step* is `substeps_per_step` calls of p.stepSimulation() at dt.
Two measurements, each the median over repeats of a timed block, in ns per
action step:
  idle_ns   scene built with sleeping allowed, settled for SETTLE_STEPS action
            steps, then timed (resting bodies are asleep by then).
  awake_ns  scene rebuilt from scratch, sleeping disabled on every dynamic
            body, settled the same way, then timed.

Sleeping in PyBullet: bodies made by createMultiBody (or loadURDF) can NOT
sleep unless created with flags=p.URDF_ENABLE_SLEEPING, i.e. PyBullet turns
Bullet's deactivation off by default (btMultiBody::setCanSleep(false)). So the
idle run passes that flag; the awake run passes it too (same scene) and then
calls changeDynamics(activationState=ACTIVATION_STATE_DISABLE_SLEEPING), which
makes the awake run equivalent to PyBullet's default behaviour.

Prints one JSON object on stdout.
"""

import argparse
import importlib.metadata
import json
import math
import statistics
import sys
import time

import pybullet as p

SETTLE_STEPS = 300  # action steps before timing
TIMED_STEPS = 100  # action steps per timed block (20 with --quick)
REPEATS = 5  # timed blocks, median taken (1 with --quick)


def part_volume(part):
    kind = part["type"]
    if kind == "box":
        hx, hy, hz = part["half_extents"]
        return 8.0 * hx * hy * hz
    if kind == "cylinder":
        return math.pi * part["radius"] ** 2 * 2.0 * part["half_height"]
    if kind == "sphere":
        return 4.0 / 3.0 * math.pi * part["radius"] ** 3
    raise ValueError(f"unknown part type {kind!r}")


def collision_shape(parts):
    """One compound collision shape holding every part at its offset."""
    types, radii, half_extents, lengths, offsets = [], [], [], [], []
    for part in parts:
        kind = part["type"]
        radius, half, length = 0.0, [0.0, 0.0, 0.0], 0.0
        if kind == "box":
            types.append(p.GEOM_BOX)
            half = list(part["half_extents"])
        elif kind == "cylinder":  # PyBullet cylinders lie along local z, as ours do
            types.append(p.GEOM_CYLINDER)
            radius, length = part["radius"], 2.0 * part["half_height"]
        elif kind == "sphere":
            types.append(p.GEOM_SPHERE)
            radius = part["radius"]
        else:
            raise ValueError(f"unknown part type {kind!r}")
        radii.append(radius)
        half_extents.append(half)
        lengths.append(length)
        offsets.append(list(part.get("offset", [0.0, 0.0, 0.0])))
    return p.createCollisionShapeArray(
        shapeTypes=types,
        radii=radii,
        halfExtents=half_extents,
        lengths=lengths,
        collisionFramePositions=offsets,
    )


def build_scene(scene, sleep_allowed):
    """Reset the world and build every object; returns the dynamic body ids."""
    p.resetSimulation()
    p.setGravity(*scene["gravity"])
    p.setTimeStep(scene["dt"])
    p.setPhysicsEngineParameter(numSubSteps=0)

    dynamic = []
    for obj in scene["objects"]:
        parts = obj["parts"]
        shape = collision_shape(parts)
        if obj["fixed"]:
            mass, com = 0.0, [0.0, 0.0, 0.0]
        else:
            volumes = [part_volume(part) for part in parts]
            total = sum(volumes)
            mass = obj["density"] * total
            # Centre of mass = volume-weighted centroid of the parts. PyBullet
            # derives the inertia itself from the compound shape (Bullet uses
            # the compound's bounding box for that), at this mass.
            com = [sum(v * part.get("offset", [0.0] * 3)[i] for v, part in zip(volumes, parts)) / total
                   for i in range(3)]
        body = p.createMultiBody(
            baseMass=mass,
            baseCollisionShapeIndex=shape,
            baseVisualShapeIndex=-1,
            basePosition=obj["position"],
            baseOrientation=obj["orientation_xyzw"],
            baseInertialFramePosition=com,
            flags=p.URDF_ENABLE_SLEEPING if sleep_allowed else 0,
        )
        p.changeDynamics(body, -1, lateralFriction=obj["friction"])
        if not obj["fixed"]:
            dynamic.append(body)
    return dynamic


def action_steps(count, substeps):
    for _ in range(count * substeps):
        p.stepSimulation()


def time_per_step(steps, substeps, repeats):
    """Median over `repeats` timed blocks of `steps` action steps, in ns per action step."""
    samples = []
    for _ in range(repeats):
        start = time.perf_counter_ns()
        action_steps(steps, substeps)
        samples.append((time.perf_counter_ns() - start) / steps)
    return statistics.median(samples)


def body_state(body):
    pos, orn = p.getBasePositionAndOrientation(body)
    lin, ang = p.getBaseVelocity(body)
    return pos + orn, lin + ang


def count_sleeping(bodies, substeps):
    """How many bodies Bullet has put to sleep.

    getDynamicsInfo does not report the activation state (it returns mass,
    friction, inertia, ..., body type and collision margin only), so sleep is
    detected from its effects: Bullet zeroes a sleeping multibody's
    velocities and stops integrating it. A body counts as asleep when its
    base velocity is exactly zero and its pose is bit-for-bit unchanged over
    one more action step; an awake body resting under gravity keeps tiny
    non-zero velocities from the contact solver. The extra step happens
    outside any timed block.
    """
    before = [body_state(b) for b in bodies]
    action_steps(1, substeps)
    after = [body_state(b) for b in bodies]
    return sum(
        1 for (pose0, _), (pose1, vel1) in zip(before, after)
        if pose0 == pose1 and all(v == 0.0 for v in vel1)
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="scene JSON file")
    parser.add_argument("--quick", action="store_true",
                        help="20 timed action steps, 1 repeat (default: 100 steps, median of 5)")
    args = parser.parse_args()

    with open(args.scene) as f:
        scene = json.load(f)
    substeps = int(scene["substeps_per_step"])
    steps, repeats = (20, 1) if args.quick else (TIMED_STEPS, REPEATS)

    p.connect(p.DIRECT)

    # Idle: sleeping allowed, bodies come to rest and fall asleep while settling.
    dynamic = build_scene(scene, sleep_allowed=True)
    action_steps(SETTLE_STEPS, substeps)
    sleeping = count_sleeping(dynamic, substeps)
    idle_ns = time_per_step(steps, substeps, repeats)

    # Awake: same scene rebuilt fresh, sleeping disabled on every dynamic body.
    dynamic = build_scene(scene, sleep_allowed=True)
    for body in dynamic:
        p.changeDynamics(body, -1, activationState=p.ACTIVATION_STATE_DISABLE_SLEEPING)
    action_steps(SETTLE_STEPS, substeps)
    sleeping_awake = count_sleeping(dynamic, substeps)
    awake_ns = time_per_step(steps, substeps, repeats)

    p.disconnect()

    result = {
        "engine": "pybullet",
        "version": importlib.metadata.version("pybullet"),
        "objects": len(scene["objects"]),
        "dynamic": len(dynamic),
        "idle_ns": round(idle_ns),
        "awake_ns": round(awake_ns),
        "sleeping_after_settle": sleeping,
        # Sanity check: must be 0, sleeping is disabled in the awake run.
        "sleeping_after_settle_awake": sleeping_awake,
        "timed_steps": steps,
        "repeats": repeats,
    }
    if sleeping_awake:
        print(f"warning: {sleeping_awake} bodies asleep in the awake run", file=sys.stderr)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
