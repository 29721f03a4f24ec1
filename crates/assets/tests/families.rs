//! Homes of every plan family, over many seeds: they generate, every room meets its type's
//! specification, L-shaped rooms are made and open along their inner side, every rectangle of
//! every room is reached from outside by a disc as wide as each robot's base, windows stand in
//! outside walls, no furniture stands in front of a doorway, and rugs lie in their rooms.

use behavior_assets::{Family, Library, Scene, generate_family, room_spec};
use behavior_core::RoomType;
use behavior_data::DataDir;
use behavior_sim::FloorRect;
use std::collections::{BTreeMap, BTreeSet};

/// Seeds per family.
const SEEDS: u64 = 100;
/// The BehaviorRobot's body radius and Fetch's base radius with 2 cm to spare, m.
const ROBOTS: [(&str, f32); 2] = [("BehaviorRobot", 0.25), ("Fetch", 0.30)];
/// The reachability grid's cell, m.
const CELL: f32 = 0.05;

fn library_taxonomy() -> behavior_bddl::Taxonomy {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap()
}

/// An axis-aligned rectangle on the floor: min and max corners.
type Rect = ([f32; 2], [f32; 2]);

/// What blocks a robot's base: walls and furniture (doors are opened first and windows stand in
/// the walls).
fn obstacles(scene: &Scene) -> Vec<Rect> {
    let walls = scene
        .walls
        .iter()
        .map(|w| ([w.min[0], w.min[1]], [w.max[0], w.max[1]]));
    let furniture = scene
        .objects
        .iter()
        .filter(|o| o.synset != "door.n.01" && o.synset != "window.n.01")
        .map(|o| {
            let (w, d) = if o.yaw_quarter_turns % 2 == 0 {
                (o.size[0], o.size[1])
            } else {
                (o.size[1], o.size[0])
            };
            let [x, y, _] = o.position;
            ([x - w / 2.0, y - d / 2.0], [x + w / 2.0, y + d / 2.0])
        });
    walls.chain(furniture).collect()
}

/// For each room, whether a disc of `radius` coming from outside the house reaches a place
/// inside it, on a grid of [`CELL`].
fn reachable_rooms(scene: &Scene, radius: f32) -> Vec<Vec<bool>> {
    let margin = 1.0;
    let rects: Vec<_> = scene.rooms.iter().flat_map(|r| r.rects()).collect();
    let lo = [0, 1].map(|k| rects.iter().map(|r| r.min[k]).fold(f32::MAX, f32::min) - margin);
    let hi = [0, 1].map(|k| rects.iter().map(|r| r.max[k]).fold(f32::MIN, f32::max) + margin);
    let n = [
        ((hi[0] - lo[0]) / CELL).ceil() as usize,
        ((hi[1] - lo[1]) / CELL).ceil() as usize,
    ];
    let centre = |i: usize, j: usize| {
        [
            lo[0] + (i as f32 + 0.5) * CELL,
            lo[1] + (j as f32 + 0.5) * CELL,
        ]
    };
    let mut blocked = vec![false; n[0] * n[1]];
    for (min, max) in obstacles(scene) {
        let i0 = (((min[0] - radius - lo[0]) / CELL).floor().max(0.0)) as usize;
        let j0 = (((min[1] - radius - lo[1]) / CELL).floor().max(0.0)) as usize;
        let i1 = (((max[0] + radius - lo[0]) / CELL).ceil() as usize).min(n[0]);
        let j1 = (((max[1] + radius - lo[1]) / CELL).ceil() as usize).min(n[1]);
        for i in i0..i1 {
            for j in j0..j1 {
                let [x, y] = centre(i, j);
                let dx = (min[0] - x).max(x - max[0]).max(0.0);
                let dy = (min[1] - y).max(y - max[1]).max(0.0);
                if dx * dx + dy * dy < radius * radius {
                    blocked[i * n[1] + j] = true;
                }
            }
        }
    }
    let mut seen = vec![false; blocked.len()];
    let mut queue = vec![(0usize, 0usize)];
    seen[0] = true;
    while let Some((i, j)) = queue.pop() {
        let mut visit = |a: usize, b: usize| {
            let k = a * n[1] + b;
            if !blocked[k] && !seen[k] {
                seen[k] = true;
                queue.push((a, b));
            }
        };
        if i > 0 {
            visit(i - 1, j);
        }
        if i + 1 < n[0] {
            visit(i + 1, j);
        }
        if j > 0 {
            visit(i, j - 1);
        }
        if j + 1 < n[1] {
            visit(i, j + 1);
        }
    }
    // For each room, for each of its rectangles.
    let mut reached: Vec<Vec<bool>> = scene
        .rooms
        .iter()
        .map(|r| vec![false; r.rects().count()])
        .collect();
    for i in 0..n[0] {
        for j in 0..n[1] {
            if seen[i * n[1] + j] {
                let [x, y] = centre(i, j);
                for (k, r) in scene.rooms.iter().enumerate() {
                    for (m, p) in r.rects().enumerate() {
                        if p.min[0] < x && x < p.max[0] && p.min[1] < y && y < p.max[1] {
                            reached[k][m] = true;
                        }
                    }
                }
            }
        }
    }
    reached
}

