//! What an object is made of: the spec a caller writes ([`ObjectSpec`]: parts, links on joints,
//! abilities, named points, appearance) and what the world keeps once it is built ([`Object`]).
//!
//! Every length is in metres in the object's own frame (z up). Links — doors, drawers, lids, and a
//! robot's arm segments — are given in the object's frame *at the zero position of every joint*,
//! each on one joint to the object's body or to an earlier link, so a chain is written as it stands
//! when all its joints read zero.

use crate::visual::{Form, Ghost, Material, ModelPiece, Visual, VisualMesh};
use behavior_core::{Ability, AbilityParams, ParamValue};
use rapier3d::dynamics::{ImpulseJointHandle, MultibodyJointHandle, RigidBodyHandle};
use rapier3d::geometry::ColliderHandle;
use rapier3d::math::{Pose, Vector};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Index of an object in its [`crate::World`], stable for the world's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct ObjectId(pub u32);

/// One rigid body of the world: an object's own body (`link: None`) or one of its links.
///
/// Velocities, forces, contacts and attachments act on bodies, so a hand can hold a drawer by its
/// front without holding the cabinet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct BodyRef {
    /// The object the body belongs to.
    pub object: ObjectId,
    /// The link's index in [`Object::links`], or `None` for the object's own body.
    pub link: Option<usize>,
}

impl From<ObjectId> for BodyRef {
    fn from(object: ObjectId) -> BodyRef {
        BodyRef { object, link: None }
    }
}

impl BodyRef {
    /// Link `link` of `object`.
    pub fn link(object: ObjectId, link: usize) -> BodyRef {
        BodyRef {
            object,
            link: Some(link),
        }
    }
}

/// A collision primitive in the object's frame. Cylinders and capsules stand along z.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Primitive {
    /// A box of the given half extents.
    Box {
        /// Half the size along x, y and z.
        half_extents: Vector,
    },
    /// An upright cylinder.
    Cylinder {
        /// m.
        radius: f32,
        /// Half its height, m.
        half_height: f32,
    },
    /// A ball.
    Sphere {
        /// m.
        radius: f32,
    },
    /// An upright capsule: a cylinder of `half_height` capped by half-balls.
    Capsule {
        /// m.
        radius: f32,
        /// Half the height of its cylinder, m.
        half_height: f32,
    },
    /// The convex hull of these points (imported meshes, convex decompositions).
    ConvexHull {
        /// At least four points, not all in a plane.
        points: Vec<Vector>,
    },
}

impl Primitive {
    /// The box around it in its own frame, as its lowest and highest corners.
    pub fn local_box(&self) -> (Vector, Vector) {
        let half = match *self {
            Primitive::Box { half_extents } => half_extents,
            Primitive::Cylinder {
                radius,
                half_height,
            } => Vector::new(radius, radius, half_height),
            Primitive::Sphere { radius } => Vector::splat(radius),
            Primitive::Capsule {
                radius,
                half_height,
            } => Vector::new(radius, radius, radius + half_height),
            Primitive::ConvexHull { ref points } => {
                let lo = points
                    .iter()
                    .copied()
                    .fold(Vector::splat(f32::MAX), Vector::min);
                let hi = points
                    .iter()
                    .copied()
                    .fold(Vector::splat(f32::MIN), Vector::max);
                return if lo.x <= hi.x {
                    (lo, hi)
                } else {
                    (Vector::ZERO, Vector::ZERO)
                };
            }
        };
        (-half, half)
    }
}

/// One primitive of an object's compound shape, placed in the object's frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Part {
    /// Its shape.
    pub primitive: Primitive,
    /// Its pose in the object's frame.
    pub offset: Pose,
    /// Its appearance, when it differs from the object's (a red button on a white stove).
    pub visual: Option<Visual>,
    /// How it is drawn: its primitive, or a detailed form filling the box around it.
    pub form: Form,
}

impl Part {
    /// A part at the object's origin.
    pub fn new(primitive: Primitive) -> Part {
        Part {
            primitive,
            offset: Pose::IDENTITY,
            visual: None,
            form: Form::Primitive,
        }
    }

    /// A part whose centre is at `offset` in the object's frame.
    pub fn at(primitive: Primitive, offset: Vector) -> Part {
        Part {
            primitive,
            offset: Pose::from_translation(offset),
            visual: None,
            form: Form::Primitive,
        }
    }

