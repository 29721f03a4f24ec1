//! The world as a binary glTF 2.0 file (`.glb`), for Blender, three.js editors, any viewer and
//! this project's browser viewer: every present object's parts with the meshes the cameras
//! draw (detailed forms, tones as primitives of their own) and physically based materials from
//! the realistic profile's finishes: base colour in the home's palette and the object's states,
//! roughness, metalness, glass translucent, lit lamps emissive, and the procedural patterns
//! (grain, boards, tiles, weave, pile, print) baked into repeating images with normal maps
//! where they have relief (`texture.rs`), mapped by box projection with tangents of our own.
//!
//! Layout: one buffer; per mesh, positions, unit normals, texture coordinates and tangents where
//! its material has an image, and per tone a list of indices; PNG images in the buffer. Top
//! nodes as the caller groups them ([`GltfWriter::node`]: one per object for export, one per
//! moving body for the browser), each holding a node per part, under a root node that turns the
//! world's z-up frame into glTF's y-up. A part's body material carries `extras.reference`, the
//! colour its image was made for, so that a viewer recolouring it (states change) sets its
//! colour factor to the new colour divided by it.

use crate::appearance::{Shown, look, tone_look};
use crate::finish::{Finisher, home_seed, object_seed};
use crate::mesh::{Drawn, MeshKey, MeshStore, PieceLevel};
use crate::texture::{GLASS_TINT, Mapping, Texture, TextureKey, bake};
use behavior_forms::Tone;
use behavior_sim::{Material, ModelLibrary, ObjectId, VisualPart, World};
use rapier3d::math::{Pose, Vector};
use serde_json::{Value, json};
use std::collections::BTreeMap;

/// How finely a glTF file draws the world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GltfDetail {
    /// As the cameras draw close up: forms at their fine level, robots' meshes as made
    /// (`behavior scene export`).
    Full,
    /// For a browser drawing on a CPU (a headset's two eyes above all): forms at their coarse
    /// level, boards' few-millimetre rounding left out, robots' meshes on a 4 mm grid; about a
    /// fifth of the triangles.
    Viewer,
}

/// The radius on an image, pixels, at which [`GltfDetail::Viewer`] picks its meshes' levels.
const VIEWER_PIXELS: f32 = 15.0;

