//! The graphics device: an adapter found without a window or display, preferring a GPU and
//! falling back to Mesa's lavapipe (Vulkan on the CPU).

use crate::error::RenderError;

/// A device and its queue, and which adapter they run on.
pub(crate) struct Gpu {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    pub(crate) adapter: wgpu::AdapterInfo,
}

impl Gpu {
    /// The first adapter wgpu offers, high performance preferred (a GPU over lavapipe).
    pub(crate) fn new() -> Result<Gpu, RenderError> {
        // WGPU_BACKEND and friends may narrow the choice (wgpu's own variables).
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        descriptor.backends &=
            wgpu::Backends::VULKAN | wgpu::Backends::METAL | wgpu::Backends::DX12;
        let instance = wgpu::Instance::new(descriptor);
        let options = wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..wgpu::RequestAdapterOptions::default()
        };
        let adapter = pollster::block_on(instance.request_adapter(&options)).map_err(|e| {
            RenderError::NoAdapter {
                reason: e.to_string(),
            }
        })?;
        let info = adapter.get_info();
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("behavior-render"),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..wgpu::DeviceDescriptor::default()
        };
        let (device, queue) =
            pollster::block_on(adapter.request_device(&descriptor)).map_err(|e| {
                RenderError::NoDevice {
                    adapter: info.name.clone(),
                    reason: e.to_string(),
                }
            })?;
        Ok(Gpu {
            device,
            queue,
            adapter: info,
        })
    }
}
