//! Checkpoints: a world saved to bytes mid-motion and loaded into a new world continues
//! bit-identically, a loaded world saves to the same bytes, and bad bytes are refused with an
//! error, never a panic.

mod common;

use behavior_core::Predicate;
use behavior_sim::{
    AttachmentId, AttachmentKind, AttachmentSpec, BodyRef, Drive, ObjectId, QueryFilter,
    WORLD_FORMAT_VERSION, World, WorldBytesError,
};
use common::*;

/// Everything that moves at once: 30 boxes, balls and cylinders falling onto a bin and each
/// other (two of them glued by an attachment), a three-link multibody arm driven toward targets,
/// a fridge whose door (an impulse joint) is driven open, an apple heating on a stove that is on,
/// a running tap with its drops, a dusty plate, and the setters' generator drawn from.
fn busy_scene() -> World {
    let mut world = World::default();
    world.reseed(7);
    two_room_floor(&mut world);
    open_box(&mut world, 0.5, 0.5);
    let mut things = Vec::new();
    for i in 0..30 {
        things.push(world.add(column_thing(i, 0.5, 0.07)).unwrap());
    }
    let glued_at = world.bodies().pose(things[0]).translation;
    world
        .attachments_mut()
        .attach(AttachmentSpec {
            holder: things[0].into(),
            held: things[4].into(),
            at: glued_at,
            kind: AttachmentKind::Point,
            max_force: 1000.0,
        })
        .unwrap();
    let arm = multibody_arm(&mut world, -2.0, 2.0);
    for (k, target) in [0.5, -0.3, 0.4].into_iter().enumerate() {
        world
            .joints_mut()
            .drive(arm, k, Drive::position(target, 2000.0, 100.0, 500.0))
            .unwrap();
    }
    let fridge = fridge(&mut world, -3.0, -2.0);
    world
        .joints_mut()
        .drive(fridge, 0, Drive::velocity(0.8, 50.0, 50.0))
        .unwrap();
    let stove = stove(&mut world, -1.0, 0.0);
    sliceable_apple(&mut world, "apple_1", v(-1.0, 0.0, 1.0));
    let sink = sink(&mut world, 1.5, -2.0);
    rag(&mut world, v(1.5, -1.85, 0.7));
    let plate = dirty_plate(&mut world, v(-3.0, 2.0, 0.05));
    world.set_state(stove, Predicate::ToggledOn, true).unwrap();
    world.set_state(sink, Predicate::ToggledOn, true).unwrap();
    world.set_state(plate, Predicate::Dusty, true).unwrap();
    world
}

fn run(world: &mut World, steps: usize) {
    for _ in 0..steps {
        world.step();
    }
}

/// Every body's pose and velocity bits, the drops' positions, and every object's non-geometric
/// state (temperatures, switches, particles), printed exactly.
fn digest(world: &World) -> (Vec<u32>, Vec<u32>, String) {
    let drops = world
        .drops()
        .iter()
        .flat_map(|d| [d.x.to_bits(), d.y.to_bits(), d.z.to_bits()])
        .collect();
    let states = world
        .bodies()
        .objects()
        .map(|(id, _)| format!("{:?}", world.object_state(id)))
        .collect();
    (world.bodies().motion_bits(), drops, states)
}

