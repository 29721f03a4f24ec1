//! A reproducible benchmark scene: a resting home-like room of 201 objects.
//!
//! A 20 × 20 m floor, 10 tables (a top on four legs) and 190 small boxes, cylinders and balls
//! resting on the tables and the floor. Used by the physics benchmarks and written out for the
//! PyBullet side-by-side (`bench/physics_side_by_side.sh`). Shared by the benches and the
//! `physics_bench` example; not part of the library's API.

use behavior_sim::{ObjectSpec, Part, Primitive};
use rapier3d::math::Vector;

fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

fn cuboid(x: f32, y: f32, z: f32) -> Primitive {
    Primitive::Box {
        half_extents: v(x, y, z),
    }
}

/// The scene's objects, fixed ones first.
pub fn resting_home() -> Vec<ObjectSpec> {
    let mut specs = vec![
        ObjectSpec::new(
            "floor",
            "floor.n.01",
            vec![Part::new(cuboid(10.0, 10.0, 0.05))],
        )
        .at(v(0.0, 0.0, -0.05))
        .fixed(),
    ];
    let mut tables = Vec::new();
    for t in 0..10 {
        let (x, y) = (-8.0 + 4.0 * (t % 5) as f32, -4.0 + 8.0 * (t / 5) as f32);
        let mut parts = vec![Part::at(cuboid(0.6, 0.4, 0.025), v(0.0, 0.0, 0.725))];
        for (lx, ly) in [(-0.55, -0.35), (0.55, -0.35), (-0.55, 0.35), (0.55, 0.35)] {
            parts.push(Part::at(cuboid(0.025, 0.025, 0.35), v(lx, ly, 0.35)));
        }
        specs.push(
            ObjectSpec::new(&format!("table_{t}"), "table.n.02", parts)
                .at(v(x, y, 0.0))
                .fixed(),
        );
        tables.push((x, y));
    }
    for i in 0..190 {
        let primitive = match i % 3 {
            0 => cuboid(0.04, 0.03, 0.02),
            1 => Primitive::Cylinder {
                radius: 0.03,
                half_height: 0.05,
            },
            _ => Primitive::Sphere { radius: 0.035 },
        };
        let height = match primitive {
            Primitive::Box { half_extents } => half_extents.z,
            Primitive::Cylinder { half_height, .. } => half_height,
            Primitive::Sphere { radius } | Primitive::Capsule { radius, .. } => radius,
            Primitive::ConvexHull { .. } => unreachable!("the scene uses simple primitives"),
        };
        // 12 objects on each table in a grid, the rest on the floor in rows.
        let at = if i < 120 {
            let (tx, ty) = tables[i / 12];
            let k = i % 12;
            v(
                tx - 0.45 + 0.3 * (k % 4) as f32,
                ty - 0.25 + 0.25 * (k / 4) as f32,
                0.75 + height + 0.01,
            )
        } else {
            let k = i - 120;
            v(
                -7.0 + 0.5 * (k % 28) as f32,
                1.0 + 0.5 * (k / 28) as f32,
                height + 0.01,
            )
        };
        let mut spec = ObjectSpec::new(
            &format!("thing_{i}"),
            "thing.n.01",
            vec![Part::new(primitive)],
        )
        .at(at);
        spec.angular_damping = 0.0; // as in PyBullet's defaults
        specs.push(spec);
    }
    specs
}
