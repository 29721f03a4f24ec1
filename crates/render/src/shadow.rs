//! The sun's shadow maps for the realistic profile: one of everything fixed (walls, floors,
//! furniture bodies) over the whole home, drawn again only when that changes, and one of
//! everything that moves (objects, doors and drawers, the robot) around where the camera
//! looks, drawn every frame. Glass lets the sun through.
//!
//! Two maps because a CPU rasterizer pays for every triangle: a home's fixed geometry is most
//! of its triangles and stays put, while what moves is little and near.
//!
//! The fixed map sees the walls cut at their windows and a roof over them (`sunlight.rs`), so
//! that the sun comes in through the windows only (`Renderer::set_sun_through_windows` turns
//! that off, to compare).
//!
//! A third map, the sky map, sees the fixed geometry straight from above: how much of the sky
//! over a point's neighbourhood is covered by something higher (a table top, a shelf, the walls
//! of a corner) is how much ambient light it loses — ambient occlusion from the fixed geometry,
//! at the cost of four lookups a pixel. It is drawn with the fixed map, when that changes.
//!
//! A fourth map is the lamp's: the camera's room's lamp looks down on its room in perspective,
//! so that a table shades the floor under it from the lamp as from the sun, and the robot casts
//! its shadow. Its fixed casters are drawn into a map of their own, kept while they and the lamp
//! stay; when something in the room moves, that map is copied into the lamp's and the moving
//! casters drawn over it, so one lookup a pixel sees both.

use crate::camera::fixed_bounds;
use crate::finish::object_seed;
use crate::instances::rows;
use crate::lighting::{Lamp, ShadowMatrices};
use crate::mesh::{Drawn, MeshKey, MeshStore, hash_words};
use crate::pipeline::uniform_layout;
use crate::sunlight::{Slab, sun_casters};
use behavior_core::WALL_SYNSET;
use behavior_sim::{BodyKind, Material, ModelLibrary, ObjectId, Primitive, VisualShape, World};
use rapier3d::glamx::{Mat4, Vec3A, Vec4};
use rapier3d::math::Vector;

/// The fixed map's size, texels a side: 2 cm a texel over a 40 m home.
const FIXED_SIZE: u32 = 2048;
/// The moving map's, over 9 m around an eye: under 2 cm a texel.
const MOVING_SIZE: u32 = 512;
/// The sky map's: 4 cm a texel over a 40 m home, finer than the occlusion it feeds (lookups
/// 15 to 35 cm from a point).
const SKY_SIZE: u32 = 1024;
/// The lamp's map: about 2 cm a texel on the floor of a 5 m room (a lamp's shadows are soft).
const LAMP_SIZE: u32 = 256;
/// The widest the lamp's view opens, as the tangent of half its angle (150° in all): a long
/// room's far ends, seen almost edge-on from the lamp, keep no shadow rather than a smeared one.
const LAMP_SPREAD: f32 = 3.7;
/// Half the side of the moving map's square at the least, m.
const MOVING_HALF: f32 = 4.5;

pub(crate) const SHADOW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A caster: a stored mesh placed in the world.
#[derive(Clone, Copy)]
struct Caster {
    mesh: u32,
    model: [[f32; 4]; 3],
    centre: Vector,
    reach: f32,
}

/// One map: its texture, its matrix's buffer, and its casters' buffers.
struct Map {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    matrix: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    vertices: Option<(wgpu::Buffer, usize)>,
    indices: Option<(wgpu::Buffer, usize)>,
    /// Indices drawn.
    count: u32,
}

