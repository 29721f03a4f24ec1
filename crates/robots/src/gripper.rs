//! A parallel-jaw gripper, whichever robot carries it: one world object (the palm) with two
//! finger links on prismatic joints driven in position, opened and closed a stroke a step, and
//! the assisted grasp that holds what both fingers touch (iGibson 2.0.3's
//! `robots/fetch_gripper_robot.py`). Its robot states its facts ([`GripperSpec`]), moves the
//! palm, and calls it in its step: the command at the step's start, the grasp after it.

use crate::grasp::{GraspRules, Hold, Release, centre_on};
use crate::magic::MagicError;
use behavior_sim::{
    AttachmentId, AttachmentKind, AttachmentSpec, BodyRef, Drive, ObjectId, STEP_SECONDS, World,
    WorldError,
};
use rapier3d::math::{Pose, Vector};

/// A gripper's facts, as its robot's URDF states them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GripperSpec {
    /// The palm object's finger links.
    pub(crate) fingers: [usize; 2],
    /// How far each finger opens, m (0 closed).
    pub(crate) open: f32,
    /// A finger's fastest travel, m/s: the stroke of one step.
    pub(crate) max_velocity: f32,
    /// The finger drives' stiffness (N/m), damping (N·s/m) and most force (N).
    pub(crate) stiffness: f32,
    pub(crate) damping: f32,
    pub(crate) effort: f32,
    /// The point between the fingers where what it takes is centred, in the palm's frame.
    pub(crate) centre: Vector,
    /// Each finger pad's inner face centre, in its link's frame (for buttons).
    pub(crate) pads: [Vector; 2],
}

/// What a gripper's grasp reads of its robot: the gripper's facts, the grasp rules in force,
/// and the robot's own objects (never taken).
#[derive(Clone, Copy)]
pub(crate) struct GraspContext<'a> {
    pub(crate) spec: &'a GripperSpec,
    pub(crate) rules: &'a GraspRules,
    pub(crate) own: &'a [ObjectId],
}

/// What the gripper holds.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
struct Held {
    body: BodyRef,
    attachment: AttachmentId,
}

/// A parallel-jaw gripper's state: what it was told and what it holds (see the module docs).
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub(crate) struct ParallelGripper {
    palm: ObjectId,
    /// The finger drives' target in force.
    target: f32,
    /// The command of the step begun last: above 0 opens, below closes.
    command: f32,
    held: Option<Held>,
    releases: Vec<Release>,
}

/// The bodies of the gripper of `palm` that touch what it takes: the palm and the two fingers.
pub(crate) fn bodies(palm: ObjectId, spec: &GripperSpec) -> [BodyRef; 3] {
    let [a, b] = spec.fingers.map(|l| BodyRef::link(palm, l));
    [BodyRef::from(palm), a, b]
}

/// The finger positions of the gripper of `palm`, m: 0 closed.
pub(crate) fn fingers(world: &World, palm: ObjectId, spec: &GripperSpec) -> [f32; 2] {
    spec.fingers.map(|l| world.joints().position(palm, l))
}

impl ParallelGripper {
    /// The gripper of `palm` (already in `world`, fingers at their joints), opened.
    pub(crate) fn open_on(
        world: &mut World,
        palm: ObjectId,
        spec: &GripperSpec,
    ) -> Result<Self, WorldError> {
        let mut gripper = ParallelGripper {
            palm,
            target: f32::NAN,
            command: 1.0,
            held: None,
            releases: Vec::new(),
        };
        for link in spec.fingers {
            world.joints_mut().set_position(palm, link, spec.open)?;
        }
        gripper.drive(world, spec, spec.open);
        Ok(gripper)
    }

    /// The bodies that touch what it takes: the palm and the two fingers.
    pub(crate) fn bodies(&self, spec: &GripperSpec) -> [BodyRef; 3] {
        bodies(self.palm, spec)
    }

    /// The body it holds.
    pub(crate) fn holding(&self) -> Option<BodyRef> {
        self.held.map(|g| g.body)
    }

    /// The attachment by which it holds, if it holds something.
    pub(crate) fn attachment(&self) -> Option<AttachmentId> {
        self.held.map(|g| g.attachment)
    }

    /// Where the palm was before a teleport of the robot.
    pub(crate) fn palm_pose(&self, world: &World) -> Pose {
        world.bodies().pose(self.palm)
    }

