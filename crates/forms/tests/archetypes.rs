//! Every archetype of the catalog, at its smallest and largest size and in each variant, is
//! drawn with valid meshes that lie within its colliders' box (± 2 cm), so that what is drawn is
//! what is simulated.

use behavior_assets::CATALOG;
use behavior_forms::{Detail, mesh, seed_of};
use behavior_sim::{VisualShape, World};
use rapier3d::math::Vector;

/// How far a drawn vertex may stray outside the colliders' box, m.
const SLACK: f32 = 0.02;

#[test]
fn every_archetype_is_drawn_inside_its_colliders() {
    let mut failures = Vec::new();
    let (mut objects, mut formed) = (0, 0);
    for archetype in CATALOG {
        for (size, tag) in [(archetype.min, "min"), (archetype.max, "max")] {
            for variant in 0..archetype.shape.variants() {
                let name = format!("{}_{tag}_{variant}", archetype.synset);
                let (spec, _) = archetype.build(&name, Vector::from_array(size), variant);
                let mut world = World::default();
                let id = match world.add(spec) {
                    Ok(id) => id,
                    Err(e) => {
                        failures.push(format!("{name}: not built: {e}"));
                        continue;
                    }
                };
                objects += 1;
                let aabb = world.bodies().aabb(id);
                let (lo, hi) = (
                    aabb.mins - Vector::splat(SLACK),
                    aabb.maxs + Vector::splat(SLACK),
                );
                for part in world.visuals().parts(id) {
                    let VisualShape::Formed { form, half_extents } = part.shape else {
                        continue;
                    };
                    formed += 1;
                    for detail in Detail::ALL {
                        let m = mesh(form, half_extents, seed_of(&name).into(), detail);
                        if let Some(d) = m.defects(half_extents, 1e-6).first() {
                            failures.push(format!("{name} {form:?} {detail:?}: {d}"));
                        }
                        if m.pressed > 1e-6 {
                            failures.push(format!(
                                "{name} {form:?} {detail:?}: pressed {} m into its part's box",
                                m.pressed
                            ));
                        }
                        let outside = m
                            .positions
                            .iter()
                            .map(|&p| part.pose.transform_point(p))
                            .find(|p| p.cmplt(lo).any() || p.cmpgt(hi).any());
                        if let Some(p) = outside {
                            failures.push(format!(
                                "{name} {form:?} {detail:?}: drawn at {p}, outside the colliders' box {} .. {}",
                                aabb.mins, aabb.maxs
                            ));
                        }
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} problems:\n{}",
        failures.len(),
        failures.join("\n")
    );
    // Every archetype in both sizes, and most of them drawn in detail.
    assert!(objects >= 2 * CATALOG.len(), "only {objects} objects built");
    assert!(
        formed >= 2 * CATALOG.len(),
        "only {formed} formed parts drawn"
    );
}
