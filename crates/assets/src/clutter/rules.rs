//! What clutter goes where: for each room type, which things lie on, in or beside which
//! furniture, and how much of it they may cover.
//!
//! A rule's `fill` is the summed footprint of the things it places, as a fraction of the
//! furniture's footprint (all levels together: a shelf's boards, a cabinet's shelf and bottom,
//! a fridge's two compartments). Surfaces that activities often use (countertops, tables) get
//! little, storage (shelves, cabinets, the fridge) more, floors a few things beside furniture
//! only, so that the middle of each room and the corridor stay free for the agent and for large
//! activity objects (plywood, a pool). Only things without moving parts are listed: a lid's
//! position is not part of a [`crate::ClutterPlan`].

use behavior_core::RoomType;

/// Where a rule puts things relative to its furniture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Spot {
    /// On its top, or on one of its boards or seats.
    On,
    /// Inside it: on its floor, its shelf or in its drawers.
    In,
    /// On the room's floor, next to it.
    Beside,
}

/// Things of some synsets put on, in or beside furniture of one synset, up to a fill fraction.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rule {
    /// The furniture's synset.
    pub(crate) furniture: &'static str,
    /// Where the things go.
    pub(crate) spot: Spot,
    /// Their summed footprint as a fraction of the furniture's footprint.
    pub(crate) fill: f32,
    /// The synsets drawn from, uniformly; each is a catalog synset.
    pub(crate) items: &'static [&'static str],
}

const fn rule(
    furniture: &'static str,
    spot: Spot,
    fill: f32,
    items: &'static [&'static str],
) -> Rule {
    Rule {
        furniture,
        spot,
        fill,
        items,
    }
}

