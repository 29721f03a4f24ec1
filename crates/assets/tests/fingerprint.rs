//! Fingerprints of what this crate generates, so that a refactoring can show it changed nothing:
//! a SHA-256 over the scene JSON of the named homes (and of homes of free seeds, which draw their
//! extra rooms at random), and one over every catalog archetype built in every variant at a few
//! sizes, with its layout, its halves and the named points the library adds.
//!
//! A change that is meant to alter homes or objects changes these; re-record them then (the
//! failure message prints the new value) and say so in the commit. The object fingerprint formats
//! the geometry field by field rather than `ObjectSpec`'s `Debug`, so a new field in
//! `behavior-sim` does not disturb it.

use behavior_assets::CATALOG;
use behavior_assets::Layout;
use behavior_assets::{Library, NAMED_HOMES, generate};
use behavior_data::DataDir;
use behavior_sim::{LinkSpec, ObjectSpec, Part};
use rapier3d::math::Vector;
use sha2::{Digest, Sha256};
use std::fmt::Write;

fn taxonomy() -> behavior_bddl::Taxonomy {
    let data = DataDir::locate(None, |m| eprintln!("{m}")).unwrap();
    behavior_bddl::load::read_taxonomy(&data.taxonomy_path()).unwrap()
}

fn hex(digest: &[u8]) -> String {
    digest.iter().map(|b| format!("{b:02x}")).collect()
}

/// The SHA-256 of the named homes' JSON, in order, then of homes `free_1` … `free_20`. Changed on
/// purpose in issue 40: every home is laid out from one of six plan families and furnished by
/// the new rules, and the named homes were chosen again among them (before that, the named homes
/// were shown to keep their corridor plan byte for byte through the change to one plan type);
/// and again in issue 40: rugs under tables and beds, L-shaped rooms, sill-height windows but in
/// living and dining rooms, beds under sills but for their headboards (a single bed where a
/// double fits nowhere), dining tables of a dining table's size, chairs only round a table (two
/// to a side where it is long enough), and shallower passages through openings.
const HOMES: &str = "db77f94111634b60c55e0c08187f77983bc6960dd4007c1011375d2e5823ffbc";

/// The SHA-256 over every archetype × variant × size (see `objects_are_unchanged`). Changed on
/// purpose in issue 10: knives got real masses (densities 700 and 1500 kg/m³, `knife.n.01` at
/// least 20 cm long), so that they cut by being pushed; and in issue 13: printers, vacuum
/// cleaners and potted plants got the masses of real ones (at most 9.5, 9.2 and 9.2 kg, within
/// the hand's 10 kg), where solid boxes of their size had weighed up to 61 kg; and in issue 38: a
/// bed's mattress part got a look of its own (cloth in the bed's colour, the duvet it is drawn
/// with), its geometry and every other field unchanged; and again in issue 38: microwaves white
/// and ovens stainless (colours only), whose near-black hid their doors' dark windows; and again
/// in issue 38: a window's casement got a look of its own (pale glass; the frame keeps the
/// archetype's), so that it is drawn glazed and lets the sun through, its geometry and every
/// other field unchanged; and in issue 40: a fax machine got the density of a hollow casing
/// (250 kg/m³, 2–7 kg), where a solid 700 kg/m³ box weighed up to 21 kg, over the hand's 10 kg;
/// and in issue 42: side-hinged and drop-down doors end 5 mm short of their carcass at their free
/// edge (`DOOR_GAP`), so that a door flush with a deeper neighbour swings past its corner when a
/// hand pulls it; and again in issue 42: every movable archetype people carry weighs at most
/// the hand's 10 kg (effective densities for hollow or airy things — lamps, boxes, bins, pots,
/// pans — where solid or thick-walled shapes had weighed up to 76 kg; plywood boards at most
/// 0.9 m square), checked by `what_people_carry_is_light_enough_for_the_assisted_grasp`, and a
/// small seat (`seat.n.03`) is a movable `Stool`.
const OBJECTS: &str = "4f326353125d5cba48817c2eef703e01fd9b6ffbe59adf4c57aa9fe514f65b1b";

#[test]
fn homes_are_unchanged() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut hash = Sha256::new();
    let free = (1..=20).map(|seed| ("free", seed));
    for (name, seed) in NAMED_HOMES.into_iter().chain(free) {
        let scene = generate(name, seed, &library).unwrap();
        hash.update(scene.to_json().as_bytes());
        hash.update(b"\n");
    }
    let digest = hex(&hash.finalize());
    assert_eq!(
        digest, HOMES,
        "the homes changed: their fingerprint is now {digest}"
    );
}

fn write_parts(out: &mut String, parts: &[Part]) {
    for p in parts {
        writeln!(
            out,
            "  part {:?} at {:?} look {:?}",
            p.primitive, p.offset, p.visual
        )
        .unwrap();
    }
}

fn write_link(out: &mut String, l: &LinkSpec) {
    let j = &l.joint;
    writeln!(
        out,
        " link {} parent {:?} density {:?} joint {:?} {:?} {:?} {:?} {:?} {:?}",
        l.name, l.parent, l.density, j.kind, j.model, j.anchor, j.axis, j.limits, j.damping
    )
    .unwrap();
    write_parts(out, &l.parts);
}

fn write_spec(out: &mut String, spec: &ObjectSpec) {
    writeln!(
        out,
        "{} {} {:?} {:?} {:?} {:?} {:?} {:?} {:?}",
        spec.name,
        spec.category,
        spec.pose,
        spec.body,
        spec.density,
        spec.friction,
        spec.angular_damping,
        spec.visual,
        spec.points
    )
    .unwrap();
    write_parts(out, &spec.parts);
    for l in &spec.links {
        write_link(out, l);
    }
    for (k, half) in spec.halves.iter().flatten().enumerate() {
        writeln!(out, " half {k}").unwrap();
        write_parts(out, half);
    }
    writeln!(
        out,
        " abilities {:?} meshes {}",
        spec.abilities.keys().collect::<Vec<_>>(),
        spec.meshes.len()
    )
    .unwrap();
}

#[test]
fn objects_are_unchanged() {
    let taxonomy = taxonomy();
    let library = Library::new(&taxonomy);
    let mut hash = Sha256::new();
    for a in CATALOG {
        let (lo, hi) = (Vector::from_array(a.min), Vector::from_array(a.max));
        // The smallest, the largest, one between, one too large and one too small to build as is.
        let sizes = [lo, hi, lo * 0.3 + hi * 0.7, hi * 1.5, Vector::splat(0.001)];
        // One variant past the last, which wraps around.
        for variant in 0..=a.shape.variants() {
            for size in sizes {
                let mut out = String::new();
                let (spec, layout): (ObjectSpec, Layout) = a.build("x", size, variant);
                write_spec(&mut out, &spec);
                writeln!(out, " layout {layout:?}").unwrap();
                for (k, half) in a.halves(size, variant).iter().enumerate() {
                    writeln!(out, " own half {k}").unwrap();
                    write_parts(&mut out, half);
                }
                write_spec(
                    &mut out,
                    &library.instance_of(a, a.synset, "y", size, variant),
                );
                hash.update(out.as_bytes());
            }
        }
    }
    let digest = hex(&hash.finalize());
    assert_eq!(
        digest, OBJECTS,
        "the objects changed: their fingerprint is now {digest}"
    );
}
