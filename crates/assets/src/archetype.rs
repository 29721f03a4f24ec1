//! Archetypes: how an object of a synset is built from primitives, at any size in its range.
//!
//! An archetype names a [`Shape`] (a family of procedural geometry), the bounding-box size range
//! of real instances, a material density and a colour. [`Archetype::build`] turns a size and a
//! variant into an [`ObjectSpec`] whose bottom rests at z = 0, centred on the origin, with the
//! doors, drawers and lids its shape has. Abilities and the named points they need are added by
//! the [`crate::library::Library`], from the taxonomy of the synset asked for.

pub use behavior_sim::Material;
use behavior_sim::{BodyKind, JointKind, JointSpec, LinkSpec, ObjectSpec, Part, Primitive, Visual};
use rapier3d::math::{Pose, Rotation, Vector};

/// A family of procedural geometry. Containers have real walls and an opening, so `inside` is
/// physical; furniture that opens has doors or drawers on joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    Ball,
    /// A box (variant 0) or a worn one with chamfered edges (variant 1): books, soap, boxes.
    Block,
    Cylinder,
    /// Thin and lying flat: plates, trays, towels, papers.
    Slab,
    /// Long and thin along x: pens, knives, brooms.
    Rod,
    /// A bottom and four walls.
    OpenContainer,
    /// An open container with a lid hinged at its back edge (variant 0) or at its right-hand side
    /// (variant 1).
    LiddedContainer,
    Table,
    /// Open shelving: sides, back and boards.
    Shelf,
    /// A carcass with one shelf and a door (variant 0) or two drawers (variant 1).
    Cabinet,
    /// A solid block at counter height.
    Countertop,
    Fridge,
    Oven,
    Microwave,
    Stove,
    Sink,
    Dishwasher,
    Washer,
    Dryer,
    Bed,
    Sofa,
    Chair,
    Toilet,
    Bathtub,
    Shower,
    /// A frame with a door leaf on a hinge.
    Door,
    /// A frame with a casement on a hinge: a window with a sill at 0.9 m (variant 0) or a
    /// floor-length one, from 5 cm up and 0.85 m taller (variant 1), that a lamp or a stool on
    /// the floor can stand next to.
    Window,
    Floor,
    /// A stand-in body for the robot until embodiments exist: an upright capsule.
    Agent,
}

impl Shape {
    /// How many geometric variants the shape has.
    pub fn variants(self) -> u32 {
        match self {
            Shape::Table
            | Shape::Cabinet
            | Shape::Shelf
            | Shape::OpenContainer
            | Shape::Chair
            | Shape::Ball
            | Shape::Cylinder
            | Shape::Slab
            | Shape::Rod
            | Shape::Window
            | Shape::Block
            | Shape::LiddedContainer => 2,
            _ => 1,
        }
    }

    /// Orientations (of the object's frame) in which an instance rests stably on a flat surface,
    /// upright first: blocks on any face, rods on either long side, cylinders standing or lying;
    /// everything else only upright. Samplers may pick among them for variety.
    pub fn resting_orientations(self) -> Vec<Rotation> {
        let quarter = std::f32::consts::FRAC_PI_2;
        let mut rotations = vec![Rotation::IDENTITY];
        match self {
            Shape::Block => rotations.extend([
                Rotation::from_rotation_x(quarter),
                Rotation::from_rotation_y(quarter),
            ]),
            Shape::Rod | Shape::Cylinder => rotations.push(Rotation::from_rotation_x(quarter)),
            _ => {}
        }
        rotations
    }

    /// Fixed in the scene (furniture) rather than free to move.
    pub fn is_fixed(self) -> bool {
        !matches!(
            self,
            Shape::Ball
                | Shape::Block
                | Shape::Cylinder
                | Shape::Slab
                | Shape::Rod
                | Shape::OpenContainer
                | Shape::LiddedContainer
                | Shape::Agent
        )
    }
}

/// An object family for one synset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Archetype {
    pub synset: &'static str,
    pub shape: Shape,
    /// Bounding box (width x, depth y, height z; metres) of the smallest and largest instances.
    pub min: [f32; 3],
    pub max: [f32; 3],
    /// Of the material, kg/m³.
    pub density: f32,
    pub material: Material,
    pub color: [u8; 3],
}

