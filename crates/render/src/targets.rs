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

    /// Decodes `modalities` (all read from this target) from the mapped readback buffer,
    /// straight from its rows, then unmaps it.
    pub(crate) fn decode(
        &self,
        modalities: &[Modality],
        (w, h): (u32, u32),
    ) -> Result<Vec<Image>, String> {
        let row = (w * self.texel) as usize;
        let images = {
            let mapped = self
                .readback
                .get_mapped_range(..)
                .map_err(|e| e.to_string())?;
            let rows = mapped
                .chunks(self.padded_row as usize)
                .take(h as usize)
                .map(|r| &r[..row]);
            modalities
                .iter()
                .map(|&m| decode(m, rows.clone(), (w, h)))
                .collect()
        };
        self.readback.unmap();
        Ok(images)
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

/// `from` of the 4 bytes at `offset` of each texel of `size` bytes.
fn word<'a, T>(
    rows: impl Iterator<Item = &'a [u8]>,
    size: usize,
    offset: usize,
    from: impl Fn([u8; 4]) -> T,
) -> Vec<T> {
    let mut out = Vec::new();
    for row in rows {
        out.reserve(row.len() / size);
        for t in row.chunks_exact(size) {
            if let Ok(bytes) = t[offset..offset + 4].try_into() {
                out.push(from(bytes));
            }
        }
    }
    out
}

/// The first three 4-byte floats of each texel of `size` bytes.
fn three_floats<'a>(rows: impl Iterator<Item = &'a [u8]> + Clone, size: usize) -> Vec<f32> {
    let [x, y, z] = [0, 4, 8].map(|offset| word(rows.clone(), size, offset, f32::from_le_bytes));
    x.iter()
        .zip(&y)
        .zip(&z)
        .flat_map(|((&x, &y), &z)| [x, y, z])
        .collect()
}

/// Decodes one modality from the rows of its target (padding cut off).
fn decode<'a>(
    modality: Modality,
    rows: impl Iterator<Item = &'a [u8]> + Clone,
    (w, h): (u32, u32),
) -> Image {
    let (w, h) = (w as usize, h as usize);
    let (shape, pixels) = match modality {
        Modality::Rgb => {
            let mut rgb = Vec::with_capacity(w * h * 3);
            for row in rows {
                for t in row.chunks_exact(4) {
                    rgb.extend_from_slice(&t[..3]);
                }
            }
            (vec![h, w, 3], Pixels::U8(rgb))
        }
        Modality::Depth => (
            vec![h, w],
            Pixels::F32(word(rows, 16, 12, f32::from_le_bytes)),
        ),
        Modality::Normal => (vec![h, w, 3], Pixels::F32(three_floats(rows, 16))),
        Modality::InsSeg => (
            vec![h, w],
            Pixels::U32(word(rows, 8, 0, u32::from_le_bytes)),
        ),
        Modality::Seg => {
            let seg = word(rows, 8, 4, |b| u16::from_le_bytes([b[0], b[1]]));
            (vec![h, w], Pixels::U16(seg))
        }
        Modality::Highlight => (vec![h, w], Pixels::U8(word(rows, 8, 4, |b| b[2] & 1))),
        Modality::Flow => (
            vec![h, w, 2],
            Pixels::F32(word(rows, 4, 0, f32::from_le_bytes)),
        ),
        Modality::SceneFlow => (vec![h, w, 3], Pixels::F32(three_floats(rows, 16))),
    };
    Image {
        modality,
        shape,
        pixels,
    }
}
