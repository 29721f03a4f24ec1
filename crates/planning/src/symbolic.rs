//! Symbolic ("magic") primitives: the feasibility checks of iGibson 2.0.3's
//! `envs/behavior_mp_env.py`, then the outcome set at once — the robot teleported, the object put
//! in the hand, placed by the world's sampler, joints opened, states set.

use crate::primitive::{Call, Failure, Primitive};
use behavior_core::rng::{SimRng, seeded, uniform};
use behavior_core::{Ability, FLOOR_SYNSET, Predicate};
use behavior_env::Edit;
use behavior_motion::BaseConfig;
use behavior_motion::{Standing, floor_gap};
use behavior_robots::{MagicError, REACH_DISTANCE, Robot};
use behavior_sim::{BodyRef, JointKind, ObjectId, PointKind, Relation, SUPPORT_COS, World};
use rapier3d::math::{Pose, Rotation, Vector};

/// Random points tried in a room for standing on its floor (the original's 60).
const FLOOR_STAND_TRIES: usize = 60;
/// Placements tried on a heat or cold source to land near one of its elements (as
/// OmniGibson's PLACE_NEAR_HEATING_ELEMENT).
const ELEMENT_TRIES: usize = 10;

/// Checks a primitive's preconditions in the world as it is, without changing anything (the
/// action mask). What only doing it can tell — a place to stand, a pose for the placement — is
/// not checked.
pub fn check(world: &World, robot: &Robot, call: &Call) -> Result<(), Failure> {
    let object = world.bodies().object(call.object);
    if !object.is_present() {
        return Err(Failure::Unable {
            what: "is gone (sliced, or taken out of the world)",
        });
    }
    if call.primitive.uses_hand() && call.hand >= robot.hands() {
        return Err(Failure::NoHand(call.hand));
    }
    let held = robot.held(call.hand);
    let reach = || {
        if within_reach(world, robot, call.object) {
            Ok(())
        } else {
            Err(Failure::Unreachable)
        }
    };
    let has = |id: ObjectId, ability| world.bodies().object(id).has(ability);
    let tool = |ability, what| match held {
        None => Err(Failure::HandEmpty),
        Some(h) if has(h, ability) => Ok(h),
        Some(_) => Err(Failure::WrongTool { what }),
    };
    match call.primitive {
        Primitive::NavigateTo | Primitive::Wait => Ok(()),
        Primitive::Grasp => {
            if let Some(h) = held {
                return Err(Failure::HandFull(world.bodies().object(h).name.clone()));
            }
            graspable(world, robot, call.object)?;
            reach()?;
            match closed_container(world, call.object) {
                Some(c) => Err(Failure::ContainerClosed(
                    world.bodies().object(c).name.clone(),
                )),
                None => Ok(()),
            }
        }
        p @ (Primitive::PlaceOnTop
        | Primitive::PlaceInside
        | Primitive::PlaceNextTo
        | Primitive::PlaceUnder
        | Primitive::PlaceOnFloor) => {
            let h = held.ok_or(Failure::HandEmpty)?;
            if h == call.object {
                return Err(Failure::SameObject);
            }
            let floor = object.category == FLOOR_SYNSET;
            if (p == Primitive::PlaceOnFloor) != floor {
                let what = if floor {
                    "is a floor"
                } else {
                    "is not a floor"
                };
                return Err(Failure::Unable { what });
            }
            if p == Primitive::PlaceInside && is_closed(world, call.object) {
                return Err(Failure::ContainerClosed(object.name.clone()));
            }
            if floor { Ok(()) } else { reach() }
        }
        Primitive::Open | Primitive::Close => {
            let switch = Switch {
                ability: Ability::Openable,
                predicate: Predicate::Open,
                lacks: "is not openable",
                states: ("open", "closed"),
            };
            if call.primitive == Primitive::Open && switch.has(world, call.object)? {
                // Open, its doors not all the way: OPEN swings them open.
                if wide_open(world, call.object) {
                    return Err(Failure::Already("open"));
                }
            } else {
                switch.check(world, call.object, call.primitive == Primitive::Open)?;
            }
            reach()
        }
        Primitive::ToggleOn | Primitive::ToggleOff => {
            let switch = Switch {
                ability: Ability::Toggleable,
                predicate: Predicate::ToggledOn,
                lacks: "is not toggleable",
                states: ("on", "off"),
            };
            switch.check(world, call.object, call.primitive == Primitive::ToggleOn)?;
            reach()
        }
        Primitive::Slice => {
            tool(Ability::Slicer, "is not a slicer")?;
            if !object.has(Ability::Sliceable) {
                return Err(Failure::Unable {
                    what: "is not sliceable",
                });
            }
            reach()
        }
        Primitive::Wipe => {
            let t = tool(Ability::CleaningTool, "is not a cleaning tool")?;
            let dusty = world.state(call.object, Predicate::Dusty);
            let stained = world.state(call.object, Predicate::Stained);
            if !dusty && !stained {
                return Err(Failure::Already("clean"));
            }
            if !dusty && !world.state(t, Predicate::Soaked) {
                return Err(Failure::WrongTool {
                    what: "is not soaked (stains need water)",
                });
            }
            reach()
        }
        Primitive::Soak => {
            tool(Ability::Soakable, "does not soak")?;
            if !object.has(Ability::WaterSource) {
                return Err(Failure::Unable {
                    what: "is not a water source",
                });
            }
            if object.has(Ability::Toggleable) && !world.state(call.object, Predicate::ToggledOn) {
                return Err(Failure::WaterOff);
            }
            reach()
        }
    }
}