/// The side two rectangles share, as its two ends, if they meet along one.
fn shared_side(a: &FloorRect, b: &FloorRect) -> Option<([f32; 2], [f32; 2])> {
    for (across, along) in [(0, 1), (1, 0)] {
        let at = if (a.max[across] - b.min[across]).abs() < 1e-3 {
            a.max[across]
        } else if (a.min[across] - b.max[across]).abs() < 1e-3 {
            a.min[across]
        } else {
            continue;
        };
        let (lo, hi) = (
            a.min[along].max(b.min[along]),
            a.max[along].min(b.max[along]),
        );
        if hi - lo > 1e-3 {
            let point = |t: f32| if across == 0 { [at, t] } else { [t, at] };
            return Some((point(lo), point(hi)));
        }
    }
    None
}

/// The unit vector an object's front faces after its quarter turns.
fn front(turns: u8) -> [f32; 2] {
    [[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]][usize::from(turns % 4)]
}

fn homes() -> Vec<(Family, Scene)> {
    let taxonomy = library_taxonomy();
    let library = Library::new(&taxonomy);
    let mut homes = Vec::new();
    for family in Family::ALL {
        for seed in 0..SEEDS {
            let scene = generate_family(&format!("{family}_{seed}"), seed, family, &library)
                .unwrap_or_else(|e| panic!("{family} seed {seed}: {e}"));
            homes.push((family, scene));
        }
    }
    homes
}

#[test]
fn every_family_makes_homes_whose_rooms_meet_their_specification() {
    let mut sizes: BTreeMap<Family, BTreeSet<usize>> = BTreeMap::new();
    let mut kinds: BTreeSet<RoomType> = BTreeSet::new();
    for (family, scene) in homes() {
        assert_eq!(scene.family, Some(family));
        let n = scene.rooms.len();
        assert!((3..=12).contains(&n), "{}: {n} rooms", scene.name);
        sizes.entry(family).or_default().insert(n);
        for r in &scene.rooms {
            kinds.insert(r.kind);
            let spec = room_spec(r.kind);
            // The main rectangle's sides, and the whole footprint's area.
            let (w, d) = (r.max[0] - r.min[0], r.max[1] - r.min[1]);
            let area: f32 = r.rects().map(|p| p.area()).sum();
            assert!(
                w.min(d) >= spec.min_side - 1e-3
                    && area >= spec.area[0] - 1e-3
                    && area <= spec.area[1] + 1e-3,
                "{}: {} is {w:.2} × {d:.2} m ({area:.1} m² in all), outside {spec:?}",
                scene.name,
                r.label()
            );
        }
        // No two rectangles overlap, within a room or between rooms.
        let rects: Vec<_> = scene
            .rooms
            .iter()
            .flat_map(|r| r.rects().map(move |p| (r.label(), p)))
            .collect();
        for (i, (la, a)) in rects.iter().enumerate() {
            for (lb, b) in &rects[i + 1..] {
                let overlap_x = a.max[0].min(b.max[0]) - a.min[0].max(b.min[0]);
                let overlap_y = a.max[1].min(b.max[1]) - a.min[1].max(b.min[1]);
                assert!(
                    overlap_x <= 1e-3 || overlap_y <= 1e-3,
                    "{}: {la} and {lb} overlap",
                    scene.name,
                );
            }
        }
    }
    for (family, n) in &sizes {
        eprintln!("{family}: room counts {n:?}");
    }
    let smallest = sizes.values().flatten().min().copied();
    let largest = sizes.values().flatten().max().copied();
    assert_eq!(smallest, Some(3), "the smallest homes have three rooms");
    assert!(
        largest >= Some(11),
        "the largest homes have {largest:?} rooms"
    );
    assert_eq!(
        kinds.len(),
        RoomType::ALL.len(),
        "room types made: {kinds:?}"
    );
}