const FRIDGE: &[&str] = &[
    "apple.n.01",
    "orange.n.01",
    "lemon.n.01",
    "tomato.n.01",
    "lettuce.n.03",
    "broccoli.n.02",
    "carrot.n.03",
    "milk.n.01",
    "juice.n.01",
    "cheese.n.01",
    "egg.n.02",
    "yogurt.n.01",
    "beer.n.01",
    "water.n.06",
    "catsup.n.01",
    "sauce.n.01",
];
const DISHES: &[&str] = &[
    "plate.n.04",
    "bowl.n.01",
    "cup.n.01",
    "mug.n.04",
    "dish.n.01",
    "saucepan.n.01",
    "pan.n.01",
];
const PANTRY: &[&str] = &[
    "cereal.n.03",
    "pasta.n.02",
    "flour.n.01",
    "sugar.n.01",
    "oatmeal.n.01",
    "soup.n.01",
    "snack_food.n.01",
    "vegetable_oil.n.01",
];
const COUNTER: &[&str] = &[
    "kettle.n.01",
    "bowl.n.01",
    "bottle.n.01",
    "cleansing_agent.n.01",
    "dishtowel.n.01",
    "bread.n.01",
    "mug.n.04",
    "banana.n.02",
];
const DISHWASHER: &[&str] = &[
    "plate.n.04",
    "bowl.n.01",
    "cup.n.01",
    "mug.n.04",
    "fork.n.01",
    "spoon.n.01",
    "knife.n.01",
];
const OVEN: &[&str] = &["pan.n.01", "saucepan.n.01"];
const KITCHEN_TABLE: &[&str] = &[
    "bowl.n.01",
    "apple.n.01",
    "orange.n.01",
    "mug.n.04",
    "newspaper.n.03",
    "candle.n.01",
];
const DINING_TABLE: &[&str] = &[
    "plate.n.04",
    "bowl.n.01",
    "cup.n.01",
    "fork.n.01",
    "spoon.n.01",
    "knife.n.01",
    "candle.n.01",
    "pot_plant.n.01",
];
const BOOKSHELF: &[&str] = &[
    "book.n.02",
    "book.n.02",
    "hardback.n.01",
    "hardback.n.01",
    "pot_plant.n.01",
    "candle.n.01",
    "basket.n.01",
    "plaything.n.01",
];
const LIVING_CABINET: &[&str] = &[
    "book.n.02",
    "box.n.01",
    "candle.n.01",
    "document.n.01",
    "plaything.n.01",
    "newspaper.n.03",
];
const LIVING_TABLE: &[&str] = &[
    "newspaper.n.03",
    "book.n.02",
    "candle.n.01",
    "mug.n.04",
    "pot_plant.n.01",
    "notebook.n.01",
];
const TOYS: &[&str] = &["ball.n.01", "plaything.n.01", "basket.n.01"];
const CLOTHES: &[&str] = &[
    "shirt.n.01",
    "sweater.n.01",
    "sock.n.01",
    "underwear.n.01",
    "apparel.n.01",
    "towel.n.01",
    "sheet.n.03",
    "hat.n.01",
    "necklace.n.01",
    "bracelet.n.02",
];
const BED: &[&str] = &["sweater.n.01", "shirt.n.01", "book.n.02"];
const NIGHTSTAND: &[&str] = &[
    "lamp.n.02",
    "book.n.02",
    "alarm.n.02",
    "perfume.n.02",
    "makeup.n.01",
    "candle.n.01",
    "mug.n.04",
];
const SHOES: &[&str] = &["shoe.n.01", "sandal.n.01", "gym_shoe.n.01"];
const DESK: &[&str] = &[
    "printer.n.03",
    "notebook.n.01",
    "pen.n.01",
    "pencil.n.01",
    "marker.n.03",
    "mug.n.04",
    "book.n.02",
    "calculator.n.02",
    "mouse.n.04",
    "document.n.01",
    "envelope.n.01",
    "pencil_box.n.01",
];
const FILES: &[&str] = &[
    "document.n.01",
    "envelope.n.01",
    "notebook.n.01",
    "book.n.02",
    "pad.n.01",
    "pencil_box.n.01",
    "box.n.01",
];
const BIN: &[&str] = &["ashcan.n.01"];
const LAUNDRY: &[&str] = &[
    "towel.n.01",
    "shirt.n.01",
    "sock.n.01",
    "underwear.n.01",
    "sweater.n.01",
];
const CLEANING: &[&str] = &[
    "detergent.n.02",
    "cleansing_agent.n.01",
    "rag.n.01",
    "brush.n.02",
    "scrub_brush.n.01",
    "bottle.n.01",
    "hand_towel.n.01",
    "dishtowel.n.01",
];
const LAUNDRY_FLOOR: &[&str] = &["basket.n.01", "bucket.n.01"];
const BATHROOM_FLOOR: &[&str] = &["ashcan.n.01", "bucket.n.01"];
const GARAGE_SHELF: &[&str] = &[
    "box.n.01",
    "bucket.n.01",
    "hammer.n.02",
    "screwdriver.n.01",
    "saw.n.02",
    "cleansing_agent.n.01",
    "vessel.n.03",
    "bottle.n.01",
    "detergent.n.02",
];
const TOOLS: &[&str] = &[
    "hammer.n.02",
    "screwdriver.n.01",
    "saw.n.02",
    "scraper.n.01",
    "brush.n.02",
    "rag.n.01",
];
const GARAGE_FLOOR: &[&str] = &["bin.n.01", "bucket.n.01", "box.n.01", "ball.n.01"];
const STORAGE_SHELF: &[&str] = &[
    "box.n.01",
    "basket.n.01",
    "bucket.n.01",
    "bottle.n.01",
    "book.n.02",
    "plaything.n.01",
];
const STORAGE_TABLE: &[&str] = &["box.n.01", "basket.n.01", "book.n.02"];
const STORAGE_FLOOR: &[&str] = &["box.n.01", "bin.n.01"];
const CLOSET_SHELF: &[&str] = &[
    "sweater.n.01",
    "shirt.n.01",
    "hat.n.01",
    "box.n.01",
    "towel.n.01",
    "sheet.n.03",
    "shoe.n.01",
];
const CLOSET_FLOOR: &[&str] = &["shoe.n.01", "sandal.n.01", "gym_shoe.n.01", "umbrella.n.01"];

