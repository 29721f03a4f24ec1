//! The BehaviorRobot: adding it to a world, stepping it, and reading it.

use crate::action::{ACTION_DIM, ACTION_SCALE, Action, ActionError, ActionSpace};
use crate::body::{BODY_HEIGHT, HAND_REACH, body_spec, eye_rest, hand_rest, head_round};
use crate::embodiment::{
    BaseDrive, BaseMove, Embodiment, EmbodimentSpec, HandMotion, LidarMount, Scan,
};
use crate::follow::{Follower, HAND_LIMITS, rotation_error, servo, settled};
use crate::grasp::{Grasp, GraspRules, Grasper, Hold, Release, centre_on, must_release};
use crate::hand::{FINGERS, Fingers, HandPoints, Side, hand_spec, sweep_shape};
use crate::magic::MagicError;
use crate::motion::{Blocker, Targets};
use crate::posed_hand::PosedHand;
use crate::proprioception::{LocalPose, Proprioception};
use crate::robot::{RobotError, RobotKind, pose_ok};
use behavior_sim::{
    AttachmentId, AttachmentKind, AttachmentSpec, BodyRef, ObjectId, Primitive, QueryFilter,
    STEP_SECONDS, StepHooks, Velocity, World, WorldError, groups,
};
use rapier3d::math::{Pose, Vector};
use std::sync::Arc;

/// The world objects a BehaviorRobot is made of.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq, Eq)]
pub struct RobotParts {
    /// The floating body.
    pub body: ObjectId,
    /// The hands (left, right): each a palm with five finger links.
    pub hands: [ObjectId; 2],
}

impl RobotParts {
    /// Adds the body and the hands at their starting places, in the robot's collision group.
    fn add(world: &mut World, pose: Pose) -> Result<RobotParts, WorldError> {
        let body = world.add(body_spec("robot_body", pose))?;
        let mut hand =
            |name: &str, side: Side| world.add(hand_spec(name, side, pose * hand_rest(side)));
        let hands = [
            hand("robot_left_hand", Side::Left)?,
            hand("robot_right_hand", Side::Right)?,
        ];
        let parts = RobotParts { body, hands };
        // Robot parts touch neither each other (the hands start inside the body) nor water.
        let others = groups::ALL & !groups::ROBOT & !groups::WATER;
        for id in parts.all() {
            world.contacts_mut().set_groups(id, groups::ROBOT, others);
        }
        Ok(parts)
    }

    /// A hand's object.
    pub fn hand(&self, side: Side) -> ObjectId {
        self.hands[side.index()]
    }

    /// The body, then the left and right hands.
    pub fn all(&self) -> [ObjectId; 3] {
        [self.body, self.hands[0], self.hands[1]]
    }
}

