//! The object catalog: one archetype per synset used by the official activities, with real-world
//! sizes, densities and colours. Sizes are the bounding box (x = width, y = depth, z = height, in
//! metres) of the smallest and largest instances; an instance is drawn uniformly between them.

use crate::archetype::{Archetype, Material, Shape};

/// Every archetype, sorted by synset.
#[rustfmt::skip]
pub const CATALOG: &[Archetype] = &[
    Archetype { synset: "agent.n.01", shape: Shape::Agent, min: [0.5, 0.5, 1.5], max: [0.5, 0.5, 1.5], density: 100.0, material: Material::Plastic, color: [90, 90, 200] },
    Archetype { synset: "alarm.n.02", shape: Shape::Cylinder, min: [0.1, 0.1, 0.035], max: [0.14, 0.14, 0.05], density: 900.0, material: Material::Plastic, color: [240, 240, 235] }, // smoke/security alarm unit, toggled on
    Archetype { synset: "apparel.n.01", shape: Shape::Slab, min: [0.25, 0.2, 0.02], max: [0.4, 0.35, 0.06], density: 300.0, material: Material::Cloth, color: [170, 60, 140] }, // a folded garment
    Archetype { synset: "apple.n.01", shape: Shape::Ball, min: [0.07, 0.07, 0.07], max: [0.09, 0.09, 0.09], density: 800.0, material: Material::Food, color: [200, 30, 30] },
    Archetype { synset: "ashcan.n.01", shape: Shape::OpenContainer, min: [0.28, 0.28, 0.4], max: [0.4, 0.4, 0.7], density: 130.0, material: Material::Plastic, color: [80, 90, 80] }, // effective density of thin plastic walls: 0.4 x 0.4 x 0.7 m ~4 kg
    Archetype { synset: "backpack.n.01", shape: Shape::LiddedContainer, min: [0.28, 0.15, 0.4], max: [0.35, 0.22, 0.5], density: 300.0, material: Material::Cloth, color: [40, 80, 150] }, // zipped flap modelled as a lid
    Archetype { synset: "ball.n.01", shape: Shape::Ball, min: [0.065, 0.065, 0.065], max: [0.24, 0.24, 0.24], density: 150.0, material: Material::Rubber, color: [240, 120, 30] }, // hollow ball, low effective density
    Archetype { synset: "banana.n.02", shape: Shape::Rod, min: [0.15, 0.035, 0.035], max: [0.22, 0.045, 0.045], density: 950.0, material: Material::Food, color: [245, 215, 60] },
    Archetype { synset: "basket.n.01", shape: Shape::OpenContainer, min: [0.25, 0.2, 0.12], max: [0.45, 0.35, 0.3], density: 500.0, material: Material::Wood, color: [190, 150, 90] },
    Archetype { synset: "bathtub.n.01", shape: Shape::Bathtub, min: [1.5, 0.7, 0.5], max: [1.8, 0.8, 0.6], density: 1000.0, material: Material::Ceramic, color: [235, 240, 245] },
    Archetype { synset: "bed.n.01", shape: Shape::Bed, min: [1.0, 2.0, 0.5], max: [2.0, 2.2, 0.6], density: 600.0, material: Material::Wood, color: [150, 110, 170] },
    Archetype { synset: "beef.n.02", shape: Shape::Block, min: [0.12, 0.08, 0.025], max: [0.25, 0.15, 0.06], density: 1050.0, material: Material::Food, color: [170, 40, 50] },
    Archetype { synset: "beer.n.01", shape: Shape::Cylinder, min: [0.065, 0.065, 0.12], max: [0.075, 0.075, 0.25], density: 1000.0, material: Material::Glass, color: [200, 150, 40] }, // can or bottle of beer
    Archetype { synset: "beverage.n.01", shape: Shape::Cylinder, min: [0.065, 0.065, 0.12], max: [0.09, 0.09, 0.3], density: 1000.0, material: Material::Plastic, color: [90, 160, 200] }, // a drink in a can, bottle or glass
    Archetype { synset: "bin.n.01", shape: Shape::OpenContainer, min: [0.3, 0.25, 0.25], max: [0.5, 0.4, 0.45], density: 100.0, material: Material::Plastic, color: [70, 120, 160] }, // effective density of thin plastic walls: ~2.2 kg at the largest
    Archetype { synset: "blender.n.01", shape: Shape::Cylinder, min: [0.15, 0.15, 0.35], max: [0.2, 0.2, 0.45], density: 280.0, material: Material::Plastic, color: [210, 210, 220] }, // effective density (jar and motor base): ~4 kg at the largest
    Archetype { synset: "book.n.02", shape: Shape::Block, min: [0.13, 0.19, 0.015], max: [0.22, 0.3, 0.05], density: 700.0, material: Material::Paper, color: [150, 40, 40] },
    Archetype { synset: "bottle.n.01", shape: Shape::Cylinder, min: [0.06, 0.06, 0.2], max: [0.09, 0.09, 0.32], density: 1000.0, material: Material::Glass, color: [60, 150, 90] },
    Archetype { synset: "bow.n.08", shape: Shape::Block, min: [0.07, 0.07, 0.04], max: [0.14, 0.14, 0.07], density: 200.0, material: Material::Cloth, color: [220, 30, 60] }, // decorative ribbon bow
    Archetype { synset: "bowl.n.01", shape: Shape::OpenContainer, min: [0.12, 0.12, 0.05], max: [0.22, 0.22, 0.1], density: 2400.0, material: Material::Ceramic, color: [240, 235, 220] },
    Archetype { synset: "box.n.01", shape: Shape::OpenContainer, min: [0.3, 0.25, 0.2], max: [0.6, 0.45, 0.4], density: 40.0, material: Material::Paper, color: [190, 150, 100] }, // cardboard storage box; effective density of corrugated board: ~1.2 kg at the largest
    Archetype { synset: "bracelet.n.02", shape: Shape::Cylinder, min: [0.06, 0.06, 0.008], max: [0.08, 0.08, 0.02], density: 3000.0, material: Material::Metal, color: [230, 190, 60] },
    Archetype { synset: "bread.n.01", shape: Shape::Block, min: [0.2, 0.1, 0.08], max: [0.3, 0.13, 0.12], density: 250.0, material: Material::Food, color: [210, 160, 90] }, // a loaf
    Archetype { synset: "briefcase.n.01", shape: Shape::LiddedContainer, min: [0.4, 0.3, 0.08], max: [0.46, 0.34, 0.12], density: 500.0, material: Material::Cloth, color: [80, 50, 30] }, // lying flat, lid on top
    Archetype { synset: "broccoli.n.02", shape: Shape::Ball, min: [0.1, 0.1, 0.1], max: [0.16, 0.16, 0.15], density: 600.0, material: Material::Food, color: [40, 130, 50] },
    Archetype { synset: "broom.n.01", shape: Shape::Rod, min: [1.2, 0.04, 0.04], max: [1.5, 0.05, 0.05], density: 500.0, material: Material::Wood, color: [200, 170, 80] },
    Archetype { synset: "brush.n.02", shape: Shape::Rod, min: [0.2, 0.04, 0.03], max: [0.35, 0.06, 0.05], density: 600.0, material: Material::Wood, color: [120, 80, 50] },
    Archetype { synset: "bucket.n.01", shape: Shape::OpenContainer, min: [0.25, 0.25, 0.25], max: [0.32, 0.32, 0.35], density: 95.0, material: Material::Plastic, color: [60, 110, 200] }, // effective density of thin plastic walls: an empty bucket ~1 kg
    Archetype { synset: "cabinet.n.01", shape: Shape::Cabinet, min: [0.5, 0.4, 0.7], max: [1.0, 0.6, 1.0], density: 600.0, material: Material::Wood, color: [160, 110, 60] },
    Archetype { synset: "cake.n.03", shape: Shape::Cylinder, min: [0.18, 0.18, 0.07], max: [0.28, 0.28, 0.12], density: 500.0, material: Material::Food, color: [240, 200, 210] },
    Archetype { synset: "calculator.n.02", shape: Shape::Block, min: [0.07, 0.12, 0.01], max: [0.1, 0.18, 0.025], density: 900.0, material: Material::Plastic, color: [50, 50, 60] },
    Archetype { synset: "caldron.n.01", shape: Shape::OpenContainer, min: [0.25, 0.25, 0.2], max: [0.45, 0.45, 0.35], density: 70.0, material: Material::Plastic, color: [30, 30, 30] }, // Halloween cauldron decoration; effective density of a thin plastic shell: ~1.6 kg at the largest
    Archetype { synset: "candle.n.01", shape: Shape::Cylinder, min: [0.03, 0.03, 0.08], max: [0.08, 0.08, 0.25], density: 900.0, material: Material::Plastic, color: [245, 240, 210] },
    Archetype { synset: "candy.n.01", shape: Shape::Block, min: [0.02, 0.02, 0.01], max: [0.08, 0.04, 0.02], density: 1300.0, material: Material::Food, color: [230, 80, 160] },
    Archetype { synset: "car.n.01", shape: Shape::LiddedContainer, min: [3.6, 1.6, 1.4], max: [4.2, 1.8, 1.5], density: 1000.0, material: Material::Metal, color: [180, 30, 40] }, // things go inside and it opens: a car-sized lidded box
    Archetype { synset: "carrot.n.03", shape: Shape::Rod, min: [0.14, 0.025, 0.025], max: [0.2, 0.035, 0.035], density: 1000.0, material: Material::Food, color: [240, 120, 30] },
    Archetype { synset: "carton.n.02", shape: Shape::LiddedContainer, min: [0.25, 0.2, 0.15], max: [0.5, 0.4, 0.35], density: 40.0, material: Material::Paper, color: [200, 160, 110] }, // cardboard box with flaps on top; effective density of corrugated board: ~1 kg at the largest
    Archetype { synset: "carving_knife.n.01", shape: Shape::Rod, min: [0.3, 0.03, 0.02], max: [0.38, 0.04, 0.025], density: 700.0, material: Material::Metal, color: [190, 190, 200] },
    Archetype { synset: "casserole.n.02", shape: Shape::Block, min: [0.25, 0.18, 0.06], max: [0.35, 0.25, 0.09], density: 380.0, material: Material::Ceramic, color: [200, 120, 70] }, // a casserole (food in its baking dish); food and dish: ~3 kg at the largest
    Archetype { synset: "catsup.n.01", shape: Shape::Cylinder, min: [0.06, 0.06, 0.18], max: [0.075, 0.075, 0.23], density: 1000.0, material: Material::Plastic, color: [190, 20, 20] }, // ketchup bottle
    Archetype { synset: "cereal.n.03", shape: Shape::Block, min: [0.18, 0.06, 0.25], max: [0.22, 0.08, 0.32], density: 250.0, material: Material::Paper, color: [230, 180, 40] }, // cereal box
    Archetype { synset: "chair.n.01", shape: Shape::Chair, min: [0.45, 0.45, 0.8], max: [0.55, 0.55, 1.0], density: 600.0, material: Material::Wood, color: [140, 100, 60] },
    Archetype { synset: "cheese.n.01", shape: Shape::Block, min: [0.08, 0.06, 0.04], max: [0.15, 0.1, 0.07], density: 1100.0, material: Material::Food, color: [250, 220, 90] },
    Archetype { synset: "chestnut.n.03", shape: Shape::Ball, min: [0.025, 0.025, 0.02], max: [0.035, 0.035, 0.03], density: 900.0, material: Material::Food, color: [110, 60, 30] }, // edible nut
    Archetype { synset: "chicken.n.01", shape: Shape::Block, min: [0.12, 0.08, 0.04], max: [0.25, 0.18, 0.12], density: 1050.0, material: Material::Food, color: [230, 180, 150] }, // chicken meat
    Archetype { synset: "chip.n.04", shape: Shape::Block, min: [0.15, 0.06, 0.2], max: [0.22, 0.09, 0.3], density: 100.0, material: Material::Plastic, color: [240, 200, 60] }, // potato chips (crisps), a bag of them
    Archetype { synset: "christmas_tree.n.05", shape: Shape::Cylinder, min: [0.6, 0.6, 1.2], max: [1.1, 1.1, 2.1], density: 4.9, material: Material::Plastic, color: [20, 110, 40] }, // ornamental tree; effective density of artificial foliage: a 2.1 m tree ~10 kg
    Archetype { synset: "cleansing_agent.n.01", shape: Shape::Cylinder, min: [0.07, 0.07, 0.2], max: [0.1, 0.1, 0.3], density: 1000.0, material: Material::Plastic, color: [80, 200, 220] }, // bottle of cleaner
    Archetype { synset: "cookie.n.01", shape: Shape::Cylinder, min: [0.05, 0.05, 0.008], max: [0.09, 0.09, 0.015], density: 700.0, material: Material::Food, color: [200, 150, 80] },
    Archetype { synset: "countertop.n.01", shape: Shape::Countertop, min: [1.0, 0.6, 0.9], max: [2.4, 0.65, 0.9], density: 600.0, material: Material::Wood, color: [200, 200, 190] },
    Archetype { synset: "cracker.n.01", shape: Shape::Slab, min: [0.04, 0.04, 0.004], max: [0.07, 0.07, 0.008], density: 600.0, material: Material::Food, color: [220, 180, 110] },
    Archetype { synset: "cube.n.05", shape: Shape::Block, min: [0.04, 0.04, 0.04], max: [0.08, 0.08, 0.08], density: 600.0, material: Material::Plastic, color: [60, 170, 220] }, // toy cube (stocking stuffer)
    Archetype { synset: "cup.n.01", shape: Shape::Cylinder, min: [0.07, 0.07, 0.08], max: [0.09, 0.09, 0.11], density: 2400.0, material: Material::Ceramic, color: [230, 230, 240] },
    Archetype { synset: "date.n.08", shape: Shape::Ball, min: [0.018, 0.018, 0.03], max: [0.025, 0.025, 0.045], density: 1100.0, material: Material::Food, color: [110, 50, 30] }, // the date fruit
    Archetype { synset: "detergent.n.02", shape: Shape::Block, min: [0.12, 0.08, 0.2], max: [0.18, 0.12, 0.3], density: 1000.0, material: Material::Plastic, color: [240, 110, 30] }, // detergent jug/box
    Archetype { synset: "dish.n.01", shape: Shape::OpenContainer, min: [0.18, 0.18, 0.05], max: [0.3, 0.3, 0.1], density: 400.0, material: Material::Ceramic, color: [235, 235, 225] }, // serving dish that food goes inside; effective density of a ceramic dish's walls: ~1.5 kg at the largest
    Archetype { synset: "dishtowel.n.01", shape: Shape::Slab, min: [0.2, 0.2, 0.01], max: [0.35, 0.3, 0.02], density: 300.0, material: Material::Cloth, color: [220, 230, 240] }, // folded
    Archetype { synset: "dishwasher.n.01", shape: Shape::Dishwasher, min: [0.45, 0.55, 0.82], max: [0.6, 0.62, 0.87], density: 1000.0, material: Material::Metal, color: [200, 205, 210] },
    Archetype { synset: "document.n.01", shape: Shape::Slab, min: [0.21, 0.28, 0.001], max: [0.22, 0.3, 0.005], density: 700.0, material: Material::Paper, color: [250, 250, 245] },
    Archetype { synset: "door.n.01", shape: Shape::Door, min: [0.8, 0.05, 2.0], max: [0.9, 0.05, 2.1], density: 600.0, material: Material::Wood, color: [130, 85, 45] },
    Archetype { synset: "dryer.n.01", shape: Shape::Dryer, min: [0.6, 0.6, 0.85], max: [0.7, 0.75, 1.0], density: 1000.0, material: Material::Metal, color: [235, 235, 235] },
    Archetype { synset: "duffel_bag.n.01", shape: Shape::OpenContainer, min: [0.45, 0.25, 0.25], max: [0.7, 0.35, 0.35], density: 300.0, material: Material::Cloth, color: [50, 70, 50] },
    Archetype { synset: "dustpan.n.02", shape: Shape::Slab, min: [0.22, 0.25, 0.04], max: [0.32, 0.35, 0.1], density: 40.0, material: Material::Plastic, color: [200, 60, 60] }, // effective density of a thin plastic pan: ~0.4 kg at the largest
    Archetype { synset: "earphone.n.01", shape: Shape::Block, min: [0.03, 0.03, 0.02], max: [0.06, 0.06, 0.04], density: 900.0, material: Material::Plastic, color: [240, 240, 240] },
    Archetype { synset: "egg.n.02", shape: Shape::Ball, min: [0.04, 0.04, 0.05], max: [0.045, 0.045, 0.06], density: 1030.0, material: Material::Food, color: [245, 235, 215] },
    Archetype { synset: "electric_refrigerator.n.01", shape: Shape::Fridge, min: [0.6, 0.6, 1.6], max: [0.9, 0.8, 1.9], density: 1000.0, material: Material::Metal, color: [225, 230, 235] },
    Archetype { synset: "envelope.n.01", shape: Shape::Slab, min: [0.16, 0.11, 0.002], max: [0.24, 0.16, 0.008], density: 700.0, material: Material::Paper, color: [245, 240, 225] },
    Archetype { synset: "facsimile.n.02", shape: Shape::Block, min: [0.3, 0.25, 0.12], max: [0.42, 0.35, 0.2], density: 250.0, material: Material::Plastic, color: [70, 70, 75] }, // hollow casing: a fax machine weighs 2–7 kg
    Archetype { synset: "fish.n.02", shape: Shape::Block, min: [0.15, 0.07, 0.02], max: [0.35, 0.12, 0.06], density: 1050.0, material: Material::Food, color: [220, 140, 120] }, // fish as food (fillet or whole)
    Archetype { synset: "floor.n.01", shape: Shape::Floor, min: [4.0, 4.0, 0.1], max: [4.0, 4.0, 0.1], density: 600.0, material: Material::Wood, color: [185, 175, 160] },
    Archetype { synset: "flour.n.01", shape: Shape::Block, min: [0.12, 0.08, 0.2], max: [0.16, 0.11, 0.28], density: 600.0, material: Material::Paper, color: [245, 245, 235] }, // bag of flour
    Archetype { synset: "folder.n.02", shape: Shape::LiddedContainer, min: [0.23, 0.3, 0.01], max: [0.25, 0.32, 0.03], density: 700.0, material: Material::Paper, color: [60, 120, 200] }, // file folder; its cover is the lid
    Archetype { synset: "food.n.01", shape: Shape::Block, min: [0.1, 0.08, 0.05], max: [0.2, 0.15, 0.12], density: 800.0, material: Material::Food, color: [200, 140, 90] }, // generic packaged food
    Archetype { synset: "food.n.02", shape: Shape::Block, min: [0.1, 0.08, 0.05], max: [0.2, 0.15, 0.12], density: 800.0, material: Material::Food, color: [190, 150, 100] }, // generic solid food, packaged
    Archetype { synset: "fork.n.01", shape: Shape::Rod, min: [0.17, 0.025, 0.01], max: [0.21, 0.03, 0.02], density: 7800.0, material: Material::Metal, color: [180, 180, 190] },
    Archetype { synset: "grape.n.01", shape: Shape::Ball, min: [0.018, 0.018, 0.02], max: [0.025, 0.025, 0.028], density: 1000.0, material: Material::Food, color: [110, 40, 120] },
    Archetype { synset: "grill.n.02", shape: Shape::Block, min: [0.6, 0.5, 0.9], max: [1.2, 0.7, 1.1], density: 55.0, material: Material::Metal, color: [40, 40, 45] }, // barbecue grill; effective density of a kettle grill on legs: ~50 kg at the largest
    Archetype { synset: "gym_shoe.n.01", shape: Shape::Block, min: [0.1, 0.26, 0.09], max: [0.12, 0.32, 0.13], density: 400.0, material: Material::Rubber, color: [230, 230, 230] },
    Archetype { synset: "hamburger.n.01", shape: Shape::Cylinder, min: [0.09, 0.09, 0.05], max: [0.12, 0.12, 0.08], density: 700.0, material: Material::Food, color: [170, 100, 50] },
    Archetype { synset: "hammer.n.02", shape: Shape::Rod, min: [0.28, 0.1, 0.03], max: [0.35, 0.13, 0.04], density: 2500.0, material: Material::Metal, color: [110, 90, 80] },
    Archetype { synset: "hand_towel.n.01", shape: Shape::Slab, min: [0.25, 0.2, 0.015], max: [0.4, 0.3, 0.04], density: 300.0, material: Material::Cloth, color: [200, 220, 240] }, // folded
    Archetype { synset: "hanger.n.02", shape: Shape::Slab, min: [0.38, 0.18, 0.008], max: [0.45, 0.22, 0.015], density: 800.0, material: Material::Plastic, color: [210, 190, 150] }, // coat hanger lying flat
    Archetype { synset: "hardback.n.01", shape: Shape::Block, min: [0.15, 0.22, 0.02], max: [0.22, 0.3, 0.05], density: 700.0, material: Material::Paper, color: [40, 60, 120] }, // hardcover book
    Archetype { synset: "hat.n.01", shape: Shape::Cylinder, min: [0.25, 0.25, 0.1], max: [0.35, 0.35, 0.15], density: 100.0, material: Material::Cloth, color: [120, 80, 60] },
    Archetype { synset: "headset.n.01", shape: Shape::Block, min: [0.16, 0.08, 0.16], max: [0.2, 0.1, 0.2], density: 300.0, material: Material::Plastic, color: [40, 40, 45] },
    Archetype { synset: "highchair.n.01", shape: Shape::Chair, min: [0.5, 0.6, 0.9], max: [0.6, 0.75, 1.05], density: 600.0, material: Material::Wood, color: [230, 220, 200] },
    Archetype { synset: "highlighter.n.02", shape: Shape::Rod, min: [0.11, 0.015, 0.015], max: [0.14, 0.022, 0.022], density: 900.0, material: Material::Plastic, color: [240, 240, 40] },
    Archetype { synset: "jar.n.01", shape: Shape::LiddedContainer, min: [0.07, 0.07, 0.08], max: [0.12, 0.12, 0.18], density: 2500.0, material: Material::Glass, color: [170, 210, 200] }, // glass jar with a lid
    Archetype { synset: "jewelry.n.01", shape: Shape::Block, min: [0.02, 0.02, 0.005], max: [0.06, 0.05, 0.02], density: 5000.0, material: Material::Metal, color: [230, 200, 70] },
    Archetype { synset: "juice.n.01", shape: Shape::Block, min: [0.07, 0.07, 0.18], max: [0.1, 0.1, 0.27], density: 1000.0, material: Material::Paper, color: [250, 160, 30] }, // juice carton
    Archetype { synset: "kettle.n.01", shape: Shape::Cylinder, min: [0.16, 0.16, 0.18], max: [0.22, 0.22, 0.25], density: 160.0, material: Material::Metal, color: [190, 190, 200] }, // effective density of a hollow kettle: ~1.5 kg at the largest
    Archetype { synset: "knife.n.01", shape: Shape::Rod, min: [0.2, 0.02, 0.016], max: [0.3, 0.03, 0.02], density: 1500.0, material: Material::Metal, color: [190, 190, 200] },
    Archetype { synset: "lamp.n.02", shape: Shape::Cylinder, min: [0.25, 0.25, 0.45], max: [0.45, 0.45, 1.6], density: 30.0, material: Material::Metal, color: [250, 230, 150] }, // table or floor lamp; effective density: a pole and a shade fill little of the cylinder; 1.6 m floor lamp ~7.6 kg
    Archetype { synset: "lemon.n.01", shape: Shape::Ball, min: [0.055, 0.055, 0.065], max: [0.07, 0.07, 0.08], density: 900.0, material: Material::Food, color: [250, 240, 70] },
    Archetype { synset: "lettuce.n.03", shape: Shape::Ball, min: [0.12, 0.12, 0.1], max: [0.18, 0.18, 0.15], density: 400.0, material: Material::Food, color: [120, 200, 80] },
    Archetype { synset: "makeup.n.01", shape: Shape::Block, min: [0.02, 0.02, 0.06], max: [0.08, 0.08, 0.12], density: 1000.0, material: Material::Plastic, color: [220, 120, 140] }, // compact, lipstick or bottle
    Archetype { synset: "marker.n.03", shape: Shape::Rod, min: [0.12, 0.015, 0.015], max: [0.15, 0.02, 0.02], density: 900.0, material: Material::Plastic, color: [30, 30, 160] },
    Archetype { synset: "meat.n.01", shape: Shape::Block, min: [0.12, 0.08, 0.03], max: [0.25, 0.15, 0.08], density: 1050.0, material: Material::Food, color: [180, 50, 60] },
    Archetype { synset: "melon.n.01", shape: Shape::Ball, min: [0.15, 0.15, 0.15], max: [0.25, 0.22, 0.22], density: 950.0, material: Material::Food, color: [180, 210, 120] },
    Archetype { synset: "microwave.n.02", shape: Shape::Microwave, min: [0.45, 0.35, 0.26], max: [0.6, 0.45, 0.35], density: 1000.0, material: Material::Metal, color: [226, 226, 222] }, // white, so that its dark window and panel show
    Archetype { synset: "milk.n.01", shape: Shape::Block, min: [0.07, 0.07, 0.2], max: [0.1, 0.1, 0.26], density: 1000.0, material: Material::Paper, color: [250, 250, 255] }, // milk carton/jug
    Archetype { synset: "modem.n.01", shape: Shape::Block, min: [0.15, 0.12, 0.03], max: [0.25, 0.18, 0.05], density: 600.0, material: Material::Plastic, color: [30, 30, 35] },
    Archetype { synset: "mouse.n.04", shape: Shape::Block, min: [0.06, 0.1, 0.03], max: [0.07, 0.12, 0.045], density: 600.0, material: Material::Plastic, color: [60, 60, 70] }, // computer mouse
    Archetype { synset: "mousetrap.n.01", shape: Shape::Block, min: [0.08, 0.04, 0.015], max: [0.11, 0.06, 0.03], density: 600.0, material: Material::Wood, color: [200, 170, 120] },
    Archetype { synset: "mug.n.04", shape: Shape::Cylinder, min: [0.08, 0.08, 0.09], max: [0.1, 0.1, 0.12], density: 2400.0, material: Material::Ceramic, color: [220, 90, 60] },
    Archetype { synset: "mushroom.n.05", shape: Shape::Ball, min: [0.03, 0.03, 0.03], max: [0.06, 0.06, 0.05], density: 600.0, material: Material::Food, color: [220, 210, 190] },
    Archetype { synset: "necklace.n.01", shape: Shape::Slab, min: [0.05, 0.05, 0.006], max: [0.12, 0.1, 0.015], density: 4000.0, material: Material::Metal, color: [230, 200, 80] }, // coiled, lying flat
    Archetype { synset: "newspaper.n.03", shape: Shape::Slab, min: [0.28, 0.38, 0.005], max: [0.32, 0.42, 0.02], density: 700.0, material: Material::Paper, color: [215, 215, 205] }, // folded
    Archetype { synset: "notebook.n.01", shape: Shape::Slab, min: [0.15, 0.21, 0.005], max: [0.22, 0.3, 0.02], density: 700.0, material: Material::Paper, color: [90, 150, 200] },
    Archetype { synset: "oatmeal.n.01", shape: Shape::Cylinder, min: [0.1, 0.1, 0.15], max: [0.13, 0.13, 0.2], density: 400.0, material: Material::Paper, color: [210, 190, 140] }, // oatmeal canister
    Archetype { synset: "olive.n.04", shape: Shape::Ball, min: [0.015, 0.015, 0.02], max: [0.022, 0.022, 0.03], density: 1000.0, material: Material::Food, color: [110, 120, 40] }, // olive fruit
    Archetype { synset: "orange.n.01", shape: Shape::Ball, min: [0.07, 0.07, 0.07], max: [0.09, 0.09, 0.09], density: 850.0, material: Material::Food, color: [250, 140, 20] },
    Archetype { synset: "oven.n.01", shape: Shape::Oven, min: [0.6, 0.6, 0.85], max: [0.76, 0.7, 0.95], density: 1000.0, material: Material::Metal, color: [186, 188, 192] }, // stainless, so that its dark window and knobs show
    Archetype { synset: "package.n.02", shape: Shape::LiddedContainer, min: [0.2, 0.15, 0.1], max: [0.5, 0.4, 0.35], density: 40.0, material: Material::Paper, color: [200, 160, 110] }, // parcel/present box that is opened; effective density of corrugated board: ~1 kg at the largest
    Archetype { synset: "pad.n.01", shape: Shape::Slab, min: [0.1, 0.15, 0.005], max: [0.22, 0.3, 0.015], density: 700.0, material: Material::Paper, color: [250, 240, 140] }, // paper notepad (trash)
    Archetype { synset: "painting.n.01", shape: Shape::Slab, min: [0.3, 0.25, 0.02], max: [0.9, 0.7, 0.04], density: 160.0, material: Material::Wood, color: [120, 160, 200] }, // framed picture lying flat; effective density of canvas in a frame: 0.9 x 0.7 m ~4 kg
    Archetype { synset: "pan.n.01", shape: Shape::OpenContainer, min: [0.2, 0.2, 0.04], max: [0.3, 0.3, 0.06], density: 510.0, material: Material::Metal, color: [60, 60, 65] }, // effective density of a pan's walls: a 30 cm pan ~1.5 kg
    Archetype { synset: "parsley.n.02", shape: Shape::Block, min: [0.06, 0.05, 0.12], max: [0.1, 0.08, 0.2], density: 300.0, material: Material::Food, color: [60, 150, 50] }, // a bunch
    Archetype { synset: "pasta.n.02", shape: Shape::Block, min: [0.15, 0.05, 0.2], max: [0.2, 0.08, 0.28], density: 500.0, material: Material::Paper, color: [240, 210, 120] }, // box of pasta
    Archetype { synset: "peach.n.03", shape: Shape::Ball, min: [0.06, 0.06, 0.06], max: [0.08, 0.08, 0.08], density: 900.0, material: Material::Food, color: [250, 170, 110] },
    Archetype { synset: "pen.n.01", shape: Shape::Rod, min: [0.13, 0.01, 0.01], max: [0.15, 0.014, 0.014], density: 1100.0, material: Material::Plastic, color: [30, 60, 160] },
    Archetype { synset: "pencil.n.01", shape: Shape::Rod, min: [0.12, 0.007, 0.007], max: [0.19, 0.008, 0.008], density: 700.0, material: Material::Wood, color: [240, 200, 40] },
    Archetype { synset: "pencil_box.n.01", shape: Shape::Block, min: [0.18, 0.06, 0.03], max: [0.24, 0.1, 0.06], density: 700.0, material: Material::Plastic, color: [200, 80, 80] },
    Archetype { synset: "perfume.n.02", shape: Shape::Cylinder, min: [0.04, 0.04, 0.08], max: [0.07, 0.07, 0.14], density: 2000.0, material: Material::Glass, color: [230, 170, 220] },
    Archetype { synset: "piece_of_cloth.n.01", shape: Shape::Slab, min: [0.2, 0.2, 0.005], max: [0.4, 0.4, 0.02], density: 300.0, material: Material::Cloth, color: [170, 190, 220] },
    Archetype { synset: "plate.n.04", shape: Shape::Slab, min: [0.2, 0.2, 0.02], max: [0.28, 0.28, 0.02], density: 2400.0, material: Material::Ceramic, color: [245, 245, 240] },
    Archetype { synset: "plaything.n.01", shape: Shape::Block, min: [0.05, 0.05, 0.05], max: [0.25, 0.2, 0.2], density: 300.0, material: Material::Plastic, color: [250, 80, 180] }, // a toy
    Archetype { synset: "plywood.n.01", shape: Shape::Slab, min: [0.6, 0.6, 0.012], max: [0.9, 0.9, 0.018], density: 550.0, material: Material::Wood, color: [215, 180, 120] }, // boards a person carries in one hand (~8 kg at the largest); a full 1.22 x 2.44 m sheet, 15-30 kg, is over the assisted grasp's 10 kg
    Archetype { synset: "pool.n.01", shape: Shape::OpenContainer, min: [1.2, 1.2, 0.3], max: [2.0, 2.0, 0.8], density: 900.0, material: Material::Plastic, color: [60, 170, 230] }, // swimming pool / hot tub: a large open basin
    Archetype { synset: "pop.n.02", shape: Shape::Cylinder, min: [0.066, 0.066, 0.12], max: [0.066, 0.066, 0.16], density: 1000.0, material: Material::Metal, color: [200, 40, 60] }, // soda pop, a can
    Archetype { synset: "pork.n.01", shape: Shape::Block, min: [0.12, 0.08, 0.03], max: [0.25, 0.15, 0.08], density: 1050.0, material: Material::Food, color: [235, 150, 150] },
    Archetype { synset: "pot_plant.n.01", shape: Shape::Cylinder, min: [0.15, 0.15, 0.25], max: [0.35, 0.35, 0.8], density: 120.0, material: Material::Ceramic, color: [50, 150, 60] }, // a houseplant in its pot, 0.5–9 kg
    Archetype { synset: "printer.n.03", shape: Shape::Block, min: [0.35, 0.3, 0.15], max: [0.5, 0.42, 0.3], density: 150.0, material: Material::Plastic, color: [220, 220, 225] }, // hollow casing: a desktop printer weighs 5–10 kg
    Archetype { synset: "pumpkin.n.02", shape: Shape::Ball, min: [0.2, 0.2, 0.17], max: [0.35, 0.35, 0.3], density: 500.0, material: Material::Food, color: [240, 130, 20] }, // hollow inside: a 35 cm pumpkin ~9 kg
    Archetype { synset: "radish.n.01", shape: Shape::Ball, min: [0.025, 0.025, 0.025], max: [0.04, 0.04, 0.04], density: 950.0, material: Material::Food, color: [210, 40, 80] },
    Archetype { synset: "rag.n.01", shape: Shape::Slab, min: [0.2, 0.2, 0.005], max: [0.35, 0.35, 0.02], density: 300.0, material: Material::Cloth, color: [180, 160, 140] },
    Archetype { synset: "raspberry.n.02", shape: Shape::Ball, min: [0.015, 0.015, 0.015], max: [0.022, 0.022, 0.022], density: 700.0, material: Material::Food, color: [200, 30, 70] },
    Archetype { synset: "receptacle.n.01", shape: Shape::OpenContainer, min: [0.25, 0.25, 0.15], max: [0.4, 0.4, 0.35], density: 90.0, material: Material::Plastic, color: [100, 140, 170] }, // a container such as a tub or bucket; effective density of thin plastic walls: ~1.6 kg at the largest
    Archetype { synset: "ribbon.n.01", shape: Shape::Cylinder, min: [0.06, 0.06, 0.02], max: [0.1, 0.1, 0.05], density: 300.0, material: Material::Cloth, color: [220, 40, 80] }, // a spool of ribbon
    Archetype { synset: "sack.n.01", shape: Shape::OpenContainer, min: [0.25, 0.15, 0.3], max: [0.4, 0.25, 0.5], density: 300.0, material: Material::Paper, color: [190, 160, 110] }, // paper/cloth bag
    Archetype { synset: "salad.n.01", shape: Shape::Cylinder, min: [0.15, 0.15, 0.07], max: [0.25, 0.25, 0.12], density: 600.0, material: Material::Ceramic, color: [100, 190, 70] }, // salad in a bowl
    Archetype { synset: "sandal.n.01", shape: Shape::Block, min: [0.09, 0.24, 0.03], max: [0.12, 0.3, 0.07], density: 400.0, material: Material::Rubber, color: [160, 110, 70] },
    Archetype { synset: "sandwich.n.01", shape: Shape::Slab, min: [0.09, 0.09, 0.03], max: [0.15, 0.12, 0.06], density: 500.0, material: Material::Food, color: [220, 180, 120] },
    Archetype { synset: "sauce.n.01", shape: Shape::Cylinder, min: [0.05, 0.05, 0.12], max: [0.08, 0.08, 0.22], density: 1000.0, material: Material::Glass, color: [160, 40, 30] }, // bottle or jar of sauce
    Archetype { synset: "saucepan.n.01", shape: Shape::OpenContainer, min: [0.16, 0.16, 0.08], max: [0.24, 0.24, 0.15], density: 520.0, material: Material::Metal, color: [150, 150, 160] }, // effective density of a pot's walls: ~1.5 kg at the largest
    Archetype { synset: "saw.n.02", shape: Shape::Slab, min: [0.45, 0.1, 0.02], max: [0.65, 0.15, 0.03], density: 240.0, material: Material::Metal, color: [170, 170, 180] }, // hand saw lying flat; effective density of a blade and handle: ~0.7 kg at the largest
    Archetype { synset: "scanner.n.02", shape: Shape::Block, min: [0.4, 0.28, 0.06], max: [0.5, 0.36, 0.12], density: 190.0, material: Material::Plastic, color: [50, 50, 55] }, // effective density of a flatbed scanner: ~4 kg at the largest
    Archetype { synset: "scraper.n.01", shape: Shape::Rod, min: [0.2, 0.08, 0.02], max: [0.35, 0.12, 0.03], density: 900.0, material: Material::Plastic, color: [60, 120, 200] }, // hand scraper (e.g. ice scraper)
    Archetype { synset: "screwdriver.n.01", shape: Shape::Rod, min: [0.15, 0.025, 0.025], max: [0.25, 0.035, 0.035], density: 2000.0, material: Material::Metal, color: [220, 50, 40] },
    Archetype { synset: "scrub_brush.n.01", shape: Shape::Block, min: [0.12, 0.06, 0.04], max: [0.2, 0.09, 0.07], density: 600.0, material: Material::Plastic, color: [210, 120, 60] }, // hand-held scrubbing brush
    Archetype { synset: "seat.n.03", shape: Shape::Stool, min: [0.35, 0.35, 0.4], max: [0.5, 0.5, 0.5], density: 600.0, material: Material::Wood, color: [150, 120, 80] }, // small seat/stool (sits on a bed in rearranging_furniture)
    Archetype { synset: "shampoo.n.01", shape: Shape::Cylinder, min: [0.06, 0.06, 0.15], max: [0.08, 0.08, 0.25], density: 1000.0, material: Material::Plastic, color: [120, 200, 220] },
    Archetype { synset: "sheet.n.03", shape: Shape::Slab, min: [0.3, 0.25, 0.03], max: [0.45, 0.35, 0.08], density: 300.0, material: Material::Cloth, color: [240, 240, 250] }, // bed sheet, folded
    Archetype { synset: "shelf.n.01", shape: Shape::Shelf, min: [0.6, 0.25, 1.0], max: [1.2, 0.4, 2.0], density: 600.0, material: Material::Wood, color: [170, 130, 80] },
    Archetype { synset: "shirt.n.01", shape: Shape::Slab, min: [0.25, 0.2, 0.02], max: [0.35, 0.3, 0.05], density: 300.0, material: Material::Cloth, color: [80, 130, 200] }, // folded
    Archetype { synset: "shoe.n.01", shape: Shape::Block, min: [0.09, 0.24, 0.08], max: [0.12, 0.32, 0.14], density: 400.0, material: Material::Rubber, color: [70, 45, 30] },
    Archetype { synset: "shower.n.01", shape: Shape::Shower, min: [0.8, 0.8, 2.0], max: [1.0, 1.0, 2.2], density: 1000.0, material: Material::Ceramic, color: [210, 230, 240] },
    Archetype { synset: "sink.n.01", shape: Shape::Sink, min: [0.5, 0.45, 0.85], max: [0.9, 0.6, 0.95], density: 1000.0, material: Material::Ceramic, color: [230, 235, 240] },
    Archetype { synset: "snack_food.n.01", shape: Shape::Block, min: [0.1, 0.05, 0.12], max: [0.2, 0.08, 0.25], density: 200.0, material: Material::Plastic, color: [240, 150, 50] }, // a bag/box of snacks
    Archetype { synset: "soap.n.01", shape: Shape::Block, min: [0.07, 0.045, 0.02], max: [0.1, 0.065, 0.035], density: 1000.0, material: Material::Plastic, color: [250, 230, 240] }, // a bar of soap
    Archetype { synset: "sock.n.01", shape: Shape::Slab, min: [0.08, 0.2, 0.01], max: [0.11, 0.3, 0.02], density: 300.0, material: Material::Cloth, color: [230, 230, 230] },
    Archetype { synset: "sofa.n.01", shape: Shape::Sofa, min: [1.6, 0.8, 0.75], max: [2.4, 1.0, 0.9], density: 600.0, material: Material::Cloth, color: [110, 120, 150] },
    Archetype { synset: "soup.n.01", shape: Shape::Cylinder, min: [0.07, 0.07, 0.1], max: [0.15, 0.15, 0.12], density: 1000.0, material: Material::Metal, color: [200, 110, 40] }, // can or bowl of soup
    Archetype { synset: "spoon.n.01", shape: Shape::Rod, min: [0.14, 0.03, 0.01], max: [0.2, 0.045, 0.02], density: 7800.0, material: Material::Metal, color: [185, 185, 195] },
    Archetype { synset: "stocking.n.01", shape: Shape::OpenContainer, min: [0.18, 0.1, 0.35], max: [0.25, 0.15, 0.5], density: 300.0, material: Material::Cloth, color: [200, 30, 40] }, // Christmas stocking that gifts go inside
    Archetype { synset: "stove.n.01", shape: Shape::Stove, min: [0.6, 0.6, 0.9], max: [0.76, 0.7, 0.95], density: 1000.0, material: Material::Metal, color: [90, 90, 95] },
    Archetype { synset: "strawberry.n.01", shape: Shape::Ball, min: [0.025, 0.025, 0.03], max: [0.035, 0.035, 0.045], density: 900.0, material: Material::Food, color: [220, 30, 50] },
    Archetype { synset: "sugar.n.01", shape: Shape::Block, min: [0.1, 0.06, 0.15], max: [0.14, 0.09, 0.22], density: 800.0, material: Material::Paper, color: [250, 250, 250] }, // bag/box of sugar
    Archetype { synset: "sunglass.n.01", shape: Shape::Block, min: [0.13, 0.04, 0.04], max: [0.15, 0.06, 0.05], density: 600.0, material: Material::Plastic, color: [30, 30, 30] },
    Archetype { synset: "sushi.n.01", shape: Shape::Cylinder, min: [0.03, 0.03, 0.02], max: [0.045, 0.045, 0.03], density: 1000.0, material: Material::Food, color: [240, 150, 120] },
    Archetype { synset: "sweater.n.01", shape: Shape::Slab, min: [0.3, 0.25, 0.04], max: [0.4, 0.35, 0.08], density: 250.0, material: Material::Cloth, color: [150, 50, 50] }, // folded
    Archetype { synset: "table.n.02", shape: Shape::Table, min: [1.0, 0.6, 0.72], max: [1.8, 1.0, 0.78], density: 600.0, material: Material::Wood, color: [150, 100, 55] },
    Archetype { synset: "tea_bag.n.01", shape: Shape::Slab, min: [0.05, 0.06, 0.004], max: [0.065, 0.075, 0.008], density: 400.0, material: Material::Paper, color: [190, 160, 110] },
    Archetype { synset: "teapot.n.01", shape: Shape::OpenContainer, min: [0.16, 0.13, 0.12], max: [0.24, 0.18, 0.2], density: 440.0, material: Material::Ceramic, color: [230, 230, 220] }, // tea bags go inside it; effective density of ceramic walls: ~1 kg at the largest
    Archetype { synset: "tile.n.01", shape: Shape::Slab, min: [0.2, 0.2, 0.008], max: [0.4, 0.4, 0.012], density: 2300.0, material: Material::Stone, color: [200, 190, 180] },
    Archetype { synset: "toilet.n.02", shape: Shape::Toilet, min: [0.36, 0.65, 0.72], max: [0.42, 0.75, 0.8], density: 1000.0, material: Material::Ceramic, color: [245, 245, 245] },
    Archetype { synset: "tomato.n.01", shape: Shape::Ball, min: [0.06, 0.06, 0.05], max: [0.09, 0.09, 0.07], density: 950.0, material: Material::Food, color: [220, 40, 30] },
    Archetype { synset: "toothbrush.n.01", shape: Shape::Rod, min: [0.17, 0.015, 0.015], max: [0.2, 0.02, 0.025], density: 900.0, material: Material::Plastic, color: [60, 180, 230] },
    Archetype { synset: "toothpaste.n.01", shape: Shape::Rod, min: [0.15, 0.035, 0.025], max: [0.2, 0.05, 0.035], density: 1100.0, material: Material::Plastic, color: [240, 240, 250] }, // a tube
    Archetype { synset: "towel.n.01", shape: Shape::Slab, min: [0.3, 0.25, 0.03], max: [0.5, 0.4, 0.08], density: 300.0, material: Material::Cloth, color: [150, 200, 230] }, // folded
    Archetype { synset: "tray.n.01", shape: Shape::Slab, min: [0.3, 0.22, 0.02], max: [0.5, 0.35, 0.04], density: 800.0, material: Material::Plastic, color: [160, 120, 80] },
    Archetype { synset: "umbrella.n.01", shape: Shape::Rod, min: [0.6, 0.05, 0.05], max: [1.0, 0.08, 0.08], density: 500.0, material: Material::Cloth, color: [40, 40, 110] },
    Archetype { synset: "underwear.n.01", shape: Shape::Slab, min: [0.12, 0.1, 0.01], max: [0.25, 0.2, 0.03], density: 300.0, material: Material::Cloth, color: [240, 200, 210] }, // folded
    Archetype { synset: "vacuum.n.04", shape: Shape::Block, min: [0.3, 0.25, 0.3], max: [0.4, 0.35, 1.1], density: 60.0, material: Material::Plastic, color: [180, 40, 60] }, // vacuum cleaner: mostly air in its box, 2–9 kg as upright ones weigh
    Archetype { synset: "vegetable_oil.n.01", shape: Shape::Cylinder, min: [0.06, 0.06, 0.22], max: [0.09, 0.09, 0.32], density: 950.0, material: Material::Plastic, color: [230, 200, 60] }, // bottle of oil
    Archetype { synset: "vehicle.n.01", shape: Shape::LiddedContainer, min: [3.6, 1.6, 1.4], max: [4.2, 1.8, 1.5], density: 1000.0, material: Material::Metal, color: [60, 90, 160] }, // a car-sized vehicle; openable, so a lidded box
    Archetype { synset: "vessel.n.03", shape: Shape::Cylinder, min: [0.07, 0.07, 0.1], max: [0.12, 0.12, 0.2], density: 1000.0, material: Material::Plastic, color: [200, 180, 80] }, // a container for liquid (car-wax tin/bottle)
    Archetype { synset: "vidalia_onion.n.01", shape: Shape::Ball, min: [0.07, 0.07, 0.06], max: [0.1, 0.1, 0.09], density: 950.0, material: Material::Food, color: [230, 210, 150] },
    Archetype { synset: "washer.n.03", shape: Shape::Washer, min: [0.6, 0.55, 0.85], max: [0.7, 0.7, 1.0], density: 1000.0, material: Material::Metal, color: [235, 235, 240] },
    Archetype { synset: "water.n.06", shape: Shape::Cylinder, min: [0.065, 0.065, 0.2], max: [0.09, 0.09, 0.32], density: 1000.0, material: Material::Plastic, color: [120, 180, 240] }, // bottled water
    Archetype { synset: "window.n.01", shape: Shape::Window, min: [0.8, 0.05, 1.0], max: [1.4, 0.05, 1.4], density: 2500.0, material: Material::Wood, color: [170, 210, 240] },
    Archetype { synset: "wrapping.n.01", shape: Shape::Block, min: [0.2, 0.15, 0.08], max: [0.45, 0.35, 0.25], density: 50.0, material: Material::Paper, color: [200, 40, 50] }, // gift wrapping: a wrapped present; effective density of a wrapped gift box: ~2 kg at the largest
    Archetype { synset: "wreath.n.01", shape: Shape::Slab, min: [0.3, 0.3, 0.06], max: [0.6, 0.6, 0.12], density: 150.0, material: Material::Plastic, color: [30, 120, 50] }, // lying flat
    Archetype { synset: "yogurt.n.01", shape: Shape::Cylinder, min: [0.065, 0.065, 0.06], max: [0.08, 0.08, 0.1], density: 1050.0, material: Material::Plastic, color: [245, 245, 250] }, // yogurt cup
];
