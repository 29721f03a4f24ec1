//! Laying a program out: each plan family cuts its outline into bands (rows along the front, a
//! column behind a hall, a wing) and halls, and each band into its rooms side by side, every room
//! as deep as its band. A band's depth is drawn from those every room in it can take (at least
//! each one's shortest side, at most what keeps the smallest from being narrower than its own);
//! bands that must line up share a length that all can take, and within a band the rooms get
//! the widths their drawn areas ask for, stretched or shrunk together within their ranges to fill
//! it. So every room meets its type's specification by construction, and a draw with no common
//! depth or length is drawn again. Every cut falls on a 10 cm grid, so rooms that share a wall
//! share its coordinate exactly. Rooms are laid out as rectangles; `lshape.rs` may then
//! bend a pair of them.

use super::footprint::Rect;
use super::program::{Family, Want, Zone, chance, room_spec, zone};
use behavior_core::RoomType;
use behavior_core::rng::uniform;
use rand_chacha::ChaCha8Rng;

/// The rooms of a laid-out home, halls included: each room's type and rectangle.
pub(super) type Layout = Vec<(RoomType, Rect)>;

/// A length rounded to the 10 cm grid.
fn snap(v: f32) -> f32 {
    (v * 10.0).round() / 10.0
}

fn size(r: &Rect, axis: usize) -> f32 {
    r.max[axis] - r.min[axis]
}

/// The depths a band of these rooms side by side can have (each room as deep as the band): at
/// least every room's shortest side, at most the depth at which the smallest of them would have
/// to be narrower than its shortest side.
fn depths(wants: &[Want]) -> Option<[f32; 2]> {
    let lo = wants
        .iter()
        .map(|w| room_spec(w.kind).min_side)
        .fold(0.0, f32::max);
    let hi = wants
        .iter()
        .map(|w| {
            let s = room_spec(w.kind);
            s.area[1] / s.min_side
        })
        .fold(f32::MAX, f32::min);
    (lo + 0.1 <= hi - 0.1).then_some([lo + 0.1, hi - 0.1])
}

/// Each room's width range in a band of `depth`: its shortest side and its area range, with
/// 10 cm kept from each bound for rounding to the grid.
fn widths(wants: &[Want], depth: f32) -> Option<Vec<[f32; 2]>> {
    wants
        .iter()
        .map(|w| {
            let s = room_spec(w.kind);
            let lo = s.min_side.max(s.area[0] / depth) + 0.1;
            let hi = s.area[1] / depth - 0.1;
            (lo <= hi).then_some([lo, hi])
        })
        .collect()
}

/// The lengths a band of these rooms at `depth` can have.
fn lengths(wants: &[Want], depth: f32) -> Option<[f32; 2]> {
    let w = widths(wants, depth)?;
    Some([w.iter().map(|r| r[0]).sum(), w.iter().map(|r| r[1]).sum()])
}

/// The rooms' widths in a band of `depth` and `length`: each as its drawn area asks, then all
/// stretched or shrunk within their ranges until they fill the length.
fn fill(wants: &[Want], depth: f32, length: f32) -> Option<Vec<f32>> {
    let ranges = widths(wants, depth)?;
    let asked: Vec<f32> = wants
        .iter()
        .zip(&ranges)
        .map(|(w, r)| (w.area / depth).clamp(r[0], r[1]))
        .collect();
    let sum: f32 = asked.iter().sum();
    let room: Vec<f32> = asked
        .iter()
        .zip(&ranges)
        .map(|(a, r)| if length > sum { r[1] - a } else { a - r[0] })
        .collect();
    let slack: f32 = room.iter().sum();
    let need = (length - sum).abs();
    if need > slack + 1e-4 {
        return None;
    }
    let share = if slack > 0.0 { need / slack } else { 0.0 };
    let sign = if length > sum { 1.0 } else { -1.0 };
    Some(
        asked
            .iter()
            .zip(&room)
            .map(|(a, r)| a + sign * r * share)
            .collect(),
    )
}

