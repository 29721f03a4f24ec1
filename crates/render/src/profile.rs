//! Image profiles: how a camera's colour image is made. Depth, normals, segmentation and flow
//! are the same in both; only RGB differs.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// How a camera draws colour.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
pub enum ImageProfile {
    /// Surfaces with procedural textures by material (wood grain, floor boards, tiles with
    /// grout, carpet, plaster, stone, fabric weave, brushed metal, printed paper, food skins)
    /// in each home's own palette; a sun whose direction and colour are the home's, with
    /// shadows; a lamp in every room that lights that room; sky and ground ambient; filmic tone
    /// mapping. The default for RGB and for every picture made for a person.
    #[default]
    Realistic,
    /// Flat colours under one light from above, no shadows, no textures: the fastest, and what
    /// every camera drew before the realistic profile existed.
    Fast,
}

impl ImageProfile {
    /// Both profiles.
    pub const ALL: [ImageProfile; 2] = [ImageProfile::Realistic, ImageProfile::Fast];

    /// Its name on the command line and in Python (`realistic`, `fast`).
    pub fn name(self) -> &'static str {
        match self {
            ImageProfile::Realistic => "realistic",
            ImageProfile::Fast => "fast",
        }
    }
}

impl fmt::Display for ImageProfile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name that is not an image profile.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown image profile `{0}`; known: realistic, fast")]
pub struct UnknownProfile(pub String);

impl FromStr for ImageProfile {
    type Err = UnknownProfile;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ImageProfile::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| UnknownProfile(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_a_wrong_one_says_which_exist() {
        for p in ImageProfile::ALL {
            assert_eq!(p.name().parse::<ImageProfile>(), Ok(p));
        }
        let err = "pretty".parse::<ImageProfile>().unwrap_err();
        assert!(err.to_string().contains("realistic, fast"), "{err}");
    }
}