/// A state a primitive turns on or off (`open`, `toggled_on`), and how its checks say so.
struct Switch {
    ability: Ability,
    predicate: Predicate,
    /// Why an object without the ability cannot be switched.
    lacks: &'static str,
    /// The state's words when on and off.
    states: (&'static str, &'static str),
}

impl Switch {
    /// Whether `object` has the ability and is on: an error if it lacks the ability.
    fn has(&self, world: &World, object: ObjectId) -> Result<bool, Failure> {
        if !world.bodies().object(object).has(self.ability) {
            return Err(Failure::Unable { what: self.lacks });
        }
        Ok(world.state(object, self.predicate))
    }

    /// Whether `object` can be switched to `on`: it has the ability and is not so already.
    fn check(&self, world: &World, object: ObjectId, on: bool) -> Result<(), Failure> {
        match (on, self.has(world, object)?) {
            (true, true) => Err(Failure::Already(self.states.0)),
            (false, false) => Err(Failure::Already(self.states.1)),
            _ => Ok(()),
        }
    }
}

/// Checks a primitive, then sets its outcome. On failure nothing changed.
pub fn apply(edit: Edit<'_>, call: &Call) -> Result<(), Failure> {
    check(edit.world, edit.robot, call)?;
    let mut rng = seeded(call_seed(edit.seed, edit.steps, call));
    let (world, robot) = (edit.world, edit.robot);
    let object = call.object;
    match call.primitive {
        Primitive::NavigateTo => navigate(world, robot, object, &mut rng),
        Primitive::Grasp => match robot.grasp_now(world, call.hand, object) {
            Err(MagicError::NotHoldable(_)) => Err(Failure::NotGraspable(
                "too heavy for the grasp rules, or held by the other hand",
            )),
            other => Ok(other?),
        },
        Primitive::Open => open_wide(world, object, &robot.objects()),
        Primitive::Close => shut(world, object, &robot.objects()),
        Primitive::ToggleOn => set(world, object, call.primitive, true),
        Primitive::ToggleOff => set(world, object, call.primitive, false),
        Primitive::Slice => Ok(world.set_state(object, Predicate::Sliced, true)?),
        Primitive::Wipe => {
            let tool_soaked = robot
                .held(call.hand)
                .is_some_and(|t| world.state(t, Predicate::Soaked));
            if world.state(object, Predicate::Dusty) {
                world.set_state(object, Predicate::Dusty, false)?;
            }
            if tool_soaked && world.state(object, Predicate::Stained) {
                world.set_state(object, Predicate::Stained, false)?;
            }
            Ok(())
        }
        Primitive::Soak => {
            let held = robot.held(call.hand).ok_or(Failure::HandEmpty)?;
            Ok(world.set_state(held, Predicate::Soaked, true)?)
        }
        Primitive::Wait => Ok(()),
        p @ (Primitive::PlaceOnTop
        | Primitive::PlaceInside
        | Primitive::PlaceNextTo
        | Primitive::PlaceUnder
        | Primitive::PlaceOnFloor) => {
            let relation = p.relation().ok_or(Failure::Unavailable("placement"))?;
            place(world, robot, call, relation, &mut rng)
        }
    }
}

