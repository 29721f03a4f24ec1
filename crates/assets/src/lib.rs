//! Objects and homes for BEHAVIOR, generated procedurally: no asset download.
//!
//! The [`CATALOG`] holds one [`Archetype`] per synset the official activities use (`catalog.rs`;
//! the shape families are built in `archetype/`); the [`Library`] resolves any synset to an
//! archetype (its own or a descendant's in the taxonomy), samples an instance's size and variant
//! from the episode's random number generator, and equips it with the abilities of its synset and
//! the named points they need (`library.rs`). [`generate`] lays out homes of six plan
//! [`Family`]s with furniture from a seed (`home/`: program, layout, connect, walls, furnish),
//! [`clutter`] fills a home with the everyday things no
//! activity asks for — books on shelves, dishes in cabinets, food in the fridge — placed and
//! settled with the world's physics (`clutter/`: rules, scatter, settle), [`Scene`] saves, loads
//! and builds them, everything starting asleep (`scene.rs`), [`covering`] finds the homes an
//! activity fits (`coverage.rs`), and [`import_urdf`] imports a user's own models, their
//! collision geometry and their look (`urdf.rs`). The modules are private; this page is the
//! crate's API.
//!
//! Clutter is a step of its own that callers opt into, as the original's `load_clutter` switch
//! is: [`generate`] gives the furniture-only home, fast enough to generate every named home for
//! a coverage check, and [`clutter`] (a fraction of a second) the lived-in one.
//!
//! This crate builds [`behavior_sim::ObjectSpec`]s; it knows nothing of BDDL text or of how the
//! world simulates them.
//!
//! A home from a seed, built into a world, then made lived-in:
//!
//! ```
//! use behavior_assets::{Library, Scene, clutter, generate};
//! use behavior_data::DataDir;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let data = DataDir::locate(None, |message| eprintln!("{message}"))?;
//! let taxonomy = behavior_bddl::load::read_taxonomy(&data.taxonomy_path())?;
//! let library = Library::new(&taxonomy);
//! let home = generate("my_home", 7, &library)?; // rooms, walls, doors and furniture
//! assert!(home.rooms.len() >= 3);
//! let again = Scene::from_json(&home.to_json())?; // a home is a file
//! assert_eq!(again, home);
//! let lived_in = clutter(&home, &library, 7)?; // books on shelves, dishes in cabinets
//! let built = lived_in.build(&library)?; // the world, everything asleep
//! assert_eq!(built.objects.len(), lived_in.objects.len());
//! # Ok(())
//! # }
//! ```

mod archetype;
mod catalog;
mod clutter;
mod coverage;
mod home;
mod library;
mod scene;
mod tessellate;
mod urdf;

pub use archetype::{Archetype, Layout, Material, Shape};
pub use catalog::CATALOG;
pub use clutter::{ClutterError, clutter};
pub use coverage::{Requirements, covering, first_covering, missing, requirements};
pub use home::{
    DOOR_CLEARANCE, DOORWAY, Family, NAMED_HOMES, RoomSpec, UnknownFamily, WALL_THICKNESS,
    generate, generate_family, named_home, named_homes, room_spec,
};
pub use library::{AssetError, Library};
pub use scene::{
    BuiltScene, ClutterPlan, FLOOR_THICKNESS, ObjectPlan, RUG_THICKNESS, RoomPlan, RugPlan, Scene,
    SceneError, WALL_HEIGHT, WallPlan,
};
pub use urdf::{ImportError, import_urdf};