/// The bimanual humanoid of BEHAVIOR's VR demonstrations (iGibson 2.0's `BehaviorRobot`): a
/// floating body, an eye, and two hands with five fingers each, driven by a 26-d [`Action`] and
/// holding things by assisted grasping ([`GraspRules`]).
///
/// **Body model.** The original moves every part by a force-limited constraint toward its target
/// (body 7,500 N, hands 300 N). Ours:
/// - The body is a velocity-driven kinematic body, moved at constant speed within each step to
///   its target (stopped with exactly zero velocity, so that it sleeps at any heading). It
///   costs the solver nothing, goes exactly where it is told (it drives 1 m when told to), and
///   sleeps when still. Walls and furniture stop it: it is never sent into a fixed body (see
///   `motion.rs`). Movable objects in its way it pushes with unbounded force (the original: at
///   most 7,500 N — in practice the same for household objects).
/// - Each palm is a dynamic body servoed every substep onto a smooth reference path toward its
///   target, with at most 300 N (see `follow.rs`): it carries what it holds, and presses on what
///   it meets with bounded force and yields, as the original's. A kinematic palm would squeeze an
///   apple against a table with unbounded force and shoot it away. Hands are not sent into
///   fixed bodies either.
/// - A hand that has come to rest at its target is *parked*: held to the body by a fixed
///   attachment instead of the servo, so that it and what it holds fall asleep (a
///   servoed body holding itself up against gravity never would), and an idle robot costs an idle
///   world nothing. It is unparked as soon as it must move.
/// - The fingers are shapes of the hands' bodies, turned toward what the triggers ask each
///   substep (see `hand.rs`).
///
/// The eye is a frame on the body, not a body (the original's is massless and teleported);
/// the head round it is drawn with the body ([`behavior_sim::Ghost`]), not simulated.
/// Robot parts are in [`groups::ROBOT`]: they collide with neither each other nor water.
///
/// **State.** What the robot was told (targets, triggers, grasps) lives here, the rest in the
/// world: to save an episode, clone the robot with the world's [`World::snapshot`]; the pair
/// continues bit-identically. An action acts for one step: [`BehaviorRobot::set_action`] then
/// [`World::step_with`], or [`BehaviorRobot::step`] for both; a step without one holds still.
/// Step the world with the robot ([`World::step_with`]): a step without it moves nothing of the
/// robot, and a hand that was moving (not parked) is then not held up. Buttons are pressed by the
/// palms and fingertips ([`World::set_hand_points`]), so one robot per world.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub struct BehaviorRobot {
    parts: RobotParts,
    /// Targets at the end of the last step begun.
    targets: Targets,
    /// The body's target at the start of the step being taken.
    step_from: Pose,
    hands: [Follower; 2],
    /// Each hand's parking attachment to the body, while it rests.
    parked: [Option<AttachmentId>; 2],
    /// Each hand's fingers.
    fingers: [Fingers; 2],
    grasps: [Option<Grasp>; 2],
    releases: Vec<Release>,
    pending: Action,
    /// Whether a part moved in the step being taken.
    moved: bool,
    /// Whether the body was given a velocity that must be stopped.
    body_moving: bool,
    rules: GraspRules,
}

/// A parking attachment gives way past this force, N: far more than a hand and what it may hold
/// weigh; a blow that breaks it just wakes the hand's servo.
const PARKING_FORCE: f32 = 5000.0;

impl BehaviorRobot {
    /// Adds a robot whose body stands at `pose` (its origin is the body capsule's centre: at
    /// [`crate::BODY_HEIGHT`] above a floor it floats clear of it), hands and eye in their starting
    /// places, triggers open, with the original's grasp rules.
    pub fn add(world: &mut World, pose: Pose) -> Result<BehaviorRobot, RobotError> {
        BehaviorRobot::add_with(world, pose, GraspRules::default())
    }

    /// [`BehaviorRobot::add`] with other grasp rules.
    pub fn add_with(
        world: &mut World,
        pose: Pose,
        rules: GraspRules,
    ) -> Result<BehaviorRobot, RobotError> {
        if !pose_ok(&pose) {
            return Err(RobotError::BadPose);
        }
        let pose = Pose::from_parts(pose.translation, pose.rotation.normalize());
        let parts = RobotParts::add(world, pose)?;
        let targets = Targets {
            body: pose,
            eye: eye_rest(),
            hands: [hand_rest(Side::Left), hand_rest(Side::Right)],
            triggers: [0.0; 2],
        };
        let mut robot = BehaviorRobot {
            parts,
            targets,
            step_from: pose,
            hands: Side::BOTH.map(|s| Follower::at(targets.hand_in_world(s))),
            parked: [None; 2],
            fingers: [Fingers::OPEN; 2],
            grasps: [None; 2],
            releases: Vec::new(),
            pending: Action::ZERO,
            moved: false,
            body_moving: false,
            rules,
        };
        for side in Side::BOTH {
            robot.park(world, side);
        }
        robot.press_with_hands(world);
        robot.follow_with_head(world);
        Ok(robot)
    }

    /// The action for the next step (replacing one set before); after that step the robot holds
    /// still until told otherwise.
    pub fn set_action(&mut self, action: Action) {
        self.pending = action;
    }

    /// Checks `values` as an [`Action`] and, if it is one, takes a step of the world with it. A
    /// bad action is an error and leaves the world and the robot untouched.
    pub fn step(&mut self, world: &mut World, values: &[f32]) -> Result<(), ActionError> {
        self.set_action(Action::new(values)?);
        world.step_with(self);
        Ok(())
    }

    /// The world objects the robot is made of.
    pub fn parts(&self) -> RobotParts {
        self.parts
    }

    /// The grasp rules in force.
    pub fn rules(&self) -> &GraspRules {
        &self.rules
    }

    /// The body's pose in the world.
    pub fn body_pose(&self, world: &World) -> Pose {
        world.bodies().pose(self.parts.body)
    }

