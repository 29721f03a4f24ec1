//! Importing a URDF model (with OBJ or STL meshes) as an object, so users can bring real assets.
//!
//! The root link becomes the object's body; links attached to it by `fixed` joints merge into it;
//! links on `revolute`, `continuous` or `prismatic` joints become its doors and drawers (one level:
//! a moving link may carry fixed links, not further moving ones). Joint limits must start at 0
//! (closed); a `continuous` joint opens up to a full turn.
//!
//! **Collision.** A link's collision geometry comes from its `<collision>` elements, or, when it
//! has none, from its `<visual>` ones: boxes, cylinders (along z, as ours) and spheres map to
//! primitives; a collision mesh becomes its convex hull, and a visual mesh standing in for missing
//! collision geometry is split into convex parts with parry's V-HACD (or, if that yields only flat
//! parts, replaced by its convex hull).
//!
//! **Appearance.** Every `<visual>` element is also kept as a [`VisualMesh`] in
//! [`ObjectSpec::meshes`], so a renderer draws the model as its author made it rather than its
//! collision hulls: a mesh with its own triangles (scaled, and with its winding reversed under a
//! mirroring scale so faces still point outward); a box, cylinder or sphere triangulated (24
//! sides, and 12 × 24 facets for a sphere). Vertices are in the object's frame with every joint
//! at zero, and each mesh belongs to the body (`link: None`) or to the moving link its URDF link
//! hangs from. Its colour is the visual's `<material><color rgba>`, or that of the robot-level
//! `<material>` its name refers to, read as sRGB components from 0 to 1 (as RViz shows them) and
//! rounded to bytes, alpha ignored; without one it takes the object's default [`Visual`].
//! Textures are ignored.
//!
//! A body or link that has visual meshes is drawn from them *instead of* its collision parts, so
//! a body keeps its visual meshes only if every `<visual>` of the URDF links merged into it could
//! be read: where one cannot (a COLLADA file, a missing file, a bad colour) while collision
//! elements give the link its shape, that body keeps none and is drawn from its collision parts;
//! the import does not fail for appearance alone. Where the visuals are the collision geometry,
//! their errors are errors, as before.

