//! The two render pipelines (surface and motion), their shared layout and the per-frame globals.

use crate::instances::Instance;
use crate::mesh::Vertex;
use bytemuck::{Pod, Zeroable};

/// Colour as drawn: sRGB bytes.
pub(crate) const COLOR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// Camera-frame normal and depth.
pub(crate) const GEOMETRY: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Instance id, category id and highlight bit.
pub(crate) const IDS: wgpu::TextureFormat = wgpu::TextureFormat::Rg32Uint;
/// Scene flow.
pub(crate) const SCENE_FLOW: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Optical flow.
pub(crate) const FLOW: wgpu::TextureFormat = wgpu::TextureFormat::Rg32Float;
/// The depth test's buffer.
pub(crate) const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// What `shader.wgsl` calls `Globals`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub(crate) struct Globals {
    pub(crate) view_projection: [[f32; 4]; 4],
    pub(crate) previous_view_projection: [[f32; 4]; 4],
    pub(crate) view: [[f32; 4]; 4],
    pub(crate) light: [f32; 4],
    pub(crate) size: [f32; 4],
}

/// Pipelines and the globals' binding.
pub(crate) struct Pipelines {
    pub(crate) surface: wgpu::RenderPipeline,
    pub(crate) motion: wgpu::RenderPipeline,
    pub(crate) globals: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
}

const VERTEX_ATTRIBUTES: [wgpu::VertexAttribute; 2] =
    wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
const INSTANCE_ATTRIBUTES: [wgpu::VertexAttribute; 11] = wgpu::vertex_attr_array![
    2 => Float32x4, 3 => Float32x4, 4 => Float32x4,
    5 => Float32x4, 6 => Float32x4, 7 => Float32x4,
    8 => Float32x4, 9 => Float32x4, 10 => Float32x4,
    11 => Float32x4, 12 => Uint32x2
];

fn target(format: wgpu::TextureFormat) -> Option<wgpu::ColorTargetState> {
    Some(wgpu::ColorTargetState {
        format,
        blend: None,
        write_mask: wgpu::ColorWrites::ALL,
    })
}

impl Pipelines {
    pub(crate) fn new(device: &wgpu::Device) -> Pipelines {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("behavior-render shader"),
            source: wgpu::ShaderSource::Wgsl(include_str!("shader.wgsl").into()),
        });
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("globals"),
            size: std::mem::size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("behavior-render"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let build = |(vertex, entry): (&str, &str), targets: &[Option<wgpu::ColorTargetState>]| {
            let buffers = [
                Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<Vertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &VERTEX_ATTRIBUTES,
                }),
                Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<Instance>() as u64,
                    step_mode: wgpu::VertexStepMode::Instance,
                    attributes: &INSTANCE_ATTRIBUTES,
                }),
            ];
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(entry),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some(vertex),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers: &buffers,
                },
                primitive: wgpu::PrimitiveState {
                    // Two-sided: open containers are seen from inside.
                    cull_mode: None,
                    ..wgpu::PrimitiveState::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: wgpu::StencilState::default(),
                    bias: wgpu::DepthBiasState::default(),
                }),
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    targets,
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        Pipelines {
            surface: build(
                ("vs_surface", "fs_surface"),
                &[target(COLOR), target(GEOMETRY), target(IDS)],
            ),
            motion: build(
                ("vs_motion", "fs_motion"),
                &[target(SCENE_FLOW), target(FLOW)],
            ),
            globals,
            bind_group,
        }
    }
}
