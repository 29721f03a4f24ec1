//! Detailed visual meshes made in code. The world says how a part looks with one word, a
//! [`Form`]; this crate turns the word, the box the part fills and a seed into a closed triangle
//! mesh with smooth normals ([`mesh`]), in two levels of detail, so that renderers and exporters
//! draw bottles with shoulders and caps, bowls on foot rings, dimpled apples with stems and
//! rounded furniture boards, without an asset download, and the same seed gives the same mesh
//! everywhere.
//!
//! Families by file: `household` (boards, cushions, legs, books, cloth, lamps, plants, a
//! Christmas tree, shoes, hats, a trunk, coat hangers, squeezed tubes, mousetraps), `produce`
//! (and a roast chicken, fish, herbs, tea bags), `tableware` (and jars with their lids, baking
//! dishes, kettles, hamburgers, sushi rolls), `groceries` (cartons, jugs, bags of crisps, paper
//! sacks, steaks, sweets, sandwiches, salads, cookies), `utensils` (knives, forks, spoons,
//! brooms and brushes, hammers, screwdrivers, toothbrushes, umbrellas, saws, scrapers,
//! scrubbing brushes, dustpans), `fittings` (doors and drawer fronts with their pulls, control
//! panels, a stove's top, a tap), `upholstery` (a made bed, a sofa's seat and back),
//! `machines` (a car, a kettle barbecue, an upright vacuum), `gadgets` (headphones, glasses, a
//! mouse, office machines, calculators, blenders, smoke alarms), `bags` (backpacks, duffel
//! bags, briefcases, pencil cases), `decor` (framed pictures, wreaths, teddy bears, bows, spools
//! of ribbon, stockings, candles), `jewelry` (bangles, rings, necklaces, lipsticks).
//!
//! It owns geometry only: it must not know synsets (which form an object takes is the assets'
//! choice), GPUs or the world's state. Every mesh lies inside its box, so what is drawn is what
//! is simulated; [`Mesh::defects`] checks that and that the mesh is closed and wound outward.
//!
//! ```
//! use behavior_forms::{Detail, mesh};
//! use behavior_sim::Form;
//! use rapier3d::math::Vector;
//!
//! let half = Vector::new(0.04, 0.04, 0.11);
//! let bottle = mesh(Form::Bottle, half, 7, Detail::Fine);
//! assert!(bottle.defects(half, 1e-4).is_empty());
//! assert!(bottle.triangles.len() > 300);
//! ```

mod bags;
mod check;
mod decor;
mod dice;
mod extrude;
mod fittings;
mod gadgets;
mod grid;
mod groceries;
mod household;
mod jewelry;
mod lathe;
mod machines;
mod mesh;
mod produce;
mod rounded;
mod tableware;
mod tone;
mod tube;
mod upholstery;
mod utensils;

pub use behavior_sim::Form;
pub use check::Defect;
pub use mesh::Mesh;
pub use tone::Tone;

use dice::Dice;
use rapier3d::math::Vector;

/// How finely a form is cut into triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Detail {
    /// For a form that fills more than a few dozen pixels.
    Fine,
    /// For a form a few pixels across: a quarter of the triangles or fewer.
    Coarse,
}

impl Detail {
    /// Both, finest first.
    pub const ALL: [Detail; 2] = [Detail::Fine, Detail::Coarse];

    /// Steps around a solid of revolution or a tube.
    pub(crate) fn around(self) -> usize {
        match self {
            Detail::Fine => 24,
            Detail::Coarse => 10,
        }
    }

    /// Latitude bands of a grid surface.
    pub(crate) fn bands(self) -> usize {
        match self {
            Detail::Fine => 14,
            Detail::Coarse => 6,
        }
    }

    /// Rows through a rounded edge.
    pub(crate) fn bevel_rows(self) -> usize {
        match self {
            Detail::Fine => 3,
            Detail::Coarse => 1,
        }
    }
}