    /// The eye's pose in the world: it looks along its +x, with +z up.
    pub fn eye_pose(&self, world: &World) -> Pose {
        self.body_pose(world) * self.targets.eye
    }

    /// A palm's pose in the world (see the hand's frame in `hand.rs`: x along the fingers, the
    /// palm facing −z).
    pub fn hand_pose(&self, world: &World, side: Side) -> Pose {
        world.bodies().pose(self.parts.hand(side))
    }

    /// Where a hand is told to be, in the body frame: where its actions have sent it (the palm
    /// trails this by about a step). A planner that steers a hand computes its deltas from it.
    pub fn hand_target(&self, side: Side) -> Pose {
        self.targets.hands[side.index()]
    }

    /// The centre of a hand's reach, in the world: its shoulder. A hand target farther than
    /// [`crate::HAND_REACH`] from it is pulled back onto that sphere.
    pub fn shoulder(&self, world: &World, side: Side) -> Vector {
        self.body_pose(world)
            .transform_point(crate::body::shoulder(side))
    }

    /// A trigger's fraction, 0 (open) to 1 (fully pressed).
    pub fn trigger(&self, side: Side) -> f32 {
        self.targets.triggers[side.index()]
    }

    /// The body a hand holds.
    pub fn holding(&self, side: Side) -> Option<BodyRef> {
        self.grasps[side.index()].map(|g| g.body)
    }

    /// The robot's proprioception now.
    pub fn proprioception(&self, world: &World) -> Proprioception {
        let body = self.body_pose(world);
        let hand = |side: Side| LocalPose::of(body.inv_mul(&self.hand_pose(world, side)));
        Proprioception {
            hands: [hand(Side::Left), hand(Side::Right)],
            eye: LocalPose::of(self.targets.eye),
            triggers: self.targets.triggers,
            grasping: [self.grasps[0].is_some(), self.grasps[1].is_some()],
        }
    }
}

impl BehaviorRobot {
    /// What a BehaviorRobot is, for planners and episodes.
    pub const SPEC: EmbodimentSpec = EmbodimentSpec {
        kind: RobotKind::Behavior,
        hand_names: &["left_hand", "right_hand"],
        origin_height: BODY_HEIGHT,
        drive: BaseDrive::Holonomic,
        hand_motion: HandMotion::Posed,
        spaces: &[
            ActionSpace::Full,
            ActionSpace::Navigation,
            ActionSpace::MobileManipulation,
            ActionSpace::TabletopManipulation,
        ],
        primitive_space: ActionSpace::Full,
        // A hand 1.2 m from a shoulder 1 m above the floor reaches a table's far side.
        arm_reach: 1.0,
        // Held in a palm servoed toward its target, what a hand carries trails and swings as the
        // base drives (a tile caught a wall on a path planned past it with no room, and its grasp
        // broke).
        carry_sway: 0.03,
    };
}

/// A hand's side by its number: 0 left, 1 right.
fn side(hand: usize) -> Result<Side, MagicError> {
    Side::BOTH
        .get(hand)
        .copied()
        .ok_or(MagicError::NoHand(hand))
}

