//! Building an object from its spec: checking every number first (a bad spec leaves no trace in
//! the world), then its body, colliders, links and joints.

use crate::bodies::Bodies;
use crate::core::{WorldError, pose_is_finite, tag};
use crate::object::{
    BodyKind, BodyRef, JointHandle, JointKind, JointModel, JointSpec, Link, LinkSpec, Object,
    ObjectId, ObjectSpec, Part, Primitive,
};
use rapier3d::dynamics::{
    FixedJointBuilder, GenericJoint, PrismaticJointBuilder, RevoluteJointBuilder, RigidBodyBuilder,
    RigidBodyHandle,
};
use rapier3d::geometry::{Collider, ColliderBuilder, ColliderHandle};
use rapier3d::math::{Pose, Rotation};

/// Mass given to a link without parts (a camera mount), so the solver can move it (kg).
const FRAME_MASS: f32 = 1e-3;

impl Bodies {
    /// Adds an object; its bodies and colliders carry tags so queries can map hits back to it.
    /// Every part is checked before anything is inserted, so a bad spec leaves no trace.
    pub(crate) fn add(&mut self, spec: ObjectSpec) -> Result<ObjectId, WorldError> {
        let id = ObjectId(self.objects.len() as u32);
        let bad = |reason: String| WorldError::BadObject {
            name: spec.name.clone(),
            reason,
        };
        check_spec(&spec).map_err(bad)?;
        let builders = colliders_of(&spec.parts, spec.density, spec.friction, tag(id.into()))
            .ok_or_else(|| bad("a part has a non-positive or non-finite size or offset".into()))?;
        let link_builders = link_colliders(&spec, id).map_err(bad)?;
        let body = self.insert_body(&spec, spec.body, tag(id.into()), 0.0);
        let mut colliders: Vec<ColliderHandle> = builders
            .into_iter()
            .map(|c| self.physics.insert_collider(c, Some(body)))
            .collect();
        let links = self
            .insert_links(&spec, (id, body), link_builders, &mut colliders)
            .map_err(bad)?;
        let pushed = self.push_object(Object {
            name: spec.name,
            category: spec.category,
            body_kind: spec.body,
            body,
            colliders,
            abilities: spec.abilities,
            points: spec.points,
            links,
            halves: spec.halves,
            density: spec.density,
            friction: spec.friction,
            angular_damping: spec.angular_damping,
            parts: spec.parts,
            visual: spec.visual,
            meshes: spec.meshes,
            form: spec.form,
            model: spec.model,
            replaced_by: None,
            retired: false,
            ghost: None,
        });
        debug_assert_eq!(pushed, id);
        self.refresh();
        Ok(id)
    }

    /// Each link's body, colliders (added to `colliders`) and joint to its parent.
    fn insert_links(
        &mut self,
        spec: &ObjectSpec,
        (id, body): (ObjectId, RigidBodyHandle),
        builders: Vec<Vec<Collider>>,
        colliders: &mut Vec<ColliderHandle>,
    ) -> Result<Vec<Link>, String> {
        let mut links: Vec<Link> = Vec::with_capacity(spec.links.len());
        for (i, (link, builders)) in spec.links.iter().zip(builders).enumerate() {
            let extra = if link.parts.is_empty() {
                FRAME_MASS
            } else {
                0.0
            };
            let tag = tag(BodyRef::link(id, i));
            let link_body = self.insert_body(spec, BodyKind::Dynamic, tag, extra);
            colliders.extend(
                builders
                    .into_iter()
                    .map(|c| self.physics.insert_collider(c, Some(link_body))),
            );
            let parent = link.parent.map_or(body, |p| links[p].body);
            let handle = self
                .insert_joint(parent, link_body, &link.joint)
                .ok_or_else(|| {
                    format!(
                        "link `{}` would close a loop of multibody joints",
                        link.name
                    )
                })?;
            let mut joint = link.joint.clone();
            joint.axis = joint.axis.normalize();
            links.push(Link {
                name: link.name.clone(),
                parent: link.parent,
                joint,
                parts: link.parts.clone(),
                body: link_body,
                handle,
            });
        }
        Ok(links)
    }