/// `v` on the 10 cm grid within `[lo, hi]`, if the grid has a point there.
fn on_grid(v: f32, lo: f32, hi: f32) -> Option<f32> {
    let (lo, hi) = ((lo * 10.0).ceil() / 10.0, (hi * 10.0).floor() / 10.0);
    (lo <= hi + 1e-4).then(|| snap(v).clamp(lo, hi))
}

/// A band's depth drawn from its possible ones.
fn draw_depth(wants: &[Want], rng: &mut ChaCha8Rng) -> Option<f32> {
    let [lo, hi] = depths(wants)?;
    on_grid(uniform(rng, lo, hi), lo, hi)
}

/// A length every one of the bands can take, as near their rooms' drawn areas as may be.
fn common_length(bands: &[(&[Want], f32)]) -> Option<f32> {
    let (mut lo, mut hi, mut asked) = (0.0f32, f32::MAX, 0.0f32);
    for (wants, depth) in bands {
        let [a, b] = lengths(wants, *depth)?;
        lo = lo.max(a);
        hi = hi.min(b);
        asked = asked.max(total(wants) / depth);
    }
    on_grid(asked, lo, hi)
}

/// The band `rect` cut along `axis` into these rooms at the widths [`fill`] gives them.
fn band(wants: &[Want], rect: Rect, axis: usize) -> Option<Layout> {
    let depth = size(&rect, 1 - axis);
    let widths = fill(wants, depth, size(&rect, axis))?;
    Some(placed(wants, slice(rect, axis, &widths)))
}

/// A band of these rooms at `depth` as long as they ask for.
fn free_length(wants: &[Want], depth: f32) -> Option<f32> {
    common_length(&[(wants, depth)])
}

/// `rect` cut into pieces side by side along `axis` (0: x, 1: y), sized in proportion to
/// `weights`; the last piece ends where `rect` does.
fn slice(rect: Rect, axis: usize, weights: &[f32]) -> Vec<Rect> {
    let total: f32 = weights.iter().sum();
    let (lo, hi) = (rect.min[axis], rect.max[axis]);
    let mut pieces = Vec::with_capacity(weights.len());
    let (mut start, mut sum) = (lo, 0.0);
    for (k, w) in weights.iter().enumerate() {
        sum += w;
        let end = if k + 1 == weights.len() {
            hi
        } else {
            snap(lo + (hi - lo) * sum / total)
        };
        let mut piece = rect;
        piece.min[axis] = start;
        piece.max[axis] = end;
        pieces.push(piece);
        start = end;
    }
    pieces
}

/// The program split by zone, each in program order.
struct Zones {
    public: Vec<Want>,
    private: Vec<Want>,
    service: Vec<Want>,
}

impl Zones {
    fn of(wants: &[Want]) -> Zones {
        let pick = |z: Zone| {
            wants
                .iter()
                .copied()
                .filter(|w| zone(w.kind) == z)
                .collect()
        };
        Zones {
            public: pick(Zone::Public),
            private: pick(Zone::Private),
            service: pick(Zone::Service),
        }
    }
}

fn total(wants: &[Want]) -> f32 {
    wants.iter().map(|w| w.area).sum()
}

fn rect(min: [f32; 2], max: [f32; 2]) -> Rect {
    Rect { min, max }
}

/// The rooms `wants` placed in `pieces`, in order.
fn placed(wants: &[Want], pieces: Vec<Rect>) -> Layout {
    wants.iter().map(|w| w.kind).zip(pieces).collect()
}

/// The public rooms in a row for an open space: living, dining, kitchen, or the other way round,
/// so that the dining room lies between the other two.
fn public_row(public: &[Want], rng: &mut ChaCha8Rng) -> Vec<Want> {
    let mut row = public.to_vec();
    row.sort_by_key(|w| match w.kind {
        RoomType::LivingRoom => 0,
        RoomType::DiningRoom => 1,
        _ => 2,
    });
    if chance(rng, 0.5) {
        row.reverse();
    }
    row
}

/// A hall's width, m.
fn hall_width(rng: &mut ChaCha8Rng) -> f32 {
    snap(uniform(rng, 1.4, 1.8))
}

