//! Fetch drawn with its maker's meshes: gymnasium-robotics' MuJoCo model of Fetch (its
//! `fetch/robot.xml` and `fetch/shared.xml`, with STL meshes from Fetch Robotics'
//! `fetch_description`), fetched from PyPI at first use by `behavior-data` and read here into a
//! [`ModelLibrary`] with one piece per [`FetchLink`]. The world names the piece on each link's
//! object ([`behavior_sim::ObjectSpec::model`]); collision stays our own primitives, which are
//! also the look wherever a renderer holds no meshes.
//!
//! The reader understands what that model uses: nested `<body>` elements with `pos` and `quat`
//! (or `euler` in degrees, MuJoCo's default), `<geom>` elements of type mesh (the default of the
//! model's class) with their own `pos`/`quat`, colours from the geom's `rgba` or its class's
//! (a `class` on the geom, else the nearest `childclass` above it), and the `<mesh>`
//! definitions that name the files. Box geoms (the fingers) are left out: the fingers are drawn
//! from our own pads, which are the same boxes. Bodies are posed with every joint at zero, which
//! is the frame each of our links has.

use crate::fetch_body::FetchLink;
use behavior_data::RobotAssets;
use behavior_sim::{Material, Model, ModelLibrary, ModelPiece, Visual, VisualMesh};
use rapier3d::math::{Pose, Rotation, Vector};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

/// Why Fetch's model could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// The assets could not be found or fetched.
    #[error(transparent)]
    Data(#[from] behavior_data::DataError),
    /// A file could not be read.
    #[error("cannot read {path}: {cause}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        cause: std::io::Error,
    },
    /// A file is not what the model should be.
    #[error("{path}: {reason}")]
    Bad {
        /// The file.
        path: PathBuf,
        /// What is wrong, and where.
        reason: String,
    },
}

/// The MuJoCo bodies drawn as each of our links, in [`FetchLink::ALL`] order; the first names
/// the link's frame.
const BODIES: [&[&str]; 11] = [
    &["base_link", "torso_fixed_link", "estop_link", "laser_link"],
    &["torso_lift_link"],
    &["head_pan_link"],
    &["head_tilt_link"],
    &["shoulder_pan_link"],
    &["shoulder_lift_link"],
    &["upperarm_roll_link"],
    &["elbow_flex_link"],
    &["forearm_roll_link"],
    &["wrist_flex_link"],
    &["gripper_link", "wrist_roll_link"],
];

/// The prefix gymnasium-robotics gives every name of the robot.
const PREFIX: &str = "robot0:";

/// A link's piece in the world's model pieces.
pub fn fetch_piece(link: FetchLink) -> ModelPiece {
    ModelPiece {
        model: Model::Fetch,
        piece: link as u8,
    }
}

/// The model pieces every robot can be drawn with, located (and fetched, at the first call on a
/// machine) once per process and shared by every renderer. Where they cannot be had, robots keep
/// their procedural look: the library is empty, and the reason is printed once to stderr (set
/// `BEHAVIOR_ROBOT_ASSETS=none` to do without on purpose, silently).
pub fn shared_models() -> Arc<ModelLibrary> {
    static MODELS: OnceLock<Arc<ModelLibrary>> = OnceLock::new();
    let models = MODELS.get_or_init(|| {
        let located = RobotAssets::locate(|line| eprintln!("behavior: {line}"));
        let loaded = located
            .map_err(ModelError::from)
            .and_then(|found| match found {
                Some(assets) => fetch_models(&assets),
                None => Ok(ModelLibrary::default()),
            });
        match loaded {
            Ok(models) => Arc::new(models),
            Err(e) => {
                eprintln!("behavior: robots keep their procedural look: {e}");
                Arc::new(ModelLibrary::default())
            }
        }
    });
    Arc::clone(models)
}

