//! What one frame draws: an instance per visible part (and per dust or stain particle and water
//! drop), with its mesh, transform, last frame's transform, look and ids, in drawing order.

use crate::appearance::{DUST, Look, STAIN, Shown, WATER, look};
use crate::camera::Camera;
use crate::categories::{CategoryTable, DUST_CATEGORY, STAIN_CATEGORY, WATER_CATEGORY};
use crate::finish::{Finish, Finisher, Pattern, object_seed};
use crate::mesh::{Drawn, MeshStore, contains};
use crate::occlusion::Occlusion;
use crate::profile::ImageProfile;
use behavior_core::Predicate;
use behavior_sim::{Material, ModelLibrary, ObjectId, Primitive, VisualPart, VisualShape, World};
use rapier3d::glamx::{Mat3, Mat4, Vec4};
use rapier3d::math::{Pose, Vector};

/// Objects with a model piece smaller than this radius on the image, pixels, are drawn from
/// their own parts: a robot's link a few pixels across shows no more in its maker's mesh than
/// in our primitives, which cost a hundredth of its triangles.
const PIECE_ABOVE_PIXELS: f32 = 20.0;

/// What is drawn and how it is labelled.
pub struct Scene<'a> {
    /// The world.
    pub world: &'a World,
    /// Semantic ids.
    pub categories: &'a CategoryTable,
    /// The objects the highlight mask shows (an activity's objects).
    pub highlight: &'a [ObjectId],
    /// Objects not drawn (none, usually: a camera inside a part does not draw that part anyway).
    pub hidden: &'a [ObjectId],
}

/// One drawn shape: a mesh of the store placed in the world (see `frame_geometry.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Instance {
    pub(crate) mesh: u32,
    /// Rows of the affine transform from the mesh's frame to the world.
    pub(crate) model: [[f32; 4]; 3],
    /// Rows of the normal matrix.
    pub(crate) normal: [[f32; 3]; 3],
    /// Rows of last frame's transform (the same where there was none).
    pub(crate) previous: [[f32; 4]; 3],
    /// Linear albedo, and emission in w.
    pub(crate) color: [f32; 4],
    /// Shininess of the specular highlight.
    pub(crate) shine: f32,
    /// Instance id, and category id | highlight << 16.
    pub(crate) ids: [u32; 2],
    /// The mesh's stretch (its vertices times this are in metres in the part's frame).
    pub(crate) scale: [f32; 3],
    /// The part's half size, m.
    pub(crate) extent: [f32; 3],
    /// Its finish for the realistic profile ([`Finish::packed`]).
    pub(crate) surface: [u32; 2],
}

/// Which drawn thing an instance is, to find its transform in the previous frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Key {
    /// An object's part by its index in the object's visual parts.
    Part(u32, u32),
    /// One of a model piece's meshes by its index (apart from the parts, so that an object
    /// drawn from its parts one frame and its piece the next takes no part's motion for a
    /// mesh's).
    Piece(u32, u32),
    Particle(u32, u8, u32),
    Drop(u32),
}

/// Every part's transform in one frame, sorted by key.
pub(crate) type Models = Vec<(Key, [[f32; 4]; 3])>;

/// The transforms of one frame, for the next frame's flow.
#[derive(Clone, Debug, Default)]
pub(crate) struct History {
    pub(crate) view_projection: Mat4,
    pub(crate) models: Models,
}

impl History {
    fn model(&self, key: Key) -> Option<[[f32; 4]; 3]> {
        let k = self.models.binary_search_by_key(&key, |(k, _)| *k).ok()?;
        Some(self.models[k].1)
    }
}

/// One frame's instances in drawing order.
#[derive(Default)]
pub(crate) struct Batch {
    pub(crate) instances: Vec<Instance>,
    /// Every part's transform, drawn or not, for the next frame's flow.
    pub(crate) models: Models,
    /// Instances left out as hidden behind others.
    pub(crate) culled: usize,
}

