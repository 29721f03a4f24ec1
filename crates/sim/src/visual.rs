//! How objects look: every object's parts with their shape, pose, link, colour and material, so
//! that a renderer that depends only on the world can draw it.
//!
//! Appearance is data the world carries and never reads: the physics ignores it, except that a
//! [`Material`] also names a typical friction for callers that build specs from it.

use crate::bodies::Bodies;
use crate::object::{ObjectId, Part, Primitive};
use rapier3d::math::{Pose, Vector};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// What a surface is made of.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Material {
    /// Furniture, boards.
    #[default]
    Wood,
    /// Pans, cutlery, appliances.
    Metal,
    /// Containers, toys, devices.
    Plastic,
    /// Jars, windows (a renderer may draw it translucent).
    Glass,
    /// Plates, bowls, toilets.
    Ceramic,
    /// Towels, clothes.
    Cloth,
    /// Books, boxes, mail.
    Paper,
    /// Fruit, vegetables, meals.
    Food,
    /// Balls, mats, tyres.
    Rubber,
    /// Countertops, tiles.
    Stone,
}

impl Material {
    /// Coulomb friction coefficient against typical household surfaces (engineering-table values:
    /// wood on wood ~0.4, metal ~0.4, plastic ~0.35, glass and glazed ceramic ~0.25–0.3, cloth and
    /// rubber high).
    pub fn friction(self) -> f32 {
        match self {
            Material::Wood => 0.45,
            Material::Metal => 0.4,
            Material::Plastic => 0.35,
            Material::Glass => 0.25,
            Material::Ceramic => 0.3,
            Material::Cloth => 0.7,
            Material::Paper => 0.5,
            Material::Food => 0.6,
            Material::Rubber => 0.9,
            Material::Stone => 0.55,
        }
    }
}

/// A surface's appearance: an sRGB colour and a material.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Visual {
    /// sRGB, 0–255.
    pub color: [u8; 3],
    /// What it is made of.
    pub material: Material,
}

impl Default for Visual {
    /// A neutral light grey wood, for objects nobody coloured.
    fn default() -> Self {
        Visual {
            color: [200, 200, 200],
            material: Material::Wood,
        }
    }
}

