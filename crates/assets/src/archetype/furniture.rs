//! Furniture: tables, open shelving, cabinets with a door or drawers, beds, sofas and chairs.
//! All of it is fixed in the scene; its front faces −y.

use super::geometry::{carcass, span, v};
use super::moving_parts::{drawer, side_door};
use super::{Blank, Built};
use behavior_sim::Form;

/// A top on four legs (variant 0), or on a trestle: a panel under each end, leaving the middle
/// free to walk under (variant 1).
pub(super) fn table(b: &Blank) -> Built {
    let (w, d, h, min, max) = (b.w, b.d, b.h, b.min, b.max);
    let top = 0.03f32.min(h / 4.0);
    let mut parts = vec![span(v(min.x, min.y, h - top), max)];
    let leg = 0.03f32.min(w / 8.0).min(d / 8.0);
    if b.variant == 0 {
        for (x, y) in [
            (min.x, min.y),
            (max.x - 2.0 * leg, min.y),
            (min.x, max.y - 2.0 * leg),
            (max.x - 2.0 * leg, max.y - 2.0 * leg),
        ] {
            parts.push(span(
                v(x + leg / 2.0, y + leg / 2.0, 0.0),
                v(x + 1.5 * leg, y + 1.5 * leg, h - top),
            ));
        }
    } else {
        for x in [min.x + 0.1 * w, max.x - 0.1 * w - leg] {
            parts.push(span(
                v(x, min.y + 0.1 * d, 0.0),
                v(x + leg, max.y - 0.1 * d, h - top),
            ));
        }
    }
    b.body(parts)
}

/// Open shelving: sides, back, and three boards (variant 0) or four (variant 1), the lowest on
/// the floor and the highest on top.
pub(super) fn shelf(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let mut parts = vec![
        span(min, v(min.x + t, max.y, max.z)),
        span(v(max.x - t, min.y, min.z), max),
        span(v(min.x, max.y - t, min.z), max),
    ];
    let boards = if b.variant == 0 { 3 } else { 4 };
    for k in 0..boards {
        let z = k as f32 * (h - t) / (boards - 1) as f32;
        parts.push(span(v(min.x, min.y, z), v(max.x, max.y, z + t)));
    }
    b.body(parts)
}

/// A carcass with a shelf at half height behind a side-hinged door (variant 0), or with two
/// drawers, one above the other (variant 1).
pub(super) fn cabinet(b: &Blank) -> Built {
    let (h, t, min, max, density) = (b.h, b.t, b.min, b.max, b.density);
    let mut parts = carcass(min, max, t);
    if b.variant == 0 {
        parts.push(span(
            v(min.x, min.y, h / 2.0 - t / 2.0),
            v(max.x, max.y - t, h / 2.0 + t / 2.0),
        ));
        return b
            .body(parts)
            .with_link(side_door(Form::Door, min, max, t, density));
    }
    let mid = h / 2.0;
    let bottom = drawer(
        "drawer_bottom",
        v(min.x + t, min.y, t),
        v(max.x - t, max.y - t, mid),
        t,
        density,
    );
    let top = drawer(
        "drawer_top",
        v(min.x + t, min.y, mid),
        v(max.x - t, max.y - t, h - t),
        t,
        density,
    );
    b.body(parts).with_link(bottom).with_link(top)
}

/// A base, a mattress on it, and a headboard at the back (+y).
pub(super) fn bed(b: &Blank) -> Built {
    let (h, min, max) = (b.h, b.min, b.max);
    let base = 0.6 * h;
    b.body(vec![
        span(min, v(max.x, max.y, base)),
        span(
            v(min.x + 0.02, min.y + 0.02, base),
            v(max.x - 0.02, max.y - 0.1, h),
        ),
        span(v(min.x, max.y - 0.08, 0.0), v(max.x, max.y, h + 0.4)),
    ])
}

/// A seat, a back, and an arm at each end.
pub(super) fn sofa(b: &Blank) -> Built {
    let (h, min, max) = (b.h, b.min, b.max);
    let seat = 0.45f32.min(h * 0.55);
    b.body(vec![
        span(min, v(max.x, max.y, seat)),
        span(v(min.x, max.y - 0.2, seat), max),
        span(
            v(min.x, min.y, seat),
            v(min.x + 0.15, max.y - 0.2, seat + 0.2),
        ),
        span(
            v(max.x - 0.15, min.y, seat),
            v(max.x, max.y - 0.2, seat + 0.2),
        ),
    ])
}

/// A seat on four legs with a back (variant 0), and arms too (variant 1).
pub(super) fn chair(b: &Blank) -> Built {
    let (h, min, max) = (b.h, b.min, b.max);
    let seat = 0.46f32.min(h * 0.55);
    let leg = 0.03;
    let mut parts = vec![span(v(min.x, min.y, seat - 0.04), v(max.x, max.y, seat))];
    for (x, y) in [
        (min.x, min.y),
        (max.x - leg, min.y),
        (min.x, max.y - leg),
        (max.x - leg, max.y - leg),
    ] {
        parts.push(span(v(x, y, 0.0), v(x + leg, y + leg, seat - 0.04)));
    }
    parts.push(span(v(min.x, max.y - leg, seat), max));
    if b.variant == 1 {
        parts.push(span(
            v(min.x, min.y, seat + 0.2),
            v(min.x + leg, max.y, seat + 0.23),
        ));
        parts.push(span(
            v(max.x - leg, min.y, seat + 0.2),
            v(max.x, max.y, seat + 0.23),
        ));
    }
    b.body(parts)
}