/// Where the parts of a built object are, for adding named points afterwards.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    pub size: Vector,
    /// A point on the front face (−y) at a sensible button height.
    pub front_button: Vector,
    /// Where water falls from, for sinks and showers.
    pub outlet: Option<Vector>,
    /// Burner positions, for stoves.
    pub burners: [Option<Vector>; 4],
}

fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

fn cuboid(center: Vector, half: Vector) -> Part {
    Part::at(
        Primitive::Box {
            half_extents: half.max(Vector::splat(0.0005)),
        },
        center,
    )
}

/// A box from its min and max corners.
fn span(min: Vector, max: Vector) -> Part {
    cuboid((min + max) * 0.5, (max - min) * 0.5)
}

/// Wall thickness for a container of this footprint.
fn wall(size: Vector) -> f32 {
    (0.06 * size.x.min(size.y)).clamp(0.004, 0.03)
}

/// Bottom and four walls filling the box `min..max` (open at the top).
fn tub(min: Vector, max: Vector, t: f32) -> Vec<Part> {
    vec![
        span(min, v(max.x, max.y, min.z + t)),
        span(min, v(min.x + t, max.y, max.z)),
        span(v(max.x - t, min.y, min.z), max),
        span(min, v(max.x, min.y + t, max.z)),
        span(v(min.x, max.y - t, min.z), max),
    ]
}

/// A carcass open at the front (−y): bottom, top, sides, back.
fn carcass(min: Vector, max: Vector, t: f32) -> Vec<Part> {
    vec![
        span(min, v(max.x, max.y, min.z + t)),
        span(v(min.x, min.y, max.z - t), max),
        span(min, v(min.x + t, max.y, max.z)),
        span(v(max.x - t, min.y, min.z), max),
        span(v(min.x, max.y - t, min.z), max),
    ]
}

/// A door covering the front of `min..max`, hinged on its left edge (opens outward, to −y).
fn side_door(name: &str, min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    LinkSpec {
        name: name.into(),
        parts: vec![span(v(min.x, min.y - t, min.z), v(max.x, min.y, max.z))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(min.x, min.y - t, 0.0),
            v(0.0, 0.0, -1.0),
            1.9,
            2.0,
        ),
        density,
    }
}

/// A door covering the front of `min..max`, hinged at its bottom edge (ovens, dishwashers).
fn drop_door(min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    LinkSpec {
        name: "door".into(),
        parts: vec![span(v(min.x, min.y - t, min.z), v(max.x, min.y, max.z))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.0, min.y - t, min.z),
            v(1.0, 0.0, 0.0),
            1.5,
            2.0,
        ),
        density,
    }
}

/// A drawer filling `min..max` of a carcass, sliding out to −y.
fn drawer(name: &str, min: Vector, max: Vector, t: f32, density: f32) -> LinkSpec {
    let mut parts = tub(
        v(min.x + t, min.y, min.z + t),
        v(max.x - t, max.y - t, max.z - t),
        t,
    );
    // Its front panel closes the carcass.
    parts.push(span(v(min.x, min.y - t, min.z), v(max.x, min.y, max.z)));
    LinkSpec {
        name: name.into(),
        parts,
        parent: None,
        joint: JointSpec::opening(
            JointKind::Prismatic,
            Vector::ZERO,
            v(0.0, -1.0, 0.0),
            0.8 * (max.y - min.y),
            2.0,
        ),
        density,
    }
}

/// The corners of a box with every edge cut by `c`.
fn chamfered(min: Vector, max: Vector, c: f32) -> Vec<Vector> {
    let mut points = Vec::with_capacity(24);
    for x in [min.x, max.x] {
        for y in [min.y, max.y] {
            for z in [min.z, max.z] {
                // One step in from the corner along each pair of axes.
                let inward = |a: f32, lo: f32| if a == lo { a + c } else { a - c };
                points.push(v(x, inward(y, min.y), inward(z, min.z)));
                points.push(v(inward(x, min.x), y, inward(z, min.z)));
                points.push(v(inward(x, min.x), inward(y, min.y), z));
            }
        }
    }
    points
}

fn hull(points: Vec<Vector>) -> Part {
    Part::new(Primitive::ConvexHull { points })
}

