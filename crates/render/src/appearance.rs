//! How an object's states show: the colour it is drawn with, given its own colour, material and
//! states — as the paper's simulator shows them (a cooked steak looks cooked).
//!
//! | state | look |
//! |---|---|
//! | cooked | 55 % of the way to a roast brown |
//! | burnt | 85 % of the way to charcoal |
//! | frozen | 45 % of the way to frost white-blue |
//! | soaked | 40 % darker |
//! | toggled on | glowing: it emits a warm light of its own |
//!
//! Open doors and drawers, sliced halves, dust and stains (particles on their surfaces) and water
//! drops show through the world's geometry, not through colour.

use behavior_core::Predicate;
use behavior_forms::Tone;
use behavior_sim::{Material, ObjectId, Visual, World};

/// sRGB of a roast brown.
const COOKED: [f32; 3] = [0.45, 0.25, 0.10];
/// sRGB of charcoal.
const BURNT: [f32; 3] = [0.08, 0.06, 0.05];
/// sRGB of frost.
const FROST: [f32; 3] = [0.85, 0.92, 1.0];

/// Dust particles: grey (sRGB, as the cameras and the browser viewer draw them).
pub const DUST: [u8; 3] = [150, 140, 125];
/// Stain particles: a dark brown.
pub const STAIN: [u8; 3] = [70, 45, 25];
/// Water drops: blue.
pub const WATER: [u8; 3] = [60, 120, 220];

/// What a shader needs of a surface: linear albedo, how strongly it glows, how shiny it is.
/// Public so that other drawers of the world (the browser viewer) show states as cameras do.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Look {
    /// Linear-sRGB colour, 0–1.
    pub albedo: [f32; 3],
    /// 0 (no glow) to 1.
    pub emission: f32,
    /// Specular strength, 0–1.
    pub shine: f32,
}

fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    std::array::from_fn(|i| a[i] + (b[i] - a[i]) * t)
}

/// An sRGB channel (0–1) as linear light: the colours the cameras compute with.
pub fn to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// How a form's detail in a tone of its own (a stem, a cap, a lamp's shade) is drawn, by the
/// cameras, glTF export and the browser viewer alike: its plain colour, matte, or bare metal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ToneLook {
    /// Linear RGB.
    pub albedo: [f32; 3],
    /// 0 (mirror) to 1 (chalk).
    pub roughness: f32,
    /// 0 or 1.
    pub metallic: f32,
}

/// The look of `tone`, or `None` for [`Tone::Body`] (the part's own).
pub fn tone_look(tone: Tone) -> Option<ToneLook> {
    let metal = tone == Tone::Metal;
    tone.srgb().map(|srgb| ToneLook {
        albedo: srgb.map(|c| to_linear(f32::from(c) / 255.0)),
        roughness: if metal { 0.35 } else { 0.7 },
        metallic: if metal { 1.0 } else { 0.0 },
    })
}

/// The states that change an object's colour, read once per object and frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Shown {
    pub(crate) cooked: bool,
    pub(crate) burnt: bool,
    pub(crate) frozen: bool,
    pub(crate) soaked: bool,
    pub(crate) on: bool,
}

impl Shown {
    pub(crate) fn of(world: &World, id: ObjectId) -> Shown {
        let is = |p| world.state(id, p);
        Shown {
            cooked: is(Predicate::Cooked),
            burnt: is(Predicate::Burnt),
            frozen: is(Predicate::Frozen),
            soaked: is(Predicate::Soaked),
            on: is(Predicate::ToggledOn),
        }
    }
}

/// How a surface of `object` with appearance `visual` looks in the object's states now.
pub fn state_look(world: &World, object: ObjectId, visual: Visual) -> Look {
    look(visual.color, visual.material, Shown::of(world, object))
}

/// The look of a surface of sRGB `color` and `material` in these states.
pub(crate) fn look(color: [u8; 3], material: Material, shown: Shown) -> Look {
    let mut c = color.map(|v| f32::from(v) / 255.0);
    if shown.cooked {
        c = mix(c, COOKED, 0.55);
    }
    if shown.burnt {
        c = mix(c, BURNT, 0.85);
    }
    if shown.frozen {
        c = mix(c, FROST, 0.45);
    }
    if shown.soaked {
        c = c.map(|v| v * 0.6);
    }
    let shine = match material {
        Material::Metal => 0.5,
        Material::Glass | Material::Ceramic => 0.35,
        Material::Plastic | Material::Stone => 0.15,
        _ => 0.03,
    };
    Look {
        albedo: c.map(to_linear),
        emission: if shown.on { 0.8 } else { 0.0 },
        shine,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cooking_browns_burning_blackens_and_soaking_darkens() {
        let apple = [200, 40, 30];
        let raw = look(apple, Material::Food, Shown::default());
        let cooked = look(
            apple,
            Material::Food,
            Shown {
                cooked: true,
                ..Shown::default()
            },
        );
        let burnt = look(
            apple,
            Material::Food,
            Shown {
                burnt: true,
                ..Shown::default()
            },
        );
        let soaked = look(
            apple,
            Material::Food,
            Shown {
                soaked: true,
                ..Shown::default()
            },
        );
        let sum = |l: Look| l.albedo.iter().sum::<f32>();
        assert!(cooked.albedo[0] < raw.albedo[0] && cooked.albedo[1] > raw.albedo[1]);
        assert!(sum(burnt) < 0.1 * sum(raw));
        assert!(sum(soaked) < sum(raw));
        let on = look(
            apple,
            Material::Plastic,
            Shown {
                on: true,
                ..Shown::default()
            },
        );
        assert!(on.emission > 0.0 && raw.emission == 0.0);
    }
}
