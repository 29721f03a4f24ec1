//! The mesh every form builds: vertices with normals and tones, counter-clockwise triangles, and
//! the operations the forms share (joining pieces, fitting to a box, smoothing normals).

use crate::tone::Tone;
use rapier3d::math::{Rotation, Vector};

/// A triangle mesh in the frame of the box it fills: positions in metres, unit normals pointing
/// out, a tone per vertex, counter-clockwise triangles seen from outside. It may be several
/// closed pieces (a mug and its handle) that overlap.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// m.
    pub positions: Vec<Vector>,
    /// Unit, outward.
    pub normals: Vec<Vector>,
    /// Which colour each vertex takes; a triangle is drawn in its first vertex's.
    pub tones: Vec<Tone>,
    /// Counter-clockwise seen from outside, as indices into the lists above.
    pub triangles: Vec<[u32; 3]>,
    /// How far the farthest vertex was pressed back into the box the form was made for, m:
    /// 0 where the form fits its box, more where the box is smaller than the form's details
    /// of fixed size (a pull, a book's boards).
    pub pressed: f32,
}

impl Mesh {
    /// Adds a vertex and returns its index.
    pub(crate) fn vertex(&mut self, position: Vector, normal: Vector, tone: Tone) -> u32 {
        self.positions.push(position);
        self.normals.push(normal.normalize_or(Vector::Z));
        self.tones.push(tone);
        (self.positions.len() - 1) as u32
    }

    /// Adds the triangle `a, b, c`.
    pub(crate) fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.triangles.push([a, b, c]);
    }

    /// Adds the quad `a, b, c, d` (counter-clockwise) as two triangles.
    pub(crate) fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.triangles.push([a, b, c]);
        self.triangles.push([a, c, d]);
    }

    /// Adds another mesh's vertices and triangles to this one.
    pub(crate) fn append(&mut self, other: Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend(other.positions);
        self.normals.extend(other.normals);
        self.tones.extend(other.tones);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }

    /// Every vertex in one tone.
    pub(crate) fn toned(mut self, tone: Tone) -> Mesh {
        self.tones.fill(tone);
        self
    }

    /// The lowest and highest corners of the box around the vertices.
    pub fn bounds(&self) -> (Vector, Vector) {
        self.positions.iter().fold(
            (Vector::splat(f32::MAX), Vector::splat(f32::MIN)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        )
    }

    /// Moves and stretches every vertex by `p · scale + shift` (scale positive on every axis),
    /// turning the normals to match.
    pub(crate) fn stretch(&mut self, scale: Vector, shift: Vector) {
        for p in &mut self.positions {
            *p = *p * scale + shift;
        }
        for n in &mut self.normals {
            *n = (*n / scale).normalize_or(*n);
        }
    }

    /// Moves every vertex outside the box `[-half, half]` onto its nearest side, noting how far
    /// the farthest went in [`Mesh::pressed`].
    pub(crate) fn keep_inside(&mut self, half: Vector) {
        for p in &mut self.positions {
            let inside = p.clamp(-half, half);
            self.pressed = self.pressed.max(p.distance(inside));
            *p = inside;
        }
    }

    /// Turns every vertex by `rotation`, then moves it by `shift`.
    pub(crate) fn turn(&mut self, rotation: Rotation, shift: Vector) {
        for p in &mut self.positions {
            *p = rotation * *p + shift;
        }
        for n in &mut self.normals {
            *n = rotation * *n;
        }
    }

    /// Half a turn about z: what was on +x is on −x.
    pub(crate) fn turn_half(&mut self) {
        self.turn(
            Rotation::from_rotation_z(std::f32::consts::PI),
            Vector::ZERO,
        );
    }

    /// Swaps axes so that what was built along z lies along x: (x, y, z) → (z, x, y), a turn,
    /// so triangles keep their winding.
    pub(crate) fn lay_along_x(mut self) -> Mesh {
        let turn = |v: &mut Vector| *v = Vector::new(v.z, v.x, v.y);
        self.positions.iter_mut().for_each(turn);
        self.normals.iter_mut().for_each(turn);
        self
    }

    /// Stretches the mesh so that the box around it is exactly `[-half, half]`, and smooths its
    /// normals anew over the stretched shape (folds, whose vertices are doubled, stay sharp):
    /// stretching a thin rim's averaged normal is not the average of its stretched faces'.
    pub(crate) fn fit(mut self, half: Vector) -> Mesh {
        let (lo, hi) = self.bounds();
        let size = (hi - lo).max(Vector::splat(1e-9));
        let scale = 2.0 * half / size;
        self.stretch(scale, -(lo + hi) * 0.5 * scale);
        self.smooth_normals();
        self
    }

    /// Sets every vertex's normal to the area-weighted mean of its triangles' (for shapes built
    /// on a shared grid, whose normals are not known in closed form).
    pub(crate) fn smooth_normals(&mut self) {
        let mut sums = vec![Vector::ZERO; self.positions.len()];
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            let n = (b - a).cross(c - a);
            for &i in t {
                sums[i as usize] += n;
            }
        }
        for (n, s) in self.normals.iter_mut().zip(sums) {
            *n = s.normalize_or(*n);
        }
    }
}

/// The pieces of a form in one mesh.
pub(crate) fn join(pieces: impl IntoIterator<Item = Mesh>) -> Mesh {
    let mut all = Mesh::default();
    for piece in pieces {
        all.append(piece);
    }
    all
}
