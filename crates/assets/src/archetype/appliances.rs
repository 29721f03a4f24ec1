//! Kitchen and laundry appliances: fridges, ovens and dishwashers (a drop-down door), microwaves,
//! washers and dryers (a side-hinged door), and stoves (burners on a solid top). Each places its
//! toggle button where a hand would find it; stoves also place their burners.

use super::geometry::{carcass, span, v};
use super::moving_parts::{drop_door, side_door};
use super::{Blank, Built};

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
        .with_link(side_door("door", min, max, t, b.density));
    built.layout.front_button = v(max.x - 0.05, min.y - 0.01, 0.6 * h);
    built
}

/// Ovens and dishwashers: a carcass with a rack at half height behind a door hinged at its
/// bottom edge, and a control panel along the back of the top, where the button is.
pub(super) fn drop_front(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut parts = carcass(min, max, t);
    parts.push(span(
        v(min.x, min.y, h / 2.0),
        v(max.x, max.y - t, h / 2.0 + t),
    ));
    parts.push(span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.06)));
    let mut built = b.body(parts).with_link(drop_door(min, max, t, b.density));
    built.layout.front_button = v(0.0, min.y - 0.01, h + 0.02);
    built
}

/// Microwaves, washers and dryers: a carcass behind a side-hinged door, the button at the
/// right-hand edge of the front.
pub(super) fn side_hinged(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut built = b
        .body(carcass(min, max, t))
        .with_link(side_door("door", min, max, t, b.density));
    built.layout.front_button = v(max.x - 0.03, min.y - 0.01, 0.8 * h);
    built
}

/// A solid block with a control panel at the back of the top, four burners on the top and the
/// button on the panel.
pub(super) fn stove(b: &Blank) -> Built {
    let (w, d, h, min, max) = (b.w, b.d, b.h, b.min, b.max);
    let parts = vec![
        span(min, max),
        span(v(min.x, max.y - 0.05, h), v(max.x, max.y, h + 0.1)),
    ];
    let mut built = b.body(parts);
    for (k, (fx, fy)) in [(-0.25, -0.2), (0.25, -0.2), (-0.25, 0.2), (0.25, 0.2)]
        .into_iter()
        .enumerate()
    {
        built.layout.burners[k] = Some(v(fx * w, fy * d, h + 0.02));
    }
    built.layout.front_button = v(0.0, max.y - 0.06, h + 0.05);
    built
}
