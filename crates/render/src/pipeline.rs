//! The render pipelines, one per pass and set of targets written, made when first needed; their
//! shared layout and the per-frame globals.

use crate::frame_geometry::FrameVertex;
use crate::profile::ImageProfile;
use crate::targets::{Pass, Source};
use bytemuck::{Pod, Zeroable};
use std::collections::BTreeMap;

/// Colour as drawn: sRGB bytes.
pub(crate) const COLOR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// Camera-frame normal, and depth in w.
pub(crate) const GEOMETRY: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Depth along the camera's axis, m.
pub(crate) const CAMERA_DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;
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

/// The shaders, the globals' binding, the realistic profile's light binding, and the pipelines
/// made so far.
pub(crate) struct Pipelines {
    /// The fast profile's surface pass and the motion pass.
    module: wgpu::ShaderModule,
    /// The realistic profile's surface pass.
    realistic: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    realistic_layout: wgpu::PipelineLayout,
    pub(crate) globals: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
    /// The realistic pass's lights, shadow maps and their sampler.
    pub(crate) lights_layout: wgpu::BindGroupLayout,
    /// By pass, profile and the targets written (a bit per [`Source::location`]).
    made: BTreeMap<(Pass, ImageProfile, u8), wgpu::RenderPipeline>,
}

/// `FrameVertex`'s fields in order.
const VERTEX_ATTRIBUTES: [wgpu::VertexAttribute; 9] = wgpu::vertex_attr_array![
    0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32, 4 => Float32x4, 5 => Uint32x2,
    6 => Float32x3, 7 => Float32x3, 8 => Uint32x2
];

/// A shader module of the shared prelude (`common.wgsl`) and `body`.
fn module(device: &wgpu::Device, label: &str, body: &str) -> wgpu::ShaderModule {
    let source = format!("{}\n{body}", include_str!("common.wgsl"));
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    })
}

/// A bind group layout of one uniform buffer at binding 0, seen by `visibility`.
pub(crate) fn uniform_layout(
    device: &wgpu::Device,
    label: &str,
    visibility: wgpu::ShaderStages,
) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[uniform_entry(0, visibility)],
    })
}

/// A uniform buffer's entry in a bind group layout.
fn uniform_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// The realistic pass's second bind group: the lights' uniform, the two shadow maps, a
/// comparison sampler, the sky map and the lamp's map (`realistic.wgsl`'s group 1).
fn lights_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let map = |binding| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Depth,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("lights"),
        entries: &[
            uniform_entry(0, wgpu::ShaderStages::FRAGMENT),
            map(1),
            map(2),
            wgpu::BindGroupLayoutEntry {
                binding: 3,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
                count: None,
            },
            map(4),
            map(5),
        ],
    })
}

impl Pipelines {
    pub(crate) fn new(device: &wgpu::Device) -> Pipelines {
        let realistic = module(device, "realistic", include_str!("realistic.wgsl"));
        let module = module(
            device,
            "behavior-render shader",
            include_str!("shader.wgsl"),
        );
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("globals"),
            size: std::mem::size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_layout = uniform_layout(device, "globals", wgpu::ShaderStages::VERTEX_FRAGMENT);
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout: &bind_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("behavior-render"),
            bind_group_layouts: &[Some(&bind_layout)],
            immediate_size: 0,
        });
        let lights_layout = lights_layout(device);
        let realistic_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("behavior-render realistic"),
            bind_group_layouts: &[Some(&bind_layout), Some(&lights_layout)],
            immediate_size: 0,
        });
        Pipelines {
            module,
            realistic,
            layout,
            realistic_layout,
            globals,
            bind_group,
            lights_layout,
            made: BTreeMap::new(),
        }
    }

    /// The pipeline of `pass` in `profile` writing `sources` (all of that pass), made the
    /// first time: the shader's other outputs have no target, and a CPU rasterizer spends
    /// nothing on them. The motion pass is the same in both profiles.
    pub(crate) fn get(
        &mut self,
        device: &wgpu::Device,
        pass: Pass,
        profile: ImageProfile,
        sources: &[Source],
    ) -> wgpu::RenderPipeline {
        let mask = sources
            .iter()
            .fold(0u8, |mask, s| mask | (1 << s.location()));
        let profile = match pass {
            Pass::Surface => profile,
            Pass::Motion => ImageProfile::Fast,
        };
        let (module, layout, entry) = match (pass, profile) {
            (Pass::Surface, ImageProfile::Realistic) => (
                &self.realistic,
                &self.realistic_layout,
                ("vs_realistic", "fs_realistic"),
            ),
            (Pass::Surface, ImageProfile::Fast) => {
                (&self.module, &self.layout, ("vs_surface", "fs_surface"))
            }
            (Pass::Motion, _) => (&self.module, &self.layout, ("vs_motion", "fs_motion")),
        };
        self.made
            .entry((pass, profile, mask))
            .or_insert_with(|| build(device, module, layout, entry, (pass, sources)))
            .clone()
    }
}

/// The colour targets of `pass`, by location, `None` where `sources` does not write.
pub(crate) fn slots<T>(
    pass: Pass,
    sources: &[Source],
    mut each: impl FnMut(Source) -> T,
) -> Vec<Option<T>> {
    let all: Vec<Source> = Source::ALL
        .into_iter()
        .filter(|s| s.pass() == pass)
        .collect();
    all.iter()
        .map(|&s| sources.contains(&s).then(|| each(s)))
        .collect()
}

fn build(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    (vertex, fragment): (&str, &str),
    (pass, sources): (Pass, &[Source]),
) -> wgpu::RenderPipeline {
    let targets = slots(pass, sources, |s| wgpu::ColorTargetState {
        format: s.format(),
        blend: None,
        write_mask: wgpu::ColorWrites::ALL,
    });
    let buffers = [Some(wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<FrameVertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &VERTEX_ATTRIBUTES,
    })];
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(fragment),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vertex),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            buffers: &buffers,
        },
        primitive: wgpu::PrimitiveState {
            // Both sides: open meshes are seen from inside; closed shapes' far sides are left
            // out before drawing (see `frame_geometry.rs`).
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
            module,
            entry_point: Some(fragment),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            targets: &targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}
