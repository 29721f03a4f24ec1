//! Environments over the official activities, in the first named home that covers each (with
//! its clutter), built once per test process.

#![allow(dead_code)]

use behavior_assets::{Library, NAMED_HOMES, Scene, clutter, generate, missing, requirements};
use behavior_bddl::{Activity, Knowledge, Taxonomy};
use behavior_data::DataDir;
use behavior_env::{Env, EnvConfig};
use std::sync::{Arc, OnceLock};

fn data() -> &'static DataDir {
    static DATA: OnceLock<DataDir> = OnceLock::new();
    DATA.get_or_init(|| DataDir::locate(None, |m| eprintln!("{m}")).unwrap())
}

pub fn knowledge() -> &'static Knowledge {
    static KNOWLEDGE: OnceLock<Knowledge> = OnceLock::new();
    KNOWLEDGE.get_or_init(|| {
        let data = data();
        Knowledge::read(&data.taxonomy_path(), &data.domain_path()).unwrap()
    })
}

pub fn taxonomy() -> Arc<Taxonomy> {
    static TAXONOMY: OnceLock<Arc<Taxonomy>> = OnceLock::new();
    TAXONOMY
        .get_or_init(|| Arc::new(knowledge().taxonomy.clone()))
        .clone()
}

pub fn activity(name: &str) -> Arc<Activity> {
    let source = behavior_bddl::load::read_source(&data().problem_path(name).unwrap()).unwrap();
    Arc::new(knowledge().load(&source).unwrap().0)
}

/// The first named home that covers the activity, cluttered or not.
pub fn home(activity: &Activity, cluttered: bool) -> Scene {
    let library = Library::new(&knowledge().taxonomy);
    let needs = requirements(activity);
    let home = NAMED_HOMES
        .into_iter()
        .map(|(n, s)| generate(n, s, &library).unwrap())
        .find(|h| missing(h, &needs, &knowledge().taxonomy).is_empty())
        .expect("a covering home");
    if cluttered {
        let seed = home.seed;
        clutter(&home, &library, seed).unwrap()
    } else {
        home
    }
}

/// The default configuration of an activity in its first covering home, without clutter
/// (faster to sample; clutter is the benchmark's business).
pub fn config(name: &str) -> EnvConfig {
    let activity = activity(name);
    let home = home(&activity, false);
    EnvConfig::new(activity, taxonomy(), vec![home])
}

pub fn env(name: &str) -> Env {
    Env::new(config(name))
}

/// The official activities' names.
pub fn official_activities() -> Vec<String> {
    data().activities().unwrap()
}
