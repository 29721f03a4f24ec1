//! Triangle meshes for the world's shapes, each made once and kept: unit meshes for boxes,
//! balls and cylinders (stretched by the instance's scale), one mesh per capsule size, per convex
//! hull and per imported visual mesh (found again by a hash of their numbers), and one per
//! detailed form, size, seed and level of detail (made by `behavior-forms`).

use behavior_forms::{Form, Tone};
use behavior_sim::{ModelPiece, Primitive, VisualMesh, VisualShape};
use rapier3d::math::Vector;
use std::collections::BTreeMap;
use std::f32::consts::{PI, TAU};

/// A mesh vertex: position and outward normal in the shape's frame, and which colour it takes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Vertex {
    pub(crate) position: [f32; 3],
    pub(crate) normal: [f32; 3],
    /// The object's colour, or a detail's own (a stem, a cap).
    pub(crate) tone: Tone,
}

/// Counter-clockwise triangles over vertices.
#[derive(Clone, Debug, Default)]
pub(crate) struct Mesh {
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) indices: Vec<u32>,
}

/// How finely a round shape (ball, cylinder, capsule) is cut into triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Detail {
    /// 16 segments around, 10 rings from pole to pole: 352 triangles a ball.
    Fine,
    /// 8 around, 6 rings: 112 a ball, for shapes a few pixels across.
    Coarse,
}

impl Detail {
    /// Segments around, and rings from pole to pole (even).
    fn cuts(self) -> (usize, usize) {
        match self {
            Detail::Fine => (16, 10),
            Detail::Coarse => (8, 6),
        }
    }
}

/// Which mesh a shape is drawn with: the unit meshes first, then one per distinct shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum MeshKey {
    UnitBox,
    UnitBall(Detail),
    UnitCylinder(Detail),
    Capsule {
        radius: u32,
        half_height: u32,
        detail: Detail,
    },
    Hull(u64),
    Visual(u64),
    /// One mesh of a model piece (a robot's link), as its library holds it or simplified.
    Piece {
        piece: ModelPiece,
        index: u16,
        level: PieceLevel,
    },
    /// A detailed form of a unit box (stretched by the instance's scale to its half size, whose
    /// bits are here because the form's details keep their proportions), for an object's seed.
    Form {
        form: Form,
        half: [u32; 3],
        seed: u32,
        detail: behavior_forms::Detail,
    },
}

impl MeshKey {
    /// Whether the mesh is a closed surface, seen only from outside (every primitive), so that
    /// triangles facing away from the camera are hidden behind others and need not be drawn.
    /// Imported visual meshes may be open (a bowl), so both their sides are drawn; a model
    /// piece's mesh is closed where it is watertight, which the store checks when it builds it.
    pub(crate) fn closed(self) -> bool {
        !matches!(self, MeshKey::Visual(_) | MeshKey::Piece { .. })
    }
}

/// Round shapes smaller than this radius on the image, pixels, are drawn with
/// [`Detail::Coarse`].
const COARSE_BELOW_PIXELS: f32 = 8.0;

/// Forms smaller than this radius on the image, pixels, are drawn at their coarse level.
const COARSE_FORM_BELOW_PIXELS: f32 = 20.0;

/// Forms smaller than this radius on the image, pixels, are drawn as their box: a few pixels
/// show no shape, and a coarse form costs ten to forty times a box's triangles.
const BOX_FORM_BELOW_PIXELS: f32 = 2.5;

/// A rounded box whose bevel is narrower than this on the image, pixels, is drawn as the plain
/// box: nobody sees the rounding, and it costs 25 times the triangles.
const PLAIN_BEVEL_BELOW_PIXELS: f32 = 0.75;

/// Whether a form's shadow is its box's: boxy forms (boards, cushions, books, folded cloth,
/// fronts whose fittings stand a centimetre proud).
fn casts_its_box(form: Form) -> bool {
    matches!(
        form,
        Form::Primitive
            | Form::Soft
            | Form::Turned
            | Form::Book
            | Form::Folded
            | Form::Plate
            | Form::Cake
            | Form::Loaf
    ) || behavior_forms::solid_core(form, Vector::ONE).is_some()
}

