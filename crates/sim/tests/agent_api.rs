//! What robots, cameras and planners need from the world, each in a small real scene: kinematic
//! bodies, velocities and forces, multibody arms with drives, attachments, contacts, collision
//! filtering, ray and shape queries, appearance, step hooks, threads and snapshots.

mod common;

use behavior_core::Ability;
use behavior_sim::{
    AttachmentKind, AttachmentSpec, BodyKind, BodyRef, Drive, JointKind, JointModel, JointSpec,
    LinkSpec, Material, Model, ModelLibrary, ModelPiece, ObjectId, ObjectSpec, Part, PointKind,
    Primitive, QueryFilter, StepHooks, Velocity, Visual, VisualMesh, VisualShape, World, groups,
};
use common::*;
use rapier3d::math::{Pose, Rotation, Vector};

/// A 10 × 10 m floor slab whose top is at z = 0.
fn floor(world: &mut World) -> ObjectId {
    world
        .add(
            ObjectSpec::new(
                "floor",
                "floor.n.01",
                vec![Part::new(cuboid(5.0, 5.0, 0.05))],
            )
            .at(v(0.0, 0.0, -0.05))
            .fixed(),
        )
        .unwrap()
}

/// A dynamic cube of side 2·`half` resting on the floor at (x, y).
fn cube(world: &mut World, name: &str, x: f32, y: f32, half: f32) -> ObjectId {
    let mut spec = ObjectSpec::new(name, "box.n.01", vec![Part::new(cuboid(half, half, half))])
        .at(v(x, y, half + 0.001));
    spec.density = 250.0;
    world.add(spec).unwrap()
}

fn paddle(world: &mut World, kind: BodyKind, at: Vector) -> ObjectId {
    world
        .add(
            ObjectSpec::new(
                "paddle",
                "paddle.n.01",
                vec![Part::new(cuboid(0.02, 0.3, 0.1))],
            )
            .at(at)
            .body(kind),
        )
        .unwrap()
}

fn steps(world: &mut World, n: usize) {
    for _ in 0..n {
        world.step();
    }
}

#[test]
fn a_kinematic_paddle_driven_by_velocity_pushes_a_box() {
    let mut world = World::default();
    floor(&mut world);
    let cube = cube(&mut world, "cube", 0.0, 0.0, 0.1);
    let paddle = paddle(&mut world, BodyKind::KinematicVelocity, v(-0.5, 0.0, 0.12));
    steps(&mut world, 15);
    let start = world.bodies().pose(cube).translation;
    let forward = Velocity {
        linear: v(0.5, 0.0, 0.0),
        angular: Vector::ZERO,
    };
    world
        .bodies_mut()
        .set_velocity(paddle.into(), forward)
        .unwrap();
    steps(&mut world, 60); // 2 s at 0.5 m/s: the paddle travels 1 m, through where the box was
    let paddle_x = world.bodies().pose(paddle).translation.x;
    assert!((paddle_x - 0.5).abs() < 0.01, "paddle at x = {paddle_x}");
    let pushed = world.bodies().pose(cube).translation.x - start.x;
    assert!(pushed > 0.35, "the box moved only {pushed} m");
    assert!(
        world.bodies().pose(cube).translation.x > paddle_x,
        "the box stays ahead of the paddle"
    );
    // Nothing pushes a kinematic body back.
    let velocity = world.bodies().velocity(paddle.into()).unwrap();
    assert_eq!(velocity.linear, v(0.5, 0.0, 0.0));
}

/// Sweeps a position-driven paddle along +y at 0.5 m/s, one target per substep.
struct Sweep {
    paddle: ObjectId,
    y: f32,
}

impl StepHooks for Sweep {
    fn before_substep(&mut self, world: &mut World, _substep: u32) {
        self.y += 0.5 / 300.0;
        let target = Pose::from_translation(v(0.0, self.y, 0.12));
        world
            .bodies_mut()
            .set_kinematic_target(BodyRef::from(self.paddle), target)
            .unwrap();
    }
}

#[test]
fn a_kinematic_paddle_driven_by_pose_targets_in_a_hook_pushes_a_box() {
    let mut world = World::default();
    floor(&mut world);
    let cube = cube(&mut world, "cube", 0.0, 0.0, 0.1);
    let paddle = world
        .add(
            ObjectSpec::new(
                "paddle",
                "paddle.n.01",
                vec![Part::new(cuboid(0.3, 0.02, 0.1))],
            )
            .at(v(0.0, -0.5, 0.12))
            .body(BodyKind::KinematicPosition),
        )
        .unwrap();
    steps(&mut world, 15);
    let mut sweep = Sweep { paddle, y: -0.5 };
    for _ in 0..60 {
        world.step_with(&mut sweep);
    }
    let paddle_y = world.bodies().pose(paddle).translation.y;
    assert!((paddle_y - 0.5).abs() < 0.01, "paddle at y = {paddle_y}");
    assert!(
        world.bodies().pose(cube).translation.y > 0.35,
        "the box was not pushed"
    );
    // Pose targets are for position-driven bodies only.
    let err = world
        .bodies_mut()
        .set_kinematic_target(cube.into(), Pose::IDENTITY)
        .unwrap_err();
    assert!(err.to_string().contains("KinematicPosition"), "{err}");
}

