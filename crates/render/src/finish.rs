//! Surfaces for the realistic profile: which procedural pattern a part is drawn with, how rough
//! and how metallic it is, and the colour its home's palette gives it.
//!
//! The world carries only a colour and a [`Material`] per part; a finish adds what a person
//! sees of the material — grain, boards, tiles, weave — and the home's taste: every home draws
//! its floors by room type (tiles in kitchens and bathrooms, boards or carpet elsewhere), its
//! wall paint and the wood species of its furniture from a seed of its own ([`home_seed`], a
//! hash of its rooms), so the same home always looks the same and two homes differ. The
//! pattern itself is drawn by the shader (`realistic.wgsl`) from the part's own coordinates,
//! so it moves with the part, varied by the object's seed (a hash of its name).
//!
//! Nothing here changes the world: physics, states and every other modality are untouched.

use behavior_core::RoomType;
use behavior_core::{FLOOR_SYNSET, WALL_SYNSET};
use behavior_sim::{BodyKind, Material, ObjectId, Visual, World};

/// A procedural pattern; the numbers are `realistic.wgsl`'s.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub(crate) enum Pattern {
    /// Even colour with faint mottling (plastic, rubber, glazed ceramic).
    Plain = 0,
    /// Growth rings and fibres (furniture, boards, wooden things).
    Wood = 1,
    /// Floor boards with seams, each board its own tint.
    Planks = 2,
    /// Square tiles with grout.
    Tiles = 3,
    /// Fine pile.
    Carpet = 4,
    /// Painted plaster.
    Plaster = 5,
    /// Stone with veins.
    Marble = 6,
    /// A woven cloth.
    Fabric = 7,
    /// Brushed metal.
    Brushed = 8,
    /// Printed paper: a label band with lines of print.
    Print = 9,
    /// Food skin: mottled, speckled.
    Skin = 10,
    /// Glass: dark, smooth, shiny.
    Glass = 11,
}

/// How one part is drawn under the realistic profile.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Finish {
    /// Its colour after the home's palette (sRGB).
    pub(crate) color: [u8; 3],
    pub(crate) pattern: Pattern,
    /// 0 (mirror) to 1 (chalk).
    pub(crate) roughness: f32,
    /// 0 (a dielectric) or 1 (a metal).
    pub(crate) metallic: f32,
    /// Varies the pattern between objects: a hash of the object's name.
    pub(crate) seed: u32,
}

impl Finish {
    /// The shader's `surface` word: pattern, roughness and metallic in a byte each.
    pub(crate) fn packed(&self) -> [u32; 2] {
        let byte = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u32;
        [
            self.pattern as u32 | byte(self.roughness) << 8 | byte(self.metallic) << 16,
            self.seed,
        ]
    }
}

