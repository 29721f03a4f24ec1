//! Flat pieces: a convex outline extruded into a prism with flat faces (a knife's blade, a
//! fork's tines, a shoe's sole).

use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::Vector;

/// A flat piece: the convex polygon `outline` (counter-clockwise in x–y) extruded from `z0` to
/// `z1`, its faces flat.
pub(crate) fn prism(outline: &[(f32, f32)], (z0, z1): (f32, f32), tone: Tone) -> Mesh {
    let mut mesh = Mesh::default();
    let n = outline.len();
    let at = |k: usize, z: f32| Vector::new(outline[k % n].0, outline[k % n].1, z);
    // Top and bottom, fanned from the first corner.
    let top: Vec<u32> = (0..n)
        .map(|k| mesh.vertex(at(k, z1), Vector::Z, tone))
        .collect();
    let bottom: Vec<u32> = (0..n)
        .map(|k| mesh.vertex(at(k, z0), -Vector::Z, tone))
        .collect();
    for k in 1..n - 1 {
        mesh.triangle(top[0], top[k], top[k + 1]);
        mesh.triangle(bottom[0], bottom[k + 1], bottom[k]);
    }
    // Sides, each its own quad with its outward normal.
    for k in 0..n {
        let (a, b) = (at(k, z0), at(k + 1, z0));
        let normal = Vector::new(b.y - a.y, a.x - b.x, 0.0);
        let quad = [at(k, z0), at(k + 1, z0), at(k + 1, z1), at(k, z1)]
            .map(|p| mesh.vertex(p, normal, tone));
        mesh.quad(quad[0], quad[1], quad[2], quad[3]);
    }
    mesh
}