/// A call's own random numbers: the same episode, step and call draw the same.
pub(crate) fn call_seed(seed: u64, steps: u32, call: &Call) -> u64 {
    let primitive = Primitive::ALL
        .iter()
        .position(|p| *p == call.primitive)
        .unwrap_or(0);
    let mix = (u64::from(steps) << 32)
        ^ (u64::from(call.object.0) << 8)
        ^ ((primitive as u64) << 2)
        ^ call.hand as u64;
    seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ mix
}

fn set(
    world: &mut World,
    object: ObjectId,
    primitive: Primitive,
    value: bool,
) -> Result<(), Failure> {
    let predicate = match primitive {
        Primitive::Open | Primitive::Close => Predicate::Open,
        _ => Predicate::ToggledOn,
    };
    Ok(world.set_state(object, predicate, value)?)
}

/// How far along its range a door or lid must be to count as opened all the way by OPEN
/// (a door pushed back a little by what the robot did since still counts). 65 %, not 90 %: a
/// cabinet door that meets the refrigerator beside it at 70 % was set open again and again,
/// pushed back each time, and a hand swinging it stopped there.
pub(crate) const WIDE_OPEN: f32 = 0.65;

/// The object's jointed parts with limits and their ranges, of `kind` if given: the hinged
/// doors and lids OPEN swings all the way, or every part of a room's door.
pub(crate) fn limited_links(
    world: &World,
    object: ObjectId,
    kind: Option<JointKind>,
) -> Vec<(usize, [f32; 2])> {
    let links = world.bodies().object(object).links.iter().enumerate();
    links
        .filter(|(_, link)| kind.is_none_or(|k| link.joint.kind == k))
        .filter_map(|(i, link)| Some((i, link.joint.limits?)))
        .collect()
}

/// The object's hinged doors and lids with their ranges: what OPEN swings all the way.
fn hinges(world: &World, object: ObjectId) -> Vec<(usize, [f32; 2])> {
    limited_links(world, object, Some(JointKind::Revolute))
}

/// Sets each of the object's `links` to its open end.
pub(crate) fn open_all_the_way(world: &mut World, object: ObjectId, links: &[(usize, [f32; 2])]) {
    for &(link, [_, hi]) in links {
        // The link exists and the position is finite: this cannot fail.
        let _ = world.joints_mut().set_position(object, link, hi);
    }
}

/// Whether the object is open and each of its doors and lids is open all the way (see
/// [`WIDE_OPEN`]).
pub(crate) fn wide_open(world: &World, object: ObjectId) -> bool {
    world.state(object, Predicate::Open)
        && hinges(world, object).iter().all(|&(link, [lo, hi])| {
            world.joints().position(object, link) - lo >= WIDE_OPEN * (hi - lo)
        })
}