/// Both maps, the pipeline that draws them and the sampler that reads them.
pub(crate) struct ShadowMaps {
    pipeline: wgpu::RenderPipeline,
    pub(crate) sampler: wgpu::Sampler,
    fixed: Map,
    moving: Map,
    sky: Map,
    /// The lamp's fixed casters alone, and what it shows: a hash of them and the lamp's
    /// matrix, and whether it holds anything.
    lamp_fixed: Map,
    lamp_fixed_key: Option<(u64, bool)>,
    /// The lamp's map: the fixed one with the moving casters over it, and what it shows.
    lamp: Map,
    lamp_key: Option<(u64, bool)>,
    /// World to the sky map's clip space, while it holds anything.
    sky_matrix: Option<Mat4>,
    /// What the fixed map shows: a hash of its casters and the sun, and its matrix.
    fixed_key: Option<(u64, Option<Mat4>)>,
    /// What the moving map shows: a hash of its casters and its matrix, and whether it holds
    /// anything. A frame where nothing moved (an idle robot, objects asleep) keeps it.
    moving_key: Option<(u64, bool)>,
    /// Lists refilled each frame.
    positions: Vec<[f32; 3]>,
    triangles: Vec<u32>,
}

fn map(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, size: u32) -> Map {
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("shadow map"),
        size: wgpu::Extent3d {
            width: size,
            height: size,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: SHADOW_FORMAT,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let matrix = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("shadow matrix"),
        size: 64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("shadow matrix"),
        layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: matrix.as_entire_binding(),
        }],
    });
    Map {
        view: texture.create_view(&wgpu::TextureViewDescriptor::default()),
        texture,
        matrix,
        bind_group,
        vertices: None,
        indices: None,
        count: 0,
    }
}

/// The light's view of the box `lo`–`hi` seen from direction `sun`, square around `centre` of
/// half side `half` (in the light's frame) when given, else the whole box.
fn light_matrix(sun: Vector, lo: Vector, hi: Vector, square: Option<(Vector, f32)>) -> Mat4 {
    let middle = (lo + hi) * 0.5;
    let up = if sun.cross(Vector::Z).length() < 1e-3 {
        Vector::X
    } else {
        Vector::Z
    };
    let view = look_along(middle + sun * 100.0, -sun, up);
    let corners = (0..8).map(|k| {
        let pick = |bit: u32, a: f32, b: f32| if k & bit == 0 { a } else { b };
        let p = Vector::new(
            pick(1, lo.x, hi.x),
            pick(2, lo.y, hi.y),
            pick(4, lo.z, hi.z),
        );
        view.transform_point3(p)
    });
    let (mut min, mut max) = (Vector::splat(f32::MAX), Vector::splat(f32::MIN));
    for c in corners {
        min = min.min(c);
        max = max.max(c);
    }
    if let Some((centre, half)) = square {
        let c = view.transform_point3(centre);
        min = Vector::new(c.x - half, c.y - half, min.z).max(min);
        max = Vector::new(c.x + half, c.y + half, max.z).min(max);
    }
    let projection = orthographic((min.x, max.x), (min.y, max.y), (-max.z - 0.5, -min.z + 0.5));
    projection * view
}

/// A lamp's view straight down in perspective, wide enough to see its room's footprint on the
/// floor (at most [`LAMP_SPREAD`]), from 5 cm below it to 1 m under the floor.
fn lamp_matrix(lamp: &Lamp) -> Mat4 {
    let p = lamp.position;
    let [x0, y0, x1, y1] = lamp.room;
    let across = [x0 - p.x, x1 - p.x, y0 - p.y, y1 - p.y]
        .into_iter()
        .fold(0.0f32, |m, d| m.max(d.abs()));
    let height = p.z.max(0.5);
    let spread = (across / height).clamp(0.2, LAMP_SPREAD);
    let view = look_along(p, -Vector::Z, Vector::X);
    let projection = rapier3d::glamx::glam::camera::rh::proj::directx::perspective(
        2.0 * spread.atan(),
        1.0,
        0.05,
        height + 1.0,
    );
    projection * view
}

/// The view from `eye` looking along `forward` (unit), `up` up: the camera looks down its −z.
fn look_along(eye: Vector, forward: Vector, up: Vector) -> Mat4 {
    let right = forward.cross(up).normalize();
    let up = right.cross(forward);
    Mat4::from_cols(
        Vec4::new(right.x, up.x, -forward.x, 0.0),
        Vec4::new(right.y, up.y, -forward.y, 0.0),
        Vec4::new(right.z, up.z, -forward.z, 0.0),
        Vec4::new(-right.dot(eye), -up.dot(eye), forward.dot(eye), 1.0),
    )
}

