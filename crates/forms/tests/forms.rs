//! Every form's mesh, at both levels of detail, in boxes of many proportions and for several
//! seeds, is fit to draw: closed, wound outward, without slivers, inside its box.

use behavior_forms::{Detail, Form, mesh};
use rapier3d::math::Vector;

/// Boxes of the proportions a form is given (half sizes, m): round things, things lying along
/// x, flat things, upright things, and boxes of every kind for the boxy forms. The assets' own
/// test checks every archetype at the sizes it is built at.
fn boxes(form: Form) -> Vec<Vector> {
    let round = [
        [0.04, 0.04, 0.04],
        [0.05, 0.045, 0.04],
        [0.0025, 0.0025, 0.0025],
    ];
    let lying = [[0.1, 0.02, 0.02], [0.07, 0.006, 0.006], [0.7, 0.025, 0.025]];
    let flat = [[0.12, 0.12, 0.012], [0.2, 0.14, 0.03], [0.11, 0.11, 0.05]];
    let upright = [[0.04, 0.04, 0.11], [0.06, 0.05, 0.06], [0.2, 0.2, 0.3]];
    let any = [
        [0.04, 0.04, 0.04],
        [0.12, 0.12, 0.01],
        [0.02, 0.02, 0.4],
        [0.5, 0.02, 0.3],
    ];
    let list: Vec<[f32; 3]> = match form {
        Form::Primitive | Form::Rounded | Form::Soft => any.to_vec(),
        Form::Banana
        | Form::Carrot
        | Form::Pen
        | Form::Knife
        | Form::Fork
        | Form::Spoon
        | Form::Broom
        | Form::Hammer
        | Form::Screwdriver
        | Form::Toothbrush
        | Form::Umbrella
        | Form::Tube => lying.to_vec(),
        Form::Shoe => vec![[0.05, 0.15, 0.05], [0.06, 0.16, 0.07], [0.05, 0.14, 0.02]],
        Form::Hat => vec![[0.15, 0.15, 0.06], [0.17, 0.17, 0.075], [0.04, 0.04, 0.02]],
        Form::Roast => flat.to_vec(),
        Form::Lid => vec![[0.04, 0.04, 0.008], [0.05, 0.05, 0.01], [0.03, 0.03, 0.005]],
        Form::Casserole => vec![[0.15, 0.1, 0.04], [0.17, 0.12, 0.045]],
        // A car at a car's size and at a toy's.
        Form::Car => vec![[2.0, 0.85, 0.7], [1.8, 0.8, 0.72], [0.1, 0.05, 0.04]],
        Form::Grill => vec![[0.3, 0.25, 0.5], [0.6, 0.35, 0.55]],
        Form::Vacuum => vec![[0.15, 0.125, 0.5], [0.2, 0.175, 0.55]],
        Form::Headphones => vec![[0.08, 0.04, 0.08], [0.1, 0.05, 0.1], [0.02, 0.02, 0.015]],
        Form::Glasses => vec![[0.07, 0.02, 0.02], [0.075, 0.03, 0.025]],
        Form::Mouse => vec![[0.03, 0.05, 0.015], [0.035, 0.06, 0.0225]],
        Form::Office => vec![[0.2, 0.15, 0.1], [0.25, 0.18, 0.06], [0.15, 0.12, 0.06]],
        Form::Keypad => vec![[0.035, 0.06, 0.005], [0.05, 0.09, 0.0125]],
        Form::Backpack => vec![[0.14, 0.075, 0.2], [0.175, 0.11, 0.25]],
        Form::Duffel => vec![[0.22, 0.12, 0.12], [0.35, 0.17, 0.17], [0.3, 0.15, 0.08]],
        Form::Saw => vec![[0.22, 0.05, 0.01], [0.32, 0.075, 0.015]],
        Form::Scraper => vec![[0.1, 0.04, 0.01], [0.17, 0.06, 0.015]],
        Form::ScrubBrush => vec![[0.06, 0.03, 0.02], [0.1, 0.045, 0.035]],
        Form::Dustpan => vec![[0.11, 0.125, 0.02], [0.16, 0.175, 0.05]],
        Form::Hanger => vec![[0.19, 0.09, 0.004], [0.22, 0.11, 0.0075]],
        Form::Painting => vec![[0.15, 0.125, 0.01], [0.45, 0.35, 0.02], [0.3, 0.3, 0.015]],
        Form::Wreath => vec![[0.15, 0.15, 0.03], [0.3, 0.3, 0.06]],
        Form::Teddy => vec![[0.025, 0.025, 0.025], [0.125, 0.1, 0.1], [0.1, 0.08, 0.12]],
        Form::Bangle => vec![[0.03, 0.03, 0.004], [0.04, 0.04, 0.01]],
        Form::Ring => vec![[0.01, 0.01, 0.0025], [0.03, 0.025, 0.01]],
        Form::Necklace => vec![[0.025, 0.025, 0.003], [0.06, 0.05, 0.0075]],
        Form::Fish => vec![[0.075, 0.035, 0.01], [0.175, 0.06, 0.03]],
        Form::Herbs => vec![[0.03, 0.025, 0.06], [0.05, 0.04, 0.1]],
        Form::TeaBag => vec![[0.025, 0.03, 0.002], [0.0325, 0.0375, 0.004]],
        Form::Detector => vec![[0.05, 0.05, 0.0175], [0.07, 0.07, 0.025]],
        Form::Steak => vec![[0.06, 0.04, 0.0125], [0.125, 0.075, 0.04]],
        Form::Sweet => vec![[0.01, 0.01, 0.005], [0.04, 0.02, 0.01]],
        Form::Sandwich | Form::Cookie => flat.to_vec(),
        Form::Bow => vec![[0.035, 0.035, 0.02], [0.07, 0.07, 0.035]],
        Form::Spool => vec![[0.03, 0.03, 0.01], [0.05, 0.05, 0.025]],
        Form::Mousetrap => vec![[0.04, 0.02, 0.0075], [0.055, 0.03, 0.015]],
        Form::Briefcase => vec![[0.2, 0.15, 0.04], [0.23, 0.17, 0.06]],
        Form::PencilCase => vec![[0.09, 0.03, 0.015], [0.12, 0.05, 0.03]],
        Form::Conifer => vec![[0.3, 0.3, 0.6], [0.55, 0.55, 1.05], [0.1, 0.1, 0.2]],
        Form::Plate | Form::Book | Form::Folded | Form::Cake | Form::Burger | Form::Maki => {
            flat.to_vec()
        }
        Form::Lemon | Form::Egg => [round.as_slice(), &lying[..1], &upright[..1]].concat(),
        Form::Round
        | Form::Apple
        | Form::Fruit
        | Form::Florets
        | Form::Mushroom
        | Form::Berry
        | Form::Loaf => [round.as_slice(), &flat[2..]].concat(),
        // A crown of thin leaves stretched into a box thrice as tall as wide would stand its
        // leaves' rims on edge: plants and lamps get their own proportions.
        Form::Plant | Form::Lamp => {
            vec![[0.075, 0.075, 0.125], [0.175, 0.175, 0.4], [0.1, 0.1, 0.2]]
        }
        // Fronts are thin along y: a cabinet's door, a fridge's, a drawer's front, a
        // microwave's door, a home's door; control panels are low strips.
        Form::Door
        | Form::GlassDoor
        | Form::DrawerFront
        | Form::DropDoor
        | Form::OvenDoor
        | Form::Porthole => vec![
            [0.3, 0.015, 0.4],
            [0.4, 0.015, 0.85],
            [0.2, 0.01, 0.1],
            [0.25, 0.0105, 0.14],
            [0.45, 0.05, 1.0],
        ],
        Form::Controls => vec![[0.35, 0.025, 0.03], [0.38, 0.025, 0.05], [0.1, 0.01, 0.01]],
        Form::Cooktop => vec![[0.3, 0.3, 0.45], [0.38, 0.35, 0.475], [0.1, 0.1, 0.1]],
        Form::Tap => vec![[0.02, 0.02, 0.15], [0.03, 0.03, 0.2]],
        // A bed's mattress and a sofa's seat.
        Form::Bedding => vec![[0.48, 0.99, 0.1], [0.98, 1.04, 0.12], [0.3, 0.5, 0.05]],
        Form::Seat => vec![[0.8, 0.4, 0.225], [1.2, 0.5, 0.2], [0.3, 0.3, 0.1]],
        Form::Head => vec![[0.1, 0.085, 0.11], [0.05, 0.05, 0.05]],
        Form::Backrest => vec![[0.8, 0.1, 0.2], [1.2, 0.1, 0.25], [0.3, 0.1, 0.1]],
        _ => upright.to_vec(),
    };
    list.into_iter().map(Vector::from_array).collect()
}