/// A material as glTF says it, its numbers as bits so that equal ones are shared.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct MaterialKey {
    /// Linear RGBA (the colour factor, which multiplies the image).
    color: [u32; 4],
    roughness: u32,
    metallic: u32,
    emission: u32,
    double_sided: bool,
    texture: Option<TextureKey>,
    /// What a viewer divides a new colour by (a part's body; none for a tone's own colour).
    reference: Option<[u32; 3]>,
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
            texture: None,
            reference: None,
        }
    }

    /// A part's body material: its colour `albedo` (linear) over its pattern's image (or
    /// glass's flat tint), the colour factor being the colour divided by what the image was
    /// made for (at most 1, as glTF wants).
    fn body(
        albedo: [f32; 3],
        finish: (f32, f32),
        emission: f32,
        texture: Option<(TextureKey, [f32; 3])>,
        glass: bool,
    ) -> Self {
        let reference = match texture {
            Some((_, r)) => r,
            None if glass => [1.0 / GLASS_TINT; 3],
            None => [1.0; 3],
        };
        let factor: [f32; 3] = std::array::from_fn(|k| (albedo[k] / reference[k]).min(1.0));
        MaterialKey {
            texture: texture.map(|(key, _)| key),
            reference: Some(reference.map(f32::to_bits)),
            ..MaterialKey::new(factor, if glass { 0.35 } else { 1.0 }, finish, emission)
        }
    }

    fn json(&self, images: Option<(usize, Option<usize>)>) -> Value {
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
        if let Some((color_image, normal_image)) = images {
            m["pbrMetallicRoughness"]["baseColorTexture"] = json!({ "index": color_image });
            if let Some(n) = normal_image {
                m["normalTexture"] = json!({ "index": n });
            }
        }
        if let Some(reference) = self.reference {
            m["extras"] = json!({ "reference": reference.map(f) });
        }
        if color[3] < 1.0 {
            m["alphaMode"] = json!("BLEND");
        }
        if emission > 0.0 {
            // Emission is the lit colour, not the factor (which an image divides).
            let lit: Vec<f32> = match self.reference {
                Some(r) => (0..3)
                    .map(|k| (color[k] * f(r[k])).min(1.0) * emission)
                    .collect(),
                None => color[..3].iter().map(|c| c * emission).collect(),
            };
            m["emissiveFactor"] = json!(lit);
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

/// Which glTF mesh a part takes: its store mesh, its body material, and where its image lies
/// on it (its size and mapping, as bits; none without an image).
type MeshUse = (u32, MaterialKey, Option<[u32; 9]>);

/// The file being put together: the binary buffer and the JSON's lists.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    meshes: Vec<Value>,
    materials: Vec<Value>,
    images: Vec<Value>,
    textures: Vec<Value>,
    nodes: Vec<Value>,
    mesh_ids: BTreeMap<MeshUse, usize>,
    material_ids: BTreeMap<MaterialKey, usize>,
    /// Every image baked so far.
    baked: BTreeMap<TextureKey, Texture>,
    /// A baked image's colour texture and normal texture, once in the file.
    texture_ids: BTreeMap<TextureKey, (usize, Option<usize>)>,
}

impl Builder {
    /// Appends bytes as a buffer view (for `target`, or none for images); returns the view.
    fn view(&mut self, bytes: &[u8], target: Option<u32>) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        let mut view = json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len() });
        if let Some(t) = target {
            view["target"] = json!(t);
        }
        self.views.push(view);
        self.views.len() - 1
    }

    /// Appends bytes as a buffer view and an accessor over them; returns the accessor.
    fn accessor(&mut self, bytes: &[u8], target: u32, accessor: Value) -> usize {
        let view = self.view(bytes, Some(target));
        let mut accessor = accessor;
        accessor["bufferView"] = json!(view);
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    fn floats(&mut self, values: &[f32], kind: &str, count: usize) -> usize {
        self.accessor(
            bytemuck::cast_slice(values),
            ARRAY_BUFFER,
            json!({"componentType": FLOAT, "count": count, "type": kind}),
        )
    }

    /// A PNG as an image and a texture over it (repeating, mipmapped).
    fn texture(&mut self, image: &image::RgbImage) -> usize {
        let mut png = Vec::new();
        image
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .expect("an image in memory encodes as PNG");
        let view = self.view(&png, None);
        self.images
            .push(json!({ "bufferView": view, "mimeType": "image/png" }));
        self.textures
            .push(json!({ "sampler": 0, "source": self.images.len() - 1 }));
        self.textures.len() - 1
    }

    /// What `key`'s image was made for, baking it the first time.
    fn reference(&mut self, key: TextureKey) -> [f32; 3] {
        self.baked.entry(key).or_insert_with(|| bake(key)).reference
    }

    /// The colour and normal textures of `key`'s image, put in the file the first time.
    fn images_of(&mut self, key: TextureKey) -> (usize, Option<usize>) {
        if let Some(&ids) = self.texture_ids.get(&key) {
            return ids;
        }
        let baked = self.baked.remove(&key).unwrap_or_else(|| bake(key));
        let color = self.texture(&baked.color);
        let normal = baked.normal.as_ref().map(|n| self.texture(n));
        self.texture_ids.insert(key, (color, normal));
        // Kept for `reference` (the images are in the file now).
        self.baked.insert(key, baked);
        (color, normal)
    }

    fn material(&mut self, key: MaterialKey) -> usize {
        if let Some(&m) = self.material_ids.get(&key) {
            return m;
        }
        let images = key.texture.map(|t| self.images_of(t));
        self.materials.push(key.json(images));
        let m = self.materials.len() - 1;
        self.material_ids.insert(key, m);
        m
    }

    /// The glTF mesh for a store mesh in a body material, its image mapped by `mapping` over
    /// a part of size `scale` (m), made the first time.
    fn mesh(
        &mut self,
        store: &MeshStore,
        id: u32,
        body: MaterialKey,
        mapped: Option<(Mapping, Vector)>,
    ) -> Option<usize> {
        let use_key = (id, body, mapped.map(|(m, s)| m.bits(s)));
        if let Some(&m) = self.mesh_ids.get(&use_key) {
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
        let made = match mapped {
            Some((mapping, scale)) => projected(mesh.vertices, mesh.indices, mapping, scale),
            None => VertexLists::of(mesh.vertices, mesh.indices),
        };
        let count = made.positions.len();
        let (lo, hi) = made
            .positions
            .iter()
            .fold(([f32::MAX; 3], [f32::MIN; 3]), |(lo, hi), p| {
                (
                    [0, 1, 2].map(|k| lo[k].min(p[k])),
                    [0, 1, 2].map(|k| hi[k].max(p[k])),
                )
            });
        let position = self.accessor(
            bytemuck::cast_slice(&made.positions),
            ARRAY_BUFFER,
            json!({"componentType": FLOAT, "count": count, "type": "VEC3", "min": lo, "max": hi}),
        );
        let normal = self.floats(bytemuck::cast_slice(&made.normals), "VEC3", count);
        // A primitive per tone, each triangle in its first vertex's tone (as the cameras draw it).
        let mut by_tone: BTreeMap<Tone, Vec<u32>> = BTreeMap::new();
        for t in made.indices.chunks_exact(3) {
            by_tone
                .entry(made.tones[t[0] as usize])
                .or_default()
                .extend_from_slice(t);
        }
        let plain = json!({"POSITION": position, "NORMAL": normal});
        // The body's primitive takes the image's coordinates, and tangents where it has relief;
        // details in their own colours need neither.
        let mut textured = plain.clone();
        let body_drawn = by_tone.keys().any(|&t| tone_look(t).is_none());
        if let Some((_, normal_map)) = body
            .texture
            .filter(|_| body_drawn)
            .map(|t| self.images_of(t))
        {
            textured["TEXCOORD_0"] =
                json!(self.floats(bytemuck::cast_slice(&made.uvs), "VEC2", count));
            if normal_map.is_some() {
                textured["TANGENT"] =
                    json!(self.floats(bytemuck::cast_slice(&made.tangents), "VEC4", count));
            }
        }
        let mut primitives = Vec::new();
        for (tone, indices) in by_tone {
            let material = self.material(tone_material(tone, body));
            let accessor = self.accessor(
                bytemuck::cast_slice(&indices),
                ELEMENT_ARRAY_BUFFER,
                json!({"componentType": UNSIGNED_INT, "count": indices.len(), "type": "SCALAR"}),
            );
            let attributes = if tone_look(tone).is_none() {
                &textured
            } else {
                &plain
            };
            primitives.push(json!({
                "attributes": attributes,
                "indices": accessor,
                "material": material,
            }));
        }
        self.meshes.push(json!({ "primitives": primitives }));
        let m = self.meshes.len() - 1;
        self.mesh_ids.insert(use_key, m);
        Some(m)
    }
}

/// A mesh's vertex lists as glTF takes them (texture coordinates and tangents where it has an
/// image).
struct VertexLists {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    tones: Vec<Tone>,
    uvs: Vec<[f32; 2]>,
    tangents: Vec<[f32; 4]>,
    indices: Vec<u32>,
}

impl VertexLists {
    fn of(vertices: &[crate::mesh::Vertex], indices: &[u32]) -> VertexLists {
        VertexLists {
            positions: vertices.iter().map(|v| v.position).collect(),
            normals: vertices.iter().map(|v| unit(v.normal)).collect(),
            tones: vertices.iter().map(|v| v.tone).collect(),
            uvs: Vec::new(),
            tangents: Vec::new(),
            indices: indices.to_vec(),
        }
    }
}

fn unit(n: [f32; 3]) -> [f32; 3] {
    Vector::from_array(n).normalize_or(Vector::Z).to_array()
}

/// A mesh with its image projected on it: each triangle onto the plane of the part's frame
/// that faces it most (judged on the part's real size, `scale` times the mesh), its vertices
/// split where triangles of two planes meet. Tangents run along u, their sign giving the
/// image's up.
fn projected(
    vertices: &[crate::mesh::Vertex],
    indices: &[u32],
    mapping: Mapping,
    scale: Vector,
) -> VertexLists {
    let mut out = VertexLists::of(&[], &[]);
    let mut slots = vec![[u32::MAX; 3]; vertices.len()];
    let at = |i: u32| Vector::from_array(vertices[i as usize].position) * scale;
    for t in indices.chunks_exact(3) {
        let face = (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
        let facing = mapping.facing(face.to_array());
        for &i in t {
            let slot = &mut slots[i as usize][facing];
            if *slot == u32::MAX {
                let v = vertices[i as usize];
                let p = at(i).to_array();
                let n = unit(v.normal);
                *slot = out.positions.len() as u32;
                out.positions.push(v.position);
                out.normals.push(n);
                out.tones.push(v.tone);
                out.uvs.push(mapping.uv(p, facing));
                out.tangents.push(tangent(mapping, facing, n, scale));
            }
            out.indices.push(*slot);
        }
    }
    out
}

/// The tangent at a vertex of normal `n` (the mesh's frame) on a triangle projected along
/// `facing`: the direction u grows in, made perpendicular to `n`, and the sign that turns
/// n × tangent toward the image's up.
fn tangent(mapping: Mapping, facing: usize, n: [f32; 3], scale: Vector) -> [f32; 4] {
    let n = Vector::from_array(n);
    let (u_axis, up) = mapping.axes(facing);
    // The mesh is stretched by `scale`: directions in its frame shrink by it.
    let along = |axis: Vector| (axis / scale).normalize_or(axis);
    let mut t = along(u_axis);
    t = (t - n * n.dot(t)).normalize_or(Vector::ZERO);
    if t == Vector::ZERO {
        t = n.any_orthonormal_vector();
    }
    let w = if n.cross(t).dot(along(up)) >= 0.0 {
        1.0
    } else {
        -1.0
    };
    [t.x, t.y, t.z, w]
}

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
/// Samplers: linear, trilinear mipmaps, repeat.
const LINEAR: u32 = 9729;
const LINEAR_MIPMAP_LINEAR: u32 = 9987;
const REPEAT: u32 = 10497;

/// The world as a binary glTF 2.0 file at [`GltfDetail::Full`]: every present object but
/// `hidden` ones (a node each, named after it), as the realistic profile colours it, with the
/// model pieces `models` holds (robots' links) in their meshes.
pub fn to_glb(world: &World, hidden: &[ObjectId], models: &ModelLibrary) -> Vec<u8> {
    let mut writer = GltfWriter::new(world, GltfDetail::Full);
    for (id, object) in world.bodies().objects() {
        if !object.is_present() || hidden.contains(&id) {
            continue;
        }
        let parts = world.visuals().parts_with(id, models);
        if !parts.is_empty() {
            writer.node(&object.name, id, Pose::IDENTITY, &parts);
        }
    }
    writer.finish()
}

/// A glTF file made node by node: the caller says which parts move together.
pub struct GltfWriter<'a> {
    world: &'a World,
    detail: GltfDetail,
    home: u64,
    store: MeshStore,
    b: Builder,
    /// The top nodes, in the order they were added.
    top: Vec<usize>,
}

impl<'a> GltfWriter<'a> {
    /// A file of `world`'s parts at `detail`.
    pub fn new(world: &'a World, detail: GltfDetail) -> Self {
        GltfWriter {
            world,
            detail,
            home: home_seed(world),
            store: MeshStore::default(),
            b: Builder::default(),
            top: Vec::new(),
        }
    }

    /// Adds a top node named `name`, placed at `frame` (in the world), holding `parts` of
    /// `object` (posed in the world, as [`behavior_sim::Visuals::parts_with`] gives
    /// them), a child node per part in their order. Returns the node's index among the top
    /// nodes.
    pub fn node(
        &mut self,
        name: &str,
        object: ObjectId,
        frame: Pose,
        parts: &[VisualPart],
    ) -> usize {
        let world = self.world;
        let seed = object_seed(world, object);
        let finisher = Finisher::of(world, object, self.home, seed);
        let shown = Shown::of(world, object);
        let inverse = frame.inverse();
        let mut children = Vec::new();
        for part in parts {
            let drawn = Drawn::of(&part.shape, seed);
            let key = match self.detail {
                GltfDetail::Full => drawn.key,
                GltfDetail::Viewer => viewer_key(drawn.key),
            };
            let mesh_id = self.store.id(key, &part.shape);
            let finish = finisher.part(part.visual);
            let seen = look(finish.color, part.visual.material, shown);
            let glass = part.visual.material == Material::Glass;
            let texture =
                TextureKey::of(finish.pattern, finish.seed, seen.albedo, self.home as u32)
                    .map(|key| (key, self.b.reference(key)));
            let body = MaterialKey::body(
                seen.albedo,
                (finish.roughness, finish.metallic),
                seen.emission,
                texture,
                glass,
            );
            let mapped = texture.map(|_| {
                (
                    Mapping::of(finish.pattern, drawn.extent.to_array(), finish.seed),
                    drawn.scale,
                )
            });
            let mesh = self.b.mesh(&self.store, mesh_id, body, mapped);
            let pose = inverse * part.pose;
            let (t, r) = (pose.translation, pose.rotation);
            let mut node = json!({
                "translation": [t.x, t.y, t.z],
                "rotation": [r.x, r.y, r.z, r.w],
                "scale": drawn.scale.to_array(),
            });
            if let Some(mesh) = mesh {
                node["mesh"] = json!(mesh);
            }
            self.b.nodes.push(node);
            children.push(self.b.nodes.len() - 1);
        }
        let (t, r) = (frame.translation, frame.rotation);
        let mut node = json!({ "name": name, "children": children });
        if frame != Pose::IDENTITY {
            node["translation"] = json!([t.x, t.y, t.z]);
            node["rotation"] = json!([r.x, r.y, r.z, r.w]);
        }
        self.b.nodes.push(node);
        self.top.push(self.b.nodes.len() - 1);
        self.top.len() - 1
    }

    /// The file.
    pub fn finish(self) -> Vec<u8> {
        let mut b = self.b;
        // z up (the world) to y up (glTF): a quarter turn about x.
        let half = std::f32::consts::FRAC_1_SQRT_2;
        b.nodes.push(json!({
            "name": "world (z up)",
            "rotation": [-half, 0.0, 0.0, half],
            "children": self.top,
        }));
        let root = b.nodes.len() - 1;
        let mut doc = json!({
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
        if !b.textures.is_empty() {
            doc["samplers"] = json!([{
                "magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": REPEAT, "wrapT": REPEAT,
            }]);
            doc["images"] = json!(b.images);
            doc["textures"] = json!(b.textures);
        }
        glb(&doc.to_string().into_bytes(), b.bin)
    }
}

/// The level [`GltfDetail::Viewer`] draws a mesh at: robots' pieces on their 4 mm grid,
/// everything else as a camera would draw it 15 pixels in radius (forms coarse, thin rounding
/// left out, round shapes fine).
fn viewer_key(key: MeshKey) -> MeshKey {
    match key {
        MeshKey::Piece { piece, index, .. } => MeshKey::Piece {
            piece,
            index,
            level: PieceLevel::Fine,
        },
        other => other.sized(VIEWER_PIXELS),
    }
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
        // The table's wood is an image (with its grain's relief), mapped with texture
        // coordinates and tangents; the images are PNGs.
        let floats = |accessor: &Value| -> Vec<f32> {
            let view = &doc["bufferViews"][accessor["bufferView"].as_u64().unwrap() as usize];
            let start = view["byteOffset"].as_u64().unwrap() as usize;
            let end = start + view["byteLength"].as_u64().unwrap() as usize;
            bytemuck::pod_collect_to_vec(&bin[start..end])
        };
        let textured: Vec<&Value> = doc["meshes"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|m| m["primitives"].as_array().unwrap())
            .filter(|p| {
                let m = &doc["materials"][p["material"].as_u64().unwrap() as usize];
                m["pbrMetallicRoughness"]["baseColorTexture"].is_object()
            })
            .collect();
        assert!(!textured.is_empty(), "no part has an image");
        for p in textured {
            let accessor =
                |name: &str| &doc["accessors"][p["attributes"][name].as_u64().unwrap() as usize];
            let count = accessor("POSITION")["count"].as_u64().unwrap();
            assert_eq!(accessor("TEXCOORD_0")["count"].as_u64(), Some(count));
            if p["attributes"].get("TANGENT").is_none() {
                continue;
            }
            let normals = floats(accessor("NORMAL"));
            let tangents = floats(accessor("TANGENT"));
            for (n, t) in normals.chunks(3).zip(tangents.chunks(4)) {
                let (n, w) = (Vector::new(n[0], n[1], n[2]), t[3]);
                let t = Vector::new(t[0], t[1], t[2]);
                assert!(
                    (t.length() - 1.0).abs() < 1e-3 && n.dot(t).abs() < 1e-3,
                    "tangent {t} at normal {n}"
                );
                assert!(w == 1.0 || w == -1.0);
            }
        }
        let images = doc["images"].as_array().expect("images");
        for i in images {
            let view = &doc["bufferViews"][i["bufferView"].as_u64().unwrap() as usize];
            let start = view["byteOffset"].as_u64().unwrap() as usize;
            let end = start + view["byteLength"].as_u64().unwrap() as usize;
            let png =
                image::load_from_memory_with_format(&bin[start..end], image::ImageFormat::Png);
            assert!(png.is_ok(), "an image is not a PNG: {:?}", png.err());
        }
        let wood = doc["materials"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["normalTexture"].is_object())
            .expect("a material with relief (the table's grain)");
        assert!(wood["extras"]["reference"].is_array());
    }

    #[test]
    fn a_viewers_file_has_a_node_per_body_placed_at_its_frame_and_coarser_meshes() {
        let mut world = World::default();
        let mut apple = ObjectSpec::new(
            "apple_1",
            "apple.n.01",
            vec![Part::new(Primitive::Sphere { radius: 0.04 })],
        );
        apple.form = Form::Apple;
        let id = world.add(apple.at(Vector::new(1.0, 2.0, 0.5))).unwrap();
        let models = ModelLibrary::EMPTY;
        let triangles = |detail| {
            let mut w = GltfWriter::new(&world, detail);
            let parts = world.visuals().parts_with(id, &models);
            let frame = world.bodies().pose(id);
            assert_eq!(w.node("apple_1", id, frame, &parts), 0);
            let file = w.finish();
            let (_, _, json) = chunk(&file, 12);
            let doc: Value = serde_json::from_slice(json).unwrap();
            let top = &doc["nodes"][1];
            assert_eq!(top["name"], "apple_1");
            assert_eq!(top["translation"], json!([1.0, 2.0, 0.5]));
            // Its part sits at the node's origin.
            assert_eq!(doc["nodes"][0]["translation"], json!([0.0, 0.0, 0.0]));
            doc["accessors"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|a| a["type"] == "SCALAR")
                .map(|a| a["count"].as_u64().unwrap() / 3)
                .sum::<u64>()
        };
        let (full, viewer) = (triangles(GltfDetail::Full), triangles(GltfDetail::Viewer));
        assert!(
            viewer * 2 < full,
            "the viewer's apple has {viewer} triangles, the full {full}"
        );
    }
}