/// An orthographic projection of the view box x in `l`–`r`, y in `b`–`t`, and `n`–`f` ahead,
/// onto wgpu's clip space (depth 0 at `n`, 1 at `f`).
fn orthographic((l, r): (f32, f32), (b, t): (f32, f32), (n, f): (f32, f32)) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0 / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 / (t - b), 0.0, 0.0),
        Vec4::new(0.0, 0.0, -1.0 / (f - n), 0.0),
        Vec4::new(-(r + l) / (r - l), -(t + b) / (t - b), -n / (f - n), 1.0),
    )
}

impl ShadowMaps {
    pub(crate) fn new(device: &wgpu::Device) -> ShadowMaps {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shadow"),
            source: wgpu::ShaderSource::Wgsl(include_str!("shadow.wgsl").into()),
        });
        let bind_layout = uniform_layout(device, "shadow matrix", wgpu::ShaderStages::VERTEX);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadow"),
            bind_group_layouts: &[Some(&bind_layout)],
            immediate_size: 0,
        });
        let buffers = [Some(wgpu::VertexBufferLayout {
            array_stride: 12,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wgpu::vertex_attr_array![0 => Float32x3],
        })];
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("shadow"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_shadow"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &buffers,
            },
            primitive: wgpu::PrimitiveState {
                cull_mode: None,
                ..wgpu::PrimitiveState::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: SHADOW_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState {
                    constant: 2,
                    slope_scale: 2.0,
                    clamp: 0.0,
                },
            }),
            multisample: wgpu::MultisampleState::default(),
            fragment: None,
            multiview_mask: None,
            cache: None,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..wgpu::SamplerDescriptor::default()
        });
        ShadowMaps {
            pipeline,
            sampler,
            fixed: map(device, &bind_layout, FIXED_SIZE),
            moving: map(device, &bind_layout, MOVING_SIZE),
            sky: map(device, &bind_layout, SKY_SIZE),
            lamp_fixed: map(device, &bind_layout, LAMP_SIZE),
            lamp_fixed_key: None,
            lamp: map(device, &bind_layout, LAMP_SIZE),
            lamp_key: None,
            sky_matrix: None,
            fixed_key: None,
            moving_key: None,
            positions: Vec::new(),
            triangles: Vec::new(),
        }
    }

    /// The fixed map's, the moving map's, the sky map's and the lamp's texture views.
    pub(crate) fn views(&self) -> [&wgpu::TextureView; 4] {
        [
            &self.fixed.view,
            &self.moving.view,
            &self.sky.view,
            &self.lamp.view,
        ]
    }

    /// Draws the maps for the world as it is, seen from `sun`, the moving one around
    /// `looked_at`, spanning `half` m at least (see [`MOVING_HALF`]); records the passes into
    /// `encoder`.
    pub(crate) fn update(
        &mut self,
        ctx: &mut ShadowContext<'_>,
        looked_at: Vector,
        half: f32,
    ) -> ShadowMatrices {
        let Casters {
            fixed,
            moving,
            walls,
        } = casters(ctx.world, ctx.hidden, ctx.meshes, ctx.models);
        let Some((lo, hi)) = bounds(ctx.world) else {
            return ShadowMatrices::default();
        };
        let sun = ctx.sun;
        let lamp = ctx.lamp.and_then(|l| self.lamp(ctx, &l, [&fixed, &moving]));
        // The walls cut at the windows and the roof follow from the fixed casters (windows and
        // walls are fixed objects): made only when the map is drawn again.
        let through = f32::from(u8::from(ctx.through_windows));
        let fixed_key = key(&fixed, &[sun.x, sun.y, sun.z, through]);
        if self.fixed_key.map(|(k, _)| k) != Some(fixed_key) {
            let matrix = light_matrix(sun, lo, hi, None);
            let sunlit = if ctx.through_windows {
                sunlit(ctx.world, ctx.meshes, &fixed, &walls)
            } else {
                fixed.clone()
            };
            let drawn = self.draw(ctx, (Which::Fixed, Facing::Along(sun)), &sunlit, matrix);
            self.fixed_key = Some((fixed_key, drawn.then_some(matrix)));
            let above = light_matrix(Vector::Z, lo, hi, None);
            let drawn = self.draw(ctx, (Which::Sky, Facing::Along(Vector::Z)), &fixed, above);
            self.sky_matrix = drawn.then_some(above);
        }
        let half = half.max(MOVING_HALF);
        let matrix = light_matrix(sun, lo, hi, Some((looked_at, half)));
        let near: Vec<Caster> = moving
            .into_iter()
            .filter(|c| inside(&matrix, c.centre, c.reach))
            .collect();
        let moving_key = key(&near, &matrix.to_cols_array());
        let drawn = match self.moving_key {
            Some((k, drawn)) if k == moving_key => drawn,
            _ => self.draw(ctx, (Which::Moving, Facing::Along(sun)), &near, matrix),
        };
        self.moving_key = Some((moving_key, drawn));
        ShadowMatrices {
            fixed: self.fixed_key.and_then(|(_, m)| m),
            moving: drawn.then_some(matrix),
            sky: self.sky_matrix,
            lamp,
        }
    }

    /// Brings the lamp's map up to date with the casters in its room, `[fixed, moving]`
    /// (drawing only what changed); its matrix, if it holds anything.
    fn lamp(
        &mut self,
        ctx: &mut ShadowContext<'_>,
        lamp: &Lamp,
        [fixed, moving]: [&[Caster]; 2],
    ) -> Option<Mat4> {
        let matrix = lamp_matrix(lamp);
        let [x0, y0, x1, y1] = lamp.room;
        let in_room = |c: &&Caster| {
            let (p, r) = (c.centre, c.reach);
            p.x + r >= x0
                && p.x - r <= x1
                && p.y + r >= y0
                && p.y - r <= y1
                && p.z - r < lamp.position.z
        };
        let facing = Facing::From(lamp.position);
        let fixed: Vec<Caster> = fixed.iter().filter(in_room).copied().collect();
        let fixed_key = key(&fixed, &matrix.to_cols_array());
        let fixed_drawn = match self.lamp_fixed_key {
            Some((k, drawn)) if k == fixed_key => drawn,
            _ => self.draw(ctx, (Which::LampFixed, facing), &fixed, matrix),
        };
        self.lamp_fixed_key = Some((fixed_key, fixed_drawn));
        let moving: Vec<Caster> = moving.iter().filter(in_room).copied().collect();
        // What the fixed map shows is part of what the lamp's shows.
        let under = [fixed_key as u32, (fixed_key >> 32) as u32].map(f32::from_bits);
        let lamp_key = key(&moving, &under);
        let drawn = match self.lamp_key {
            Some((k, drawn)) if k == lamp_key => drawn,
            _ => {
                ctx.encoder.copy_texture_to_texture(
                    self.lamp_fixed.texture.as_image_copy(),
                    self.lamp.texture.as_image_copy(),
                    self.lamp.texture.size(),
                );
                let moving_drawn = self.draw(ctx, (Which::Lamp, facing), &moving, matrix);
                fixed_drawn || moving_drawn
            }
        };
        self.lamp_key = Some((lamp_key, drawn));
        drawn.then_some(matrix)
    }

    /// Places `casters`, uploads them and records the pass that draws them into one map, seen
    /// as `facing` says (along the sun, straight up for the sky map, from the lamp); whether
    /// anything was drawn.
    fn draw(
        &mut self,
        ctx: &mut ShadowContext<'_>,
        (which, facing): (Which, Facing),
        casters: &[Caster],
        matrix: Mat4,
    ) -> bool {
        self.positions.clear();
        self.triangles.clear();
        for caster in casters {
            place(
                caster,
                ctx.meshes,
                facing,
                &mut self.positions,
                &mut self.triangles,
            );
        }
        let map = match which {
            Which::Fixed => &mut self.fixed,
            Which::Moving => &mut self.moving,
            Which::Sky => &mut self.sky,
            Which::LampFixed => &mut self.lamp_fixed,
            Which::Lamp => &mut self.lamp,
        };
        // The lamp's map starts as a copy of its fixed casters' map: drawn over, not cleared.
        let load = match which {
            Which::Lamp => wgpu::LoadOp::Load,
            _ => wgpu::LoadOp::Clear(1.0),
        };
        let (device, queue) = (ctx.device, ctx.queue);
        queue.write_buffer(
            &map.matrix,
            0,
            bytemuck::bytes_of(&matrix.to_cols_array_2d()),
        );
        upload(
            device,
            queue,
            &mut map.vertices,
            &self.positions,
            wgpu::BufferUsages::VERTEX,
        );
        upload(
            device,
            queue,
            &mut map.indices,
            &self.triangles,
            wgpu::BufferUsages::INDEX,
        );
        map.count = self.triangles.len() as u32;
        let mut pass = ctx.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadow"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &map.view,
                depth_ops: Some(wgpu::Operations {
                    load,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        let (Some((vertices, _)), Some((indices, _))) = (&map.vertices, &map.indices) else {
            return false;
        };
        if map.count == 0 {
            return false;
        }
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &map.bind_group, &[]);
        pass.set_vertex_buffer(0, vertices.slice(..));
        pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..map.count, 0, 0..1);
        true
    }
}

