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

#[test]
fn the_robots_sheet_shows_fetch_in_its_makers_meshes_and_each_robot_from_two_sides() {
    let draw = |name: &str, assets: Option<&str>| {
        let out = scratch(name);
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_behavior"));
        command.args(["gallery", "--robots", "--tile", "96", "--out"]);
        command.arg(&out);
        if let Some(value) = assets {
            command.env("BEHAVIOR_ROBOT_ASSETS", value);
        }
        let output = command.output().unwrap();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        assert!(
            stdout(&output).contains("6 pictures of 3 robots"),
            "{}",
            stdout(&output)
        );
        image::open(&out).unwrap().to_rgb8()
    };
    let meshes = draw("robots.png", None);
    let plain = draw("robots-plain.png", Some("none"));
    assert_eq!((meshes.width(), meshes.height()), (6 * 96, 96 + 14));
    let tile = |sheet: &image::RgbImage, k: u32| {
        image::imageops::crop_imm(sheet, 96 * k, 0, 96, 96).to_image()
    };
    // The BehaviorRobot (tiles 0 and 1) and the R1 (4 and 5) have no meshes to fetch: the
    // same either way. Fetch (2 and 3) is drawn differently from its makers' meshes, and each
    // robot differs by side.
    for k in [0, 1, 4, 5] {
        assert_eq!(tile(&meshes, k), tile(&plain, k), "tile {k}");
    }
    for k in 2..4 {
        let changed = tile(&meshes, k)
            .pixels()
            .zip(tile(&plain, k).pixels())
            .filter(|(a, b)| a != b)
            .count();
        assert!(changed > 300, "tile {k}: {changed} pixels differ");
    }
    assert_ne!(tile(&meshes, 2), tile(&meshes, 3));
    assert_ne!(tile(&meshes, 0), tile(&meshes, 1));
    assert_ne!(tile(&meshes, 4), tile(&meshes, 5));
    let refused = behavior(&["gallery", "--robots", "--only", "bowl", "--out", "x.png"]);
    assert!(!refused.status.success(), "--robots with --only");
}