#[test]
fn velocities_forces_torques_and_impulses_act_as_newton_says() {
    let mut world = World::default();
    world.bodies_mut().set_sleeping_allowed(false);
    let ball = world
        .add(
            ObjectSpec::new(
                "ball",
                "ball.n.01",
                vec![Part::new(Primitive::Sphere { radius: 0.1 })],
            )
            .at(v(0.0, 0.0, 10.0)),
        )
        .unwrap();
    let mass = world.bodies().mass(ball);
    world
        .bodies_mut()
        .apply_impulse(ball.into(), v(mass, 0.0, 0.0))
        .unwrap();
    let after_impulse = world.bodies().velocity(ball.into()).unwrap().linear;
    assert!(
        (after_impulse.x - 1.0).abs() < 1e-5,
        "impulse m·1 m/s gave {after_impulse}"
    );
    // A force of 2 m along y for one step (1/30 s) adds 2/30 m/s, then it is cleared.
    world
        .bodies_mut()
        .apply_force(ball.into(), v(0.0, 2.0 * mass, 0.0))
        .unwrap();
    world.step();
    let vy = world.bodies().velocity(ball.into()).unwrap().linear.y;
    assert!((vy - 2.0 / 30.0).abs() < 1e-3, "vy = {vy}");
    world.step();
    let vy2 = world.bodies().velocity(ball.into()).unwrap().linear.y;
    assert!(
        (vy2 - vy).abs() < 1e-5,
        "the force was cleared after its step"
    );
    // Gravity pulled for two steps meanwhile.
    let vz = world.bodies().velocity(ball.into()).unwrap().linear.z;
    assert!((vz + 9.81 * 2.0 / 30.0).abs() < 0.01, "vz = {vz}");
    world
        .bodies_mut()
        .apply_torque(ball.into(), v(0.0, 0.0, 0.01))
        .unwrap();
    world.step();
    assert!(world.bodies().velocity(ball.into()).unwrap().angular.z > 0.0);
    let set = Velocity {
        linear: v(0.0, 0.0, 3.0),
        angular: v(1.0, 0.0, 0.0),
    };
    world.bodies_mut().set_velocity(ball.into(), set).unwrap();
    assert_eq!(world.bodies().velocity(ball.into()).unwrap(), set);
    let nan = world
        .bodies_mut()
        .apply_force(ball.into(), v(f32::NAN, 0.0, 0.0));
    assert!(nan.is_err(), "a NaN force is refused");
}

#[test]
fn a_three_link_multibody_arm_reaches_its_joint_targets_and_reports_its_state() {
    let mut world = World::default();
    let arm = multibody_arm(&mut world, 0.0, 0.0);
    let targets = [0.5, -0.3, 0.4];
    for (k, &target) in targets.iter().enumerate() {
        world
            .joints_mut()
            .drive(arm, k, Drive::position(target, 2000.0, 100.0, 500.0))
            .unwrap();
    }
    steps(&mut world, 90);
    for (k, &target) in targets.iter().enumerate() {
        let state = world.joints().state(arm, k).unwrap();
        assert!(
            (state.position - target).abs() < 0.01,
            "joint {k} at {} for {target}",
            state.position
        );
        assert!(
            state.velocity.abs() < 0.01,
            "joint {k} still moves at {}",
            state.velocity
        );
    }
    // The shoulder holds all three links against gravity. About y a positive angle turns a bar's
    // tip down (x × y = z), so gravity pushes the angle up and the drive pulls back: a negative
    // effort of the weight's moment's order (a chain's efforts are approximate: 3.0× here, see
    // `joints.rs`).
    let shoulder = world.joints().state(arm, 0).unwrap();
    let bar = 0.3 * 0.04 * 0.04 * 500.0; // kg
    let (a0, a1, a2) = (0.5f32, 0.2f32, 0.6f32); // each bar's angle from the horizontal
    let lever = 0.15 * a0.cos()
        + (0.3 * a0.cos() + 0.15 * a1.cos())
        + (0.3 * a0.cos() + 0.3 * a1.cos() + 0.15 * a2.cos());
    let moment = bar * 9.81 * lever;
    assert!(
        shoulder.effort < 0.0 && (0.5..4.0).contains(&(-shoulder.effort / moment)),
        "shoulder effort {} for a gravity moment of {moment} N·m",
        shoulder.effort
    );
    // Forward kinematics: the last link's frame turned by the sum of the angles about y.
    let last = world.bodies().link_pose(arm, 2);
    let (_, angle) = last.rotation.to_axis_angle();
    assert!(
        (angle - 0.6).abs() < 0.02,
        "the last link turned {angle} rad in all"
    );
    // Teleporting a joint is read back at once, and the chain follows.
    world.joints_mut().set_position(arm, 1, 0.0).unwrap();
    assert!(world.joints().state(arm, 1).unwrap().position.abs() < 1e-4);
    let bad = world
        .joints_mut()
        .drive(arm, 7, Drive::velocity(1.0, 1.0, 1.0));
    assert!(bad.unwrap_err().to_string().contains("no link 7"));
}

