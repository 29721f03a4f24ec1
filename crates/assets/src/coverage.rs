//! Which homes can host which activities: an activity's `inroom` literals ask for rooms of given
//! types holding furniture of given synsets; a home covers the activity when it has, for every
//! room type, enough objects of each synset (or of a synset below it in the taxonomy) in rooms of
//! that type. Floors (`floor.n.01`) ask for rooms of the type.

use crate::home::named_homes;
use crate::library::{AssetError, Library};
use crate::scene::Scene;
use behavior_bddl::Taxonomy;
use behavior_bddl::activity::{Activity, InitLiteral};
use behavior_bddl::taxonomy::FLOOR_SYNSET;
use behavior_core::RoomType;
use std::collections::BTreeMap;

/// (room type, synset) → how many instances the activity places in rooms of that type.
pub type Requirements = BTreeMap<(RoomType, String), usize>;

/// What an activity asks of a home: its positive `inroom` literals counted per room type and
/// synset (other literals place objects the sampler creates, so a home need not have them).
pub fn requirements(activity: &Activity) -> Requirements {
    let mut needs = Requirements::new();
    for literal in &activity.init {
        if let InitLiteral::InRoom {
            instance,
            room,
            positive: true,
        } = literal
        {
            let synset = activity
                .category(activity.instance(*instance).category)
                .name
                .clone();
            *needs.entry((*room, synset)).or_insert(0) += 1;
        }
    }
    needs
}

/// What the scene lacks for these requirements, as readable lines; empty when it covers them.
pub fn missing(scene: &Scene, needs: &Requirements, taxonomy: &Taxonomy) -> Vec<String> {
    let mut lacks = Vec::new();
    for ((room, synset), &count) in needs {
        let rooms_of_type: Vec<usize> = (0..scene.rooms.len())
            .filter(|&i| scene.rooms[i].kind == *room)
            .collect();
        let have = if synset == FLOOR_SYNSET {
            rooms_of_type.len()
        } else {
            let wanted = taxonomy.get(synset);
            scene
                .objects
                .iter()
                .filter(|o| rooms_of_type.contains(&o.room))
                .filter(|o| match (taxonomy.get(&o.synset), wanted) {
                    (Some(have), Some(want)) => taxonomy.is_a(have, want),
                    _ => o.synset == *synset,
                })
                .count()
        };
        if have < count {
            lacks.push(format!("{count} × {synset} in a {room} (has {have})"));
        }
    }
    lacks
}

/// The first of the named homes that covers `activity` (`None`: none does), generated: the home
/// an activity runs in when none is asked for.
pub fn first_covering(
    activity: &Activity,
    library: &Library,
    taxonomy: &Taxonomy,
) -> Result<Option<Scene>, AssetError> {
    let homes = named_homes(library)?;
    Ok(covering(&homes, activity, taxonomy)
        .first()
        .map(|h| (*h).clone()))
}

/// The homes among `homes` that cover `activity`, in the order given: the one place that
/// decides which homes an activity is sampled in (`behavior sample` takes the first,
/// `sample-all` every one, `scene coverage` lists them).
pub fn covering<'h>(
    homes: &'h [Scene],
    activity: &Activity,
    taxonomy: &Taxonomy,
) -> Vec<&'h Scene> {
    let needs = requirements(activity);
    homes
        .iter()
        .filter(|h| missing(h, &needs, taxonomy).is_empty())
        .collect()
}
