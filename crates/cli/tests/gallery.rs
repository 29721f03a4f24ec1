//! `behavior gallery` run as a user would: every archetype asked for drawn twice on a sheet.

mod support;

use support::{behavior, behavior_ok, scratch, stdout};

#[test]
fn the_gallery_draws_each_archetype_in_two_variants_on_a_labelled_sheet() {
    let out = scratch("bowls.png");
    let path = out.to_str().unwrap();
    let output = behavior_ok(&[
        "gallery",
        "--only",
        "bowl.n.01",
        "--tile",
        "64",
        "--out",
        path,
    ]);
    assert!(
        stdout(&output).contains("2 pictures of 1 archetypes (realistic profile)"),
        "{}",
        stdout(&output)
    );
    let sheet = image::open(&out).unwrap().to_rgb8();
    // Two 64² tiles side by side over a 14-pixel caption strip.
    assert_eq!((sheet.width(), sheet.height()), (128, 78));
    let tile = |k: u32| image::imageops::crop_imm(&sheet, 64 * k, 0, 64, 64).to_image();
    assert_ne!(tile(0), tile(1), "the two variants look the same");
    for k in 0..2 {
        // The camera looks at the bowl's middle: a pale glazed bowl, not the brown boards.
        let [r, g, b] = tile(k).get_pixel(32, 32).0;
        assert!(
            b > 120 && r.abs_diff(b) < 80,
            "tile {k}'s middle is {:?}",
            [r, g, b]
        );
    }
    // The caption strip holds dark print (the synset's name) on white.
    let caption = image::imageops::crop_imm(&sheet, 0, 64, 64, 14).to_image();
    let dark = caption
        .pixels()
        .filter(|p| p.0.iter().all(|&c| c < 60))
        .count();
    assert!(dark > 20, "{dark} dark caption pixels");
}

#[test]
fn the_gallery_refuses_a_file_that_is_no_png_and_a_filter_that_matches_nothing() {
    let bad = behavior(&["gallery", "--out", "sheet.jpg"]);
    assert!(!bad.status.success());
    let said = String::from_utf8_lossy(&bad.stderr).into_owned();
    assert!(
        said.contains("SHEET.png") && said.contains("sheet.jpg"),
        "{said}"
    );
    let out = scratch("nothing.png");
    let none = behavior(&[
        "gallery",
        "--only",
        "unicorn",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!none.status.success());
    let said = String::from_utf8_lossy(&none.stderr).into_owned();
    assert!(
        said.contains("no archetype's synset contains `unicorn`"),
        "{said}"
    );
    assert!(!out.exists(), "a sheet was written for nothing");
}
