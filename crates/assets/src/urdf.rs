//! Importing a URDF model (with OBJ or STL meshes) as an object, so users can bring real assets.
//!
//! The root link becomes the object's body; links attached to it by `fixed` joints merge into it;
//! links on `revolute`, `continuous` or `prismatic` joints become its doors and drawers (one level:
//! a moving link may carry fixed links, not further moving ones). Geometry comes from a link's
//! `<collision>` elements, or, when it has none, from its `<visual>` ones: boxes, cylinders (along
//! z, as ours) and spheres map to primitives; a collision mesh becomes its convex hull, and a
//! visual mesh standing in for missing collision geometry is split into convex parts with parry's
//! V-HACD (or, if that yields only flat parts, replaced by its convex hull). Joint limits must start at 0 (closed); a `continuous` joint opens up to a full turn.

use behavior_sim::{JointKind, JointSpec, LinkSpec, ObjectSpec, Part, Primitive};
use rapier3d::math::{Pose, Rotation, Vector};
use rapier3d::parry::shape::ConvexPolyhedron;
use rapier3d::parry::transformation::vhacd::{VHACD, VHACDParameters};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum ImportError {
    #[error("cannot read {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: not valid XML: {source}")]
    Xml {
        path: PathBuf,
        source: roxmltree::Error,
    },
    #[error("{path}: {reason}")]
    Model { path: PathBuf, reason: String },
}

/// Reads a URDF file into an object spec named `name` of synset `category`.
pub fn import_urdf(path: &Path, name: &str, category: &str) -> Result<ObjectSpec, ImportError> {
    let text = std::fs::read_to_string(path).map_err(|source| ImportError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let doc = roxmltree::Document::parse(&text).map_err(|source| ImportError::Xml {
        path: path.to_path_buf(),
        source,
    })?;
    let fail = |reason: String| ImportError::Model {
        path: path.to_path_buf(),
        reason,
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let robot = doc.root_element();
    if robot.tag_name().name() != "robot" {
        return Err(fail("the root element is not <robot>".into()));
    }
    let links: BTreeMap<String, roxmltree::Node> = robot
        .children()
        .filter(|n| n.has_tag_name("link"))
        .filter_map(|n| Some((n.attribute("name")?.to_string(), n)))
        .collect();
    let joints: Vec<Joint> = robot
        .children()
        .filter(|n| n.has_tag_name("joint"))
        .map(|n| Joint::parse(n).map_err(fail))
        .collect::<Result<_, _>>()?;
    let children: Vec<&str> = joints.iter().map(|j| j.child.as_str()).collect();
    let roots: Vec<&String> = links
        .keys()
        .filter(|l| !children.contains(&l.as_str()))
        .collect();
    let [root] = roots.as_slice() else {
        return Err(fail(format!(
            "expected one root link, found {}",
            roots.len()
        )));
    };
    for j in &joints {
        for end in [&j.parent, &j.child] {
            if !links.contains_key(end) {
                return Err(fail(format!(
                    "joint `{}` names a link `{end}` that does not exist",
                    j.name
                )));
            }
        }
    }
    // Each link's pose in the root frame (joints at position 0), and the moving joint it hangs from.
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
                    return Err(fail(format!(
                        "joint `{}`: moving links on moving links are not supported",
                        j.name
                    )));
                }
            };
            if placed
                .insert(j.child.clone(), (parent_pose * j.origin, moving))
                .is_some()
            {
                return Err(fail(format!("link `{}` has two parents", j.child)));
            }
            frontier.push(j.child.clone());
        }
    }
    let mut base: Vec<Part> = Vec::new();
    let mut moving: BTreeMap<usize, Vec<Part>> = BTreeMap::new();
    for (link_name, (pose, hangs_from)) in &placed {
        let parts = link_parts(links[link_name], dir, *pose)
            .map_err(|e| fail(format!("link `{link_name}`: {e}")))?;
        match hangs_from {
            None => base.extend(parts),
            Some(k) => moving.entry(*k).or_default().extend(parts),
        }
    }
    if base.is_empty() {
        return Err(fail("the root link has no geometry".into()));
    }
    let mut spec = ObjectSpec::new(name, category, base);
    for (k, parts) in moving {
        let j = &joints[k];
        let (kind, range) = j.kind.expect("only moving joints are collected");
        if parts.is_empty() {
            return Err(fail(format!(
                "joint `{}` moves a link without geometry",
                j.name
            )));
        }
        let frame = placed[&j.parent].0 * j.origin;
        spec.links.push(LinkSpec {
            name: j.name.clone(),
            parts,
            parent: None,
            joint: JointSpec::opening(kind, frame.translation, frame.rotation * j.axis, range, 2.0),
            density: spec.density,
        });
    }
    Ok(spec)
}

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

