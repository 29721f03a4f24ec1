//! One small physical scene per clause of a rule, built so that exactly that clause decides the
//! outcome: every other clause of the rule is checked to hold in the scene, so the test fails if
//! the clause is dropped or broken.

mod common;

use behavior_core::{Ability, Predicate};
use behavior_sim::{
    BodyKind, BodyRef, ObjectId, ObjectSpec, Part, Primitive, STEP_SECONDS, StepHooks,
    TOUCH_DISTANCE, WIPE_MARGIN, World,
};
use common::*;
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};

// ---------------------------------------------------------------------------------------------
// Scene helpers
// ---------------------------------------------------------------------------------------------

/// The fraction of `inner`'s box that lies within `outer`'s.
fn fraction_within(inner: &Aabb, outer: &Aabb) -> f32 {
    let overlap = (inner.maxs.min(outer.maxs) - inner.mins.max(outer.mins)).max(Vector::ZERO);
    let size = inner.maxs - inner.mins;
    (overlap.x * overlap.y * overlap.z) / (size.x * size.y * size.z)
}

/// On how many of the three axes rays from the centre of `a`'s box hit `b` in both directions.
fn axes_surrounded(world: &World, a: ObjectId, b: ObjectId) -> usize {
    let center = world.bodies().aabb(a).center();
    let reach = 10.0;
    [Vector::X, Vector::Y, Vector::Z]
        .into_iter()
        .filter(|&axis| {
            world.relations().ray_hits(b, center, axis, reach)
                && world.relations().ray_hits(b, center, -axis, reach)
        })
        .count()
}

/// A fixed thing made of boxes `(half extents, centre)` standing at `at`.
fn fixed_boxes(
    world: &mut World,
    name: &str,
    category: &str,
    at: Vector,
    boxes: &[(Vector, Vector)],
) -> ObjectId {
    let parts = boxes
        .iter()
        .map(|&(half, centre)| Part::at(cuboid(half.x, half.y, half.z), centre))
        .collect();
    world
        .add(ObjectSpec::new(name, category, parts).at(at).fixed())
        .unwrap()
}

/// A dynamic box of the given half extents.
fn block(world: &mut World, name: &str, half: Vector, at: Vector) -> ObjectId {
    world
        .add(
            ObjectSpec::new(
                name,
                "block.n.01",
                vec![Part::new(cuboid(half.x, half.y, half.z))],
            )
            .at(at),
        )
        .unwrap()
}

/// A wiper driven to poses by the caller (a kinematic body): a flat pad whose bottom is at the
/// body's origin and whose leading (+x) edge is at x = 0, `length` long and `width` wide, with
/// two side skirts `skirt` deep hanging at its ±y edges (none if `skirt` is 0). A cleaning tool.
fn wiper(world: &mut World, length: f32, width: f32, skirt: f32, at: Vector) -> ObjectId {
    let (t, s) = (0.005, 0.005);
    let mut parts = vec![Part::at(
        cuboid(length / 2.0, width / 2.0, t),
        v(-length / 2.0, 0.0, t),
    )];
    if skirt > 0.0 {
        for side in [-1.0, 1.0] {
            parts.push(Part::at(
                cuboid(length / 2.0, s, skirt / 2.0),
                v(-length / 2.0, side * (width / 2.0 - s), -skirt / 2.0),
            ));
        }
    }
    let spec = ObjectSpec::new("wiper_1", "rag.n.01", parts)
        .at(at)
        .body(BodyKind::KinematicPosition)
        .ability(Ability::CleaningTool, &[])
        .ability(Ability::Soakable, &[]);
    world.add(spec).unwrap()
}

/// Moves a kinematic body to `at` (unrotated) during the next step, and takes the step.
fn drive_to(world: &mut World, body: ObjectId, at: Vector) {
    world
        .bodies_mut()
        .set_kinematic_target(BodyRef::from(body), Pose::from_translation(at))
        .unwrap();
    world.step();
}

// ---------------------------------------------------------------------------------------------
// inside
// ---------------------------------------------------------------------------------------------