#[test]
fn a_single_driven_joint_reports_the_torque_that_holds_its_load() {
    let mut world = World::default();
    let bar = LinkSpec {
        name: "bar".into(),
        parts: vec![Part::at(cuboid(0.15, 0.02, 0.02), v(0.15, 0.0, 1.0))],
        parent: None,
        joint: JointSpec {
            kind: JointKind::Revolute,
            model: JointModel::Multibody,
            anchor: v(0.0, 0.0, 1.0),
            axis: v(0.0, 1.0, 0.0),
            limits: None,
            damping: 0.0,
        },
        density: 500.0,
    };
    let post = ObjectSpec::new(
        "post",
        "post.n.04",
        vec![Part::at(cuboid(0.05, 0.05, 0.5), v(0.0, 0.0, 0.5))],
    );
    let post = world.add(post.fixed().link(bar)).unwrap();
    world
        .joints_mut()
        .drive(post, 0, Drive::position(0.0, 2000.0, 10.0, 100.0))
        .unwrap();
    steps(&mut world, 150);
    let state = world.joints().state(post, 0).unwrap();
    let moment = 0.3 * 0.04 * 0.04 * 500.0 * 9.81 * 0.15;
    assert!(
        (state.effort + moment).abs() < 0.01 * moment,
        "effort {} for {moment}",
        state.effort
    );
    // Released, the bar swings down; passive joints report their damping torque.
    world.joints_mut().release(post, 0).unwrap();
    steps(&mut world, 10);
    let falling = world.joints().state(post, 0).unwrap();
    assert!(
        falling.position > 0.1 && falling.velocity > 0.0,
        "{falling:?}"
    );
}

#[test]
fn an_attachment_holds_a_box_and_breaks_past_its_force() {
    let mut world = World::default();
    floor(&mut world);
    let hand = paddle(&mut world, BodyKind::KinematicPosition, v(0.0, 0.0, 1.0));
    let mut spec = ObjectSpec::new("box", "box.n.01", vec![Part::new(cuboid(0.05, 0.05, 0.05))])
        .at(v(0.0, 0.0, 0.85));
    spec.density = 1000.0; // 1 kg
    let held = world.add(spec).unwrap();
    let grasp = hold_at_50_n(&mut world, hand, held);
    steps(&mut world, 30);
    let state = world.attachments().get(grasp).unwrap();
    let z = world.bodies().pose(held).translation.z;
    assert!((z - 0.85).abs() < 0.01, "the held box hangs at {z}");
    assert!(!state.broken && state.violation < 0.01, "{state:?}");
    assert!(
        (state.force - 9.81).abs() < 2.0,
        "it carries the box's weight: {} N",
        state.force
    );
    // Pulling down with 200 N needs more than 50 N: it breaks and the box falls.
    world
        .bodies_mut()
        .apply_force(held.into(), v(0.0, 0.0, -200.0))
        .unwrap();
    world.step();
    assert!(world.attachments().get(grasp).unwrap().broken);
    steps(&mut world, 30);
    assert!(
        world.bodies().pose(held).translation.z < 0.1,
        "the released box fell"
    );
    assert!(world.attachments_mut().detach(grasp));
    assert!(world.attachments().get(grasp).is_none());
    // Pulled down with 200 N for a third of a step (as a lid meeting its hinge's limit pulls
    // on a carried carton), it holds: it breaks only when overloaded in half a step's
    // substeps, as PyBullet's force-limited constraint lets go only once it has drifted 0.1 m.
    world
        .bodies_mut()
        .set_pose(held, Pose::from_translation(v(0.0, 0.0, 0.85)))
        .unwrap();
    let pulled = hold_at_50_n(&mut world, hand, held);
    steps(&mut world, 10);
    let substeps = world.bodies().substeps().count();
    let mut pull = PullFor {
        body: held,
        substeps: (substeps - 1) / 3,
        most: 0.0,
        attachment: pulled,
    };
    world.step_with(&mut pull);
    assert!(
        pull.most > 50.0,
        "overloaded in some substeps: {} N",
        pull.most
    );
    let state = world.attachments().get(pulled).unwrap();
    assert!(!state.broken && state.violation < 0.01, "{state:?}");
    // Pulled for the whole step, it breaks.
    pull.substeps = substeps;
    world.step_with(&mut pull);
    assert!(world.attachments().get(pulled).unwrap().broken);
    assert!(world.attachments_mut().detach(pulled));
    // A point attachment lets the held box swing about the point.
    let point = world.bodies().pose(held).translation + v(0.0, 0.0, 0.05);
    let swing = world
        .attachments_mut()
        .attach(AttachmentSpec {
            holder: hand.into(),
            held: held.into(),
            at: point,
            kind: AttachmentKind::Point,
            max_force: 1e4,
        })
        .unwrap();
    world.step();
    assert!(!world.attachments().get(swing).unwrap().broken);
    let bad = world.attachments_mut().attach(AttachmentSpec {
        holder: hand.into(),
        held: hand.into(),
        at: Vector::ZERO,
        kind: AttachmentKind::Fixed,
        max_force: 1.0,
    });
    assert!(bad.is_err(), "a body cannot hold itself");
}