#[test]
fn world_bytes_a_world_loaded_mid_motion_continues_bit_identically() {
    let mut original = busy_scene();
    run(&mut original, 25);
    // Mid-motion: bodies fall and collide, the arm swings, the door opens, drops fly.
    let moving = original
        .bodies()
        .objects()
        .filter(|(id, o)| {
            !o.is_fixed()
                && original
                    .bodies()
                    .velocity((*id).into())
                    .unwrap()
                    .linear
                    .length()
                    > 0.1
        })
        .count();
    assert!(moving >= 10, "only {moving} objects move");
    assert!(!original.drops().is_empty());
    let door = original
        .joints()
        .state(original.bodies().object_named("fridge_1").unwrap(), 0);
    assert!(door.unwrap().velocity.abs() > 0.01);

    let bytes = original.to_bytes();
    let mut loaded = World::from_bytes(&bytes).unwrap();
    assert_eq!(digest(&loaded), digest(&original), "loaded as saved");
    // A snapshot of the original, stepped alongside, shows what a clone does.
    let mut cloned = original.clone();
    for step in 0..60 {
        original.step();
        loaded.step();
        cloned.step();
        assert_eq!(
            loaded.bodies().motion_bits(),
            original.bodies().motion_bits(),
            "step {step} after loading"
        );
    }
    assert_eq!(digest(&loaded), digest(&original));
    assert_eq!(digest(&cloned), digest(&original));
    // The full states agree, not only the digests.
    assert_eq!(loaded.to_bytes(), original.to_bytes());
    assert!(original.temperature(original.bodies().object_named("apple_1").unwrap()) > 30.0);

    // Rebuilt caches answer as the original's: rays see the same thing.
    let ray = (v(0.5, 0.5, 3.0), v(0.0, 0.0, -1.0));
    let filter = QueryFilter::default();
    assert_eq!(
        loaded.query().cast_ray(ray.0, ray.1, 5.0, &filter).unwrap(),
        original
            .query()
            .cast_ray(ray.0, ray.1, 5.0, &filter)
            .unwrap()
    );
}

#[test]
fn world_bytes_a_loaded_world_saves_to_the_same_bytes() {
    let empty = World::default();
    let bytes = empty.to_bytes();
    assert_eq!(World::from_bytes(&bytes).unwrap().to_bytes(), bytes);

    let mut world = busy_scene();
    run(&mut world, 25);
    // Relations asked before saving are memoized; they are saved too, in a fixed order.
    let apple = world.bodies().object_named("apple_1").unwrap();
    let stove = world.bodies().object_named("stove_1").unwrap();
    let _ = world.relations().ontop(apple, stove);
    let bytes = world.to_bytes();
    assert_eq!(world.to_bytes(), bytes, "saving twice");
    let loaded = World::from_bytes(&bytes).unwrap();
    assert_eq!(loaded.to_bytes(), bytes, "loaded and saved again");
    assert_eq!(loaded.clone().to_bytes(), bytes, "a clone of it");
}

#[test]
fn world_bytes_truncated_corrupt_and_foreign_bytes_are_errors_not_panics() {
    let mut world = busy_scene();
    run(&mut world, 10);
    let bytes = world.to_bytes();
    let len = bytes.len();

    for cut in [
        0,
        1,
        7,
        8,
        11,
        12,
        16,
        23,
        24,
        25,
        len / 3,
        len / 2,
        len - 1,
    ] {
        let error = World::from_bytes(&bytes[..cut]).err();
        assert!(
            matches!(
                error,
                Some(WorldBytesError::Truncated { .. } | WorldBytesError::NotAWorld)
            ),
            "cut at {cut} of {len}: {error:?}"
        );
    }
    let too_long = [bytes.as_slice(), &[0]].concat();
    assert_eq!(
        World::from_bytes(&too_long).err(),
        Some(WorldBytesError::TrailingBytes { extra: 1 })
    );

    // Every header byte, and payload bytes spread over the whole payload, flipped.
    let positions = (0..24).chain((24..len).step_by((len / 500).max(1)));
    for at in positions {
        let mut bad = bytes.clone();
        bad[at] ^= 0x5a;
        assert!(World::from_bytes(&bad).is_err(), "byte {at} flipped");
    }

    let mut foreign = bytes.clone();
    foreign[..8].copy_from_slice(b"PNG\r\n\x1a\n\0");
    let error = World::from_bytes(&foreign).err().unwrap();
    assert_eq!(error, WorldBytesError::NotAWorld);
    assert!(error.to_string().contains("not a saved BEHAVIOR world"));

    let mut newer = bytes.clone();
    newer[8..12].copy_from_slice(&(WORLD_FORMAT_VERSION + 1).to_le_bytes());
    let error = World::from_bytes(&newer).err().unwrap();
    assert_eq!(
        error,
        WorldBytesError::Version {
            found: WORLD_FORMAT_VERSION + 1,
            expected: WORLD_FORMAT_VERSION
        }
    );
    let message = error.to_string();
    assert!(
        message.contains(&format!("format version {}", WORLD_FORMAT_VERSION + 1)),
        "{message}"
    );
}