/// A 1 m stick leaning in a 0.5 m bin, its foot in a corner of the bin and its shaft resting on
/// the opposite rim: its box's centre is in the bin's box and the bin's walls surround that
/// centre along x and y, but most of its box sticks out above and beyond the bin. Only the
/// half-within clause makes it not inside; an apple on the bin's bottom is inside.
#[test]
fn inside_needs_half_of_the_box_within_a_stick_leaning_out_of_a_bin_is_not_inside() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let bin = open_box(&mut world, 1.0, 1.0);
    // Foot against the -x wall on the bottom, shaft over the +x rim (x = 0.25, z = 0.4).
    let (foot, rim) = (v(-0.215, 0.0, 0.035), v(0.245, 0.0, 0.42));
    let dir = (rim - foot).normalize();
    let length = 1.0;
    let centre = foot + dir * (length / 2.0);
    let tilt = Rotation::from_rotation_y(-dir.z.atan2(dir.x));
    let mut spec = ObjectSpec::new(
        "stick_1",
        "stick.n.01",
        vec![Part::new(cuboid(length / 2.0, 0.015, 0.01))],
    );
    spec.pose = Pose::from_parts(v(1.0, 1.0, 0.0) + centre, tilt);
    let stick = world.add(spec).unwrap();
    let apple = apple(&mut world, "apple_1", v(1.0, 1.15, 0.1));
    settle(&mut world, 2.0);

    let (own, container) = (world.bodies().aabb(stick), world.bodies().aabb(bin));
    assert!(
        own.maxs.z > 0.6 && own.maxs.x > 1.45,
        "the stick still leans out of the bin: {own:?}"
    );
    assert!(
        container.contains_local_point(own.center()),
        "the stick's centre is in the bin's box"
    );
    assert!(
        axes_surrounded(&world, stick, bin) >= 2,
        "the bin surrounds the stick's centre"
    );
    let within = fraction_within(&own, &container);
    assert!(within < 0.45, "{within} of the stick's box is in the bin's");
    assert!(!world.relations().inside(stick, bin));

    assert!(fraction_within(&world.bodies().aabb(apple), &container) > 0.99);
    assert!(
        world.relations().inside(apple, bin),
        "the control is inside"
    );
}

/// A trough: a bottom and two walls at ±x, open at both ends and on top. An apple lying in it has
/// its whole box within the trough's, but the trough surrounds it along x only (up and along y
/// the rays miss), so it is not inside; the same apple in a bin with four walls is.
#[test]
fn inside_needs_rays_to_hit_on_two_axes_an_apple_in_an_open_ended_trough_is_not_inside() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let (w, l, h, t) = (0.12, 0.2, 0.1, 0.01);
    let trough = fixed_boxes(
        &mut world,
        "trough_1",
        "trough.n.01",
        v(1.0, -1.0, 0.0),
        &[
            (v(w, l, t), v(0.0, 0.0, t)),
            (v(t, l, h / 2.0), v(-w + t, 0.0, h / 2.0)),
            (v(t, l, h / 2.0), v(w - t, 0.0, h / 2.0)),
        ],
    );
    let in_trough = apple(&mut world, "apple_1", v(1.0, -1.0, 0.1));
    let bin = open_box(&mut world, 2.0, 1.0);
    let in_bin = apple(&mut world, "apple_2", v(2.0, 1.0, 0.1));
    settle(&mut world, 2.0);

    let own = world.bodies().aabb(in_trough);
    let container = world.bodies().aabb(trough);
    assert!(container.contains_local_point(own.center()));
    assert!(fraction_within(&own, &container) > 0.99, "wholly within");
    assert_eq!(
        axes_surrounded(&world, in_trough, trough),
        1,
        "the walls surround it along x only"
    );
    assert!(!world.relations().inside(in_trough, trough));

    assert!(axes_surrounded(&world, in_bin, bin) >= 2);
    assert!(
        world.relations().inside(in_bin, bin),
        "the control is inside"
    );
}

// ---------------------------------------------------------------------------------------------
// under
// ---------------------------------------------------------------------------------------------

