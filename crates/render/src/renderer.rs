//! The renderer: a device, its pipelines and mesh store, drawing a [`Scene`] through a
//! [`View`] into the modalities asked for.

use crate::camera::Camera;
use crate::error::RenderError;
use crate::finish::home_seed;
use crate::frame_geometry::{FrameGeometry, FrameVertex};
use crate::gpu::Gpu;
use crate::instances::{Gatherer, History, Scene};
use crate::lighting::{Lighting, ShadowMatrices};
use crate::mesh::MeshStore;
use crate::modality::{Frame, Modality};
use crate::pipeline::{Globals, Pipelines, slots};
use crate::profile::ImageProfile;
use crate::shadow::{ShadowContext, ShadowMaps};
use crate::targets::{Pass, Source, Target, Targets};
use behavior_sim::ModelLibrary;
use rapier3d::glamx::Mat4;
use rapier3d::math::Vector;
use std::sync::Arc;

/// A camera, how it draws colour, and what it saw last, for the flow modalities: keep one per
/// camera and render through it every step.
#[derive(Clone, Debug)]
pub struct View {
    /// The camera; move it between frames as its mount moves.
    pub camera: Camera,
    /// How its colour image is drawn (the other modalities are the same in both profiles).
    pub profile: ImageProfile,
    previous: Option<History>,
}

impl View {
    /// A camera that has seen nothing yet (its first frame's flow is zero), drawing in the
    /// default profile ([`ImageProfile::Realistic`]).
    pub fn new(camera: Camera) -> View {
        View::with_profile(camera, ImageProfile::default())
    }

    /// A camera that has seen nothing yet, drawing colour in `profile`.
    pub fn with_profile(camera: Camera, profile: ImageProfile) -> View {
        View {
            camera,
            profile,
            previous: None,
        }
    }

    /// Forgets the last frame (after a reset): the next frame's flow is zero.
    pub fn forget(&mut self) {
        self.previous = None;
    }
}

/// An offscreen renderer. Making one finds an adapter and compiles the shaders (tens of
/// milliseconds); keep it for every frame.
pub struct Renderer {
    gpu: Gpu,
    pipelines: Pipelines,
    meshes: MeshStore,
    /// The frame's vertices and indices, kept to be refilled.
    geometry: FrameGeometry,
    /// Their GPU copies, grown as frames need.
    buffers: Option<Buffers>,
    /// Render targets, one set per image size drawn lately (a robot's eye and an overview of
    /// another size take turns without remaking them).
    targets: Vec<Targets>,
    /// Whether to leave out what big boxes hide.
    cull: bool,
    /// Whether the realistic profile dims what the fixed geometry covers from above.
    ambient_occlusion: bool,
    /// Whether the sun comes in through the windows only (see `sunlight.rs`).
    sun_through_windows: bool,
    /// Whether the realistic profile's materials tilt the shading normal by their relief.
    normal_detail: bool,
    stats: FrameStats,
    /// The realistic profile's light and shadow maps, made at its first frame.
    realistic: Option<Realistic>,
    /// Real meshes of model pieces ([`Renderer::set_models`]).
    models: Arc<ModelLibrary>,
}

/// What the realistic profile draws with besides the fast one's.
struct Realistic {
    shadows: ShadowMaps,
    lights: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

impl Realistic {
    fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> Realistic {
        let shadows = ShadowMaps::new(device);
        let lights = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lights"),
            size: std::mem::size_of::<crate::lighting::LightsUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let [fixed, moving, sky, lamp] = shadows.views();
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("lights"),
            layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: lights.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(fixed),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(moving),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::Sampler(&shadows.sampler),
                },
                wgpu::BindGroupEntry {
                    binding: 4,
                    resource: wgpu::BindingResource::TextureView(sky),
                },
                wgpu::BindGroupEntry {
                    binding: 5,
                    resource: wgpu::BindingResource::TextureView(lamp),
                },
            ],
        });
        Realistic {
            shadows,
            lights,
            bind_group,
        }
    }
}

/// The GPU's vertex and index buffers, and how many of each they hold.
struct Buffers {
    vertices: wgpu::Buffer,
    vertex_capacity: usize,
    indices: wgpu::Buffer,
    index_capacity: usize,
}

/// What the last frame drew.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Instances drawn (a part, particle or drop each).
    pub instances: usize,
    /// Instances in the view left out as hidden behind big boxes.
    pub culled: usize,
    /// Triangles sent to the GPU.
    pub triangles: u64,
}