    /// After a teleport of the robot that took the palm from `before`: what it holds follows,
    /// keeping its pose relative to the palm.
    pub(crate) fn carry_held(&self, world: &mut World, before: Pose) -> Result<(), WorldError> {
        let Some(body) = self.holding() else {
            return Ok(());
        };
        let relative = before.inv_mul(&world.bodies().pose(body.object));
        let target = world.bodies().pose(self.palm) * relative;
        world.bodies_mut().set_pose(body.object, target)
    }

    /// The fingers' positions, m: 0 closed.
    pub(crate) fn fingers(&self, world: &World, spec: &GripperSpec) -> [f32; 2] {
        fingers(world, self.palm, spec)
    }

    /// Takes the step's command: the fingers a stroke further open or closed, unless it holds
    /// something (they stay as they closed on it).
    pub(crate) fn command(&mut self, world: &mut World, spec: &GripperSpec, command: f32) {
        self.command = command;
        if self.held.is_none() {
            let stroke = spec.max_velocity * STEP_SECONDS;
            let direction = if self.command > 0.0 { 1.0 } else { -1.0 };
            let target = (self.target + direction * stroke).clamp(0.0, spec.open);
            self.drive(world, spec, target);
        }
    }

    /// After a step: lets go where the grasp must end, grasps where a closing gripper has a
    /// body between its fingers; contacts come back with what it let go once apart.
    pub(crate) fn after_step(&mut self, world: &mut World, cx: GraspContext<'_>) {
        match self.held {
            Some(held) if self.must_release(world, &held, cx.rules) => {
                world.attachments_mut().detach(held.attachment);
                self.held = None;
                self.releases.push(Release {
                    body: held.body,
                    parts: vec![self.palm],
                    since: world.bodies().steps(),
                });
            }
            None if self.command < 0.0 => self.try_grasp(world, cx),
            _ => {}
        }
        if !self.releases.is_empty() {
            // Contacts come back after the release step, once apart, and not while held again.
            let (held, now) = (self.holding(), world.bodies().steps());
            self.releases
                .retain_mut(|r| Some(r.body) == held || r.since == now || !r.settle(world));
        }
    }

    /// Tells the world where the gripper's centre and pads are, for buttons: a robot with one
    /// gripper.
    pub(crate) fn press(&self, world: &mut World, spec: &GripperSpec) {
        world.set_hand_points(&self.points(world, spec));
    }

    /// Where the gripper's centre and pads are, in the world.
    pub(crate) fn points(&self, world: &World, spec: &GripperSpec) -> [Vector; 3] {
        let centre = world.bodies().pose(self.palm).transform_point(spec.centre);
        let pads = [0, 1].map(|k| {
            let pose = world.bodies().link_pose(self.palm, spec.fingers[k]);
            pose.transform_point(spec.pads[k])
        });
        [centre, pads[0], pads[1]]
    }

    /// Sets both finger drives toward `target` if it changed.
    fn drive(&mut self, world: &mut World, spec: &GripperSpec, target: f32) {
        if target == self.target {
            return;
        }
        let drive = Drive::position(target, spec.stiffness, spec.damping, spec.effort);
        for link in spec.fingers {
            // The links exist and the drive's numbers are finite: this cannot fail.
            let _ = world.joints_mut().drive(self.palm, link, drive);
        }
        self.target = target;
    }

    fn must_release(&self, world: &World, held: &Held, rules: &GraspRules) -> bool {
        match world.attachments().get(held.attachment) {
            None => true,
            Some(state) => {
                self.command > 0.0 || state.broken || state.violation > rules.max_violation
            }
        }
    }

    /// The assisted grasp: a body touching both fingers, the one closest to the gripper's
    /// centre, if the rules let it be held.
    fn try_grasp(&mut self, world: &mut World, cx: GraspContext<'_>) {
        let Some((body, at)) = self.candidate(world, cx.spec, cx.own) else {
            return;
        };
        let Some(kind) = cx.rules.holdable(world, body) else {
            return;
        };
        let _ = self.hold(world, cx, body, at, kind);
    }

    /// Attaches `body` to the palm at `at` as the assisted grasp does: its contacts with the
    /// palm and fingers off, the fingers frozen where they are while it is held.
    fn hold(
        &mut self,
        world: &mut World,
        cx: GraspContext<'_>,
        body: BodyRef,
        at: Vector,
        kind: AttachmentKind,
    ) -> Result<(), WorldError> {
        let attach = AttachmentSpec {
            holder: BodyRef::from(self.palm),
            held: body,
            at,
            kind,
            max_force: cx.rules.max_force(kind),
        };
        let attachment = world.attachments_mut().attach(attach)?;
        for part in self.bodies(cx.spec) {
            let _ = world.contacts_mut().ignore(part, body, true);
        }
        let [first, _] = self.fingers(world, cx.spec);
        self.drive(world, cx.spec, first.clamp(0.0, cx.spec.open));
        self.held = Some(Held { body, attachment });
        Ok(())
    }

