//! What can go wrong when rendering, each with what to do about it.

/// Why a renderer could not be made or a frame not drawn.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// No graphics adapter: on a machine without a GPU this means no Vulkan driver for the CPU.
    #[error(
        "no graphics adapter found ({reason}). For rendering on a CPU install Mesa's Vulkan \
         drivers and loader (Debian/Ubuntu: `apt-get install mesa-vulkan-drivers libvulkan1`); \
         on a machine with a GPU, install its Vulkan driver"
    )]
    NoAdapter {
        /// What wgpu said.
        reason: String,
    },
    /// The adapter refused to make a device.
    #[error("the graphics adapter `{adapter}` refused a device: {reason}")]
    NoDevice {
        /// The adapter's name.
        adapter: String,
        /// What wgpu said.
        reason: String,
    },
    /// A camera that cannot be drawn from.
    #[error("bad camera: {0}")]
    BadCamera(String),
    /// The GPU failed while drawing or reading back a frame.
    #[error("the GPU failed to render a frame: {0}")]
    Gpu(String),
}