/// Image sizes whose targets a renderer keeps.
const KEPT_SIZES: usize = 4;

/// The light's direction in the world (the shader gets it in the camera's frame): from above, a
/// little from the side.
const LIGHT: Vector = Vector::new(0.3, 0.2, 0.93);

impl Renderer {
    /// A renderer on the best adapter found: a GPU, else Mesa's lavapipe on the CPU. Fails with
    /// [`RenderError::NoAdapter`], naming the packages to install, where there is neither.
    pub fn new() -> Result<Renderer, RenderError> {
        let gpu = Gpu::new()?;
        let pipelines = Pipelines::new(&gpu.device);
        Ok(Renderer {
            gpu,
            pipelines,
            meshes: MeshStore::default(),
            geometry: FrameGeometry::default(),
            buffers: None,
            targets: Vec::new(),
            cull: true,
            ambient_occlusion: true,
            sun_through_windows: true,
            normal_detail: true,
            stats: FrameStats::default(),
            realistic: None,
            models: Arc::new(ModelLibrary::EMPTY),
        })
    }

    /// Draws objects that name a model piece (a robot's link) with the piece's meshes from
    /// `models` (for Fetch, `behavior_robots::shared_models()`); without, or for a piece it does
    /// not hold, with their own parts. The meshes made of the previous library are dropped.
    pub fn set_models(&mut self, models: Arc<ModelLibrary>) {
        if !Arc::ptr_eq(&models, &self.models) {
            self.models = models;
            // Mesh ids change: the shadow maps, which remember what they drew by them, go too.
            self.meshes = MeshStore::default();
            self.realistic = None;
        }
    }

    /// The adapter drawing: its name and backend (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)
    /// (Vulkan)").
    pub fn adapter(&self) -> String {
        let a = &self.gpu.adapter;
        format!("{} ({:?})", a.name, a.backend)
    }

    /// Turns occlusion culling on (the default) or off. Culling is conservative, so images are
    /// the same either way, only slower without it; turning it off is for checking that.
    pub fn set_occlusion_culling(&mut self, on: bool) {
        self.cull = on;
    }

    /// Turns the realistic profile's ambient occlusion on (the default) or off, to see what it
    /// does (an ablation); the other modalities are the same either way.
    pub fn set_ambient_occlusion(&mut self, on: bool) {
        self.ambient_occlusion = on;
    }

    /// Lets the sun into a home through its windows only (the default: a roof over the walls and
    /// the walls cut at the windows, in the sun's map alone, as a home with ceilings has it), or
    /// from above as well (off: the homes have no ceilings, so that an overview sees into every
    /// room), to compare. A world without walls is lit from above either way.
    pub fn set_sun_through_windows(&mut self, on: bool) {
        self.sun_through_windows = on;
    }

    /// Turns the realistic profile's normal detail (grout, seams, weave and grain tilting the
    /// shading normal) on (the default) or off, as an ablation; the other modalities, the
    /// normal modality included, are the same either way.
    pub fn set_normal_detail(&mut self, on: bool) {
        self.normal_detail = on;
    }

    /// What the last frame drew.
    pub fn stats(&self) -> FrameStats {
        self.stats
    }

    /// Draws `scene` from `view`'s camera and reads back the modalities asked for (each once, in
    /// [`Modality::ALL`]'s order); the view remembers this frame for the next one's flow.
    pub fn render(
        &mut self,
        scene: &Scene,
        view: &mut View,
        modalities: &[Modality],
    ) -> Result<Frame, RenderError> {
        view.camera.check()?;
        let camera = view.camera;
        let realistic =
            view.profile == ImageProfile::Realistic && modalities.contains(&Modality::Rgb);
        let home = home_seed(scene.world);
        let profile = if realistic {
            ImageProfile::Realistic
        } else {
            ImageProfile::Fast
        };
        let batch = Gatherer {
            scene,
            camera: &camera,
            meshes: &mut self.meshes,
            previous: view.previous.as_ref(),
            cull: self.cull,
            profile,
            home,
            models: &self.models,
        }
        .gather();
        let motion = modalities
            .iter()
            .any(|&m| Source::of(m, modalities).pass() == Pass::Motion);
        self.geometry.fill(
            &batch.instances,
            &self.meshes,
            camera.pose.translation,
            motion,
        );
        self.stats = FrameStats {
            instances: batch.instances.len(),
            culled: batch.culled,
            triangles: self.geometry.triangles(),
        };
        self.upload(&camera, view.previous.as_ref());
        let mut wanted: Vec<Modality> = Modality::ALL
            .into_iter()
            .filter(|m| modalities.contains(m))
            .collect();
        wanted.dedup();
        let mut encoder = self
            .gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        if realistic {
            self.light(scene, &camera, home, &mut encoder);
        }
        let frame = self.draw(encoder, &camera, profile, &wanted)?;
        view.previous = Some(History {
            view_projection: camera.view_projection(),
            models: batch.models,
        });
        Ok(frame)
    }