#[test]
fn contacts_name_the_other_body_with_points_normals_and_impulses() {
    let mut world = World::default();
    let floor = floor(&mut world);
    let cube = cube(&mut world, "cube", 0.0, 0.0, 0.1);
    steps(&mut world, 10);
    world.bodies_mut().set_sleeping_allowed(false);
    world.step();
    let contacts = world.contacts().of(cube.into()).unwrap();
    assert!(
        contacts.len() >= 3,
        "a box rests on its corners: {contacts:?}"
    );
    let mass = world.bodies().mass(cube);
    let substep = 1.0 / 300.0;
    let mut impulse = 0.0;
    for c in &contacts {
        assert_eq!(c.other, Some(BodyRef::from(floor)));
        assert!(c.point.z.abs() < 0.01, "at the floor: {}", c.point);
        assert!(
            c.normal.z < -0.99,
            "pointing from the box to the floor: {}",
            c.normal
        );
        impulse += c.impulse;
    }
    assert!(
        (impulse / substep - mass * 9.81).abs() < 0.1 * mass * 9.81,
        "the floor carries the box's weight: {} N",
        impulse / substep
    );
    let floor_side = world.contacts().of_object(floor);
    assert!(
        floor_side
            .iter()
            .all(|c| c.other == Some(BodyRef::from(cube)) && c.normal.z > 0.99)
    );
}

#[test]
fn ignored_pairs_pass_through_each_other_and_collision_groups_let_water_through() {
    let mut world = World::default();
    floor(&mut world);
    let bottom = cube(&mut world, "bottom", 0.0, 0.0, 0.1);
    let top = cube(&mut world, "top", 0.0, 0.0, 0.1);
    world
        .bodies_mut()
        .set_pose(top, Pose::from_translation(v(0.0, 0.0, 0.31)))
        .unwrap();
    steps(&mut world, 20);
    assert!(world.relations().ontop(top, bottom));
    world
        .contacts_mut()
        .ignore(top.into(), bottom.into(), true)
        .unwrap();
    assert!(world.contacts().ignored(bottom.into(), top.into()));
    steps(&mut world, 30);
    assert!(
        world.bodies().pose(top).translation.z < 0.15,
        "the top cube fell through the bottom one"
    );

    // A sink's drops splash on a plate and soak it; they fall through a plate that ignores water
    // (a robot's hand) and leave it dry.
    let splash = |filtered: bool| {
        let mut world = World::default();
        floor(&mut world);
        let sink = ObjectSpec::new(
            "sink",
            "sink.n.01",
            vec![Part::at(cuboid(0.05, 0.05, 0.05), v(0.0, 0.0, 1.5))],
        )
        .fixed()
        .ability(Ability::WaterSource, &[])
        .point(PointKind::WaterOutlet, v(0.0, 0.0, 1.44));
        world.add(sink).unwrap();
        let plate = ObjectSpec::new(
            "plate",
            "plate.n.04",
            vec![Part::new(cuboid(0.2, 0.2, 0.01))],
        )
        .at(v(0.0, 0.0, 0.8))
        .fixed()
        .ability(Ability::Soakable, &[]);
        let plate = world.add(plate).unwrap();
        if filtered {
            world
                .contacts_mut()
                .set_groups(plate, groups::ROBOT, groups::ALL & !groups::WATER);
        }
        steps(&mut world, 25);
        let below = world.drops().iter().filter(|d| d.z < 0.75).count();
        (below, world.state(plate, behavior_core::Predicate::Soaked))
    };
    assert_eq!(
        splash(false),
        (0, true),
        "the plate stops the drops and is soaked"
    );
    let (below, soaked) = splash(true);
    assert!(
        below > 0 && !soaked,
        "{below} drops fell through a plate that ignores water; soaked: {soaked}"
    );
}

