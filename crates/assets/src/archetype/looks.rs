//! Which detailed form an archetype is drawn in (see `behavior-forms`): small things as one form
//! filling the box around their body (a bowl, whose colliders are a bottom and four walls, drawn
//! as a bowl on its foot ring), furniture and appliances box by box: rounded edges, soft
//! upholstery, turned legs.
//! Collision is untouched: what is drawn lies within the colliders' box.

use super::{Archetype, Shape};
use behavior_sim::{Form, Material, ObjectSpec, Part, Primitive, Visual};
use rapier3d::math::Vector;

/// The form a synset's body is drawn in, or [`Form::Primitive`] to draw its parts.
fn body_form(synset: &str, shape: Shape) -> Form {
    let name = synset.split('.').next().unwrap_or(synset);
    let by_name = match name {
        "apple" => Form::Apple,
        "orange" | "peach" | "tomato" | "melon" | "pumpkin" | "radish" | "vidalia_onion"
        | "grape" | "olive" | "chestnut" | "date" | "lettuce" => Form::Fruit,
        "lemon" => Form::Lemon,
        "egg" => Form::Egg,
        "broccoli" => Form::Florets,
        "mushroom" => Form::Mushroom,
        "strawberry" | "raspberry" => Form::Berry,
        "banana" => Form::Banana,
        "carrot" => Form::Carrot,
        "bread" => Form::Loaf,
        "book" | "hardback" | "notebook" => Form::Book,
        "cheese" | "soap" | "cracker" => Form::Soft,
        "beef" | "meat" | "pork" => Form::Steak,
        "candy" => Form::Sweet,
        "snack_food" | "chip" => Form::Pouch,
        "sandwich" => Form::Sandwich,
        "bow" => Form::Bow,
        "kettle" => Form::Kettle,
        "blender" => Form::Blender,
        "alarm" => Form::Detector,
        "milk" | "juice" => Form::Carton,
        "detergent" => Form::Jug,
        "flour" | "sugar" | "sack" => Form::Sack,
        "salad" => Form::Salad,
        "cookie" => Form::Cookie,
        "ribbon" => Form::Spool,
        "stocking" => Form::Stocking,
        "makeup" => Form::Lipstick,
        "mousetrap" => Form::Mousetrap,
        "briefcase" => Form::Briefcase,
        "pencil_box" => Form::PencilCase,
        "gym_shoe" | "shoe" | "sandal" => Form::Shoe,
        "hat" => Form::Hat,
        "hammer" => Form::Hammer,
        "screwdriver" => Form::Screwdriver,
        "toothbrush" => Form::Toothbrush,
        "umbrella" => Form::Umbrella,
        "bottle" | "beer" | "catsup" | "shampoo" | "perfume" | "vegetable_oil"
        | "cleansing_agent" | "sauce" | "beverage" | "water" | "pop" => Form::Bottle,
        "soup" | "oatmeal" | "yogurt" => Form::Can,
        "cup" | "vessel" => Form::Cup,
        "mug" => Form::Mug,
        "cake" => Form::Cake,
        "candle" => Form::Candle,
        "hamburger" => Form::Burger,
        "sushi" => Form::Maki,
        "lamp" => Form::Lamp,
        "pot_plant" => Form::Plant,
        "christmas_tree" => Form::Conifer,
        "chicken" => Form::Roast,
        "knife" | "carving_knife" => Form::Knife,
        "fork" => Form::Fork,
        "spoon" => Form::Spoon,
        "broom" | "brush" => Form::Broom,
        "plate" => Form::Plate,
        "dishtowel" | "hand_towel" | "towel" | "rag" | "piece_of_cloth" | "apparel" | "shirt"
        | "sweater" | "sock" | "underwear" | "sheet" => Form::Folded,
        "pen" | "pencil" | "marker" | "highlighter" => Form::Pen,
        "bowl" | "dish" => Form::Bowl,
        "bucket" | "ashcan" => Form::Bucket,
        "pan" | "saucepan" | "caldron" | "teapot" => Form::Pot,
        "jar" => Form::Jar,
        "casserole" => Form::Casserole,
        "car" | "vehicle" => Form::Car,
        "grill" => Form::Grill,
        "vacuum" => Form::Vacuum,
        "headset" | "earphone" => Form::Headphones,
        "sunglass" => Form::Glasses,
        "mouse" => Form::Mouse,
        "printer" | "scanner" | "facsimile" => Form::Office,
        "calculator" => Form::Keypad,
        "backpack" => Form::Backpack,
        "duffel_bag" => Form::Duffel,
        "saw" => Form::Saw,
        "scraper" => Form::Scraper,
        "scrub_brush" => Form::ScrubBrush,
        "dustpan" => Form::Dustpan,
        "hanger" => Form::Hanger,
        "toothpaste" => Form::Tube,
        "painting" => Form::Painting,
        "wreath" => Form::Wreath,
        "plaything" => Form::Teddy,
        "bracelet" => Form::Bangle,
        "jewelry" => Form::Ring,
        "necklace" => Form::Necklace,
        "fish" => Form::Fish,
        "parsley" => Form::Herbs,
        "tea_bag" => Form::TeaBag,
        _ => Form::Primitive,
    };
    match (by_name, shape) {
        (Form::Primitive, Shape::Ball) => Form::Round,
        (form, _) => form,
    }
}

