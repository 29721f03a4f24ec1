//! Resolving synsets to archetypes, and spawning equipped instances.

use crate::archetype::{Archetype, Layout, Shape};
use crate::catalog::CATALOG;
use behavior_bddl::Taxonomy;
use behavior_core::Ability;
use behavior_sim::{ObjectSpec, PointKind};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::Rng;
use rapier3d::math::Vector;
use std::collections::HashMap;

/// Why no object could be made for a synset.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum AssetError {
    /// The synset is not in the taxonomy (a typo, or a synset of another BDDL version).
    #[error("unknown synset `{0}`: it is not in the taxonomy")]
    UnknownSynset(String),
    /// The synset is known, but neither it nor any synset below it has an archetype in the
    /// catalog: the catalog needs an entry.
    #[error("no object archetype for `{0}` or any synset below it")]
    NoArchetype(String),
    /// No draw of a seed gave a home of its family that meets every room's specification.
    #[error("seed {seed} gave no {family} home that meets every room's specification")]
    NoPlan {
        /// The family's name.
        family: &'static str,
        /// The seed.
        seed: u64,
    },
}

/// The catalog indexed by synset, with the taxonomy to resolve and equip synsets.
pub struct Library<'t> {
    taxonomy: &'t Taxonomy,
    by_synset: HashMap<&'static str, &'static Archetype>,
}

impl<'t> Library<'t> {
    /// The catalog over `taxonomy`, which resolves synsets without archetypes of their own and
    /// gives instances their abilities.
    pub fn new(taxonomy: &'t Taxonomy) -> Library<'t> {
        Library {
            taxonomy,
            by_synset: CATALOG.iter().map(|a| (a.synset, a)).collect(),
        }
    }

    /// The taxonomy it resolves and equips with, so that callers building other objects (floors,
    /// say) equip them alike.
    pub fn taxonomy(&self) -> &'t Taxonomy {
        self.taxonomy
    }