/// Past the checksum: payload bytes changed and the checksum made to match, as a buggy or
/// hostile writer would, still decode to an error or a consistent world, never a panic.
#[test]
fn world_bytes_a_payload_that_passes_the_checksum_but_is_corrupt_does_not_panic() {
    let mut world = busy_scene();
    run(&mut world, 10);
    let bytes = world.to_bytes();
    let len = bytes.len();
    let mut errors = 0;
    let reseal = |bad: &mut Vec<u8>| {
        let crc = crc32fast::hash(&bad[24..]);
        bad[12..16].copy_from_slice(&crc.to_le_bytes());
    };
    for (k, at) in (24..len).step_by((len / 300).max(1)).enumerate() {
        let mut bad = bytes.clone();
        bad[at] = bad[at].wrapping_add(1 + (k % 255) as u8);
        reseal(&mut bad);
        errors += usize::from(World::from_bytes(&bad).is_err());
    }
    // A cut payload, with its header saying so.
    for cut in [1, len / 4, len / 2, len - 30] {
        let mut bad = bytes[..len - cut].to_vec();
        bad[16..24].copy_from_slice(&((len - cut - 24) as u64).to_le_bytes());
        reseal(&mut bad);
        assert!(matches!(
            World::from_bytes(&bad),
            Err(WorldBytesError::Decode(_) | WorldBytesError::Inconsistent(_))
        ));
    }
    assert!(errors > 0, "no changed payload was refused");
}

#[test]
fn world_bytes_public_ids_serialize() {
    let body = BodyRef::link(ObjectId(3), 1);
    let attachment = AttachmentId(9);
    let text = serde_json::to_string(&(ObjectId(3), body, attachment)).unwrap();
    let back: (ObjectId, BodyRef, AttachmentId) = serde_json::from_str(&text).unwrap();
    assert_eq!(back, (ObjectId(3), body, attachment));
}

/// Saved right after changes made between steps — a new attachment, a teleport, a new drive —
/// before any step has taken them in, the loaded world still continues as the original.
#[test]
fn world_bytes_changes_made_between_steps_are_saved_too() {
    let mut original = busy_scene();
    run(&mut original, 40);
    let a = original.bodies().object_named("thing_10").unwrap();
    let b = original.bodies().object_named("thing_11").unwrap();
    let at = original.bodies().pose(a).translation;
    original
        .attachments_mut()
        .attach(AttachmentSpec {
            holder: a.into(),
            held: b.into(),
            at,
            kind: AttachmentKind::Fixed,
            max_force: 1000.0,
        })
        .unwrap();
    let c = original.bodies().object_named("thing_20").unwrap();
    let mut pose = original.bodies().pose(c);
    pose.translation.z += 0.3;
    original.bodies_mut().set_pose(c, pose).unwrap();
    let fridge = original.bodies().object_named("fridge_1").unwrap();
    original
        .joints_mut()
        .drive(fridge, 0, Drive::position(0.2, 200.0, 20.0, 50.0))
        .unwrap();
    let mut loaded = World::from_bytes(&original.to_bytes()).unwrap();
    for step in 0..60 {
        original.step();
        loaded.step();
        assert_eq!(
            loaded.bodies().motion_bits(),
            original.bodies().motion_bits(),
            "step {step} after loading"
        );
    }
    assert_eq!(digest(&loaded), digest(&original));
}
