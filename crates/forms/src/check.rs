//! What makes a mesh fit to draw in place of its colliders, checked: every piece closed and
//! wound outward, no triangle without area, normals on the side their triangles face, and
//! everything inside the box the form fills.

use crate::mesh::Mesh;
use rapier3d::math::Vector;
use std::collections::BTreeMap;
use std::fmt;

/// A way a mesh falls short.
#[derive(Clone, Debug, PartialEq)]
pub enum Defect {
    /// No triangles at all.
    Empty,
    /// A triangle refers to a vertex that does not exist, or the lists differ in length.
    Malformed,
    /// A triangle of (almost) no area, m².
    Degenerate {
        /// Its index.
        triangle: usize,
        /// Its area, m².
        area: f32,
    },
    /// An edge not matched by exactly one edge running the other way: a hole, a flap, or two
    /// neighbours wound in opposite senses.
    Open {
        /// The edge's first vertex.
        from: Vector,
        /// Its second.
        to: Vector,
    },
    /// A closed piece whose triangles face inward (negative volume, m³).
    Inward {
        /// The piece's signed volume, m³.
        volume: f32,
    },
    /// A vertex normal that points away from the face of a triangle it belongs to (more than a
    /// little past square to it).
    NormalAgainstFace {
        /// The triangle's index.
        triangle: usize,
    },
    /// A vertex outside the box, by this much, m.
    OutsideBox {
        /// The vertex.
        position: Vector,
        /// How far outside, m.
        by: f32,
    },
}

impl fmt::Display for Defect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Defect::Empty => write!(f, "no triangles"),
            Defect::Malformed => write!(f, "a triangle names a vertex that is not there"),
            Defect::Degenerate { triangle, area } => {
                write!(f, "triangle {triangle} has almost no area ({area:e} m²)")
            }
            Defect::Open { from, to } => write!(f, "edge {from} → {to} is open or misturned"),
            Defect::Inward { volume } => write!(f, "a piece faces inward (volume {volume:e} m³)"),
            Defect::NormalAgainstFace { triangle } => {
                write!(f, "a normal of triangle {triangle} points against its face")
            }
            Defect::OutsideBox { position, by } => {
                write!(f, "vertex {position} lies {by} m outside the box")
            }
        }
    }
}

/// How far past square to its face a vertex normal may lean (the cosine): smoothing a thin rim
/// (a leaf's edge) averages faces that look opposite ways, so its normals stand about square to
/// both; a normal turned inside out is far beyond this.
const NORMAL_SLACK: f32 = 0.25;

/// Positions closer than this are the same point (a seam's two copies), m.
const WELD: f32 = 1e-6;

impl Mesh {
    /// Everything wrong with the mesh as the drawing of a box of half size `half` (give a
    /// tolerance in `slack`, m); empty when it is fit to draw.
    pub fn defects(&self, half: Vector, slack: f32) -> Vec<Defect> {
        let n = self.positions.len();
        if self.normals.len() != n
            || self.tones.len() != n
            || self.triangles.iter().flatten().any(|&i| i as usize >= n)
        {
            return vec![Defect::Malformed];
        }
        if self.triangles.is_empty() {
            return vec![Defect::Empty];
        }
        let mut out = Vec::new();
        self.faces(&mut out);
        self.edges(&mut out);
        for &p in &self.positions {
            let by = (p.abs() - half).max_element();
            if by > slack {
                out.push(Defect::OutsideBox { position: p, by });
                break;
            }
        }
        out
    }

    fn faces(&self, out: &mut Vec<Defect>) {
        for (k, t) in self.triangles.iter().enumerate() {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            let n = (b - a).cross(c - a);
            let area = 0.5 * n.length();
            if area < 1e-12 {
                out.push(Defect::Degenerate { triangle: k, area });
                continue;
            }
            let face = n / (2.0 * area);
            if t.iter()
                .any(|&i| self.normals[i as usize].dot(face) < -NORMAL_SLACK)
            {
                out.push(Defect::NormalAgainstFace { triangle: k });
            }
        }
    }

    /// Welds equal positions, then checks that every edge is met once the other way round and
    /// that every piece so joined encloses a positive volume.
    fn edges(&self, out: &mut Vec<Defect>) {
        let mut ids: BTreeMap<[i64; 3], u32> = BTreeMap::new();
        let welded: Vec<u32> = self
            .positions
            .iter()
            .map(|p| {
                let key = p.to_array().map(|c| (c / WELD).round() as i64);
                let next = ids.len() as u32;
                *ids.entry(key).or_insert(next)
            })
            .collect();
        let mut edges: BTreeMap<(u32, u32), (u32, usize)> = BTreeMap::new();
        for t in &self.triangles {
            let w = t.map(|i| welded[i as usize]);
            for k in 0..3 {
                let entry = edges.entry((w[k], w[(k + 1) % 3])).or_insert((0, 0));
                entry.0 += 1;
                entry.1 = t[k] as usize;
            }
        }
        for (&(a, b), &(count, at)) in &edges {
            if count != 1 || edges.get(&(b, a)).map(|e| e.0) != Some(1) {
                let to = self.positions[welded.iter().position(|&w| w == b).unwrap_or(at)];
                out.push(Defect::Open {
                    from: self.positions[at],
                    to,
                });
                return;
            }
        }
        for volume in self.piece_volumes(&welded) {
            if volume <= 0.0 {
                out.push(Defect::Inward { volume });
            }
        }
    }

    /// The signed volume of each piece (triangles joined through welded vertices).
    fn piece_volumes(&self, welded: &[u32]) -> Vec<f32> {
        let count = welded.iter().max().map_or(0, |&m| m as usize + 1);
        let mut parent: Vec<usize> = (0..count).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for t in &self.triangles {
            let w = t.map(|i| welded[i as usize] as usize);
            for k in 1..3 {
                let (a, b) = (root(&mut parent, w[0]), root(&mut parent, w[k]));
                parent[a] = b;
            }
        }
        let mut volumes: BTreeMap<usize, f64> = BTreeMap::new();
        for t in &self.triangles {
            let piece = root(&mut parent, welded[t[0] as usize] as usize);
            let [a, b, c] = t.map(|i| self.positions[i as usize].as_dvec3());
            *volumes.entry(piece).or_default() += a.dot(b.cross(c)) / 6.0;
        }
        volumes.into_values().map(|v| v as f32).collect()
    }
}