/// A detailed shape drawn in place of plain primitives: a renderer makes its mesh from the form,
/// the box it fills and a seed (see the `behavior-forms` crate), so the world carries a word
/// where it would otherwise carry thousands of vertices, and checkpoints stay small.
///
/// A part's form is drawn filling the box around its primitive; an object's form
/// ([`crate::ObjectSpec::form`]) fills the box around all its body's parts and is drawn instead
/// of them. The physics never reads it: what collides is still the parts.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
pub enum Form {
    /// The primitive itself.
    #[default]
    Primitive,
    /// A box with rounded edges (a bevel of a quarter of its thinnest half side, at most 12 mm):
    /// boards, carcasses, appliances, boxes.
    Rounded,
    /// A box rounded like a cushion, a bar of soap or a slab of cheese.
    Soft,
    /// A smooth ball or ellipsoid.
    Round,
    /// A turned post: a spindle with beads (table and chair legs, candlesticks).
    Turned,
    /// An apple: a dimpled ball with a stem.
    Apple,
    /// A round fruit or vegetable with a small calyx: an orange, a tomato, a peach.
    Fruit,
    /// A lemon: an ellipsoid with pointed ends.
    Lemon,
    /// An egg.
    Egg,
    /// Broccoli or lettuce: a stalk under a cluster of florets.
    Florets,
    /// A mushroom: a cap on a stalk.
    Mushroom,
    /// A strawberry or raspberry: a rounded cone.
    Berry,
    /// A banana: a curved, ridged, tapering body, lying along x.
    Banana,
    /// A carrot: a long taper with its leaves' stub, lying along x.
    Carrot,
    /// A loaf: a block with a domed top.
    Loaf,
    /// A bottle: body, shoulder, neck and cap.
    Bottle,
    /// A can or tin with rolled rims.
    Can,
    /// A cup or drinking glass, open at the top.
    Cup,
    /// A mug: a cup with a handle on +x.
    Mug,
    /// A bowl on a foot ring.
    Bowl,
    /// A plate with a well and a rim.
    Plate,
    /// A cooking pot with two handles on ±x.
    Pot,
    /// A bucket or bin: a tapered tub with a rolled rim.
    Bucket,
    /// A cake or round dish: a cylinder with soft edges.
    Cake,
    /// A book: covers and spine around a block of pages.
    Book,
    /// Folded cloth: a soft slab in layers.
    Folded,
    /// A pen, pencil or marker lying along x: a round barrel with a tip.
    Pen,
    /// A table lamp: base, stem and shade.
    Lamp,
    /// A plant in a pot: pot, soil and a crown of leaves.
    Plant,
    /// A person's trunk from the hips to the neck, with shoulders, 0.6 as deep (along x) as
    /// wide: the BehaviorRobot's body.
    Torso,
    /// A door leaf facing −y, hinged on −x: a panel (raised in its middle on some seeds) with a
    /// bar or a knob by its free edge (cabinets, fridges, the homes' doors).
    Door,
    /// A side-hinged door glazed over most of its width, a bar by its free edge (microwaves).
    GlassDoor,
    /// A drawer's front facing −y: a panel with a bar or a knob at its middle.
    DrawerFront,
    /// A door hinged at its bottom edge, facing −y: a panel with a bar along its top
    /// (dishwashers).
    DropDoor,
    /// An oven's door: a drop-down door with a dark window under its bar.
    OvenDoor,
    /// A washer's or dryer's door facing −y: a round window in a metal ring.
    Porthole,
    /// A control panel facing −y: a row of knobs and a display.
    Controls,
    /// A stove: a block with four burners on its top, an oven's window and bar on its front.
    Cooktop,
    /// A sink's tap: a metal column on a round foot under a wider head.
    Tap,
    /// A made bed's mattress, head at +y: a sheet, a duvet turned back, one or two pillows.
    Bedding,
    /// A sofa's seat: a plinth under a row of two or three cushions.
    Seat,
    /// A knife lying along x: a dark handle toward −x, the blade toward +x.
    Knife,
    /// A fork lying along x: a handle, the tines toward +x.
    Fork,
    /// A spoon lying along x: a handle, the bowl toward +x.
    Spoon,
    /// A broom or a brush lying along x: bristles under a stock toward −x, a handle toward +x.
    Broom,
    /// A Christmas tree: a stand, a trunk, tiers of boughs up to a point.
    Conifer,
    /// A roast chicken: a plump body, drumsticks toward +x, wings at its sides.
    Roast,
    /// A hammer lying along x: a handle, the head across its +x end.
    Hammer,
    /// A screwdriver lying along x: a fat handle toward −x, the shaft toward +x.
    Screwdriver,
    /// A toothbrush lying along x: a handle, the bristles' head toward +x.
    Toothbrush,
    /// A closed umbrella lying along x: a hook toward −x, the furled canopy toward +x.
    Umbrella,
    /// A shoe, its toe toward +y: a sole and an upper rising to the heel.
    Shoe,
    /// A hat, brim down: a brim, a band, a crown.
    Hat,
    /// A glass jar: a round body, a shoulder and a short neck (its lid is a part of its own).
    Jar,
    /// A jar's screw lid: a flat metal cap with a knurled edge, a little narrower than its box.
    Lid,
    /// A baking dish with food in it: a pale dish with a lug at each end (±x), the food on top.
    Casserole,
    /// A car, its front toward +x: a body on four wheels, a glazed cabin, headlights.
    Car,
    /// A kettle barbecue: a round bowl and domed lid on three legs.
    Grill,
    /// An upright vacuum cleaner: a floor head, a body and a handle with a grip at the top.
    Vacuum,
    /// Headphones standing: a band arching over two ear cups, which face each other along x.
    Headphones,
    /// A pair of glasses, lenses toward −y and the temples back along +y.
    Glasses,
    /// A computer mouse, its front toward +y: a dome with a scroll wheel.
    Mouse,
    /// An office machine (printer, scanner, fax): a body, a lid, a paper tray at the back
    /// (+y), a slot and buttons at the front.
    Office,
    /// A calculator lying flat: a display toward +y above a grid of keys.
    Keypad,
    /// A backpack standing: a soft body, a front pocket toward −y, straps at the back (+y).
    Backpack,
    /// A duffel bag lying along x: a soft roll with two handles on top.
    Duffel,
    /// A hand saw lying along x: a handle with a grip's hole at −x, the blade narrowing
    /// toward +x.
    Saw,
    /// A scraper lying along x: a handle toward −x, a wide flat blade toward +x.
    Scraper,
    /// A scrubbing brush: a shaped wooden stock on a block of bristles.
    ScrubBrush,
    /// A dustpan: a scoop open toward −y, walled at its sides and back, a handle toward +y.
    Dustpan,
    /// A coat hanger lying flat: a wire triangle, its hook toward +y.
    Hanger,
    /// A squeezed tube lying along x (toothpaste): a cap toward −x, flattening to a crimped
    /// end.
    Tube,
    /// A framed picture lying flat: a moulded frame around a painted landscape.
    Painting,
    /// A wreath lying flat: a ring of leafy clusters with berries and a bow.
    Wreath,
    /// A teddy bear sitting, facing −y: body, head with ears and muzzle, arms and legs.
    Teddy,
    /// A bangle lying flat: a ring of rounded section.
    Bangle,
    /// A finger ring lying flat with a stone set on it.
    Ring,
    /// A necklace lying flat: beads on an oval loop with a pendant.
    Necklace,
    /// A whole fish lying on its side along x: head toward −x, a forked tail toward +x, fins.
    Fish,
    /// A bunch of herbs standing: stalks tied low, leafy sprigs above.
    Herbs,
    /// A tea bag lying flat: a paper pouch toward −y, a string to a tag toward +y.
    TeaBag,
    /// A hamburger: a bun in the object's colour around a dark patty and a leaf of lettuce.
    Burger,
    /// A sushi roll: dark seaweed around, pale rice on top with the filling at its centre.
    Maki,
    /// A kettle: a body narrowing to a lid, a spout toward +x, a handle arching over the lid.
    Kettle,
    /// A blender: a base, a jug widening upward with a dark lid, a handle at +x.
    Blender,
    /// A smoke alarm lying on its back: a pale disc, a vent ring, a domed middle, a red lamp.
    Detector,
    /// A gable-top carton (milk, juice): a box under two slopes meeting at a fin, a cap.
    Carton,
    /// A jug (detergent): a rounded body, a handle over the back of its top, a cap at the front.
    Jug,
    /// A bag of crisps standing: a puffed pillow crimped flat at its top and bottom.
    Pouch,
    /// A paper sack (flour, sugar): a soft-edged box, its top rolled down.
    Sack,
    /// A steak lying flat: a thick slab with a lumpy outline and a rim of fat toward −y.
    Steak,
    /// A wrapped sweet lying along x: a round middle, the wrapper twisted into fans.
    Sweet,
    /// A sandwich cut corner to corner: two slices of bread, lettuce and tomato between.
    Sandwich,
    /// A salad: a pale bowl heaped with leaves in the object's colour.
    Salad,
    /// A cookie: a flat round with a soft edge and dark chips on top.
    Cookie,
    /// A bow lying flat: two loops either side of a knot, two tails toward −y.
    Bow,
    /// A spool of ribbon: the ribbon between two pale flanges, a hole through the middle.
    Spool,
    /// A Christmas stocking: a leg, its foot toward +x, under a pale cuff.
    Stocking,
    /// A lipstick standing: a dark case, a metal ring, the stick with a rounded tip.
    Lipstick,
    /// A mousetrap: a wooden board, a bait plate, a wire bar lying open across it.
    Mousetrap,
    /// A briefcase lying flat: a case, a handle and two latches at its front (−y).
    Briefcase,
    /// A pencil case lying along x: a soft box with a zip along its top.
    PencilCase,
    /// A sofa's back, its front toward −y: a frame and a row of cushions leaning on it.
    Backrest,
    /// The BehaviorRobot's head: a rounded head with a dark visor across its face (+x).
    Head,
    /// A candle: a pillar with a softened top rim and a dark wick standing out of its middle.
    Candle,
}

