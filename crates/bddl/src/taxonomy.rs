//! The synset taxonomy of `hierarchy_owned.json`: WordNet synsets, their parents and children, and
//! the abilities (with parameters) that say which object states apply to each.
//!
//! The file is a tree whose root is `entity.n.01`; a synset with several parents appears once under
//! each, with identical contents, so the tree is folded into a DAG keyed by name. `agent.n.01`,
//! which the activities declare for the robot but the file lacks, is added as a child of the root.

use serde::Deserialize;
use std::collections::{BTreeMap, BTreeSet, HashMap};

pub use behavior_core::{AGENT_SYNSET, Ability, AbilityParams, FLOOR_SYNSET, ParamValue};

/// Index of a synset in a [`Taxonomy`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SynsetId(pub u32);

/// One synset of the taxonomy, e.g. `apple.n.01`, with its place in the DAG and its abilities.
#[derive(Clone, Debug, PartialEq)]
pub struct Synset {
    /// The WordNet name as the file spells it, e.g. `apple.n.01`.
    pub name: String,
    /// The synsets it is filed under, in file order: several when the file lists it under
    /// several, none for the root.
    pub parents: Vec<SynsetId>,
    /// The synsets filed directly under it, in file order.
    pub children: Vec<SynsetId>,
    /// Its abilities, which say which states apply (`cookable` for `cooked`), with their
    /// parameters (`cookable: {"cook_temperature": 70}`). As listed for this synset: not inherited
    /// from its parents.
    pub abilities: BTreeMap<Ability, AbilityParams>,
    /// Object categories of the original iGibson dataset filed under this synset (for reference).
    pub igibson_categories: Vec<String>,
}

/// Why a taxonomy file could not be folded into a [`Taxonomy`].
#[derive(Debug, thiserror::Error)]
pub enum TaxonomyError {
    /// Not JSON, or not a tree of `{"name", "children", "abilities", "igibson_categories"}`
    /// nodes (or nested deeper than serde_json's limit of 128).
    #[error("the taxonomy is not valid JSON of the expected shape: {0}")]
    Json(#[from] serde_json::Error),
    /// A synset lists an ability that [`Ability`] does not name.
    #[error("synset {synset}: unknown ability `{ability}`")]
    UnknownAbility {
        /// The synset's name.
        synset: String,
        /// The ability as written in the file.
        ability: String,
    },
    /// A synset listed under several parents has different abilities in two places, so folding
    /// the tree into one node per synset would lose one of them. Only the abilities are compared.
    #[error("synset {synset}: appears twice with different contents")]
    Inconsistent {
        /// The synset's name.
        synset: String,
    },
}

/// The folded taxonomy: every synset once, with all its parents.
#[derive(Clone, Debug)]
pub struct Taxonomy {
    synsets: Vec<Synset>,
    by_name: HashMap<String, SynsetId>,
    root: SynsetId,
}

#[derive(Deserialize)]
struct RawNode {
    name: String,
    #[serde(default)]
    children: Vec<RawNode>,
    #[serde(default)]
    igibson_categories: Option<Vec<String>>,
    #[serde(default)]
    abilities: Option<BTreeMap<String, AbilityParams>>,
}

impl Taxonomy {
    /// Builds the taxonomy from the text of a `hierarchy_*.json` file.
    pub fn from_json(text: &str) -> Result<Taxonomy, TaxonomyError> {
        // serde_json recurses per nesting level; it refuses input nested deeper than 128 itself.
        let raw: RawNode = serde_json::from_str(text)?;
        let mut taxonomy = Taxonomy {
            synsets: Vec::new(),
            by_name: HashMap::new(),
            root: SynsetId(0),
        };
        // Depth-first with an explicit stack: (node, parent).
        let mut stack = vec![(&raw, None::<SynsetId>)];
        while let Some((node, parent)) = stack.pop() {
            let abilities = node
                .abilities
                .iter()
                .flatten()
                .map(|(name, params)| {
                    name.parse::<Ability>()
                        .map(|a| (a, params.clone()))
                        .map_err(|()| TaxonomyError::UnknownAbility {
                            synset: node.name.clone(),
                            ability: name.clone(),
                        })
                })
                .collect::<Result<BTreeMap<_, _>, _>>()?;
            let id = match taxonomy.by_name.get(&node.name) {
                Some(&id) => {
                    if taxonomy.synsets[id.0 as usize].abilities != abilities {
                        return Err(TaxonomyError::Inconsistent {
                            synset: node.name.clone(),
                        });
                    }
                    id
                }
                None => taxonomy.add(Synset {
                    name: node.name.clone(),
                    parents: Vec::new(),
                    children: Vec::new(),
                    abilities,
                    igibson_categories: node.igibson_categories.clone().unwrap_or_default(),
                }),
            };
            if let Some(parent) = parent {
                taxonomy.link(parent, id);
            }
            // Reversed so that children are visited in file order.
            for child in node.children.iter().rev() {
                stack.push((child, Some(id)));
            }
        }
        if !taxonomy.by_name.contains_key(AGENT_SYNSET) {
            let agent = taxonomy.add(Synset {
                name: AGENT_SYNSET.to_string(),
                parents: Vec::new(),
                children: Vec::new(),
                abilities: BTreeMap::new(),
                igibson_categories: Vec::new(),
            });
            taxonomy.link(taxonomy.root, agent);
        }
        Ok(taxonomy)
    }

