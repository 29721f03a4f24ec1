//! Solids of revolution about z from a profile in the (r, z) half plane: bottles, bowls, cups,
//! legs, fruit. A profile that starts and ends on the axis gives a solid; one that does not is
//! a closed loop and gives a ring (a lamp shade with thickness, a [`torus`]).

use crate::Detail;
use crate::mesh::Mesh;
use crate::tone::Tone;
use rapier3d::math::Vector;
use std::f32::consts::{FRAC_PI_2, TAU};

/// A point of a profile: radius and height, whether the surface folds there (a rim, a cap's
/// edge) rather than runs smoothly through, and the tone of the stretch that starts there.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pt {
    pub(crate) r: f32,
    pub(crate) z: f32,
    pub(crate) sharp: bool,
    pub(crate) tone: Tone,
}

/// A smooth point in the body's tone.
pub(crate) fn p(r: f32, z: f32) -> Pt {
    Pt {
        r,
        z,
        sharp: false,
        tone: Tone::Body,
    }
}

/// A fold in the body's tone.
pub(crate) fn fold(r: f32, z: f32) -> Pt {
    Pt {
        sharp: true,
        ..p(r, z)
    }
}

impl Pt {
    /// The same point, starting a stretch of `tone` (a fold, so the colour changes crisply).
    pub(crate) fn tone(self, tone: Tone) -> Pt {
        Pt {
            tone,
            sharp: true,
            ..self
        }
    }
}

/// The outward normal of the stretch from `a` to `b`, for a profile that runs outward along the
/// bottom, up the outside, in over the top and down the inside (counter-clockwise in (r, z)).
fn side_normal(a: Pt, b: Pt) -> (f32, f32) {
    let (dr, dz) = (b.r - a.r, b.z - a.z);
    let length = (dr * dr + dz * dz).sqrt().max(1e-12);
    (dz / length, -dr / length)
}

/// The ring of vertices one profile point becomes: one index for a point on the axis.
#[derive(Clone, Copy)]
enum Ring {
    Pole(u32),
    Around(u32),
}

/// Revolves `profile` in `segments` steps; `wobble(φ)` scales the radius around the turn (1 for
/// a true solid of revolution). Profiles run as [`side_normal`] says.
pub(crate) fn revolve(profile: &[Pt], segments: usize, wobble: impl Fn(f32) -> f32) -> Mesh {
    let n = profile.len();
    let on_axis = |pt: &Pt| pt.r <= 1e-7;
    let closed_loop = !(on_axis(&profile[0]) && on_axis(&profile[n - 1]));
    let neighbour = |i: usize, step: isize| -> Option<Pt> {
        let j = i as isize + step;
        if (0..n as isize).contains(&j) {
            Some(profile[j as usize])
        } else if closed_loop {
            Some(profile[j.rem_euclid(n as isize) as usize])
        } else {
            None
        }
    };
    let mut mesh = Mesh::default();
    // For every point, the ring its incoming stretch ends on and the one its outgoing starts from.
    let mut rings: Vec<(Ring, Ring)> = Vec::with_capacity(n);
    for (i, &pt) in profile.iter().enumerate() {
        let before = neighbour(i, -1).map(|q| side_normal(q, pt));
        let after = neighbour(i, 1).map(|q| side_normal(pt, q));
        if on_axis(&pt) {
            let (_, nz) = after.or(before).unwrap_or((0.0, 1.0));
            let tone = if after.is_some() {
                pt.tone
            } else {
                profile[i - 1].tone
            };
            let pole = mesh.vertex(Vector::new(0.0, 0.0, pt.z), Vector::new(0.0, 0.0, nz), tone);
            rings.push((Ring::Pole(pole), Ring::Pole(pole)));
            continue;
        }
        let incoming_tone = neighbour(i, -1).map_or(pt.tone, |q| q.tone);
        let mut ring = |normal: (f32, f32), tone: Tone| {
            let first = mesh.positions.len() as u32;
            for s in 0..segments {
                let phi = TAU * s as f32 / segments as f32;
                let (c, sn) = (phi.cos(), phi.sin());
                let r = pt.r * wobble(phi);
                mesh.vertex(
                    Vector::new(r * c, r * sn, pt.z),
                    Vector::new(normal.0 * c, normal.0 * sn, normal.1),
                    tone,
                );
            }
            Ring::Around(first)
        };
        let mean = match (before, after) {
            (Some(a), Some(b)) => (a.0 + b.0, a.1 + b.1),
            (Some(a), None) | (None, Some(a)) => a,
            (None, None) => (1.0, 0.0),
        };
        if pt.sharp || incoming_tone != pt.tone {
            let incoming = ring(before.unwrap_or(mean), incoming_tone);
            let outgoing = ring(after.unwrap_or(mean), pt.tone);
            rings.push((incoming, outgoing));
        } else {
            let both = ring(mean, pt.tone);
            rings.push((both, both));
        }
    }
    let stretches = if closed_loop { n } else { n - 1 };
    for i in 0..stretches {
        let from = rings[i].1;
        let to = rings[(i + 1) % n].0;
        stitch(&mut mesh, from, to, segments as u32);
    }
    mesh
}

/// Triangles between two rings, outward by the rule of [`side_normal`].
fn stitch(mesh: &mut Mesh, from: Ring, to: Ring, segments: u32) {
    for s in 0..segments {
        let t = (s + 1) % segments;
        match (from, to) {
            (Ring::Around(a), Ring::Around(b)) => {
                mesh.triangle(a + s, a + t, b + s);
                mesh.triangle(a + t, b + t, b + s);
            }
            (Ring::Pole(a), Ring::Around(b)) => mesh.triangle(a, b + t, b + s),
            (Ring::Around(a), Ring::Pole(b)) => mesh.triangle(a + s, a + t, b),
            (Ring::Pole(_), Ring::Pole(_)) => {}
        }
    }
}

/// No wobble: a true solid of revolution.
pub(crate) fn even(_: f32) -> f32 {
    1.0
}

/// A ring about z: its tube's centre `radius` from the axis, the tube `thick` in radius (a
/// bangle, a wreath).
pub(crate) fn torus(radius: f32, thick: f32, detail: Detail) -> Mesh {
    let points = detail.around() / 2;
    // Counter-clockwise in (r, z), from the bottom: out, up the outside, in over the top.
    let profile: Vec<Pt> = (0..points)
        .map(|k| {
            let a = TAU * k as f32 / points as f32 - FRAC_PI_2;
            p(radius + thick * a.cos(), thick * a.sin())
        })
        .collect();
    revolve(&profile, 2 * detail.around(), even)
}

/// A plain cylinder of radius 1 from z = 0 to 1, `segments` round (a cap, a hub).
pub(crate) fn cylinder(segments: usize) -> Mesh {
    let profile = [p(0.0, 0.0), fold(1.0, 0.0), fold(1.0, 1.0), p(0.0, 1.0)];
    revolve(&profile, segments, even)
}
