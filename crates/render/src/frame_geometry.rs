//! A frame's triangles in the world: every drawn instance's mesh placed by the CPU into one
//! vertex list and one index list, drawn by a single call, without the triangles of closed
//! shapes that face away from the camera.
//!
//! Why here and not on the GPU: on lavapipe every triangle costs about a thousand instructions
//! of setup and rasterization, and every draw call or instance its own pass through the vertex
//! stage, while placing a vertex or testing a triangle's side here costs tens. Half of a closed
//! shape's triangles face away, and the pipeline cannot cull them itself because open meshes
//! (a bowl) are seen from both sides in the same draw. A GPU would not mind either way.

use crate::appearance::tone_look;
use crate::finish::{Finish, Pattern};
use crate::instances::Instance;
use crate::mesh::MeshStore;
use behavior_forms::Tone;
use bytemuck::{Pod, Zeroable};
use rapier3d::glamx::{Affine3A, Mat3A, Vec3A};
use rapier3d::math::Vector;

/// A vertex as the shader reads it (`shader.wgsl`'s `VertexIn`), in the world's frame.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub(crate) struct FrameVertex {
    pub(crate) position: [f32; 3],
    /// Not of unit length (the shader normalises per pixel).
    pub(crate) normal: [f32; 3],
    /// Where this point was last frame (for the flow modalities).
    pub(crate) previous: [f32; 3],
    pub(crate) shine: f32,
    /// Linear albedo, and emission in w.
    pub(crate) color: [f32; 4],
    /// Instance id, and category id | highlight << 16.
    pub(crate) ids: [u32; 2],
    /// Where the point is in its part's own frame, m (for the realistic profile's patterns).
    pub(crate) local: [f32; 3],
    /// The part's half size, m.
    pub(crate) extent: [f32; 3],
    /// The part's finish: pattern, roughness and metallic, and its object's seed.
    pub(crate) surface: [u32; 2],
}

/// The colour of a vertex of `tone` on an instance of `color` (linear albedo, emission in w):
/// the instance's own, or the tone's, lit alike.
fn toned(tone: Tone, color: [f32; 4]) -> [f32; 4] {
    match tone_look(tone) {
        None => color,
        Some(look) => {
            let [r, g, b] = look.albedo;
            [r, g, b, color[3]]
        }
    }
}

/// The realistic profile's finish of a vertex of `tone` on an instance finished `surface`
/// ([`crate::finish::Finish::packed`]): the instance's own, or the tone's, plain.
fn toned_surface(tone: Tone, surface: [u32; 2]) -> [u32; 2] {
    match tone_look(tone) {
        None => surface,
        Some(look) => Finish {
            color: [0; 3],
            pattern: Pattern::Plain,
            roughness: look.roughness,
            metallic: look.metallic,
            seed: surface[1],
        }
        .packed(),
    }
}

/// The lists, kept between frames so that a frame like the last allocates nothing.
#[derive(Default)]
pub(crate) struct FrameGeometry {
    pub(crate) vertices: Vec<FrameVertex>,
    pub(crate) indices: Vec<u32>,
    /// The drawing order's list, kept between frames so that a frame allocates none.
    order: Vec<(f32, usize)>,
}

/// The affine transform whose rows are `rows`.
fn affine(rows: &[[f32; 4]; 3]) -> Affine3A {
    let [x, y, z] = rows;
    Affine3A::from_cols(
        Vec3A::new(x[0], y[0], z[0]),
        Vec3A::new(x[1], y[1], z[1]),
        Vec3A::new(x[2], y[2], z[2]),
        Vec3A::new(x[3], y[3], z[3]),
    )
}

/// Whether the counter-clockwise `triangle` of `vertices` shows its front to `eye`.
fn faces(vertices: &[FrameVertex], triangle: &[u32], eye: Vector) -> bool {
    let corner = |k: usize| {
        let i = triangle[k] as usize;
        vertices
            .get(i)
            .map_or(Vector::ZERO, |v| Vector::from_array(v.position))
    };
    let (a, b, c) = (corner(0), corner(1), corner(2));
    (b - a).cross(c - a).dot(eye - a) > 0.0
}

/// Fills `order` with `instances`' indices in the order they are drawn: by the distance of their
/// origin from `eye`, nearest first, ties in the gatherer's order. The depth test then turns away most of what lies behind
/// a nearer surface before its fragments are shaded (lavapipe tests depth ahead of a fragment
/// shader that writes none), instead of shading a room's floor and walls and then the furniture
/// over them: the realistic profile's frames took a fifth less time. The order depends on the
/// scene and the eye alone, so a frame stays the same for the same state.
fn nearest_first(instances: &[Instance], eye: Vector, order: &mut Vec<(f32, usize)>) {
    order.clear();
    order.extend(instances.iter().enumerate().map(|(k, instance)| {
        let [x, y, z] = instance.model.map(|row| row[3]);
        (Vector::new(x, y, z).distance_squared(eye), k)
    }));
    order.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
}

impl FrameGeometry {
    /// Replaces the lists with `instances` placed, nearest `eye` first ([`nearest_first`]),
    /// seen from `eye`; with where each vertex was last frame if `motion`.
    pub(crate) fn fill(
        &mut self,
        instances: &[Instance],
        meshes: &MeshStore,
        eye: Vector,
        motion: bool,
    ) {
        self.vertices.clear();
        self.indices.clear();
        let mut order = std::mem::take(&mut self.order);
        nearest_first(instances, eye, &mut order);
        for instance in order.iter().map(|&(_, k)| &instances[k]) {
            let mesh = meshes.mesh(instance.mesh);
            let base = self.vertices.len();
            let model = affine(&instance.model);
            let previous = affine(&instance.previous);
            let [x, y, z] = instance.normal;
            let normal = Mat3A::from_cols_array_2d(&[x, y, z]).transpose();
            let scale = Vec3A::from_array(instance.scale);
            self.vertices.extend(mesh.vertices.iter().map(|v| {
                let p = Vec3A::from_array(v.position);
                let position = model.transform_point3a(p).to_array();
                FrameVertex {
                    position,
                    normal: (normal * Vec3A::from_array(v.normal)).to_array(),
                    previous: if motion {
                        previous.transform_point3a(p).to_array()
                    } else {
                        position
                    },
                    shine: instance.shine,
                    color: toned(v.tone, instance.color),
                    ids: instance.ids,
                    local: (p * scale).to_array(),
                    extent: instance.extent,
                    surface: toned_surface(v.tone, instance.surface),
                }
            }));
            let placed = &self.vertices[base..];
            for triangle in mesh.indices.chunks_exact(3) {
                if mesh.closed && !faces(placed, triangle, eye) {
                    continue;
                }
                self.indices
                    .extend(triangle.iter().map(|&i| base as u32 + i));
            }
        }
        self.order = order;
    }

    pub(crate) fn triangles(&self) -> u64 {
        self.indices.len() as u64 / 3
    }
}