/// Points on an ellipsoid filling a box of `size` standing at z = 0, those `keep` accepts, plus
/// points where the cut plane x = 0 meets it (so a half closes flat).
fn ellipsoid(size: Vector, keep: impl Fn(Vector) -> bool) -> Vec<Vector> {
    let r = size * 0.5;
    let mut points = Vec::new();
    for i in 0..=8 {
        let theta = std::f32::consts::PI * i as f32 / 8.0;
        for j in 0..16 {
            let phi = std::f32::consts::TAU * j as f32 / 16.0;
            let unit = v(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let p = unit * r + v(0.0, 0.0, r.z);
            if keep(p) || unit.x.abs() < 1e-6 {
                points.push(p);
            }
        }
    }
    points
}

/// Points of a regular `sides`-gon prism of radius `radius` and height `height` (those `keep`
/// accepts, plus the cut plane's).
fn prism(radius: f32, height: f32, sides: usize, keep: impl Fn(Vector) -> bool) -> Vec<Vector> {
    let mut points = Vec::new();
    for k in 0..sides {
        let a = std::f32::consts::TAU * (k as f32 + 0.5) / sides as f32;
        for z in [0.0, height] {
            let p = v(radius * a.cos(), radius * a.sin(), z);
            if keep(p) {
                points.push(p);
            }
        }
    }
    for z in [0.0, height] {
        points.push(v(0.0, -radius, z));
        points.push(v(0.0, radius, z));
    }
    points
}

impl Archetype {
    /// The two halves of a sliced instance, in its frame: split across x, the cut through its
    /// middle. Round things give half-spheres or half-cylinders, others half boxes.
    pub fn halves(&self, size: Vector, variant: u32) -> [Vec<Part>; 2] {
        let s = self.fit(size);
        let side = |sign: f32| move |p: Vector| p.x * sign >= -1e-6;
        match (self.shape, variant % self.shape.variants()) {
            (Shape::Ball, 0) => {
                let r = s.min_element();
                let ball = Vector::splat(r);
                [-1.0, 1.0].map(|sign| vec![hull(ellipsoid(ball, side(sign)))])
            }
            (Shape::Ball, _) => [-1.0, 1.0].map(|sign| vec![hull(ellipsoid(s, side(sign)))]),
            (Shape::Cylinder, _) => {
                let radius = s.x.min(s.y) / 2.0;
                [-1.0, 1.0].map(|sign| vec![hull(prism(radius, s.z, 16, side(sign)))])
            }
            _ => {
                let (min, max) = (v(-s.x / 2.0, -s.y / 2.0, 0.0), v(s.x / 2.0, s.y / 2.0, s.z));
                [
                    vec![span(min, v(0.0, max.y, max.z))],
                    vec![span(v(0.0, min.y, min.z), max)],
                ]
            }
        }
    }

    /// A size no larger than the archetype's largest (smaller is allowed: a sampler may shrink
    /// an object to fit its container), and at least 5 mm.
    pub fn fit(&self, size: Vector) -> Vector {
        let finite = Vector::select(size.is_finite_mask(), size, Vector::from_array(self.min));
        finite
            .min(Vector::from_array(self.max))
            .max(Vector::splat(0.005))
    }

    /// Builds an instance of the given size (see [`Archetype::fit`]) and variant.
    pub fn build(&self, name: &str, size: Vector, variant: u32) -> (ObjectSpec, Layout) {
        let s = self.fit(size);
        let (w, d, h) = (s.x, s.y, s.z);
        let (min, max) = (v(-w / 2.0, -d / 2.0, 0.0), v(w / 2.0, d / 2.0, h));
        let t = wall(s);
        let density = self.density;
        let variant = variant % self.shape.variants();
        let mut links = Vec::new();
        let mut layout = Layout {
            size: s,
            front_button: v(0.0, min.y - 0.01, 0.8 * h),
            outlet: None,
            burners: [None; 4],
        };
        let parts: Vec<Part> = match (self.shape, variant) {
            (Shape::Ball, 0) => vec![Part::at(
                Primitive::Sphere {
                    radius: w.min(d).min(h) / 2.0,
                },
                v(0.0, 0.0, w.min(d).min(h) / 2.0),
            )],
            // An ellipsoid filling the box: pears, eggs, lemons.
            (Shape::Ball, _) => vec![hull(ellipsoid(s, |_| true))],
            (Shape::Slab, 1) => vec![Part::at(
                Primitive::Cylinder {
                    radius: w.min(d) / 2.0,
                    half_height: h / 2.0,
                },
                v(0.0, 0.0, h / 2.0),
            )],
            (Shape::Rod, 1) => {
                // Round in section: a capsule lying along x.
                let radius = d.min(h) / 2.0;
                let lying = Pose::from_parts(
                    v(0.0, 0.0, radius),
                    Rotation::from_rotation_y(std::f32::consts::FRAC_PI_2),
                );
                vec![Part {
                    primitive: Primitive::Capsule {
                        radius,
                        half_height: (w / 2.0 - radius).max(0.001),
                    },
                    offset: lying,
                    visual: None,
                }]
            }
            // Worn: every edge chamfered by a fifth of the thinnest side.
            (Shape::Block, 1) => vec![hull(chamfered(min, max, 0.2 * w.min(d).min(h)))],
            (Shape::Block | Shape::Slab | Shape::Rod | Shape::Countertop | Shape::Floor, _) => {
                vec![span(min, max)]
            }
            (Shape::Cylinder, 0) => vec![Part::at(
                Primitive::Cylinder {
                    radius: w.min(d) / 2.0,
                    half_height: h / 2.0,
                },
                v(0.0, 0.0, h / 2.0),
            )],
            // Faceted: an octagonal prism (jars, tins, candles).
            (Shape::Cylinder, _) => vec![hull(prism(w.min(d) / 2.0, h, 8, |_| true))],
            (Shape::Agent, _) => vec![Part::at(
                Primitive::Capsule {
                    radius: w.min(d) / 2.0,
                    half_height: (h - w.min(d)).max(0.01) / 2.0,
                },
                v(0.0, 0.0, h / 2.0),
            )],
            (Shape::OpenContainer, _) => {
                if variant == 1 {
                    // Low and wide: a tray-like basin, same footprint, 60 % of the height.
                    tub(min, v(max.x, max.y, 0.6 * h), t)
                } else {
                    tub(min, max, t)
                }
            }
            (Shape::LiddedContainer, _) => {
                let (anchor, axis) = if variant == 0 {
                    (v(0.0, max.y, h), v(-1.0, 0.0, 0.0))
                } else {
                    (v(max.x, 0.0, h), v(0.0, 1.0, 0.0))
                };
                links.push(LinkSpec {
                    name: "lid".into(),
                    parts: vec![span(v(min.x, min.y, h), v(max.x, max.y, h + t))],
                    parent: None,
                    joint: JointSpec::opening(JointKind::Revolute, anchor, axis, 1.9, 1.0),
                    density,
                });
                tub(min, max, t)
            }
            (Shape::Table, _) => {
                let top = 0.03f32.min(h / 4.0);
                let mut parts = vec![span(v(min.x, min.y, h - top), max)];
                let leg = 0.03f32.min(w / 8.0).min(d / 8.0);
                if variant == 0 {
                    for (x, y) in [
                        (min.x, min.y),
                        (max.x - 2.0 * leg, min.y),
                        (min.x, max.y - 2.0 * leg),
                        (max.x - 2.0 * leg, max.y - 2.0 * leg),
                    ] {
                        parts.push(span(
                            v(x + leg / 2.0, y + leg / 2.0, 0.0),
                            v(x + 1.5 * leg, y + 1.5 * leg, h - top),
                        ));
                    }
                } else {
                    // Trestle: a panel under each end, leaving the middle free to walk under.
                    for x in [min.x + 0.1 * w, max.x - 0.1 * w - leg] {
                        parts.push(span(
                            v(x, min.y + 0.1 * d, 0.0),
                            v(x + leg, max.y - 0.1 * d, h - top),
                        ));
                    }
                }
                parts
            }
            (Shape::Shelf, _) => {
                let mut parts = vec![
                    span(min, v(min.x + t, max.y, max.z)),
                    span(v(max.x - t, min.y, min.z), max),
                    span(v(min.x, max.y - t, min.z), max),
                ];
                let boards = if variant == 0 { 3 } else { 4 };
                for k in 0..boards {
                    let z = k as f32 * (h - t) / (boards - 1) as f32;
                    parts.push(span(v(min.x, min.y, z), v(max.x, max.y, z + t)));
                }
                parts
            }
            (Shape::Cabinet, _) => {
                let mut parts = carcass(min, max, t);
                if variant == 0 {
                    parts.push(span(
                        v(min.x, min.y, h / 2.0 - t / 2.0),
                        v(max.x, max.y - t, h / 2.0 + t / 2.0),
                    ));
                    links.push(side_door("door", min, max, t, density));
                } else {
                    let mid = h / 2.0;
                    links.push(drawer(
                        "drawer_bottom",
                        v(min.x + t, min.y, t),
                        v(max.x - t, max.y - t, mid),
                        t,
                        density,
                    ));
                    links.push(drawer(
                        "drawer_top",
                        v(min.x + t, min.y, mid),
                        v(max.x - t, max.y - t, h - t),
                        t,
                        density,
                    ));
                }
                parts
            }
            (Shape::Fridge, _) => {
                let mut parts = carcass(min, max, t);
                parts.push(span(
                    v(min.x, min.y, h / 2.0),
                    v(max.x, max.y - t, h / 2.0 + t),
                ));
                links.push(side_door("door", min, max, t, density));
                layout.front_button = v(max.x - 0.05, min.y - 0.01, 0.6 * h);
                parts
            }
            (Shape::Oven | Shape::Dishwasher, _) => {
                let mut parts = carcass(min, max, t);
                parts.push(span(
                    v(min.x, min.y, h / 2.0),
                    v(max.x, max.y - t, h / 2.0 + t),
                ));
                links.push(drop_door(min, max, t, density));
                layout.front_button = v(0.0, min.y - 0.01, h + 0.02);
                parts.push(span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.06)));
                parts
            }
            (Shape::Microwave | Shape::Washer | Shape::Dryer, _) => {
                links.push(side_door("door", min, max, t, density));
                layout.front_button = v(max.x - 0.03, min.y - 0.01, 0.8 * h);
                carcass(min, max, t)
            }
            (Shape::Stove, _) => {
                let mut parts = vec![span(min, max)];
                // A control panel at the back of the top.
                parts.push(span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.1)));
                for (k, (fx, fy)) in [(-0.25, -0.2), (0.25, -0.2), (-0.25, 0.2), (0.25, 0.2)]
                    .into_iter()
                    .enumerate()
                {
                    layout.burners[k] = Some(v(fx * w, fy * d, h + 0.02));
                }
                layout.front_button = v(0.0, max.y - 0.06, h + 0.05);
                parts
            }
            (Shape::Sink, _) => {
                // A basin on a stand, with a spout at the back.
                let bowl = 0.25f32.min(h / 2.0);
                let mut parts = vec![span(
                    v(min.x + t, min.y + t, 0.0),
                    v(max.x - t, max.y - t, h - bowl),
                )];
                parts.extend(tub(v(min.x, min.y, h - bowl), max, t));
                parts.push(span(
                    v(-0.02, max.y - 0.05, h),
                    v(0.02, max.y - 0.01, h + 0.3),
                ));
                layout.outlet = Some(v(0.0, max.y - 0.1, h + 0.25));
                layout.front_button = v(0.08, max.y - 0.03, h + 0.05);
                parts
            }
            (Shape::Bathtub, _) => {
                layout.outlet = Some(v(min.x + 0.15, 0.0, h + 0.2));
                layout.front_button = v(min.x + 0.05, 0.0, h + 0.05);
                tub(min, max, t.max(0.03))
            }
            (Shape::Shower, _) => {
                let mut parts = vec![span(min, v(max.x, max.y, 0.05))];
                parts.push(span(v(min.x, min.y, 0.0), v(min.x + t, max.y, h)));
                parts.push(span(v(max.x - t, min.y, 0.0), v(max.x, max.y, h)));
                parts.push(span(v(min.x, max.y - t, 0.0), v(max.x, max.y, h)));
                layout.outlet = Some(v(0.0, max.y - 0.15, h - 0.2));
                layout.front_button = v(0.0, max.y - t - 0.01, 1.1);
                parts
            }
            (Shape::Toilet, _) => {
                let seat = 0.42f32.min(h * 0.6);
                let mut parts = vec![span(
                    v(-0.12, min.y + 0.1, 0.0),
                    v(0.12, max.y - 0.2, seat - 0.15),
                )];
                parts.extend(tub(
                    v(min.x, min.y, seat - 0.15),
                    v(max.x, max.y - 0.18, seat),
                    0.02,
                ));
                parts.push(span(v(min.x, max.y - 0.18, 0.0), v(max.x, max.y, h)));
                layout.front_button = v(max.x - 0.03, max.y - 0.09, h + 0.01);
                parts
            }
            (Shape::Bed, _) => {
                let base = 0.6 * h;
                vec![
                    span(min, v(max.x, max.y, base)),
                    span(
                        v(min.x + 0.02, min.y + 0.02, base),
                        v(max.x - 0.02, max.y - 0.1, h),
                    ),
                    span(v(min.x, max.y - 0.08, 0.0), v(max.x, max.y, h + 0.4)),
                ]
            }
            (Shape::Sofa, _) => {
                let seat = 0.45f32.min(h * 0.55);
                vec![
                    span(min, v(max.x, max.y, seat)),
                    span(v(min.x, max.y - 0.2, seat), max),
                    span(
                        v(min.x, min.y, seat),
                        v(min.x + 0.15, max.y - 0.2, seat + 0.2),
                    ),
                    span(
                        v(max.x - 0.15, min.y, seat),
                        v(max.x, max.y - 0.2, seat + 0.2),
                    ),
                ]
            }
            (Shape::Chair, _) => {
                let seat = 0.46f32.min(h * 0.55);
                let leg = 0.03;
                let mut parts = vec![span(v(min.x, min.y, seat - 0.04), v(max.x, max.y, seat))];
                for (x, y) in [
                    (min.x, min.y),
                    (max.x - leg, min.y),
                    (min.x, max.y - leg),
                    (max.x - leg, max.y - leg),
                ] {
                    parts.push(span(v(x, y, 0.0), v(x + leg, y + leg, seat - 0.04)));
                }
                parts.push(span(v(min.x, max.y - leg, seat), max));
                if variant == 1 {
                    // Arms.
                    parts.push(span(
                        v(min.x, min.y, seat + 0.2),
                        v(min.x + leg, max.y, seat + 0.23),
                    ));
                    parts.push(span(
                        v(max.x - leg, min.y, seat + 0.2),
                        v(max.x, max.y, seat + 0.23),
                    ));
                }
                parts
            }
            (Shape::Door | Shape::Window, _) => {
                // A frame in the x–z plane (y is the wall's thickness) and a leaf on a hinge.
                let frame = 0.05;
                let (sill, h) = match (self.shape, variant) {
                    (Shape::Window, 0) => (0.9, h),
                    (Shape::Window, _) => (0.05, h + 0.85),
                    _ => (0.0, h),
                };
                let parts = vec![
                    span(v(min.x, min.y, sill), v(min.x + frame, max.y, sill + h)),
                    span(v(max.x - frame, min.y, sill), v(max.x, max.y, sill + h)),
                    span(v(min.x, min.y, sill + h - frame), v(max.x, max.y, sill + h)),
                ];
                links.push(LinkSpec {
                    name: "leaf".into(),
                    parts: vec![span(
                        v(min.x + frame, min.y + d / 4.0, sill + 0.01),
                        v(max.x - frame, max.y - d / 4.0, sill + h - frame),
                    )],
                    parent: None,
                    joint: JointSpec::opening(
                        JointKind::Revolute,
                        v(min.x + frame, 0.0, 0.0),
                        v(0.0, 0.0, -1.0),
                        1.6,
                        2.0,
                    ),
                    density,
                });
                layout.front_button = v(max.x - frame - 0.05, min.y - 0.01, sill + h * 0.5);
                parts
            }
        };
        let mut spec = ObjectSpec::new(name, self.synset, parts);
        spec.body = if self.shape.is_fixed() {
            BodyKind::Fixed
        } else {
            BodyKind::Dynamic
        };
        spec.density = density;
        spec.friction = self.material.friction();
        spec.visual = Visual {
            color: self.color,
            material: self.material,
        };
        spec.links = links;
        (spec, layout)
    }
}