/// A book on the lower board of a two-board shelf: the ray up from its top hits the shelf's upper
/// board, but the ray down from its bottom hits the lower board, so it is not under the shelf. A
/// ball below a table (nothing of the table beneath it) is under the table.
#[test]
fn under_is_false_when_the_ray_down_also_hits_a_book_between_two_shelf_boards() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let (w, d, t) = (0.3, 0.15, 0.01);
    let shelf = fixed_boxes(
        &mut world,
        "shelf_1",
        "shelf.n.01",
        v(1.0, 2.0, 0.0),
        &[
            (v(w, d, t), v(0.0, 0.0, 0.3)),
            (v(w, d, t), v(0.0, 0.0, 0.6)),
            (v(t, d, 0.35), v(-w - t, 0.0, 0.35)),
            (v(t, d, 0.35), v(w + t, 0.0, 0.35)),
        ],
    );
    let book = block(&mut world, "book_1", v(0.08, 0.05, 0.1), v(1.0, 2.0, 0.42));
    let table = table(&mut world, -1.0, 0.0);
    let ball = apple(&mut world, "apple_1", v(-1.0, 0.1, 0.1));
    settle(&mut world, 2.0);

    let b = world.bodies().aabb(book);
    let (top, bottom) = (
        v(b.center().x, b.center().y, b.maxs.z),
        v(b.center().x, b.center().y, b.mins.z),
    );
    assert!(
        world.relations().touching(book, shelf) && (b.mins.z - 0.31).abs() < 0.005,
        "the book stands on the lower board: {b:?}"
    );
    assert!(
        world.relations().ray_hits(shelf, top, Vector::Z, 5.0),
        "the upper board is above the book"
    );
    assert!(world.relations().ray_hits(shelf, bottom, -Vector::Z, 5.0));
    assert!(!world.relations().under(book, shelf));

    assert!(world.relations().under(ball, table), "the control is under");
}

// ---------------------------------------------------------------------------------------------
// nextto
// ---------------------------------------------------------------------------------------------

/// Two 10 cm cubes 1 cm apart sideways, one on the floor and one on a 12 cm step beside it: the
/// gap between their boxes (√(1² + 2²) cm) is within the threshold (a sixth of their mean summed
/// size, 3.3 cm), but each one's centre is level with no part of the other, so no horizontal
/// ray finds it: not next to. The same cube on the floor on the other side is next to.
#[test]
fn nextto_needs_a_horizontal_ray_a_cube_on_a_step_beside_another_is_not_nextto() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let half = v(0.05, 0.05, 0.05);
    let low = block(&mut world, "cube_1", half, v(1.0, -2.0, 0.051));
    fixed_boxes(
        &mut world,
        "step_1",
        "step.n.01",
        v(1.11, -2.0, 0.0),
        &[(v(0.05, 0.05, 0.06), v(0.0, 0.0, 0.06))],
    );
    let high = block(&mut world, "cube_2", half, v(1.11, -2.0, 0.171));
    let level = block(&mut world, "cube_3", half, v(0.89, -2.0, 0.051));
    settle(&mut world, 1.0);

    let (a, b) = (world.bodies().aabb(low), world.bodies().aabb(high));
    let gap = (a.mins - b.maxs)
        .max(b.mins - a.maxs)
        .max(Vector::ZERO)
        .length();
    let extents = (a.maxs - a.mins) + (b.maxs - b.mins);
    let threshold = (extents.x + extents.y + extents.z) / 18.0;
    assert!(
        gap > 0.01 && gap < threshold * 0.9,
        "gap {gap}, threshold {threshold}"
    );
    assert!(
        a.center().z < b.mins.z && b.center().z > a.maxs.z,
        "each centre is level with nothing of the other"
    );
    assert!(!world.relations().nextto(low, high) && !world.relations().nextto(high, low));

    assert!(
        world.relations().nextto(low, level),
        "the control is next to"
    );
}

// ---------------------------------------------------------------------------------------------
// dusty
// ---------------------------------------------------------------------------------------------

