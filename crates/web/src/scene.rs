//! What the page is told about the world: what to draw once per episode, the poses every step.
//!
//! The world's visual description (`World::visual_parts`) is regrouped into *nodes*, one per
//! rigid body (an object's base or one of its links) and one per ghost (a shape drawn with an
//! object that the physics does not move: the BehaviorRobot's head): each node carries its
//! parts (a shape, its pose in the node's frame, a colour) and moves as one, so a step needs
//! only one pose per node. Convex hulls are sent as triangles (parry's hull), detailed forms as
//! their coarse meshes (rounded boards as plain boxes), everything else as its primitive.
//! Colours are linear sRGB in the home's palette, as the cameras' realistic profile gives them
//! for the object's states, with its roughness and metalness.

use crate::checklist::Checklist;
use behavior_core::Predicate;
use behavior_env::Env;
use behavior_forms::Tone;
use behavior_render::{DUST, Finishes, Look, STAIN, WATER, state_look, tone_look};
use behavior_sim::{Form, ModelLibrary, ObjectId, Primitive, Visual, VisualShape, World};
use rapier3d::math::{Pose, Vector};
use serde::Serialize;
use std::collections::BTreeMap;

/// A shape as the page builds it: in its own frame, z up.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum Shape {
    Box {
        half_extents: [f32; 3],
    },
    Cylinder {
        radius: f32,
        half_height: f32,
    },
    Sphere {
        radius: f32,
    },
    Capsule {
        radius: f32,
        half_height: f32,
    },
    Mesh {
        vertices: Vec<f32>,
        triangles: Vec<u32>,
    },
    /// A detailed form at its coarse level, smooth (the page averages each vertex's normal
    /// from its triangles; folds have vertices of their own and stay sharp), its details in
    /// colours of their own. Why coarse: a home's forms at both levels came to 10 MB of scene
    /// for the page, and the fine level to too many triangles for a browser drawing on a CPU,
    /// a headset's two eyes above all; the coarse level is a fifth of that.
    Form(FormMesh),
}

/// A detailed form's mesh for the page.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct FormMesh {
    /// x, y, z after one another, m, to a tenth of a millimetre.
    vertices: Vec<f32>,
    triangles: Vec<u32>,
    /// The form's parts in colours of their own (a stem, a cap): their triangles come after the
    /// body's, in this order.
    details: Vec<Detail>,
}

/// Triangles of a mesh in a colour of their own.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Detail {
    /// How many indices (three a triangle).
    pub(crate) count: u32,
    /// Linear sRGB, 0–1.
    pub(crate) color: [f32; 3],
    /// 0 (mirror) to 1 (chalk).
    pub(crate) roughness: f32,
    /// 0 or 1.
    pub(crate) metallic: f32,
}

/// One drawn part of a node.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct DrawnPart {
    pub(crate) shape: Shape,
    /// Position and quaternion (x, y, z, w) in the node's frame.
    pub(crate) offset: [f32; 7],
    /// Linear sRGB, 0–1, as the object's states show.
    pub(crate) color: [f32; 3],
    /// 0–1: how much it glows (toggled on).
    pub(crate) emission: f32,
    /// 0 (mirror) to 1 (chalk), as the realistic profile finishes it.
    pub(crate) roughness: f32,
    /// 0 or 1.
    pub(crate) metallic: f32,
}

/// A rigid body: an object's base or one of its links.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Node {
    /// The object's name in the world.
    pub(crate) object: String,
    /// Its category (synset or furniture kind).
    pub(crate) category: String,
    /// The link's index, or none for the base.
    pub(crate) link: Option<usize>,
    pub(crate) parts: Vec<DrawnPart>,
}

/// Everything the page needs to draw an episode, sent on joining and at each new episode.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct SceneDescription {
    pub(crate) activity: String,
    pub(crate) scene: String,
    pub(crate) seed: u64,
    /// Episodes started since the server did, this one included.
    pub(crate) episode: u32,
    /// Node names of the robot's parts, for the page's camera to follow.
    pub(crate) robot: Vec<String>,
    pub(crate) nodes: Vec<Node>,
    /// The goal's ground literals, as text.
    pub(crate) literals: Vec<String>,
    /// The action steps an episode may take.
    pub(crate) max_steps: u32,
    /// The colours of dust, stains and water drops (linear sRGB, 0–1), as the cameras draw them.
    pub(crate) particle_colors: ParticleColors,
}