    /// Sends the frame's vertices, indices and globals to the GPU.
    fn upload(&mut self, camera: &Camera, previous: Option<&History>) {
        let device = &self.gpu.device;
        let (vertices, indices) = (&self.geometry.vertices, &self.geometry.indices);
        let fits =
            |b: &Buffers| b.vertex_capacity >= vertices.len() && b.index_capacity >= indices.len();
        if !self.buffers.as_ref().is_some_and(fits) {
            let buffer = |label, count: usize, size: usize, usage| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size: (count * size) as u64,
                    usage: usage | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            };
            let vertex_capacity = vertices.len().next_power_of_two().max(4096);
            let index_capacity = indices.len().next_power_of_two().max(8192);
            self.buffers = Some(Buffers {
                vertices: buffer(
                    "vertices",
                    vertex_capacity,
                    std::mem::size_of::<FrameVertex>(),
                    wgpu::BufferUsages::VERTEX,
                ),
                vertex_capacity,
                indices: buffer("indices", index_capacity, 4, wgpu::BufferUsages::INDEX),
                index_capacity,
            });
        }
        if let Some(b) = &self.buffers
            && !indices.is_empty()
        {
            let queue = &self.gpu.queue;
            queue.write_buffer(&b.vertices, 0, bytemuck::cast_slice(vertices));
            queue.write_buffer(&b.indices, 0, bytemuck::cast_slice(indices));
        }
        let view_projection = camera.view_projection();
        let previous = previous.map_or(view_projection, |h| h.view_projection);
        let globals = Globals {
            view_projection: view_projection.to_cols_array_2d(),
            previous_view_projection: previous.to_cols_array_2d(),
            view: camera.view().to_cols_array_2d(),
            light: (camera.pose.rotation.inverse() * LIGHT.normalize())
                .extend(0.0)
                .to_array(),
            size: [camera.width as f32, camera.height as f32, 0.0, 0.0],
        };
        self.gpu
            .queue
            .write_buffer(&self.pipelines.globals, 0, bytemuck::bytes_of(&globals));
    }

    /// Records the realistic profile's shadow passes into `encoder` and sets the lights of the
    /// home of seed `home` for `camera`.
    fn light(
        &mut self,
        scene: &Scene,
        camera: &Camera,
        home: u64,
        encoder: &mut wgpu::CommandEncoder,
    ) {
        let device = &self.gpu.device;
        let realistic = self
            .realistic
            .get_or_insert_with(|| Realistic::new(device, &self.pipelines.lights_layout));
        let lighting = Lighting::of(scene.world, home);
        let (looked_at, half) = looked_at(camera);
        let mut ctx = ShadowContext {
            device,
            queue: &self.gpu.queue,
            encoder,
            world: scene.world,
            hidden: scene.hidden,
            meshes: &mut self.meshes,
            models: &self.models,
            sun: lighting.sun,
            lamp: lighting.main_lamp(camera.pose.translation).copied(),
            through_windows: self.sun_through_windows,
        };
        let mut shadows: ShadowMatrices = realistic.shadows.update(&mut ctx, looked_at, half);
        if !self.ambient_occlusion {
            shadows.sky = None;
        }
        let to_world =
            Mat4::from_rotation_translation(camera.pose.rotation, camera.pose.translation);
        let mut uniform = lighting.uniform(to_world, camera.pose.translation, shadows);
        uniform.detail[0] = if self.normal_detail { 1.0 } else { 0.0 };
        self.gpu
            .queue
            .write_buffer(&realistic.lights, 0, bytemuck::bytes_of(&uniform));
    }

    fn draw(
        &mut self,
        mut encoder: wgpu::CommandEncoder,
        camera: &Camera,
        profile: ImageProfile,
        wanted: &[Modality],
    ) -> Result<Frame, RenderError> {
        let size = (camera.width, camera.height);
        let kept = match self.targets.iter().position(|t| t.size() == size) {
            Some(k) => k,
            None => {
                if self.targets.len() == KEPT_SIZES {
                    self.targets.remove(0);
                }
                self.targets
                    .push(Targets::new(&self.gpu.device, size.0, size.1));
                self.targets.len() - 1
            }
        };
        let (Some(targets), Some(buffers)) = (self.targets.get(kept), &self.buffers) else {
            return Err(RenderError::Gpu("buffers missing".into()));
        };
        let sources = Source::all_of(wanted);
        for pass in [Pass::Surface, Pass::Motion] {
            let drawn: Vec<Source> = sources
                .iter()
                .copied()
                .filter(|s| s.pass() == pass)
                .collect();
            if drawn.is_empty() {
                continue;
            }
            let attachments = slots(pass, &drawn, |s| {
                targets
                    .get(s)
                    .map(|t| attachment(&t.view, s.clear(profile)))
            });
            let attachments: Vec<_> = attachments.into_iter().map(Option::flatten).collect();
            let pipeline = self.pipelines.get(&self.gpu.device, pass, profile, &drawn);
            let lights = match (pass, profile, &self.realistic) {
                (Pass::Surface, ImageProfile::Realistic, Some(r)) => Some(&r.bind_group),
                _ => None,
            };
            let geometry = Geometry {
                buffers,
                indices: self.geometry.indices.len() as u32,
                bind_group: &self.pipelines.bind_group,
                lights,
            };
            geometry.pass(&mut encoder, &attachments, &targets.depth, &pipeline);
        }
        let read: Vec<(Source, &Target)> = sources
            .iter()
            .filter_map(|&s| Some((s, targets.get(s)?)))
            .collect();
        for (_, target) in &read {
            target.copy(&mut encoder, size);
        }
        self.gpu.queue.submit([encoder.finish()]);
        for (_, target) in &read {
            target.request();
        }
        self.gpu
            .device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        let mut images = Vec::with_capacity(wanted.len());
        for (s, target) in &read {
            let from_here: Vec<Modality> = wanted
                .iter()
                .copied()
                .filter(|&m| Source::of(m, wanted) == *s)
                .collect();
            let decoded = target.decode(&from_here, size);
            images.extend(decoded.map_err(RenderError::Gpu)?);
        }
        // In `wanted`'s order, which is `Modality::ALL`'s.
        images.sort_by_key(|i| wanted.iter().position(|&m| m == i.modality));
        Ok(Frame {
            width: size.0,
            height: size.1,
            images,
        })
    }
}