impl Form {
    /// Every form, in order.
    pub const ALL: [Form; 105] = [
        Form::Primitive,
        Form::Rounded,
        Form::Soft,
        Form::Round,
        Form::Turned,
        Form::Apple,
        Form::Fruit,
        Form::Lemon,
        Form::Egg,
        Form::Florets,
        Form::Mushroom,
        Form::Berry,
        Form::Banana,
        Form::Carrot,
        Form::Loaf,
        Form::Bottle,
        Form::Can,
        Form::Cup,
        Form::Mug,
        Form::Bowl,
        Form::Plate,
        Form::Pot,
        Form::Bucket,
        Form::Cake,
        Form::Book,
        Form::Folded,
        Form::Pen,
        Form::Lamp,
        Form::Plant,
        Form::Torso,
        Form::Door,
        Form::GlassDoor,
        Form::DrawerFront,
        Form::DropDoor,
        Form::OvenDoor,
        Form::Porthole,
        Form::Controls,
        Form::Cooktop,
        Form::Tap,
        Form::Bedding,
        Form::Seat,
        Form::Knife,
        Form::Fork,
        Form::Spoon,
        Form::Broom,
        Form::Conifer,
        Form::Roast,
        Form::Hammer,
        Form::Screwdriver,
        Form::Toothbrush,
        Form::Umbrella,
        Form::Shoe,
        Form::Hat,
        Form::Jar,
        Form::Lid,
        Form::Casserole,
        Form::Car,
        Form::Grill,
        Form::Vacuum,
        Form::Headphones,
        Form::Glasses,
        Form::Mouse,
        Form::Office,
        Form::Keypad,
        Form::Backpack,
        Form::Duffel,
        Form::Saw,
        Form::Scraper,
        Form::ScrubBrush,
        Form::Dustpan,
        Form::Hanger,
        Form::Tube,
        Form::Painting,
        Form::Wreath,
        Form::Teddy,
        Form::Bangle,
        Form::Ring,
        Form::Necklace,
        Form::Fish,
        Form::Herbs,
        Form::TeaBag,
        Form::Burger,
        Form::Maki,
        Form::Kettle,
        Form::Blender,
        Form::Detector,
        Form::Carton,
        Form::Jug,
        Form::Pouch,
        Form::Sack,
        Form::Steak,
        Form::Sweet,
        Form::Sandwich,
        Form::Salad,
        Form::Cookie,
        Form::Bow,
        Form::Spool,
        Form::Stocking,
        Form::Lipstick,
        Form::Mousetrap,
        Form::Briefcase,
        Form::PencilCase,
        Form::Backrest,
        Form::Head,
        Form::Candle,
    ];
}

