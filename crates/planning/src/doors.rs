//! OPEN and CLOSE by hand, the same for every manipulator that can hold a leaf on its hinge
//! ([`Manipulator::SWINGS_LEAVES`]: the BehaviorRobot's palms; Fetch's and the R1's arms,
//! moved kinematically, cannot). The hand is brought before a door, lid or drawer near its free
//! edge (its "handle": on its front, half way along the hinge and [`HANDLE_INSET`] in from the
//! edge away from it, or the middle of a drawer's front), pressed on until it touches, and
//! closed on it — the world's assisted grasp holds a leaf of fixed furniture point to point, so
//! the leaf turns about the hand — then moved along the leaf's own arc [`TURN_STEP`] at a time
//! (a drawer straight out), each move aimed from where the grasp's anchor on the leaf is now,
//! until the joint reaches its goal; then it lets go and comes back. The world's joints and the
//! grasp's force limit decide how far the leaf goes; the primitive judges by the state reached.
//! Where the hand cannot (no hand pose before the leaf, no free path, a full hand, a leaf that
//! jams, a movable box's lid), [`crate::run`] falls back to the kinematic setter, recorded as an
//! edit and marked on the outcome ([`crate::Outcome::set`]).

use crate::execute::Watcher;
use crate::manipulation::{Grip, Manipulator};
use crate::physical::{Attempt, Stepper, at_once, attempt, call_rng};
use crate::primitive::{Call, Failure, Primitive};
use crate::symbolic::{WIDE_OPEN, limited_links, resting_in, wide_open};
use crate::tools::{checked, judged};
use crate::tuning::Tuning;
use behavior_core::Predicate;
use behavior_core::rng::SimRng;
use behavior_env::Env;
use behavior_sim::{BodyRef, JointKind, OPEN_FRACTION, ObjectId, World};
use rapier3d::math::{Pose, Rotation, Vector};

/// How far in from the leaf's free edge the hand takes it, m: a pull's width.
const HANDLE_INSET: f32 = 0.05;
/// How far out from the leaf's front the hand's pressing point is brought first, m, nearest
/// first; it then presses in until it touches.
const GRIP_OUT: [f32; 3] = [0.05, 0.09, 0.13];
/// How far past the front the press in goes at most, m.
const PRESS_IN: f32 = 0.03;
/// A hinged leaf's turn per move of the hand, rad (10°).
const TURN_STEP: f32 = 0.175;
/// A drawer's travel per move of the hand, m.
const SLIDE_STEP: f32 = 0.05;
/// Moves at most per leaf: a door's 109° in 10° moves is 11; the rest make up for lag.
const MOVES: usize = 24;
/// Moves in a row that gain less than a tenth of a step before the leaf counts as jammed.
const STALLS: usize = 3;
/// How far a door, lid or drawer is opened by hand: past the planner's "wide open" (a hand
/// carrying a box into a fridge meets a door opened less).
const OPEN_TO: f32 = 0.97;

/// A door, lid or drawer to move, and the joint position to bring it to.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Leaf {
    link: usize,
    to: f32,
}