/// Wipes a fixed dusty slab with a wiper pad sweeping in from -x, one particle (or a few, where
/// their x coincide) at a time, and checks the count and `dusty` at each stage: dusty while more
/// than `threshold_num / threshold_den` of the particles remain.
fn wipe_down(category: &str, threshold_num: usize, threshold_den: usize) {
    let mut world = World::default();
    // Turned a little about z, so that particles on a side face (if any) differ in x.
    let turn: f32 = 0.05;
    let mut spec = ObjectSpec::new("slab_1", category, vec![Part::new(cuboid(0.15, 0.1, 0.02))])
        .fixed()
        .ability(Ability::Dustyable, &[]);
    spec.pose = Pose::from_parts(v(0.0, 0.0, 0.5), Rotation::from_rotation_z(turn));
    let slab = world.add(spec).unwrap();
    let bounds = world.bodies().aabb(slab);
    let (top, y) = (bounds.maxs.z, bounds.center().y);
    // The skirts hang 1 cm clear of the slab's sides, down past its bottom, so the wiper's
    // box covers every particle on the top and sides at the x it has reached.
    // The pad presses 0.2 mm into the slab (a kinematic body and a fixed one exert no forces):
    // with a gap instead, parry's distance between the two boxes, turned to each other, comes
    // out wrong by up to centimetres and `touching` would be false.
    let width = bounds.maxs.y - bounds.mins.y + 0.04;
    let pad_z = top - 0.0002;
    let wiper = wiper(&mut world, 0.45, width, 0.06, v(-0.5, y, pad_z));
    world.set_state(slab, Predicate::Dusty, true).unwrap();
    assert!(world.state(slab, Predicate::Dusty));
    let start = world.particle_positions(slab, Predicate::Dusty);
    let n = start.len();
    assert!(n >= 10, "only {n} particles");
    let mut xs: Vec<f32> = start.iter().map(|p| p.x).collect();
    xs.sort_by(f32::total_cmp);

    let mut seen = Vec::new();
    for k in 1..=n {
        // Wipe the k particles of smallest x: the wiped region ends WIPE_MARGIN past the pad.
        let cut = if k == n {
            xs[n - 1] + 0.005
        } else {
            (xs[k - 1] + xs[k]) / 2.0
        };
        if k < n && xs[k] - xs[k - 1] < 2e-4 {
            continue; // tied with the next one: wiped together
        }
        let edge = cut - WIPE_MARGIN;
        if edge < bounds.mins.x + 0.002 {
            continue; // the pad would not yet lie on the slab
        }
        drive_to(&mut world, wiper, v(edge, y, pad_z));
        assert!(world.relations().touching(wiper, slab));
        let remaining = world.particle_positions(slab, Predicate::Dusty).len();
        assert_eq!(remaining, n - k, "wiped up to x = {cut}");
        let dirty = remaining * threshold_den > threshold_num * n;
        assert_eq!(
            world.state(slab, Predicate::Dusty),
            dirty,
            "{category}: {remaining} of {n} particles remain"
        );
        seen.push(remaining);
    }
    // Both sides of the threshold were checked, right where it is crossed.
    let last_dusty = n * threshold_num / threshold_den + 1;
    assert!(
        seen.contains(&last_dusty) && seen.contains(&(last_dusty - 1)),
        "{category}: stages {seen:?} of {n} miss the threshold"
    );
}

#[test]
fn dusty_while_more_than_half_of_the_particles_remain() {
    wipe_down("countertop.n.01", 1, 2);
}

#[test]
fn dusty_floor_while_more_than_three_quarters_of_the_particles_remain() {
    wipe_down("floor.n.01", 3, 4);
}

/// A wiper held 7 mm above a dusty plate: every particle lies in its box grown by the wipe
/// margin (1 cm), but it does not touch the plate (5 mm), so nothing is wiped however long it
/// stays; lowered to 1 mm it touches and wipes them all at once. (Its skirts, 2 cm clear of
/// the plate's rim, stretch its box down over the plate's sides, where particles may lie.)
#[test]
fn dusty_cleaning_needs_the_tool_to_touch_not_just_to_be_near() {
    let mut world = World::default();
    two_room_floor(&mut world);
    table(&mut world, -1.0, 0.0);
    let plate = dirty_plate(&mut world, v(-1.0, 0.0, 0.8));
    settle(&mut world, 1.0);
    world.set_state(plate, Predicate::Dusty, true).unwrap();
    let n = world.particle_positions(plate, Predicate::Dusty).len();
    assert!(n >= 5);
    let top = world.bodies().aabb(plate).maxs.z;
    let above = |gap: f32| v(-1.0 + 0.15, 0.0, top + gap);
    let wiper = wiper(&mut world, 0.3, 0.3, 0.02, above(0.007));
    drive_to(&mut world, wiper, above(0.007));

    let reach = world.bodies().aabb(wiper).loosened(WIPE_MARGIN);
    assert!(
        world
            .particle_positions(plate, Predicate::Dusty)
            .iter()
            .all(|&p| reach.contains_local_point(p)),
        "every particle is within the wiper's reach"
    );
    assert!(!world.relations().touching(wiper, plate));
    assert!(world.bodies().pose(wiper).translation.z - top > TOUCH_DISTANCE + 0.001);
    for _ in 0..30 {
        drive_to(&mut world, wiper, above(0.007));
    }
    assert_eq!(world.particle_positions(plate, Predicate::Dusty).len(), n);
    assert!(world.state(plate, Predicate::Dusty));

    drive_to(&mut world, wiper, above(0.001));
    assert!(world.relations().touching(wiper, plate));
    assert_eq!(world.particle_positions(plate, Predicate::Dusty).len(), 0);
    assert!(!world.state(plate, Predicate::Dusty));
}

