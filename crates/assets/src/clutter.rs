//! Clutter: the everyday things a lived-in home holds that no activity asks for — books on the
//! shelves, dishes in the cabinets, food in the fridge, shoes by the bed, towels in the washer —
//! so that our homes are as full as the original's scanned ones (134 to 216 objects in the
//! scenes of its speed benchmark) rather than bare furniture.
//!
//! [`clutter`] takes a home and a seed and returns the home with [`Scene::clutter`] filled. It is
//! a step of its own, which callers opt into: [`crate::generate`] stays furniture-only and fast
//! (coverage checks and `behavior scene list` generate every named home), and the same home can
//! be used with or without clutter ([`Scene::without_clutter`]), as the original's
//! `load_clutter` switch allows.
//!
//! Three stages, each in a private module: `rules` says what goes where by room type and
//! furniture type (with how much of each surface or interior it may cover, leaving room for
//! the activities' own objects); `scatter` draws each thing from the [`Library`] and places it in
//! a scratch copy of the home with the world's placement helper ([`behavior_sim::World::place_jointly`]:
//! collision-free, the relation checked); `settle` lets everything come to rest with physics,
//! drops what ended up elsewhere, and checks that the home built from the result holds its
//! clutter asleep and still. The poses recorded are those settled poses, so a scene file
//! rebuilds its clutter exactly, asleep, costing nothing per step until something touches it.
//!
//! Everything is drawn from one generator seeded from the seed given (on a stream of its own,
//! apart from the home's layout), in a fixed order: the same home and seed give the same clutter,
//! bit for bit.

mod rules;
mod scatter;
mod settle;

use crate::library::{AssetError, Library};
use crate::scene::{ClutterPlan, Scene, SceneError};
use behavior_sim::WorldError;
use scatter::Placed;
use std::collections::BTreeMap;

/// The random stream clutter draws from, apart from the home generator's (stream 0), so that a
/// home's seed can serve for its clutter too without the two sharing numbers.
const CLUTTER_STREAM: u64 = 1;

/// Why a home could not be cluttered.
#[derive(Debug, thiserror::Error)]
pub enum ClutterError {
    /// The home itself does not build (a bad scene file): the scene's reason.
    #[error("{0}")]
    Scene(SceneError),
    /// A synset the rules draw from has no archetype (a catalog entry is missing).
    #[error("clutter `{synset}`: {cause}")]
    Asset {
        /// The synset drawn.
        synset: String,
        /// The library's reason.
        cause: AssetError,
    },
    /// The world refused a thing built from the library.
    #[error("{0}")]
    World(WorldError),
    /// Things kept moving after every round of settling (a bug in the rules or the physics).
    #[error("the clutter did not come to rest")]
    Unsettled,
}

impl From<SceneError> for ClutterError {
    fn from(error: SceneError) -> ClutterError {
        ClutterError::Scene(error)
    }
}

impl From<WorldError> for ClutterError {
    fn from(error: WorldError) -> ClutterError {
        ClutterError::World(error)
    }
}

/// The home with clutter: the furniture of `scene` (any clutter it had is replaced) and the
/// things placed and settled from `seed` (see the module docs).
///
/// ```
/// use behavior_assets::{Library, NAMED_HOMES, clutter, generate};
/// use behavior_data::DataDir;
///
/// let data = DataDir::locate(None, |_| {}).unwrap();
/// let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap();
/// let library = Library::new(&taxonomy);
/// let (name, seed) = NAMED_HOMES[0];
/// let home = generate(name, seed, &library).unwrap();
/// let full = clutter(&home, &library, seed).unwrap();
/// assert!(full.clutter.len() > 100);
/// assert_eq!(full.objects, home.objects);
/// assert_eq!(full.without_clutter(), home);
/// ```
pub fn clutter(scene: &Scene, library: &Library, seed: u64) -> Result<Scene, ClutterError> {
    let home = scene.without_clutter();
    let mut rng = behavior_core::rng::seeded(seed);
    rng.set_stream(CLUTTER_STREAM);
    let placed = scatter::scatter(&home, library, &mut rng)?;
    let settled = settle::settle(&home, library, placed)?;
    Ok(Scene {
        clutter: named(settled),
        ..home
    })
}

/// The plans, named after their synset and numbered per synset in order: `clutter_book_0`.
fn named(placed: Vec<Placed>) -> Vec<ClutterPlan> {
    let mut counts: BTreeMap<String, u32> = BTreeMap::new();
    placed
        .into_iter()
        .map(|p| {
            let lemma = p
                .plan
                .synset
                .split('.')
                .next()
                .unwrap_or("thing")
                .to_string();
            let n = counts.entry(lemma.clone()).or_insert(0);
            *n += 1;
            ClutterPlan {
                name: format!("clutter_{lemma}_{}", *n - 1),
                ..p.plan
            }
        })
        .collect()
}
