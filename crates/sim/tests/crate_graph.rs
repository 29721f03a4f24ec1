//! The world knows nothing of the language (`docs/design.md` §2–3): its manifest depends on the shared
//! vocabulary crate and never on `behavior-bddl`, not even for its tests.

#[test]
fn the_world_depends_on_the_vocabulary_crate_and_not_on_the_language() {
    let manifest = include_str!("../Cargo.toml");
    let dependencies: Vec<&str> = manifest
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("behavior-"))
        .map(|l| l.split(['.', ' ', '=']).next().unwrap_or(l))
        .collect();
    assert!(dependencies.contains(&"behavior-core"), "{dependencies:?}");
    assert!(
        dependencies.iter().all(|d| *d == "behavior-core"),
        "behavior-sim may depend on behavior-core only among our crates: {dependencies:?}"
    );
}