#[test]
fn a_ray_finds_the_first_object_and_batched_rays_see_teleports_without_a_step() {
    let mut world = World::default();
    floor(&mut world);
    let near = cube(&mut world, "near", 1.0, 0.0, 0.1);
    let far = cube(&mut world, "far", 2.0, 0.0, 0.1);
    let (origin, along_x) = (v(0.0, 0.0, 0.1), v(1.0, 0.0, 0.0));
    let hit = world
        .query()
        .cast_ray(origin, along_x, 10.0, &QueryFilter::default())
        .unwrap()
        .unwrap();
    assert_eq!(hit.body, Some(BodyRef::from(near)));
    assert!((hit.distance - 0.9).abs() < 1e-3, "{hit:?}");
    assert!(
        hit.normal.x < -0.99,
        "the face seen is the one facing the ray"
    );
    let past_near = QueryFilter::excluding(&[near]);
    let hit = world
        .query()
        .cast_ray(origin, along_x, 10.0, &past_near)
        .unwrap()
        .unwrap();
    assert_eq!(hit.body, Some(BodyRef::from(far)));
    let lidar = [
        (origin, along_x),
        (origin, v(-1.0, 0.0, 0.0)),
        (v(0.0, 0.0, 1.0), v(0.0, 0.0, -1.0)),
    ];
    let hits = world
        .query()
        .cast_rays(&lidar, 3.0, &QueryFilter::default())
        .unwrap();
    assert_eq!(hits[0].and_then(|h| h.body), Some(near.into()));
    assert!(hits[1].is_none(), "nothing behind");
    assert!(
        (hits[2].unwrap().distance - 1.0).abs() < 1e-3,
        "the floor 1 m below"
    );
    // Moved without a step, the near cube is out of the way at once.
    world
        .bodies_mut()
        .set_pose(near, Pose::from_translation(v(1.0, 3.0, 0.1)))
        .unwrap();
    let hit = world
        .query()
        .cast_ray(origin, along_x, 10.0, &QueryFilter::default())
        .unwrap()
        .unwrap();
    assert_eq!(hit.body, Some(BodyRef::from(far)));
    let bad = world
        .query()
        .cast_ray(origin, v(0.0, 0.0, 0.0), 1.0, &QueryFilter::default());
    assert!(bad.is_err(), "a zero direction is an error");
}

#[test]
fn a_shape_query_reports_a_collision_and_a_distance_without_a_step() {
    let mut world = World::default();
    let floor = floor(&mut world);
    let table = table(&mut world, 0.0, 0.0);
    let probe = Primitive::Sphere { radius: 0.1 };
    let none = QueryFilter::default();
    let above_top = Pose::from_translation(v(0.0, 0.0, 0.8));
    assert_eq!(
        world.query().overlaps(&probe, above_top, &none).unwrap(),
        vec![BodyRef::from(table)]
    );
    let clear = Pose::from_translation(v(3.0, 3.0, 1.0));
    assert!(
        world
            .query()
            .overlaps(&probe, clear, &none)
            .unwrap()
            .is_empty()
    );
    let nearest = world
        .query()
        .nearest(&probe, clear, 5.0, &none)
        .unwrap()
        .unwrap();
    assert_eq!(nearest.body, BodyRef::from(floor));
    assert!((nearest.distance - 0.9).abs() < 1e-3, "{nearest:?}");
    // A cylinder (a robot's base) standing on the floor touches it; lifted 1 cm, it does not.
    let base = Primitive::Cylinder {
        radius: 0.3,
        half_height: 0.2,
    };
    let standing = Pose::from_translation(v(2.0, 0.0, 0.199));
    assert_eq!(
        world.query().overlaps(&base, standing, &none).unwrap(),
        vec![BodyRef::from(floor)]
    );
    let lifted = Pose::from_translation(v(2.0, 0.0, 0.21));
    assert!(
        world
            .query()
            .overlaps(&base, lifted, &QueryFilter::default())
            .unwrap()
            .is_empty()
    );
    assert!(
        world
            .query()
            .nearest(&base, lifted, 0.005, &none)
            .unwrap()
            .is_none()
    );
    let bad = Primitive::Sphere { radius: -1.0 };
    assert!(world.query().overlaps(&bad, lifted, &none).is_err());
}

