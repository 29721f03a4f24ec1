//! Where an action sends each part: the targets of the step, composed as the original does
//! (iGibson 2.0.3's `robots/behavior_robot.py`), clipped to the reach spheres, and kept out of
//! fixed things.
//!
//! - The body's Δ is in its own frame and right-multiplied: `new = old · Δ`.
//! - The eye's and hands' targets live in the body frame; their Δ position is added there and
//!   their Δ rotation left-multiplied (`new = Δ · old`). When the body moves, they come along.
//! - A hand's target is projected into the sphere of [`crate::HAND_REACH`] around its shoulder,
//!   the eye's into that of [`crate::EYE_REACH`] around the neck.
//! - Triggers add their Δ and stay in [0, 1].
//!
//! The original's parts are pulled by force-limited constraints, which walls and tables stop.
//! Our body is kinematic and would go through them, and our palms' servo would press into them
//! with its full 300 N; so a part's new target is refused when its shape there would overlap a
//! fixed body it does not already overlap (so a part that starts inside something can still move
//! out): the body then stays, a hand keeps its previous target in the body frame, and if even
//! that is blocked (the body carrying the hand into a table) the body stays too. A hand's shape
//! here is its palm with the fingers straight. One shape query per moving part and step; none at
//! rest. Movable things (and the doors and drawers of furniture) do not block: they are pushed.
//!
//! The original rounds new poses to 5 decimals (a VR convenience); we do not.

use crate::action::{Action, Delta};
use crate::body::{EYE_REACH, HAND_REACH, NECK, body_shape, shoulder, within};
use crate::hand::{Side, sweep_shape};
use behavior_sim::{BodyRef, Primitive, QueryFilter, World};
use rapier3d::math::Pose;

/// What the robot is told to do by the end of the step.
#[derive(serde::Serialize, serde::Deserialize, Clone, Copy, Debug, PartialEq)]
pub(crate) struct Targets {
    /// The body, in the world.
    pub(crate) body: Pose,
    /// The eye, in the body frame.
    pub(crate) eye: Pose,
    /// The hands (left, right), in the body frame.
    pub(crate) hands: [Pose; 2],
    /// The trigger fractions (left, right), in [0, 1].
    pub(crate) triggers: [f32; 2],
}

impl Targets {
    /// The targets an action asks for, before any check against the world.
    pub(crate) fn after(&self, action: &Action) -> Targets {
        let hand = |side: Side| {
            let old = self.hands[side.index()];
            local_after(old, action.hand(side), |p| {
                within(p, shoulder(side), HAND_REACH)
            })
        };
        let trigger =
            |side: Side| (self.triggers[side.index()] + action.trigger(side)).clamp(0.0, 1.0);
        Targets {
            body: body_after(self.body, action.body()),
            eye: local_after(self.eye, action.eye(), |p| within(p, NECK, EYE_REACH)),
            hands: [hand(Side::Left), hand(Side::Right)],
            triggers: [trigger(Side::Left), trigger(Side::Right)],
        }
    }

    /// A hand's target in the world.
    pub(crate) fn hand_in_world(&self, side: Side) -> Pose {
        self.body * self.hands[side.index()]
    }
}

fn body_after(body: Pose, delta: Delta) -> Pose {
    let translation = body.translation + body.rotation * delta.translation;
    Pose::from_parts(translation, (body.rotation * delta.rotation).normalize())
}

fn local_after(
    local: Pose,
    delta: Delta,
    clip: impl Fn(rapier3d::math::Vector) -> rapier3d::math::Vector,
) -> Pose {
    let translation = clip(local.translation + delta.translation);
    Pose::from_parts(translation, (delta.rotation * local.rotation).normalize())
}

/// Refuses moves into fixed bodies (see the module docs).
pub(crate) struct Blocker<'a> {
    pub(crate) world: &'a World,
    /// The robot's own objects, which never block it.
    pub(crate) filter: QueryFilter,
}

impl Blocker<'_> {
    /// The fixed bodies a shape (at `offset` in a part's frame) overlaps with the part at `pose`.
    fn fixed_overlaps(&self, shape: &(Primitive, Pose), pose: Pose) -> Vec<BodyRef> {
        let fixed =
            |b: &BodyRef| b.link.is_none() && self.world.bodies().object(b.object).is_fixed();
        // A pose built from finite targets is finite, so the query cannot fail.
        let hits = self
            .world
            .query()
            .overlaps(&shape.0, pose * shape.1, &self.filter);
        hits.unwrap_or_default().into_iter().filter(fixed).collect()
    }

    /// Whether moving a part from `from` to `to` enters a fixed body.
    pub(crate) fn blocked(&self, shape: &(Primitive, Pose), from: Pose, to: Pose) -> bool {
        if from == to {
            return false;
        }
        let after = self.fixed_overlaps(shape, to);
        if after.is_empty() {
            return false;
        }
        let before = self.fixed_overlaps(shape, from);
        after.iter().any(|b| !before.contains(b))
    }

    /// The targets `wanted` as far as fixed bodies let them be, starting from `old`.
    pub(crate) fn allow(&self, old: &Targets, wanted: Targets) -> Targets {
        let body = (body_shape(), Pose::IDENTITY);
        let mut out = wanted;
        if self.blocked(&body, old.body, wanted.body) {
            out.body = old.body;
        }
        let hand = sweep_shape();
        for side in Side::BOTH {
            let i = side.index();
            let from = old.hand_in_world(side);
            if !self.blocked(&hand, from, out.body * wanted.hands[i]) {
                continue;
            }
            out.hands[i] = old.hands[i];
            if self.blocked(&hand, from, out.body * old.hands[i]) {
                // The body would carry this hand into something: it stays, and so do the hands.
                out.body = old.body;
                return self.hands_only(old, out);
            }
        }
        out
    }

    /// With the body where it was, each hand moves unless that is blocked.
    fn hands_only(&self, old: &Targets, mut out: Targets) -> Targets {
        let hand = sweep_shape();
        for side in Side::BOTH {
            let i = side.index();
            let from = old.hand_in_world(side);
            if self.blocked(&hand, from, old.body * out.hands[i]) {
                out.hands[i] = old.hands[i];
            }
        }
        out
    }
}
