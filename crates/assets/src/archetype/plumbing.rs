//! Fixtures with water: sinks, bathtubs, showers and toilets. Those that are water sources place
//! their outlet (where drops fall from) and their tap's button.

use super::geometry::{span, tub, v};
use super::{Blank, Built};
use behavior_sim::Form;

/// A basin on a stand, with a tap at the back.
pub(super) fn sink(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let bowl = 0.25f32.min(h / 2.0);
    let mut parts = vec![span(
        v(min.x + t, min.y + t, 0.0),
        v(max.x - t, max.y - t, h - bowl),
    )];
    parts.extend(tub(v(min.x, min.y, h - bowl), max, t));
    parts
        .push(span(v(-0.02, max.y - 0.05, h), v(0.02, max.y - 0.01, h + 0.3)).with_form(Form::Tap));
    let mut built = b.body(parts);
    built.layout.outlet = Some(v(0.0, max.y - 0.1, h + 0.25));
    built.layout.front_button = v(0.08, max.y - 0.03, h + 0.05);
    built
}

/// A tub with walls at least 3 cm thick, the tap at its −x end.
pub(super) fn bathtub(b: &Blank) -> Built {
    let (h, min, max) = (b.h, b.min, b.max);
    let mut built = b.body(tub(min, max, b.t.max(0.03)));
    built.layout.outlet = Some(v(min.x + 0.15, 0.0, h + 0.2));
    built.layout.front_button = v(min.x + 0.05, 0.0, h + 0.05);
    built
}

/// A tray with walls on three sides, open at the front; the head high on the back wall.
pub(super) fn shower(b: &Blank) -> Built {
    let (h, t, min, max) = (b.h, b.t, b.min, b.max);
    let parts = vec![
        span(min, v(max.x, max.y, 0.05)),
        span(v(min.x, min.y, 0.0), v(min.x + t, max.y, h)),
        span(v(max.x - t, min.y, 0.0), v(max.x, max.y, h)),
        span(v(min.x, max.y - t, 0.0), v(max.x, max.y, h)),
    ];
    let mut built = b.body(parts);
    built.layout.outlet = Some(v(0.0, max.y - 0.15, h - 0.2));
    built.layout.front_button = v(0.0, max.y - t - 0.01, 1.1);
    built
}

/// A pedestal, a bowl at seat height and a cistern at the back, its flush button on top.
pub(super) fn toilet(b: &Blank) -> Built {
    let (h, min, max) = (b.h, b.min, b.max);
    let seat = 0.42f32.min(h * 0.6);
    let mut parts = vec![span(
        v(-0.12, min.y + 0.1, 0.0),
        v(0.12, max.y - 0.2, seat - 0.15),
    )];
    parts.extend(tub(
        v(min.x, min.y, seat - 0.15),
        v(max.x, max.y - 0.18, seat),
        0.02,
    ));
    parts.push(span(v(min.x, max.y - 0.18, 0.0), v(max.x, max.y, h)));
    let mut built = b.body(parts);
    built.layout.front_button = v(max.x - 0.03, max.y - 0.09, h + 0.01);
    built
}