use behavior_sim::{
    Form, JointKind, JointSpec, LinkSpec, ObjectSpec, Part, Primitive, Visual, VisualMesh,
};
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::shape::ConvexPolyhedron;
use rapier3d::parry::transformation::vhacd::{VHACD, VHACDParameters};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Why a URDF file could not be imported. Each message names the file and carries its cause (no
/// separate [`std::error::Error::source`], so a report that walks sources does not repeat it).
#[derive(Debug, thiserror::Error)]
pub enum ImportError {
    /// The file could not be read.
    #[error("cannot read {path}: {cause}")]
    Io {
        /// The URDF file.
        path: PathBuf,
        /// The operating system's reason.
        cause: std::io::Error,
    },
    /// The file is not well-formed XML.
    #[error("{path}: not valid XML: {cause}")]
    Xml {
        /// The URDF file.
        path: PathBuf,
        /// The parser's reason, with its position.
        cause: roxmltree::Error,
    },
    /// The XML is not a model this importer supports (a bad tree, joint, geometry or mesh).
    #[error("{path}: {reason}")]
    Model {
        /// The URDF file.
        path: PathBuf,
        /// What is wrong, naming the link or joint at fault.
        reason: String,
    },
}

/// Reads a URDF file into an object spec named `name` of synset `category`. Mesh file names are
/// relative to the URDF's directory (a `package://` prefix is dropped).
pub fn import_urdf(path: &Path, name: &str, category: &str) -> Result<ObjectSpec, ImportError> {
    let text = std::fs::read_to_string(path).map_err(|cause| ImportError::Io {
        path: path.to_path_buf(),
        cause,
    })?;
    let doc = roxmltree::Document::parse(&text).map_err(|cause| ImportError::Xml {
        path: path.to_path_buf(),
        cause,
    })?;
    let dir = path.parent().unwrap_or(Path::new("."));
    model(&doc, dir, name, category).map_err(|reason| ImportError::Model {
        path: path.to_path_buf(),
        reason,
    })
}

/// The object a parsed URDF describes.
fn model(
    doc: &roxmltree::Document,
    dir: &Path,
    name: &str,
    category: &str,
) -> Result<ObjectSpec, String> {
    let robot = doc.root_element();
    if robot.tag_name().name() != "robot" {
        return Err("the root element is not <robot>".into());
    }
    let links: BTreeMap<String, roxmltree::Node> = robot
        .children()
        .filter(|n| n.has_tag_name("link"))
        .filter_map(|n| Some((n.attribute("name")?.to_string(), n)))
        .collect();
    let joints: Vec<Joint> = robot
        .children()
        .filter(|n| n.has_tag_name("joint"))
        .map(Joint::parse)
        .collect::<Result<_, _>>()?;
    let root = root_link(&links, &joints)?;
    let placed = place_links(root, &joints)?;
    let materials = named_colors(robot);
    let mut base = Body::default();
    let mut moving: BTreeMap<usize, Body> = BTreeMap::new();
    for (link_name, (pose, hangs_from)) in &placed {
        let geometry = link_geometry(links[link_name], dir, *pose, &materials)
            .map_err(|e| format!("link `{link_name}`: {e}"))?;
        match hangs_from {
            None => base.add(geometry),
            Some(k) => moving.entry(*k).or_default().add(geometry),
        }
    }
    if base.parts.is_empty() {
        return Err("the root link has no geometry".into());
    }
    let mut spec = ObjectSpec::new(name, category, Vec::new());
    let look = spec.visual;
    spec.meshes.extend(base.meshes(None, look));
    spec.parts = base.parts;
    for (k, body) in moving {
        let j = &joints[k];
        let (kind, range) = j.kind.expect("only moving joints are collected");
        if body.parts.is_empty() {
            return Err(format!("joint `{}` moves a link without geometry", j.name));
        }
        let frame = placed[&j.parent].0 * j.origin;
        spec.meshes
            .extend(body.meshes(Some(spec.links.len()), look));
        spec.links.push(LinkSpec {
            name: j.name.clone(),
            parts: body.parts,
            parent: None,
            joint: JointSpec::opening(kind, frame.translation, frame.rotation * j.axis, range, 2.0),
            density: spec.density,
        });
    }
    Ok(spec)
}

/// The one link no joint has as its child, after checking that every joint's ends exist.
fn root_link<'l>(
    links: &'l BTreeMap<String, roxmltree::Node>,
    joints: &[Joint],
) -> Result<&'l String, String> {
    let children: Vec<&str> = joints.iter().map(|j| j.child.as_str()).collect();
    let roots: Vec<&String> = links
        .keys()
        .filter(|l| !children.contains(&l.as_str()))
        .collect();
    let [root] = roots.as_slice() else {
        return Err(format!("expected one root link, found {}", roots.len()));
    };
    for j in joints {
        for end in [&j.parent, &j.child] {
            if !links.contains_key(end) {
                return Err(format!(
                    "joint `{}` names a link `{end}` that does not exist",
                    j.name
                ));
            }
        }
    }
    Ok(root)
}

/// Each link's pose in the root frame (joints at position 0), and the moving joint it hangs from
/// (`None` for links merged into the body).
fn place_links(
    root: &str,
    joints: &[Joint],
) -> Result<BTreeMap<String, (Pose, Option<usize>)>, String> {
    let mut placed: BTreeMap<String, (Pose, Option<usize>)> = BTreeMap::new();
    placed.insert(root.to_string(), (Pose::IDENTITY, None));
    let mut frontier = vec![root.to_string()];
    while let Some(parent) = frontier.pop() {
        let (parent_pose, parent_moving) = placed[&parent];
        for (k, j) in joints
            .iter()
            .enumerate()
            .filter(|(_, j)| j.parent == parent)
        {
            let moving = match (&j.kind, parent_moving) {
                (None, m) => m,
                (Some(_), None) => Some(k),
                (Some(_), Some(_)) => {
                    return Err(format!(
                        "joint `{}`: moving links on moving links are not supported",
                        j.name
                    ));
                }
            };
            if placed
                .insert(j.child.clone(), (parent_pose * j.origin, moving))
                .is_some()
            {
                return Err(format!("link `{}` has two parents", j.child));
            }
            frontier.push(j.child.clone());
        }
    }
    Ok(placed)
}