/// FNV-1a over bytes: stable across runs and machines (unlike std's hasher), for seeds.
pub(crate) fn fnv(bytes: impl IntoIterator<Item = u8>) -> u64 {
    bytes.into_iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// An object's own seed, which varies its finish and its form's shape: a hash of its name.
pub(crate) fn object_seed(world: &World, object: ObjectId) -> u32 {
    behavior_forms::seed_of(&world.bodies().object(object).name)
}

/// The home's own seed: a hash of its rooms (types and footprints), 0 for a world without rooms.
pub(crate) fn home_seed(world: &World) -> u64 {
    if world.rooms().is_empty() {
        return 0;
    }
    fnv(world.rooms().iter().flat_map(|r| {
        let words = [r.kind as u32, r.instance]
            .into_iter()
            .chain(r.min.iter().chain(&r.max).map(|v| v.to_bits()));
        words.flat_map(u32::to_le_bytes).collect::<Vec<u8>>()
    }))
}

/// One of `options`, picked by `seed` mixed with `salt`.
fn pick<T: Copy>(options: &[T], seed: u64, salt: u64) -> T {
    let h = (seed ^ salt.wrapping_mul(0x9e37_79b9_7f4a_7c15)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    options[((h >> 33) % options.len() as u64) as usize]
}

/// Wood species a home's furniture is made of (sRGB): oak, walnut, maple, cherry, ash, teak.
const SPECIES: [[u8; 3]; 6] = [
    [176, 132, 84],
    [104, 70, 46],
    [214, 180, 134],
    [150, 86, 58],
    [196, 170, 130],
    [138, 96, 60],
];
/// Wall paints: warm whites, greige, sage, pale blue, sand, dusty rose.
const PAINTS: [[u8; 3]; 7] = [
    [236, 230, 218],
    [222, 214, 200],
    [196, 204, 186],
    [196, 210, 222],
    [226, 210, 180],
    [226, 200, 196],
    [244, 242, 236],
];
/// Floor boards.
const BOARDS: [[u8; 3]; 4] = [
    [170, 124, 80],
    [120, 84, 56],
    [200, 170, 130],
    [150, 110, 76],
];
/// Tiles: white, cream, slate, terracotta, sage.
const TILES: [[u8; 3]; 5] = [
    [232, 232, 228],
    [224, 214, 190],
    [110, 116, 122],
    [176, 102, 70],
    [170, 186, 170],
];
/// Carpets: grey, beige, blue, moss.
const CARPETS: [[u8; 3]; 4] = [
    [140, 138, 134],
    [190, 174, 150],
    [96, 110, 140],
    [120, 130, 96],
];

/// The finish of a floor in a room of `kind`.
fn floor(kind: Option<RoomType>, home: u64) -> Finish {
    let wet = matches!(
        kind,
        Some(RoomType::Kitchen | RoomType::Bathroom | RoomType::UtilityRoom)
    );
    let soft = matches!(kind, Some(RoomType::Bedroom | RoomType::Closet));
    let (pattern, color, roughness) = if kind == Some(RoomType::Garage) {
        (Pattern::Marble, [150, 150, 146], 0.9)
    } else if wet {
        (
            Pattern::Tiles,
            pick(&TILES, home, kind.map_or(0, |k| k as u64 + 1)),
            0.3,
        )
    } else if soft && pick(&[true, false], home, 17) {
        (Pattern::Carpet, pick(&CARPETS, home, 3), 0.95)
    } else {
        (Pattern::Planks, pick(&BOARDS, home, 5), 0.55)
    };
    Finish {
        color,
        pattern,
        roughness,
        metallic: 0.0,
        seed: (home as u32) ^ kind.map_or(0, |k| k as u32 * 0x9e37),
    }
}

fn mix(a: [u8; 3], b: [u8; 3], t: f32) -> [u8; 3] {
    std::array::from_fn(|i| (f32::from(a[i]) + (f32::from(b[i]) - f32::from(a[i])) * t) as u8)
}

/// What an object's parts share of their finish, worked out once per object and frame.
pub(crate) enum Finisher {
    /// Floors and walls: every part alike, whatever its own look.
    Whole(Finish),
    /// A floor: its slabs alike, its rugs (parts of cloth) in pile of their own colour.
    Floor(Finish),
    /// Anything else: each part by its material, the object's seed for all, and the home's
    /// wood species for furniture.
    ByMaterial {
        seed: u32,
        /// The home's wood for a fixed object's wooden parts.
        species: Option<[u8; 3]>,
    },
}

impl Finisher {
    /// How `object`'s parts are finished in a home of seed `home`; `seed` is the object's own
    /// ([`object_seed`], which its caller has already worked out for its form).
    pub(crate) fn of(world: &World, object: ObjectId, home: u64, seed: u32) -> Finisher {
        let o = world.bodies().object(object);
        match o.category.as_str() {
            FLOOR_SYNSET => {
                let room = world.rooms().iter().find(|r| r.floor == Some(object));
                Finisher::Floor(floor(room.map(|r| r.kind), home))
            }
            WALL_SYNSET => Finisher::Whole(Finish {
                color: pick(&PAINTS, home, 11),
                pattern: Pattern::Plaster,
                roughness: 0.85,
                metallic: 0.0,
                seed,
            }),
            _ => Finisher::ByMaterial {
                seed,
                species: (o.body_kind == BodyKind::Fixed).then(|| pick(&SPECIES, home, 7)),
            },
        }
    }

    /// The finish of one part of the object, of appearance `visual`.
    pub(crate) fn part(&self, visual: Visual) -> Finish {
        let (seed, species) = match *self {
            Finisher::Whole(finish) => return finish,
            Finisher::Floor(finish) if visual.material == Material::Cloth => {
                return Finish {
                    color: visual.color,
                    pattern: Pattern::Carpet,
                    roughness: 0.95,
                    ..finish
                };
            }
            Finisher::Floor(finish) => return finish,
            Finisher::ByMaterial { seed, species } => (seed, species),
        };
        let (pattern, roughness, metallic) = match visual.material {
            Material::Wood => (Pattern::Wood, 0.6, 0.0),
            Material::Metal => (Pattern::Brushed, 0.35, 1.0),
            Material::Plastic => (Pattern::Plain, 0.45, 0.0),
            Material::Glass => (Pattern::Glass, 0.05, 0.0),
            Material::Ceramic => (Pattern::Plain, 0.15, 0.0),
            Material::Cloth => (Pattern::Fabric, 0.95, 0.0),
            Material::Paper => (Pattern::Print, 0.8, 0.0),
            Material::Food => (Pattern::Skin, 0.5, 0.0),
            Material::Rubber => (Pattern::Plain, 0.9, 0.0),
            Material::Stone => (Pattern::Marble, 0.3, 0.0),
        };
        // Furniture takes the home's wood species; small wooden things keep their own colour.
        let color = match (visual.material, species) {
            (Material::Wood, Some(wood)) => mix(visual.color, wood, 0.7),
            _ => visual.color,
        };
        Finish {
            color,
            pattern,
            roughness,
            metallic,
            seed,
        }
    }
}

/// A part's surface as the realistic profile finishes it, for drawers other than the cameras
/// (the browser viewer): its colour in the home's palette (before the object's states change
/// it), roughness and metalness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartFinish {
    /// sRGB, 0–255.
    pub color: [u8; 3],
    /// 0 (mirror) to 1 (chalk).
    pub roughness: f32,
    /// 0 (a dielectric) or 1 (a metal).
    pub metallic: f32,
}

/// The finishes of a world's parts, its home's palette worked out once.
#[derive(Clone, Copy, Debug)]
pub struct Finishes {
    home: u64,
}

impl Finishes {
    /// The finishes of `world`'s parts.
    pub fn of(world: &World) -> Finishes {
        Finishes {
            home: home_seed(world),
        }
    }

    /// How a part of `object` of appearance `visual` is finished.
    pub fn part(&self, world: &World, object: ObjectId, visual: Visual) -> PartFinish {
        let seed = object_seed(world, object);
        let f = Finisher::of(world, object, self.home, seed).part(visual);
        PartFinish {
            color: f.color,
            roughness: f.roughness,
            metallic: f.metallic,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wet_rooms_get_tiles_and_the_palette_follows_the_home() {
        assert_eq!(floor(Some(RoomType::Kitchen), 1).pattern, Pattern::Tiles);
        assert_eq!(floor(Some(RoomType::Bathroom), 1).pattern, Pattern::Tiles);
        assert_eq!(
            floor(Some(RoomType::DiningRoom), 1).pattern,
            Pattern::Planks
        );
        let paints: std::collections::BTreeSet<[u8; 3]> =
            (0..64).map(|home| pick(&PAINTS, home, 11)).collect();
        assert!(paints.len() >= 4, "64 homes drew only {paints:?}");
        assert_eq!(pick(&PAINTS, 5, 11), pick(&PAINTS, 5, 11));
    }

    #[test]
    fn the_packed_word_keeps_pattern_roughness_and_metallic() {
        let f = Finish {
            color: [0; 3],
            pattern: Pattern::Brushed,
            roughness: 0.5,
            metallic: 1.0,
            seed: 9,
        };
        let [word, seed] = f.packed();
        assert_eq!(
            (word & 0xff, (word >> 8) & 0xff, word >> 16, seed),
            (8, 128, 255, 9)
        );
    }
}