/// OPEN or CLOSE with physics: each of `call.object`'s leaves that must move ([`leaves`])
/// taken by hand `call.hand` and swung (or slid) to its goal. Done where the object ends wide
/// open (OPEN) or shut (CLOSE), whatever stopped the hand after.
pub(crate) fn swing_with<M: Manipulator>(
    hands: &M,
    env: &mut Env,
    call: &Call,
    tuning: &Tuning,
    watcher: Option<&mut dyn Watcher>,
) -> Attempt<()> {
    let hand = attempt!(at_once(checked(hands, env, call)));
    if !M::SWINGS_LEAVES {
        return Ok(Err(Failure::Unavailable(
            "an arm moved kinematically cannot hold a door on its hinge",
        )));
    }
    if let Some(held) = env.robot().and_then(|r| r.held(call.hand)) {
        let name = env.world().map(|w| w.bodies().object(held).name.clone());
        return Ok(Err(Failure::HandFull(name.unwrap_or_default())));
    }
    let opening = call.primitive == Primitive::Open;
    let Some(world) = env.world() else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    // A hand closed on a movable box's lid holds the box: its lid is set, as before.
    if !world.bodies().object(call.object).is_fixed() {
        return Ok(Err(Failure::Unavailable(
            "a movable object's lid is not swung by hand",
        )));
    }
    let robot = env.robot().map_or(Vec::new(), |r| r.objects());
    let leaves = leaves(world, call.object, opening, &robot);
    let object = call.object;
    let done = move |env: &Env| {
        env.world().is_some_and(|w| match opening {
            true => wide_open(w, object),
            false => !w.state(object, Predicate::Open),
        })
    };
    let mut rng = call_rng(env, call);
    let mut steps = Stepper {
        env,
        tuning,
        watcher,
    };
    let mut moves = Ok(());
    for leaf in leaves {
        if done(steps.env) {
            break;
        }
        moves = move_leaf(hands, &mut steps, hand, call, leaf, &mut rng)?;
        if moves.is_err() {
            break;
        }
    }
    let what = match opening {
        true => "the hand did not swing it wide open",
        false => "the hand did not shut it",
    };
    Ok(judged(done(steps.env), moves, what))
}

/// The leaves OPEN or CLOSE moves, with their goals: opening, every hinged door or lid not yet
/// wide open, and the drawers that hold something (else, with no door, the top drawer);
/// closing, every leaf not shut.
fn leaves(world: &World, object: ObjectId, opening: bool, robot: &[ObjectId]) -> Vec<Leaf> {
    let links = &world.bodies().object(object).links;
    let at = |link: usize| world.joints().position(object, link);
    let all = limited_links(world, object, None);
    if !opening {
        return all
            .into_iter()
            .filter(|&(link, [lo, hi])| at(link) - lo > 0.5 * OPEN_FRACTION * (hi - lo))
            .map(|(link, [lo, _])| Leaf { link, to: lo })
            .collect();
    }
    let open_to = |(link, [lo, hi]): (usize, [f32; 2])| Leaf {
        link,
        to: lo + OPEN_TO * (hi - lo),
    };
    let kind = |link: usize| links[link].joint.kind;
    let doors: Vec<Leaf> = all
        .iter()
        .filter(|&&(link, [lo, hi])| {
            kind(link) == JointKind::Revolute && at(link) - lo < WIDE_OPEN * (hi - lo)
        })
        .map(|&l| open_to(l))
        .collect();
    let drawers: Vec<(usize, [f32; 2])> = all
        .iter()
        .copied()
        .filter(|&(link, _)| kind(link) == JointKind::Prismatic)
        .collect();
    let mut full: Vec<Leaf> = drawers
        .iter()
        .filter(|&&(link, _)| !resting_in(world, object, link, robot).is_empty())
        .map(|&l| open_to(l))
        .collect();
    let any_open = world.state(object, Predicate::Open);
    if full.is_empty() && doors.is_empty() && !any_open {
        let top =
            |&(link, _): &(usize, [f32; 2])| world.bodies().link_local_aabb(object, link).maxs.z;
        full.extend(
            drawers
                .iter()
                .max_by(|a, b| top(a).total_cmp(&top(b)))
                .map(|&l| open_to(l)),
        );
    }
    let mut all = doors;
    all.extend(full);
    all
}