/// A `<joint>` as this importer uses it.
struct Joint {
    name: String,
    parent: String,
    child: String,
    /// `None` for a fixed joint; else the kind and its opening range.
    kind: Option<(JointKind, f32)>,
    origin: Pose,
    axis: Vector,
}

impl Joint {
    fn parse(node: roxmltree::Node) -> Result<Joint, String> {
        let name = node.attribute("name").unwrap_or("?").to_string();
        let child_attr = |tag: &str| {
            node.children()
                .find(|c| c.has_tag_name(tag))
                .and_then(|c| c.attribute("link"))
                .map(str::to_string)
                .ok_or_else(|| format!("joint `{name}` has no <{tag} link=...>"))
        };
        let (parent, child) = (child_attr("parent")?, child_attr("child")?);
        let origin = origin(node).map_err(|e| format!("joint `{name}`: {e}"))?;
        let axis = match node.children().find(|c| c.has_tag_name("axis")) {
            Some(a) => vector(a.attribute("xyz").unwrap_or("1 0 0"))
                .map_err(|e| format!("joint `{name}`: {e}"))?,
            None => Vector::X,
        };
        if axis.length() < 1e-6 {
            return Err(format!("joint `{name}` has a zero axis"));
        }
        let limit = |attr: &str| -> Result<Option<f32>, String> {
            node.children()
                .find(|c| c.has_tag_name("limit"))
                .and_then(|l| l.attribute(attr))
                .map(|v| {
                    v.trim()
                        .parse::<f32>()
                        .map_err(|_| format!("joint `{name}`: bad limit {attr}=\"{v}\""))
                })
                .transpose()
        };
        let kind = match node.attribute("type").unwrap_or("") {
            "fixed" => None,
            "continuous" => Some((JointKind::Revolute, std::f32::consts::TAU)),
            t @ ("revolute" | "prismatic") => {
                let (lower, upper) = (
                    limit("lower")?.unwrap_or(0.0),
                    limit("upper")?.unwrap_or(0.0),
                );
                if lower.abs() > 1e-6 || !(upper.is_finite() && upper > 0.0) {
                    return Err(format!(
                        "joint `{name}`: limits must run from 0 (closed) to a positive opening, got [{lower}, {upper}]"
                    ));
                }
                let kind = if t == "revolute" {
                    JointKind::Revolute
                } else {
                    JointKind::Prismatic
                };
                Some((kind, upper))
            }
            other => return Err(format!("joint `{name}` has unsupported type `{other}`")),
        };
        Ok(Joint {
            name,
            parent,
            child,
            kind,
            origin,
            axis: axis.normalize(),
        })
    }
}

fn vector(text: &str) -> Result<Vector, String> {
    let values: Vec<f32> = text
        .split_whitespace()
        .map(|v| {
            v.parse::<f32>()
                .map_err(|_| format!("`{text}` is not three numbers"))
        })
        .collect::<Result<_, _>>()?;
    match values.as_slice() {
        [x, y, z] if values.iter().all(|v| v.is_finite()) => Ok(Vector::new(*x, *y, *z)),
        _ => Err(format!("`{text}` is not three numbers")),
    }
}

/// An element's `<origin xyz rpy>` (roll about x, then pitch about y, then yaw about z).
fn origin(node: roxmltree::Node) -> Result<Pose, String> {
    let Some(o) = node.children().find(|c| c.has_tag_name("origin")) else {
        return Ok(Pose::IDENTITY);
    };
    let xyz = vector(o.attribute("xyz").unwrap_or("0 0 0"))?;
    let rpy = vector(o.attribute("rpy").unwrap_or("0 0 0"))?;
    let rotation = Rotation::from_rotation_z(rpy.z)
        * Rotation::from_rotation_y(rpy.y)
        * Rotation::from_rotation_x(rpy.x);
    Ok(Pose::from_parts(xyz, rotation))
}