#[test]
fn every_part_is_described_with_colour_material_and_pose_and_links_follow_their_joints() {
    let mut world = World::default();
    let red = Visual {
        color: [200, 20, 20],
        material: Material::Plastic,
    };
    let door = LinkSpec {
        name: "door".into(),
        parts: vec![Part::at(cuboid(0.2, 0.01, 0.3), v(0.2, -0.21, 0.3))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.0, -0.21, 0.0),
            v(0.0, 0.0, 1.0),
            1.5,
            1.0,
        ),
        density: 300.0,
    };
    let spec = ObjectSpec::new(
        "cabinet",
        "cabinet.n.01",
        vec![
            Part::at(cuboid(0.2, 0.2, 0.3), v(0.2, 0.0, 0.3)),
            Part::at(cuboid(0.02, 0.02, 0.02), v(0.3, -0.22, 0.5)).with_visual(red),
        ],
    )
    .fixed()
    .looks([120, 90, 60], Material::Wood)
    .link(door);
    let cabinet = world.add(spec).unwrap();
    let parts = world.visuals().parts(cabinet);
    assert_eq!(parts.len(), 3);
    assert_eq!(parts[0].visual.color, [120, 90, 60]);
    assert_eq!(parts[1].visual, red, "a part's own appearance wins");
    assert_eq!(parts[2].link, Some(0));
    assert!(matches!(
        parts[0].shape,
        VisualShape::Primitive(Primitive::Box { .. })
    ));
    let closed = parts[2].pose.translation;
    let body = parts[0].pose.translation;
    world.joints_mut().set_position(cabinet, 0, 1.5).unwrap();
    let open = world.visuals().parts(cabinet)[2].pose.translation;
    assert!(
        (open - closed).length() > 0.2,
        "the door part swung: {closed} → {open}"
    );
    assert!((body - v(0.2, 0.0, 0.3)).length() < 1e-6);
    // A cabinet naming a model piece: drawn from its parts until a library holds the piece,
    // then from the piece's meshes on its body (the door, a link, keeps its part). The world
    // keeps the name through a checkpoint.
    let piece = ModelPiece {
        model: Model::Fetch,
        piece: 7,
    };
    let parts = world.bodies().object(cabinet).parts.clone();
    let mut named = ObjectSpec::new("cabinet_2", "cabinet.n.01", parts).fixed();
    named.model = Some(piece);
    let named = world.add(named).unwrap();
    let mut library = ModelLibrary::default();
    let square = VisualMesh {
        link: None,
        vertices: vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)],
        triangles: vec![[0, 1, 2]],
        visual: red,
    };
    assert_eq!(world.visuals().parts_with(named, &library).len(), 2);
    library.insert(piece, vec![square.clone(), square]);
    let held = world.visuals().parts_with(named, &library);
    assert_eq!(held.len(), 2);
    assert!(
        matches!(held[1].shape, VisualShape::Piece { piece: p, index: 1, held } if p == piece && held.reach == 1.0 && held.bounds[1] == v(1.0, 1.0, 0.0)),
        "{:?}",
        held[1].shape
    );
    assert_eq!(held[0].visual, red);
    assert_eq!(
        world.visuals().parts(named).len(),
        2,
        "no library, its parts"
    );
    let loaded = World::from_bytes(&world.to_bytes()).unwrap();
    assert_eq!(loaded.bodies().object(named).model, Some(piece));
}

/// Counts hook calls and, as a controller would, drives a ball sideways every substep.
struct Counter {
    ball: ObjectId,
    before: u32,
    after: u32,
}

impl StepHooks for Counter {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        assert_eq!(substep, self.before % 10);
        self.before += 1;
        let push = Velocity {
            linear: v(1.0, 0.0, 0.0),
            angular: Vector::ZERO,
        };
        world
            .bodies_mut()
            .set_velocity(self.ball.into(), push)
            .unwrap();
    }

    fn after_step(&mut self, world: &mut World) {
        self.after += 1;
        assert_eq!(world.bodies().steps(), u64::from(self.after));
    }
}

#[test]
fn hooks_run_before_every_substep_and_after_each_step() {
    let mut world = World::default();
    floor(&mut world);
    let ball = world
        .add(
            ObjectSpec::new(
                "ball",
                "ball.n.01",
                vec![Part::new(Primitive::Sphere { radius: 0.05 })],
            )
            .at(v(0.0, 0.0, 0.05)),
        )
        .unwrap();
    let mut hooks = Counter {
        ball,
        before: 0,
        after: 0,
    };
    for _ in 0..30 {
        world.step_with(&mut hooks);
    }
    assert_eq!((hooks.before, hooks.after), (300, 30));
    let x = world.bodies().pose(ball).translation.x;
    assert!(
        (x - 1.0).abs() < 0.05,
        "driven at 1 m/s for 1 s, it went {x} m"
    );
}

#[test]
fn worlds_step_in_threads_and_a_reader_shares_one_while_another_steps() {
    let mut template = World::default();
    floor(&mut template);
    let t = table(&mut template, 0.0, 0.0);
    let apple = apple(&mut template, "apple", v(0.0, 0.0, 1.2));
    let mut sequential = template.clone();
    steps(&mut sequential, 60);
    let expected = sequential.bodies().motion_bits();
    let (mut a, mut b) = (template.clone(), template.clone());
    let reader = &sequential;
    std::thread::scope(|s| {
        s.spawn(|| steps(&mut a, 60));
        s.spawn(|| steps(&mut b, 60));
        // A renderer reads a settled world while the others step.
        s.spawn(move || assert!(reader.relations().ontop(apple, t)));
    });
    assert_eq!(a.bodies().motion_bits(), expected);
    assert_eq!(b.bodies().motion_bits(), expected);
}

