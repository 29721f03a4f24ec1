//! The images a frame is drawn into, the buffers they are read back through, and the decoding of
//! their bytes into a [`Frame`]'s arrays.

use crate::modality::{Image, Modality, Pixels};
use crate::pipeline::{COLOR, DEPTH, FLOW, GEOMETRY, IDS, SCENE_FLOW};

/// A texture and the buffer it is copied into for reading.
pub(crate) struct Target {
    pub(crate) texture: wgpu::Texture,
    pub(crate) view: wgpu::TextureView,
    readback: wgpu::Buffer,
    /// Bytes per texel.
    texel: u32,
    /// Bytes per row in the buffer (padded to wgpu's 256).
    padded_row: u32,
}

/// Every target of one image size.
pub(crate) struct Targets {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) color: Target,
    pub(crate) geometry: Target,
    pub(crate) ids: Target,
    pub(crate) scene_flow: Target,
    pub(crate) flow: Target,
    pub(crate) depth: wgpu::TextureView,
}

fn texture(
    device: &wgpu::Device,
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("frame"),
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

impl Target {
    fn new(
        device: &wgpu::Device,
        size: (u32, u32),
        format: wgpu::TextureFormat,
        texel: u32,
    ) -> Target {
        let texture = texture(device, size, format);
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let padded_row = (size.0 * texel).div_ceil(align) * align;
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: u64::from(padded_row) * u64::from(size.1),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Target {
            texture,
            view,
            readback,
            texel,
            padded_row,
        }
    }

    /// Records the copy of the texture into the readback buffer.
    pub(crate) fn copy(&self, encoder: &mut wgpu::CommandEncoder, (w, h): (u32, u32)) {
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.padded_row),
                    rows_per_image: Some(h),
                },
            },
            wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
        );
    }

    /// Asks for the readback buffer to be mapped once the GPU is done.
    pub(crate) fn request(&self) {
        self.readback.map_async(wgpu::MapMode::Read, .., |_| {});
    }

    /// The texels' bytes without the row padding; the buffer must be mapped.
    pub(crate) fn bytes(&self, (w, h): (u32, u32)) -> Result<Vec<u8>, String> {
        let row = (w * self.texel) as usize;
        let mut out = Vec::with_capacity(row * h as usize);
        {
            let mapped = self
                .readback
                .get_mapped_range(..)
                .map_err(|e| e.to_string())?;
            for y in 0..h as usize {
                let start = y * self.padded_row as usize;
                out.extend_from_slice(&mapped[start..start + row]);
            }
        }
        self.readback.unmap();
        Ok(out)
    }
}

impl Targets {
    pub(crate) fn new(device: &wgpu::Device, width: u32, height: u32) -> Targets {
        let size = (width, height);
        let depth =
            texture(device, size, DEPTH).create_view(&wgpu::TextureViewDescriptor::default());
        Targets {
            width,
            height,
            color: Target::new(device, size, COLOR, 4),
            geometry: Target::new(device, size, GEOMETRY, 16),
            ids: Target::new(device, size, IDS, 8),
            scene_flow: Target::new(device, size, SCENE_FLOW, 16),
            flow: Target::new(device, size, FLOW, 8),
            depth,
        }
    }

    pub(crate) fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    pub(crate) fn get(&self, source: Source) -> &Target {
        match source {
            Source::Color => &self.color,
            Source::Geometry => &self.geometry,
            Source::Ids => &self.ids,
            Source::SceneFlow => &self.scene_flow,
            Source::Flow => &self.flow,
        }
    }
}

/// Which target a modality is read from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Source {
    Color,
    Geometry,
    Ids,
    SceneFlow,
    Flow,
}

impl Source {
    pub(crate) fn of(modality: Modality) -> Source {
        match modality {
            Modality::Rgb => Source::Color,
            Modality::Depth | Modality::Normal => Source::Geometry,
            Modality::Seg | Modality::InsSeg | Modality::Highlight => Source::Ids,
            Modality::SceneFlow => Source::SceneFlow,
            Modality::Flow => Source::Flow,
        }
    }

    /// The targets some modalities are read from, each once.
    pub(crate) fn all_of(modalities: &[Modality]) -> Vec<Source> {
        let mut out: Vec<Source> = Vec::new();
        for &m in modalities {
            let s = Source::of(m);
            if !out.contains(&s) {
                out.push(s);
            }
        }
        out
    }
}

fn floats(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}

fn words(bytes: &[u8]) -> Vec<u32> {
    bytes
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}

/// Channels `pick` of every texel of `channels` each.
fn every<T: Copy>(values: &[T], channels: usize, pick: &[usize]) -> Vec<T> {
    values
        .chunks_exact(channels)
        .flat_map(|texel| pick.iter().map(move |&c| texel[c]))
        .collect()
}

/// Decodes one modality from the bytes of its target.
pub(crate) fn decode(modality: Modality, bytes: &[u8], (w, h): (u32, u32)) -> Image {
    let (w, h) = (w as usize, h as usize);
    let (shape, pixels) = match modality {
        Modality::Rgb => (vec![h, w, 3], Pixels::U8(every(bytes, 4, &[0, 1, 2]))),
        Modality::Depth => (vec![h, w], Pixels::F32(every(&floats(bytes), 4, &[3]))),
        Modality::Normal => (
            vec![h, w, 3],
            Pixels::F32(every(&floats(bytes), 4, &[0, 1, 2])),
        ),
        Modality::InsSeg => (vec![h, w], Pixels::U32(every(&words(bytes), 2, &[0]))),
        Modality::Seg => {
            let ids = every(&words(bytes), 2, &[1]);
            (
                vec![h, w],
                Pixels::U16(ids.iter().map(|&c| (c & 0xffff) as u16).collect()),
            )
        }
        Modality::Highlight => {
            let ids = every(&words(bytes), 2, &[1]);
            (
                vec![h, w],
                Pixels::U8(ids.iter().map(|&c| ((c >> 16) & 1) as u8).collect()),
            )
        }
        Modality::Flow => (vec![h, w, 2], Pixels::F32(floats(bytes))),
        Modality::SceneFlow => (
            vec![h, w, 3],
            Pixels::F32(every(&floats(bytes), 4, &[0, 1, 2])),
        ),
    };
    Image {
        modality,
        shape,
        pixels,
    }
}
