//! The images a frame is drawn into, the buffers they are read back through, and the decoding of
//! their bytes into a [`Frame`]'s arrays.

use crate::modality::{Image, Modality, Pixels};
use crate::pipeline::{CAMERA_DEPTH, COLOR, DEPTH, FLOW, GEOMETRY, IDS, SCENE_FLOW};
use crate::profile::ImageProfile;

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

/// Every target of one image size, by [`Source`], and the depth test's buffer.
pub(crate) struct Targets {
    pub(crate) width: u32,
    pub(crate) height: u32,
    targets: [Target; 6],
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
    fn new(device: &wgpu::Device, size: (u32, u32), source: Source) -> Target {
        let texture = texture(device, size, source.format());
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let texel = source.texel();
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
                .map(|&m| decode(m, self.texel, rows.clone(), (w, h)))
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
            targets: Source::ALL.map(|s| Target::new(device, size, s)),
            depth,
        }
    }

    pub(crate) fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    pub(crate) fn get(&self, source: Source) -> Option<&Target> {
        self.targets.get(source as usize)
    }
}

/// Which pass draws a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Pass {
    /// Colour, normals, depth and ids (`fs_surface`).
    Surface,
    /// Scene and optical flow (`fs_motion`).
    Motion,
}

/// A target modalities are read from: one output of a pass. A pass writes only the targets
/// the modalities asked for need, since every byte a pixel writes costs a CPU rasterizer time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Source {
    Color,
    /// Normal and depth, when normals are asked for.
    Geometry,
    /// Depth alone, when they are not. (Colour, a separate normal and depth, and ids together
    /// would pass the 32 bytes a pixel that portable adapters allow.)
    Depth,
    Ids,
    SceneFlow,
    Flow,
}

impl Source {
    /// In `shader.wgsl`'s order of outputs, pass by pass.
    pub(crate) const ALL: [Source; 6] = [
        Source::Color,
        Source::Geometry,
        Source::Depth,
        Source::Ids,
        Source::SceneFlow,
        Source::Flow,
    ];

    /// Where `modality` is read from in a frame that asks for `wanted`.
    pub(crate) fn of(modality: Modality, wanted: &[Modality]) -> Source {
        match modality {
            Modality::Rgb => Source::Color,
            Modality::Normal => Source::Geometry,
            Modality::Depth if wanted.contains(&Modality::Normal) => Source::Geometry,
            Modality::Depth => Source::Depth,
            Modality::Seg | Modality::InsSeg | Modality::Highlight => Source::Ids,
            Modality::SceneFlow => Source::SceneFlow,
            Modality::Flow => Source::Flow,
        }
    }

    /// The targets the modalities `wanted` are read from, each once, in [`Source::ALL`]'s
    /// order.
    pub(crate) fn all_of(wanted: &[Modality]) -> Vec<Source> {
        Source::ALL
            .into_iter()
            .filter(|&s| wanted.iter().any(|&m| Source::of(m, wanted) == s))
            .collect()
    }

    pub(crate) fn pass(self) -> Pass {
        match self {
            Source::Color | Source::Geometry | Source::Depth | Source::Ids => Pass::Surface,
            Source::SceneFlow | Source::Flow => Pass::Motion,
        }
    }

    /// The fragment output (`@location`) of its pass it is drawn from.
    pub(crate) fn location(self) -> usize {
        match self {
            Source::Color | Source::SceneFlow => 0,
            Source::Geometry | Source::Flow => 1,
            Source::Depth => 2,
            Source::Ids => 3,
        }
    }

    pub(crate) fn format(self) -> wgpu::TextureFormat {
        match self {
            Source::Color => COLOR,
            Source::Geometry => GEOMETRY,
            Source::Depth => CAMERA_DEPTH,
            Source::Ids => IDS,
            Source::SceneFlow => SCENE_FLOW,
            Source::Flow => FLOW,
        }
    }

    /// Bytes per texel.
    fn texel(self) -> u32 {
        match self {
            Source::Color | Source::Depth => 4,
            Source::Ids | Source::Flow => 8,
            Source::Geometry | Source::SceneFlow => 16,
        }
    }

    /// What a pixel holds where nothing is drawn: the realistic profile's colour sees a pale
    /// sky.
    pub(crate) fn clear(self, profile: ImageProfile) -> wgpu::Color {
        match self {
            Source::Color if profile == ImageProfile::Realistic => wgpu::Color {
                r: 0.52,
                g: 0.62,
                b: 0.78,
                a: 1.0,
            },
            Source::Color => wgpu::Color {
                r: 0.05,
                g: 0.05,
                b: 0.06,
                a: 1.0,
            },
            _ => wgpu::Color::TRANSPARENT,
        }
    }
}

/// The texels of some rows, each mapped by `from`.
fn texels<'a, const N: usize, T>(
    rows: impl Iterator<Item = &'a [u8]>,
    capacity: usize,
    from: impl Fn(&[u8; N]) -> T,
) -> Vec<T> {
    let mut out = Vec::with_capacity(capacity);
    for row in rows {
        out.extend(row.as_chunks::<N>().0.iter().map(&from));
    }
    out
}

fn f32_at<const N: usize>(texel: &[u8; N], offset: usize) -> f32 {
    f32::from_le_bytes([
        texel[offset],
        texel[offset + 1],
        texel[offset + 2],
        texel[offset + 3],
    ])
}

/// Decodes one modality from the rows of its target (padding cut off), whose texels are
/// `texel` bytes (depth is read from the depth target or the geometry's fourth float).
fn decode<'a>(
    modality: Modality,
    texel: u32,
    rows: impl Iterator<Item = &'a [u8]>,
    (w, h): (u32, u32),
) -> Image {
    let (w, h) = (w as usize, h as usize);
    let n = w * h;
    let (shape, pixels) = match modality {
        Modality::Rgb => {
            let rgb = texels(rows, n, |t: &[u8; 4]| [t[0], t[1], t[2]]);
            (vec![h, w, 3], Pixels::U8(rgb.into_flattened()))
        }
        Modality::Depth if texel == 16 => (
            vec![h, w],
            Pixels::F32(texels(rows, n, |t: &[u8; 16]| f32_at(t, 12))),
        ),
        Modality::Depth => (
            vec![h, w],
            Pixels::F32(texels(rows, n, |t: &[u8; 4]| f32_at(t, 0))),
        ),
        Modality::Normal | Modality::SceneFlow => {
            let xyz = texels(rows, n, |t: &[u8; 16]| [0, 4, 8].map(|o| f32_at(t, o)));
            (vec![h, w, 3], Pixels::F32(xyz.into_flattened()))
        }
        Modality::InsSeg => {
            let ids = texels(rows, n, |t: &[u8; 8]| {
                u32::from_le_bytes([t[0], t[1], t[2], t[3]])
            });
            (vec![h, w], Pixels::U32(ids))
        }
        Modality::Seg => {
            let seg = texels(rows, n, |t: &[u8; 8]| u16::from_le_bytes([t[4], t[5]]));
            (vec![h, w], Pixels::U16(seg))
        }
        Modality::Highlight => (
            vec![h, w],
            Pixels::U8(texels(rows, n, |t: &[u8; 8]| t[6] & 1)),
        ),
        Modality::Flow => {
            let xy = texels(rows, n, |t: &[u8; 8]| [f32_at(t, 0), f32_at(t, 4)]);
            (vec![h, w, 2], Pixels::F32(xy.into_flattened()))
        }
    };
    Image {
        modality,
        shape,
        pixels,
    }
}