impl MeshKey {
    /// The mesh a shape casts into a shadow map: round shapes' coarse meshes, pieces' shadow
    /// level, boxy forms' boxes ([`casts_its_box`]), and other forms' boxes where
    /// they are under 40 cm from centre to corner and their coarse level where they are bigger
    /// (a torso, a tall plant, a floor lamp), whose box would cast a box's shadow and darken
    /// the form's own surface. (Every form over 15 cm casting its coarse mesh cost a tenth of
    /// the realistic profile's frame: a home's clutter, redrawn into the moving map.)
    pub(crate) fn caster(self) -> MeshKey {
        match self {
            MeshKey::Piece { piece, index, .. } => MeshKey::Piece {
                piece,
                index,
                level: PieceLevel::Shadow,
            },
            MeshKey::Form {
                form, half, seed, ..
            } if !casts_its_box(form)
                && Vector::from_array(half.map(f32::from_bits)).length() > 0.4 =>
            {
                MeshKey::Form {
                    form,
                    half,
                    seed,
                    detail: behavior_forms::Detail::Coarse,
                }
            }
            other => other.sized(0.0),
        }
    }

    /// This key, or its coarse version for a round shape `pixels` in radius on the image.
    pub(crate) fn sized(self, pixels: f32) -> MeshKey {
        if let MeshKey::Piece { piece, index, .. } = self {
            return MeshKey::Piece {
                piece,
                index,
                level: PieceLevel::for_pixels(pixels),
            };
        }
        if let MeshKey::Form { form, half, .. } = self {
            let half = Vector::from_array(half.map(f32::from_bits));
            if pixels < BOX_FORM_BELOW_PIXELS {
                return MeshKey::UnitBox;
            }
            let plain_bevel =
                pixels * behavior_forms::bevel(half) < PLAIN_BEVEL_BELOW_PIXELS * half.length();
            if matches!(form, Form::Rounded) && plain_bevel {
                return MeshKey::UnitBox;
            }
            // A front whose rounding would not show: its coarse level, plain boxes with the
            // fittings on them.
            if plain_bevel && behavior_forms::solid_core(form, half).is_some() {
                return self.coarse();
            }
        }
        if pixels >= COARSE_BELOW_PIXELS && !matches!(self, MeshKey::Form { .. })
            || pixels >= COARSE_FORM_BELOW_PIXELS
        {
            return self;
        }
        self.coarse()
    }

    /// This key's coarse level (the key itself where it has none).
    fn coarse(self) -> MeshKey {
        match self {
            MeshKey::Form {
                form, half, seed, ..
            } => MeshKey::Form {
                form,
                half,
                seed,
                detail: behavior_forms::Detail::Coarse,
            },
            MeshKey::UnitBall(_) => MeshKey::UnitBall(Detail::Coarse),
            MeshKey::UnitCylinder(_) => MeshKey::UnitCylinder(Detail::Coarse),
            MeshKey::Capsule {
                radius,
                half_height,
                ..
            } => MeshKey::Capsule {
                radius,
                half_height,
                detail: Detail::Coarse,
            },
            other => other,
        }
    }
}

/// How finely a model piece's mesh is drawn: as made, or with its vertices merged on a grid
/// (vertex clustering), which keeps its outline and drops detail finer than a pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum PieceLevel {
    /// Every triangle: for pieces 150 pixels or more in radius on the image.
    Made,
    /// Vertices merged in 4 mm cells (Fetch: 31,700 triangles become about 14,000): 50 to
    /// 150 pixels.
    Fine,
    /// 12 mm cells (about 6,500): below 50 pixels.
    Coarse,
    /// 30 mm cells (about 2,700): what a piece casts into the shadow maps, whose texels are
    /// centimetres wide.
    Shadow,
}

/// The grid of [`PieceLevel::Fine`], m (also what the browser viewer gets).
const FINE_CELL: f32 = 0.004;

impl PieceLevel {
    /// The grid's cell, m (none for [`PieceLevel::Made`]).
    fn cell(self) -> Option<f32> {
        match self {
            PieceLevel::Made => None,
            PieceLevel::Fine => Some(FINE_CELL),
            PieceLevel::Coarse => Some(0.012),
            PieceLevel::Shadow => Some(0.03),
        }
    }

    fn for_pixels(pixels: f32) -> PieceLevel {
        if pixels >= 150.0 {
            PieceLevel::Made
        } else if pixels >= 50.0 {
            PieceLevel::Fine
        } else {
            PieceLevel::Coarse
        }
    }
}

