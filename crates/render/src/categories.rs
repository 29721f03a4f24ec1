//! The semantic segmentation's category ids: a table of names in sorted order, so that the same
//! names give the same ids in every home and every run. 0 is "nothing" (the background, or a
//! category the table lacks).

use serde::{Deserialize, Serialize};

/// Category names and their ids (position + 1).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct CategoryTable {
    names: Vec<String>,
}

/// The category of dust particles.
pub const DUST_CATEGORY: &str = "dust.n.01";
/// The category of stain particles.
pub const STAIN_CATEGORY: &str = "stain.n.01";
/// The category of water drops.
pub const WATER_CATEGORY: &str = "water.n.06";

impl CategoryTable {
    /// A table of these names (any order, repeats ignored) and the particles' and water's.
    /// Give it every category a world may hold — an object library's — rather than one world's,
    /// so that ids stay the same from home to home.
    pub fn new<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> CategoryTable {
        let mut names: Vec<String> = names.into_iter().map(|n| n.as_ref().to_string()).collect();
        names.extend([DUST_CATEGORY, STAIN_CATEGORY, WATER_CATEGORY].map(String::from));
        names.sort();
        names.dedup();
        CategoryTable { names }
    }

    /// A category's id, 0 if the table lacks it.
    pub fn id(&self, name: &str) -> u16 {
        self.names
            .binary_search_by(|n| n.as_str().cmp(name))
            .map_or(0, |i| (i + 1).min(usize::from(u16::MAX)) as u16)
    }

    /// The name of an id, `None` for 0 or an id past the table.
    pub fn name(&self, id: u16) -> Option<&str> {
        let i = usize::from(id).checked_sub(1)?;
        self.names.get(i).map(String::as_str)
    }

    /// Every (id, name), in id order.
    pub fn iter(&self) -> impl Iterator<Item = (u16, &str)> {
        self.names
            .iter()
            .enumerate()
            .map(|(i, n)| ((i + 1) as u16, n.as_str()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_depend_on_the_names_only() {
        let a = CategoryTable::new(["table.n.02", "apple.n.01", "table.n.02"]);
        let b = CategoryTable::new(vec!["apple.n.01".to_string(), "table.n.02".to_string()]);
        assert_eq!(a, b);
        let apple = a.id("apple.n.01");
        assert!(apple > 0);
        assert_eq!(a.name(apple), Some("apple.n.01"));
        assert_eq!(a.id("banana.n.02"), 0);
        assert_eq!(a.name(0), None);
        assert!(a.id(DUST_CATEGORY) > 0);
    }
}