/// What drawing the maps needs of the renderer and the frame.
pub(crate) struct ShadowContext<'a> {
    pub(crate) device: &'a wgpu::Device,
    pub(crate) queue: &'a wgpu::Queue,
    pub(crate) encoder: &'a mut wgpu::CommandEncoder,
    pub(crate) world: &'a World,
    pub(crate) hidden: &'a [ObjectId],
    pub(crate) meshes: &'a mut MeshStore,
    /// Real meshes of model pieces: a robot casts the shadow of the mesh it is drawn with, so
    /// that no box around it darkens its own surface.
    pub(crate) models: &'a ModelLibrary,
    /// Toward the sun.
    pub(crate) sun: Vector,
    /// The lamp of the camera's room, whose shadows are drawn.
    pub(crate) lamp: Option<Lamp>,
    /// Whether the sun comes in through the windows only (`sunlight.rs`).
    pub(crate) through_windows: bool,
}

#[derive(Clone, Copy)]
enum Which {
    Fixed,
    Moving,
    Sky,
    LampFixed,
    Lamp,
}

/// Where a map's light comes from: along a direction (the sun, the sky) or from a point (a
/// lamp). Of a closed mesh, only the triangles that face the light are drawn.
#[derive(Clone, Copy)]
enum Facing {
    Along(Vector),
    From(Vector),
}

