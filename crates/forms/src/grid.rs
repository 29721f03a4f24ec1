//! Closed surfaces over a sphere's grid of latitude and longitude: each grid direction is mapped
//! to a point by a function (an ellipsoid, a rounded box, a lumpy floret), vertices are shared,
//! and normals are averaged from the triangles, so the surface shades smoothly.

use crate::Detail;
use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::Vector;
use std::f32::consts::{PI, TAU};

/// A closed surface of `rings` latitude bands and `segments` longitudes: `at(direction)` places
/// the point seen from the centre in that unit direction.
pub(crate) fn sphere_grid(rings: usize, segments: usize, at: impl Fn(Vector) -> Vector) -> Mesh {
    let mut mesh = Mesh::default();
    let direction = |theta: f32, phi: f32| {
        Vector::new(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        )
    };
    let top = mesh.vertex(at(Vector::Z), Vector::Z, Tone::Body);
    for r in 1..rings {
        let theta = PI * r as f32 / rings as f32;
        for s in 0..segments {
            let d = direction(theta, TAU * s as f32 / segments as f32);
            mesh.vertex(at(d), d, Tone::Body);
        }
    }
    let bottom = mesh.vertex(at(-Vector::Z), -Vector::Z, Tone::Body);
    let ring = |r: usize, s: usize| (1 + (r - 1) * segments + s % segments) as u32;
    for s in 0..segments {
        mesh.triangle(top, ring(1, s), ring(1, s + 1));
        mesh.triangle(bottom, ring(rings - 1, s + 1), ring(rings - 1, s));
    }
    for r in 1..rings - 1 {
        for s in 0..segments {
            mesh.quad(
                ring(r, s),
                ring(r + 1, s),
                ring(r + 1, s + 1),
                ring(r, s + 1),
            );
        }
    }
    mesh.smooth_normals();
    mesh
}

/// `x` raised to `power`, keeping its sign.
pub(crate) fn signed_pow(x: f32, power: f32) -> f32 {
    x.signum() * x.abs().powf(power)
}

/// A ball of radius `radius` at `at`, in `tone`, half as finely cut as a form's own surfaces
/// (beads, berries, chips, an eye).
pub(crate) fn ball(at: Vector, radius: f32, detail: Detail, tone: Tone) -> Mesh {
    let b = (detail.bands() / 2).max(3);
    sphere_grid(b, 2 * b, |d| at + d * radius).toned(tone)
}