    fn add(&mut self, synset: Synset) -> SynsetId {
        let id = SynsetId(self.synsets.len() as u32);
        self.by_name.insert(synset.name.clone(), id);
        self.synsets.push(synset);
        id
    }

    fn link(&mut self, parent: SynsetId, child: SynsetId) {
        if !self.synsets[child.0 as usize].parents.contains(&parent) {
            self.synsets[child.0 as usize].parents.push(parent);
            self.synsets[parent.0 as usize].children.push(child);
        }
    }

    /// The root, the file's top node (`entity.n.01` in the official taxonomy).
    pub fn root(&self) -> SynsetId {
        self.root
    }

    /// The number of distinct synsets, `agent.n.01` included.
    pub fn len(&self) -> usize {
        self.synsets.len()
    }

    /// Whether there are no synsets; never true for a taxonomy from [`Taxonomy::from_json`],
    /// which holds at least its root.
    pub fn is_empty(&self) -> bool {
        self.synsets.is_empty()
    }

    /// The synset of that name (`apple.n.01`, spelled exactly as in the file), if the taxonomy
    /// has it.
    pub fn get(&self, name: &str) -> Option<SynsetId> {
        self.by_name.get(name).copied()
    }

    /// The synset with that id. Panics on an id out of range (one from another taxonomy).
    pub fn synset(&self, id: SynsetId) -> &Synset {
        &self.synsets[id.0 as usize]
    }

    /// The name of the synset with that id.
    pub fn name(&self, id: SynsetId) -> &str {
        &self.synset(id).name
    }

    /// Every synset's id, in the order first met in the file (depth-first, children in file
    /// order), then `agent.n.01` if the file lacks it.
    pub fn ids(&self) -> impl Iterator<Item = SynsetId> {
        (0..self.synsets.len() as u32).map(SynsetId)
    }

    /// The abilities, with their parameters, of the synset of that name.
    pub fn abilities(&self, name: &str) -> Option<&BTreeMap<Ability, AbilityParams>> {
        self.get(name).map(|id| &self.synset(id).abilities)
    }

    /// Whether the synset itself lists the ability (abilities are not inherited); what the
    /// checker's ability warnings ask.
    pub fn has_ability(&self, id: SynsetId, ability: Ability) -> bool {
        self.synset(id).abilities.contains_key(&ability)
    }

    /// The parameters of an ability of a synset, if it has it.
    pub fn ability(&self, id: SynsetId, ability: Ability) -> Option<&AbilityParams> {
        self.synset(id).abilities.get(&ability)
    }

    /// All synsets below `id` (not including it), each once, in breadth-first order.
    pub fn descendants(&self, id: SynsetId) -> Vec<SynsetId> {
        self.closure(id, |s| &s.children)
    }

    /// All synsets above `id` (not including it), each once, in breadth-first order.
    pub fn ancestors(&self, id: SynsetId) -> Vec<SynsetId> {
        self.closure(id, |s| &s.parents)
    }

