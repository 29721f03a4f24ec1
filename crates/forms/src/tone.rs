//! Tones: the few colours a form's details take besides its object's own (an apple's stem, a
//! book's pages, a bottle's cap), so one mesh can be drawn in more than one colour.

/// Which colour a vertex takes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Tone {
    /// The object's own colour, as its state shows it (cooked, soaked, frozen…).
    #[default]
    Body,
    /// Wood-brown stems and stalks.
    Stem,
    /// Green leaves and calyxes.
    Leaf,
    /// Pale green-white stalks (broccoli, mushrooms are [`Tone::Light`]).
    Stalk,
    /// A book's pages, a label.
    Paper,
    /// Black plastic and rubber: caps, tips, knobs.
    Dark,
    /// Bare metal: can rims, lamp stems.
    Metal,
    /// Off-white: lamp shades, mushroom stalks, icing.
    Light,
    /// Potting soil.
    Soil,
    /// Terracotta: flower pots.
    Clay,
}

impl Tone {
    /// Its sRGB colour, or `None` for [`Tone::Body`] (the object's).
    pub fn srgb(self) -> Option<[u8; 3]> {
        match self {
            Tone::Body => None,
            Tone::Stem => Some([95, 65, 35]),
            Tone::Leaf => Some([62, 118, 44]),
            Tone::Stalk => Some([172, 196, 122]),
            Tone::Paper => Some([238, 232, 214]),
            Tone::Dark => Some([34, 34, 38]),
            Tone::Metal => Some([188, 190, 196]),
            Tone::Light => Some([236, 232, 224]),
            Tone::Soil => Some([66, 48, 34]),
            Tone::Clay => Some([176, 96, 62]),
        }
    }
}