    /// The body touching both fingers closest to the gripper's centre, and the middle of its
    /// contacts with them.
    fn candidate(
        &self,
        world: &World,
        spec: &GripperSpec,
        own: &[ObjectId],
    ) -> Option<(BodyRef, Vector)> {
        let contacts = spec.fingers.map(|l| {
            let all = world.contacts().of(BodyRef::link(self.palm, l));
            all.unwrap_or_default()
                .into_iter()
                .filter_map(|c| Some((c.other?, c.point)))
                .filter(|(b, _)| !own.contains(&b.object))
                .collect::<Vec<_>>()
        });
        let centre = world.bodies().pose(self.palm).transform_point(spec.centre);
        let mut best: Option<(f32, BodyRef, Vector)> = None;
        for &(body, _) in &contacts[0] {
            if !contacts[1].iter().any(|(b, _)| *b == body) {
                continue;
            }
            let points: Vec<Vector> = contacts
                .iter()
                .flatten()
                .filter(|(b, _)| *b == body)
                .map(|(_, p)| *p)
                .collect();
            let at = points.iter().copied().sum::<Vector>() / points.len() as f32;
            let d = points
                .iter()
                .map(|p| (*p - centre).length())
                .fold(f32::INFINITY, f32::min);
            if best.is_none_or(|(bd, bb, _)| d < bd || (d == bd && body < bb)) {
                best = Some((d, body, at));
            }
        }
        best.map(|(_, body, at)| (body, at))
    }

    /// Puts `object` between the fingers, attaches it as the assisted grasp does and closes.
    pub(crate) fn grasp_now(
        &mut self,
        world: &mut World,
        cx: GraspContext<'_>,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        self.empty()?;
        let body = BodyRef::from(object);
        let kind = cx.rules.kind_for(world, body, cx.own, None)?;
        let centre = world
            .bodies()
            .pose(self.palm)
            .transform_point(cx.spec.centre);
        centre_on(world, object, centre)?;
        let palm = self.palm;
        let attachment = self.at_once(cx).attach(world, palm, body, centre, kind)?;
        self.command = -1.0;
        self.held = Some(Held { body, attachment });
        Ok(())
    }

    /// Holds `object` where it is, if the palm or a finger touches it: the forced assisted
    /// grasp after a physical GRASP closed the gripper, attached at the middle of those
    /// contacts.
    pub(crate) fn grasp_touching(
        &mut self,
        world: &mut World,
        cx: GraspContext<'_>,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        self.empty()?;
        let mut points = Vec::new();
        let mut body = None;
        for part in self.bodies(cx.spec) {
            for c in world.contacts().of(part)? {
                if let Some(b) = c.other.filter(|b| b.object == object) {
                    points.push(c.point);
                    body = Some(body.map_or(b, |old: BodyRef| old.min(b)));
                }
            }
        }
        let body = body.ok_or(MagicError::NotTouching(object))?;
        let kind = cx.rules.kind_for(world, body, cx.own, None)?;
        let at = points.iter().copied().sum::<Vector>() / points.len() as f32;
        self.hold(world, cx, body, at, kind)?;
        self.command = -1.0;
        Ok(())
    }

    /// Detaches what it holds and opens; what it held, if anything.
    pub(crate) fn release(&mut self, world: &mut World, cx: GraspContext<'_>) -> Option<ObjectId> {
        self.command = 1.0;
        let held = self.held.take()?;
        self.at_once(cx).let_go(world, held.body, held.attachment);
        self.drive(world, cx.spec, cx.spec.open);
        Some(held.body.object)
    }

    /// Refuses a grasp while it holds something.
    fn empty(&self) -> Result<(), MagicError> {
        match self.held {
            Some(held) => Err(MagicError::HandFull(held.body.object)),
            None => Ok(()),
        }
    }

    /// Takes and lets go of things at once, as the assisted grasp does.
    fn at_once<'r>(&'r mut self, cx: GraspContext<'r>) -> Hold<'r> {
        Hold {
            rules: cx.rules,
            own: cx.own.to_vec(),
            releases: &mut self.releases,
        }
    }
}