/// The parts of a link, placed by `pose` (the link's frame in the object's).
fn link_parts(link: roxmltree::Node, dir: &Path, pose: Pose) -> Result<Vec<Part>, String> {
    let collisions: Vec<roxmltree::Node> = link
        .children()
        .filter(|c| c.has_tag_name("collision"))
        .collect();
    let (elements, from_visual) = if collisions.is_empty() {
        (
            link.children()
                .filter(|c| c.has_tag_name("visual"))
                .collect::<Vec<_>>(),
            true,
        )
    } else {
        (collisions, false)
    };
    let mut parts = Vec::new();
    for element in elements {
        let at = pose * origin(element)?;
        let Some(geometry) = element.children().find(|c| c.has_tag_name("geometry")) else {
            continue;
        };
        let Some(shape) = geometry.children().find(|c| c.is_element()) else {
            continue;
        };
        let number = |attr: &str| -> Result<f32, String> {
            shape
                .attribute(attr)
                .and_then(|v| v.trim().parse::<f32>().ok())
                .filter(|v| v.is_finite() && *v > 0.0)
                .ok_or_else(|| format!("<{}> needs a positive `{attr}`", shape.tag_name().name()))
        };
        let primitive = match shape.tag_name().name() {
            "box" => Primitive::Box {
                half_extents: vector(shape.attribute("size").unwrap_or(""))? * 0.5,
            },
            "cylinder" => Primitive::Cylinder {
                radius: number("radius")?,
                half_height: number("length")? / 2.0,
            },
            "sphere" => Primitive::Sphere {
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
                let (points, triangles) =
                    load_mesh(&dir.join(file.trim_start_matches("package://")))?;
                let points: Vec<Vector> = points.into_iter().map(|p| p * scale).collect();
                if !points.iter().all(|p| p.is_finite()) {
                    return Err(format!(
                        "mesh `{file}` scaled by {scale} has non-finite points"
                    ));
                }
                if from_visual {
                    // No collision geometry: approximate the visual mesh by convex parts, keeping
                    // those with volume (thin meshes can yield flat ones).
                    let hulls: Vec<Vec<Vector>> =
                        VHACD::decompose(&VHACDParameters::default(), &points, &triangles, false)
                            .compute_convex_hulls(4)
                            .into_iter()
                            .map(|(hull, _)| hull)
                            .filter(|hull| ConvexPolyhedron::from_convex_hull(hull).is_some())
                            .collect();
                    if !hulls.is_empty() {
                        parts.extend(hulls.into_iter().map(|hull| Part {
                            primitive: Primitive::ConvexHull { points: hull },
                            offset: at,
                            visual: None,
                        }));
                        continue;
                    }
                }
                if ConvexPolyhedron::from_convex_hull(&points).is_none() {
                    return Err(format!("mesh `{file}` is flat: it encloses no volume"));
                }
                Primitive::ConvexHull { points }
            }
            other => return Err(format!("unsupported geometry <{other}>")),
        };
        parts.push(Part {
            primitive,
            offset: at,
            visual: None,
        });
    }
    Ok(parts)
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