    fn insert_body(
        &mut self,
        spec: &ObjectSpec,
        kind: BodyKind,
        tag: u128,
        extra_mass: f32,
    ) -> RigidBodyHandle {
        let builder = match kind {
            BodyKind::Fixed => RigidBodyBuilder::fixed(),
            BodyKind::Dynamic => RigidBodyBuilder::dynamic(),
            BodyKind::KinematicPosition => RigidBodyBuilder::kinematic_position_based(),
            BodyKind::KinematicVelocity => RigidBodyBuilder::kinematic_velocity_based(),
        };
        // Only dynamic bodies sleep; a kinematic or fixed one ignores the flag.
        let asleep = spec.asleep && kind == BodyKind::Dynamic;
        let body = builder
            .sleeping(asleep)
            .pose(spec.pose)
            .angular_damping(spec.angular_damping)
            .additional_mass(extra_mass)
            .user_data(tag)
            .build();
        let handle = self.physics.insert_body(body);
        if asleep {
            self.fall_asleep_at_once(handle);
        }
        handle
    }

    /// The joint between a link and its parent. Both bodies start at the object's pose, so the
    /// anchor is the same point in both frames.
    fn insert_joint(
        &mut self,
        parent: RigidBodyHandle,
        child: RigidBodyHandle,
        spec: &JointSpec,
    ) -> Option<JointHandle> {
        let joint = generic_joint(spec);
        Some(match spec.model {
            JointModel::Impulse => {
                JointHandle::Impulse(self.physics.insert_impulse_joint(parent, child, joint))
            }
            JointModel::Multibody => JointHandle::Multibody(
                self.physics
                    .multibody_joints
                    .insert(parent, child, joint, true)?,
            ),
        })
    }
}

/// The rapier joint for a spec, with its passive damping.
fn generic_joint(spec: &JointSpec) -> GenericJoint {
    let axis = spec.axis.normalize();
    let mut joint: GenericJoint = match spec.kind {
        JointKind::Revolute => RevoluteJointBuilder::new(axis)
            .local_anchor1(spec.anchor)
            .local_anchor2(spec.anchor)
            .contacts_enabled(false)
            .build()
            .into(),
        JointKind::Prismatic => PrismaticJointBuilder::new(axis)
            .local_anchor1(spec.anchor)
            .local_anchor2(spec.anchor)
            .contacts_enabled(false)
            .build()
            .into(),
        JointKind::Fixed => FixedJointBuilder::new()
            .local_anchor1(spec.anchor)
            .local_anchor2(spec.anchor)
            .contacts_enabled(false)
            .build()
            .into(),
    };
    if let Some(axis) = crate::joints::free_axis(spec.kind) {
        if let Some(limits) = spec.limits {
            joint.set_limits(axis, limits);
        }
        crate::joints::passive(&mut joint, axis, spec.damping);
    }
    joint
}

/// Every link checked, with its colliders built (not yet inserted).
fn link_colliders(spec: &ObjectSpec, id: ObjectId) -> Result<Vec<Vec<Collider>>, String> {
    spec.links
        .iter()
        .enumerate()
        .map(|(i, link)| {
            check_link(link, i, &spec.links).map_err(|r| format!("link `{}`: {r}", link.name))?;
            colliders_of(
                &link.parts,
                link.density,
                spec.friction,
                tag(BodyRef::link(id, i)),
            )
            .ok_or_else(|| format!("link `{}` has a malformed part", link.name))
        })
        .collect()
}