/// The movable things that one of the object's drawers (`link`) holds up — its normal at a
/// contact within 45° of up, as `ontop`'s support ([`SUPPORT_COS`]) — the robot's parts
/// (`robot`) aside.
pub(crate) fn resting_in(
    world: &World,
    object: ObjectId,
    link: usize,
    robot: &[ObjectId],
) -> Vec<ObjectId> {
    let drawer = BodyRef {
        object,
        link: Some(link),
    };
    let mut riders: Vec<ObjectId> = world
        .contacts()
        .of(drawer)
        .unwrap_or_default()
        .iter()
        .filter(|c| c.normal.z >= SUPPORT_COS)
        .filter_map(|c| c.other.map(|b| b.object))
        .filter(|&o| o != object && !robot.contains(&o) && !world.bodies().object(o).is_fixed())
        .collect();
    riders.sort();
    riders.dedup();
    riders
}

/// A drawer's contents and where the drawer was: [`carry_contents`] moves them as it moved.
struct Contents {
    link: usize,
    was: Pose,
    riders: Vec<ObjectId>,
}

/// What rests in each of the object's drawers, with each drawer's pose.
fn contents(world: &World, object: ObjectId, robot: &[ObjectId]) -> Vec<Contents> {
    limited_links(world, object, Some(JointKind::Prismatic))
        .into_iter()
        .map(|(link, _)| Contents {
            link,
            was: world.bodies().link_pose(object, link),
            riders: resting_in(world, object, link, robot),
        })
        .filter(|c| !c.riders.is_empty())
        .collect()
}

/// Moves each drawer's contents by the drawer's motion since [`contents`] was taken. Setting a
/// joint moves only the link: pulled out, a drawer left its necklace hanging over the
/// carcass, and it fell to the cabinet's floor, out of every hand's reach.
fn carry_contents(world: &mut World, object: ObjectId, contents: &[Contents]) {
    for c in contents {
        let moved = world.bodies().link_pose(object, c.link) * c.was.inverse();
        for &rider in &c.riders {
            let at = moved * world.bodies().pose(rider);
            // A finite pose moved by a finite one: the teleport cannot fail.
            let _ = world.bodies_mut().set_pose(rider, at);
        }
    }
}

/// OPEN's outcome: the object opened as the world's setter opens it (a random non-empty subset
/// of its joints, as the original's `Open.set_value(True)`, iGibson 2.0.3's
/// `envs/behavior_mp_env.py`) where it is shut, what lies in a drawer carried with it
/// ([`carry_contents`]), then each of its doors and lids swung all the way. A fridge door opened a
/// tenth of its swing reads as open, and a hand carrying a box into the fridge meets the door.
/// Drawers keep the setter's subset: pulled all the way, an upper drawer covers the one below it.
fn open_wide(world: &mut World, object: ObjectId, robot: &[ObjectId]) -> Result<(), Failure> {
    let contents = contents(world, object, robot);
    if !world.state(object, Predicate::Open) {
        world.set_state(object, Predicate::Open, true)?;
    }
    carry_contents(world, object, &contents);
    let hinges = hinges(world, object);
    open_all_the_way(world, object, &hinges);
    Ok(())
}

/// CLOSE's outcome: every joint shut by the world's setter, what lies in a drawer carried in
/// with it (left where the drawer was, it would fall to the floor).
fn shut(world: &mut World, object: ObjectId, robot: &[ObjectId]) -> Result<(), Failure> {
    let contents = contents(world, object, robot);
    set(world, object, Primitive::Close, false)?;
    carry_contents(world, object, &contents);
    Ok(())
}

/// Whether a hand may hold the object: movable and not the robot's (the grasp rules' mass
/// limit is checked as it grasps). The original also refuses a box over 0.2³ m³, sized for its
/// own models; ours are sized as real objects, and that check would refuse a quarter of the
/// activities' cartons, backpacks, brooms and boards, so we leave it to the mass limit.
fn graspable(world: &World, robot: &Robot, object: ObjectId) -> Result<(), Failure> {
    if world.bodies().object(object).is_fixed() {
        return Err(Failure::NotGraspable("it is fixed"));
    }
    if robot.objects().contains(&object) {
        return Err(Failure::NotGraspable("it is the robot's"));
    }
    Ok(())
}