/// Lays out a program as a home of `family`; `None` when the draw gives no usable layout (the
/// caller draws again).
pub(super) fn lay_out(family: Family, wants: &[Want], rng: &mut ChaCha8Rng) -> Option<Layout> {
    let (garage, rest): (Vec<Want>, Vec<Want>) =
        wants.iter().partition(|w| w.kind == RoomType::Garage);
    let zones = Zones::of(&rest);
    let mut layout = match family {
        Family::Studio => studio(&zones, rng),
        Family::OpenPlan => open_plan(&zones, rng),
        Family::CentralHall => central_hall(&zones, rng),
        Family::LShaped => l_shaped(&zones, rng),
        Family::TwoWings => two_wings(&zones, rng),
        Family::Corridor => corridor(&zones, rng),
    }?;
    if let Some(garage) = garage.first() {
        layout.push(attached(garage, &layout, rng)?);
    }
    let mirrored = chance(rng, 0.5);
    let layout: Layout = if mirrored { mirror(layout) } else { layout };
    layout
        .iter()
        .all(|(kind, r)| fits(*kind, r))
        .then_some(layout)
}

/// An attached garage: a block of its own against the house's west end, from the front, as
/// near square as its area allows (its rooms' bands are too shallow for a car turned any way).
fn attached(garage: &Want, layout: &Layout, rng: &mut ChaCha8Rng) -> Option<(RoomType, Rect)> {
    let s = room_spec(RoomType::Garage);
    let (west, _) = west_and_east(layout);
    let side = on_grid(uniform(rng, s.min_side, 6.2), s.min_side, 6.2)?;
    let depth = on_grid(garage.area / side, s.min_side, s.area[1] / side)?;
    Some((RoomType::Garage, rect([west - side, 0.0], [west, depth])))
}

/// Whether a room's rectangle meets its type's specification.
fn fits(kind: RoomType, r: &Rect) -> bool {
    let s = room_spec(kind);
    let (w, d) = (size(r, 0), size(r, 1));
    let area = w * d;
    w.min(d) >= s.min_side - 1e-3 && (s.area[0] - 1e-3..=s.area[1] + 1e-3).contains(&area)
}

/// The x of the layout's west and east edges.
fn west_and_east(layout: &Layout) -> (f32, f32) {
    layout.iter().fold((f32::MAX, f32::MIN), |(w, e), (_, r)| {
        (w.min(r.min[0]), e.max(r.max[0]))
    })
}

/// The layout turned over west for east, then moved back to start at x = 0.
fn mirror(layout: Layout) -> Layout {
    let (west, east) = west_and_east(&layout);
    layout
        .into_iter()
        .map(|(k, r)| {
            let min = [snap(east + west - r.max[0]), r.min[1]];
            let max = [snap(east + west - r.min[0]), r.max[1]];
            (k, rect(min, max))
        })
        .collect()
}

/// A living room along the front with the bedroom, if there is one, beside it; behind them the
/// kitchen, open onto the living room, the bathroom and the closet.
fn studio(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let (front, back): (Vec<Want>, Vec<Want>) = z
        .public
        .iter()
        .chain(&z.private)
        .partition(|w| matches!(w.kind, RoomType::LivingRoom | RoomType::Bedroom));
    let (a, b) = (draw_depth(&front, rng)?, draw_depth(&back, rng)?);
    let width = common_length(&[(&front, a), (&back, b)])?;
    let mut layout = band(&front, rect([0.0, 0.0], [width, a]), 0)?;
    layout.extend(band(&back, rect([0.0, a], [width, a + b]), 0)?);
    Some(layout)
}

/// The public rooms in a row along the front; behind them the private and service rooms in a
/// row, along a hall where there are four or more, else opening off the public rooms.
fn open_plan(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let back: Vec<Want> = z.private.iter().chain(&z.service).copied().collect();
    let row = public_row(&z.public, rng);
    let (front, deep) = (draw_depth(&row, rng)?, draw_depth(&back, rng)?);
    let width = common_length(&[(&row, front), (&back, deep)])?;
    let mut layout = band(&row, rect([0.0, 0.0], [width, front]), 0)?;
    let mut y = front;
    if back.len() >= 4 {
        let h = hall_width(rng);
        layout.push((RoomType::Corridor, rect([0.0, y], [width, y + h])));
        y += h;
    }
    layout.extend(band(&back, rect([0.0, y], [width, y + deep]), 0)?);
    Some(layout)
}