/// What colour each kind of particle is drawn in.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct ParticleColors {
    dust: [f32; 3],
    stain: [f32; 3],
    water: [f32; 3],
}

impl Default for ParticleColors {
    fn default() -> Self {
        let linear = |c: [u8; 3]| c.map(|v| f32::from(v) / 255.0);
        ParticleColors {
            dust: linear(DUST),
            stain: linear(STAIN),
            water: linear(WATER),
        }
    }
}

/// Dust and stain particles on surfaces and water drops in flight, as world positions (x, y, z
/// after one another): the states the cameras draw as particles rather than as colours.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub(crate) struct Particles {
    dust: Vec<f32>,
    stain: Vec<f32>,
    water: Vec<f32>,
}

impl Particles {
    /// The world's particles now.
    pub(crate) fn of(world: &World) -> Particles {
        let mut particles = Particles::default();
        for (id, object) in world.core().objects() {
            if !object.is_present() {
                continue;
            }
            flatten(
                &mut particles.dust,
                &world.particle_positions(id, Predicate::Dusty),
            );
            flatten(
                &mut particles.stain,
                &world.particle_positions(id, Predicate::Stained),
            );
        }
        flatten(&mut particles.water, &world.drops());
        particles
    }
}

fn flatten(out: &mut Vec<f32>, points: &[Vector]) {
    out.extend(points.iter().flat_map(|p| [p.x, p.y, p.z]));
}

/// A part's new colour: `[node, part, r, g, b, emission]`.
pub(crate) type Recolor = [f32; 6];

/// What a node moves with: an object's base (`Link(None)`), one of its links, or its ghost (a
/// shape the physics does not move, placed by its owner: the BehaviorRobot's head round its
/// eye).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Carrier {
    Link(Option<usize>),
    Ghost,
}

/// The server's side of a scene: which body each node is and how each part looked last.
#[derive(Clone, Debug, Default)]
pub(crate) struct SceneView {
    bodies: Vec<(ObjectId, Carrier)>,
    /// The objects present when it was made.
    present: Vec<ObjectId>,
    /// Per node, per part: its appearance and the look last sent.
    looks: Vec<Vec<(Visual, [f32; 4])>>,
    /// Every part whose look has changed since the scene was made, with its look now (node,
    /// part → colour and glow): each status sends them all.
    changed: BTreeMap<(usize, usize), [f32; 4]>,
}

/// The world's current parts, grouped into nodes.
pub(crate) fn describe(world: &World, models: &ModelLibrary) -> (SceneView, Vec<Node>) {
    let core = world.core();
    let mut bodies = Vec::new();
    let mut looks = Vec::new();
    let mut nodes = Vec::new();
    let finishes = Finishes::of(world);
    for (id, object) in core.objects() {
        let parts = core.visual_parts_with(id, models);
        // The ghost is drawn last (if the object is drawn at all); it is a node of its own,
        // since it moves apart from the body.
        let ghosted = object.ghost.is_some() && !parts.is_empty();
        let (parts, ghost) = parts.split_at(parts.len() - usize::from(ghosted));
        let carriers = std::iter::once(None)
            .chain((0..object.links.len()).map(Some))
            .map(Carrier::Link)
            .chain(object.ghost.map(|_| Carrier::Ghost));
        for carrier in carriers {
            let frame = node_pose(world, id, carrier);
            let inverse = frame.inverse();
            let mine: Vec<_> = match carrier {
                Carrier::Link(link) => parts.iter().filter(|p| p.link == link).collect(),
                Carrier::Ghost => ghost.iter().collect(),
            };
            if mine.is_empty() {
                continue;
            }
            let mut drawn = Vec::with_capacity(mine.len());
            let mut node_looks = Vec::with_capacity(mine.len());
            for p in mine {
                // The colour in the home's palette, as the cameras' realistic profile has it.
                let finish = finishes.part(world, id, p.visual);
                let visual = Visual {
                    color: finish.color,
                    ..p.visual
                };
                let look = state_look(world, id, visual);
                node_looks.push((visual, look_key(&look)));
                drawn.push(DrawnPart {
                    shape: shape_of(&p.shape, &object.name),
                    offset: pose_values(inverse * p.pose),
                    color: look.albedo,
                    emission: look.emission,
                    roughness: finish.roughness,
                    metallic: finish.metallic,
                });
            }
            looks.push(node_looks);
            bodies.push((id, carrier));
            let (name, link) = match carrier {
                Carrier::Link(link) => (object.name.clone(), link),
                Carrier::Ghost => (format!("{}/ghost", object.name), None),
            };
            nodes.push(Node {
                object: name,
                category: object.category.clone(),
                link,
                parts: drawn,
            });
        }
    }
    let present = present(world);
    (
        SceneView {
            bodies,
            present,
            looks,
            changed: BTreeMap::new(),
        },
        nodes,
    )
}