/// Rows of the affine transform `pose · scale`.
pub(crate) fn rows(pose: &Pose, scale: Vector) -> [[f32; 4]; 3] {
    let m = Mat3::from_quat(pose.rotation) * Mat3::from_diagonal(scale);
    let t = pose.translation;
    let r = m.transpose();
    [
        r.x_axis.extend(t.x),
        r.y_axis.extend(t.y),
        r.z_axis.extend(t.z),
    ]
    .map(|v| v.to_array())
}

/// Rows of the normal matrix of `pose · scale` (its inverse transpose: rotation · 1/scale).
fn normal_rows(pose: &Pose, scale: Vector) -> [[f32; 3]; 3] {
    let inverse = Vector::ONE / scale.max(Vector::splat(1e-6));
    let r = (Mat3::from_quat(pose.rotation) * Mat3::from_diagonal(inverse)).transpose();
    [r.x_axis, r.y_axis, r.z_axis].map(|v| v.to_array())
}

/// The six planes of a camera's view, as (normal, offset) with the inside positive.
fn frustum(view_projection: &Mat4) -> [Vec4; 6] {
    let m = view_projection.transpose();
    let (r0, r1, r2, r3) = (m.x_axis, m.y_axis, m.z_axis, m.w_axis);
    [r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2]
}

fn visible(planes: &[Vec4; 6], centre: Vector, radius: f32) -> bool {
    planes
        .iter()
        .all(|p| p.truncate().dot(centre) + p.w >= -radius * p.truncate().length())
}

/// Gathers a frame's instances.
pub(crate) struct Gatherer<'a> {
    pub(crate) scene: &'a Scene<'a>,
    pub(crate) camera: &'a Camera,
    pub(crate) meshes: &'a mut MeshStore,
    pub(crate) previous: Option<&'a History>,
    /// Whether to leave out what big boxes hide (see `occlusion.rs`).
    pub(crate) cull: bool,
    /// How colour is drawn: the realistic profile finishes each part (`finish.rs`).
    pub(crate) profile: ImageProfile,
    /// The home's seed, for its palette.
    pub(crate) home: u64,
    /// Real meshes of model pieces (robots' links), drawn instead of their objects' parts.
    pub(crate) models: &'a ModelLibrary,
}

/// One instance before it is put in drawing order.
struct Pending {
    /// A ball that holds it: centre and radius, m.
    centre: Vector,
    reach: f32,
    /// How near to the camera it may come, m: instances are drawn nearest first, so that the
    /// depth test spares the shading of what they hide.
    near: f32,
    /// A big box (a wall, a floor): drawn after everything else, which mostly stands in front
    /// of it, so that its hidden pixels are not shaded.
    backdrop: bool,
    instance: Instance,
}

/// What one gathering pass collects.
#[derive(Default)]
struct Gathered {
    pending: Vec<Pending>,
    /// Big opaque boxes that are drawn: pose and half extents.
    occluders: Vec<(Pose, Vector)>,
    models: Models,
}

impl<'a> Gatherer<'a> {
    pub(crate) fn gather(mut self) -> Batch {
        let planes = frustum(&self.camera.view_projection());
        // Room for a frame like the last one, so that the lists do not grow part by part.
        let parts = self.previous.map_or(0, |h| h.models.len());
        let mut out = Gathered {
            pending: Vec::with_capacity(parts),
            occluders: Vec::with_capacity(parts / 4),
            models: Vec::with_capacity(parts),
        };
        for (id, object) in self.scene.world.bodies().objects() {
            if !object.is_present() || self.scene.hidden.contains(&id) {
                continue;
            }
            self.object(id, &planes, &mut out);
        }
        self.particles(&planes, &mut out);
        self.drops(&planes, &mut out);
        let before = out.pending.len();
        if self.cull {
            self.cull_hidden(&mut out);
        }
        let culled = before - out.pending.len();
        Batch {
            culled,
            ..in_drawing_order(out.pending, out.models)
        }
    }