/// How to draw one shape: which mesh, stretched how, and how far it reaches from its origin.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Drawn {
    pub(crate) key: MeshKey,
    pub(crate) scale: Vector,
    /// A ball around the shape's origin that holds it (in its own frame, scaled), m.
    pub(crate) reach: f32,
    /// Half its size along its own axes, m (what the realistic profile's patterns scale by).
    pub(crate) extent: Vector,
}

impl Drawn {
    /// How to draw `shape` of an object of seed `seed` (which varies its form).
    pub(crate) fn of(shape: &VisualShape, seed: u32) -> Drawn {
        match shape {
            VisualShape::Primitive(p) => Drawn::primitive(p),
            &VisualShape::Formed { form, half_extents } => Drawn {
                key: MeshKey::Form {
                    form,
                    half: half_extents.to_array().map(f32::to_bits),
                    seed,
                    detail: behavior_forms::Detail::Fine,
                },
                scale: half_extents,
                reach: half_extents.length(),
                extent: half_extents,
            },
            VisualShape::Mesh(m) => Drawn {
                key: MeshKey::Visual(hash_mesh(m)),
                scale: Vector::ONE,
                reach: m.vertices.iter().map(|v| v.length()).fold(0.0, f32::max),
                extent: half_size(&m.vertices),
            },
            &VisualShape::Piece { piece, index, held } => Drawn {
                key: MeshKey::Piece {
                    piece,
                    index,
                    level: PieceLevel::Made,
                },
                scale: Vector::ONE,
                reach: held.reach,
                extent: (held.bounds[1] - held.bounds[0]) * 0.5,
            },
        }
    }

    pub(crate) fn primitive(p: &Primitive) -> Drawn {
        match *p {
            Primitive::Box { half_extents } => Drawn {
                key: MeshKey::UnitBox,
                scale: half_extents,
                reach: half_extents.length(),
                extent: half_extents,
            },
            Primitive::Sphere { radius } => Drawn {
                key: MeshKey::UnitBall(Detail::Fine),
                scale: Vector::splat(radius),
                reach: radius,
                extent: Vector::splat(radius),
            },
            Primitive::Cylinder {
                radius,
                half_height,
            } => Drawn {
                key: MeshKey::UnitCylinder(Detail::Fine),
                scale: Vector::new(radius, radius, half_height),
                reach: (radius * radius + half_height * half_height).sqrt(),
                extent: Vector::new(radius, radius, half_height),
            },
            Primitive::Capsule {
                radius,
                half_height,
            } => Drawn {
                key: MeshKey::Capsule {
                    radius: radius.to_bits(),
                    half_height: half_height.to_bits(),
                    detail: Detail::Fine,
                },
                scale: Vector::ONE,
                reach: radius + half_height,
                extent: Vector::new(radius, radius, radius + half_height),
            },
            Primitive::ConvexHull { ref points } => Drawn {
                key: MeshKey::Hull(hash_points(points)),
                scale: Vector::ONE,
                reach: points.iter().map(|v| v.length()).fold(0.0, f32::max),
                extent: half_size(points),
            },
        }
    }
}