// ---------------------------------------------------------------------------------------------
// soaked
// ---------------------------------------------------------------------------------------------

/// A rag lying in a sink (touching it) stays dry while the tap is off, however long; once the
/// tap runs, the drops soak it. A rag on the floor stays dry throughout.
#[test]
fn soaked_only_by_drops_a_rag_in_a_sink_stays_dry_while_the_tap_is_off() {
    let mut world = World::default();
    two_room_floor(&mut world);
    let sink = sink(&mut world, -1.0, 0.0);
    let wet = rag(&mut world, v(-1.0, 0.05, 0.7));
    let dry = rag(&mut world, v(-2.5, 0.0, 0.1));
    world.set_state(sink, Predicate::ToggledOn, true).unwrap();
    world.set_state(sink, Predicate::ToggledOn, false).unwrap();
    settle(&mut world, 1.0);
    assert!(
        world.relations().touching(wet, sink),
        "the rag lies in the sink"
    );
    for _ in 0..150 {
        world.step();
        assert!(world.drops().is_empty(), "a tap that is off emits nothing");
        assert!(!world.state(wet, Predicate::Soaked));
    }

    world.set_state(sink, Predicate::ToggledOn, true).unwrap();
    let mut soaked_at = None;
    let mut saw_drops = false;
    for step in 0..90 {
        world.step();
        saw_drops |= !world.drops().is_empty();
        if world.state(wet, Predicate::Soaked) {
            soaked_at = Some(step);
            break;
        }
    }
    assert!(saw_drops, "the running tap emits drops");
    assert!(soaked_at.is_some(), "the drops soak the rag");
    assert!(!world.state(dry, Predicate::Soaked));
}

// ---------------------------------------------------------------------------------------------
// sliced
// ---------------------------------------------------------------------------------------------

/// Records the largest contact force between a slicer and a sliceable object over every physics
/// substep (each substep's contacts are read before the next one, and after the step's last).
struct ForceProbe {
    knife: ObjectId,
    tomato: ObjectId,
    push: Vector,
    max: f32,
}

impl ForceProbe {
    fn read(&mut self, world: &World) {
        let dt = STEP_SECONDS / world.bodies().substeps().count() as f32;
        let force: f32 = world
            .contacts()
            .of_object(self.knife)
            .iter()
            .filter(|c| c.other.map(|b| b.object) == Some(self.tomato))
            .map(|c| c.impulse / dt)
            .sum();
        self.max = self.max.max(force);
    }
}

impl StepHooks for ForceProbe {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        if substep > 0 {
            self.read(world);
        }
        if substep == 0
            && self.push != Vector::ZERO
            && world.bodies().object(self.knife).is_present()
        {
            world
                .bodies_mut()
                .apply_force(BodyRef::from(self.knife), self.push)
                .unwrap();
        }
    }

    fn after_step(&mut self, world: &mut World) {
        self.read(world);
    }
}