    /// Leaves out what the gathered occluders hide (see `occlusion.rs`).
    fn cull_hidden(&self, out: &mut Gathered) {
        let mut occlusion = Occlusion::new(self.camera);
        // Nearest first, so that a wall behind another costs only the test that skips it.
        let eye = self.camera.pose.translation;
        out.occluders
            .sort_by(|a, b| distance(a, eye).total_cmp(&distance(b, eye)));
        for (pose, half_extents) in &out.occluders {
            if !occlusion.hides(pose.translation, half_extents.length()) {
                occlusion.add_box(pose, *half_extents);
            }
        }
        out.pending.retain(|p| !occlusion.hides(p.centre, p.reach));
    }

    /// About how many pixels a ball at `centre` of `radius` spans in radius on the image.
    fn pixels(&self, centre: Vector, radius: f32) -> f32 {
        let camera = self.camera;
        let distance = (centre - camera.pose.translation).length().max(radius);
        let focal = camera.height as f32 / (2.0 * (0.5 * camera.vertical_fov).tan());
        radius / distance * focal
    }

    fn ids(&self, id: ObjectId, category: &str) -> [u32; 2] {
        let highlighted = u32::from(self.scene.highlight.contains(&id));
        let category = u32::from(self.scene.categories.id(category));
        [id.0 + 1, category | (highlighted << 16)]
    }

    fn instance(&self, mesh: u32, key: Key, placed: (&Pose, &Drawn), shade: Shade) -> Instance {
        let (pose, drawn) = placed;
        let model = rows(pose, drawn.scale);
        let previous = self.previous.and_then(|h| h.model(key)).unwrap_or(model);
        let [r, g, b] = shade.look.albedo;
        Instance {
            mesh,
            model,
            normal: normal_rows(pose, drawn.scale),
            previous,
            color: [r, g, b, shade.look.emission],
            shine: shade.look.shine,
            ids: shade.ids,
            scale: drawn.scale.to_array(),
            extent: drawn.extent.to_array(),
            surface: shade.surface,
        }
    }

    fn object(&mut self, id: ObjectId, planes: &[Vec4; 6], out: &mut Gathered) {
        let world = self.scene.world;
        let ids = self.ids(id, &world.bodies().object(id).category);
        let shown = Shown::of(world, id);
        let seed = object_seed(world, id);
        let finisher = (self.profile == ImageProfile::Realistic)
            .then(|| Finisher::of(world, id, self.home, seed));
        let eye = self.camera.pose.translation;
        for (k, part) in self.parts(id).iter().enumerate() {
            let drawn = Drawn::of(&part.shape, seed);
            let key = match part.shape {
                VisualShape::Piece { .. } => Key::Piece(id.0, k as u32),
                _ => Key::Part(id.0, k as u32),
            };
            out.models.push((key, rows(&part.pose, drawn.scale)));
            let centre = part.pose.translation;
            if !visible(planes, centre, drawn.reach) {
                continue;
            }
            let mut backdrop = false;
            if let VisualShape::Formed { form, half_extents } = part.shape {
                let local = part.pose.inverse_transform_point(eye);
                if local.abs().cmplt(half_extents).all() {
                    continue;
                }
                // A rounded board holds the box inside its bevel whole, a door the box of its
                // panel: that box hides what is behind it as a plain board would.
                if let Some((centre, inner)) = behavior_forms::solid_core(form, half_extents) {
                    let core = part.pose * Pose::from_translation(centre);
                    if Occlusion::worth(&core, inner) {
                        out.occluders.push((core, inner));
                        backdrop = true;
                    }
                }
            }
            // A camera inside a model piece's box does not draw it, as with a primitive.
            if let VisualShape::Piece { held, .. } = part.shape {
                let local = part.pose.inverse_transform_point(eye);
                if local.cmpgt(held.bounds[0]).all() && local.cmplt(held.bounds[1]).all() {
                    continue;
                }
            }
            if let VisualShape::Primitive(p) = part.shape {
                if contains(p, part.pose.inverse_transform_point(eye)) {
                    continue;
                }
                if let Primitive::Box { half_extents } = *p
                    && Occlusion::worth(&part.pose, half_extents)
                {
                    out.occluders.push((part.pose, half_extents));
                    backdrop = true;
                }
            }
            let pixels = self.pixels(centre, drawn.reach);
            let mesh = self.meshes.id(drawn.key.sized(pixels), &part.shape);
            let shade = match &finisher {
                None => Shade {
                    look: look(part.visual.color, part.visual.material, shown),
                    ids,
                    surface: [0, 0],
                },
                Some(finisher) => {
                    let finish = finisher.part(part.visual);
                    Shade {
                        look: look(finish.color, part.visual.material, shown),
                        ids,
                        surface: finish.packed(),
                    }
                }
            };
            let instance = self.instance(mesh, key, (&part.pose, &drawn), shade);
            out.pending.push(Pending {
                centre,
                reach: drawn.reach,
                near: (centre - eye).length() - drawn.reach,
                backdrop,
                instance,
            });
        }
    }