impl Embodiment for BehaviorRobot {
    fn spec(&self) -> &'static EmbodimentSpec {
        &BehaviorRobot::SPEC
    }

    fn action_dim(&self, space: ActionSpace) -> usize {
        space.dim()
    }

    fn set_action(&mut self, space: ActionSpace, values: &[f32]) -> Result<(), ActionError> {
        self.pending = space.action(values)?;
        Ok(())
    }

    fn base_action(&self, space: ActionSpace, step: BaseMove) -> Option<Vec<f32>> {
        if !space.moves_body() {
            return None;
        }
        let mut full = [0.0; ACTION_DIM];
        full[Action::BODY.start] = (step.forward / ACTION_SCALE).clamp(-1.0, 1.0);
        full[Action::BODY.start + 1] = (step.left / ACTION_SCALE).clamp(-1.0, 1.0);
        full[Action::BODY.start + 5] = (step.turn / ACTION_SCALE).clamp(-1.0, 1.0);
        space.reduce(&full)
    }

    fn proprioception_dim(&self) -> usize {
        Proprioception::DIM
    }

    fn proprioception_into(&self, world: &World, out: &mut Vec<f32>) {
        out.extend(self.proprioception(world).to_array());
    }

    fn base_pose(&self, world: &World) -> Pose {
        self.body_pose(world)
    }

    fn base(&self) -> ObjectId {
        self.parts.body
    }

    fn objects(&self) -> Vec<ObjectId> {
        self.parts.all().to_vec()
    }

    fn hand_object(&self, hand: usize) -> Option<ObjectId> {
        side(hand).ok().map(|s| self.parts.hand(s))
    }

    fn held(&self, hand: usize) -> Option<ObjectId> {
        self.holding(side(hand).ok()?).map(|b| b.object)
    }

    fn grasp_attachment(&self, hand: usize) -> Option<AttachmentId> {
        self.grasps[side(hand).ok()?.index()].map(|g| g.attachment)
    }

    fn grasp_rules(&self) -> &GraspRules {
        &self.rules
    }

    fn posed_hand(&self, hand: usize) -> Option<Arc<dyn PosedHand>> {
        let side = side(hand).ok()?;
        Some(Arc::new(Palm {
            side,
            body: self.parts.body,
            target: self.hand_target(side),
            trigger: self.trigger(side),
        }))
    }

    fn camera_pose(&self, world: &World) -> Pose {
        self.eye_pose(world)
    }

    /// It has none in the original: a 16 × 360 scan all round (30° vertically) from its eye.
    fn lidar(&self, world: &World) -> LidarMount {
        LidarMount {
            pose: self.eye_pose(world),
            scan: Scan::AllRound {
                rows: 16,
                columns: 360,
                vertical_fov: 30f32.to_radians(),
            },
            min_range: 0.05,
            max_range: 25.0,
        }
    }

    /// The body is stopped where a palm's target with straight fingers would enter something
    /// fixed (`motion.rs`): those shapes go with the base.
    fn base_sweep(&self, world: &World) -> Vec<(Primitive, Pose)> {
        let (sweep, offset) = sweep_shape();
        let body = self.body_pose(world);
        Side::BOTH
            .map(|s| (sweep.clone(), body * self.hand_target(s) * offset))
            .to_vec()
    }

    fn teleport(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError> {
        self.place_at(world, pose)
    }

    fn grasp_now(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        self.grasp_now_in(world, side(hand)?, object)
    }

    fn grasp_touching(
        &mut self,
        world: &mut World,
        hand: usize,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        self.grasp_touching_in(world, side(hand)?, object)
    }

    fn reset_hand(&mut self, world: &mut World, hand: usize) -> Result<(), MagicError> {
        self.reset_palm(world, side(hand)?)
    }

    fn release_now(&mut self, world: &mut World, hand: usize) -> Option<ObjectId> {
        self.release_from(world, side(hand).ok()?)
    }
}

impl StepHooks for BehaviorRobot {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        if substep == 0 {
            self.begin_step(world);
        }
        self.move_parts(world, substep);
    }

    fn after_step(&mut self, world: &mut World) {
        self.update_grasps(world);
        if !self.releases.is_empty() {
            // Contacts come back after the release step, once apart, and not while held again.
            let (grasps, now) = (self.grasps, world.bodies().steps());
            let held = |body: BodyRef| grasps.iter().flatten().any(|g| g.body == body);
            self.releases
                .retain_mut(|r| held(r.body) || r.since == now || !r.settle(world));
        }
        if self.moved {
            self.press_with_hands(world);
        }
        self.follow_with_head(world);
    }
}

impl BehaviorRobot {
    /// Draws the head round the eye (the world keeps it only if it moved).
    fn follow_with_head(&self, world: &mut World) {
        let head = head_round(self.eye_pose(world));
        world.bodies_mut().set_ghost(self.parts.body, Some(head));
    }

    /// Tells the world where the palms and fingertips are, for buttons.
    fn press_with_hands(&self, world: &mut World) {
        let [l, r] = Side::BOTH.map(|s| HandPoints::pressing(world, self.parts.hand(s)));
        world.set_hand_points(&[l, r].concat());
    }