/// A body of the object (its own, or one moving link) gathered from the URDF links merged into
/// it: collision parts, and the looks of their visual elements, or `None` once one of those could
/// not be read (the body is then drawn from its collision parts).
struct Body {
    parts: Vec<Part>,
    looks: Option<Vec<Look>>,
}

impl Default for Body {
    fn default() -> Body {
        Body {
            parts: Vec::new(),
            looks: Some(Vec::new()),
        }
    }
}

impl Body {
    fn add(&mut self, geometry: LinkGeometry) {
        self.parts.extend(geometry.parts);
        match (&mut self.looks, geometry.looks) {
            (Some(looks), Some(more)) => looks.extend(more),
            _ => self.looks = None,
        }
    }

    /// Its looks as the visual meshes of `link`, coloured or in the object's `default` look.
    fn meshes(&self, link: Option<usize>, default: Visual) -> Vec<VisualMesh> {
        self.looks
            .iter()
            .flatten()
            .map(|look| VisualMesh {
                link,
                vertices: look.vertices.clone(),
                triangles: look.triangles.clone(),
                visual: Visual {
                    color: look.color.unwrap_or(default.color),
                    material: default.material,
                },
            })
            .collect()
    }
}

/// A visual element as drawn: a triangle mesh in the object's frame, and its colour if it has one.
struct Look {
    vertices: Vec<Vector>,
    triangles: Vec<[u32; 3]>,
    color: Option<[u8; 3]>,
}

/// What one URDF link contributes: its collision parts, and its looks (`None` if a visual
/// element could not be read).
struct LinkGeometry {
    parts: Vec<Part>,
    looks: Option<Vec<Look>>,
}

/// A `<collision>` or `<visual>` element read: its shape and its pose in the object's frame.
struct Element {
    at: Pose,
    shape: Shape,
}

/// The shape of an element, in its own frame.
enum Shape {
    Box {
        half_extents: Vector,
    },
    Cylinder {
        radius: f32,
        half_height: f32,
    },
    Sphere {
        radius: f32,
    },
    Mesh {
        file: String,
        /// Scaled.
        points: Vec<Vector>,
        triangles: Vec<[u32; 3]>,
        /// Scaled by a negative determinant, which turns its faces inside out.
        mirrored: bool,
    },
}

/// The collision parts and looks of a link, placed by `pose` (the link's frame in the object's).
fn link_geometry(
    link: roxmltree::Node,
    dir: &Path,
    pose: Pose,
    materials: &BTreeMap<String, roxmltree::Node>,
) -> Result<LinkGeometry, String> {
    let collisions: Vec<roxmltree::Node> = link
        .children()
        .filter(|c| c.has_tag_name("collision"))
        .collect();
    let visuals = link.children().filter(|c| c.has_tag_name("visual"));
    let mut parts = Vec::new();
    let mut looks = Some(Vec::new());
    let mut keep = |look: Result<Look, String>| match (&mut looks, look) {
        (Some(all), Ok(look)) => all.push(look),
        _ => looks = None,
    };
    if collisions.is_empty() {
        // The visual elements are the collision geometry too: errors in them are errors.
        for node in visuals {
            if let Some(element) = read_element(node, dir, pose)? {
                parts.extend(collision_parts(&element, true)?);
                keep(look(node, &element, materials));
            }
        }
    } else {
        for node in collisions {
            if let Some(element) = read_element(node, dir, pose)? {
                parts.extend(collision_parts(&element, false)?);
            }
        }
        for node in visuals {
            match read_element(node, dir, pose) {
                Ok(Some(element)) => keep(look(node, &element, materials)),
                Ok(None) => {}
                Err(e) => keep(Err(e)),
            }
        }
    }
    Ok(LinkGeometry { parts, looks })
}