/// Half the size of the box around `points` along each axis.
fn half_size(points: &[Vector]) -> Vector {
    let (lo, hi) = points.iter().fold(
        (Vector::splat(f32::MAX), Vector::splat(f32::MIN)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    );
    if lo.x > hi.x {
        Vector::ZERO
    } else {
        (hi - lo) * 0.5
    }
}

/// A 64-bit hash of some numbers' bits, quick enough to run on every part every frame: four
/// lanes of xor-and-multiply that do not wait on each other, folded at the end. (Byte-wise
/// FNV-1a, used before, took a third of a frame's gathering in a furnished home.)
pub(crate) fn hash_words(words: impl Iterator<Item = u32>) -> u64 {
    const K: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut lanes: [u64; 4] = [
        0x243f_6a88_85a3_08d3,
        0x1319_8a2e_0370_7344,
        0xa409_3822_299f_31d0,
        0x082e_fa98_ec4e_6c89,
    ];
    let mut count = 0u64;
    for (k, w) in words.enumerate() {
        let lane = &mut lanes[k & 3];
        *lane = (*lane ^ u64::from(w)).wrapping_mul(K);
        count += 1;
    }
    let h = lanes
        .into_iter()
        .fold(count, |h, l| (h ^ l ^ (l >> 32)).wrapping_mul(K));
    h ^ (h >> 29)
}

fn hash_points(points: &[Vector]) -> u64 {
    hash_words(points.iter().flat_map(|p| p.to_array().map(f32::to_bits)))
}

fn hash_mesh(mesh: &VisualMesh) -> u64 {
    let vertices = mesh
        .vertices
        .iter()
        .flat_map(|p| p.to_array().map(f32::to_bits));
    hash_words(vertices.chain(mesh.triangles.iter().flatten().copied()))
}

/// Builds the mesh a key names; `shape` is the shape it was found for (for hulls and visual
/// meshes, whose numbers the key only hashes).
pub(crate) fn build(key: MeshKey, shape: &VisualShape) -> Mesh {
    match (key, shape) {
        (MeshKey::UnitBox, _) => unit_box(),
        (MeshKey::UnitBall(detail), _) => ball(1.0, 0.0, detail),
        (MeshKey::UnitCylinder(detail), _) => cylinder(detail),
        (
            MeshKey::Capsule {
                radius,
                half_height,
                detail,
            },
            _,
        ) => ball(f32::from_bits(radius), f32::from_bits(half_height), detail),
        (MeshKey::Hull(_), VisualShape::Primitive(Primitive::ConvexHull { points })) => {
            hull(points)
        }
        (MeshKey::Visual(_), VisualShape::Mesh(m)) => faceted(&m.vertices, &m.triangles),
        (MeshKey::Piece { level, .. }, VisualShape::Piece { held, .. }) => match level.cell() {
            None => creased(&held.mesh.vertices, &held.mesh.triangles),
            Some(cell) => {
                let (vertices, triangles) =
                    clustered(&held.mesh.vertices, &held.mesh.triangles, cell);
                creased(&vertices, &triangles)
            }
        },
        (
            MeshKey::Form {
                form,
                half,
                seed,
                detail,
            },
            _,
        ) => formed(
            form,
            Vector::from_array(half.map(f32::from_bits)),
            seed,
            detail,
        ),
        _ => Mesh::default(),
    }
}

/// A form's mesh shrunk to the unit box (the instance stretches it back by `half`): positions
/// divided by `half`, normals multiplied by it, so that the instance's normal matrix (which
/// divides by its scale) turns them back.
fn formed(form: Form, half: Vector, seed: u32, detail: behavior_forms::Detail) -> Mesh {
    let made = behavior_forms::mesh(form, half, u64::from(seed), detail);
    let unit = half.max(Vector::splat(1e-6));
    Mesh {
        vertices: (made.positions.iter().zip(&made.normals).zip(&made.tones))
            .map(|((&p, &n), &tone)| Vertex {
                position: (p / unit).to_array(),
                normal: (n * unit).to_array(),
                tone,
            })
            .collect(),
        indices: made.triangles.into_iter().flatten().collect(),
    }
}

fn unit_box() -> Mesh {
    let mut mesh = Mesh::default();
    for axis in 0..3 {
        for sign in [1.0f32, -1.0] {
            let mut n = [0.0; 3];
            n[axis] = sign;
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            let base = mesh.vertices.len() as u32;
            for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let mut p = [0.0; 3];
                p[axis] = sign;
                p[u] = a;
                p[v] = b;
                mesh.vertices.push(Vertex {
                    position: p,
                    normal: n,
                    tone: Tone::Body,
                });
            }
            let quad = if sign > 0.0 {
                [0, 1, 2, 0, 2, 3]
            } else {
                [0, 2, 1, 0, 3, 2]
            };
            mesh.indices.extend(quad.map(|i| base + i));
        }
    }
    mesh
}

/// A ball of `radius` whose two halves are pulled `half_height` apart along z, joined by a
/// cylinder: a capsule, or a ball when `half_height` is 0.
fn ball(radius: f32, half_height: f32, detail: Detail) -> Mesh {
    let (round, rings_count) = detail.cuts();
    let mut mesh = Mesh::default();
    // Rings from the top pole to the bottom one; the equator is doubled for a capsule's two halves.
    let mut rings: Vec<(f32, f32)> = Vec::new(); // (polar angle, z shift)
    for r in 0..=rings_count / 2 {
        rings.push((PI * r as f32 / rings_count as f32, half_height));
    }
    for r in rings_count / 2..=rings_count {
        rings.push((PI * r as f32 / rings_count as f32, -half_height));
    }
    for &(theta, shift) in &rings {
        for s in 0..=round {
            let phi = TAU * s as f32 / round as f32;
            let n = [
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ];
            let p = [radius * n[0], radius * n[1], radius * n[2] + shift];
            mesh.vertices.push(Vertex {
                position: p,
                normal: n,
                tone: Tone::Body,
            });
        }
    }
    let row = (round + 1) as u32;
    for r in 0..(rings.len() as u32 - 1) {
        for s in 0..round as u32 {
            let a = r * row + s;
            let b = a + row;
            mesh.indices.extend([a, b, a + 1, a + 1, b, b + 1]);
        }
    }
    mesh
}