    /// An object's parts to draw: a model piece's meshes where the library holds them and the
    /// object is at least [`PIECE_ABOVE_PIXELS`] in radius on the image, else its own parts.
    fn parts(&self, id: ObjectId) -> Vec<VisualPart<'a>> {
        let world = self.scene.world;
        if world.bodies().object(id).model.is_some() {
            let b = world.bodies().local_aabb(id);
            let centre = world.bodies().pose(id) * b.center();
            if self.pixels(centre, (b.maxs - b.mins).length() * 0.5) >= PIECE_ABOVE_PIXELS {
                return world.visuals().parts_with(id, self.models);
            }
        }
        world.visuals().parts(id)
    }

    /// Dust as small grey balls, stains as thin dark discs lying flat.
    fn particles(&mut self, planes: &[Vec4; 6], out: &mut Gathered) {
        let world = self.scene.world;
        let kinds = [
            (
                Predicate::Dusty,
                DUST_CATEGORY,
                DUST,
                Primitive::Sphere { radius: 0.008 },
            ),
            (
                Predicate::Stained,
                STAIN_CATEGORY,
                STAIN,
                Primitive::Cylinder {
                    radius: 0.02,
                    half_height: 0.002,
                },
            ),
        ];
        for (id, object) in world.bodies().objects() {
            if !object.is_present() || self.scene.hidden.contains(&id) {
                continue;
            }
            for (kind, (predicate, category, color, shape)) in kinds.iter().enumerate() {
                let points = world.particle_positions(id, *predicate);
                if points.is_empty() {
                    continue;
                }
                let ids = [id.0 + 1, u32::from(self.scene.categories.id(category))];
                let shade = Shade {
                    look: look(*color, Material::Paper, Shown::default()),
                    ids,
                    surface: speck(Pattern::Plain, 0.9),
                };
                let dots = Dots { shape, shade };
                let key = |n| Key::Particle(id.0, kind as u8, n);
                self.dots(&dots, &points, key, planes, out);
            }
        }
    }

    fn drops(&mut self, planes: &[Vec4; 6], out: &mut Gathered) {
        let drops = self.scene.world.drops();
        if drops.is_empty() {
            return;
        }
        let ids = [0, u32::from(self.scene.categories.id(WATER_CATEGORY))];
        let shade = Shade {
            look: look(WATER, Material::Glass, Shown::default()),
            ids,
            surface: speck(Pattern::Glass, 0.05),
        };
        let ball = Primitive::Sphere { radius: 0.009 };
        let dots = Dots {
            shape: &ball,
            shade,
        };
        self.dots(&dots, &drops, Key::Drop, planes, out);
    }

    /// Instances of one small shape at world points, each keyed by its index.
    fn dots(
        &mut self,
        dots: &Dots,
        at: &[Vector],
        key: impl Fn(u32) -> Key,
        planes: &[Vec4; 6],
        out: &mut Gathered,
    ) {
        let shape = VisualShape::Primitive(dots.shape);
        let drawn = Drawn::of(&shape, 0);
        for (n, &p) in at.iter().enumerate() {
            let key = key(n as u32);
            let pose = Pose::from_translation(p);
            out.models.push((key, rows(&pose, drawn.scale)));
            if !visible(planes, p, drawn.reach) {
                continue;
            }
            let mesh = self
                .meshes
                .id(drawn.key.sized(self.pixels(p, drawn.reach)), &shape);
            let instance = self.instance(mesh, key, (&pose, &drawn), dots.shade);
            out.pending.push(Pending {
                centre: p,
                reach: drawn.reach,
                near: (p - self.camera.pose.translation).length(),
                backdrop: false,
                instance,
            });
        }
    }
}