#[test]
fn snapshots_of_an_arm_holding_a_box_restore_bit_identically() {
    let mut world = World::default();
    floor(&mut world);
    let arm = multibody_arm(&mut world, 0.0, 0.0);
    let held = cube(&mut world, "held", 0.9, 0.0, 0.03);
    world
        .bodies_mut()
        .set_pose(
            held,
            Pose::from_parts(v(0.92, 0.0, 0.95), Rotation::IDENTITY),
        )
        .unwrap();
    world
        .attachments_mut()
        .attach(AttachmentSpec {
            holder: BodyRef::link(arm, 2),
            held: held.into(),
            at: v(0.9, 0.0, 0.98),
            kind: AttachmentKind::Fixed,
            max_force: 500.0,
        })
        .unwrap();
    for (k, target) in [0.3f32, 0.2, -0.4].into_iter().enumerate() {
        world
            .joints_mut()
            .drive(arm, k, Drive::position(target, 1000.0, 50.0, 300.0))
            .unwrap();
    }
    steps(&mut world, 20);
    let snapshot = world.snapshot();
    steps(&mut world, 40);
    let end = world.bodies().motion_bits();
    world.restore(&snapshot);
    steps(&mut world, 40);
    assert_eq!(world.bodies().motion_bits(), end, "rewound and replayed");
    let mut fresh = World::default();
    fresh.restore(&snapshot);
    steps(&mut fresh, 40);
    assert_eq!(
        fresh.bodies().motion_bits(),
        end,
        "restored into another world"
    );
}

#[test]
fn a_velocity_driven_base_carries_its_multibody_arm_and_the_arm_keeps_its_targets() {
    let mut world = World::default();
    floor(&mut world);
    let mut base = ObjectSpec::new(
        "robot",
        "robot.n.01",
        vec![Part::at(cuboid(0.25, 0.25, 0.15), v(0.0, 0.0, 0.15))],
    )
    .at(v(0.0, 0.0, 0.001))
    .body(BodyKind::KinematicVelocity);
    for k in 0..2 {
        let z0 = 0.3 + 0.3 * k as f32;
        base = base.link(LinkSpec {
            name: format!("segment_{k}"),
            parts: vec![Part::at(cuboid(0.02, 0.02, 0.15), v(0.0, 0.0, z0 + 0.15))],
            parent: if k == 0 { None } else { Some(k - 1) },
            joint: JointSpec {
                kind: JointKind::Revolute,
                model: JointModel::Multibody,
                anchor: v(0.0, 0.0, z0),
                axis: v(0.0, 1.0, 0.0),
                limits: Some([-1.5, 1.5]),
                damping: 0.0,
            },
            density: 500.0,
        });
    }
    let robot = world.add(base).unwrap();
    for (k, target) in [0.3f32, -0.4].into_iter().enumerate() {
        world
            .joints_mut()
            .drive(robot, k, Drive::position(target, 500.0, 20.0, 100.0))
            .unwrap();
    }
    let drive = Velocity {
        linear: v(0.5, 0.0, 0.0),
        angular: Vector::ZERO,
    };
    world
        .bodies_mut()
        .set_velocity(robot.into(), drive)
        .unwrap();
    steps(&mut world, 60);
    let x = world.bodies().pose(robot).translation.x;
    assert!((x - 1.0).abs() < 0.01, "the base drove to x = {x}");
    let elbow = world.bodies().link_pose(robot, 1).translation.x;
    assert!(
        elbow > 0.9,
        "the arm came along: its last segment is at x = {elbow}"
    );
    for (k, target) in [0.3f32, -0.4].into_iter().enumerate() {
        let q = world.joints().state(robot, k).unwrap().position;
        assert!((q - target).abs() < 0.02, "joint {k} at {q} for {target}");
    }
}