    /// The same part drawn in a detailed form.
    pub fn with_form(mut self, form: Form) -> Part {
        self.form = form;
        self
    }

    /// The same part with an appearance of its own.
    pub fn with_visual(mut self, visual: Visual) -> Part {
        self.visual = Some(visual);
        self
    }
}

/// How an object's body moves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum BodyKind {
    /// Never moves: furniture, walls, floors.
    Fixed,
    /// Moved by forces and contacts.
    #[default]
    Dynamic,
    /// Moved only by the caller, toward a pose set with [`crate::Bodies::set_kinematic_target`];
    /// it pushes dynamic bodies and nothing pushes it (a robot's base driven to a pose).
    /// Beware: once turned away from the identity rotation it never sleeps, even untouched
    /// (rapier derives its velocity from rounded rotations, about 1e-4 rad/s); a body that must
    /// rest cheaply (the robots' parts) is better `KinematicVelocity`, stopped at exactly zero.
    KinematicPosition,
    /// Moved only by the caller, at a velocity set with [`crate::Bodies::set_velocity`]
    /// (a differential-drive base).
    KinematicVelocity,
}

/// Everything needed to add an object.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ObjectSpec {
    /// E.g. `apple.n.01_1` once bound to an activity, or a scene name such as `table_3`.
    pub name: String,
    /// The synset, e.g. `apple.n.01`.
    pub category: String,
    /// The body's shape: at least one part.
    pub parts: Vec<Part>,
    /// Where the object stands.
    pub pose: Pose,
    /// Fixed, dynamic or kinematic.
    pub body: BodyKind,
    /// Whether its dynamic body and links start asleep: for an object put where it already came
    /// to rest (a home's clutter, settled when the home was made; a cabinet's closed door), so
    /// that it costs nothing per step until something touches it, when it wakes like any
    /// sleeping body. Put it where it rests: asleep, it does not fall.
    pub asleep: bool,
    /// kg/m³; the mass follows from the parts' volumes.
    pub density: f32,
    /// Coulomb friction coefficient of every part.
    pub friction: f32,
    /// 1/s. Stands in for rolling resistance: household objects are not perfect spheres, and
    /// without it a round object nudged on a flat plate rolls away for ever.
    pub angular_damping: f32,
    /// What the object can do or undergo, with the parameters (from the taxonomy).
    #[serde(with = "crate::bytes::abilities")]
    pub abilities: BTreeMap<Ability, AbilityParams>,
    /// Named points in the object's frame: heating element, toggle button, water outlet, slicing
    /// edge, cleaning area.
    pub points: Vec<(PointKind, Vector)>,
    /// Moving parts: doors, drawers and lids, or a robot's segments, each on one joint.
    pub links: Vec<LinkSpec>,
    /// For a sliceable object, the parts of its two halves in its frame; without them slicing
    /// splits its bounding box.
    pub halves: Option<[Vec<Part>; 2]>,
    /// How the object looks where a part does not say otherwise.
    pub visual: Visual,
    /// Visual-only meshes (an imported model's look), drawn instead of the collision parts of
    /// the body or link they belong to.
    pub meshes: Vec<VisualMesh>,
    /// A detailed form drawn instead of the body's parts, filling the box around them (a bowl
    /// whose colliders are a bottom and four walls); [`Form::Primitive`] draws the parts. Not
    /// passed on to the halves of a sliced object.
    pub form: Form,
    /// A piece of a real model (a robot's link) drawn instead of the body's parts where the
    /// renderer holds its meshes ([`crate::ModelLibrary`]); the parts (in their forms) are the
    /// look where it does not.
    pub model: Option<ModelPiece>,
}

/// Where an ability acts, as a point in the object's frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum PointKind {
    /// A heat source's element (stove burner): objects within its distance threshold heat up.
    HeatingElement,
    /// Touched by a hand for a few steps, it toggles the object on or off.
    ToggleButton,
    /// Where a water source's drops come out.
    WaterOutlet,
    /// A slicer's cutting edge: only contacts within [`crate::EDGE_REACH`] of it slice.
    SlicingEdge,
    /// A cleaning tool's working face: only particles within [`crate::CLEANING_REACH`] of it
    /// are wiped.
    CleaningArea,
}