/// Whether the object's box comes within [`REACH_DISTANCE`] of the robot's base, measured
/// across the floor: the primitives' reach. The `in reach` predicate measures to the centre in
/// 3-D from the base's origin, which is a BehaviorRobot's body centre but Fetch's point on
/// the floor; a primitive acts on the near side of a bed or a pool, and on a high shelf.
pub fn within_reach(world: &World, robot: &Robot, object: ObjectId) -> bool {
    within(world, robot, object, REACH_DISTANCE)
}

/// Whether the object's box comes within `distance` of the robot's base, across the floor.
pub(crate) fn within(world: &World, robot: &Robot, object: ObjectId, distance: f32) -> bool {
    let at = robot.base_pose(world).translation;
    let b = world.bodies().aabb(object);
    floor_gap([b.mins.x, b.mins.y], [b.maxs.x, b.maxs.y], at.x, at.y) <= distance
}

/// Whether an openable object is closed.
fn is_closed(world: &World, object: ObjectId) -> bool {
    world.bodies().object(object).has(Ability::Openable) && !world.state(object, Predicate::Open)
}

/// A closed openable object the object is inside, if any.
fn closed_container(world: &World, object: ObjectId) -> Option<ObjectId> {
    container_where(world, object, |c| !world.state(c, Predicate::Open))
}

/// An openable object the object is inside for which `shut` holds, if any.
pub(crate) fn container_where(
    world: &World,
    object: ObjectId,
    shut: impl Fn(ObjectId) -> bool,
) -> Option<ObjectId> {
    world
        .bodies()
        .objects()
        .filter(|(id, o)| *id != object && o.is_present() && o.has(Ability::Openable))
        .map(|(id, _)| id)
        .find(|&c| shut(c) && world.relations().inside(object, c))
}

/// NAVIGATE_TO: a place to stand facing the object (§5's search), or for a floor a clear
/// point of its room; the robot teleported there. Where no clear place sees the object (a
/// sink's centre lies below its counter's top), the first clear place within reach of its box.
fn navigate(
    world: &mut World,
    robot: &mut Robot,
    object: ObjectId,
    rng: &mut SimRng,
) -> Result<(), Failure> {
    let standing = Standing::of(world, robot);
    let config = stand_for(
        world,
        &standing,
        object,
        REACH_DISTANCE,
        None,
        &|_| true,
        rng,
    )
    .ok_or(Failure::NoPlaceToStand)?;
    let z = robot.base_pose(world).translation.z;
    let pose = Pose::from_parts(
        Vector::new(config.x, config.y, z),
        Rotation::from_rotation_z(config.yaw),
    );
    Ok(robot.teleport(world, pose)?)
}

/// Where NAVIGATE_TO stands for `object`: facing it and seeing it within `reach` of it (the
/// mode's reach), else clear within that reach, else seeing it from farther; for a floor, a
/// clear place in its room. Given an `arm` test (physical mode: a hand reaches the object
/// from there), the places within reach that pass it come first. Only places that `only`
/// accepts are taken at all (physical mode: those a base path can reach).
pub(crate) fn stand_for(
    world: &World,
    standing: &Standing,
    object: ObjectId,
    reach: f32,
    arm: Option<&dyn Fn(&BaseConfig) -> bool>,
    only: &dyn Fn(&BaseConfig) -> bool,
    rng: &mut SimRng,
) -> Option<BaseConfig> {
    if world.bodies().object(object).category == FLOOR_SYNSET {
        return stand_in_room(world, standing, object, only, rng);
    }
    let within = |accept: &dyn Fn(&BaseConfig) -> bool, rng: &mut SimRng| {
        let accept = |c: &BaseConfig| only(c) && accept(c);
        standing
            .near_within(world, object, reach, &accept, rng)
            .or_else(|| standing.within(world, object, reach, &accept, rng))
    };
    arm.and_then(|arm| within(arm, rng))
        .or_else(|| within(&|_| true, rng))
        .or_else(|| standing.near_where(world, object, only, rng))
}

