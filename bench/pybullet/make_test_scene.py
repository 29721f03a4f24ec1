#!/usr/bin/env python3
"""Write a test scene for pybullet_bench.py (the same JSON format our Rust side writes).

Usage: make_test_scene.py OUT.json

The scene: a 20 x 20 m fixed floor slab (top at z = 0), 10 fixed tables
(0.75 m high top slab on 4 legs) on a 5 x 2 grid, and 190 small dynamic
objects (a deterministic mix of boxes, upright cylinders and spheres, a few cm
in size): 10 on each table top and 90 on the floor between the tables. Every
dynamic object starts 5 mm above its support so that it drops and settles.
Standard library only.
"""

import json
import sys

GRAVITY = [0.0, 0.0, -9.81]
DT = 1.0 / 300.0
SUBSTEPS_PER_STEP = 10

TABLE_TOP_Z = 0.75  # height of the table's top surface
TABLE_HALF = [0.6, 0.4, 0.025]  # table top slab half extents
LEG_HALF = 0.025  # square legs, half side
DROP = 0.005  # initial gap between a dynamic object and its support

# Dynamic object kinds: (part without offset, half height along z).
KINDS = [
    ({"type": "box", "half_extents": [0.04, 0.03, 0.02]}, 0.02),
    ({"type": "cylinder", "radius": 0.03, "half_height": 0.05}, 0.05),
    ({"type": "sphere", "radius": 0.03}, 0.03),
    ({"type": "box", "half_extents": [0.025, 0.025, 0.025]}, 0.025),
    ({"type": "cylinder", "radius": 0.02, "half_height": 0.02}, 0.02),
]


def fixed(name, position, parts, friction=0.7):
    return {
        "name": name,
        "fixed": True,
        "position": position,
        "orientation_xyzw": [0.0, 0.0, 0.0, 1.0],
        "density": 500.0,
        "friction": friction,
        "parts": parts,
    }


def table(index, x, y):
    """Table frame at floor level; the top slab's upper face is at TABLE_TOP_Z."""
    hx, hy, hz = TABLE_HALF
    leg_h = (TABLE_TOP_Z - 2 * hz) / 2  # legs reach from the floor to the slab
    parts = [{"type": "box", "half_extents": TABLE_HALF, "offset": [0.0, 0.0, TABLE_TOP_Z - hz]}]
    for sx in (-1, 1):
        for sy in (-1, 1):
            parts.append({
                "type": "box",
                "half_extents": [LEG_HALF, LEG_HALF, leg_h],
                "offset": [sx * (hx - LEG_HALF), sy * (hy - LEG_HALF), leg_h],
            })
    return fixed(f"table_{index}", [x, y, 0.0], parts)


def dynamic(index, x, y, support_z):
    part, half_z = KINDS[index % len(KINDS)]
    part = dict(part, offset=[0.0, 0.0, 0.0])
    return {
        "name": f"{part['type']}_{index}",
        "fixed": False,
        "position": [round(x, 4), round(y, 4), round(support_z + half_z + DROP, 4)],
        "orientation_xyzw": [0.0, 0.0, 0.0, 1.0],
        "density": 500.0,
        "friction": 0.7,
        "parts": [part],
    }


def make_scene():
    objects = [fixed("floor", [0.0, 0.0, -0.05],
                     [{"type": "box", "half_extents": [10.0, 10.0, 0.05], "offset": [0.0, 0.0, 0.0]}])]

    # 5 x 2 grid of tables, 3 m apart in x and 4 m in y.
    tables = [(-6.0 + 3.0 * i, -2.0 + 4.0 * j) for j in range(2) for i in range(5)]
    for k, (x, y) in enumerate(tables):
        objects.append(table(k, x, y))

    n = 0
    # 10 objects per table top: 5 x 2, 0.2 m apart (the top is 1.2 x 0.8 m).
    for tx, ty in tables:
        for i in range(5):
            for j in range(2):
                objects.append(dynamic(n, tx - 0.4 + 0.2 * i, ty - 0.1 + 0.2 * j, TABLE_TOP_Z))
                n += 1
    # 90 objects on the floor: a 15 x 6 grid along y = 0, between the two table rows.
    for i in range(15):
        for j in range(6):
            objects.append(dynamic(n, -7.0 + 1.0 * i, -0.5 + 0.2 * j, 0.0))
            n += 1

    return {"gravity": GRAVITY, "dt": DT, "substeps_per_step": SUBSTEPS_PER_STEP, "objects": objects}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    scene = make_scene()
    with open(sys.argv[1], "w") as f:
        json.dump(scene, f, indent=1)
    dyn = sum(not o["fixed"] for o in scene["objects"])
    print(f"wrote {sys.argv[1]}: {len(scene['objects'])} objects, {dyn} dynamic", file=sys.stderr)


if __name__ == "__main__":
    main()