/// Reads Fetch's model into one piece per link, each piece's meshes in its link's frame.
pub fn fetch_models(assets: &RobotAssets) -> Result<ModelLibrary, ModelError> {
    let definitions = Definitions::read(&assets.fetch_definitions())?;
    let path = assets.fetch_model();
    let text = read(&path)?;
    let bad = |reason: String| ModelError::Bad {
        path: path.clone(),
        reason,
    };
    let document = roxmltree::Document::parse(&text).map_err(|e| bad(e.to_string()))?;
    let mut bodies = BTreeMap::new();
    for body in document.root_element().children().filter(is("body")) {
        collect(body, Pose::IDENTITY, "", &mut bodies).map_err(bad)?;
    }
    let mut library = ModelLibrary::default();
    for (link, names) in FetchLink::ALL.into_iter().zip(BODIES) {
        let frame = bodies
            .get(names[0])
            .ok_or_else(|| bad(format!("no body {PREFIX}{}", names[0])))?
            .pose;
        let mut meshes = Vec::new();
        for name in names {
            let body = bodies
                .get(*name)
                .ok_or_else(|| bad(format!("no body {PREFIX}{name}")))?;
            for geom in &body.geoms {
                let place = frame.inverse() * body.pose * geom.pose;
                meshes.push(definitions.mesh(geom, place, assets)?);
            }
        }
        library.insert(fetch_piece(link), meshes);
    }
    Ok(library)
}

/// A body's pose in the model's frame and its mesh geoms.
struct Body {
    pose: Pose,
    geoms: Vec<Geom>,
}

/// A mesh geom: which mesh, where in its body, and its colour's source.
struct Geom {
    mesh: String,
    pose: Pose,
    rgba: Option<[f32; 3]>,
    class: String,
}

fn is(name: &'static str) -> impl Fn(&roxmltree::Node) -> bool {
    move |n| n.has_tag_name(name)
}

/// Reads a body and the bodies inside it, named without the prefix.
fn collect(
    node: roxmltree::Node,
    parent: Pose,
    class: &str,
    out: &mut BTreeMap<String, Body>,
) -> Result<(), String> {
    let name = node.attribute("name").unwrap_or_default();
    let at = format!("body `{name}` (line {})", line_of(node));
    let pose = parent * placement(node).map_err(|e| format!("{at}: {e}"))?;
    let class = node.attribute("childclass").unwrap_or(class);
    let mut geoms = Vec::new();
    for geom in node.children().filter(is("geom")) {
        let Some(mesh) = geom.attribute("mesh") else {
            continue;
        };
        let at = format!("geom of {at}");
        geoms.push(Geom {
            mesh: mesh.to_string(),
            pose: placement(geom).map_err(|e| format!("{at}: {e}"))?,
            rgba: geom
                .attribute("rgba")
                .map(rgb)
                .transpose()
                .map_err(|e| format!("{at}: {e}"))?,
            class: geom.attribute("class").unwrap_or(class).to_string(),
        });
    }
    if let Some(short) = name.strip_prefix(PREFIX) {
        out.insert(short.to_string(), Body { pose, geoms });
    }
    for child in node.children().filter(is("body")) {
        collect(child, pose, class, out)?;
    }
    Ok(())
}

fn line_of(node: roxmltree::Node) -> u32 {
    node.document().text_pos_at(node.range().start).row
}

/// An element's `pos` with its `quat` (w x y z) or `euler` (x y z, degrees, rotating about the
/// moving axes in that order, MuJoCo's defaults).
fn placement(node: roxmltree::Node) -> Result<Pose, String> {
    let position = match node.attribute("pos") {
        Some(text) => numbers::<3>(text)?,
        None => [0.0; 3],
    };
    let rotation = if let Some(text) = node.attribute("quat") {
        let [w, x, y, z] = numbers::<4>(text)?;
        let q = Rotation::from_xyzw(x, y, z, w);
        if q.length() <= 1e-6 {
            return Err(format!("quat `{text}` has no length"));
        }
        q.normalize()
    } else if let Some(text) = node.attribute("euler") {
        let [x, y, z] = numbers::<3>(text)?.map(f32::to_radians);
        Rotation::from_rotation_x(x) * Rotation::from_rotation_y(y) * Rotation::from_rotation_z(z)
    } else {
        Rotation::IDENTITY
    };
    Ok(Pose::from_parts(Vector::from_array(position), rotation))
}