/// An object's seed from its name (FNV-1a, the low 32 bits): the same object looks the same in
/// every renderer, process and machine, and two objects of one synset differ.
pub fn seed_of(name: &str) -> u32 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    }) as u32
}

/// The radius of a [`Form::Rounded`] box's edges: a quarter of its thinnest half side, at most
/// 12 mm. A renderer may draw the plain box where this is under a pixel.
pub fn bevel(half: Vector) -> f32 {
    (0.25 * half.min_element()).min(0.012)
}

/// The mesh of `form` filling the box `[-half, half]` (z up), varied by `seed`. A form with no
/// mesh of its own ([`Form::Primitive`]) gives the box.
pub fn mesh(form: Form, half: Vector, seed: u64, detail: Detail) -> Mesh {
    let half = half.max(Vector::splat(1e-4));
    let mut dice = Dice::new(seed);
    let ctx = Ctx {
        half,
        detail,
        dice: &mut dice,
    };
    let mut made = match form {
        Form::Primitive | Form::Rounded => household::rounded(ctx),
        Form::Soft => household::soft(ctx),
        Form::Turned => household::turned(ctx),
        Form::Book => household::book(ctx),
        Form::Folded => household::folded(ctx),
        Form::Pen => household::pen(ctx),
        Form::Lamp => household::lamp(ctx),
        Form::Plant => household::plant(ctx),
        Form::Torso => household::torso(ctx),
        Form::Round => produce::round(ctx),
        Form::Apple => produce::apple(ctx),
        Form::Fruit => produce::fruit(ctx),
        Form::Lemon => produce::lemon(ctx),
        Form::Egg => produce::egg(ctx),
        Form::Florets => produce::florets(ctx),
        Form::Mushroom => produce::mushroom(ctx),
        Form::Berry => produce::berry(ctx),
        Form::Banana => produce::banana(ctx),
        Form::Carrot => produce::carrot(ctx),
        Form::Loaf => produce::loaf(ctx),
        Form::Bottle => tableware::bottle(ctx),
        Form::Can => tableware::can(ctx),
        Form::Cup => tableware::cup(ctx),
        Form::Mug => tableware::mug(ctx),
        Form::Bowl => tableware::bowl(ctx),
        Form::Plate => tableware::plate(ctx),
        Form::Pot => tableware::pot(ctx),
        Form::Bucket => tableware::bucket(ctx),
        Form::Cake => tableware::cake(ctx),
        Form::Door => fittings::door(ctx),
        Form::GlassDoor => fittings::glass_door(ctx),
        Form::DrawerFront => fittings::drawer_front(ctx),
        Form::DropDoor => fittings::drop_door(ctx),
        Form::OvenDoor => fittings::oven_door(ctx),
        Form::Porthole => fittings::porthole(ctx),
        Form::Controls => fittings::controls(ctx),
        Form::Cooktop => fittings::cooktop(ctx),
        Form::Tap => fittings::tap(ctx),
        Form::Bedding => upholstery::bedding(ctx),
        Form::Seat => upholstery::seat(ctx),
        Form::Knife => utensils::knife(ctx),
        Form::Fork => utensils::fork(ctx),
        Form::Spoon => utensils::spoon(ctx),
        Form::Broom => utensils::broom(ctx),
        Form::Conifer => household::conifer(ctx),
        Form::Roast => produce::roast(ctx),
        Form::Hammer => utensils::hammer(ctx),
        Form::Screwdriver => utensils::screwdriver(ctx),
        Form::Toothbrush => utensils::toothbrush(ctx),
        Form::Umbrella => utensils::umbrella(ctx),
        Form::Shoe => household::shoe(ctx),
        Form::Hat => household::hat(ctx),
        Form::Jar => tableware::jar(ctx),
        Form::Lid => tableware::lid(ctx),
        Form::Casserole => tableware::casserole(ctx),
        Form::Car => machines::car(ctx),
        Form::Grill => machines::grill(ctx),
        Form::Vacuum => machines::vacuum(ctx),
        Form::Headphones => gadgets::headphones(ctx),
        Form::Glasses => gadgets::glasses(ctx),
        Form::Mouse => gadgets::mouse(ctx),
        Form::Office => gadgets::office(ctx),
        Form::Keypad => gadgets::keypad(ctx),
        Form::Backpack => bags::backpack(ctx),
        Form::Duffel => bags::duffel(ctx),
        Form::Saw => utensils::saw(ctx),
        Form::Scraper => utensils::scraper(ctx),
        Form::ScrubBrush => utensils::scrub_brush(ctx),
        Form::Dustpan => utensils::dustpan(ctx),
        Form::Hanger => household::hanger(ctx),
        Form::Tube => household::squeeze_tube(ctx),
        Form::Painting => decor::painting(ctx),
        Form::Wreath => decor::wreath(ctx),
        Form::Teddy => decor::teddy(ctx),
        Form::Bangle => jewelry::bangle(ctx),
        Form::Ring => jewelry::ring(ctx),
        Form::Necklace => jewelry::necklace(ctx),
        Form::Fish => produce::fish(ctx),
        Form::Herbs => produce::herbs(ctx),
        Form::TeaBag => produce::tea_bag(ctx),
        Form::Burger => tableware::burger(ctx),
        Form::Maki => tableware::maki(ctx),
        Form::Kettle => tableware::kettle(ctx),
        Form::Blender => gadgets::blender(ctx),
        Form::Detector => gadgets::detector(ctx),
        Form::Carton => groceries::carton(ctx),
        Form::Jug => groceries::jug(ctx),
        Form::Pouch => groceries::pouch(ctx),
        Form::Sack => groceries::sack(ctx),
        Form::Steak => groceries::steak(ctx),
        Form::Sweet => groceries::sweet(ctx),
        Form::Sandwich => groceries::sandwich(ctx),
        Form::Salad => groceries::salad(ctx),
        Form::Cookie => groceries::cookie(ctx),
        Form::Bow => decor::bow(ctx),
        Form::Spool => decor::spool(ctx),
        Form::Stocking => decor::stocking(ctx),
        Form::Lipstick => jewelry::lipstick(ctx),
        Form::Mousetrap => household::mousetrap(ctx),
        Form::Briefcase => bags::briefcase(ctx),
        Form::PencilCase => bags::pencil_case(ctx),
        Form::Backrest => upholstery::backrest(ctx),
        Form::Head => household::head(ctx),
        Form::Candle => decor::candle(ctx),
    };
    // Details of a fixed size (a pull's bar, a book's boards) in a box smaller than they are
    // would stick out of it: they are pressed flat against its sides instead, so that what is
    // drawn never leaves what is simulated, whatever size a scene gives.
    made.keep_inside(half);
    made
}

/// A box that `form`'s mesh in the box `[-half, half]` fills wholly, as its centre and half
/// size, for forms that are boxes with things on them (a rounded board, a front with its pull,
/// a mattress with its pillows): a renderer may let it hide what lies behind it. `None` for
/// other forms.
pub fn solid_core(form: Form, half: Vector) -> Option<(Vector, Vector)> {
    match form {
        Form::Rounded => Some((Vector::ZERO, half - Vector::splat(bevel(half)))),
        Form::Door
        | Form::GlassDoor
        | Form::DrawerFront
        | Form::DropDoor
        | Form::OvenDoor
        | Form::Porthole
        | Form::Controls
        | Form::Cooktop => Some(fittings::panel_core(form, half)),
        Form::Bedding | Form::Seat | Form::Backrest => Some(upholstery::core(form, half)),
        _ => None,
    }
}

/// What every form's builder is given.
pub(crate) struct Ctx<'a> {
    /// Half the box it fills, m.
    pub(crate) half: Vector,
    pub(crate) detail: Detail,
    pub(crate) dice: &'a mut Dice,
}
