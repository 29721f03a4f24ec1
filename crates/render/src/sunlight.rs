//! Where the sun gets into a home: through its windows. The homes have no ceilings (so that an
//! overview sees into every room), which would let the sun fall into every room from above; for
//! the sun's map of the fixed geometry, a roof is laid over the walls' tops and each wall is cut
//! at its windows, so that the sun lights a room through its windows' glass only, in patches on
//! the floor and the far wall that move with the sun's height and side.
//!
//! Nothing here is drawn by a camera or reaches the physics: the roof and the cut walls are
//! shadow casters only, and the sky map (ambient occlusion) and the lamps' maps keep the walls
//! whole and no roof.

use behavior_core::{WALL_SYNSET, WINDOW_SYNSET};
use behavior_sim::{Primitive, VisualShape, World};
use rapier3d::math::{Pose, Vector};

/// A box to cast the sun's shadow: where its centre is and how it is turned, and its half size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Slab {
    pub(crate) pose: Pose,
    pub(crate) half: Vector,
}

/// The roof's thickness, m.
const ROOF: f32 = 0.1;
/// How far in front of its wall a window may stand and still open it, m (they stand 5 cm in).
const WINDOW_GAP: f32 = 0.2;

/// The walls' casters cut at the windows, and a roof over the walls' tops; none in a world
/// without walls. `Some` only where the world has walls: each wall part (by its object's index
/// in `world.bodies().objects()` order and the part's) is replaced by the slabs given.
pub(crate) fn sun_casters(world: &World) -> Option<SunCasters> {
    let walls = wall_parts(world);
    if walls.is_empty() {
        return None;
    }
    let windows: Vec<(Vector, Vector)> = world
        .bodies()
        .objects()
        .filter(|(_, o)| o.is_present() && o.category == WINDOW_SYNSET)
        .map(|(id, _)| {
            let b = world.bodies().aabb(id);
            (b.mins, b.maxs)
        })
        .collect();
    let mut slabs = Vec::new();
    let (mut lo, mut hi) = (Vector::splat(f32::MAX), Vector::splat(f32::MIN));
    for wall in &walls {
        let (wlo, whi) = box_bounds(wall);
        lo = lo.min(wlo);
        hi = hi.max(whi);
        slabs.extend(cut(wall, &windows));
    }
    let roof = Slab {
        pose: Pose::from_translation(Vector::new(
            (lo.x + hi.x) / 2.0,
            (lo.y + hi.y) / 2.0,
            hi.z + ROOF / 2.0,
        )),
        half: Vector::new((hi.x - lo.x) / 2.0, (hi.y - lo.y) / 2.0, ROOF / 2.0),
    };
    slabs.push(roof);
    Some(SunCasters { slabs })
}

/// What the sun's map of the fixed geometry casts instead of the walls.
pub(crate) struct SunCasters {
    /// The walls cut at their windows, then the roof.
    pub(crate) slabs: Vec<Slab>,
}

/// Every box of the walls, posed in the world.
fn wall_parts(world: &World) -> Vec<Slab> {
    let mut walls = Vec::new();
    for (id, object) in world.bodies().objects() {
        if !object.is_present() || object.category != WALL_SYNSET {
            continue;
        }
        for part in world.visuals().parts(id) {
            let half = match part.shape {
                VisualShape::Primitive(Primitive::Box { half_extents }) => *half_extents,
                VisualShape::Formed { half_extents, .. } => half_extents,
                _ => continue,
            };
            walls.push(Slab {
                pose: part.pose,
                half,
            });
        }
    }
    walls
}

/// The world box around a slab.
fn box_bounds(slab: &Slab) -> (Vector, Vector) {
    let mut lo = Vector::splat(f32::MAX);
    let mut hi = Vector::splat(f32::MIN);
    for corner in corners(slab.half) {
        let p = slab.pose * corner;
        lo = lo.min(p);
        hi = hi.max(p);
    }
    (lo, hi)
}

fn corners(h: Vector) -> [Vector; 8] {
    std::array::from_fn(|k| {
        Vector::new(
            if k & 1 == 0 { -h.x } else { h.x },
            if k & 2 == 0 { -h.y } else { h.y },
            if k & 4 == 0 { -h.z } else { h.z },
        )
    })
}

