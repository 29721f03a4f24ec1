//! Sensors for BEHAVIOR: cameras drawn by an offscreen rasterizer, and lidar.
//!
//! A [`Renderer`] draws a [`Scene`] — the world's visual description
//! ([`behavior_sim::Visuals::parts`]), labelled by a [`CategoryTable`] and a highlight set —
//! through a [`View`] (a [`Camera`] and its previous frame) into the [`Modality`]s asked for:
//! colour, depth, normals, semantic and instance segmentation, the highlight mask, optical and
//! scene flow. Only what is asked for is drawn and read back: the flow modalities take a second
//! pass, each image its own readback.
//!
//! It runs headless on any machine: wgpu on Vulkan, through Mesa's lavapipe on a CPU (Debian's
//! `mesa-vulkan-drivers libvulkan1`) or a GPU's driver; Metal and DX12 elsewhere. Without an
//! adapter [`Renderer::new`] says which packages to install.
//!
//! Colour comes in two [`ImageProfile`]s, chosen per [`View`]: `realistic` (the default:
//! procedural materials in each home's palette, `finish.rs`; the home's sun with shadow maps and
//! ambient occlusion from a map of the fixed geometry seen from above, `shadow.rs`; sky and
//! ground ambient and a lamp per room, `lighting.rs`; filmic tone mapping, `realistic.wgsl`) and `fast` (flat colours under one light, `shader.wgsl`). Depth, normals,
//! segmentation and flow are drawn by the same arithmetic in both and are identical.
//!
//! States are visible (see `appearance.rs`): cooked browner, burnt dark, frozen frosted, soaked
//! darker, toggled on glowing; doors and drawers at their joints, sliced halves, dust and stain
//! particles on the surfaces they lie on, and water drops, as the world has them.
//!
//! [`to_glb`] writes the world as a binary glTF 2.0 file with the same meshes and the realistic
//! profile's materials, its procedural patterns baked into repeating images (`texture.rs`);
//! [`GltfWriter`] makes such a file node by node, at the browser viewer's lighter
//! [`GltfDetail`] where asked.
//!
//! Objects that name a model piece (a robot's link) are drawn with the piece's real meshes where
//! the renderer was handed a library that holds them ([`Renderer::set_models`]; the robots crate
//! reads Fetch's), once they are 20 pixels or more in radius on the image, and from their own
//! parts otherwise; shadows are always cast by the parts, which follow the meshes within a few
//! centimetres. A camera inside a piece's box does not draw it.
//!
//! [`Lidar`] casts beams through the world's batched ray queries: a planar fan (Fetch's base
//! laser) or a multi-beam 3-D scan, as points and as a range image.
//!
//! It knows nothing of activities, episodes or robots (a model piece is a name with meshes): an
//! environment places the cameras (an eye, a head camera) and says what to highlight.
//!
//! A lidar needs no graphics adapter:
//!
//! ```
//! use behavior_render::{Lidar, Pattern};
//! use behavior_sim::{ObjectSpec, Part, Primitive, QueryFilter, World};
//! use rapier3d::math::{Pose, Vector};
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let mut world = World::default();
//! let slab = Part::new(Primitive::Box {
//!     half_extents: Vector::new(0.1, 2.0, 1.0),
//! });
//! let wall = ObjectSpec::new("wall_1", "wall.n.01", vec![slab]);
//! world.add(wall.at(Vector::new(2.0, 0.0, 0.0)).fixed())?;
//! let lidar = Lidar {
//!     pose: Pose::IDENTITY,
//!     pattern: Pattern::Planar { beams: 3, fov: 0.5 },
//!     min_range: 0.05,
//!     max_range: 10.0,
//! };
//! let scan = lidar.scan(&world, &QueryFilter::default())?;
//! assert!((scan.ranges[1] - 1.9).abs() < 1e-3); // straight ahead: the wall's near face
//! # Ok(())
//! # }
//! ```

mod appearance;
mod camera;
mod categories;
mod error;
mod export;
mod finish;
mod frame_geometry;
mod gltf;
mod gpu;
mod instances;
mod lidar;
mod lighting;
mod mesh;
mod modality;
mod occlusion;
mod pipeline;
mod profile;
mod renderer;
mod shadow;
mod sunlight;
mod targets;
mod texture;

pub use appearance::{DUST, Look, STAIN, ToneLook, WATER, state_look, to_linear, tone_look};
pub use camera::{Camera, EYE_FOV, EYE_SIZE, FAR, NEAR};
pub use categories::{CategoryTable, DUST_CATEGORY, STAIN_CATEGORY, WATER_CATEGORY};
pub use error::RenderError;
pub use export::{ExportError, save_npy, save_png, to_rgb};
pub use finish::{Finishes, PartFinish};
pub use gltf::{GltfDetail, GltfWriter, to_glb};
pub use instances::Scene;
pub use lidar::{Lidar, Pattern, Scan};
pub use modality::{Frame, Image, Modality, Pixels, UnknownModality};
pub use profile::{ImageProfile, UnknownProfile};
pub use renderer::{FrameStats, Renderer, View};