/// A shape drawn with an object but outside the physics: it touches nothing, no query finds
/// it, and its owner puts it where it belongs ([`crate::Bodies::set_ghost`]) — the BehaviorRobot's
/// head, round an eye that the world does not simulate. Kept out of rapier altogether, so that
/// it cannot change how anything else moves.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ghost {
    /// Its look, filling the box of half size `half_extents` about its pose.
    pub form: Form,
    /// m.
    pub half_extents: Vector,
    /// Its colour and material.
    pub visual: Visual,
    /// Its centre's pose in the world.
    pub pose: Pose,
}

/// A visual-only triangle mesh (an imported model's look), in the frame of its body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VisualMesh {
    /// The link it moves with, or `None` for the object's body.
    pub link: Option<usize>,
    /// Vertices in the object's frame (at the zero position of every joint).
    pub vertices: Vec<Vector>,
    /// Counter-clockwise triangles, as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// Its appearance.
    pub visual: Visual,
}

/// A model whose meshes are real (a robot maker's) and come from a package fetched at run time,
/// never from the world: a world names the piece, a renderer holds the meshes
/// ([`ModelLibrary`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Model {
    /// Fetch, from gymnasium-robotics' MuJoCo model.
    Fetch,
}

/// One rigid piece of a [`Model`] (a link), numbered by whoever builds the model (for Fetch,
/// the robots crate's link order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct ModelPiece {
    /// Which model.
    pub model: Model,
    /// Which of its pieces.
    pub piece: u8,
}

