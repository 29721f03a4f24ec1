//! What a camera can deliver, and a rendered frame holding the arrays asked for.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// One kind of image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Modality {
    /// Colour: `[h, w, 3]` u8, sRGB.
    Rgb,
    /// Depth along the camera's axis: `[h, w]` f32, m; 0 where nothing is seen.
    Depth,
    /// Surface normals in the camera frame (x forward, y left, z up): `[h, w, 3]` f32; 0 where
    /// nothing is seen.
    Normal,
    /// Semantic segmentation: `[h, w]` u16 category ids ([`crate::CategoryTable`]).
    Seg,
    /// Instance segmentation: `[h, w]` u32, the object's id + 1 (0: nothing).
    InsSeg,
    /// The activity's objects: `[h, w]` u8, 1 on their pixels.
    Highlight,
    /// Optical flow: `[h, w, 2]` f32, how far (pixels, x right, y down) the surface seen at each
    /// pixel moved in the image since the previous frame.
    Flow,
    /// Scene flow: `[h, w, 3]` f32, how far (m, world frame) the surface seen at each pixel moved
    /// since the previous frame.
    SceneFlow,
}

impl Modality {
    /// Every camera modality.
    pub const ALL: [Modality; 8] = [
        Modality::Rgb,
        Modality::Depth,
        Modality::Normal,
        Modality::Seg,
        Modality::InsSeg,
        Modality::Highlight,
        Modality::Flow,
        Modality::SceneFlow,
    ];

    /// Its name in observations and on the command line (the original's).
    pub fn name(self) -> &'static str {
        match self {
            Modality::Rgb => "rgb",
            Modality::Depth => "depth",
            Modality::Normal => "normal",
            Modality::Seg => "seg",
            Modality::InsSeg => "ins_seg",
            Modality::Highlight => "highlight",
            Modality::Flow => "flow",
            Modality::SceneFlow => "scene_flow",
        }
    }
}

impl fmt::Display for Modality {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name that is not a modality.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown modality `{0}`; known: rgb, depth, normal, seg, ins_seg, highlight, flow, scene_flow"
)]
pub struct UnknownModality(pub String);

impl FromStr for Modality {
    type Err = UnknownModality;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Modality::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| UnknownModality(s.to_string()))
    }
}

/// The numbers of one image, row-major from the top-left pixel.
#[derive(Clone, Debug, PartialEq)]
pub enum Pixels {
    /// u8 values.
    U8(Vec<u8>),
    /// u16 values.
    U16(Vec<u16>),
    /// u32 values.
    U32(Vec<u32>),
    /// f32 values.
    F32(Vec<f32>),
}

impl Pixels {
    /// How many numbers.
    pub fn len(&self) -> usize {
        match self {
            Pixels::U8(v) => v.len(),
            Pixels::U16(v) => v.len(),
            Pixels::U32(v) => v.len(),
            Pixels::F32(v) => v.len(),
        }
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One image: its numbers and their shape (`[h, w]` or `[h, w, c]`).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Which modality.
    pub modality: Modality,
    /// Dimensions, outermost first.
    pub shape: Vec<usize>,
    /// `shape.iter().product()` numbers.
    pub pixels: Pixels,
}

/// What one camera saw: an image per modality asked for, in [`Modality::ALL`]'s order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frame {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// The images.
    pub images: Vec<Image>,
}

impl Frame {
    /// The image of a modality, if it was asked for.
    pub fn get(&self, modality: Modality) -> Option<&Image> {
        self.images.iter().find(|i| i.modality == modality)
    }

    /// The pixel index of (x, y).
    pub fn index(&self, x: u32, y: u32) -> usize {
        (y * self.width + x) as usize
    }
}