/// How a link moves relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum JointKind {
    /// Turns about the axis (radians).
    Revolute,
    /// Slides along the axis (metres).
    Prismatic,
    /// Does not move (a camera mount, a fingertip pad).
    Fixed,
}

/// How the solver treats a joint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum JointModel {
    /// A constraint between two free bodies (rapier's impulse joints): cheap, and right for doors,
    /// drawers and lids, whose looseness nobody sees.
    #[default]
    Impulse,
    /// Reduced coordinates (rapier's multibody joints): the chain cannot drift apart, so a robot
    /// arm holds its pose under load. A chain's links must all use this model.
    Multibody,
}

/// The joint that carries a link.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct JointSpec {
    /// Revolute, prismatic or fixed.
    pub kind: JointKind,
    /// Impulse or multibody.
    pub model: JointModel,
    /// A point on the joint axis, in the object's frame.
    pub anchor: Vector,
    /// The joint axis, in the object's frame; positive positions turn or slide about it.
    pub axis: Vector,
    /// The lowest and highest positions (radians or metres), or `None` for a free joint (a
    /// wheel). A door's closed position is its lower limit.
    pub limits: Option<[f32; 2]>,
    /// Passive damping: a motor toward velocity 0 of this factor while no drive is set.
    pub damping: f32,
}

/// A moving part of an object: its parts (in the object's frame, at the zero position of every
/// joint) and the joint that carries it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LinkSpec {
    /// E.g. `door_0`, `shoulder_pan_link`.
    pub name: String,
    /// Its shape; may be empty for a massless frame (a camera mount) on a fixed joint.
    pub parts: Vec<Part>,
    /// The link it hangs from, an index into [`ObjectSpec::links`] before this one, or `None` for
    /// the object's body.
    pub parent: Option<usize>,
    /// The joint to its parent.
    pub joint: JointSpec,
    /// kg/m³.
    pub density: f32,
}

impl JointSpec {
    /// The joint of a door, drawer or lid on an object's body: closed at 0, fully open at `range`
    /// (radians for [`JointKind::Revolute`], metres for [`JointKind::Prismatic`]), with passive
    /// damping so it stays where it is left.
    pub fn opening(
        kind: JointKind,
        anchor: Vector,
        axis: Vector,
        range: f32,
        damping: f32,
    ) -> Self {
        JointSpec {
            kind,
            model: JointModel::Impulse,
            anchor,
            axis,
            limits: Some([0.0, range]),
            damping,
        }
    }
}

impl ObjectSpec {
    /// A dynamic object of wood-like density at the origin, with no abilities.
    pub fn new(name: &str, category: &str, parts: Vec<Part>) -> ObjectSpec {
        ObjectSpec {
            name: name.to_string(),
            category: category.to_string(),
            parts,
            pose: Pose::IDENTITY,
            body: BodyKind::Dynamic,
            asleep: false,
            density: 500.0,
            friction: 0.7,
            angular_damping: 1.0,
            abilities: BTreeMap::new(),
            points: Vec::new(),
            links: Vec::new(),
            halves: None,
            visual: Visual::default(),
            meshes: Vec::new(),
            form: Form::Primitive,
            model: None,
        }
    }

    /// The same object standing at `position`.
    pub fn at(mut self, position: Vector) -> ObjectSpec {
        self.pose = Pose::from_translation(position);
        self
    }

    /// The same object, fixed in place.
    pub fn fixed(mut self) -> ObjectSpec {
        self.body = BodyKind::Fixed;
        self
    }

    /// The same object with another kind of body.
    pub fn body(mut self, body: BodyKind) -> ObjectSpec {
        self.body = body;
        self
    }

    /// The same object, starting asleep (see [`ObjectSpec::asleep`]).
    pub fn asleep(mut self) -> ObjectSpec {
        self.asleep = true;
        self
    }

    /// Adds an ability with its parameters, e.g. `(Cookable, &[("cook_temperature", 70)])`.
    pub fn ability(mut self, ability: Ability, params: &[(&str, ParamValue)]) -> ObjectSpec {
        let params = params.iter().map(|(k, v)| (k.to_string(), *v)).collect();
        self.abilities.insert(ability, params);
        self
    }