/// One leaf taken by the hand and moved to its goal, then let go; the hand brought back.
fn move_leaf<M: Manipulator>(
    hands: &M,
    steps: &mut Stepper<'_, '_>,
    hand: M::Hand,
    call: &Call,
    leaf: Leaf,
    rng: &mut SimRng,
) -> Attempt<()> {
    let Some((goals, inward)) = grip_goals(hands, steps.env, hand, call.object, leaf.link) else {
        return Ok(Err(Failure::Unavailable("no episode")));
    };
    let mut reached = attempt!(hands.reach(steps, hand, &goals, Grip::Open, rng));
    let (object, link) = (call.object, leaf.link);
    let touching = move |env: &Env| touches_leaf(env, object, link);
    let press = inward * (GRIP_OUT[GRIP_OUT.len() - 1] + PRESS_IN);
    attempt!(hands.slide(steps, hand, press, &mut reached, &touching));
    let grasp = Call {
        primitive: Primitive::Grasp,
        ..*call
    };
    hands.close(steps, &grasp)?;
    let pulled = match holds_leaf(steps.env, call.hand, object, link) {
        true => pull(hands, steps, hand, call, leaf, &mut reached)?,
        false => Err(Failure::Missed),
    };
    attempt!(hands.open(steps, hand));
    attempt!(hands.leave(steps, hand, &mut reached));
    // A hand that let go far out (a door swung against the next cabinet) and finds no way
    // back is drawn in as before a drive, rather than left where the next grasp plans from.
    if hands
        .come_back(steps, hand, Grip::Open, &mut reached)?
        .is_err()
    {
        attempt!(hands.tuck(steps));
    }
    Ok(pulled)
}

/// The leaf, held, moved toward its goal [`TURN_STEP`] (or [`SLIDE_STEP`]) at a time: each
/// move takes the grasp's anchor on the leaf where the joint's arc carries it, aimed from where
/// the hand's anchor is now (so that lag does not add up). Stops at the goal, when the hand
/// has let go, or when the leaf no longer follows.
fn pull<M: Manipulator>(
    hands: &M,
    steps: &mut Stepper<'_, '_>,
    hand: M::Hand,
    call: &Call,
    leaf: Leaf,
    reached: &mut M::Reached,
) -> Attempt<()> {
    let (object, link) = (call.object, leaf.link);
    let mut stalls = 0;
    for _ in 0..MOVES {
        let Some(world) = steps.env.world() else {
            break;
        };
        let now = world.joints().position(object, link);
        let joint = &world.bodies().object(object).links[link].joint;
        let step = match joint.kind {
            JointKind::Revolute => TURN_STEP,
            _ => SLIDE_STEP,
        };
        if (leaf.to - now).abs() < 0.2 * step {
            break;
        }
        let Some([hand_at, leaf_at]) = anchors(steps.env, call.hand) else {
            return Ok(Err(Failure::NoEffect("the hand let go of it")));
        };
        let body = world.bodies().pose(object);
        let (axis, anchor) = (
            body.rotation * joint.axis,
            body.transform_point(joint.anchor),
        );
        let by = (leaf.to - now).clamp(-step, step);
        let goal = match joint.kind {
            JointKind::Revolute => {
                anchor + Rotation::from_axis_angle(axis, by) * (leaf_at - anchor)
            }
            _ => leaf_at + axis * by,
        };
        attempt!(hands.slide(steps, hand, goal - hand_at, reached, &|_| false));
        let gained = steps.env.world().map_or(0.0, |w| {
            (w.joints().position(object, link) - now) * by.signum()
        });
        stalls = if gained < 0.1 * step { stalls + 1 } else { 0 };
        if stalls >= STALLS {
            break;
        }
    }
    Ok(Ok(()))
}

/// Where hand `hand`'s grasp is anchored now, the hand's point and the held body's.
fn anchors(env: &Env, hand: usize) -> Option<[Vector; 2]> {
    let (world, robot) = (env.world()?, env.robot()?);
    world.attachments().anchors(robot.grasp_attachment(hand)?)
}

/// Whether hand `hand` holds `object`'s link `link`.
fn holds_leaf(env: &Env, hand: usize, object: ObjectId, link: usize) -> bool {
    let held = BodyRef::link(object, link);
    env.world().zip(env.robot()).is_some_and(|(world, robot)| {
        robot
            .grasp_attachment(hand)
            .and_then(|id| world.attachments().get(id))
            .is_some_and(|a| a.spec.held == held && !a.broken)
    })
}