/// Where a camera looks, for the moving shadow map, and half the width it must cover there (at
/// least the map's own minimum): for a camera looking down from afar (an overview), the ground
/// it sees; for one among the furniture (an eye), the floor 3 m ahead.
fn looked_at(camera: &Camera) -> (Vector, f32) {
    let eye = camera.pose.translation;
    let forward = camera.pose.rotation * Vector::X;
    let reach = if forward.z < -0.2 {
        eye.z / -forward.z
    } else {
        f32::INFINITY
    };
    if reach > 8.0 && reach.is_finite() {
        let reach = reach.min(60.0);
        let half = reach * (0.5 * camera.vertical_fov).tan() * 1.5;
        (eye + forward * reach, half)
    } else {
        let ahead = Vector::new(forward.x, forward.y, 0.0).normalize_or(Vector::X);
        (Vector::new(eye.x, eye.y, 0.0) + ahead * 3.0, 0.0)
    }
}

fn attachment(view: &wgpu::TextureView, clear: wgpu::Color) -> wgpu::RenderPassColorAttachment<'_> {
    wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(clear),
            store: wgpu::StoreOp::Store,
        },
    }
}

/// What a pass draws.
struct Geometry<'a> {
    buffers: &'a Buffers,
    /// How many indices of the buffer this frame uses.
    indices: u32,
    bind_group: &'a wgpu::BindGroup,
    /// The realistic pass's second group.
    lights: Option<&'a wgpu::BindGroup>,
}

impl Geometry<'_> {
    fn pass(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        attachments: &[Option<wgpu::RenderPassColorAttachment<'_>>],
        depth: &wgpu::TextureView,
        pipeline: &wgpu::RenderPipeline,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("draw"),
            color_attachments: attachments,
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: depth,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        if self.indices == 0 {
            return;
        }
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, self.bind_group, &[]);
        if let Some(lights) = self.lights {
            pass.set_bind_group(1, lights, &[]);
        }
        pass.set_vertex_buffer(0, self.buffers.vertices.slice(..));
        pass.set_index_buffer(self.buffers.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.indices, 0, 0..1);
    }
}
