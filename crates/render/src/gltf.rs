//! The world as a binary glTF 2.0 file (`.glb`), for Blender, three.js editors and any viewer:
//! every present object's parts with the meshes the cameras draw (detailed forms at their fine
//! level, tones as primitives of their own) and physically based materials from the realistic
//! profile's finishes (base colour in the home's palette and the object's states, roughness,
//! metalness, glass translucent, lit lamps emissive). The procedural patterns (grain, tiles) are
//! drawn by the cameras' shader and are not baked into textures: a glTF part is its finish's
//! flat colour.
//!
//! Layout: one buffer; per mesh, positions, unit normals and per tone a list of indices; one
//! node per object holding a node per part, under a root node that turns the world's z-up frame
//! into glTF's y-up.

use crate::appearance::{Shown, look, tone_look};
use crate::finish::{Finisher, home_seed, object_seed};
use crate::mesh::{Drawn, MeshStore};
use behavior_forms::Tone;
use behavior_sim::{Material, ModelLibrary, ObjectId, World};
use serde_json::{Value, json};
use std::collections::BTreeMap;

/// A material as glTF says it, its numbers as bits so that equal ones are shared.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct MaterialKey {
    /// Linear RGBA.
    color: [u32; 4],
    roughness: u32,
    metallic: u32,
    emission: u32,
    double_sided: bool,
}

impl MaterialKey {
    fn new(rgb: [f32; 3], alpha: f32, (roughness, metallic): (f32, f32), emission: f32) -> Self {
        let [r, g, b] = rgb;
        MaterialKey {
            color: [r, g, b, alpha].map(f32::to_bits),
            roughness: roughness.to_bits(),
            metallic: metallic.to_bits(),
            emission: emission.to_bits(),
            double_sided: false,
        }
    }

    fn json(&self) -> Value {
        let f = f32::from_bits;
        let color = self.color.map(f);
        let emission = f(self.emission);
        let mut m = json!({
            "pbrMetallicRoughness": {
                "baseColorFactor": color,
                "roughnessFactor": f(self.roughness),
                "metallicFactor": f(self.metallic),
            },
            "doubleSided": self.double_sided,
        });
        if color[3] < 1.0 {
            m["alphaMode"] = json!("BLEND");
        }
        if emission > 0.0 {
            m["emissiveFactor"] =
                json!(color[..3].iter().map(|c| c * emission).collect::<Vec<_>>());
        }
        m
    }
}

/// What one tone of a mesh is drawn in: its own plain colour, or the part's.
fn tone_material(tone: Tone, body: MaterialKey) -> MaterialKey {
    match tone_look(tone) {
        None => body,
        Some(look) => MaterialKey {
            double_sided: body.double_sided,
            ..MaterialKey::new(look.albedo, 1.0, (look.roughness, look.metallic), 0.0)
        },
    }
}

/// The file being put together: the binary buffer and the JSON's lists.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    meshes: Vec<Value>,
    materials: Vec<Value>,
    nodes: Vec<Value>,
    /// glTF mesh per (store mesh, body material).
    mesh_ids: BTreeMap<(u32, MaterialKey), usize>,
    material_ids: BTreeMap<MaterialKey, usize>,
}