    /// Whether `descendant` is `ancestor` or lies below it.
    pub fn is_a(&self, descendant: SynsetId, ancestor: SynsetId) -> bool {
        descendant == ancestor || self.ancestors(descendant).contains(&ancestor)
    }

    /// Whether no synset is filed under it.
    pub fn is_leaf(&self, id: SynsetId) -> bool {
        self.synset(id).children.is_empty()
    }

    fn closure(&self, id: SynsetId, next: impl Fn(&Synset) -> &Vec<SynsetId>) -> Vec<SynsetId> {
        let mut seen = BTreeSet::from([id]);
        let mut order = Vec::new();
        let mut frontier = std::collections::VecDeque::from([id]);
        while let Some(current) = frontier.pop_front() {
            for &n in next(self.synset(current)) {
                if seen.insert(n) {
                    order.push(n);
                    frontier.push_back(n);
                }
            }
        }
        order
    }
}

/// Whether a name has the shape of a synset: `lemma.n.NN`.
pub fn is_synset_name(name: &str) -> bool {
    let mut parts = name.rsplitn(3, '.');
    let (Some(number), Some(pos), Some(lemma)) = (parts.next(), parts.next(), parts.next()) else {
        return false;
    };
    !lemma.is_empty()
        && pos == "n"
        && !number.is_empty()
        && number.bytes().all(|b| b.is_ascii_digit())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A small taxonomy in the file's format, for tests that must not need the official data.
    pub const SMALL: &str = r#"{"name": "entity.n.01", "children": [
        {"name": "food.n.01", "abilities": {"cookable": {"cook_temperature": 70}}, "children": [
            {"name": "apple.n.01", "abilities": {"cookable": {"cook_temperature": 70}, "sliceable": {}}, "children": []}
        ]},
        {"name": "furniture.n.01", "children": [
            {"name": "table.n.02", "abilities": {"dustyable": {}}, "children": []},
            {"name": "stove.n.01", "abilities": {"heatSource": {"temperature": 500, "requires_toggled_on": true}, "toggleable": {}}, "children": []}
        ]},
        {"name": "device.n.01", "children": [
            {"name": "stove.n.01", "abilities": {"heatSource": {"temperature": 500, "requires_toggled_on": true}, "toggleable": {}}, "children": []}
        ]},
        {"name": "floor.n.01", "children": []},
        {"name": "plate.n.04", "abilities": {"stainable": {}}, "children": []}
    ]}"#;

    #[test]
    fn folds_repeated_synsets_into_one_with_two_parents() {
        let t = Taxonomy::from_json(SMALL).unwrap();
        let stove = t.get("stove.n.01").unwrap();
        let parents: Vec<_> = t.synset(stove).parents.iter().map(|&p| t.name(p)).collect();
        assert_eq!(parents, ["furniture.n.01", "device.n.01"]);
        assert!(t.has_ability(stove, Ability::Toggleable));
        assert!(
            t.abilities("stove.n.01")
                .unwrap()
                .contains_key(&Ability::HeatSource)
        );
        assert!(t.abilities("zzz.n.01").is_none());
        let heat = t.ability(stove, Ability::HeatSource).unwrap();
        assert_eq!(heat["temperature"].as_f64(), Some(500.0));
        assert_eq!(heat["requires_toggled_on"].as_bool(), Some(true));
        let entity = t.get("entity.n.01").unwrap();
        assert!(t.is_a(stove, entity));
        assert!(t.descendants(entity).contains(&stove));
        assert!(t.get(AGENT_SYNSET).is_some());
    }

    #[test]
    fn rejects_unknown_abilities_and_bad_json() {
        let bad = r#"{"name": "a.n.01", "abilities": {"flying": {}}}"#;
        assert!(matches!(
            Taxonomy::from_json(bad),
            Err(TaxonomyError::UnknownAbility { .. })
        ));
        assert!(Taxonomy::from_json("{").is_err());
    }

    #[test]
    fn synset_names() {
        assert!(is_synset_name("apple.n.01"));
        assert!(is_synset_name("t.v.n.02"));
        assert!(!is_synset_name("apple.n.01_1"));
        assert!(!is_synset_name("apple"));
        assert!(!is_synset_name(".n.01"));
    }
}