/// A hall through the middle from the front: the public and service rooms one behind the other
/// on one side, the private rooms on the other.
fn central_hall(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let mut west_rooms = public_row(&z.public, rng);
    if west_rooms[0].kind != RoomType::LivingRoom {
        west_rooms.reverse(); // the living room by the front door
    }
    west_rooms.extend(z.service.iter().copied());
    let (west, east) = (draw_depth(&west_rooms, rng)?, draw_depth(&z.private, rng)?);
    let depth = common_length(&[(&west_rooms, west), (&z.private, east)])?;
    let h = snap(uniform(rng, 1.8, 2.2));
    let mut layout = band(&west_rooms, rect([0.0, 0.0], [west, depth]), 1)?;
    let x = west + h;
    layout.extend(band(&z.private, rect([x, 0.0], [x + east, depth]), 1)?);
    layout.push((RoomType::Corridor, rect([west, 0.0], [x, depth])));
    Some(layout)
}

/// The service and public rooms in a row along the front; at the living room's end a wing of
/// private rooms going back along a hall that opens onto the public rooms: on the hall's inner
/// side only, or on both sides where there are four or more.
fn l_shaped(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let mut row: Vec<Want> = z.service.clone();
    let mut public = public_row(&z.public, rng);
    if public[0].kind == RoomType::LivingRoom {
        public.reverse(); // the living room at the east end, where the wing is
    }
    row.extend(public);
    let depth = draw_depth(&row, rng)?;
    let length = free_length(&row, depth)?;
    let mut layout = band(&row, rect([0.0, 0.0], [length, depth]), 0)?;
    let h = hall_width(rng);
    // Rooms alternate between the hall's sides, so each side is about as long.
    let (inner, outer): (Vec<Want>, Vec<Want>) = if z.private.len() >= 4 {
        let (a, b): (Vec<_>, Vec<_>) = z.private.iter().enumerate().partition(|(k, _)| k % 2 == 0);
        (
            a.into_iter().map(|p| *p.1).collect(),
            b.into_iter().map(|p| *p.1).collect(),
        )
    } else {
        (z.private.clone(), Vec::new())
    };
    let a = draw_depth(&inner, rng)?;
    let b = if outer.is_empty() {
        0.0
    } else {
        draw_depth(&outer, rng)?
    };
    let wing = if outer.is_empty() {
        free_length(&inner, a)?
    } else {
        common_length(&[(&inner, a), (&outer, b)])?
    };
    if a + h + b > length {
        return None;
    }
    let (x0, x1) = (length - b - h - a, length - b - h);
    let top = depth + wing;
    layout.extend(band(&inner, rect([x0, depth], [x1, top]), 1)?);
    layout.push((RoomType::Corridor, rect([x1, depth], [x1 + h, top])));
    if !outer.is_empty() {
        layout.extend(band(&outer, rect([x1 + h, depth], [length, top]), 1)?);
    }
    Some(layout)
}