/// An element's shape and pose, or `None` if it has no geometry.
fn read_element(
    element: roxmltree::Node,
    dir: &Path,
    pose: Pose,
) -> Result<Option<Element>, String> {
    let at = pose * origin(element)?;
    let Some(geometry) = element.children().find(|c| c.has_tag_name("geometry")) else {
        return Ok(None);
    };
    let Some(shape) = geometry.children().find(|c| c.is_element()) else {
        return Ok(None);
    };
    let number = |attr: &str| -> Result<f32, String> {
        shape
            .attribute(attr)
            .and_then(|v| v.trim().parse::<f32>().ok())
            .filter(|v| v.is_finite() && *v > 0.0)
            .ok_or_else(|| format!("<{}> needs a positive `{attr}`", shape.tag_name().name()))
    };
    let shape = match shape.tag_name().name() {
        "box" => Shape::Box {
            half_extents: vector(shape.attribute("size").unwrap_or(""))? * 0.5,
        },
        "cylinder" => Shape::Cylinder {
            radius: number("radius")?,
            half_height: number("length")? / 2.0,
        },
        "sphere" => Shape::Sphere {
            radius: number("radius")?,
        },
        "mesh" => {
            let file = shape
                .attribute("filename")
                .ok_or("<mesh> needs a `filename`")?;
            let scale = match shape.attribute("scale") {
                Some(s) => vector(s)?,
                None => Vector::ONE,
            };
            let (points, triangles) = load_mesh(&dir.join(file.trim_start_matches("package://")))?;
            let points: Vec<Vector> = points.into_iter().map(|p| p * scale).collect();
            if !points.iter().all(|p| p.is_finite()) {
                return Err(format!(
                    "mesh `{file}` scaled by {scale} has non-finite points"
                ));
            }
            Shape::Mesh {
                file: file.to_string(),
                points,
                triangles,
                mirrored: scale.x * scale.y * scale.z < 0.0,
            }
        }
        other => return Err(format!("unsupported geometry <{other}>")),
    };
    Ok(Some(Element { at, shape }))
}

/// An element as collision parts: a primitive, a mesh's convex hull, or — for a visual mesh
/// standing in for missing collision geometry — its V-HACD decomposition.
fn collision_parts(element: &Element, from_visual: bool) -> Result<Vec<Part>, String> {
    let part = |primitive| Part {
        primitive,
        offset: element.at,
        visual: None,
        form: Form::Primitive,
    };
    let primitive = match &element.shape {
        &Shape::Box { half_extents } => Primitive::Box { half_extents },
        &Shape::Cylinder {
            radius,
            half_height,
        } => Primitive::Cylinder {
            radius,
            half_height,
        },
        &Shape::Sphere { radius } => Primitive::Sphere { radius },
        Shape::Mesh {
            file,
            points,
            triangles,
            ..
        } => {
            if from_visual {
                // No collision geometry: approximate the visual mesh by convex parts, keeping
                // those with volume (thin meshes can yield flat ones).
                let hulls: Vec<Vec<Vector>> =
                    VHACD::decompose(&VHACDParameters::default(), points, triangles, false)
                        .compute_convex_hulls(4)
                        .into_iter()
                        .map(|(hull, _)| hull)
                        .filter(|hull| ConvexPolyhedron::from_convex_hull(hull).is_some())
                        .collect();
                if !hulls.is_empty() {
                    return Ok(hulls
                        .into_iter()
                        .map(|points| part(Primitive::ConvexHull { points }))
                        .collect());
                }
            }
            if ConvexPolyhedron::from_convex_hull(points).is_none() {
                return Err(format!("mesh `{file}` is flat: it encloses no volume"));
            }
            Primitive::ConvexHull {
                points: points.clone(),
            }
        }
    };
    Ok(vec![part(primitive)])
}

/// A visual element as drawn: its mesh, or its primitive triangulated, moved into the object's
/// frame, with the colour of its material.
fn look(
    node: roxmltree::Node,
    element: &Element,
    materials: &BTreeMap<String, roxmltree::Node>,
) -> Result<Look, String> {
    let color = material_color(node, materials)?;
    let (points, triangles) = match &element.shape {
        Shape::Mesh {
            points,
            triangles,
            mirrored,
            ..
        } => {
            let triangles = if *mirrored {
                triangles.iter().map(|&[a, b, c]| [a, c, b]).collect()
            } else {
                triangles.clone()
            };
            (points.clone(), triangles)
        }
        &Shape::Box { half_extents } => crate::tessellate::cuboid(half_extents),
        &Shape::Cylinder {
            radius,
            half_height,
        } => crate::tessellate::cylinder(radius, half_height, 24),
        &Shape::Sphere { radius } => crate::tessellate::sphere(radius, 12, 24),
    };
    Ok(Look {
        vertices: points
            .into_iter()
            .map(|p| element.at.transform_point(p))
            .collect(),
        triangles,
        color,
    })
}