/// Whether an archetype's own boxes are drawn with rounded edges: furniture, appliances,
/// fixtures and boxy things; not floors (flush with the rooms' walls) nor the agent's stand-in.
fn rounds_its_boxes(shape: Shape) -> bool {
    !matches!(shape, Shape::Floor | Shape::Agent)
}

/// The form of one box of a piece of furniture or a fixture: a sofa's seat and back have their
/// cushions and its arms are soft, a bed's mattress is made with a duvet and pillows, a thin
/// upright post of a table or chair is a turned leg, the rest has
/// rounded edges.
fn box_form(shape: Shape, index: usize, half: Vector) -> Form {
    let post = half.z > 3.0 * half.x.max(half.y) && half.x.max(half.y) < 0.04;
    match shape {
        // The sofa's parts: seat, back, arms.
        Shape::Sofa if index == 0 => Form::Seat,
        Shape::Sofa if index == 1 => Form::Backrest,
        Shape::Sofa => Form::Soft,
        // The bed's parts: base, mattress, headboard.
        Shape::Bed if index == 1 => Form::Bedding,
        Shape::Table | Shape::Chair | Shape::Stool if post => Form::Turned,
        _ => Form::Rounded,
    }
}

/// The form of a lid hinged on a body drawn as `body`: a jar's screw cap, a backpack's soft
/// flap; `None` for a lid drawn as the rounded board it is.
fn lid_form(body: Form) -> Option<Form> {
    match body {
        Form::Jar => Some(Form::Lid),
        Form::Backpack => Some(Form::Soft),
        _ => None,
    }
}

/// Sets the forms of a spec built from `archetype`: its body's, and those of its boxes that
/// the family building them left unnamed (a family names what only it knows: a door with its
/// pull, a control panel, a stove's top).
pub(super) fn dress(spec: &mut ObjectSpec, archetype: &Archetype) {
    spec.form = body_form(archetype.synset, archetype.shape);
    if !rounds_its_boxes(archetype.shape) {
        return;
    }
    let shape = archetype.shape;
    let dress_boxes = |parts: &mut Vec<Part>| {
        for (index, part) in parts.iter_mut().enumerate() {
            if let Primitive::Box { half_extents } = part.primitive
                && part.form == Form::Primitive
            {
                part.form = box_form(shape, index, half_extents);
            }
            // A bed's duvet is cloth in the bed's colour, whatever its frame is made of.
            if part.form == Form::Bedding && part.visual.is_none() {
                part.visual = Some(Visual {
                    color: archetype.color,
                    material: Material::Cloth,
                });
            }
        }
    };
    if spec.form == Form::Primitive {
        dress_boxes(&mut spec.parts);
    }
    let lid = lid_form(spec.form);
    for link in &mut spec.links {
        if let Some(form) = lid {
            for part in &mut link.parts {
                part.form = form;
            }
        }
        dress_boxes(&mut link.parts);
    }
}
