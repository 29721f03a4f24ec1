//! The tool primitives with physics — SLICE, SOAK and WIPE — and a switch pressed by hand, by
//! each robot in a small real scene (our own activities, `activities/`): the tool taken and the
//! robot brought to the target by the physical primitives, a call the primitive refuses
//! (nothing moves), then the primitive doing what the world's own rule asks (the lemon cut in
//! two, the towel soaked, dust taken off the table, the printer switched on). Physics makes
//! runs chaotic, so each robot is given a few seeds: on one of them the primitive must succeed.
//! The toggle is called through `press`, which has no kinematic fallback: a switch that flips
//! was pressed by the hand.

#[path = "../../env/tests/common/mod.rs"]
mod common;
mod support;

use behavior_core::Predicate;
use behavior_env::Env;
use behavior_planning::{Call, Failure, Mode, Primitive, Tuning, press, run};
use behavior_robots::RobotKind;
use behavior_sim::ObjectId;

/// The robots, and the seeds each one's episodes try in turn.
const ROBOTS: [RobotKind; 3] = [RobotKind::Behavior, RobotKind::Fetch, RobotKind::R1];
const SEEDS: [u64; 10] = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9];

/// One tool primitive's case: the own activity whose scene it runs in, the tool and the target
/// (instance names), the refused call and what the refusal says, a switch turned on after it
/// (the tap), and the effect the primitive must have.
struct Case {
    activity: &'static str,
    tool: &'static str,
    target: &'static str,
    refused: (Primitive, &'static str, &'static str),
    switch_on: Option<&'static str>,
    primitive: Primitive,
    effect: Effect,
}

/// What a tool primitive does by the world's rules.
#[derive(Clone, Copy, Debug)]
enum Effect {
    /// The target cut in two.
    TargetSliced,
    /// The tool soaked.
    ToolSoaked,
    /// Dust taken off the target: fewer particles than before (one WIPE cleans what the tool
    /// reaches from one place; the planner wipes from several).
    DustTaken,
}

/// The target's dust particles.
fn dust(env: &Env, target: ObjectId) -> usize {
    let world = env.world().unwrap();
    world.particle_positions(target, Predicate::Dusty).len()
}

fn object(env: &Env, instance: &str) -> ObjectId {
    let k = env.config().activity.instance_named(instance).unwrap();
    env.bindings().unwrap()[k.0 as usize].unwrap()
}

fn act(env: &mut Env, primitive: Primitive, object: ObjectId) -> Result<(), Failure> {
    let call = Call {
        primitive,
        object,
        hand: 0,
    };
    run(env, call, Mode::Physical, None).unwrap().result
}

/// Whether the episode's robot holds `x` (in its first hand, the tool's).
fn holds(env: &Env, x: ObjectId) -> bool {
    env.robot().unwrap().held(0) == Some(x)
}

/// Runs `case` for `robot` on each seed until the primitive has its effect; panics, with
/// every seed's outcome, where it never does. A seed whose preparation (drive, grasp, drive)
/// fails moves on to the next; the refusal is checked on every seed prepared.
fn check(case: &Case, robot: RobotKind) {
    let mut outcomes = Vec::new();
    for seed in SEEDS {
        let config = support::physical(support::own_config(case.activity), robot);
        let mut env = Env::new(config);
        env.reset(seed).unwrap();
        let (tool, target) = (object(&env, case.tool), object(&env, case.target));
        let prepared = act(&mut env, Primitive::NavigateTo, tool)
            .and_then(|()| act(&mut env, Primitive::Grasp, tool))
            .and_then(|()| act(&mut env, Primitive::NavigateTo, target));
        let prepared = prepared.and_then(|()| {
            if holds(&env, tool) {
                Ok(())
            } else {
                Err(Failure::HandEmpty)
            }
        });
        if let Err(why) = prepared {
            outcomes.push(format!("seed {seed}: not prepared: {why}"));
            continue;
        }
        let (primitive, instance, says) = case.refused;
        let wrong = object(&env, instance);
        let steps = env.steps();
        let refusal = act(&mut env, primitive, wrong).expect_err("the wrong call is refused");
        assert!(
            refusal.to_string().contains(says),
            "{} ({}), seed {seed}: {} {instance}: {refusal}",
            case.activity,
            robot.name(),
            primitive.name()
        );
        // A refused primitive takes only the still step after it.
        assert_eq!(env.steps(), steps + 1, "the refusal moved nothing");
        if let Some(switch) = case.switch_on {
            let switch = object(&env, switch);
            act(&mut env, Primitive::ToggleOn, switch).unwrap();
        }
        let before = dust(&env, target);
        let done = act(&mut env, case.primitive, target);
        let world = env.world().unwrap();
        let had = match case.effect {
            Effect::TargetSliced => world.state(target, Predicate::Sliced),
            Effect::ToolSoaked => world.state(tool, Predicate::Soaked),
            Effect::DustTaken => dust(&env, target) < before,
        };
        if had {
            return;
        }
        outcomes.push(format!("seed {seed}: {done:?}"));
    }
    panic!(
        "{} ({}): {} never had its effect, {:?}: {outcomes:#?}",
        case.activity,
        robot.name(),
        case.primitive.name(),
        case.effect
    );
}