    /// The archetype of a synset: its own, else that of the nearest descendant that has one
    /// (breadth first, so `fruit.n.01` gets a fruit's).
    pub fn resolve(&self, synset: &str) -> Result<&'static Archetype, AssetError> {
        if let Some(a) = self.by_synset.get(synset) {
            return Ok(a);
        }
        let id = self
            .taxonomy
            .get(synset)
            .ok_or_else(|| AssetError::UnknownSynset(synset.to_string()))?;
        self.taxonomy
            .descendants(id)
            .into_iter()
            .find_map(|d| self.by_synset.get(self.taxonomy.name(d)).copied())
            .ok_or_else(|| AssetError::NoArchetype(synset.to_string()))
    }

    /// An instance of `synset` named `name`: a size drawn uniformly in the archetype's range and a
    /// variant, both from `rng`; the synset's abilities from the taxonomy; and the named points
    /// those abilities use. Its bottom rests at z = 0 around the origin.
    pub fn spawn(
        &self,
        synset: &str,
        name: &str,
        rng: &mut ChaCha8Rng,
    ) -> Result<ObjectSpec, AssetError> {
        let (size, variant) = self.sample(synset, rng)?;
        self.instance(synset, name, size, variant)
    }

    /// An archetype for a new object of `synset`, drawn uniformly among its own and those of the
    /// synsets below it that are alike (movable or fixed as its own), so `food.n.02` may come as an
    /// apple or a loaf.
    pub fn choose(
        &self,
        synset: &str,
        rng: &mut ChaCha8Rng,
    ) -> Result<&'static Archetype, AssetError> {
        let first = self.resolve(synset)?;
        let mut candidates: Vec<&'static Archetype> =
            self.by_synset.get(synset).copied().into_iter().collect();
        if let Some(id) = self.taxonomy.get(synset) {
            let below: Vec<&'static Archetype> = self
                .taxonomy
                .descendants(id)
                .into_iter()
                .filter_map(|d| self.by_synset.get(self.taxonomy.name(d)).copied())
                .filter(|a| a.shape.is_fixed() == first.shape.is_fixed())
                .collect();
            candidates.extend(below);
        }
        // Catalog order, so the draw depends only on the generator.
        candidates.sort_by_key(|a| a.synset);
        candidates.dedup_by_key(|a| a.synset);
        Ok(candidates[rng.next_u32() as usize % candidates.len()])
    }

    /// An archetype (see [`Library::choose`]), a size uniform in its range and a variant.
    pub fn sample_any(
        &self,
        synset: &str,
        rng: &mut ChaCha8Rng,
    ) -> Result<(&'static Archetype, Vector, u32), AssetError> {
        let archetype = self.choose(synset, rng)?;
        let size = Vector::from_array(std::array::from_fn(|k| {
            behavior_core::rng::uniform(rng, archetype.min[k], archetype.max[k])
        }));
        Ok((archetype, size, rng.next_u32() % archetype.shape.variants()))
    }

    /// A size (uniform in the archetype's range) and a variant for a synset.
    pub fn sample(&self, synset: &str, rng: &mut ChaCha8Rng) -> Result<(Vector, u32), AssetError> {
        let archetype = self.resolve(synset)?;
        let size = Vector::from_array(std::array::from_fn(|k| {
            behavior_core::rng::uniform(rng, archetype.min[k], archetype.max[k])
        }));
        Ok((size, rng.next_u32() % archetype.shape.variants()))
    }

    /// An instance of a given size (at most the archetype's largest) and variant, equipped.
    pub fn instance(
        &self,
        synset: &str,
        name: &str,
        size: Vector,
        variant: u32,
    ) -> Result<ObjectSpec, AssetError> {
        Ok(self.instance_of(self.resolve(synset)?, synset, name, size, variant))
    }

    /// An instance of `synset` built from a given archetype (which may be a descendant's).
    pub fn instance_of(
        &self,
        archetype: &Archetype,
        synset: &str,
        name: &str,
        size: Vector,
        variant: u32,
    ) -> ObjectSpec {
        let (mut spec, layout) = archetype.build(name, size, variant);
        spec.category = synset.to_string();
        if let Some(abilities) = self.taxonomy.abilities(&spec.category) {
            spec.abilities = abilities.clone();
        }
        if spec.abilities.contains_key(&Ability::Sliceable) {
            spec.halves = Some(archetype.halves(size, variant));
        }
        equip(&mut spec, archetype, &layout);
        spec
    }
}

/// Adds the named points the spec's abilities need.
fn equip(spec: &mut ObjectSpec, archetype: &Archetype, layout: &Layout) {
    let s = layout.size;
    let top = Vector::new(0.0, 0.0, s.z + 0.01);
    let has = |a: Ability| spec.abilities.contains_key(&a);
    let mut points = Vec::new();
    if has(Ability::Toggleable) {
        let button = if archetype.shape.is_fixed() {
            layout.front_button
        } else {
            top
        };
        points.push((PointKind::ToggleButton, button));
    }
    if has(Ability::HeatSource) {
        let burners: Vec<Vector> = layout.burners.iter().flatten().copied().collect();
        if burners.is_empty() {
            points.push((PointKind::HeatingElement, top));
        }
        points.extend(burners.into_iter().map(|b| (PointKind::HeatingElement, b)));
    }
    if has(Ability::WaterSource) {
        points.push((PointKind::WaterOutlet, layout.outlet.unwrap_or(top)));
    }
    if has(Ability::Slicer) {
        // The cutting half of a blade lying along x, at its bottom edge.
        points.push((PointKind::SlicingEdge, Vector::new(s.x / 4.0, 0.0, 0.0)));
    }
    if has(Ability::CleaningTool) && archetype.shape == Shape::Rod {
        // A brush or broom cleans with its head, the −x end.
        points.push((
            PointKind::CleaningArea,
            Vector::new(-s.x / 2.0 + 0.05, 0.0, 0.0),
        ));
    }
    spec.points.extend(points);
}