#[test]
fn every_room_is_reached_from_outside_by_each_robot() {
    let mut failures = Vec::new();
    for (_, scene) in homes() {
        for (robot, radius) in ROBOTS {
            let reached = reachable_rooms(&scene, radius);
            for (r, parts) in scene.rooms.iter().zip(reached) {
                for (k, ok) in parts.into_iter().enumerate() {
                    if !ok {
                        failures.push(format!(
                            "{}: {robot} cannot reach rectangle {k} of {}",
                            scene.name,
                            r.label()
                        ));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn windows_stand_in_outside_walls_and_doorways_are_clear() {
    for (_, scene) in homes() {
        for o in &scene.objects {
            let [fx, fy] = front(o.yaw_quarter_turns);
            let [x, y, _] = o.position;
            if o.synset == "window.n.01" {
                // Its front faces into its room; 30 cm behind it is outside the house.
                let inside = scene.room_at(x + 0.3 * fx, y + 0.3 * fy);
                let behind = scene.room_at(x - 0.3 * fx, y - 0.3 * fy);
                assert_eq!(inside, Some(o.room), "{}: {} faces out", scene.name, o.name);
                assert_eq!(
                    behind, None,
                    "{}: {} is in an inner wall",
                    scene.name, o.name
                );
            }
        }
        let doors: Vec<_> = scene
            .objects
            .iter()
            .filter(|o| o.synset == "door.n.01")
            .collect();
        let furniture = scene
            .objects
            .iter()
            .filter(|o| o.synset != "door.n.01" && o.synset != "window.n.01");
        for f in furniture {
            let (w, d) = if f.yaw_quarter_turns % 2 == 0 {
                (f.size[0], f.size[1])
            } else {
                (f.size[1], f.size[0])
            };
            for door in &doors {
                // 60 cm on each side of the doorway, as wide as it.
                let [dx, _] = front(door.yaw_quarter_turns);
                let [x, y, _] = door.position;
                let (hw, hd) = if dx == 0.0 { (0.5, 0.75) } else { (0.75, 0.5) };
                let clear = ([x - hw, y - hd], [x + hw, y + hd]);
                let [fx, fy, _] = f.position;
                let hit = fx + w / 2.0 > clear.0[0]
                    && fx - w / 2.0 < clear.1[0]
                    && fy + d / 2.0 > clear.0[1]
                    && fy - d / 2.0 < clear.1[1];
                assert!(
                    !hit,
                    "{}: {} stands in front of {} at {:?}",
                    scene.name, f.name, door.name, door.position
                );
            }
        }
    }
}

#[test]
fn some_rooms_are_l_shaped_with_no_wall_inside_them() {
    let (mut homes_with, mut total) = (0, 0);
    for (_, scene) in homes() {
        total += 1;
        if scene.rooms.iter().any(|r| !r.annexes.is_empty()) {
            homes_with += 1;
        }
        for r in scene.rooms.iter().filter(|r| !r.annexes.is_empty()) {
            let main = r.rects().next().unwrap();
            for annex in &r.annexes {
                let (w, d) = (annex.max[0] - annex.min[0], annex.max[1] - annex.min[1]);
                assert!(
                    w.min(d) >= 1.5 - 1e-3,
                    "{}: an annex of {} is {w:.2} × {d:.2} m",
                    scene.name,
                    r.label()
                );
                // Joined to the main rectangle along the annex's whole side, with no wall on it.
                let (a, b) = shared_side(&main, annex).unwrap_or_else(|| {
                    panic!("{}: an annex of {} is apart from it", scene.name, r.label())
                });
                let side = (b[0] - a[0]).abs().max((b[1] - a[1]).abs());
                assert!(
                    (side - w).abs() < 1e-3 || (side - d).abs() < 1e-3,
                    "{}: an annex of {} meets it along {side:.2} m only",
                    scene.name,
                    r.label()
                );
                for k in 1..10 {
                    let t = k as f32 / 10.0;
                    let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                    let walled = scene.walls.iter().any(|w| {
                        w.min[0] <= p[0] && p[0] <= w.max[0] && w.min[1] <= p[1] && p[1] <= w.max[1]
                    });
                    assert!(
                        !walled,
                        "{}: a wall inside {} at {p:?}",
                        scene.name,
                        r.label()
                    );
                }
            }
        }
    }
    eprintln!("{homes_with} of {total} homes have an L-shaped room");
    assert!(
        homes_with * 5 >= total,
        "{homes_with} of {total} homes have an L-shaped room (a fifth at least expected)"
    );
}

#[test]
fn rugs_lie_under_tables_within_their_rooms() {
    let (mut with_rug, mut total) = (0, 0);
    for (_, scene) in homes() {
        total += 1;
        let mut table_rug = false;
        for (index, r) in scene.rooms.iter().enumerate() {
            for rug in &r.rugs {
                let inside = r.rects().any(|p| {
                    p.min[0] <= rug.min[0]
                        && p.min[1] <= rug.min[1]
                        && rug.max[0] <= p.max[0]
                        && rug.max[1] <= p.max[1]
                });
                assert!(
                    inside,
                    "{}: a rug of {} lies outside it",
                    scene.name,
                    r.label()
                );
                let under_table = scene.objects.iter().any(|o| {
                    let [x, y, _] = o.position;
                    o.room == index
                        && o.synset == "table.n.02"
                        && (rug.min[0]..=rug.max[0]).contains(&x)
                        && (rug.min[1]..=rug.max[1]).contains(&y)
                });
                table_rug |= under_table;
            }
        }
        with_rug += usize::from(table_rug);
    }
    eprintln!("{with_rug} of {total} homes have a rug under a table");
    assert!(
        with_rug * 10 >= total * 9,
        "{with_rug} of {total} homes have a rug under a table (nine in ten expected)"
    );
}
