//! How objects look: every object's parts with their shape, pose, link, colour and material, so
//! that a renderer that depends only on the world can draw it.
//!
//! Appearance is data the world carries and never reads: the physics ignores it, except that a
//! [`Material`] also names a typical friction for callers that build specs from it.

use crate::core::Core;
use crate::object::{ObjectId, Part, Primitive};
use rapier3d::math::{Pose, Vector};
use serde::{Deserialize, Serialize};

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

/// The shape of a drawn part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VisualShape<'a> {
    /// A collision primitive.
    Primitive(&'a Primitive),
    /// A visual-only mesh.
    Mesh(&'a VisualMesh),
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

impl Core {
    /// What to draw for an object, posed as it is now: its collision parts (or, for a body or
    /// link that has visual meshes, those instead). Nothing for an object replaced by its halves.
    pub fn visual_parts(&self, id: ObjectId) -> Vec<VisualPart<'_>> {
        let object = self.object(id);
        if !object.is_present() {
            return Vec::new();
        }
        let body_pose = self.pose(id);
        // A link's parts and meshes are given in the object's frame at zero joint position; its
        // body started at the object's pose, so its current pose maps them.
        let frame = |link: Option<usize>| match link {
            None => body_pose,
            Some(l) => self.link_pose(id, l),
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
            if meshes.is_empty() {
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
        out
    }
}

fn drawn_part(part: &Part, frame: Pose, link: Option<usize>, default: Visual) -> VisualPart<'_> {
    VisualPart {
        shape: VisualShape::Primitive(&part.primitive),
        pose: frame * part.offset,
        link,
        visual: part.visual.unwrap_or(default),
    }
}