#[test]
fn every_form_is_closed_outward_and_inside_its_box() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for form in Form::ALL {
        for detail in Detail::ALL {
            for half in boxes(form) {
                for seed in [0, 1, 77, 0xdead_beef] {
                    let m = mesh(form, half, seed, detail);
                    checked += 1;
                    if let Some(d) = m.defects(half, 1e-6).first() {
                        failures.push(format!("{form:?} {detail:?} {half} seed {seed}: {d}"));
                    }
                    // Inside its box by its own proportions, not by being pressed into it.
                    if m.pressed > 1e-6 {
                        failures.push(format!(
                            "{form:?} {detail:?} {half} seed {seed}: pressed {} m into its box",
                            m.pressed
                        ));
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {checked} meshes are not fit to draw:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(checked > 500, "only {checked} meshes checked");
}

#[test]
fn a_form_fills_its_box() {
    for form in Form::ALL {
        let half = Vector::new(0.05, 0.04, 0.07);
        let (lo, hi) = mesh(form, half, 3, Detail::Fine).bounds();
        // Forms stretched to their box touch it on every side; forms built at their true size
        // (a mug's body and handle, a book, folded cloth) come within a fifth of it; a torso
        // is 0.6 as deep as its (round) collider; a hanger is its wire's thickness.
        let mut filled = (hi - lo) / (2.0 * half);
        if form == Form::Torso {
            assert!((filled.x - 0.6).abs() < 1e-3, "{form:?} fills {filled}");
            filled.x /= 0.6;
        }
        // A wire coat hanger is as thick as its wire, whatever the box's height.
        if form == Form::Hanger {
            filled.z = 1.0;
        }
        assert!(
            filled.min_element() > 0.8,
            "{form:?} fills only {filled} of its box"
        );
    }
}

#[test]
fn seeds_vary_a_form_and_repeat_it() {
    let half = Vector::new(0.05, 0.05, 0.12);
    let mut varied = 0;
    for form in Form::ALL {
        let a = mesh(form, half, 1, Detail::Fine);
        assert_eq!(
            a,
            mesh(form, half, 1, Detail::Fine),
            "{form:?} differs for one seed"
        );
        if a != mesh(form, half, 2, Detail::Fine) {
            varied += 1;
        }
    }
    // Boxes, cans, eggs, lemons and the like have one shape; the rest vary with the seed.
    assert!(varied >= 16, "only {varied} forms vary with the seed");
}

#[test]
fn the_coarse_level_has_at_most_half_the_triangles() {
    let half = Vector::new(0.05, 0.05, 0.12);
    for form in Form::ALL {
        let fine = mesh(form, half, 5, Detail::Fine).triangles.len();
        let coarse = mesh(form, half, 5, Detail::Coarse).triangles.len();
        assert!(
            2 * coarse <= fine,
            "{form:?}: {coarse} coarse triangles against {fine} fine"
        );
    }
}

#[test]
fn no_form_panics_in_an_odd_box() {
    // Sizes come from scene files and archetypes' ranges: a form must make some mesh for any
    // box, however thin, tiny or long, and stay inside it (pressed into it where its details
    // are bigger than the box).
    let odd = [
        [1e-4, 1e-4, 1e-4],
        [0.003, 0.2, 0.002],
        [2.0, 0.001, 0.001],
        [0.001, 0.001, 1.5],
        [0.01, 0.01, 0.01],
        [3.0, 3.0, 0.004],
    ];
    let mut failures = Vec::new();
    for form in Form::ALL {
        for half in odd.map(Vector::from_array) {
            for detail in Detail::ALL {
                let m = mesh(form, half, 9, detail);
                let (lo, hi) = m.bounds();
                let slack = Vector::splat(1e-4);
                if m.triangles.is_empty() {
                    failures.push(format!("{form:?} {detail:?} {half}: no triangles"));
                } else if lo.cmplt(-half - slack).any() || hi.cmpgt(half + slack).any() {
                    failures.push(format!(
                        "{form:?} {detail:?} {half}: drawn over {lo} .. {hi}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
