//! Archetypes: how an object of a synset is built from primitives, at any size in its range.
//!
//! An archetype names a [`Shape`] (a family of procedural geometry), the bounding-box size range
//! of real instances, a material density and a colour. [`Archetype::build`] turns a size and a
//! variant into an [`ObjectSpec`] whose bottom rests at z = 0, centred on the origin, with the
//! doors, drawers and lids its shape has. Abilities and the named points they need are added by
//! the [`crate::library::Library`], from the taxonomy of the synset asked for.
//!
//! Each family of shapes is built by a short function in a private submodule named for what it
//! holds — `solids`, `containers`, `furniture`, `appliances`, `plumbing`, `openings` — from the
//! boxes and point clouds of `geometry` and the doors and drawers of `moving_parts`;
//! [`Archetype::build`] picks the function and finishes the spec.

mod appliances;
mod containers;
mod furniture;
mod geometry;
mod looks;
mod moving_parts;
mod openings;
mod plumbing;
mod solids;

pub use behavior_sim::Material;
use behavior_sim::{BodyKind, LinkSpec, ObjectSpec, Part, Visual};
use geometry::{ellipsoid, hull, prism, span, v, wall};
use rapier3d::math::{Rotation, Vector};

/// A family of procedural geometry. Containers have real walls and an opening, so `inside` is
/// physical; furniture that opens has doors or drawers on joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    /// A sphere (variant 0) or an ellipsoid filling its box (variant 1): fruit, eggs, balls.
    Ball,
    /// A box (variant 0) or a worn one with chamfered edges (variant 1): books, soap, boxes.
    Block,
    /// Upright and round (variant 0) or an octagonal prism (variant 1): bottles, jars, cans.
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
    /// A top on four legs (variant 0) or on two end panels (variant 1), so things go on and under it.
    Table,
    /// Open shelving: sides, back and boards.
    Shelf,
    /// A carcass with one shelf and a door (variant 0) or two drawers (variant 1).
    Cabinet,
    /// A solid block at counter height.
    Countertop,
    /// A carcass with a shelf behind a side-hinged door: things go inside and cool.
    Fridge,
    /// A carcass with a rack behind a door hinged at the bottom, and a control panel on top.
    Oven,
    /// A small carcass behind a side-hinged door, standing on a countertop.
    Microwave,
    /// A solid block with four burners (heating elements) on top.
    Stove,
    /// A basin on a stand with a spout, where water comes out.
    Sink,
    /// Built like an oven: a rack behind a drop-down door.
    Dishwasher,
    /// A carcass behind a side-hinged door, like a dryer.
    Washer,
    /// A carcass behind a side-hinged door, like a washer.
    Dryer,
    /// A base with a mattress and a headboard at the back.
    Bed,
    /// A seat with a back and two arms.
    Sofa,
    /// A seat on four legs with a back (variant 0), with arms too (variant 1).
    Chair,
    /// Built as a [`Shape::Chair`], but movable: a seat people carry from room to room (a
    /// dining chair stays where it stands round its table).
    Stool,
    /// A pedestal, a bowl and a cistern with its flush button.
    Toilet,
    /// A tub with thick walls and a tap at one end.
    Bathtub,
    /// A tray with walls on three sides and a shower head on the back one.
    Shower,
    /// A frame with a door leaf on a hinge.
    Door,
    /// A frame with a casement on a hinge: a window with a sill at 0.9 m (variant 0) or a
    /// floor-length one, from 5 cm up and 0.85 m taller (variant 1), that a lamp or a stool on
    /// the floor can stand next to.
    Window,
    /// A solid slab: what a room's floor is made of when built as an object.
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
            | Shape::Stool
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
                | Shape::Stool
                | Shape::Agent
        )
    }
}

/// An object family for one synset: enough to build an instance of any size in its range, with
/// a plausible mass, friction and look.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Archetype {
    /// The synset it is for, e.g. `apple.n.01`; the catalog's key.
    pub synset: &'static str,
    /// The family of geometry it is built as.
    pub shape: Shape,
    /// Bounding box (width x, depth y, height z; metres) of the smallest instances…
    pub min: [f32; 3],
    /// …and of the largest; sizes are drawn uniformly between them.
    pub max: [f32; 3],
    /// Of the material, kg/m³; masses follow from the parts' volumes.
    pub density: f32,
    /// What it is made of: its friction and, for a renderer, its surface.
    pub material: Material,
    /// sRGB, 0–255.
    pub color: [u8; 3],
}

