//! Doors and windows: a frame in the x–z plane (y is the wall's thickness) and a leaf on a hinge
//! at the frame's left side, opening to −y.

use super::geometry::{span, v};
use super::{Blank, Built};
use behavior_sim::{Form, JointKind, JointSpec, LinkSpec, Material, Visual};

/// A window's pane: pale, clear glass (the frame keeps the archetype's look). Drawn as glass, it
/// lets the sun through into the room.
const PANE: Visual = Visual {
    color: [190, 215, 235],
    material: Material::Glass,
};

/// A door: the frame stands on the floor; the leaf is drawn with its handle.
pub(super) fn door(b: &Blank) -> Built {
    framed_leaf(b, 0.0, b.h, Form::Door, None)
}

/// A window with a sill at 0.9 m (variant 0), or a floor-length one from 5 cm up and 0.85 m
/// taller than its size says (variant 1).
pub(super) fn window(b: &Blank) -> Built {
    if b.variant == 0 {
        framed_leaf(b, 0.9, b.h, Form::Primitive, Some(PANE))
    } else {
        framed_leaf(b, 0.05, b.h + 0.85, Form::Primitive, Some(PANE))
    }
}

/// A frame of height `h` from `sill` up, and its leaf (drawn as `leaf_form`, or as the
/// archetype's looks say if that is [`Form::Primitive`], in `leaf_look` where given, else the
/// archetype's); the button (a handle) at mid-height by the leaf's free edge.
fn framed_leaf(b: &Blank, sill: f32, h: f32, leaf_form: Form, leaf_look: Option<Visual>) -> Built {
    let (d, min, max) = (b.d, b.min, b.max);
    let frame = 0.05;
    let parts = vec![
        span(v(min.x, min.y, sill), v(min.x + frame, max.y, sill + h)),
        span(v(max.x - frame, min.y, sill), v(max.x, max.y, sill + h)),
        span(v(min.x, min.y, sill + h - frame), v(max.x, max.y, sill + h)),
    ];
    let mut pane = span(
        v(min.x + frame, min.y + d / 4.0, sill + 0.01),
        v(max.x - frame, max.y - d / 4.0, sill + h - frame),
    )
    .with_form(leaf_form);
    if let Some(look) = leaf_look {
        pane = pane.with_visual(look);
    }
    let leaf = LinkSpec {
        name: "leaf".into(),
        parts: vec![pane],
        parent: None,
        joint: JointSpec::opening(
            JointKind::Revolute,
            v(min.x + frame, 0.0, 0.0),
            v(0.0, 0.0, -1.0),
            1.6,
            2.0,
        ),
        density: b.density,
    };
    let mut built = b.body(parts).with_link(leaf);
    built.layout.front_button = v(max.x - frame - 0.05, min.y - 0.01, sill + h * 0.5);
    built
}