/// A hash of what a map shows: its casters (meshes and placements) and `more` (the sun, or the
/// map's matrix).
fn key(casters: &[Caster], more: &[f32]) -> u64 {
    let placed = casters
        .iter()
        .flat_map(|c| std::iter::once(c.mesh).chain(c.model.iter().flatten().map(|v| v.to_bits())));
    hash_words(placed.chain(more.iter().map(|v| v.to_bits())))
}

/// Whether a ball lies (partly) inside a map's view.
fn inside(matrix: &Mat4, centre: Vector, reach: f32) -> bool {
    let c: Vec4 = *matrix * centre.extend(1.0);
    // The matrix is orthographic: x and y scale by its diagonal.
    let (sx, sy) = (
        matrix.x_axis.truncate().length(),
        matrix.y_axis.truncate().length(),
    );
    c.x.abs() <= 1.0 + reach * sx && c.y.abs() <= 1.0 + reach * sy
}

/// The box of the world's fixed objects, raised to hold what stands above them.
fn bounds(world: &World) -> Option<(Vector, Vector)> {
    let (lo, hi) = fixed_bounds(world)?;
    Some((lo - Vector::splat(0.5), hi + Vector::new(0.5, 0.5, 1.0)))
}

/// The world's casters.
struct Casters {
    /// Of fixed objects' bodies.
    fixed: Vec<Caster>,
    /// Of everything else.
    moving: Vec<Caster>,
    /// Which of `fixed` are walls' (the sun's map casts them cut at the windows).
    walls: Vec<usize>,
}