impl Builder {
    /// Appends bytes as a buffer view and an accessor over them; returns the accessor.
    fn accessor(&mut self, bytes: &[u8], target: u32, accessor: Value) -> usize {
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.views.push(json!({
            "buffer": 0, "byteOffset": offset, "byteLength": bytes.len(), "target": target,
        }));
        let mut accessor = accessor;
        accessor["bufferView"] = json!(self.views.len() - 1);
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    fn material(&mut self, key: MaterialKey) -> usize {
        let next = self.materials.len();
        *self.material_ids.entry(key).or_insert_with(|| {
            self.materials.push(key.json());
            next
        })
    }

    /// The glTF mesh for a store mesh in a body material, made the first time.
    fn mesh(&mut self, store: &MeshStore, id: u32, body: MaterialKey) -> Option<usize> {
        if let Some(&m) = self.mesh_ids.get(&(id, body)) {
            return Some(m);
        }
        let mesh = store.mesh(id);
        if mesh.indices.is_empty() {
            return None;
        }
        let body = MaterialKey {
            double_sided: !mesh.closed,
            ..body
        };
        let positions: Vec<f32> = mesh.vertices.iter().flat_map(|v| v.position).collect();
        let normals: Vec<f32> = mesh
            .vertices
            .iter()
            .flat_map(|v| {
                let n = rapier3d::math::Vector::from_array(v.normal);
                n.normalize_or(rapier3d::math::Vector::Z).to_array()
            })
            .collect();
        let (lo, hi) = mesh
            .vertices
            .iter()
            .fold(([f32::MAX; 3], [f32::MIN; 3]), |(lo, hi), v| {
                let p = v.position;
                (
                    [0, 1, 2].map(|k| lo[k].min(p[k])),
                    [0, 1, 2].map(|k| hi[k].max(p[k])),
                )
            });
        let count = mesh.vertices.len();
        let position = self.accessor(
            bytemuck::cast_slice(&positions),
            ARRAY_BUFFER,
            json!({"componentType": FLOAT, "count": count, "type": "VEC3", "min": lo, "max": hi}),
        );
        let normal = self.accessor(
            bytemuck::cast_slice(&normals),
            ARRAY_BUFFER,
            json!({"componentType": FLOAT, "count": count, "type": "VEC3"}),
        );
        // A primitive per tone, each triangle in its first vertex's tone (as the cameras draw it).
        let mut by_tone: BTreeMap<Tone, Vec<u32>> = BTreeMap::new();
        for t in mesh.indices.chunks_exact(3) {
            let tone = mesh.vertices[t[0] as usize].tone;
            by_tone.entry(tone).or_default().extend_from_slice(t);
        }
        let mut primitives = Vec::new();
        for (tone, indices) in by_tone {
            let material = self.material(tone_material(tone, body));
            let accessor = self.accessor(
                bytemuck::cast_slice(&indices),
                ELEMENT_ARRAY_BUFFER,
                json!({"componentType": UNSIGNED_INT, "count": indices.len(), "type": "SCALAR"}),
            );
            primitives.push(json!({
                "attributes": {"POSITION": position, "NORMAL": normal},
                "indices": accessor,
                "material": material,
            }));
        }
        self.meshes.push(json!({ "primitives": primitives }));
        let m = self.meshes.len() - 1;
        self.mesh_ids.insert((id, body), m);
        Some(m)
    }
}

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

/// The world as a binary glTF 2.0 file: every present object but `hidden` ones, as the
/// realistic profile colours it, with the model pieces `models` holds (robots' links) in their
/// meshes.
pub fn to_glb(world: &World, hidden: &[ObjectId], models: &ModelLibrary) -> Vec<u8> {
    let mut store = MeshStore::default();
    let mut b = Builder::default();
    let home = home_seed(world);
    let mut objects = Vec::new();
    for (id, object) in world.objects() {
        if !object.is_present() || hidden.contains(&id) {
            continue;
        }
        let seed = object_seed(world, id);
        let finisher = Finisher::of(world, id, home, seed);
        let shown = Shown::of(world, id);
        let mut parts = Vec::new();
        for part in world.core().visual_parts_with(id, models) {
            let drawn = Drawn::of(&part.shape, seed);
            let mesh_id = store.id(drawn.key, &part.shape);
            let finish = finisher.part(part.visual);
            let seen = look(finish.color, part.visual.material, shown);
            let alpha = if part.visual.material == Material::Glass {
                0.35
            } else {
                1.0
            };
            let body = MaterialKey::new(
                seen.albedo,
                alpha,
                (finish.roughness, finish.metallic),
                seen.emission,
            );
            let Some(mesh) = b.mesh(&store, mesh_id, body) else {
                continue;
            };
            let (t, r) = (part.pose.translation, part.pose.rotation);
            b.nodes.push(json!({
                "mesh": mesh,
                "translation": [t.x, t.y, t.z],
                "rotation": [r.x, r.y, r.z, r.w],
                "scale": drawn.scale.to_array(),
            }));
            parts.push(b.nodes.len() - 1);
        }
        if !parts.is_empty() {
            b.nodes
                .push(json!({ "name": object.name, "children": parts }));
            objects.push(b.nodes.len() - 1);
        }
    }
    // z up (the world) to y up (glTF): a quarter turn about x.
    let half = std::f32::consts::FRAC_1_SQRT_2;
    b.nodes.push(json!({
        "name": "world (z up)",
        "rotation": [-half, 0.0, 0.0, half],
        "children": objects,
    }));
    let root = b.nodes.len() - 1;
    let doc = json!({
        "asset": {"version": "2.0", "generator": concat!("behavior-render ", env!("CARGO_PKG_VERSION"))},
        "scene": 0,
        "scenes": [{"nodes": [root]}],
        "nodes": b.nodes,
        "meshes": b.meshes,
        "materials": b.materials,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": b.bin.len()}],
    });
    glb(&doc.to_string().into_bytes(), b.bin)
}

/// The GLB container: a 12-byte header, the JSON chunk padded with spaces and the binary chunk
/// padded with zeros, each to four bytes.
fn glb(json: &[u8], mut bin: Vec<u8>) -> Vec<u8> {
    let mut json = json.to_vec();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use behavior_sim::{Form, ObjectSpec, Part, Primitive, Visual};
    use rapier3d::math::Vector;

    fn chunk(file: &[u8], at: usize) -> (u32, &[u8], &[u8]) {
        let length = u32::from_le_bytes(file[at..at + 4].try_into().unwrap());
        let kind = &file[at + 4..at + 8];
        (length, kind, &file[at + 8..at + 8 + length as usize])
    }

    #[test]
    fn a_world_becomes_a_glb_whose_json_names_its_objects_and_meshes() {
        let mut world = World::default();
        let mut bowl = ObjectSpec::new(
            "bowl_1",
            "bowl.n.01",
            vec![Part::new(Primitive::Box {
                half_extents: Vector::new(0.08, 0.08, 0.03),
            })],
        );
        bowl.form = Form::Bowl;
        let board = Part::new(Primitive::Box {
            half_extents: Vector::new(0.5, 0.3, 0.02),
        })
        .with_form(Form::Rounded);
        let mut table = ObjectSpec::new("table_1", "table.n.02", vec![board]).fixed();
        table.visual = Visual {
            color: [150, 100, 60],
            material: Material::Wood,
        };
        world.add(bowl.at(Vector::new(0.0, 0.0, 0.5))).unwrap();
        world.add(table).unwrap();
        let file = to_glb(&world, &[], &ModelLibrary::EMPTY);
        assert_eq!(&file[..4], b"glTF");
        assert_eq!(
            u32::from_le_bytes(file[8..12].try_into().unwrap()) as usize,
            file.len()
        );
        let (json_len, kind, json) = chunk(&file, 12);
        assert_eq!(kind, b"JSON");
        let (_, kind, bin) = chunk(&file, 20 + json_len as usize);
        assert_eq!(kind, b"BIN\0");
        let doc: Value = serde_json::from_slice(json).unwrap();
        let names: Vec<&str> = doc["nodes"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|n| n["name"].as_str())
            .collect();
        assert_eq!(names, ["bowl_1", "table_1", "world (z up)"]);
        // The bowl's mesh is its form (hundreds of vertices), not a box's 24.
        let vertices = doc["accessors"][0]["count"].as_u64().unwrap();
        assert!(vertices > 200, "the bowl has only {vertices} vertices");
        let declared = doc["buffers"][0]["byteLength"].as_u64().unwrap() as usize;
        assert!(declared <= bin.len() && bin.len() - declared < 4);
        // Every index stays within its mesh's vertices.
        for mesh in doc["meshes"].as_array().unwrap() {
            for p in mesh["primitives"].as_array().unwrap() {
                let count = doc["accessors"][p["attributes"]["POSITION"].as_u64().unwrap() as usize]
                    ["count"]
                    .as_u64()
                    .unwrap() as u32;
                let indices = &doc["accessors"][p["indices"].as_u64().unwrap() as usize];
                let view = &doc["bufferViews"][indices["bufferView"].as_u64().unwrap() as usize];
                let start = view["byteOffset"].as_u64().unwrap() as usize;
                let end = start + view["byteLength"].as_u64().unwrap() as usize;
                let mut list = bin[start..end].chunks_exact(4);
                assert!(list.all(|b| u32::from_le_bytes(b.try_into().unwrap()) < count));
            }
        }
    }
}