/// A flat-topped tomato (a short cylinder) on a table and a 0.19 kg knife lying flat on it: the
/// knife's weight (1.8 N) never slices it; the same knife pushed down with 15 N more does.
#[test]
fn sliced_only_above_ten_newtons_a_resting_knife_does_not_slice_a_pushed_one_does() {
    let mut world = World::default();
    two_room_floor(&mut world);
    table(&mut world, -1.0, 0.0);
    let mut spec = ObjectSpec::new(
        "tomato_1",
        "tomato.n.01",
        vec![Part::new(Primitive::Cylinder {
            radius: 0.04,
            half_height: 0.025,
        })],
    )
    .at(v(-1.0, 0.0, 0.776))
    .ability(Ability::Sliceable, &[]);
    spec.density = 900.0;
    let tomato = world.add(spec).unwrap();
    settle(&mut world, 1.0);
    let top = world.bodies().aabb(tomato).maxs.z;
    // A blade 20 × 3 cm, 4 mm thick, of steel, lying flat a hair above the tomato.
    let mut spec = ObjectSpec::new(
        "knife_1",
        "carving_knife.n.01",
        vec![Part::new(cuboid(0.1, 0.015, 0.002))],
    )
    .at(v(-1.0, 0.0, top + 0.0025))
    .ability(Ability::Slicer, &[]);
    spec.density = 7800.0;
    let knife = world.add(spec).unwrap();
    let mass = world.bodies().mass(knife);
    assert!((0.05..=0.3).contains(&mass), "{mass} kg");
    // Well below iGibson's 10 N (not read from the world's constant, which a break could move).
    let weight = mass * 9.81;
    assert!(weight < 5.0, "{weight} N");

    let mut probe = ForceProbe {
        knife,
        tomato,
        push: Vector::ZERO,
        max: 0.0,
    };
    for _ in 0..150 {
        world.step_with(&mut probe);
    }
    assert!(
        world.relations().ontop(knife, tomato),
        "the knife rests on the tomato"
    );
    assert!(
        !world.state(tomato, Predicate::Sliced),
        "sliced by the knife's weight alone (largest contact force {} N)",
        probe.max
    );
    let resting = probe.max;

    probe.push = v(0.0, 0.0, -15.0);
    probe.max = 0.0;
    for _ in 0..30 {
        world.step_with(&mut probe);
        if world.state(tomato, Predicate::Sliced) {
            break;
        }
    }
    assert!(
        world.state(tomato, Predicate::Sliced),
        "not sliced when pressed with {} N (resting: {resting} N)",
        probe.max
    );
}

// ---------------------------------------------------------------------------------------------
// determinism
// ---------------------------------------------------------------------------------------------

/// A kitchen where things happen: a running tap over a rag in a sink, a second tap over a second
/// rag that is turned on only late, and a sponge pushed by a force across a dusty board on a
/// table.
struct Kitchen {
    world: World,
    rag: ObjectId,
    late_sink: ObjectId,
    late_rag: ObjectId,
    board: ObjectId,
    sponge: ObjectId,
}

/// The step at which the second tap is turned on, after the snapshot of the test below.
const LATE_TAP_STEP: u64 = 70;

fn busy_kitchen() -> Kitchen {
    let mut world = World::default();
    two_room_floor(&mut world);
    let sink_1 = sink(&mut world, -1.0, 0.0);
    let rag = rag(&mut world, v(-1.0, 0.05, 0.7));
    world.set_state(sink_1, Predicate::ToggledOn, true).unwrap();
    let late_sink = sink(&mut world, -3.0, 0.0);
    let late_rag = common::rag(&mut world, v(-3.0, 0.05, 0.7));
    table(&mut world, 1.0, 0.0);
    let mut spec = ObjectSpec::new(
        "board_1",
        "chopping_board.n.01",
        vec![Part::new(cuboid(0.2, 0.12, 0.01))],
    )
    .at(v(1.0, 0.0, 0.761))
    .ability(Ability::Dustyable, &[]);
    spec.density = 700.0;
    let board = world.add(spec).unwrap();
    let mut spec = ObjectSpec::new(
        "sponge_1",
        "sponge.n.01",
        vec![Part::new(cuboid(0.04, 0.03, 0.015))],
    )
    .at(v(0.85, 0.0, 0.787))
    .ability(Ability::CleaningTool, &[])
    .ability(Ability::Soakable, &[]);
    spec.density = 150.0;
    let sponge = world.add(spec).unwrap();
    world.set_state(board, Predicate::Dusty, true).unwrap();
    Kitchen {
        world,
        rag,
        late_sink,
        late_rag,
        board,
        sponge,
    }
}