/// The meshes of model pieces a renderer holds, each piece's in the frame of the object (or
/// body) that names it. Plain data, built once per process and shared by every renderer.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelLibrary {
    pieces: BTreeMap<ModelPiece, Vec<HeldMesh>>,
}

/// A model piece's mesh with the numbers a renderer asks of it every frame, worked out once.
#[derive(Clone, Debug, PartialEq)]
pub struct HeldMesh {
    /// The mesh, in its piece's frame.
    pub mesh: VisualMesh,
    /// The corners of the box around its vertices.
    pub bounds: [Vector; 2],
    /// The farthest vertex from the frame's origin, m.
    pub reach: f32,
}

impl HeldMesh {
    fn new(mesh: VisualMesh) -> HeldMesh {
        let bounds = mesh.vertices.iter().fold(
            [Vector::splat(f32::MAX), Vector::splat(f32::MIN)],
            |[lo, hi], &p| [lo.min(p), hi.max(p)],
        );
        let reach = mesh.vertices.iter().map(|v| v.length()).fold(0.0, f32::max);
        HeldMesh {
            mesh,
            bounds,
            reach,
        }
    }
}

impl ModelLibrary {
    /// A library with no pieces: every model is drawn from its object's parts.
    pub const EMPTY: ModelLibrary = ModelLibrary {
        pieces: BTreeMap::new(),
    };

    /// Adds (or replaces) a piece's meshes.
    pub fn insert(&mut self, piece: ModelPiece, meshes: Vec<VisualMesh>) {
        self.pieces
            .insert(piece, meshes.into_iter().map(HeldMesh::new).collect());
    }

    /// A piece's meshes, if held.
    pub fn get(&self, piece: ModelPiece) -> Option<&[HeldMesh]> {
        self.pieces.get(&piece).map(Vec::as_slice)
    }

    /// Every piece held, in order.
    pub fn pieces(&self) -> impl Iterator<Item = (ModelPiece, &[HeldMesh])> {
        self.pieces.iter().map(|(&p, m)| (p, m.as_slice()))
    }

    /// Whether it holds no piece.
    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }
}

/// The shape of a drawn part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VisualShape<'a> {
    /// A collision primitive.
    Primitive(&'a Primitive),
    /// A visual-only mesh.
    Mesh(&'a VisualMesh),
    /// One mesh of a model piece held by a [`ModelLibrary`], in the part's frame.
    Piece {
        /// The piece.
        piece: ModelPiece,
        /// Which of the piece's meshes.
        index: u16,
        /// The mesh (vertices in the part's frame) and its bounds.
        held: &'a HeldMesh,
    },
    /// A detailed form filling a box of these half extents, centred on the part's pose.
    Formed {
        /// Which form.
        form: Form,
        /// Half the box's size along the part's axes, m.
        half_extents: Vector,
    },
}

/// One thing to draw: a shape at a world pose, with its appearance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VisualPart<'a> {
    /// The shape, in its own frame.
    pub shape: VisualShape<'a>,
    /// Where the shape's frame is in the world now.
    pub pose: Pose,
    /// The link it belongs to, or `None` for the object's body.
    pub link: Option<usize>,
    /// Its appearance.
    pub visual: Visual,
}

/// What the objects look like now: the parts a renderer draws. Reached through
/// [`crate::World::visuals`].
#[derive(Clone, Copy)]
pub struct Visuals<'w> {
    pub(crate) bodies: &'w Bodies,
}

