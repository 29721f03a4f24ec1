//! The renderer: a device, its pipelines and mesh store, drawing a [`Scene`] through a
//! [`View`] into the modalities asked for.

use crate::camera::Camera;
use crate::error::RenderError;
use crate::gpu::Gpu;
use crate::instances::{Batch, Gatherer, History, Instance, Scene};
use crate::mesh::{MeshStore, Vertex};
use crate::modality::{Frame, Modality};
use crate::pipeline::{Globals, Pipelines};
use crate::targets::{Source, Targets};
use rapier3d::math::Vector;
use wgpu::util::DeviceExt;

/// A camera and what it saw last, for the flow modalities: keep one per camera and render
/// through it every step.
#[derive(Clone, Debug)]
pub struct View {
    /// The camera; move it between frames as its mount moves.
    pub camera: Camera,
    previous: Option<History>,
}

impl View {
    /// A camera that has seen nothing yet (its first frame's flow is zero).
    pub fn new(camera: Camera) -> View {
        View {
            camera,
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
    mesh_buffers: Option<(wgpu::Buffer, wgpu::Buffer)>,
    instances: Option<(wgpu::Buffer, usize)>,
    /// Render targets, one set per image size drawn lately (a robot's eye and an overview of
    /// another size take turns without remaking them).
    targets: Vec<Targets>,
    /// Whether to leave out what big boxes hide.
    cull: bool,
    stats: FrameStats,
}

/// What the last frame drew.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Instances sent to the GPU (a part, particle or drop each).
    pub instances: usize,
    /// Instances in the view left out as hidden behind big boxes.
    pub culled: usize,
    /// Triangles sent to the GPU.
    pub triangles: u64,
    /// Draw calls per pass.
    pub draws: usize,
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
            mesh_buffers: None,
            instances: None,
            targets: Vec::new(),
            cull: true,
            stats: FrameStats::default(),
        })
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
        let batch = Gatherer {
            scene,
            camera: &camera,
            meshes: &mut self.meshes,
            previous: view.previous.as_ref(),
            cull: self.cull,
        }
        .gather();
        self.stats = FrameStats {
            instances: batch.instances.len(),
            culled: batch.culled,
            triangles: batch
                .draws
                .iter()
                .map(|&(mesh, _, count)| {
                    let indices = self.meshes.ranges.get(mesh as usize).map_or(0, |r| r.1);
                    u64::from(indices / 3) * u64::from(count)
                })
                .sum(),
            draws: batch.draws.len(),
        };
        self.upload(&batch, &camera, view.previous.as_ref());
        let mut wanted: Vec<Modality> = Modality::ALL
            .into_iter()
            .filter(|m| modalities.contains(m))
            .collect();
        wanted.dedup();
        let frame = self.draw(&batch, &camera, &wanted)?;
        view.previous = Some(History {
            view_projection: camera.view_projection(),
            models: batch.models,
        });
        Ok(frame)
    }

    /// Sends meshes (when new ones were made), instances and globals to the GPU.
    fn upload(&mut self, batch: &Batch, camera: &Camera, previous: Option<&History>) {
        let device = &self.gpu.device;
        if self.meshes.grown || self.mesh_buffers.is_none() {
            let vertices = if self.meshes.vertices.is_empty() {
                vec![Vertex::default()]
            } else {
                self.meshes.vertices.clone()
            };
            let indices = if self.meshes.indices.is_empty() {
                vec![0u32]
            } else {
                self.meshes.indices.clone()
            };
            let v = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("vertices"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX,
            });
            let i = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("indices"),
                contents: bytemuck::cast_slice(&indices),
                usage: wgpu::BufferUsages::INDEX,
            });
            self.mesh_buffers = Some((v, i));
            self.meshes.grown = false;
        }
        let needed = batch.instances.len().max(1);
        if self.instances.as_ref().is_none_or(|(_, cap)| *cap < needed) {
            let capacity = needed.next_power_of_two().max(256);
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("instances"),
                size: (capacity * std::mem::size_of::<Instance>()) as u64,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.instances = Some((buffer, capacity));
        }
        if let Some((buffer, _)) = &self.instances
            && !batch.instances.is_empty()
        {
            self.gpu
                .queue
                .write_buffer(buffer, 0, bytemuck::cast_slice(&batch.instances));
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

    fn draw(
        &mut self,
        batch: &Batch,
        camera: &Camera,
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
        let (Some(targets), Some((vertices, indices)), Some((instances, _))) =
            (self.targets.get(kept), &self.mesh_buffers, &self.instances)
        else {
            return Err(RenderError::Gpu("buffers missing".into()));
        };
        let mut encoder = self
            .gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        let still = wanted.iter().any(|m| !m.moving());
        let moving = wanted.iter().any(|m| m.moving());
        let geometry = Geometry {
            vertices,
            indices,
            instances,
            batch,
            ranges: &self.meshes.ranges,
            pipelines: &self.pipelines,
        };
        if still {
            let attachments = [
                attachment(
                    &targets.color.view,
                    wgpu::Color {
                        r: 0.05,
                        g: 0.05,
                        b: 0.06,
                        a: 1.0,
                    },
                ),
                attachment(&targets.geometry.view, wgpu::Color::TRANSPARENT),
                attachment(&targets.ids.view, wgpu::Color::TRANSPARENT),
            ];
            geometry.pass(
                &mut encoder,
                &attachments,
                &targets.depth,
                &self.pipelines.surface,
            );
        }
        if moving {
            let attachments = [
                attachment(&targets.scene_flow.view, wgpu::Color::TRANSPARENT),
                attachment(&targets.flow.view, wgpu::Color::TRANSPARENT),
            ];
            geometry.pass(
                &mut encoder,
                &attachments,
                &targets.depth,
                &self.pipelines.motion,
            );
        }
        let sources = Source::all_of(wanted);
        for &s in &sources {
            targets.get(s).copy(&mut encoder, size);
        }
        self.gpu.queue.submit([encoder.finish()]);
        for &s in &sources {
            targets.get(s).request();
        }
        self.gpu
            .device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        let mut images = Vec::with_capacity(wanted.len());
        for &s in &sources {
            let from_here: Vec<Modality> = wanted
                .iter()
                .copied()
                .filter(|&m| Source::of(m) == s)
                .collect();
            let decoded = targets.get(s).decode(&from_here, size);
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

fn attachment(
    view: &wgpu::TextureView,
    clear: wgpu::Color,
) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(clear),
            store: wgpu::StoreOp::Store,
        },
    })
}

/// What a pass draws.
struct Geometry<'a> {
    vertices: &'a wgpu::Buffer,
    indices: &'a wgpu::Buffer,
    instances: &'a wgpu::Buffer,
    batch: &'a Batch,
    /// Per mesh: first index, index count, base vertex.
    ranges: &'a [(u32, u32, i32)],
    pipelines: &'a Pipelines,
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
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &self.pipelines.bind_group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_vertex_buffer(1, self.instances.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        for &(mesh, first, count) in &self.batch.draws {
            let Some(&(start, n, base)) = self.ranges.get(mesh as usize) else {
                continue;
            };
            pass.draw_indexed(start..start + n, base, first..first + count);
        }
    }
}