/// A cylinder of radius 1 from z = −1 to 1, with caps.
fn cylinder(detail: Detail) -> Mesh {
    let (round, _) = detail.cuts();
    let mut mesh = Mesh::default();
    for s in 0..=round {
        let phi = TAU * s as f32 / round as f32;
        let (x, y) = (phi.cos(), phi.sin());
        for z in [1.0, -1.0] {
            mesh.vertices.push(Vertex {
                position: [x, y, z],
                normal: [x, y, 0.0],
                tone: Tone::Body,
            });
        }
    }
    for s in 0..round as u32 {
        let (a, b) = (2 * s, 2 * s + 2);
        mesh.indices.extend([a, a + 1, b, b, a + 1, b + 1]);
    }
    for z in [1.0f32, -1.0] {
        let centre = mesh.vertices.len() as u32;
        mesh.vertices.push(Vertex {
            position: [0.0, 0.0, z],
            normal: [0.0, 0.0, z],
            tone: Tone::Body,
        });
        for s in 0..=round {
            let phi = TAU * s as f32 / round as f32;
            mesh.vertices.push(Vertex {
                position: [phi.cos(), phi.sin(), z],
                normal: [0.0, 0.0, z],
                tone: Tone::Body,
            });
        }
        for s in 0..round as u32 {
            let (a, b) = (centre + 1 + s, centre + 2 + s);
            let tri = if z > 0.0 {
                [centre, a, b]
            } else {
                [centre, b, a]
            };
            mesh.indices.extend(tri);
        }
    }
    mesh
}

/// The convex hull of points, with flat faces.
fn hull(points: &[Vector]) -> Mesh {
    let (vertices, triangles) = rapier3d::parry::transformation::convex_hull(points);
    faceted(&vertices, &triangles)
}

/// Triangles with one normal per face (each face its own three vertices).
fn faceted(vertices: &[Vector], triangles: &[[u32; 3]]) -> Mesh {
    let mut mesh = Mesh::default();
    for tri in triangles {
        let Some(p) = tri
            .iter()
            .map(|&i| vertices.get(i as usize).copied())
            .collect::<Option<Vec<Vector>>>()
        else {
            continue;
        };
        let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
        let base = mesh.vertices.len() as u32;
        for q in &p {
            mesh.vertices.push(Vertex {
                position: q.to_array(),
                normal: n.to_array(),
                tone: Tone::Body,
            });
        }
        mesh.indices.extend([base, base + 1, base + 2]);
    }
    mesh
}

/// Surfaces meeting at more than this angle keep a crease (a model's edges); gentler ones are
/// shaded smooth (its rounded covers), rad.
const CREASE: f32 = 0.7;

/// A model's mesh with smooth normals wherever its faces meet at less than [`CREASE`]: each
/// corner takes the area-weighted normals of the faces around its vertex that lie within the
/// crease of its own face. Degenerate triangles are left out.
fn creased(vertices: &[Vector], triangles: &[[u32; 3]]) -> Mesh {
    let corner = |t: &[u32; 3], k: usize| vertices.get(t[k] as usize).copied();
    // Area-weighted face normals (zero for a degenerate or malformed triangle).
    let faces: Vec<Vector> = triangles
        .iter()
        .map(|t| match (corner(t, 0), corner(t, 1), corner(t, 2)) {
            (Some(a), Some(b), Some(c)) => (b - a).cross(c - a),
            _ => Vector::ZERO,
        })
        .collect();
    let mut around = vec![Vec::new(); vertices.len()];
    for (f, t) in triangles.iter().enumerate() {
        if faces[f] != Vector::ZERO {
            for &i in t {
                around[i as usize].push(f);
            }
        }
    }
    let limit = CREASE.cos();
    let mut mesh = Mesh::default();
    let mut made: BTreeMap<(u32, [u32; 3]), u32> = BTreeMap::new();
    for (f, t) in triangles.iter().enumerate() {
        let own = faces[f].normalize_or_zero();
        if own == Vector::ZERO {
            continue;
        }
        for &i in t {
            let normal = around[i as usize]
                .iter()
                .map(|&g| faces[g])
                .filter(|n| n.normalize_or_zero().dot(own) >= limit)
                .sum::<Vector>()
                .normalize_or(own);
            let key = (i, normal.to_array().map(f32::to_bits));
            let next = mesh.vertices.len() as u32;
            let index = *made.entry(key).or_insert_with(|| {
                mesh.vertices.push(Vertex {
                    position: vertices[i as usize].to_array(),
                    normal: normal.to_array(),
                    tone: Tone::Body,
                });
                next
            });
            mesh.indices.push(index);
        }
    }
    mesh
}