#[test]
fn masses_of_bodies_links_and_whole_objects_and_the_gravity_they_feel() {
    use behavior_sim::{BodyRef, JointKind, JointSpec, LinkSpec, ObjectSpec, Part};
    let mut world = World::default();
    // A 20 × 20 × 10 cm box of 1000 kg/m³ (4 kg) with a 20 × 20 × 1 cm lid of 500 kg/m³ (0.2 kg).
    let mut spec = ObjectSpec::new(
        "box_1",
        "carton.n.02",
        vec![Part::new(cuboid(0.1, 0.1, 0.05))],
    );
    spec.density = 1000.0;
    let lid = LinkSpec {
        name: "lid".into(),
        parts: vec![Part::at(cuboid(0.1, 0.1, 0.005), v(0.0, 0.0, 0.055))],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(0.0, 0.1, 0.05),
            v(-1.0, 0.0, 0.0),
            1.5,
            1.0,
        ),
        density: 500.0,
    };
    let id = world.add(spec.link(lid)).unwrap();
    let body = world.bodies().body_mass(BodyRef::from(id)).unwrap();
    let link = world
        .bodies()
        .body_mass(BodyRef {
            object: id,
            link: Some(0),
        })
        .unwrap();
    assert!(
        (body - 4.0).abs() < 1e-3 && (link - 0.2).abs() < 1e-4,
        "{body} {link}"
    );
    assert!((world.bodies().total_mass(id) - 4.2).abs() < 1e-3);
    assert_eq!(world.bodies().mass(id), body);
    assert!(
        world
            .bodies()
            .body_mass(BodyRef {
                object: id,
                link: Some(3)
            })
            .is_err()
    );
    assert_eq!(world.bodies().gravity(), v(0.0, 0.0, -9.81));
}

#[test]
fn a_part_moved_within_its_body_is_where_queries_drawing_and_mass_find_it() {
    let mut world = World::default();
    floor(&mut world);
    // A 40 × 40 × 4 cm slab on the floor with a 10 cm cube standing on its +x edge.
    let flag = Pose::from_translation(v(0.15, 0.0, 0.07));
    let spec = ObjectSpec::new(
        "signpost",
        "box.n.01",
        vec![
            Part::new(cuboid(0.2, 0.2, 0.02)),
            Part {
                offset: flag,
                ..Part::new(cuboid(0.05, 0.05, 0.05))
            },
        ],
    )
    .at(v(0.0, 0.0, 0.021));
    let id = world.add(spec).unwrap();
    steps(&mut world, 5);
    let body = BodyRef::from(id);
    let before = world.bodies().centre_of_mass(body).unwrap();
    assert!(
        before.x > 0.01,
        "the cube weighs on the +x side: {before:?}"
    );

    // Over to the −x edge.
    let moved = Pose::from_translation(v(-0.15, 0.0, 0.07));
    world.bodies_mut().set_part_offset(id, 1, moved).unwrap();
    assert_eq!(world.bodies().object(id).parts[1].offset, moved);
    steps(&mut world, 1);
    let after = world.bodies().centre_of_mass(body).unwrap();
    assert!((after.x + before.x).abs() < 0.01, "{before:?} → {after:?}");
    let down = |x: f32| {
        let hit = world.query().cast_ray(
            v(x, 0.0, 1.0),
            v(0.0, 0.0, -1.0),
            2.0,
            &QueryFilter::default(),
        );
        hit.unwrap().unwrap().point.z
    };
    let top = world.bodies().pose(id).translation.z;
    assert!(
        (down(-0.15) - (top + 0.12)).abs() < 0.01,
        "the cube is at −x now"
    );
    assert!(
        (down(0.15) - (top + 0.02)).abs() < 0.01,
        "and no longer at +x"
    );
    let drawn = world.visuals().parts(id)[1].pose.translation;
    assert!((drawn - world.bodies().pose(id).transform_point(moved.translation)).length() < 1e-5);

    // A part it does not have, or a pose that is not finite: refused, nothing changed.
    assert!(world.bodies_mut().set_part_offset(id, 2, moved).is_err());
    let nan = Pose::from_translation(v(f32::NAN, 0.0, 0.0));
    assert!(world.bodies_mut().set_part_offset(id, 1, nan).is_err());
    assert_eq!(world.bodies().object(id).parts[1].offset, moved);
}

/// Pulls `body` down with 200 N for the first `substeps` substeps of a step, noting the most
/// force `attachment` applied in them.
struct PullFor {
    body: ObjectId,
    substeps: u32,
    most: f32,
    attachment: behavior_sim::AttachmentId,
}

impl StepHooks for PullFor {
    fn before_substep(&mut self, world: &mut World, substep: u32) {
        if let Some(state) = world.attachments().get(self.attachment) {
            self.most = self.most.max(state.force);
        }
        // The force lasts the rest of the step: pushed, then cancelled.
        let force = match substep {
            0 => -200.0,
            s if s == self.substeps => 200.0,
            _ => return,
        };
        world
            .bodies_mut()
            .apply_force(self.body.into(), v(0.0, 0.0, force))
            .unwrap();
    }
}

/// `held` attached to `hand` at (0, 0, 0.9), fixed, at most 50 N.
fn hold_at_50_n(world: &mut World, hand: ObjectId, held: ObjectId) -> behavior_sim::AttachmentId {
    let spec = AttachmentSpec {
        holder: hand.into(),
        held: held.into(),
        at: v(0.0, 0.0, 0.9),
        kind: AttachmentKind::Fixed,
        max_force: 50.0,
    };
    world.attachments_mut().attach(spec).unwrap()
}
