//! Soft furnishings on furniture: a made bed's mattress under a duvet with its pillows, a
//! sofa's seat with its row of cushions and its back with cushions leaning on it. Each fills
//! the box of the collider it draws, so that whatever rests on it rests where it is seen (a
//! pillow's top is the collider's top; the duvet lies 2 cm under it, the tolerance within which
//! a drawn surface may differ from the collider).

use crate::grid::{signed_pow, sphere_grid};
use crate::mesh::{Mesh, join};
use crate::rounded::block;
use crate::tone::Tone;
use crate::{Ctx, Detail, Form};
use rapier3d::math::{Rotation, Vector};

/// A puffy cushion or pillow filling the box of half size `half` at `centre`: flat-ish on its
/// faces, round at its edges, fullest in the middle.
fn puff(centre: Vector, half: Vector, detail: Detail, tone: Tone) -> Mesh {
    // Ten bands show a pillow's puff; a few pixels across (the coarse level), it is a lump.
    let bands = match detail {
        Detail::Fine => 10,
        Detail::Coarse => 4,
    };
    let mut mesh = sphere_grid(bands, 2 * bands, |d| {
        Vector::new(
            signed_pow(d.x, 0.25) * half.x,
            signed_pow(d.y, 0.25) * half.y,
            signed_pow(d.z, 0.7) * half.z,
        )
    })
    .toned(tone);
    mesh.turn(Rotation::IDENTITY, centre);
    mesh
}

/// How far a made bed's duvet lies under the box's top, m.
fn sag(h: Vector) -> f32 {
    (0.2 * h.z).min(0.02)
}

/// The mattress under a made bed's duvet and pillows, as centre and half size: as wide as the
/// box less the duvet's fall at each side, its top a centimetre under the duvet's.
fn mattress_box(h: Vector) -> (Vector, Vector) {
    let top = h.z - sag(h) - 0.01f32.min(0.2 * h.z);
    let inset = 0.02f32.min(0.1 * h.x);
    let half = Vector::new(h.x - inset, h.y, 0.5 * (top + h.z));
    (Vector::new(0.0, 0.0, 0.5 * (top - h.z)), half)
}

fn mattress_radius(half: Vector) -> f32 {
    0.4 * half.min_element().min(0.06)
}

/// How thick a sofa's seat cushions are, m.
fn cushion(h: Vector) -> f32 {
    (0.3 * h.z).min(0.07)
}

/// The plinth under a sofa's cushions, as centre and half size.
fn plinth_box(h: Vector) -> (Vector, Vector) {
    let c = cushion(h);
    (Vector::new(0.0, 0.0, -c), Vector::new(h.x, h.y, h.z - c))
}

fn plinth_radius(half: Vector) -> f32 {
    0.5 * half.min_element().min(0.05)
}

/// The box a form of this file fills wholly (its mattress or plinth inside its rounding), as
/// centre and half size: what [`crate::solid_core`] says of them.
pub(crate) fn core(form: Form, h: Vector) -> (Vector, Vector) {
    let (centre, half, radius) = match form {
        Form::Bedding => {
            let (c, half) = mattress_box(h);
            (c, half, mattress_radius(half))
        }
        Form::Backrest => {
            let (c, half) = back_frame(h);
            (c, half, plinth_radius(half))
        }
        _ => {
            let (c, half) = plinth_box(h);
            (c, half, plinth_radius(half))
        }
    };
    (centre, half - Vector::splat(radius))
}