fn present(world: &World) -> Vec<ObjectId> {
    let core = world.core();
    core.objects()
        .filter(|(_, o)| o.is_present())
        .map(|(id, _)| id)
        .collect()
}

fn node_pose(world: &World, id: ObjectId, carrier: Carrier) -> Pose {
    let core = world.core();
    match carrier {
        Carrier::Link(None) => core.pose(id),
        Carrier::Link(Some(l)) => core.link_pose(id, l),
        Carrier::Ghost => core.object(id).ghost.map_or(core.pose(id), |g| g.pose),
    }
}

/// What a part's recolouring compares: its colour and glow.
fn look_key(look: &Look) -> [f32; 4] {
    [
        look.albedo[0],
        look.albedo[1],
        look.albedo[2],
        look.emission,
    ]
}

fn shape_of(shape: &VisualShape, name: &str) -> Shape {
    match shape {
        // A board's rounded edges are a few millimetres: the page draws the plain board.
        &VisualShape::Formed {
            form: Form::Rounded,
            half_extents: h,
        } => Shape::Box {
            half_extents: [h.x, h.y, h.z],
        },
        &VisualShape::Formed { form, half_extents } => {
            let seed = u64::from(behavior_forms::seed_of(name));
            let coarse = behavior_forms::Detail::Coarse;
            Shape::Form(formed(&behavior_forms::mesh(
                form,
                half_extents,
                seed,
                coarse,
            )))
        }
        VisualShape::Primitive(p) => match p {
            Primitive::Box { half_extents: h } => Shape::Box {
                half_extents: [h.x, h.y, h.z],
            },
            &&Primitive::Cylinder {
                radius,
                half_height,
            } => Shape::Cylinder {
                radius,
                half_height,
            },
            &&Primitive::Sphere { radius } => Shape::Sphere { radius },
            &&Primitive::Capsule {
                radius,
                half_height,
            } => Shape::Capsule {
                radius,
                half_height,
            },
            Primitive::ConvexHull { points } => {
                let (vertices, triangles) =
                    rapier3d::parry::transformation::convex_hull(points.as_slice());
                mesh(&vertices, &triangles)
            }
        },
        VisualShape::Mesh(m) => mesh(&m.vertices, &m.triangles),
        // A robot's link in its maker's mesh, simplified and creased as the cameras draw it
        // mid-size: smooth where the page averages its normals, sharp at its edges.
        VisualShape::Piece { held, .. } => {
            let (positions, triangles) = behavior_render::viewer_piece(held);
            Shape::Form(FormMesh {
                vertices: tenths_of_millimetres(positions.into_iter().flatten().collect()),
                triangles,
                details: Vec::new(),
            })
        }
    }
}

fn mesh(vertices: &[Vector], triangles: &[[u32; 3]]) -> Shape {
    Shape::Mesh {
        vertices: tenths_of_millimetres(flat(vertices)),
        triangles: triangles.iter().flatten().copied().collect(),
    }
}

/// Coordinates rounded to 0.1 mm: nobody sees less at the viewer, and the scene's text is
/// shorter by half.
fn tenths_of_millimetres(values: Vec<f32>) -> Vec<f32> {
    values
        .into_iter()
        .map(|c| (c * 1e4).round() / 1e4)
        .collect()
}

fn flat(points: &[Vector]) -> Vec<f32> {
    points.iter().flat_map(|v| [v.x, v.y, v.z]).collect()
}