/// The `rgba` of a material's `<color>`.
fn rgba<'a>(material: roxmltree::Node<'a, '_>) -> Option<&'a str> {
    material
        .children()
        .find(|c| c.has_tag_name("color"))
        .and_then(|c| c.attribute("rgba"))
}

/// The robot-level `<material name>` elements, which visuals may refer to by name.
fn named_colors<'a, 'i>(
    robot: roxmltree::Node<'a, 'i>,
) -> BTreeMap<String, roxmltree::Node<'a, 'i>> {
    robot
        .children()
        .filter(|n| n.has_tag_name("material"))
        .filter_map(|n| Some((n.attribute("name")?.to_string(), n)))
        .collect()
}

/// The colour of a visual's `<material>`: its own `<color rgba>`, else that of the robot-level
/// material of its name; `None` when neither gives one.
fn material_color(
    visual: roxmltree::Node,
    materials: &BTreeMap<String, roxmltree::Node>,
) -> Result<Option<[u8; 3]>, String> {
    let Some(material) = visual.children().find(|c| c.has_tag_name("material")) else {
        return Ok(None);
    };
    let named = material.attribute("name").and_then(|n| materials.get(n));
    let Some(text) = rgba(material).or_else(|| named.and_then(|&m| rgba(m))) else {
        return Ok(None);
    };
    let values: Vec<f32> = text
        .split_whitespace()
        .map(|v| v.parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("`{text}` is not an rgba colour"))?;
    match values.as_slice() {
        [r, g, b, _] | [r, g, b] if values.iter().all(|v| v.is_finite()) => Ok(Some(
            [*r, *g, *b].map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8),
        )),
        _ => Err(format!("`{text}` is not an rgba colour")),
    }
}

/// Vertices and triangles of an OBJ or STL file.
fn load_mesh(path: &Path) -> Result<(Vec<Vector>, Vec<[u32; 3]>), String> {
    let shown = path.display();
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let (points, triangles) = match extension.as_str() {
        "obj" => {
            let options = tobj::LoadOptions {
                triangulate: true,
                single_index: true,
                ..Default::default()
            };
            let (models, _) =
                tobj::load_obj(path, &options).map_err(|e| format!("{shown}: {e}"))?;
            let mut points = Vec::new();
            let mut triangles = Vec::new();
            for model in models {
                let base = points.len() as u32;
                let m = model.mesh;
                points.extend(
                    m.positions
                        .chunks_exact(3)
                        .map(|p| Vector::new(p[0], p[1], p[2])),
                );
                triangles.extend(
                    m.indices
                        .chunks_exact(3)
                        .map(|t| [base + t[0], base + t[1], base + t[2]]),
                );
            }
            (points, triangles)
        }
        "stl" => {
            let mut file = std::fs::File::open(path).map_err(|e| format!("{shown}: {e}"))?;
            let mesh = stl_io::read_stl(&mut file).map_err(|e| format!("{shown}: {e}"))?;
            let points = mesh
                .vertices
                .iter()
                .map(|v| Vector::new(v[0], v[1], v[2]))
                .collect();
            let triangles = mesh
                .faces
                .iter()
                .map(|f| f.vertices.map(|i| i as u32))
                .collect();
            (points, triangles)
        }
        _ => return Err(format!("{shown}: only .obj and .stl meshes are supported")),
    };
    let valid = points.iter().all(|p: &Vector| p.is_finite())
        && triangles
            .iter()
            .flatten()
            .all(|&i| (i as usize) < points.len());
    if points.len() < 4 || triangles.is_empty() || !valid {
        return Err(format!(
            "{shown}: not a usable mesh ({} vertices, {} triangles)",
            points.len(),
            triangles.len()
        ));
    }
    Ok((points, triangles))
}