/// A public block in the middle (the living room along the front, dining room and kitchen
/// behind it); west of it the main bedroom with its bathroom and a closet behind it; east of it
/// a hall with the other rooms along it.
fn two_wings(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let living: Vec<Want> = z
        .public
        .iter()
        .filter(|w| w.kind == RoomType::LivingRoom)
        .copied()
        .collect();
    let back: Vec<Want> = z
        .public
        .iter()
        .filter(|w| w.kind != RoomType::LivingRoom)
        .copied()
        .collect();
    let (front, behind_depth) = (draw_depth(&living, rng)?, draw_depth(&back, rng)?);
    let width = common_length(&[(&living, front), (&back, behind_depth)])?;
    let depth = front + behind_depth;
    let mut layout = band(&living, rect([0.0, 0.0], [width, front]), 0)?;
    layout.extend(band(&back, rect([0.0, front], [width, depth]), 0)?);
    // The suite: the first bedroom, the first bathroom and the closet if there is one.
    let mut others: Vec<Want> = z.private.iter().chain(&z.service).copied().collect();
    let mut take = |kind: RoomType| {
        let k = others.iter().position(|w| w.kind == kind)?;
        Some(others.remove(k))
    };
    let bedroom = vec![take(RoomType::Bedroom)?];
    let mut behind = vec![take(RoomType::Bathroom)?];
    behind.extend(take(RoomType::Closet));
    let (bed, back_suite) = (draw_depth(&bedroom, rng)?, draw_depth(&behind, rng)?);
    let suite = common_length(&[(&bedroom, bed), (&behind, back_suite)])?;
    layout.extend(band(&bedroom, rect([-suite, 0.0], [0.0, bed]), 0)?);
    let top = bed + back_suite;
    layout.extend(band(&behind, rect([-suite, bed], [0.0, top]), 0)?);
    let h = hall_width(rng);
    let column = draw_depth(&others, rng)?;
    let wing = free_length(&others, column)?;
    let (x0, x1) = (width + h, width + h + column);
    layout.extend(band(&others, rect([x0, 0.0], [x1, wing]), 1)?);
    layout.push((RoomType::Corridor, rect([width, 0.0], [x0, wing])));
    Some(shifted(layout))
}

/// The layout moved so that its west edge is at x = 0.
fn shifted(layout: Layout) -> Layout {
    let (west, _) = west_and_east(&layout);
    layout
        .into_iter()
        .map(|(k, r)| {
            let min = [snap(r.min[0] - west), r.min[1]];
            let max = [snap(r.max[0] - west), r.max[1]];
            (k, rect(min, max))
        })
        .collect()
}

/// A corridor the length of the house: the public and service rooms in a row along its south
/// side, the private rooms along its north side, both rows as long as the corridor.
fn corridor(z: &Zones, rng: &mut ChaCha8Rng) -> Option<Layout> {
    let south: Vec<Want> = public_row(&z.public, rng)
        .into_iter()
        .chain(z.service.iter().copied())
        .collect();
    let north = z.private.clone();
    let (ds, dn) = (draw_depth(&south, rng)?, draw_depth(&north, rng)?);
    let length = common_length(&[(&south, ds), (&north, dn)])?;
    let h = hall_width(rng);
    let mut layout = band(&south, rect([0.0, 0.0], [length, ds]), 0)?;
    let y = ds + h;
    layout.extend(band(&north, rect([0.0, y], [length, y + dn]), 0)?);
    layout.push((RoomType::Corridor, rect([0.0, ds], [length, y])));
    Some(layout)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn want(kind: RoomType, area: f32) -> Want {
        Want { kind, area }
    }

    #[test]
    fn a_band_fills_its_length_with_rooms_within_their_specification() {
        let rooms = [
            want(RoomType::Bedroom, 14.0),
            want(RoomType::Bathroom, 8.0),
            want(RoomType::Closet, 4.0),
        ];
        let [lo, hi] = depths(&rooms).expect("a bedroom, a bathroom and a closet share a band");
        let closet = room_spec(RoomType::Closet);
        assert!(
            lo >= 3.0 && hi <= closet.area[1] / closet.min_side,
            "depths {lo}..{hi}"
        );
        let depth = 3.5;
        let [shortest, longest] = lengths(&rooms, depth).unwrap();
        for length in [shortest, (shortest + longest) / 2.0, longest] {
            let length = (length * 10.0).round() / 10.0;
            let length = length.clamp(shortest, longest);
            let Some(layout) = band(&rooms, rect([0.0, 0.0], [length, depth]), 0) else {
                continue; // rounded out of range at an end
            };
            let end = layout.last().unwrap().1.max[0];
            assert_eq!(end, length, "the band ends where its rectangle does");
            for (kind, r) in &layout {
                assert!(fits(*kind, r), "{kind} {r:?} at length {length}");
            }
        }
        // Too deep for a closet: no band.
        assert!(widths(&rooms, 4.5).is_none());
    }
}