/// A clear place in the room whose floor is `floor`, facing a random way.
fn stand_in_room(
    world: &World,
    standing: &Standing,
    floor: ObjectId,
    only: &dyn Fn(&BaseConfig) -> bool,
    rng: &mut SimRng,
) -> Option<BaseConfig> {
    let room = world.rooms().iter().find(|r| r.floor == Some(floor))?;
    (0..FLOOR_STAND_TRIES).find_map(|_| {
        // In the box around an L-shaped room; a point in its notch is drawn again.
        let b = room.bounds();
        let x = uniform(rng, b.min[0], b.max[0]);
        let y = uniform(rng, b.min[1], b.max[1]);
        let c = BaseConfig::new(
            x,
            y,
            uniform(rng, -std::f32::consts::PI, std::f32::consts::PI),
        );
        (room.contains(x, y) && standing.clear_at(world, &c) && only(&c)).then_some(c)
    })
}

/// PLACE_*: lets go of what the hand holds and places it by the world's sampler; on failure
/// the world and the robot are as before.
fn place(
    world: &mut World,
    robot: &mut Robot,
    call: &Call,
    relation: Relation,
    rng: &mut SimRng,
) -> Result<(), Failure> {
    let before = (world.snapshot(), robot.clone());
    let held = robot
        .release_now(world, call.hand)
        .ok_or(Failure::HandEmpty)?;
    if let Err(e) = put(world, held, call.object, relation, rng) {
        world.restore(&before.0);
        *robot = before.1;
        return Err(e);
    }
    Ok(())
}

/// Places `held` (let go of) in `relation` to `target` by the world's sampler: on a stove, up
/// to [`ELEMENT_TRIES`] poses until one lands near a heating element. On failure the world may
/// have changed.
pub(crate) fn put(
    world: &mut World,
    held: ObjectId,
    target: ObjectId,
    relation: Relation,
    rng: &mut SimRng,
) -> Result<(), Failure> {
    let tries = if relation == Relation::OnTop && has_elements(world, target) {
        ELEMENT_TRIES
    } else {
        1
    };
    for _ in 0..tries {
        world.place_turning(held, &[(relation, target)], rng)?;
        if near_element(world, held, target) {
            break;
        }
    }
    Ok(())
}

/// Whether a heat or cold source heats from elements (a stove), not from inside (an oven).
fn has_elements(world: &World, object: ObjectId) -> bool {
    let o = world.bodies().object(object);
    (o.has(Ability::HeatSource) || o.has(Ability::ColdSource))
        && o.points
            .iter()
            .any(|(k, _)| *k == PointKind::HeatingElement)
}

/// Whether `object`'s centre lies within the source's reach of one of its elements (or the
/// source has none).
fn near_element(world: &World, object: ObjectId, source: ObjectId) -> bool {
    let s = world.bodies().object(source);
    let Some(ability) = [Ability::HeatSource, Ability::ColdSource]
        .into_iter()
        .find(|&a| s.has(a))
    else {
        return true;
    };
    let reach = s.param(
        ability,
        "distance_threshold",
        behavior_sim::DEFAULT_DISTANCE_THRESHOLD,
    );
    let pose = world.bodies().pose(source);
    let centre = world.bodies().aabb(object).center();
    let mut elements = s
        .points
        .iter()
        .filter(|(k, _)| *k == PointKind::HeatingElement)
        .peekable();
    elements.peek().is_none()
        || elements.any(|(_, p)| (centre - pose.transform_point(*p)).length() <= reach)
}