const SLICE: Case = Case {
    activity: "serving_a_sliced_lemon",
    tool: "carving_knife.n.01_1",
    target: "lemon.n.01_1",
    refused: (Primitive::Slice, "countertop.n.01_1", "is not sliceable"),
    switch_on: None,
    primitive: Primitive::Slice,
    effect: Effect::TargetSliced,
};

const SOAK: Case = Case {
    activity: "wetting_a_dishtowel",
    tool: "dishtowel.n.01_1",
    target: "sink.n.01_1",
    refused: (Primitive::Soak, "sink.n.01_1", "the water source is off"),
    switch_on: Some("sink.n.01_1"),
    primitive: Primitive::Soak,
    effect: Effect::ToolSoaked,
};

const WIPE: Case = Case {
    activity: "dusting_the_living_room_table",
    tool: "rag.n.01_1",
    target: "table.n.02_1",
    refused: (Primitive::Wipe, "floor.n.01_1", "already clean"),
    switch_on: None,
    primitive: Primitive::Wipe,
    effect: Effect::DustTaken,
};

#[test]
fn each_robot_cuts_a_lemon_with_a_held_knife_and_refuses_to_cut_the_counter() {
    for robot in ROBOTS {
        check(&SLICE, robot);
    }
}

#[test]
fn each_robot_soaks_a_towel_under_a_running_tap_and_is_refused_while_it_is_off() {
    for robot in ROBOTS {
        check(&SOAK, robot);
    }
}

#[test]
fn each_robot_dusts_a_table_with_a_held_rag_and_refuses_to_wipe_a_clean_floor() {
    for robot in ROBOTS {
        check(&WIPE, robot);
    }
}

#[test]
fn each_robot_switches_a_printer_on_by_hand_and_is_refused_a_table() {
    for robot in ROBOTS {
        let mut outcomes = Vec::new();
        let mut pressed = false;
        for seed in SEEDS {
            let config = support::physical(support::own_config("switching_on_the_printer"), robot);
            let mut env = Env::new(config);
            env.reset(seed).unwrap();
            let (printer, table) = (object(&env, "printer.n.03_1"), object(&env, "table.n.02_1"));
            if let Err(why) = act(&mut env, Primitive::NavigateTo, printer) {
                outcomes.push(format!("seed {seed}: not prepared: {why}"));
                continue;
            }
            // The hand the planner presses with: the carrying one (the right, Fetch's only).
            let hand = env.robot().unwrap().hands() - 1;
            let call = |object| Call {
                primitive: Primitive::ToggleOn,
                object,
                hand,
            };
            let steps = env.steps();
            let refused = press(&mut env, &call(table), &Tuning::default(), None).unwrap();
            assert!(
                matches!(
                    refused,
                    Err(Failure::Unable {
                        what: "is not toggleable"
                    })
                ),
                "{} seed {seed}: {refused:?}",
                robot.name()
            );
            assert_eq!(env.steps(), steps, "the refusal took no step");
            // `press` has no kinematic fallback: the hand switched it, or nothing did.
            let done = press(&mut env, &call(printer), &Tuning::default(), None).unwrap();
            if env.world().unwrap().state(printer, Predicate::ToggledOn) {
                assert!(env.steps() > steps + 5, "the hand was held at the button");
                pressed = true;
                break;
            }
            outcomes.push(format!("seed {seed}: {done:?}"));
        }
        assert!(
            pressed,
            "{}: the printer was never switched on by hand: {outcomes:#?}",
            robot.name()
        );
    }
}