    /// Takes the pending action: the step's targets, checked against fixed bodies.
    fn begin_step(&mut self, world: &mut World) {
        let action = std::mem::take(&mut self.pending);
        let old = self.targets;
        let wanted = old.after(&action);
        if wanted != old {
            let own = self.parts.all();
            let blocker = Blocker {
                world,
                filter: QueryFilter {
                    fixed_only: true,
                    ..QueryFilter::excluding(&own)
                },
            };
            self.targets = blocker.allow(&old, wanted);
        }
        self.step_from = old.body;
        self.moved = false;
        for side in Side::BOTH {
            self.park_or_unpark(world, side);
        }
    }

    /// Parks a hand that rests at its target for the whole step (held to the body, so that it
    /// can sleep), and unparks one that must move or whose parking broke.
    fn park_or_unpark(&mut self, world: &mut World, side: Side) {
        let i = side.index();
        let palm = BodyRef::from(self.parts.hand(side));
        let still = self.step_from == self.targets.body
            && self.hands[i].rests_on(&self.targets.hand_in_world(side));
        match self.parked[i] {
            Some(id) => {
                let intact = world.attachments().get(id).is_some_and(|a| !a.broken);
                if !(still && intact) {
                    world.attachments_mut().detach(id);
                    self.parked[i] = None;
                }
            }
            None if still && settled(world, palm, &self.hands[i].pose) => self.park(world, side),
            None => {}
        }
    }

    /// Holds a hand to the body where it is.
    fn park(&mut self, world: &mut World, side: Side) {
        let palm = BodyRef::from(self.parts.hand(side));
        let spec = AttachmentSpec {
            holder: BodyRef::from(self.parts.body),
            held: palm,
            at: world.bodies().pose(palm.object).translation,
            kind: AttachmentKind::Fixed,
            max_force: PARKING_FORCE,
        };
        self.parked[side.index()] = world.attachments_mut().attach(spec).ok();
    }

    /// Moves the body and palms for one substep.
    fn move_parts(&mut self, world: &mut World, substep: u32) {
        let n = world.bodies().substeps().count();
        let body = if substep + 1 >= n {
            self.targets.body
        } else {
            let t = (substep + 1) as f32 / n as f32;
            self.step_from.lerp(&self.targets.body, t)
        };
        let dt = STEP_SECONDS / n as f32;
        if self.step_from != self.targets.body {
            // The velocity that lands the body on this substep's pose. A velocity-driven body
            // stopped with exactly zero velocity sleeps; a position-driven one turned by any
            // angle never does (rapier derives its velocity from rounded rotations).
            let now = world.bodies().pose(self.parts.body);
            let velocity = Velocity {
                linear: (body.translation - now.translation) / dt,
                angular: rotation_error(now.rotation, body.rotation) / dt,
            };
            // Finite poses make finite velocities: the world cannot refuse these.
            let _ = world
                .bodies_mut()
                .set_velocity(self.parts.body.into(), velocity);
            self.moved = true;
            self.body_moving = true;
        } else if self.body_moving {
            let _ = world
                .bodies_mut()
                .set_velocity(self.parts.body.into(), Velocity::default());
            self.body_moving = false;
        }
        for side in Side::BOTH {
            let i = side.index();
            let hand = (self.parts.hand(side), side);
            let fingers = self.finger_targets(side);
            if self.fingers[i].advance(world, hand, &fingers, dt) {
                self.moved = true;
            }
            if self.parked[i].is_some() {
                continue;
            }
            let target = body * self.targets.hands[i];
            self.hands[i].advance(&target, dt, &HAND_LIMITS);
            servo(world, self.parts.hand(side), &self.hands[i].pose, dt);
            self.moved = true;
        }
    }

    /// Where a hand's fingers are going: toward `trigger × closed`, or staying while it holds.
    fn finger_targets(&self, side: Side) -> [f32; FINGERS] {
        let i = side.index();
        match self.grasps[i] {
            Some(grasp) => grasp.fingers,
            None => Fingers::for_trigger(self.targets.triggers[i]),
        }
    }

    /// After a step: lets go where a grasp must end, grasps where a pressed hand finds something.
    fn update_grasps(&mut self, world: &mut World) {
        for side in Side::BOTH {
            let i = side.index();
            let trigger = self.targets.triggers[i];
            match self.grasps[i] {
                Some(grasp) if must_release(world, &grasp, trigger, &self.rules) => {
                    world.attachments_mut().detach(grasp.attachment);
                    self.grasps[i] = None;
                    self.releases.push(Release {
                        body: grasp.body,
                        parts: self.parts.all().to_vec(),
                        since: world.bodies().steps(),
                    });
                }
                None if trigger > self.rules.threshold => {
                    let own = self.parts.all();
                    let grasper = Grasper {
                        rules: &self.rules,
                        hand: self.parts.hand(side),
                        own: &own,
                        other_holds: self.holding(side.other()),
                        fingers: self.fingers[i].angles,
                    };
                    self.grasps[i] = grasper.try_grasp(world);
                }
                _ => {}
            }
        }
    }
}

