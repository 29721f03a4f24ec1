//! Triangle meshes of boxes, cylinders and spheres, centred on the origin (cylinders along z),
//! with counter-clockwise triangles seen from outside: how an imported model's `<visual>`
//! primitives are drawn once they sit among visual meshes, which replace the collision parts.

use rapier3d::math::Vector;

/// Vertices and counter-clockwise triangles.
pub(crate) type Mesh = (Vec<Vector>, Vec<[u32; 3]>);

/// A box of half extents `h`: its 8 corners and 12 triangles.
pub(crate) fn cuboid(h: Vector) -> Mesh {
    let vertices = (0..8)
        .map(|i| {
            Vector::new(
                if i & 1 == 0 { -h.x } else { h.x },
                if i & 2 == 0 { -h.y } else { h.y },
                if i & 4 == 0 { -h.z } else { h.z },
            )
        })
        .collect();
    let triangles = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    (vertices, triangles)
}

/// An upright cylinder as a prism of `sides` sides, with its two caps.
pub(crate) fn cylinder(radius: f32, half_height: f32, sides: u32) -> Mesh {
    let mut vertices = Vec::with_capacity(2 * sides as usize + 2);
    for z in [-half_height, half_height] {
        vertices.extend((0..sides).map(|k| {
            let a = std::f32::consts::TAU * k as f32 / sides as f32;
            Vector::new(radius * a.cos(), radius * a.sin(), z)
        }));
    }
    let (bottom, top) = (2 * sides, 2 * sides + 1);
    vertices.push(Vector::new(0.0, 0.0, -half_height));
    vertices.push(Vector::new(0.0, 0.0, half_height));
    let mut triangles = Vec::with_capacity(4 * sides as usize);
    for k in 0..sides {
        let next = (k + 1) % sides;
        let (b0, b1, t0, t1) = (k, next, sides + k, sides + next);
        triangles.extend([[b0, b1, t1], [b0, t1, t0], [bottom, b1, b0], [top, t0, t1]]);
    }
    (vertices, triangles)
}

/// A sphere of `stacks` bands from pole to pole and `slices` facets around.
pub(crate) fn sphere(radius: f32, stacks: u32, slices: u32) -> Mesh {
    let mut vertices = vec![Vector::new(0.0, 0.0, radius)];
    for i in 1..stacks {
        let theta = std::f32::consts::PI * i as f32 / stacks as f32;
        vertices.extend((0..slices).map(|j| {
            let phi = std::f32::consts::TAU * j as f32 / slices as f32;
            radius
                * Vector::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                )
        }));
    }
    let south = vertices.len() as u32;
    vertices.push(Vector::new(0.0, 0.0, -radius));
    // Vertex j of ring i (1 ≤ i < stacks).
    let ring = |i: u32, j: u32| 1 + (i - 1) * slices + j % slices;
    let mut triangles = Vec::new();
    for j in 0..slices {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        for i in 1..stacks - 1 {
            let (u0, u1, l0, l1) = (
                ring(i, j),
                ring(i, j + 1),
                ring(i + 1, j),
                ring(i + 1, j + 1),
            );
            triangles.extend([[u0, l0, l1], [u0, l1, u1]]);
        }
        triangles.push([ring(stacks - 1, j), south, ring(stacks - 1, j + 1)]);
    }
    (vertices, triangles)
}