/// A mesh with its vertices merged in cubic cells of `cell` metres, each cell's vertices
/// replaced by their mean; triangles that collapse to an edge or a point, and repeats, are
/// dropped. Quick and robust (no surface is assumed), so a 4 mm grid leaves a robot's shells as
/// they look and its emergency stop's 7,700 triangles as 1,200.
fn clustered(
    vertices: &[Vector],
    triangles: &[[u32; 3]],
    cell: f32,
) -> (Vec<Vector>, Vec<[u32; 3]>) {
    let mut cells: BTreeMap<[i32; 3], u32> = BTreeMap::new();
    let mut sums: Vec<(Vector, f32)> = Vec::new();
    let merged: Vec<u32> = vertices
        .iter()
        .map(|&p| {
            let key = (p / cell).floor().to_array().map(|c| c as i32);
            let next = sums.len() as u32;
            let id = *cells.entry(key).or_insert(next);
            if id == next {
                sums.push((Vector::ZERO, 0.0));
            }
            let sum = &mut sums[id as usize];
            *sum = (sum.0 + p, sum.1 + 1.0);
            id
        })
        .collect();
    let points = sums.into_iter().map(|(sum, n)| sum / n).collect();
    let mut seen = std::collections::BTreeSet::new();
    let mut kept = Vec::new();
    for t in triangles {
        let Some(m) = t
            .iter()
            .map(|&i| merged.get(i as usize).copied())
            .collect::<Option<Vec<u32>>>()
        else {
            continue;
        };
        let [a, b, c] = [m[0], m[1], m[2]];
        if a == b || b == c || c == a {
            continue;
        }
        // The same triangle whichever corner it starts at.
        let first = [a, b, c].iter().copied().min().unwrap_or(a);
        let turned = match first {
            x if x == a => [a, b, c],
            x if x == b => [b, c, a],
            _ => [c, a, b],
        };
        if seen.insert(turned) {
            kept.push(turned);
        }
    }
    (points, kept)
}

/// Whether every edge (between vertex positions) is met as often in each direction: a closed
/// surface, whose faces turned away from the camera are hidden behind others.
fn watertight(vertices: &[Vector], triangles: &[[u32; 3]]) -> bool {
    let Some(far) = triangles.iter().flatten().max() else {
        return false;
    };
    if *far as usize >= vertices.len() {
        return false;
    }
    let at = |i: u32| vertices[i as usize].to_array().map(f32::to_bits);
    let mut edges: BTreeMap<([u32; 3], [u32; 3]), i32> = BTreeMap::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (at(t[k]), at(t[(k + 1) % 3]));
            let (key, turn) = if a < b { ((a, b), 1) } else { ((b, a), -1) };
            *edges.entry(key).or_default() += turn;
        }
    }
    edges.values().all(|&n| n == 0)
}

/// Whether a point (in the shape's frame) lies inside a primitive: a camera inside a part does
/// not draw it (a robot's eye inside its head).
pub(crate) fn contains(p: &Primitive, point: Vector) -> bool {
    match *p {
        Primitive::Box { half_extents } => point.abs().cmplt(half_extents).all(),
        Primitive::Sphere { radius } => point.length() < radius,
        Primitive::Cylinder {
            radius,
            half_height,
        } => point.z.abs() < half_height && point.truncate().length() < radius,
        Primitive::Capsule {
            radius,
            half_height,
        } => {
            let axis = Vector::new(0.0, 0.0, point.z.clamp(-half_height, half_height));
            (point - axis).length() < radius
        }
        Primitive::ConvexHull { .. } => false,
    }
}