const KITCHEN: &[Rule] = &[
    rule("electric_refrigerator.n.01", Spot::In, 0.45, FRIDGE),
    rule("countertop.n.01", Spot::On, 0.12, COUNTER),
    rule("cabinet.n.01", Spot::In, 0.3, DISHES),
    rule("cabinet.n.01", Spot::In, 0.25, PANTRY),
    rule("dishwasher.n.01", Spot::In, 0.3, DISHWASHER),
    rule("oven.n.01", Spot::In, 0.15, OVEN),
    rule("table.n.02", Spot::On, 0.12, KITCHEN_TABLE),
    rule("countertop.n.01", Spot::Beside, 0.08, BIN),
];
const LIVING_ROOM: &[Rule] = &[
    rule("shelf.n.01", Spot::On, 1.0, BOOKSHELF),
    rule("cabinet.n.01", Spot::In, 0.55, LIVING_CABINET),
    rule("table.n.02", Spot::On, 0.1, LIVING_TABLE),
    rule("sofa.n.01", Spot::Beside, 0.03, TOYS),
];
const BEDROOM: &[Rule] = &[
    rule("bed.n.01", Spot::On, 0.04, BED),
    rule("cabinet.n.01", Spot::In, 0.55, CLOTHES),
    rule("table.n.02", Spot::On, 0.15, NIGHTSTAND),
    rule("bed.n.01", Spot::Beside, 0.05, SHOES),
];
const BATHROOM: &[Rule] = &[
    rule("toilet.n.02", Spot::Beside, 0.3, BATHROOM_FLOOR),
    rule("bathtub.n.01", Spot::Beside, 0.03, &["towel.n.01"]),
];
const DINING_ROOM: &[Rule] = &[rule("table.n.02", Spot::On, 0.22, DINING_TABLE)];
const GARAGE: &[Rule] = &[
    rule("shelf.n.01", Spot::On, 1.0, GARAGE_SHELF),
    rule("cabinet.n.01", Spot::In, 0.55, TOOLS),
    rule("shelf.n.01", Spot::Beside, 0.4, GARAGE_FLOOR),
];
const HOME_OFFICE: &[Rule] = &[
    rule("cabinet.n.01", Spot::In, 0.55, FILES),
    rule("table.n.02", Spot::On, 0.2, DESK),
    rule("table.n.02", Spot::Beside, 0.06, BIN),
];
const STORAGE_ROOM: &[Rule] = &[
    rule("shelf.n.01", Spot::On, 1.0, STORAGE_SHELF),
    rule("table.n.02", Spot::On, 0.2, STORAGE_TABLE),
    rule("shelf.n.01", Spot::Beside, 0.4, STORAGE_FLOOR),
];
const UTILITY_ROOM: &[Rule] = &[
    rule("washer.n.03", Spot::In, 0.2, LAUNDRY),
    rule("dryer.n.01", Spot::In, 0.2, LAUNDRY),
    rule("cabinet.n.01", Spot::In, 0.55, CLEANING),
    rule("washer.n.03", Spot::Beside, 0.15, LAUNDRY_FLOOR),
];
const CLOSET: &[Rule] = &[
    rule("shelf.n.01", Spot::On, 1.0, CLOSET_SHELF),
    rule("cabinet.n.01", Spot::In, 0.55, CLOTHES),
    rule("shelf.n.01", Spot::Beside, 0.3, CLOSET_FLOOR),
];

/// The rules of a room type, in the order they are applied. The corridor has none: it stays
/// clear for the agent.
pub(crate) fn rules(kind: RoomType) -> &'static [Rule] {
    match kind {
        RoomType::Kitchen => KITCHEN,
        RoomType::LivingRoom => LIVING_ROOM,
        RoomType::Bedroom => BEDROOM,
        RoomType::Bathroom => BATHROOM,
        RoomType::DiningRoom => DINING_ROOM,
        RoomType::Garage => GARAGE,
        RoomType::HomeOffice => HOME_OFFICE,
        RoomType::StorageRoom => STORAGE_ROOM,
        RoomType::UtilityRoom => UTILITY_ROOM,
        RoomType::Closet => CLOSET,
        RoomType::Corridor => &[],
    }
}

/// Things that may also stand on an edge (a book upright on a shelf); the rest keep the
/// orientation they are built in, which is the way they usually lie or stand.
pub(crate) const STAND_ON_EDGE: &[&str] = &["book.n.02", "hardback.n.01"];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog::CATALOG;
    use rapier3d::math::Vector;

    fn archetype(synset: &str) -> &'static crate::Archetype {
        CATALOG
            .iter()
            .find(|a| a.synset == synset)
            .unwrap_or_else(|| panic!("{synset} is not in the catalog"))
    }

    #[test]
    fn every_rule_puts_movable_things_without_moving_parts_at_fixed_furniture() {
        for kind in RoomType::ALL {
            for rule in rules(kind) {
                assert!(
                    archetype(rule.furniture).shape.is_fixed(),
                    "{}",
                    rule.furniture
                );
                assert!(rule.fill > 0.0 && rule.fill <= 1.0, "{}", rule.furniture);
                assert!(!rule.items.is_empty());
                for item in rule.items {
                    let a = archetype(item);
                    assert!(!a.shape.is_fixed(), "{item} is furniture");
                    for variant in 0..a.shape.variants() {
                        let (spec, _) = a.build("x", Vector::from_array(a.max), variant);
                        assert!(spec.links.is_empty(), "{item} has moving parts");
                    }
                }
            }
        }
        assert!(
            rules(RoomType::Corridor).is_empty(),
            "the corridor stays clear"
        );
    }

    #[test]
    fn things_that_stand_on_an_edge_can() {
        for synset in STAND_ON_EDGE {
            assert!(archetype(synset).shape.resting_orientations().len() > 1);
        }
    }
}