/// A detailed form's mesh, its triangles grouped by tone (the body's first), each other tone a
/// detail in its colour, as the cameras draw it.
fn formed(made: &behavior_forms::Mesh) -> FormMesh {
    let mut by_tone: std::collections::BTreeMap<Tone, Vec<u32>> = Default::default();
    for t in &made.triangles {
        let tone = made.tones[t[0] as usize];
        by_tone.entry(tone).or_default().extend_from_slice(t);
    }
    let mut triangles = by_tone.remove(&Tone::Body).unwrap_or_default();
    let mut details = Vec::new();
    for (tone, indices) in by_tone {
        if let Some(look) = tone_look(tone) {
            details.push(Detail {
                count: indices.len() as u32,
                color: look.albedo,
                roughness: look.roughness,
                metallic: look.metallic,
            });
        }
        triangles.extend(indices);
    }
    FormMesh {
        vertices: tenths_of_millimetres(flat(&made.positions)),
        triangles,
        details,
    }
}

fn pose_values(p: Pose) -> [f32; 7] {
    let (t, r) = (p.translation, p.rotation);
    [t.x, t.y, t.z, r.x, r.y, r.z, r.w]
}

impl SceneView {
    /// Whether the world still has the objects this view was made for (slicing replaces an
    /// object by new ones; then the page needs a new scene).
    pub(crate) fn matches(&self, world: &World) -> bool {
        present(world) == self.present
    }

    /// One binary frame: the step, then every node's pose (NaN position once it has gone).
    pub(crate) fn frame(&self, world: &World, step: u32) -> Vec<u8> {
        let mut out = Vec::with_capacity(4 + self.bodies.len() * 28);
        out.extend_from_slice(&step.to_le_bytes());
        for &(id, carrier) in &self.bodies {
            let mut values = pose_values(node_pose(world, id, carrier));
            if !world.core().object(id).is_present() {
                values[..3].fill(f32::NAN);
            }
            for v in values {
                out.extend_from_slice(&v.to_le_bytes());
            }
        }
        out
    }

    /// Every part whose colour has changed since the scene was made (states: cooked, soaked,
    /// on…), with its colour now: whole, so that a page that skipped a status is right again.
    pub(crate) fn recolor(&mut self, world: &World) -> Vec<Recolor> {
        for (node, (&(id, _), parts)) in self.bodies.iter().zip(&mut self.looks).enumerate() {
            for (part, (visual, last)) in parts.iter_mut().enumerate() {
                let key = look_key(&state_look(world, id, *visual));
                if key != *last {
                    *last = key;
                    self.changed.insert((node, part), key);
                }
            }
        }
        self.changed
            .iter()
            .map(|(&(node, part), k)| [node as f32, part as f32, k[0], k[1], k[2], k[3]])
            .collect()
    }
}

/// The scene's description for an episode.
pub(crate) struct Describe<'a> {
    pub(crate) world: &'a World,
    pub(crate) robot: Vec<ObjectId>,
    pub(crate) checklist: &'a Checklist,
    pub(crate) activity: String,
    pub(crate) scene: String,
    pub(crate) seed: u64,
    pub(crate) episode: u32,
    pub(crate) max_steps: u32,
}