impl<'w> Visuals<'w> {
    /// What to draw for an object, posed as it is now: its collision parts, each in its form (or,
    /// for a body or link that has visual meshes, those instead; for a body with a form of its
    /// own, that form filling the box around its parts), and its [`Ghost`], if it has one, last.
    /// Nothing for an object replaced by its halves. A model piece is drawn from the parts: see
    /// [`Visuals::parts_with`].
    pub fn parts(&self, id: ObjectId) -> Vec<VisualPart<'w>> {
        static NO_MODELS: ModelLibrary = ModelLibrary::EMPTY;
        self.parts_with(id, &NO_MODELS)
    }

    /// [`Visuals::parts`], but a body naming a model piece that `models` holds is drawn
    /// from the piece's meshes instead of its parts.
    pub fn parts_with<'a>(&self, id: ObjectId, models: &'a ModelLibrary) -> Vec<VisualPart<'a>>
    where
        'w: 'a,
    {
        let all: &'a Bodies = self.bodies;
        let object = all.object(id);
        if !object.is_present() {
            return Vec::new();
        }
        let body_pose = all.pose(id);
        // A link's parts and meshes are given in the object's frame at zero joint position; its
        // body started at the object's pose, so its current pose maps them.
        let frame = |link: Option<usize>| match link {
            None => body_pose,
            Some(l) => all.link_pose(id, l),
        };
        let mut out = Vec::new();
        let bodies = std::iter::once((None, &object.parts)).chain(
            object
                .links
                .iter()
                .enumerate()
                .map(|(i, l)| (Some(i), &l.parts)),
        );
        for (link, list) in bodies {
            let meshes: Vec<&VisualMesh> =
                object.meshes.iter().filter(|m| m.link == link).collect();
            let pose = frame(link);
            let piece = object
                .model
                .filter(|_| link.is_none())
                .and_then(|p| Some((p, models.get(p)?)));
            if let Some((piece, held)) = piece {
                out.extend(held.iter().enumerate().map(|(index, held)| VisualPart {
                    shape: VisualShape::Piece {
                        piece,
                        index: index as u16,
                        held,
                    },
                    pose,
                    link,
                    visual: held.mesh.visual,
                }));
            } else if link.is_none() && meshes.is_empty() && object.form != Form::Primitive {
                let b = all.local_aabb(id);
                out.push(VisualPart {
                    shape: VisualShape::Formed {
                        form: object.form,
                        half_extents: (b.maxs - b.mins) * 0.5,
                    },
                    pose: pose * Pose::from_translation(b.center()),
                    link,
                    visual: object.visual,
                });
            } else if meshes.is_empty() {
                out.extend(
                    list.iter()
                        .map(|part| drawn_part(part, pose, link, object.visual)),
                );
            } else {
                out.extend(meshes.into_iter().map(|mesh| VisualPart {
                    shape: VisualShape::Mesh(mesh),
                    pose,
                    link,
                    visual: mesh.visual,
                }));
            }
        }
        if let Some(ghost) = &object.ghost {
            out.push(VisualPart {
                shape: VisualShape::Formed {
                    form: ghost.form,
                    half_extents: ghost.half_extents,
                },
                pose: ghost.pose,
                link: None,
                visual: ghost.visual,
            });
        }
        out
    }
}

fn drawn_part(part: &Part, frame: Pose, link: Option<usize>, default: Visual) -> VisualPart<'_> {
    let shape = match part.form {
        Form::Primitive => VisualShape::Primitive(&part.primitive),
        form => {
            let (lo, hi) = part.primitive.local_box();
            return VisualPart {
                shape: VisualShape::Formed {
                    form,
                    half_extents: (hi - lo) * 0.5,
                },
                pose: frame * part.offset * Pose::from_translation((lo + hi) * 0.5),
                link,
                visual: part.visual.unwrap_or(default),
            };
        }
    };
    VisualPart {
        shape,
        pose: frame * part.offset,
        link,
        visual: part.visual.unwrap_or(default),
    }
}
