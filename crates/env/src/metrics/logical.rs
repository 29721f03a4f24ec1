//! Logical disarrangement (iGibson 2.0.3's `metrics/`): how many of the home's logical states
//! changed.
//!
//! For every object but walls, floors, the robot and the agent's stand-in, a picture holds its
//! unary states (cooked, burnt, frozen, soaked, open, dusty, stained, sliced, toggled on) and
//! the relations it is the subject of: `ontop`, `inside`, `under`, `touching` against every other
//! such object, `onfloor` against every floor. Between the picture taken at the start (after
//! the reset settled) and one taken at the end, an object counts **1** if any of its relations
//! changed (the original's grouping; `nextto` is not compared, as there) plus **1 per changed
//! unary state**. The sum over objects is the logical disarrangement.
//!
//! Chosen differently from the original: its picture also holds the robot-relative states (in
//! reach, in the same room, in view, in hand), so walking about counted as disarranging the home;
//! ours leaves them out, measuring the home only. Relations are only evaluated between objects
//! whose boxes overlap in plan (2 cm margin): none of the four can hold otherwise, and a home's
//! 200 objects then cost hundreds of pair tests, not 40,000.

use behavior_core::Predicate;
use behavior_core::{FLOOR_SYNSET, WALL_SYNSET};
use behavior_sim::{ObjectId, World};

/// Plan-view margin within which two objects may relate, m.
const PLAN_MARGIN: f32 = 0.02;
/// The relations compared, as the original groups them.
const RELATIONS: [Predicate; 4] = [
    Predicate::OnTop,
    Predicate::Inside,
    Predicate::Under,
    Predicate::Touching,
];

/// One object's logical state.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug, PartialEq)]
struct Picture {
    id: ObjectId,
    states: [bool; Predicate::UNARY_STATES.len()],
    /// (predicate, other object) pairs that hold, `onfloor` included, sorted.
    relations: Vec<(Predicate, ObjectId)>,
}

/// The logical state of the home at the start of an episode.
#[derive(serde::Serialize, serde::Deserialize, Clone, Debug)]
pub(crate) struct Logical {
    start: Vec<Picture>,
    ignored: Vec<ObjectId>,
}

/// The comparison of two pictures.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct LogicalChange {
    /// Objects with changed relations + changed unary states.
    pub(crate) relative: u32,
    /// Objects compared.
    pub(crate) total_objects: u32,
    /// States compared: unary states plus one grouped relation state per object.
    pub(crate) total_states: u32,
}

impl Logical {
    /// Takes the starting picture of every object but `ignored`, walls and floors.
    pub(crate) fn start(world: &World, ignored: &[ObjectId]) -> Logical {
        Logical {
            start: picture(world, ignored),
            ignored: ignored.to_vec(),
        }
    }

    /// Compares the start with `world` now.
    pub(crate) fn compare(&self, world: &World) -> LogicalChange {
        let mut change = LogicalChange::default();
        let (others, floors) = (subjects_of(world, &self.ignored), floors(world));
        for before in &self.start {
            let after = picture_of(world, before.id, &others, &floors);
            change.total_objects += 1;
            change.total_states += before.states.len() as u32 + 1;
            change.relative += u32::from(after.relations != before.relations);
            change.relative += before
                .states
                .iter()
                .zip(&after.states)
                .filter(|(a, b)| a != b)
                .count() as u32;
        }
        change
    }
}

fn is_structure(world: &World, id: ObjectId) -> bool {
    let category = &world.bodies().object(id).category;
    category == WALL_SYNSET || category == FLOOR_SYNSET
}

fn floors(world: &World) -> Vec<ObjectId> {
    world
        .bodies()
        .objects()
        .filter(|(_, o)| o.category == FLOOR_SYNSET)
        .map(|(id, _)| id)
        .collect()
}

/// The objects pictured: present, not structure, not ignored.
fn subjects_of(world: &World, ignored: &[ObjectId]) -> Vec<ObjectId> {
    world
        .bodies()
        .objects()
        .filter(|(id, o)| o.is_present() && !ignored.contains(id) && !is_structure(world, *id))
        .map(|(id, _)| id)
        .collect()
}