/// Where one mesh lies in the store's lists.
#[derive(Clone, Copy, Debug)]
struct MeshRange {
    first_vertex: usize,
    vertex_count: usize,
    first_index: usize,
    index_count: usize,
    closed: bool,
}

/// One mesh of the store.
pub(crate) struct StoredMesh<'a> {
    pub(crate) vertices: &'a [Vertex],
    /// Counter-clockwise triangles, as indices into `vertices`.
    pub(crate) indices: &'a [u32],
    /// See [`MeshKey::closed`].
    pub(crate) closed: bool,
}

/// Every mesh made so far, packed in one vertex and one index list, and where each lies.
#[derive(Default)]
pub(crate) struct MeshStore {
    vertices: Vec<Vertex>,
    /// Indices into each mesh's own vertices.
    indices: Vec<u32>,
    ranges: Vec<MeshRange>,
    ids: BTreeMap<MeshKey, u32>,
}

impl MeshStore {
    /// The mesh for a key, made from `shape` the first time.
    pub(crate) fn id(&mut self, key: MeshKey, shape: &VisualShape) -> u32 {
        if let Some(&id) = self.ids.get(&key) {
            return id;
        }
        let mesh = build(key, shape);
        // A piece's simplified levels count as closed where the piece is: the gaps merging may
        // open are narrower than its grid's cell, under a pixel where that level is drawn.
        let closed = match (key, shape) {
            (MeshKey::Piece { .. }, VisualShape::Piece { held, .. }) => {
                watertight(&held.mesh.vertices, &held.mesh.triangles)
            }
            _ => key.closed(),
        };
        let id = self.ranges.len() as u32;
        self.ranges.push(MeshRange {
            first_vertex: self.vertices.len(),
            vertex_count: mesh.vertices.len(),
            first_index: self.indices.len(),
            index_count: mesh.indices.len(),
            closed,
        });
        self.vertices.extend(mesh.vertices);
        self.indices.extend(mesh.indices);
        self.ids.insert(key, id);
        id
    }

    /// A mesh by its id (empty for an unknown id).
    pub(crate) fn mesh(&self, id: u32) -> StoredMesh<'_> {
        let Some(r) = self.ranges.get(id as usize) else {
            return StoredMesh {
                vertices: &[],
                indices: &[],
                closed: false,
            };
        };
        StoredMesh {
            vertices: &self.vertices[r.first_vertex..r.first_vertex + r.vertex_count],
            indices: &self.indices[r.first_index..r.first_index + r.index_count],
            closed: r.closed,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn closed_and_outward(mesh: &Mesh) {
        let centre: Vector = mesh
            .vertices
            .iter()
            .map(|v| Vector::from(v.position))
            .sum::<Vector>()
            / mesh.vertices.len() as f32;
        for tri in mesh.indices.chunks(3) {
            let p: Vec<Vector> = tri
                .iter()
                .map(|&i| mesh.vertices[i as usize].position.into())
                .collect();
            let n = (p[1] - p[0]).cross(p[2] - p[0]);
            if n.length() < 1e-5 {
                continue; // a pole's sliver
            }
            let out = (p[0] + p[1] + p[2]) / 3.0 - centre;
            assert!(n.dot(out) > 0.0, "an inward triangle {p:?}");
        }
    }

    #[test]
    fn every_shape_is_wound_counter_clockwise_seen_from_outside() {
        closed_and_outward(&unit_box());
        for detail in [Detail::Fine, Detail::Coarse] {
            closed_and_outward(&ball(1.0, 0.0, detail));
            closed_and_outward(&ball(0.1, 0.3, detail));
            closed_and_outward(&cylinder(detail));
        }
        let cube: Vec<Vector> = (0..8)
            .map(|i| Vector::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32))
            .collect();
        let h = hull(&cube);
        assert_eq!(h.indices.len(), 36);
        closed_and_outward(&h);
    }

    #[test]
    fn round_shapes_a_few_pixels_across_get_the_coarse_mesh() {
        let ball_key = Drawn::primitive(&Primitive::Sphere { radius: 0.05 }).key;
        assert_eq!(ball_key.sized(20.0), MeshKey::UnitBall(Detail::Fine));
        assert_eq!(ball_key.sized(3.0), MeshKey::UnitBall(Detail::Coarse));
        let triangles = |d| ball(1.0, 0.0, d).indices.len() / 3;
        assert_eq!(
            (triangles(Detail::Fine), triangles(Detail::Coarse)),
            (352, 112)
        );
        // Boxes and hulls have one mesh only.
        assert_eq!(MeshKey::UnitBox.sized(1.0), MeshKey::UnitBox);
    }

