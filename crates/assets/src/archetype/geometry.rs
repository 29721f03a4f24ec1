//! The building blocks every family shares: boxes from corners, hulls, and the point clouds of
//! ellipsoids and prisms, plus the two box assemblies (an open-topped tub, a carcass open at the
//! front) that containers, cabinets and appliances are made of.

use behavior_sim::{Part, Primitive};
use rapier3d::math::Vector;

/// Shorthand for a vector, so that coordinates read as coordinates.
pub(super) fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

/// A box from its centre and half extents, never thinner than 1 mm (a zero extent would be a
/// degenerate collider).
fn cuboid(center: Vector, half: Vector) -> Part {
    Part::at(
        Primitive::Box {
            half_extents: half.max(Vector::splat(0.0005)),
        },
        center,
    )
}

/// A box from its min and max corners.
pub(super) fn span(min: Vector, max: Vector) -> Part {
    cuboid((min + max) * 0.5, (max - min) * 0.5)
}

/// Wall thickness for a container of this footprint.
pub(super) fn wall(size: Vector) -> f32 {
    (0.06 * size.x.min(size.y)).clamp(0.004, 0.03)
}

/// Bottom and four walls filling the box `min..max` (open at the top).
pub(super) fn tub(min: Vector, max: Vector, t: f32) -> Vec<Part> {
    vec![
        span(min, v(max.x, max.y, min.z + t)),
        span(min, v(min.x + t, max.y, max.z)),
        span(v(max.x - t, min.y, min.z), max),
        span(min, v(max.x, min.y + t, max.z)),
        span(v(min.x, max.y - t, min.z), max),
    ]
}

/// A carcass open at the front (−y): bottom, top, sides, back.
pub(super) fn carcass(min: Vector, max: Vector, t: f32) -> Vec<Part> {
    vec![
        span(min, v(max.x, max.y, min.z + t)),
        span(v(min.x, min.y, max.z - t), max),
        span(min, v(min.x + t, max.y, max.z)),
        span(v(max.x - t, min.y, min.z), max),
        span(v(min.x, max.y - t, min.z), max),
    ]
}

/// The corners of a box with every edge cut by `c`.
pub(super) fn chamfered(min: Vector, max: Vector, c: f32) -> Vec<Vector> {
    let mut points = Vec::with_capacity(24);
    for x in [min.x, max.x] {
        for y in [min.y, max.y] {
            for z in [min.z, max.z] {
                // One step in from the corner along each pair of axes.
                let inward = |a: f32, lo: f32| if a == lo { a + c } else { a - c };
                points.push(v(x, inward(y, min.y), inward(z, min.z)));
                points.push(v(inward(x, min.x), y, inward(z, min.z)));
                points.push(v(inward(x, min.x), inward(y, min.y), z));
            }
        }
    }
    points
}

/// The convex hull of points, as a part at the object's origin.
pub(super) fn hull(points: Vec<Vector>) -> Part {
    Part::new(Primitive::ConvexHull { points })
}

/// Points on an ellipsoid filling a box of `size` standing at z = 0, those `keep` accepts, plus
/// points where the cut plane x = 0 meets it (so a half closes flat).
pub(super) fn ellipsoid(size: Vector, keep: impl Fn(Vector) -> bool) -> Vec<Vector> {
    let r = size * 0.5;
    let mut points = Vec::new();
    for i in 0..=8 {
        let theta = std::f32::consts::PI * i as f32 / 8.0;
        for j in 0..16 {
            let phi = std::f32::consts::TAU * j as f32 / 16.0;
            let unit = v(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let p = unit * r + v(0.0, 0.0, r.z);
            if keep(p) || unit.x.abs() < 1e-6 {
                points.push(p);
            }
        }
    }
    points
}

/// Points of a regular `sides`-gon prism of radius `radius` and height `height` (those `keep`
/// accepts, plus the cut plane's).
pub(super) fn prism(
    radius: f32,
    height: f32,
    sides: usize,
    keep: impl Fn(Vector) -> bool,
) -> Vec<Vector> {
    let mut points = Vec::new();
    for k in 0..sides {
        let a = std::f32::consts::TAU * (k as f32 + 0.5) / sides as f32;
        for z in [0.0, height] {
            let p = v(radius * a.cos(), radius * a.sin(), z);
            if keep(p) {
                points.push(p);
            }
        }
    }
    for z in [0.0, height] {
        points.push(v(0.0, -radius, z));
        points.push(v(0.0, radius, z));
    }
    points
}
