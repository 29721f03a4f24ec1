//! Flat pieces: a convex outline extruded into a prism with flat faces (a knife's blade, a
//! fork's tines, a shoe's sole), lying in x–y or standing in x–z.

use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::{Rotation, Vector};
use std::f32::consts::FRAC_PI_2;

/// A flat piece: the convex polygon `outline` in x–y extruded from `z0` to `z1`, its faces flat.
/// The outline may run either way round (a left piece written as its right one mirrored): a
/// clockwise one is taken counter-clockwise.
pub(crate) fn prism(outline: &[(f32, f32)], (z0, z1): (f32, f32), tone: Tone) -> Mesh {
    let turned: Vec<(f32, f32)>;
    let outline = if twice_area(outline) < 0.0 {
        turned = outline.iter().rev().copied().collect();
        &turned
    } else {
        outline
    };
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

/// Twice the signed area of a polygon: positive when it runs counter-clockwise.
fn twice_area(outline: &[(f32, f32)]) -> f32 {
    let n = outline.len();
    (0..n)
        .map(|k| {
            let ((x0, y0), (x1, y1)) = (outline[k], outline[(k + 1) % n]);
            x0 * y1 - x1 * y0
        })
        .sum()
}

/// A flat piece whose outline is in the x–z plane (x, then z), extruded across y from `y0` to
/// `y1`: a car's cabin, a carton's gable, a lens.
pub(crate) fn prism_across_y(outline: &[(f32, f32)], (y0, y1): (f32, f32), tone: Tone) -> Mesh {
    // A quarter turn about x takes (x, y, z) to (x, −z, y): the extrusion's z becomes −y.
    let mut made = prism(outline, (-y1, -y0), tone);
    made.turn(Rotation::from_rotation_x(FRAC_PI_2), Vector::ZERO);
    made
}