/// Every number of the spec except its parts and links, which are checked as they are built.
fn check_spec(spec: &ObjectSpec) -> Result<(), String> {
    if spec.parts.is_empty() {
        return Err("it has no parts".into());
    }
    if !(spec.density.is_finite() && spec.density > 0.0) {
        return Err("density must be a positive number".into());
    }
    let non_negative = |x: f32| x.is_finite() && x >= 0.0;
    if !non_negative(spec.friction) || !non_negative(spec.angular_damping) {
        return Err("friction and damping must be non-negative numbers".into());
    }
    if !pose_is_finite(&spec.pose) {
        return Err("its pose is not finite or its rotation not a unit quaternion".into());
    }
    if !spec.points.iter().all(|(_, p)| p.is_finite()) {
        return Err("a named point is not finite".into());
    }
    if let Some(halves) = &spec.halves
        && halves
            .iter()
            .any(|h| h.is_empty() || colliders_of(h, 1.0, 0.5, 0).is_none())
    {
        return Err("its halves must each have valid parts".into());
    }
    for mesh in &spec.meshes {
        let n = mesh.vertices.len() as u32;
        let link_ok = mesh.link.is_none_or(|l| l < spec.links.len());
        if !link_ok
            || !mesh.vertices.iter().all(|v| v.is_finite())
            || mesh.triangles.iter().flatten().any(|&i| i >= n)
        {
            return Err("a visual mesh has a bad link, vertex or triangle index".into());
        }
    }
    Ok(())
}

fn check_link(link: &LinkSpec, index: usize, all: &[LinkSpec]) -> Result<(), String> {
    let j = &link.joint;
    if !(link.density.is_finite() && link.density > 0.0) {
        return Err("density must be a positive number".into());
    }
    if !(j.anchor.is_finite() && j.axis.is_finite() && j.axis.length() > 1e-6) {
        return Err("its anchor or axis is not finite, or the axis is zero".into());
    }
    if !(j.damping.is_finite() && j.damping >= 0.0) {
        return Err("damping must be a non-negative number".into());
    }
    if let Some([lo, hi]) = j.limits
        && !(lo.is_finite() && hi.is_finite() && lo < hi)
    {
        return Err(format!("limits [{lo}, {hi}] must be finite and increasing"));
    }
    if link.parts.is_empty() && j.kind != JointKind::Fixed {
        return Err("only a link on a fixed joint may have no parts".into());
    }
    match link.parent {
        Some(p) if p >= index => Err(format!("its parent {p} must be an earlier link")),
        Some(p) if all[p].joint.model != j.model => {
            Err("a chain must use one joint model (impulse or multibody) throughout".into())
        }
        _ => Ok(()),
    }
}

/// Colliders for parts, tagged; `None` if a part is malformed.
pub(crate) fn colliders_of(
    parts: &[Part],
    density: f32,
    friction: f32,
    tag: u128,
) -> Option<Vec<Collider>> {
    parts
        .iter()
        .map(|part| {
            let builder = collider(&part.primitive)?;
            pose_is_finite(&part.offset).then(|| {
                builder
                    .position(part.offset)
                    .density(density)
                    .friction(friction)
                    .user_data(tag)
                    .build()
            })
        })
        .collect()
}

fn collider(primitive: &Primitive) -> Option<ColliderBuilder> {
    let ok = |x: f32| x.is_finite() && x > 0.0;
    // parry's cylinders and capsules run along y; ours stand along z.
    let upright = Pose::from_rotation(Rotation::from_rotation_x(std::f32::consts::FRAC_PI_2));
    Some(match *primitive {
        Primitive::ConvexHull { ref points } => {
            if points.len() < 4 || !points.iter().all(|p| p.is_finite()) {
                return None;
            }
            ColliderBuilder::convex_hull(points)?
        }
        Primitive::Box { half_extents: h } if ok(h.x) && ok(h.y) && ok(h.z) => {
            ColliderBuilder::cuboid(h.x, h.y, h.z)
        }
        Primitive::Sphere { radius } if ok(radius) => ColliderBuilder::ball(radius),
        Primitive::Capsule {
            radius,
            half_height,
        } if ok(radius) && ok(half_height) => ColliderBuilder::capsule_z(half_height, radius),
        Primitive::Cylinder {
            radius,
            half_height,
        } if ok(radius) && ok(half_height) => {
            let shape = rapier3d::geometry::SharedShape::cylinder(half_height, radius);
            ColliderBuilder::compound(vec![(upright, shape)])
        }
        _ => return None,
    })
}
