//! Robots stand on the world and nothing above it (`docs/design.md` §3): among our crates the manifest
//! names `behavior-sim`, the vocabulary crate and `behavior-data` (a leaf that finds fetched
//! files, for Fetch's meshes) only — no BDDL, assets, sampling or episode.

#[test]
fn the_robots_depend_on_the_world_and_the_vocabulary_only() {
    let manifest = include_str!("../Cargo.toml");
    let ours: Vec<&str> = manifest
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("behavior-"))
        .map(|l| l.split(['.', ' ', '=']).next().unwrap_or(l))
        .collect();
    assert!(ours.contains(&"behavior-sim"), "{ours:?}");
    assert!(
        ours.iter()
            .all(|d| ["behavior-sim", "behavior-core", "behavior-data"].contains(d)),
        "behavior-robots may depend on behavior-sim, behavior-core and behavior-data only: {ours:?}"
    );
}