    /// Adds a named point.
    pub fn point(mut self, kind: PointKind, position: Vector) -> ObjectSpec {
        self.points.push((kind, position));
        self
    }

    /// Adds a link.
    pub fn link(mut self, link: LinkSpec) -> ObjectSpec {
        self.links.push(link);
        self
    }

    /// The same object in another colour (sRGB) and material.
    pub fn looks(mut self, color: [u8; 3], material: Material) -> ObjectSpec {
        self.visual = Visual { color, material };
        self
    }
}

/// A built object, as the world keeps it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Object {
    /// Its name, unique by convention (not enforced).
    pub name: String,
    /// Its synset.
    pub category: String,
    /// Fixed, dynamic or kinematic.
    pub body_kind: BodyKind,
    pub(crate) body: RigidBodyHandle,
    /// Every collider of the object, its links' included.
    pub(crate) colliders: Vec<ColliderHandle>,
    /// What it can do or undergo.
    #[serde(with = "crate::bytes::abilities")]
    pub abilities: BTreeMap<Ability, AbilityParams>,
    /// Named points in its frame.
    pub points: Vec<(PointKind, Vector)>,
    /// Its links, built.
    pub links: Vec<Link>,
    /// The parts of its halves, for slicing.
    pub halves: Option<[Vec<Part>; 2]>,
    /// The density it was made with (for its halves).
    pub density: f32,
    /// The friction of its parts (its halves keep it).
    pub friction: f32,
    /// The angular damping of its body (its halves keep it).
    pub angular_damping: f32,
    /// The body's parts as given (for drawing).
    pub parts: Vec<Part>,
    /// Its appearance.
    pub visual: Visual,
    /// Visual-only meshes.
    pub meshes: Vec<VisualMesh>,
    /// The body's form ([`ObjectSpec::form`]).
    pub form: Form,
    /// The body's model piece ([`ObjectSpec::model`]).
    pub model: Option<ModelPiece>,
    /// The two objects that replaced it when it was sliced: it has left the simulation.
    pub replaced_by: Option<[ObjectId; 2]>,
    /// Taken out of the simulation by [`crate::Bodies::retire`] (a stand-in a robot replaced).
    pub retired: bool,
    /// A shape drawn with the object but outside the physics, placed by its owner
    /// ([`crate::Bodies::set_ghost`]): the BehaviorRobot's head round its eye.
    pub ghost: Option<Ghost>,
}

/// A built link: its body, colliders and joint.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Link {
    /// Its name.
    pub name: String,
    /// Its parent link, or `None` for the object's body.
    pub parent: Option<usize>,
    /// Its joint, as specified (axis normalized).
    pub joint: JointSpec,
    /// Its parts as given (for drawing).
    pub parts: Vec<Part>,
    pub(crate) body: RigidBodyHandle,
    pub(crate) handle: JointHandle,
}

/// The solver's handle of a link's joint.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub(crate) enum JointHandle {
    Impulse(ImpulseJointHandle),
    Multibody(MultibodyJointHandle),
}

impl Object {
    /// Whether it has an ability.
    pub fn has(&self, ability: Ability) -> bool {
        self.abilities.contains_key(&ability)
    }

    /// A numeric parameter of an ability, or `default` when the ability lists none.
    pub fn param(&self, ability: Ability, name: &str, default: f32) -> f32 {
        self.abilities
            .get(&ability)
            .and_then(|p| p.get(name))
            .and_then(|v| v.as_f64())
            .map_or(default, |v| v as f32)
    }

    /// A boolean parameter of an ability, or `default`.
    pub fn flag(&self, ability: Ability, name: &str, default: bool) -> bool {
        self.abilities
            .get(&ability)
            .and_then(|p| p.get(name))
            .and_then(|v| v.as_bool())
            .unwrap_or(default)
    }

    /// The first named point of a kind, in the object's frame.
    pub fn point(&self, kind: PointKind) -> Option<Vector> {
        self.points
            .iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, p)| *p)
    }

    /// Whether it never moves.
    pub fn is_fixed(&self) -> bool {
        self.body_kind == BodyKind::Fixed
    }

    /// Whether it is still in the simulation (not replaced by its halves, not retired).
    pub fn is_present(&self) -> bool {
        self.replaced_by.is_none() && !self.retired
    }
}