/// Where the parts of a built object are, for adding named points afterwards.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The size the object was built at (its archetype's fit of the size asked for).
    pub size: Vector,
    /// A point on the front face (−y) at a sensible button height.
    pub front_button: Vector,
    /// Where water falls from, for sinks and showers.
    pub outlet: Option<Vector>,
    /// Burner positions, for stoves.
    pub burners: [Option<Vector>; 4],
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

    /// Builds an instance of the given size (see [`Archetype::fit`]) and variant (taken modulo
    /// [`Shape::variants`]): its body, its doors, drawers and lids, and the [`Layout`] of the
    /// points the library may add. Each family of shapes builds in a module of its own.
    pub fn build(&self, name: &str, size: Vector, variant: u32) -> (ObjectSpec, Layout) {
        let blank = Blank::new(self, size, variant);
        let build: fn(&Blank) -> Built = match self.shape {
            Shape::Ball => solids::ball,
            Shape::Block => solids::block,
            Shape::Cylinder => solids::cylinder,
            Shape::Slab => solids::slab,
            Shape::Rod => solids::rod,
            Shape::Countertop | Shape::Floor => solids::solid,
            Shape::Agent => solids::agent,
            Shape::OpenContainer => containers::open,
            Shape::LiddedContainer => containers::lidded,
            Shape::Table => furniture::table,
            Shape::Shelf => furniture::shelf,
            Shape::Cabinet => furniture::cabinet,
            Shape::Bed => furniture::bed,
            Shape::Sofa => furniture::sofa,
            Shape::Chair | Shape::Stool => furniture::chair,
            Shape::Fridge => appliances::fridge,
            Shape::Oven => appliances::oven,
            Shape::Dishwasher => appliances::dishwasher,
            Shape::Microwave => appliances::microwave,
            Shape::Washer | Shape::Dryer => appliances::laundry,
            Shape::Stove => appliances::stove,
            Shape::Sink => plumbing::sink,
            Shape::Bathtub => plumbing::bathtub,
            Shape::Shower => plumbing::shower,
            Shape::Toilet => plumbing::toilet,
            Shape::Door => openings::door,
            Shape::Window => openings::window,
        };
        let Built {
            parts,
            links,
            layout,
        } = build(&blank);
        let mut spec = ObjectSpec::new(name, self.synset, parts);
        spec.body = if self.shape.is_fixed() {
            BodyKind::Fixed
        } else {
            BodyKind::Dynamic
        };
        spec.density = self.density;
        spec.friction = self.material.friction();
        spec.visual = Visual {
            color: self.color,
            material: self.material,
        };
        spec.links = links;
        looks::dress(&mut spec, self);
        (spec, layout)
    }
}

/// An instance about to be built: its fitted size and what every family derives from it.
struct Blank {
    /// The fitted size (see [`Archetype::fit`]).
    size: Vector,
    /// Width (x), depth (y) and height (z) of `size`, named as the geometry reads them.
    w: f32,
    d: f32,
    h: f32,
    /// The bounding box: centred on the origin, standing on z = 0.
    min: Vector,
    max: Vector,
    /// Wall thickness for containers and carcasses of this footprint.
    t: f32,
    /// Of the material, kg/m³, for links.
    density: f32,
    /// Which variant, already taken modulo the shape's count.
    variant: u32,
}

impl Blank {
    fn new(archetype: &Archetype, size: Vector, variant: u32) -> Blank {
        let s = archetype.fit(size);
        let (w, d, h) = (s.x, s.y, s.z);
        Blank {
            size: s,
            w,
            d,
            h,
            min: v(-w / 2.0, -d / 2.0, 0.0),
            max: v(w / 2.0, d / 2.0, h),
            t: wall(s),
            density: archetype.density,
            variant: variant % archetype.shape.variants(),
        }
    }

    /// A body of these parts, without links, its toggle button on the front at 80 % of the
    /// height, no outlet and no burners; families with other points move them.
    fn body(&self, parts: Vec<Part>) -> Built {
        Built {
            parts,
            links: Vec::new(),
            layout: Layout {
                size: self.size,
                front_button: v(0.0, self.min.y - 0.01, 0.8 * self.h),
                outlet: None,
                burners: [None; 4],
            },
        }
    }
}

/// What a family builds: the body's parts, its links in order, and where its points are.
struct Built {
    parts: Vec<Part>,
    links: Vec<LinkSpec>,
    layout: Layout,
}

impl Built {
    /// The same, with one more link after those it has.
    fn with_link(mut self, link: LinkSpec) -> Built {
        self.links.push(link);
        self
    }
}