/// Symbolic moves (see `magic.rs`).
impl BehaviorRobot {
    /// Puts the body at `pose`, the hands at their targets about it and what they hold with
    /// them, all at rest and the hands parked.
    fn place_at(&mut self, world: &mut World, pose: Pose) -> Result<(), MagicError> {
        if !pose_ok(&pose) {
            return Err(MagicError::BadPose);
        }
        let pose = Pose::from_parts(pose.translation, pose.rotation.normalize());
        for id in self.parked.iter_mut().filter_map(Option::take) {
            world.attachments_mut().detach(id);
        }
        // Where each hand is now, to carry what it holds along.
        let before = Side::BOTH.map(|s| self.hand_pose(world, s));
        world.bodies_mut().set_pose(self.parts.body, pose)?;
        self.targets.body = pose;
        self.step_from = pose;
        self.body_moving = false;
        for side in Side::BOTH {
            self.put_hand_at_target(world, side, before[side.index()])?;
        }
        self.press_with_hands(world);
        self.follow_with_head(world);
        Ok(())
    }

    /// Puts a palm at its target at once, at rest and parked, carrying what it holds from
    /// where the palm was (`before`).
    fn put_hand_at_target(
        &mut self,
        world: &mut World,
        side: Side,
        before: Pose,
    ) -> Result<(), MagicError> {
        let i = side.index();
        let target = self.targets.hand_in_world(side);
        world.bodies_mut().set_pose(self.parts.hand(side), target)?;
        self.hands[i] = Follower::at(target);
        if let Some(grasp) = self.grasps[i] {
            let held = grasp.body.object;
            let relative = before.inv_mul(&world.bodies().pose(held));
            world.bodies_mut().set_pose(held, target * relative)?;
        }
        self.park(world, side);
        Ok(())
    }

    /// The raw action's reset entry (iGibson 2.0.3's `robots/behavior_robot.py`, left out of the
    /// env's 26): the palm put at its target at once, with what it holds, at rest and parked. For a
    /// hand pinned behind furniture that its servo cannot pull free.
    fn reset_palm(&mut self, world: &mut World, side: Side) -> Result<(), MagicError> {
        if let Some(id) = self.parked[side.index()].take() {
            world.attachments_mut().detach(id);
        }
        let before = self.hand_pose(world, side);
        self.put_hand_at_target(world, side, before)?;
        self.press_with_hands(world);
        Ok(())
    }

    /// Puts `object` just under the palm of an empty hand, attaches it as a grasp does and
    /// presses the trigger.
    fn grasp_now_in(
        &mut self,
        world: &mut World,
        side: Side,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        let kind = self.may_hold(world, side, BodyRef::from(object))?;
        let palm = world.bodies().pose(self.parts.hand(side));
        // The palm faces its −z: the object's box goes just below it, touching.
        let aabb = world.bodies().aabb(object);
        let half = (aabb.maxs - aabb.mins) * 0.5;
        let below = palm.rotation * rapier3d::math::Vector::NEG_Z;
        let reach = (below * half).abs().element_sum() + 0.01;
        centre_on(world, object, palm.translation + below * reach)?;
        self.attach(world, side, BodyRef::from(object), kind, palm.translation)
    }

    /// Holds `object` where it is, if the hand touches it (the original's forced assisted
    /// grasp, which also asks for contact): the body it touches, a door or drawer of fixed
    /// furniture point to point, anything else as the rules hold the whole object.
    fn grasp_touching_in(
        &mut self,
        world: &mut World,
        side: Side,
        object: ObjectId,
    ) -> Result<(), MagicError> {
        let hand = self.parts.hand(side);
        let touched = world
            .contacts()
            .of(BodyRef::from(hand))?
            .iter()
            .filter_map(|c| c.other.filter(|b| b.object == object))
            .min()
            .ok_or(MagicError::NotTouching(object))?;
        let body = match touched.link {
            Some(_) if world.bodies().object(object).is_fixed() => touched,
            _ => BodyRef::from(object),
        };
        let kind = self.may_hold(world, side, body)?;
        let at = world
            .bodies()
            .pose(hand)
            .transform_point(crate::hand::PALM_CENTRE);
        self.attach(world, side, body, kind, at)
    }