fn numbers<const N: usize>(text: &str) -> Result<[f32; N], String> {
    let values: Vec<f32> = text
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .map_err(|_| format!("`{text}` is not {N} numbers"))?;
    let values: [f32; N] = values
        .try_into()
        .map_err(|_| format!("`{text}` is not {N} numbers"))?;
    if values.iter().all(|v| v.is_finite()) {
        Ok(values)
    } else {
        Err(format!("`{text}` is not {N} finite numbers"))
    }
}

fn rgb(text: &str) -> Result<[f32; 3], String> {
    let [r, g, b, _] = numbers::<4>(text)?;
    Ok([r, g, b])
}

/// What `shared.xml` defines: each mesh's file and each class's geom colour.
struct Definitions {
    files: BTreeMap<String, String>,
    colours: BTreeMap<String, [f32; 3]>,
}

impl Definitions {
    fn read(path: &Path) -> Result<Definitions, ModelError> {
        let text = read(path)?;
        let bad = |reason: String| ModelError::Bad {
            path: path.to_path_buf(),
            reason,
        };
        let document = roxmltree::Document::parse(&text).map_err(|e| bad(e.to_string()))?;
        let mut files = BTreeMap::new();
        let mut colours = BTreeMap::new();
        for node in document.descendants() {
            if node.has_tag_name("mesh")
                && let (Some(name), Some(file)) = (node.attribute("name"), node.attribute("file"))
            {
                files.insert(name.to_string(), file.to_string());
            }
            if node.has_tag_name("default")
                && let Some(class) = node.attribute("class")
                && let Some(geom) = node.children().find(is("geom"))
                && let Some(text) = geom.attribute("rgba")
            {
                let colour = rgb(text)
                    .map_err(|e| bad(format!("class `{class}` (line {}): {e}", line_of(geom))))?;
                colours.insert(class.to_string(), colour);
            }
        }
        Ok(Definitions { files, colours })
    }

    /// A geom's mesh, placed by `place` (from its file's frame to its link's), with its colour.
    fn mesh(
        &self,
        geom: &Geom,
        place: Pose,
        assets: &RobotAssets,
    ) -> Result<VisualMesh, ModelError> {
        let file = self.files.get(&geom.mesh).ok_or_else(|| ModelError::Bad {
            path: assets.fetch_definitions(),
            reason: format!("no <mesh> named `{}`", geom.mesh),
        })?;
        // A file name, never a path out of the meshes' folder.
        let path = assets
            .fetch_meshes()
            .join(Path::new(file).file_name().unwrap_or_default());
        let mut reader = std::fs::File::open(&path).map_err(|cause| ModelError::Io {
            path: path.clone(),
            cause,
        })?;
        let stl = stl_io::read_stl(&mut reader).map_err(|cause| ModelError::Io {
            path: path.clone(),
            cause,
        })?;
        let vertices: Vec<Vector> = stl
            .vertices
            .iter()
            .map(|v| place.transform_point(Vector::new(v[0], v[1], v[2])))
            .collect();
        let triangles: Vec<[u32; 3]> = stl
            .faces
            .iter()
            .map(|f| f.vertices.map(|i| i as u32))
            .collect();
        let usable = vertices.iter().all(|p| p.is_finite())
            && triangles
                .iter()
                .flatten()
                .all(|&i| (i as usize) < vertices.len());
        if triangles.is_empty() || !usable {
            return Err(ModelError::Bad {
                path,
                reason: format!(
                    "not a usable mesh ({} vertices, {} triangles)",
                    vertices.len(),
                    triangles.len()
                ),
            });
        }
        let [r, g, b] = geom
            .rgba
            .or_else(|| self.colours.get(&geom.class).copied())
            .unwrap_or([1.0; 3]);
        Ok(VisualMesh {
            link: None,
            vertices,
            triangles,
            visual: Visual {
                color: [r, g, b].map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8),
                material: Material::Plastic,
            },
        })
    }
}

fn read(path: &Path) -> Result<String, ModelError> {
    std::fs::read_to_string(path).map_err(|cause| ModelError::Io {
        path: path.to_path_buf(),
        cause,
    })
}
