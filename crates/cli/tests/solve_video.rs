//! `behavior solve --video` run as a user would: the planner's episode filmed as an animated GIF
//! whose path it prints; a file that is not `.gif` refused before the planner runs.

mod support;

use support::{behavior, behavior_ok, scratch};

#[test]
fn a_solve_is_filmed_into_the_gif_it_names() {
    let out = scratch("solve.gif");
    let output = behavior_ok(&[
        "solve",
        "re-shelving_library_books",
        "--video",
        out.to_str().unwrap(),
        "--video-size",
        "64",
        "--profile",
        "fast",
    ]);
    let printed = String::from_utf8_lossy(&output.stdout);
    let line = printed
        .lines()
        .find(|l| l.contains("video of"))
        .unwrap_or_else(|| panic!("no video line in {printed}"));
    assert!(line.contains(out.to_str().unwrap()), "{line}");
    let frames: u32 = line
        .split_whitespace()
        .nth(2)
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no frame count in {line}"));
    assert!(frames >= 2, "{frames} frames");
    let file = std::fs::read(&out).unwrap();
    assert_eq!(&file[..6], b"GIF89a", "not a GIF");
    // Two 64-pixel pictures side by side, over the caption and Q's curve.
    let (width, height) = (
        u16::from_le_bytes([file[6], file[7]]),
        u16::from_le_bytes([file[8], file[9]]),
    );
    assert_eq!((width, height), (128, 64 + 20 + 40));
}

#[test]
fn a_video_that_is_not_a_gif_is_refused() {
    let out = scratch("solve.mp4");
    let output = behavior(&["solve", "--video", out.to_str().unwrap()]);
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(said.contains("FILE.gif"), "{said}");
    assert!(!out.exists());
}