/// What the sun's map of the fixed geometry casts: `fixed` with the walls (`walls`) cut at their
/// windows and a roof over them, where the world has walls; `fixed` as it is otherwise.
fn sunlit(world: &World, meshes: &mut MeshStore, fixed: &[Caster], walls: &[usize]) -> Vec<Caster> {
    let Some(sun) = sun_casters(world) else {
        return fixed.to_vec();
    };
    let unit = Primitive::Box {
        half_extents: Vector::ONE,
    };
    let mesh = meshes.id(MeshKey::UnitBox, &VisualShape::Primitive(&unit));
    let slab = |s: &Slab| Caster {
        mesh,
        model: rows(&s.pose, s.half),
        centre: s.pose.translation,
        reach: s.half.length(),
    };
    let kept = fixed
        .iter()
        .enumerate()
        .filter(|(k, _)| walls.binary_search(k).is_err())
        .map(|(_, c)| *c);
    kept.chain(sun.slabs.iter().map(slab)).collect()
}

/// The world's casters: fixed ones (bodies of fixed objects) and moving ones (the rest).
fn casters(
    world: &World,
    hidden: &[ObjectId],
    meshes: &mut MeshStore,
    models: &ModelLibrary,
) -> Casters {
    let (mut fixed, mut moving, mut walls) = (Vec::new(), Vec::new(), Vec::new());
    for (id, object) in world.bodies().objects() {
        if !object.is_present() || hidden.contains(&id) {
            continue;
        }
        let still = object.body_kind == BodyKind::Fixed;
        let seed = object_seed(world, id);
        for part in world.visuals().parts_with(id, models) {
            if part.visual.material == Material::Glass {
                continue;
            }
            let drawn = Drawn::of(&part.shape, seed);
            let caster = Caster {
                mesh: meshes.id(drawn.key.caster(), &part.shape),
                model: rows(&part.pose, drawn.scale),
                centre: part.pose.translation,
                reach: drawn.reach,
            };
            if still && part.link.is_none() {
                if object.category == WALL_SYNSET {
                    walls.push(fixed.len());
                }
                fixed.push(caster);
            } else {
                moving.push(caster);
            }
        }
    }
    Casters {
        fixed,
        moving,
        walls,
    }
}

/// Appends a caster's triangles, placed in the world; of a closed mesh only those that face
/// the light (the others are behind them).
fn place(
    caster: &Caster,
    meshes: &MeshStore,
    facing: Facing,
    positions: &mut Vec<[f32; 3]>,
    triangles: &mut Vec<u32>,
) {
    let mesh = meshes.mesh(caster.mesh);
    let [x, y, z] = caster.model;
    let row = |r: [f32; 4], p: Vec3A| r[0] * p.x + r[1] * p.y + r[2] * p.z + r[3];
    let base = positions.len();
    positions.extend(mesh.vertices.iter().map(|v| {
        let p = Vec3A::from_array(v.position);
        [row(x, p), row(y, p), row(z, p)]
    }));
    let placed = &positions[base..];
    for t in mesh.indices.chunks_exact(3) {
        if mesh.closed {
            let corner = |k: usize| Vec3A::from_array(placed[t[k] as usize]);
            let (a, b, c) = (corner(0), corner(1), corner(2));
            let toward = match facing {
                Facing::Along(sun) => Vec3A::from(sun),
                Facing::From(light) => Vec3A::from(light) - a,
            };
            if (b - a).cross(c - a).dot(toward) <= 0.0 {
                continue;
            }
        }
        triangles.extend(t.iter().map(|&i| base as u32 + i));
    }
}

/// Writes `data` into `slot`'s buffer, remade bigger when it does not fit.
fn upload<T: bytemuck::Pod>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    slot: &mut Option<(wgpu::Buffer, usize)>,
    data: &[T],
    usage: wgpu::BufferUsages,
) {
    let bytes = std::mem::size_of_val(data);
    if slot.as_ref().is_none_or(|(_, capacity)| *capacity < bytes) {
        let capacity = bytes.next_power_of_two().max(1 << 16);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shadow casters"),
            size: capacity as u64,
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        *slot = Some((buffer, capacity));
    }
    if let Some((buffer, _)) = slot
        && bytes > 0
    {
        queue.write_buffer(buffer, 0, bytemuck::cast_slice(data));
    }
}
