//! Tubes swept along a path with capped ends: handles, a banana, stems.

use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::Vector;
use std::f32::consts::TAU;

/// A tube through `path` (at least two points, none repeated) of radius `radius(i, θ)` at point
/// `i` and angle `θ` around it, `sides` vertices around, with flat caps at both ends.
pub(crate) fn tube(
    path: &[Vector],
    sides: usize,
    radius: impl Fn(usize, f32) -> f32,
    tone: Tone,
) -> Mesh {
    let n = path.len();
    let tangent = |i: usize| {
        let (a, b) = (path[i.saturating_sub(1)], path[(i + 1).min(n - 1)]);
        (b - a).normalize_or(Vector::X)
    };
    // A frame carried along the path without twisting (parallel transport).
    let first = tangent(0);
    let seed = if first.z.abs() < 0.9 {
        Vector::Z
    } else {
        Vector::X
    };
    let mut normal = (seed - first * seed.dot(first)).normalize();
    let mut frames = Vec::with_capacity(n);
    for i in 0..n {
        let t = tangent(i);
        normal = (normal - t * normal.dot(t)).normalize_or(normal);
        frames.push((t, normal, t.cross(normal)));
    }
    let mut mesh = Mesh::default();
    let ring = |mesh: &mut Mesh, i: usize, cap: Option<Vector>| {
        let (_, u, w) = frames[i];
        let start = mesh.positions.len() as u32;
        for s in 0..sides {
            let theta = TAU * s as f32 / sides as f32;
            let out = u * theta.cos() + w * theta.sin();
            mesh.vertex(path[i] + out * radius(i, theta), cap.unwrap_or(out), tone);
        }
        start
    };
    let sides32 = sides as u32;
    let rings: Vec<u32> = (0..n).map(|i| ring(&mut mesh, i, None)).collect();
    for i in 0..n - 1 {
        let (a, b) = (rings[i], rings[i + 1]);
        for s in 0..sides32 {
            let t = (s + 1) % sides32;
            mesh.triangle(a + s, a + t, b + s);
            mesh.triangle(a + t, b + t, b + s);
        }
    }
    // Caps: their own rings with the cap's normal, fanned to the end point.
    let (t0, tn) = (frames[0].0, frames[n - 1].0);
    let start_ring = ring(&mut mesh, 0, Some(-t0));
    let start = mesh.vertex(path[0], -t0, tone);
    let end_ring = ring(&mut mesh, n - 1, Some(tn));
    let end = mesh.vertex(path[n - 1], tn, tone);
    for s in 0..sides32 {
        let t = (s + 1) % sides32;
        mesh.triangle(start, start_ring + t, start_ring + s);
        mesh.triangle(end_ring + s, end_ring + t, end);
    }
    mesh
}

/// `points` with each inner corner rounded by an arc of radius `bend` (less where the sides
/// are too short for it), `steps` segments along each arc, so that a tube bent there does not
/// fold into itself.
pub(crate) fn fillet(points: &[Vector], bend: f32, steps: usize) -> Vec<Vector> {
    let n = points.len();
    let mut out = vec![points[0]];
    for k in 1..n.saturating_sub(1) {
        let (corner, before, after) = (points[k], points[k - 1], points[k + 1]);
        let (u, v) = (
            (before - corner).normalize_or(Vector::X),
            (after - corner).normalize_or(Vector::X),
        );
        let half_angle = 0.5 * u.dot(v).clamp(-1.0, 1.0).acos();
        if !(1e-3..=1.5).contains(&half_angle) {
            // Almost straight on, or turned back on itself: left as it is.
            out.push(corner);
            continue;
        }
        let reach = 0.45 * corner.distance(before).min(corner.distance(after));
        let cut = (bend / half_angle.tan()).min(reach);
        let radius = cut * half_angle.tan();
        let centre = corner + (u + v).normalize() * (radius / half_angle.sin());
        let (from, to) = (
            (corner + u * cut - centre).normalize(),
            (corner + v * cut - centre).normalize(),
        );
        let sweep = from.dot(to).clamp(-1.0, 1.0).acos().max(1e-6);
        out.extend((0..=steps).map(|s| {
            let t = s as f32 / steps as f32;
            let d = (from * ((1.0 - t) * sweep).sin() + to * (t * sweep).sin()) / sweep.sin();
            centre + d * radius
        }));
    }
    if n > 1 {
        out.push(points[n - 1]);
    }
    out
}