/// One step of the kitchen: the sponge is pulled by a spring and damper toward a point that
/// sweeps along the board (a force computed from the world's own state), and the second tap is
/// turned on at its step.
fn kitchen_step(kitchen: &mut Kitchen) {
    let world = &mut kitchen.world;
    if world.bodies().steps() == LATE_TAP_STEP {
        world
            .set_state(kitchen.late_sink, Predicate::ToggledOn, true)
            .unwrap();
    }
    let sponge = BodyRef::from(kitchen.sponge);
    let t = world.bodies().steps() as f32 * STEP_SECONDS;
    let target = v(0.85 + 0.08 * t, 0.02 * (3.0 * t).sin(), 0.0);
    let at = world.bodies().pose(kitchen.sponge).translation;
    let vel = world.bodies().velocity(sponge).unwrap().linear;
    let (k, c) = (8.0, 0.6);
    let force = v(
        k * (target.x - at.x) - c * vel.x,
        k * (target.y - at.y) - c * vel.y,
        0.0,
    );
    world.bodies_mut().apply_force(sponge, force).unwrap();
    world.step();
}

/// Every pose, drop, particle and dirt/water state of the world, bit for bit, hashed.
fn digest(world: &World) -> u64 {
    use std::hash::{DefaultHasher, Hash, Hasher};
    let mut h = DefaultHasher::new();
    let bits = |h: &mut DefaultHasher, p: Vector| {
        for x in [p.x, p.y, p.z] {
            x.to_bits().hash(h);
        }
    };
    for (id, _) in world.bodies().objects() {
        let pose = world.bodies().pose(id);
        bits(&mut h, pose.translation);
        for q in pose.rotation.to_array() {
            q.to_bits().hash(&mut h);
        }
        for kind in [Predicate::Dusty, Predicate::Stained] {
            let particles = world.particle_positions(id, kind);
            particles.len().hash(&mut h);
            for p in particles {
                bits(&mut h, p);
            }
        }
        for state in [Predicate::Soaked, Predicate::Dusty, Predicate::Stained] {
            world.state(id, state).hash(&mut h);
        }
    }
    let drops = world.drops();
    drops.len().hash(&mut h);
    for d in drops {
        bits(&mut h, d);
    }
    world.bodies().steps().hash(&mut h);
    h.finish()
}

/// The kitchen stepped twice from scratch, and once resumed from a snapshot taken halfway, ends
/// in the same state bit for bit: poses, drops, dust particles and states. And the scene did
/// something on both sides of the snapshot: drops were in flight when it was taken, the sponge
/// wiped dust before and after it, and the late rag got soaked after it.
#[test]
fn snapshot_determinism_with_drops_soaking_and_wiping_in_the_digest() {
    const STEPS: usize = 120;
    let mut first = busy_kitchen();
    let dust = |k: &Kitchen| k.world.particle_positions(k.board, Predicate::Dusty).len();
    let dust_before = dust(&first);
    let mut midway = None;
    for step in 0..STEPS {
        if step == STEPS / 2 {
            let w = &first.world;
            assert!(!w.drops().is_empty(), "drops are in flight at the snapshot");
            assert!(w.state(first.rag, Predicate::Soaked));
            assert!(!w.state(first.late_rag, Predicate::Soaked));
            midway = Some((w.snapshot(), digest(w), dust(&first)));
        }
        kitchen_step(&mut first);
    }
    let mut second = busy_kitchen();
    for _ in 0..STEPS {
        kitchen_step(&mut second);
    }
    let (snapshot, at_snapshot, dust_midway) = midway.unwrap();
    let mut resumed = busy_kitchen();
    resumed.world.restore(&snapshot);
    assert_eq!(digest(&resumed.world), at_snapshot, "restored as saved");
    for _ in STEPS / 2..STEPS {
        kitchen_step(&mut resumed);
    }

    let end = digest(&first.world);
    assert_eq!(digest(&second.world), end, "a second run from scratch");
    assert_eq!(digest(&resumed.world), end, "resumed from the snapshot");

    let dust_after = dust(&first);
    assert!(
        dust_before > dust_midway && dust_midway > dust_after && dust_after > 0,
        "the sponge wiped part of the dust: {dust_before} → {dust_midway} → {dust_after}"
    );
    assert!(
        first.world.state(first.late_rag, Predicate::Soaked),
        "the late rag got soaked after the snapshot"
    );
    let moved = first.world.bodies().pose(first.sponge).translation.x - 0.85;
    assert!(moved > 0.05, "the sponge moved {moved} m");
}