    #[test]
    fn a_camera_inside_a_shape_is_found_inside() {
        let capsule = Primitive::Capsule {
            radius: 0.25,
            half_height: 0.25,
        };
        assert!(contains(&capsule, Vector::new(0.1, 0.0, 0.4)));
        assert!(!contains(&capsule, Vector::new(0.3, 0.0, 0.0)));
        let cube = Primitive::Box {
            half_extents: Vector::splat(0.1),
        };
        assert!(
            contains(&cube, Vector::splat(0.05)) && !contains(&cube, Vector::new(0.2, 0.0, 0.0))
        );
    }

    /// A fine ball (radius 0.1 m) as a model's indexed mesh: positions and triangles.
    fn ball_model() -> (Vec<Vector>, Vec<[u32; 3]>) {
        let mesh = ball(0.1, 0.0, Detail::Fine);
        // The ball's vertices repeat along its seam; merge them as a model file's would be.
        let mut points: Vec<Vector> = Vec::new();
        let index: Vec<u32> = mesh
            .vertices
            .iter()
            .map(|v| {
                let p = Vector::from(v.position);
                match points.iter().position(|q| (*q - p).length() < 1e-6) {
                    Some(k) => k as u32,
                    None => {
                        points.push(p);
                        points.len() as u32 - 1
                    }
                }
            })
            .collect();
        let triangles = mesh
            .indices
            .chunks_exact(3)
            .map(|t| {
                [
                    index[t[0] as usize],
                    index[t[1] as usize],
                    index[t[2] as usize],
                ]
            })
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
            .collect();
        (points, triangles)
    }

    #[test]
    fn model_meshes_are_shaded_smooth_within_the_crease_and_simplified_on_a_grid() {
        let (points, triangles) = ball_model();
        assert!(watertight(&points, &triangles));
        // Smooth: a ball's normals point away from its centre.
        let smooth = creased(&points, &triangles);
        for v in &smooth.vertices {
            let out = Vector::from(v.position).normalize();
            assert!(Vector::from(v.normal).dot(out) > 0.98, "{v:?}");
        }
        closed_and_outward(&smooth);
        // A cube keeps its edges: every normal is a face's.
        let cube = unit_box();
        let corners: Vec<Vector> = cube
            .vertices
            .iter()
            .map(|v| Vector::from(v.position))
            .collect();
        let faces: Vec<[u32; 3]> = cube
            .indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect();
        for v in creased(&corners, &faces).vertices {
            let n = Vector::from(v.normal);
            assert!((n.abs().max_element() - 1.0).abs() < 1e-5, "{n:?}");
        }
        // On a 6 cm grid (its edges are 4 cm) the ball keeps its size within a cell and loses
        // most of its triangles.
        let (merged, kept) = clustered(&points, &triangles, 0.06);
        assert!(
            kept.len() * 2 < triangles.len(),
            "{} of {}",
            kept.len(),
            triangles.len()
        );
        assert!(kept.len() >= 8, "{kept:?}");
        for p in &merged {
            assert!((p.length() - 0.1).abs() < 0.06, "{p:?}");
        }
        assert!(kept.iter().flatten().all(|&i| (i as usize) < merged.len()));
        // An open mesh is not watertight; a bad index is no panic.
        assert!(!watertight(&points, &triangles[1..]));
        assert!(!watertight(&points, &[[0, 1, 999]]));
        assert!(creased(&points, &[[0, 1, 999]]).indices.is_empty());
    }

    #[test]
    fn pieces_get_coarser_with_fewer_pixels_and_cast_their_coarsest() {
        let piece = ModelPiece {
            model: behavior_sim::Model::Fetch,
            piece: 0,
        };
        let key = |level| MeshKey::Piece {
            piece,
            index: 0,
            level,
        };
        let made = key(PieceLevel::Made);
        assert_eq!(made.sized(200.0), made);
        assert_eq!(made.sized(80.0), key(PieceLevel::Fine));
        assert_eq!(made.sized(30.0), key(PieceLevel::Coarse));
        assert_eq!(made.caster(), key(PieceLevel::Shadow));
        assert_eq!(
            MeshKey::UnitBall(Detail::Fine).caster(),
            MeshKey::UnitBall(Detail::Coarse)
        );
    }
}