/// How far an occluder's centre is from `eye`, m.
fn distance(occluder: &(Pose, Vector), eye: Vector) -> f32 {
    (occluder.0.translation - eye).length()
}

/// How an instance is coloured and labelled.
#[derive(Clone, Copy)]
struct Shade {
    look: Look,
    ids: [u32; 2],
    /// [`Finish::packed`], or zeros in the fast profile.
    surface: [u32; 2],
}

/// The packed finish of particles and drops: a plain pattern of this roughness.
fn speck(pattern: Pattern, roughness: f32) -> [u32; 2] {
    Finish {
        color: [0; 3],
        pattern,
        roughness,
        metallic: 0.0,
        seed: 0,
    }
    .packed()
}

/// Small things drawn at points (dust, stains, drops): one shape, shade and ids for all.
struct Dots<'a> {
    shape: &'a Primitive,
    shade: Shade,
}

/// Puts instances in drawing order: nearest first, so that the depth test spares the shading of
/// what they hide, and backdrops last (stably: ties keep the world's order).
fn in_drawing_order(pending: Vec<Pending>, mut models: Models) -> Batch {
    // Gathered in key order already (objects, then particles, then drops), so this only checks.
    models.sort_by_key(|(k, _)| *k);
    let mut order: Vec<(bool, f32, usize)> = pending
        .iter()
        .enumerate()
        .map(|(k, p)| (p.backdrop, p.near, k))
        .collect();
    order.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    Batch {
        instances: order.iter().map(|&(_, _, k)| pending[k].instance).collect(),
        models,
        culled: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_transform_maps_the_unit_cube_onto_the_box() {
        let pose = Pose::from_parts(
            Vector::new(1.0, 2.0, 3.0),
            rapier3d::math::Rotation::from_rotation_z(0.5),
        );
        let scale = Vector::new(0.1, 0.2, 0.3);
        let r = rows(&pose, scale);
        let corner = Vector::ONE;
        let mapped = Vector::new(
            Vec4::from(r[0]).dot(corner.extend(1.0)),
            Vec4::from(r[1]).dot(corner.extend(1.0)),
            Vec4::from(r[2]).dot(corner.extend(1.0)),
        );
        assert!((mapped - pose.transform_point(scale)).length() < 1e-5);
    }

    #[test]
    fn the_frustum_keeps_what_is_ahead_and_drops_what_is_behind() {
        let camera = Camera::eye(Pose::IDENTITY);
        let planes = frustum(&camera.view_projection());
        assert!(visible(&planes, Vector::new(2.0, 0.0, 0.0), 0.1));
        assert!(!visible(&planes, Vector::new(-2.0, 0.0, 0.0), 0.1));
        assert!(visible(&planes, Vector::new(-0.05, 0.0, 0.0), 0.1));
    }
}
