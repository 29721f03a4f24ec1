//! Settling: the placed things are dropped into the home together and simulated until all rest;
//! those that ended up elsewhere (a ball rolled off a table) or never stop (a fruit rolling about
//! the fridge) are dropped. Then the home is built as a scene file would build it, the clutter
//! asleep at the settled poses, and stepped: a thing that wakes or moves by a bit is dropped too.
//! Rounds repeat until one drops nothing (a dropped thing may have held others up), so what a
//! scene file holds is at rest, asleep, as built.

use super::ClutterError;
use super::rules::Spot;
use super::scatter::Placed;
use crate::library::Library;
use crate::scene::{BuiltScene, Scene, add_clutter};
use behavior_sim::{ObjectId, World};

/// Steps (5 s) the placed things get to come to rest, from 2 mm above their supports: most rest
/// within one. A thing still moving after that (an upright cylinder that keeps rocking) is
/// dropped: it would never sleep.
const SETTLE_STEPS: usize = 150;
/// Steps (1 s) a rebuilt home is watched for clutter that wakes or moves: twice the time at rest
/// a woken body needs to fall asleep again (0.5 s), so one woken by its first contacts and not
/// put back to sleep at once would show.
const WATCH_STEPS: usize = 30;
/// Below this speed (m/s) and spin (rad/s) an awake thing counts as resting: far below the
/// speeds of a rolling fruit or a rocking bottle, which never sleep.
const RESTING_SPEED: f32 = 1e-3;
const RESTING_SPIN: f32 = 1e-2;
/// Rounds of settling and watching before giving up; a named home needs two or three.
const ROUNDS: usize = 8;

/// Settles the placed things (see the module docs); those that stay, at their settled poses.
pub(super) fn settle(
    home: &Scene,
    library: &Library,
    mut placed: Vec<Placed>,
) -> Result<Vec<Placed>, ClutterError> {
    for _ in 0..ROUNDS {
        let rested = rest(home, library, &mut placed)?;
        let before = placed.len();
        retain(&mut placed, &rested);
        let steady = watch(home, library, &placed)?;
        retain(&mut placed, &steady);
        if placed.len() == before {
            return Ok(placed);
        }
    }
    Err(ClutterError::Unsettled)
}

/// Simulates the home with the placed things awake until everything rests; records where each
/// came to rest and says which are at rest where their rule put them.
fn rest(home: &Scene, library: &Library, placed: &mut [Placed]) -> Result<Vec<bool>, ClutterError> {
    let mut built = home.build(library)?;
    built.clutter = placed
        .iter()
        .map(|p| add_clutter(&mut built.world, &p.plan, library, false))
        .collect::<Result<_, _>>()?;
    built.world.settle(SETTLE_STEPS);
    let mut kept = Vec::with_capacity(placed.len());
    for (item, &id) in placed.iter_mut().zip(&built.clutter) {
        let pose = built.world.bodies().pose(id);
        item.plan.position = pose.translation.to_array();
        item.plan.rotation = pose.rotation.to_array();
        kept.push(at_rest(&built.world, id) && still_there(&built, item, id));
    }
    Ok(kept)
}

/// Asleep, or so slow that only a neighbour still moving keeps it awake (a pile sleeps as a
/// whole): it is kept, and the next round settles it again without what kept it awake.
fn at_rest(world: &World, id: ObjectId) -> bool {
    world.bodies().is_sleeping(id)
        || world
            .bodies()
            .velocity(id.into())
            .is_ok_and(|v| v.linear.length() < RESTING_SPEED && v.angular.length() < RESTING_SPIN)
}

/// Whether a thing is still on, in or beside its furniture.
fn still_there(built: &BuiltScene, item: &Placed, id: ObjectId) -> bool {
    let relations = built.world.relations();
    let furniture = built.objects[item.furniture];
    match item.spot {
        Spot::On => relations.ontop(id, furniture),
        Spot::In => relations.inside(id, furniture),
        Spot::Beside => {
            relations.nextto(id, furniture) && relations.onfloor(id, built.floors[item.room])
        }
    }
}

/// Builds the home with the things asleep at their recorded poses, as a scene file builds it,
/// steps it for [`WATCH_STEPS`], and says which stayed asleep without moving a bit.
fn watch(home: &Scene, library: &Library, placed: &[Placed]) -> Result<Vec<bool>, ClutterError> {
    let scene = with_plans(home, placed);
    let mut built = scene.build(library)?;
    for _ in 0..WATCH_STEPS {
        built.world.step();
    }
    Ok(placed
        .iter()
        .zip(&built.clutter)
        .map(|(item, &id)| unmoved(&built.world, item, id))
        .collect())
}

/// Asleep, at exactly the recorded pose.
fn unmoved(world: &World, item: &Placed, id: ObjectId) -> bool {
    let pose = world.bodies().pose(id);
    world.bodies().is_sleeping(id)
        && pose.translation.to_array() == item.plan.position
        && pose.rotation.to_array() == item.plan.rotation
}

/// The home with these things as its clutter.
fn with_plans(home: &Scene, placed: &[Placed]) -> Scene {
    Scene {
        clutter: placed.iter().map(|p| p.plan.clone()).collect(),
        ..home.clone()
    }
}

/// Keeps the things marked true.
fn retain(placed: &mut Vec<Placed>, keep: &[bool]) {
    let mut marks = keep.iter();
    placed.retain(|_| marks.next().copied().unwrap_or(false));
}
