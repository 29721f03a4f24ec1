//! Objects and homes for BEHAVIOR, generated procedurally: no asset download.
//!
//! The [`catalog`] holds one [`archetype::Archetype`] per synset the official activities use;
//! the [`library::Library`] resolves any synset to an archetype (its own or a descendant's in the
//! taxonomy), samples an instance's size and variant from the episode's random number
//! generator, and equips it with the abilities of its synset and the named points they need.
//! [`home`] generates floor plans with furniture from a seed, and [`scene`] saves, loads and
//! builds them; [`urdf`] imports a user's own models, their collision geometry and their look.
//!
//! This crate builds [`behavior_sim::ObjectSpec`]s; it knows nothing of BDDL text or of how the
//! world simulates them.

#![warn(missing_docs)]

pub mod archetype;
pub mod catalog;
pub mod coverage;
pub mod home;
pub mod library;
pub mod scene;
mod tessellate;
pub mod urdf;

pub use archetype::{Archetype, Shape};
pub use home::{NAMED_HOMES, generate};
pub use library::{AssetError, Library};
pub use scene::{BuiltScene, Scene, SceneError};