fn picture(world: &World, ignored: &[ObjectId]) -> Vec<Picture> {
    let subjects = subjects_of(world, ignored);
    let floors = floors(world);
    subjects
        .iter()
        .map(|&id| picture_of(world, id, &subjects, &floors))
        .collect()
}

/// Whether two objects' boxes overlap in plan, within the margin.
fn overlap_in_plan(world: &World, a: ObjectId, b: ObjectId) -> bool {
    let (a, b) = (world.bodies().aabb(a), world.bodies().aabb(b));
    a.mins.x <= b.maxs.x + PLAN_MARGIN
        && b.mins.x <= a.maxs.x + PLAN_MARGIN
        && a.mins.y <= b.maxs.y + PLAN_MARGIN
        && b.mins.y <= a.maxs.y + PLAN_MARGIN
}

fn picture_of(world: &World, id: ObjectId, others: &[ObjectId], floors: &[ObjectId]) -> Picture {
    let states = Predicate::UNARY_STATES.map(|p| world.state(id, p));
    let kinematic = world.relations();
    let mut relations = Vec::new();
    for &other in others {
        if other == id || !overlap_in_plan(world, id, other) {
            continue;
        }
        for p in RELATIONS {
            let holds = match p {
                Predicate::OnTop => kinematic.ontop(id, other),
                Predicate::Inside => kinematic.inside(id, other),
                Predicate::Under => kinematic.under(id, other),
                _ => kinematic.touching(id, other),
            };
            if holds {
                relations.push((p, other));
            }
        }
    }
    for &floor in floors {
        if kinematic.onfloor(id, floor) {
            relations.push((Predicate::OnFloor, floor));
        }
    }
    relations.sort();
    Picture {
        id,
        states,
        relations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{ObjectSpec, Part, Primitive};
    use rapier3d::math::{Pose, Vector};

    fn boxed(name: &str, category: &str, half: Vector, at: Vector) -> ObjectSpec {
        ObjectSpec::new(
            name,
            category,
            vec![Part::new(Primitive::Box { half_extents: half })],
        )
        .at(at)
    }

    #[test]
    fn an_object_counts_once_for_its_relations_and_walking_robots_count_nothing() {
        let mut world = World::default();
        let floor = boxed(
            "floor",
            "floor.n.01",
            Vector::new(5.0, 5.0, 0.05),
            Vector::new(0.0, 0.0, -0.05),
        );
        world.add(floor.fixed()).unwrap();
        let table = boxed(
            "table",
            "table.n.02",
            Vector::new(0.5, 0.5, 0.4),
            Vector::new(0.0, 0.0, 0.4),
        );
        world.add(table.fixed()).unwrap();
        let small = Vector::splat(0.04);
        let apples: Vec<ObjectId> = (0..3)
            .map(|k| {
                let spec = boxed(
                    &format!("apple_{k}"),
                    "apple.n.01",
                    small,
                    Vector::new(-0.3 + 0.3 * k as f32, 0.0, 0.85),
                );
                world.add(spec).unwrap()
            })
            .collect();
        let robot = boxed(
            "robot",
            "agent.n.01",
            Vector::splat(0.2),
            Vector::new(2.0, 0.0, 0.2),
        );
        let robot = world.add(robot).unwrap();
        world.settle(200);
        let logical = Logical::start(&world, &[robot]);
        // Two apples go from the table to the floor; the robot walks up to the third one's side.
        for (k, &apple) in apples[..2].iter().enumerate() {
            let to = Pose::from_translation(Vector::new(1.0, -0.5 + k as f32, 0.04));
            world.bodies_mut().set_pose(apple, to).unwrap();
        }
        world
            .bodies_mut()
            .set_pose(robot, Pose::from_translation(Vector::new(0.8, 0.0, 0.2)))
            .unwrap();
        world.settle(200);
        let change = logical.compare(&world);
        // Each moved apple counts once (ontop, touching and onfloor changed, grouped); the
        // table counts once too: it no longer touches them. The robot is not pictured.
        assert_eq!(change.relative, 3);
        assert_eq!(change.total_objects, 4, "three apples and the table");
        assert_eq!(change.total_states, 4 * 10);
    }
}