/// Whether any part of the robot touches `object`'s link `link`.
fn touches_leaf(env: &Env, object: ObjectId, link: usize) -> bool {
    env.world().zip(env.robot()).is_some_and(|(world, robot)| {
        let own = robot.objects();
        world
            .contacts()
            .of(BodyRef::link(object, link))
            .unwrap_or_default()
            .iter()
            .any(|c| c.other.is_some_and(|b| own.contains(&b.object)))
    })
}

/// Poses of the hand that put its pressing point [`GRIP_OUT`] before the leaf's handle
/// ([`handle`]), facing into it, nearest first; with the way into the leaf (in the world).
fn grip_goals<M: Manipulator>(
    hands: &M,
    env: &Env,
    hand: M::Hand,
    object: ObjectId,
    link: usize,
) -> Option<(Vec<Pose>, Vector)> {
    let (world, robot) = (env.world()?, env.robot()?);
    let (at, out) = handle(world, object, link)?;
    let base = robot.base_pose(world).translation;
    // Facing into a door's front; over a lid, the way from the robot to it.
    let ahead = match out.with_z(0.0).length() > 0.5 {
        true => -out,
        false => at - base,
    };
    let facing = ahead.y.atan2(ahead.x);
    let goals = GRIP_OUT
        .iter()
        .flat_map(|&gap| hands.press_goals(env, hand, at + out * gap, facing))
        .collect();
    Some((goals, -out))
}

/// A leaf's handle in the world now, and its front's outward normal: for a hinged leaf, on its
/// face away from the object's body (its thinnest side), in the middle along the hinge and
/// [`HANDLE_INSET`] in from the edge farthest from it; for a drawer, the middle of its front,
/// the face it slides out by.
fn handle(world: &World, object: ObjectId, link: usize) -> Option<(Vector, Vector)> {
    let bodies = world.bodies();
    let joint = &bodies.object(object).links.get(link)?.joint;
    let b = bodies.link_local_aabb(object, link);
    let (lo, hi) = (b.mins, b.maxs);
    let mut at = 0.5 * (lo + hi);
    let along = largest(joint.axis.abs());
    let mut out = Vector::ZERO;
    match joint.kind {
        JointKind::Revolute => {
            let size = hi - lo;
            let front = (0..3)
                .filter(|&i| i != along)
                .min_by(|&i, &j| size[i].total_cmp(&size[j]))?;
            let edge = (0..3).find(|&i| i != along && i != front)?;
            let body = bodies.local_aabb(object).center();
            let outward = if at[front] >= body[front] { 1.0 } else { -1.0 };
            at[front] = if outward > 0.0 { hi[front] } else { lo[front] };
            out[front] = outward;
            let far =
                if (hi[edge] - joint.anchor[edge]).abs() >= (lo[edge] - joint.anchor[edge]).abs() {
                    hi[edge] - HANDLE_INSET.min(0.5 * size[edge])
                } else {
                    lo[edge] + HANDLE_INSET.min(0.5 * size[edge])
                };
            at[edge] = far;
        }
        JointKind::Prismatic => {
            let sign = joint.axis[along].signum();
            at[along] = if sign > 0.0 { hi[along] } else { lo[along] };
            out[along] = sign;
        }
        _ => return None,
    }
    let pose = bodies.link_pose(object, link);
    Some((pose.transform_point(at), pose.rotation * out))
}

