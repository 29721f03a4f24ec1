//! Boxes with rounded edges, at their true size so that the rounding is the same on every side:
//! each face is a grid whose rows bunch at its edges, and each grid point is pushed onto the
//! rounded surface (the inner box grown by the radius), with its normal known exactly.

use crate::Detail;
use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::Vector;
use std::f32::consts::FRAC_PI_4;

/// Where the grid lines of a face run along one axis from `-half` to `half`: `steps` through
/// each rounded edge (evenly in angle) and one jump across the flat middle.
fn cuts(half: f32, radius: f32, steps: usize) -> Vec<f32> {
    let inner = half - radius;
    let mut out = Vec::with_capacity(2 * steps + 2);
    // tan(π/4) is not exactly 1 in floats: the ends are set exactly, so that the faces that
    // meet at an edge put its points at the very same places.
    out.push(-half);
    for k in 1..=steps {
        let angle = FRAC_PI_4 * (steps - k) as f32 / steps as f32;
        out.push(-inner - radius * angle.tan());
    }
    for k in 0..steps {
        let angle = FRAC_PI_4 * k as f32 / steps as f32;
        out.push(inner + radius * angle.tan());
    }
    out.push(half);
    out
}

/// A box of half size `half` centred at `centre` whose edges are rounded by `radius` (no more
/// than its smallest half side), `steps` rows through each rounded edge.
pub(crate) fn rounded_box(
    centre: Vector,
    half: Vector,
    radius: f32,
    steps: usize,
    tone: Tone,
) -> Mesh {
    // A box made thinner than nothing by a caller's arithmetic on an odd size is drawn flat
    // rather than turned inside out (or panicking).
    let half = half.max(Vector::splat(1e-5));
    let radius = radius.clamp(1e-6, 0.9 * half.min_element());
    let inner = half - Vector::splat(radius);
    let mut mesh = Mesh::default();
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        let (us, vs) = (cuts(half[u], radius, steps), cuts(half[v], radius, steps));
        for sign in [1.0f32, -1.0] {
            let base = mesh.positions.len() as u32;
            for &b in &vs {
                for &a in &us {
                    let mut q = Vector::ZERO;
                    q[axis] = sign * half[axis];
                    q[u] = a;
                    q[v] = b;
                    let core = q.clamp(-inner, inner);
                    let normal = (q - core).normalize_or(Vector::ZERO);
                    mesh.vertex(centre + core + normal * radius, normal, tone);
                }
            }
            let row = us.len() as u32;
            for j in 0..vs.len() as u32 - 1 {
                for i in 0..row - 1 {
                    let (a, b) = (base + j * row + i, base + j * row + i + 1);
                    let (c, d) = (b + row, a + row);
                    if sign > 0.0 {
                        mesh.quad(a, b, c, d);
                    } else {
                        mesh.quad(a, d, c, b);
                    }
                }
            }
        }
    }
    mesh
}

/// [`rounded_box`] with its centre and half size given as arrays (a form's frame's units).
pub(crate) fn boxed(
    centre: [f32; 3],
    half: [f32; 3],
    radius: f32,
    rows: usize,
    tone: Tone,
) -> Mesh {
    rounded_box(
        Vector::from_array(centre),
        Vector::from_array(half),
        radius,
        rows,
        tone,
    )
}

/// A box rounded by `radius` with `rows` through each edge at the fine level, plain at the
/// coarse one: fronts and upholstery are drawn coarse wherever their rounding is under a pixel,
/// and what is left to see is their parts' outlines (a pull, a pillow).
pub(crate) fn block(
    centre: Vector,
    half: Vector,
    radius: f32,
    rows: usize,
    detail: Detail,
    tone: Tone,
) -> Mesh {
    match detail {
        Detail::Fine => rounded_box(centre, half, radius, rows, tone),
        Detail::Coarse => plain_box(centre, half, tone),
    }
}

/// A plain box of half size `half` centred at `centre`: four vertices a face with the face's
/// normal, two triangles a face (a front's coarse level, where no rounding would show).
pub(crate) fn plain_box(centre: Vector, half: Vector, tone: Tone) -> Mesh {
    let half = half.max(Vector::splat(1e-5));
    let mut mesh = Mesh::default();
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for sign in [1.0f32, -1.0] {
            let mut normal = Vector::ZERO;
            normal[axis] = sign;
            let corner = |a: f32, b: f32| {
                let mut q = normal * half[axis];
                q[u] = a * half[u];
                q[v] = b * half[v];
                centre + q
            };
            let k = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                .map(|(a, b)| mesh.vertex(corner(a, b), normal, tone));
            // Counter-clockwise seen from outside: (u, v) turn toward +axis on the + face.
            if sign > 0.0 {
                mesh.quad(k[0], k[1], k[2], k[3]);
            } else {
                mesh.quad(k[0], k[3], k[2], k[1]);
            }
        }
    }
    mesh
}
