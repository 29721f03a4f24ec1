//! What the page is told about the world: what to draw once per scene, the poses every step.
//!
//! The world's visual description (`World::visual_parts`) is regrouped into *nodes*, one per
//! rigid body (an object's base or one of its links) and one per ghost (a shape drawn with an
//! object that the physics does not move: the BehaviorRobot's head). Each node moves as one, so
//! a step needs only one pose per node. What the nodes hold is sent once per scene as a binary
//! glTF file (`behavior_render::GltfWriter` at its viewer's detail: the cameras' meshes, forms
//! at their coarse level, and the realistic profile's materials with their patterns baked into
//! images), a top node per node in the description's order, a child per part; the page fetches
//! it from the address the description names ([`SceneFiles`]). A part's colour changes with the
//! object's states (cooked, soaked, on), sent as [`Recolor`]s.

use crate::checklist::Checklist;
use axum::body::Bytes;
use behavior_core::Predicate;
use behavior_env::Env;
use behavior_render::{DUST, Finishes, GltfDetail, GltfWriter, Look, STAIN, WATER, state_look};
use behavior_sim::{ModelLibrary, ObjectId, Visual, VisualPart, World};
use rapier3d::math::{Pose, Vector};
use serde::Serialize;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// A rigid body: an object's base or one of its links.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Node {
    /// The object's name in the world.
    pub(crate) object: String,
    /// Its category (synset or furniture kind).
    pub(crate) category: String,
    /// The link's index, or none for the base.
    pub(crate) link: Option<usize>,
    /// How many parts its glTF node holds (a child each).
    pub(crate) parts: usize,
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
    /// Where the page fetches the nodes' glTF file.
    pub(crate) gltf: String,
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
        for (id, object) in world.bodies().objects() {
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

/// The world's current parts, grouped into nodes, and the nodes' glTF file.
pub(crate) fn describe(world: &World, models: &ModelLibrary) -> (SceneView, Vec<Node>, Vec<u8>) {
    let mut bodies = Vec::new();
    let mut looks = Vec::new();
    let mut nodes = Vec::new();
    let mut file = GltfWriter::new(world, GltfDetail::Viewer);
    let finishes = Finishes::of(world);
    for (id, object) in world.bodies().objects() {
        let parts = world.visuals().parts_with(id, models);
        // The ghost is drawn last (if the object is drawn at all); it is a node of its own,
        // since it moves apart from the body.
        let ghosted = object.ghost.is_some() && !parts.is_empty();
        let (parts, ghost) = parts.split_at(parts.len() - usize::from(ghosted));
        let carriers = std::iter::once(None)
            .chain((0..object.links.len()).map(Some))
            .map(Carrier::Link)
            .chain(object.ghost.map(|_| Carrier::Ghost));
        for carrier in carriers {
            let mine: Vec<VisualPart> = match carrier {
                Carrier::Link(link) => parts.iter().filter(|p| p.link == link).copied().collect(),
                Carrier::Ghost => ghost.to_vec(),
            };
            if mine.is_empty() {
                continue;
            }
            // Each part's colour in the home's palette, as the cameras' realistic profile has
            // it, and its look in the object's states now (what recolouring compares with).
            let node_looks = mine
                .iter()
                .map(|p| {
                    let visual = Visual {
                        color: finishes.part(world, id, p.visual).color,
                        ..p.visual
                    };
                    (visual, look_key(&state_look(world, id, visual)))
                })
                .collect();
            looks.push(node_looks);
            bodies.push((id, carrier));
            let (name, link) = match carrier {
                Carrier::Link(link) => (object.name.clone(), link),
                Carrier::Ghost => (format!("{}/ghost", object.name), None),
            };
            file.node(&name, id, node_pose(world, id, carrier), &mine);
            nodes.push(Node {
                object: name,
                category: object.category.clone(),
                link,
                parts: mine.len(),
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
        file.finish(),
    )
}

fn present(world: &World) -> Vec<ObjectId> {
    world
        .bodies()
        .objects()
        .filter(|(_, o)| o.is_present())
        .map(|(id, _)| id)
        .collect()
}

fn node_pose(world: &World, id: ObjectId, carrier: Carrier) -> Pose {
    match carrier {
        Carrier::Link(None) => world.bodies().pose(id),
        Carrier::Link(Some(l)) => world.bodies().link_pose(id, l),
        Carrier::Ghost => world
            .bodies()
            .object(id)
            .ghost
            .map_or(world.bodies().pose(id), |g| g.pose),
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
            if !world.bodies().object(id).is_present() {
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

    /// The scene's view and description, its glTF file published in `files` with `kept - 1`
    /// before it.
    pub(crate) fn build(self, files: &SceneFiles, kept: usize) -> (SceneView, SceneDescription) {
        // Robots in their makers' meshes where this process has them.
        let (view, nodes, file) = describe(self.world, &behavior_robots::shared_models());
        let bodies = self.world.bodies();
        let robot = self
            .robot
            .iter()
            .map(|&id| bodies.object(id).name.clone())
            .collect();
        let description = SceneDescription {
            activity: self.activity,
            scene: self.scene,
            seed: self.seed,
            episode: self.episode,
            robot,
            nodes,
            gltf: files.publish(file, kept),
            literals: self.checklist.texts().to_vec(),
            max_steps: self.max_steps,
            particle_colors: ParticleColors::default(),
        };
        (view, description)
    }
}

/// The scenes' glTF files the page may fetch, each at an address of its own
/// (`/scene/<n>.glb`, numbered as published). A live session keeps the last few (a page may
/// still be loading the one before); a recording's playback keeps every scene it made (a few:
/// one more per slicing), so that the page scrubbed back finds the earlier ones.
#[derive(Debug, Default)]
pub(crate) struct SceneFiles(Mutex<FilesInner>);

#[derive(Debug, Default)]
struct FilesInner {
    published: u64,
    files: BTreeMap<u64, Bytes>,
}

impl SceneFiles {
    /// Keeps `file` with the `kept - 1` published before it; returns its address.
    pub(crate) fn publish(&self, file: Vec<u8>, kept: usize) -> String {
        // A poisoned lock held only a map: its data is still whole.
        let mut inner = self.0.lock().unwrap_or_else(|e| e.into_inner());
        inner.published += 1;
        let n = inner.published;
        inner.files.insert(n, Bytes::from(file));
        while inner.files.len() > kept.max(1) {
            inner.files.pop_first();
        }
        format!("/scene/{n}.glb")
    }

    /// The file at `path`, if it is one of those kept.
    pub(crate) fn get(&self, path: &str) -> Option<Bytes> {
        let n: u64 = path
            .strip_prefix("/scene/")?
            .strip_suffix(".glb")?
            .parse()
            .ok()?;
        let inner = self.0.lock().unwrap_or_else(|e| e.into_inner());
        inner.files.get(&n).cloned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    /// The JSON of a binary glTF file.
    fn json_of(glb: &[u8]) -> Value {
        assert_eq!(&glb[..4], b"glTF");
        let length = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
        serde_json::from_slice(&glb[20..20 + length]).unwrap()
    }

    /// Triangles in every primitive of a glTF file.
    fn triangles(doc: &Value) -> u64 {
        let accessors = doc["accessors"].as_array().unwrap();
        doc["meshes"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|m| m["primitives"].as_array().unwrap())
            .map(|p| {
                accessors[p["indices"].as_u64().unwrap() as usize]["count"]
                    .as_u64()
                    .unwrap()
                    / 3
            })
            .sum()
    }

    #[test]
    fn the_scenes_file_holds_a_node_per_body_in_the_descriptions_order() {
        let mut world = World::default();
        behavior_robots::Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        let (_, nodes, glb) = describe(&world, &ModelLibrary::EMPTY);
        let doc = json_of(&glb);
        let all = doc["nodes"].as_array().unwrap();
        let root = all.last().unwrap();
        let top = root["children"].as_array().unwrap();
        assert_eq!(top.len(), nodes.len(), "a top node per node");
        for (node, at) in nodes.iter().zip(top) {
            let gltf = &all[at.as_u64().unwrap() as usize];
            assert_eq!(gltf["name"], node.object);
            assert_eq!(
                gltf["children"].as_array().unwrap().len(),
                node.parts,
                "{}",
                node.object
            );
        }
        assert!(
            nodes.iter().any(|n| n.link.is_some()),
            "the gripper's fingers are nodes"
        );
    }

    #[test]
    fn fetch_reaches_the_page_in_its_makers_meshes_simplified() {
        let mut world = World::default();
        behavior_robots::Fetch::add(&mut world, Pose::IDENTITY).unwrap();
        let models = behavior_robots::shared_models();
        assert!(
            !models.is_empty(),
            "Fetch's meshes could not be had (gymnasium-robotics from PyPI)"
        );
        let (_, with, file) = describe(&world, &models);
        let (_, without, bare) = describe(&world, &ModelLibrary::EMPTY);
        // Its links' meshes on a 4 mm grid: thousands of triangles (31,700 as made).
        let added = triangles(&json_of(&file)) - triangles(&json_of(&bare));
        assert!((8_000..20_000).contains(&added), "{added} triangles more");
        // The gripper's fingers stay our pads, with or without.
        let fingers = |nodes: &[Node]| nodes.iter().filter(|n| n.link.is_some()).count();
        assert_eq!(fingers(&with), 2);
        assert_eq!(fingers(&with), fingers(&without));
    }

    #[test]
    fn scene_files_are_found_at_their_address_while_kept() {
        let files = SceneFiles::default();
        let first = files.publish(vec![1], 2);
        let second = files.publish(vec![2], 2);
        assert_eq!(files.get(&first).as_deref(), Some(&[1u8][..]));
        let third = files.publish(vec![3], 2);
        assert!(files.get(&first).is_none(), "only two are kept");
        assert_eq!(files.get(&second).as_deref(), Some(&[2u8][..]));
        assert_eq!(files.get(&third).as_deref(), Some(&[3u8][..]));
        for wrong in ["/scene/x.glb", "/scene/3", "/other/3.glb", "/scene/99.glb"] {
            assert!(files.get(wrong).is_none(), "{wrong}");
        }
    }

    #[test]
    fn the_behavior_robots_head_is_a_node_of_its_own_that_follows_the_eye() {
        let mut world = World::default();
        let at = Pose::from_translation(Vector::new(0.0, 0.0, behavior_robots::BODY_HEIGHT));
        let mut robot = behavior_robots::BehaviorRobot::add(&mut world, at).unwrap();
        let (view, nodes, _) = describe(&world, &ModelLibrary::EMPTY);
        let head = nodes
            .iter()
            .position(|n| n.object == "robot_body/ghost")
            .expect("a node for the head");
        assert_eq!(nodes[head].parts, 1, "the head alone");
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