impl<'a> Describe<'a> {
    /// What describes `env`'s episode as it is now: `seed` and `episode` as the page shows them
    /// (none outside an episode).
    pub(crate) fn episode(
        env: &'a Env,
        checklist: &'a Checklist,
        seed: u64,
        episode: u32,
    ) -> Option<Describe<'a>> {
        let (world, robot, start) = (env.world()?, env.robot()?, env.start()?);
        Some(Describe {
            world,
            robot: robot.objects(),
            checklist,
            activity: env.config().activity.name.clone(),
            scene: start.instance.scene.name.clone(),
            seed,
            episode,
            max_steps: env.config().max_steps,
        })
    }

    pub(crate) fn build(self) -> (SceneView, SceneDescription) {
        // Robots in their makers' meshes where this process has them.
        let (view, nodes) = describe(self.world, &behavior_robots::shared_models());
        let core = self.world.core();
        let robot = self
            .robot
            .iter()
            .map(|&id| core.object(id).name.clone())
            .collect();
        let description = SceneDescription {
            activity: self.activity,
            scene: self.scene,
            seed: self.seed,
            episode: self.episode,
            robot,
            nodes,
            literals: self.checklist.texts().to_vec(),
            max_steps: self.max_steps,
            particle_colors: ParticleColors::default(),
        };
        (view, description)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_forms::Detail as Level;

    #[test]
    fn a_form_reaches_the_page_with_its_stem_after_its_body() {
        let made = behavior_forms::mesh(Form::Apple, Vector::splat(0.04), 1, Level::Fine);
        let FormMesh {
            vertices,
            triangles,
            details,
        } = formed(&made);
        assert_eq!(vertices.len(), 3 * made.positions.len());
        assert_eq!(triangles.len(), 3 * made.triangles.len());
        assert_eq!(details.len(), 1, "an apple has one detail, its stem");
        let [r, _, b] = details[0].color;
        assert!(r > b, "the stem is not brown: {:?}", details[0].color);
        let body = triangles.len() - details[0].count as usize;
        let tone = |t: &[u32]| made.tones[t[0] as usize];
        assert!(triangles[..body].chunks(3).all(|t| tone(t) == Tone::Body));
        assert!(triangles[body..].chunks(3).all(|t| tone(t) == Tone::Stem));
    }

    #[test]
    fn fetch_reaches_the_page_in_its_makers_meshes_simplified_and_creased() {
        let mut world = World::default();
        behavior_robots::Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        let models = behavior_robots::shared_models();
        assert!(
            !models.is_empty(),
            "Fetch's meshes could not be had (gymnasium-robotics from PyPI)"
        );
        let triangles = |nodes: &[Node]| -> (usize, usize) {
            let shapes = nodes.iter().flat_map(|n| &n.parts).map(|p| &p.shape);
            let forms: Vec<&FormMesh> = shapes
                .filter_map(|s| match s {
                    Shape::Form(f) => Some(f),
                    _ => None,
                })
                .collect();
            (
                forms.len(),
                forms.iter().map(|f| f.triangles.len() / 3).sum(),
            )
        };
        let (_, with) = describe(&world, &models);
        let (_, without) = describe(&world, &ModelLibrary::EMPTY);
        let (pieces, sent) = triangles(&with);
        // Every link's meshes (the base's four, the gripper's two), on a 4 mm grid.
        assert_eq!(pieces, 15, "{pieces} meshes");
        assert!((8_000..20_000).contains(&sent), "{sent} triangles");
        assert_eq!(
            triangles(&without),
            (0, 0),
            "without meshes, its primitives"
        );
        // The gripper's fingers stay our pads, with or without.
        let fingers = |nodes: &[Node]| nodes.iter().filter(|n| n.link.is_some()).count();
        assert_eq!(fingers(&with), 2);
        assert_eq!(fingers(&with), fingers(&without));
    }

    #[test]
    fn the_behavior_robots_head_is_a_node_of_its_own_that_follows_the_eye() {
        let mut world = World::default();
        let at = Pose::from_translation(Vector::new(0.0, 0.0, behavior_robots::BODY_HEIGHT));
        let mut robot = behavior_robots::BehaviorRobot::add(&mut world, at).unwrap();
        let (view, nodes) = describe(&world, &ModelLibrary::EMPTY);
        let head = nodes
            .iter()
            .position(|n| n.object == "robot_body/ghost")
            .expect("a node for the head");
        assert_eq!(nodes[head].parts.len(), 1, "the head alone");
        let body = nodes.iter().position(|n| n.object == "robot_body").unwrap();
        assert!(
            body < head,
            "the body's node comes first, for the page's camera"
        );
        // A frame: the step, then seven numbers per node.
        let pose_in = |frame: &[u8], node: usize| -> Vector {
            let at = |k: usize| {
                let start = 4 + 28 * node + 4 * k;
                f32::from_le_bytes(frame[start..start + 4].try_into().unwrap())
            };
            Vector::new(at(0), at(1), at(2))
        };
        let before = pose_in(&view.frame(&world, 0), head);
        let mut values = [0.0; behavior_robots::ACTION_DIM];
        values[behavior_robots::Action::EYE.start] = 1.0;
        for _ in 0..4 {
            robot.step(&mut world, &values).unwrap();
        }
        let after = pose_in(&view.frame(&world, 4), head);
        assert!(
            (after - before).length() > 0.1,
            "the head's node moved from {before} to {after} as the eye went forward"
        );
        assert_eq!(
            pose_in(&view.frame(&world, 4), body),
            pose_in(&view.frame(&world, 0), body),
            "while the body stood still"
        );
    }
}