/// A wall's box less the openings of the windows in front of it: the solid stretches between
/// them full height, and under and over each opening.
fn cut(wall: &Slab, windows: &[(Vector, Vector)]) -> Vec<Slab> {
    let h = wall.half;
    // The wall runs along its longer horizontal axis.
    let along = if h.x >= h.y { 0 } else { 1 };
    let across = 1 - along;
    let inverse = wall.pose.inverse();
    let mut holes: Vec<(f32, f32, f32, f32)> = windows
        .iter()
        .filter_map(|&(lo, hi)| {
            let local: Vec<Vector> = corners((hi - lo) / 2.0)
                .iter()
                .map(|&c| inverse * ((lo + hi) / 2.0 + c))
                .collect();
            let min = local.iter().fold(Vector::splat(f32::MAX), |a, &p| a.min(p));
            let max = local.iter().fold(Vector::splat(f32::MIN), |a, &p| a.max(p));
            let near =
                min[across] <= h[across] + WINDOW_GAP && max[across] >= -h[across] - WINDOW_GAP;
            let (a0, a1) = (min[along].max(-h[along]), max[along].min(h[along]));
            let (z0, z1) = (min.z.max(-h.z), max.z.min(h.z));
            (near && a1 > a0 && z1 > z0).then_some((a0, a1, z0, z1))
        })
        .collect();
    if holes.is_empty() {
        return vec![*wall];
    }
    holes.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut pieces = Vec::new();
    // A piece from `a0` to `a1` along the wall and `z0` to `z1` up it (the wall's own frame).
    let mut piece = |a0: f32, a1: f32, z0: f32, z1: f32| {
        if a1 - a0 < 1e-3 || z1 - z0 < 1e-3 {
            return;
        }
        let mut centre = Vector::ZERO;
        let mut half = h;
        centre[along] = (a0 + a1) / 2.0;
        half[along] = (a1 - a0) / 2.0;
        centre.z = (z0 + z1) / 2.0;
        half.z = (z1 - z0) / 2.0;
        pieces.push(Slab {
            pose: wall.pose * Pose::from_translation(centre),
            half,
        });
    };
    let mut from = -h[along];
    for &(a0, a1, z0, z1) in &holes {
        let a0 = a0.max(from);
        piece(from, a0, -h.z, h.z);
        piece(a0, a1, -h.z, z0);
        piece(a0, a1, z1, h.z);
        from = from.max(a1);
    }
    piece(from, h[along], -h.z, h.z);
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{ObjectSpec, Part};

    fn wall(world: &mut World, name: &str, at: Vector, half: Vector) {
        let part = Part::new(Primitive::Box { half_extents: half });
        world
            .add(
                ObjectSpec::new(name, "wall.n.01", vec![part])
                    .fixed()
                    .at(at),
            )
            .unwrap();
    }

    /// A slab's volume.
    fn volume(s: &Slab) -> f32 {
        8.0 * s.half.x * s.half.y * s.half.z
    }

    #[test]
    fn a_window_opens_its_wall_and_a_roof_covers_the_walls() {
        let mut world = World::default();
        assert!(sun_casters(&world).is_none(), "no walls, nothing changes");
        wall(
            &mut world,
            "wall_0",
            Vector::new(0.0, 0.0, 1.25),
            Vector::new(2.0, 0.05, 1.25),
        );
        wall(
            &mut world,
            "wall_1",
            Vector::new(0.0, 3.0, 1.25),
            Vector::new(2.0, 0.05, 1.25),
        );
        // A window 1 m wide and 1.2 m high, its sill at 0.9 m, 5 cm in front of the first wall.
        let glass = Part::new(Primitive::Box {
            half_extents: Vector::new(0.5, 0.03, 0.6),
        });
        world
            .add(
                ObjectSpec::new("window_0", "window.n.01", vec![glass])
                    .fixed()
                    .at(Vector::new(0.5, 0.1, 1.5)),
            )
            .unwrap();
        let casters = sun_casters(&world).expect("walls");
        let (pieces, roof) = casters.slabs.split_at(casters.slabs.len() - 1);
        // The first wall in four pieces (left, under, over, right), the second whole.
        assert_eq!(pieces.len(), 5, "{pieces:?}");
        let whole = volume(&Slab {
            pose: Pose::IDENTITY,
            half: Vector::new(2.0, 0.05, 1.25),
        });
        let cut: f32 = pieces[..4].iter().map(volume).sum();
        let hole = 1.0 * 0.1 * 1.2;
        assert!(
            (whole - cut - hole).abs() < 1e-3,
            "{whole} - {cut} is not the hole's {hole}"
        );
        // The window's middle is open: no piece holds it.
        let open = Vector::new(0.5, 0.0, 1.5);
        let holds = |s: &Slab| {
            let p = s.pose.inverse() * open;
            p.abs().cmple(s.half).all()
        };
        assert!(!pieces.iter().any(holds), "the opening is closed");
        assert!(
            pieces[4..]
                .iter()
                .all(|s| s.half == Vector::new(2.0, 0.05, 1.25))
        );
        // The roof spans both walls, on their tops.
        let r = roof[0];
        assert!(
            (r.pose.translation.z - r.half.z - 2.5).abs() < 1e-4,
            "{r:?}"
        );
        assert!(r.half.x >= 2.0 && r.half.y >= 1.5, "{r:?}");
    }
}