/// The index of a vector's largest coordinate.
fn largest(v: Vector) -> usize {
    (0..3).max_by(|&i, &j| v[i].total_cmp(&v[j])).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_core::Ability;
    use behavior_sim::{JointSpec, LinkSpec, ObjectSpec, Part, Primitive as Shape};
    use std::f32::consts::FRAC_PI_2;

    fn v(x: f32, y: f32, z: f32) -> Vector {
        Vector::new(x, y, z)
    }

    /// A box part spanning `lo..hi`.
    fn span(lo: Vector, hi: Vector) -> Part {
        let shape = Shape::Box {
            half_extents: 0.5 * (hi - lo),
        };
        Part::at(shape, 0.5 * (lo + hi))
    }

    fn leaf(name: &str, part: Part, joint: JointSpec) -> LinkSpec {
        LinkSpec {
            name: name.into(),
            parts: vec![part],
            parent: None,
            joint,
            density: 400.0,
        }
    }

    /// A fixed cabinet 0.5 × 0.4 × 0.8 m at the origin, its front at y = −0.2, with a door
    /// 2 cm thick hinged on its left edge (x = −0.25, opening to −y) and a drawer beside it.
    fn cabinet(world: &mut World) -> ObjectId {
        let door = leaf(
            "door",
            span(v(-0.25, -0.22, 0.0), v(0.25, -0.2, 0.8)),
            JointSpec::opening(
                JointKind::Revolute,
                v(-0.25, -0.22, 0.0),
                v(0.0, 0.0, -1.0),
                1.9,
                2.0,
            ),
        );
        let drawer = leaf(
            "drawer",
            span(v(0.3, -0.22, 0.6), v(0.7, 0.2, 0.8)),
            JointSpec::opening(
                JointKind::Prismatic,
                Vector::ZERO,
                v(0.0, -1.0, 0.0),
                0.3,
                2.0,
            ),
        );
        let body = span(v(-0.25, -0.2, 0.0), v(0.7, 0.2, 0.8));
        let spec = ObjectSpec::new("cabinet_1", "cabinet.n.01", vec![body])
            .fixed()
            .ability(Ability::Openable, &[])
            .link(door)
            .link(drawer);
        world.add(spec).unwrap()
    }

    fn near(a: Vector, b: Vector) -> bool {
        (a - b).length() < 1e-4
    }

    #[test]
    fn a_door_is_taken_on_its_front_by_the_edge_away_from_its_hinge() {
        let mut world = World::default();
        let cabinet = cabinet(&mut world);
        let (at, out) = handle(&world, cabinet, 0).unwrap();
        // Mid-height, 5 cm in from the free edge (x = 0.25), on the front face.
        assert!(near(at, v(0.2, -0.22, 0.4)), "{at:?}");
        assert!(near(out, v(0.0, -1.0, 0.0)), "{out:?}");
        // Swung a quarter turn open, the handle has gone round with it, 45 cm out in front of
        // the hinge, the door's outer face now toward the hinge's side.
        world
            .joints_mut()
            .set_position(cabinet, 0, FRAC_PI_2)
            .unwrap();
        let (at, out) = handle(&world, cabinet, 0).unwrap();
        assert!(near(at, v(-0.25, -0.67, 0.4)), "{at:?}");
        assert!(near(out, v(-1.0, 0.0, 0.0)), "{out:?}");
    }

    #[test]
    fn a_drawer_is_taken_by_the_middle_of_its_front() {
        let mut world = World::default();
        let cabinet = cabinet(&mut world);
        let (at, out) = handle(&world, cabinet, 1).unwrap();
        assert!(near(at, v(0.5, -0.22, 0.7)), "{at:?}");
        assert!(near(out, v(0.0, -1.0, 0.0)), "{out:?}");
    }

    #[test]
    fn opening_moves_the_shut_door_and_closing_every_leaf_not_shut() {
        let mut world = World::default();
        let cabinet = cabinet(&mut world);
        // Opening: the door, to 97 % of its swing; the empty drawer stays (a door opens it).
        let open = leaves(&world, cabinet, true, &[]);
        assert_eq!(
            open,
            vec![Leaf {
                link: 0,
                to: OPEN_TO * 1.9
            }]
        );
        // Nothing to close while all is shut; once both are open, both.
        assert!(leaves(&world, cabinet, false, &[]).is_empty());
        world.joints_mut().set_position(cabinet, 0, 1.0).unwrap();
        world.joints_mut().set_position(cabinet, 1, 0.2).unwrap();
        let shut = leaves(&world, cabinet, false, &[]);
        assert_eq!(
            shut,
            vec![Leaf { link: 0, to: 0.0 }, Leaf { link: 1, to: 0.0 }]
        );
        // Open past nine tenths, the door is left as it is.
        world.joints_mut().set_position(cabinet, 0, 1.8).unwrap();
        assert!(leaves(&world, cabinet, true, &[]).is_empty());
    }
}
