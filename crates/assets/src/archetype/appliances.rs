//! Kitchen and laundry appliances: fridges, ovens and dishwashers (a drop-down door), microwaves,
//! washers and dryers (a side-hinged door), and stoves (burners on a solid top). Each places its
//! toggle button where a hand would find it; stoves also place their burners. Each names the
//! forms its door and control panel are drawn in.

use super::geometry::{carcass, span, v};
use super::moving_parts::{drop_door, side_door};
use super::{Blank, Built};
use behavior_sim::Form;

/// A carcass with a shelf at half height behind a side-hinged door, the button by the handle.
pub(super) fn fridge(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut parts = carcass(min, max, t);
    parts.push(span(
        v(min.x, min.y, h / 2.0),
        v(max.x, max.y - t, h / 2.0 + t),
    ));
    let mut built = b
        .body(parts)
        .with_link(side_door(Form::Door, min, max, t, b.density));
    built.layout.front_button = v(max.x - 0.05, min.y - 0.01, 0.6 * h);
    built
}

/// An oven: a drop-down door with a window.
pub(super) fn oven(b: &Blank) -> Built {
    drop_front(b, Form::OvenDoor)
}

/// A dishwasher: a plain drop-down door with a bar.
pub(super) fn dishwasher(b: &Blank) -> Built {
    drop_front(b, Form::DropDoor)
}

/// Ovens and dishwashers: a carcass with a rack at half height behind a door hinged at its
/// bottom edge (drawn as `door`), and a control panel along the back of the top, where the
/// button is.
fn drop_front(b: &Blank, door: Form) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut parts = carcass(min, max, t);
    parts.push(span(
        v(min.x, min.y, h / 2.0),
        v(max.x, max.y - t, h / 2.0 + t),
    ));
    parts
        .push(span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.06)).with_form(Form::Controls));
    let mut built = b
        .body(parts)
        .with_link(drop_door(door, min, max, t, b.density));
    built.layout.front_button = v(0.0, min.y - 0.01, h + 0.02);
    built
}

/// A microwave: a glazed side-hinged door.
pub(super) fn microwave(b: &Blank) -> Built {
    side_hinged(b, Form::GlassDoor)
}

/// A washer or a dryer: a side-hinged door with a porthole.
pub(super) fn laundry(b: &Blank) -> Built {
    side_hinged(b, Form::Porthole)
}

/// A carcass behind a side-hinged door (drawn as `door`), the button at the right-hand edge of
/// the front.
fn side_hinged(b: &Blank, door: Form) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut built = b
        .body(carcass(min, max, t))
        .with_link(side_door(door, min, max, t, b.density));
    built.layout.front_button = v(max.x - 0.03, min.y - 0.01, 0.8 * h);
    built
}

/// A solid block (drawn with its burners and an oven's front) with a control panel at the back
/// of the top, four burners on the top and the button on the panel.
pub(super) fn stove(b: &Blank) -> Built {
    let (w, d, h, min, max) = (b.w, b.d, b.h, b.min, b.max);
    let parts = vec![
        span(min, max).with_form(Form::Cooktop),
        span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.1)).with_form(Form::Controls),
    ];
    let mut built = b.body(parts);
    // Where the cooktop form draws them: a quarter of the width and a fifth of the depth off
    // the centre.
    for (k, (fx, fy)) in [(-0.25, -0.2), (0.25, -0.2), (-0.25, 0.2), (0.25, 0.2)]
        .into_iter()
        .enumerate()
    {
        built.layout.burners[k] = Some(v(fx * w, fy * d, h + 0.02));
    }
    built.layout.front_button = v(0.0, max.y - 0.06, h + 0.05);
    built
}