    /// How the hand may hold `body` (an object or one of its links): it is empty, and the
    /// rules allow it.
    fn may_hold(
        &self,
        world: &World,
        side: Side,
        body: BodyRef,
    ) -> Result<AttachmentKind, MagicError> {
        if let Some(grasp) = self.grasps[side.index()] {
            return Err(MagicError::HandFull(grasp.body.object));
        }
        let other = self.holding(side.other()).map(|b| b.object);
        let own = self.parts.all();
        self.rules.kind_for(world, body, &own, other)
    }

    /// Attaches `body` to the hand at `at` as the assisted grasp does, and closes it.
    fn attach(
        &mut self,
        world: &mut World,
        side: Side,
        body: BodyRef,
        kind: AttachmentKind,
        at: Vector,
    ) -> Result<(), MagicError> {
        let i = side.index();
        let hand = self.parts.hand(side);
        let attachment = self.at_once().attach(world, hand, body, at, kind)?;
        self.targets.triggers[i] = 1.0;
        self.grasps[i] = Some(Grasp {
            body,
            attachment,
            fingers: self.fingers[i].angles,
        });
        Ok(())
    }

    /// Takes and lets go of things at once, as the assisted grasp does.
    fn at_once(&mut self) -> Hold<'_> {
        Hold {
            rules: &self.rules,
            own: self.parts.all().to_vec(),
            releases: &mut self.releases,
        }
    }

    /// Detaches what a hand holds and opens it.
    fn release_from(&mut self, world: &mut World, side: Side) -> Option<ObjectId> {
        let i = side.index();
        self.targets.triggers[i] = 0.0;
        let grasp = self.grasps[i].take()?;
        self.at_once().let_go(world, grasp.body, grasp.attachment);
        Some(grasp.body.object)
    }
}

/// A BehaviorRobot's palm as a [`PosedHand`]: a snapshot of its target and trigger.
#[derive(Clone, Copy, Debug)]
struct Palm {
    side: Side,
    body: ObjectId,
    target: Pose,
    trigger: f32,
}

impl Palm {
    /// An action of the full space with `values` (each divided by the action's scale and
    /// clipped) at `at`, everything else still.
    fn action(at: usize, values: &[f32]) -> Vec<f32> {
        let mut action = vec![0.0; ACTION_DIM];
        for (k, v) in values.iter().enumerate() {
            action[at + k] = (v / ACTION_SCALE).clamp(-1.0, 1.0);
        }
        action
    }
}

impl PosedHand for Palm {
    fn hand(&self) -> usize {
        self.side.index()
    }

    fn target(&self) -> Pose {
        self.target
    }

    fn shoulder(&self, world: &World) -> Vector {
        world
            .bodies()
            .pose(self.body)
            .transform_point(crate::body::shoulder(self.side))
    }

    fn reach(&self) -> f32 {
        HAND_REACH
    }

    fn step(&self) -> f32 {
        ACTION_SCALE
    }

    fn sweep(&self) -> (Primitive, Pose) {
        sweep_shape()
    }

    fn trigger(&self) -> f32 {
        self.trigger
    }

    /// Drawn in so that palm and fingers lie within the body's capsule (at rest the fingertips
    /// stick out 2 cm, and a door leaf the body pushes open caught them and left both palms
    /// behind at a doorway).
    fn tucked(&self) -> Pose {
        Pose::from_translation(Vector::new(-0.02, self.side.sign() * 0.1, 0.05))
    }

    fn move_action(&self, offset: [f32; 6]) -> Vec<f32> {
        Palm::action(Action::hand_range(self.side).start, &offset)
    }

    fn trigger_action(&self, press: f32) -> Vec<f32> {
        let mut action = vec![0.0; ACTION_DIM];
        action[Action::trigger_index(self.side)] = press;
        action
    }

    fn lift_action(&self, up: f32) -> Vec<f32> {
        Palm::action(Action::BODY.start + 2, &[up])
    }
}