/// A made bed's mattress (its head at +y, against the headboard): a mattress in a pale sheet,
/// a duvet in the part's own colour over its foot and hanging down its sides, turned back at
/// the head over a band of sheet, and one pillow (a bed under 1.2 m wide) or two, whose tops are
/// the box's top; the duvet lies up to 2 cm under it.
pub(crate) fn bedding(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let rows = ctx.detail.bevel_rows();
    let sag = sag(h);
    let (centre, mattress_half) = mattress_box(h);
    let mattress_top = centre.z + mattress_half.z;
    let mattress = block(
        centre,
        mattress_half,
        mattress_radius(mattress_half),
        rows,
        ctx.detail,
        Tone::Light,
    );
    // The pillows' strip at the head, and the duvet up to it.
    let pillow_depth = (0.2 * h.y).min(0.22);
    let head = h.y - 2.0 * pillow_depth - 0.02f32.min(0.05 * h.y);
    let fold = ctx.dice.between(0.03, 0.08).min(0.1 * h.y);
    let fall = (0.45 * h.z).min(0.15);
    let duvet_half = Vector::new(h.x, 0.5 * (head + h.y), 0.5 * fall);
    let duvet = block(
        Vector::new(0.0, 0.5 * (head - h.y), h.z - sag - 0.5 * fall),
        duvet_half,
        0.45 * duvet_half.min_element(),
        rows,
        ctx.detail,
        Tone::Body,
    );
    let band_half = Vector::new(h.x, fold, 0.5 * fall);
    let band = block(
        Vector::new(0.0, head - fold, h.z - 0.8 * sag - 0.5 * fall),
        band_half,
        0.45 * band_half.min_element(),
        rows,
        ctx.detail,
        Tone::Light,
    );
    let count = if h.x > 0.6 { 2 } else { 1 };
    let gap = 0.02f32.min(0.05 * h.x);
    let width = (2.0 * h.x - gap * (count as f32 + 1.0)) / count as f32;
    let thick = 0.5 * (h.z - mattress_top) + 0.005f32.min(0.1 * h.z);
    let mut pieces = vec![mattress, duvet, band];
    for k in 0..count {
        let x = -h.x + gap + width * (k as f32 + 0.5) + gap * k as f32;
        pieces.push(puff(
            Vector::new(x, h.y - pillow_depth - 0.01f32.min(0.02 * h.y), h.z - thick),
            Vector::new(0.5 * width, pillow_depth, thick),
            ctx.detail,
            Tone::Light,
        ));
    }
    join(pieces)
}

/// How far a sofa's back cushions stand in from the ends of its back, m: the sofa's arms are
/// 15 cm wide (`crates/assets`, `furniture.rs`), and the cushions sit between them.
const ARM: f32 = 0.15;

/// The frame behind a sofa's back cushions, as centre and half size: the back half of the box.
fn back_frame(h: Vector) -> (Vector, Vector) {
    (
        Vector::new(0.0, 0.5 * h.y, 0.0),
        Vector::new(h.x, 0.5 * h.y, h.z),
    )
}

/// A sofa's back (its front toward −y): a frame in the back half of the box and, leaning on its
/// front, two cushions (a back under 1.9 m wide) or three between the arms, a little under the
/// frame's top.
pub(crate) fn backrest(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let (centre, frame_half) = back_frame(h);
    let frame = block(
        centre,
        frame_half,
        plinth_radius(frame_half),
        ctx.detail.bevel_rows(),
        ctx.detail,
        Tone::Body,
    );
    let count = if h.x < 0.95 { 2 } else { 3 };
    let inner = (h.x - ARM.min(0.2 * h.x)).max(0.5 * h.x);
    let gap = 0.01f32.min(0.05 * h.x);
    let width = (2.0 * inner - gap * (count as f32 - 1.0)) / count as f32;
    let top = ctx.dice.between(0.8, 0.9);
    let tall = 0.5 * (1.0 + top) * h.z;
    let mut pieces = vec![frame];
    for k in 0..count {
        let x = -inner + width * (k as f32 + 0.5) + gap * k as f32;
        pieces.push(puff(
            Vector::new(x, -0.45 * h.y, -h.z + tall),
            Vector::new(0.5 * width, 0.55 * h.y, tall),
            ctx.detail,
            Tone::Body,
        ));
    }
    join(pieces)
}

/// A sofa's seat: a plinth with a row of two cushions (a seat under 1.9 m wide) or three on
/// top, each a little apart from the next.
pub(crate) fn seat(ctx: Ctx) -> Mesh {
    let h = ctx.half;
    let rows = ctx.detail.bevel_rows();
    let cushion = cushion(h);
    let (centre, plinth_half) = plinth_box(h);
    let plinth = block(
        centre,
        plinth_half,
        plinth_radius(plinth_half),
        rows,
        ctx.detail,
        Tone::Body,
    );
    let count = if h.x < 0.95 { 2 } else { 3 };
    let gap = 0.01f32.min(0.05 * h.x);
    let width = (2.0 * h.x - gap * (count as f32 - 1.0)) / count as f32;
    let mut pieces = vec![plinth];
    for k in 0..count {
        let x = -h.x + width * (k as f32 + 0.5) + gap * k as f32;
        pieces.push(puff(
            Vector::new(x, 0.0, h.z - cushion),
            Vector::new(0.5 * width, h.y, cushion),
            ctx.detail,
            Tone::Body,
        ));
    }
    join(pieces)
}
