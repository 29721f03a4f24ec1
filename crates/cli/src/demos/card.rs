//! The dataset card of generated demonstrations: `README.md` and `plots/*.png`, in the manner
//! of the paper's analysis of its 500 human demonstrations (their durations, the distance
//! navigated, the hands' displacement, the rooms visited; overall and per activity), with the
//! provenance said first: these are the planner's, not people's.

use super::generate::{Demo, Manifest};
use crate::map::text;
use crate::prelude::median;
use anyhow::{Context, Result};
use image::{Rgb, RgbImage};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use std::path::Path;

/// A histogram's size, pixels.
const WIDTH: u32 = 640;
const HEIGHT: u32 = 360;
const MARGIN: u32 = 48;
/// Bars per histogram.
const BINS: usize = 20;

/// One statistic of a demonstration, as the card shows it.
struct Measure {
    /// The plot's file stem.
    stem: &'static str,
    /// Its title.
    title: &'static str,
    /// Its value for a demonstration.
    of: fn(&Demo) -> f64,
}

const MEASURES: [Measure; 4] = [
    Measure {
        stem: "duration",
        title: "duration (simulated s)",
        of: |d| d.sim_time_s,
    },
    Measure {
        stem: "distance_navigated",
        title: "distance navigated (m)",
        of: |d| d.distance_navigated_m,
    },
    Measure {
        stem: "hand_displacement",
        title: "hand displacement, both hands (m)",
        of: |d| d.hand_left_m + d.hand_right_m,
    },
    Measure {
        stem: "rooms_visited",
        title: "rooms visited",
        of: |d| d.rooms_visited.len() as f64,
    },
];

/// Writes `README.md` and the plots into `dir`.
pub fn write(dir: &Path, manifest: &Manifest) -> Result<()> {
    let plots = dir.join("plots");
    std::fs::create_dir_all(&plots).with_context(|| format!("cannot make {}", plots.display()))?;
    for m in &MEASURES {
        let values: Vec<f64> = manifest.demos.iter().map(m.of).collect();
        histogram(&values, m.title, &plots.join(format!("{}.png", m.stem)))?;
    }
    let path = dir.join("README.md");
    std::fs::write(&path, card_text(dir, manifest))
        .with_context(|| format!("cannot write {}", path.display()))
}

fn card_text(dir: &Path, manifest: &Manifest) -> String {
    let demos = &manifest.demos;
    let activities: BTreeSet<&str> = demos.iter().map(|d| d.activity.as_str()).collect();
    let tried: BTreeSet<&str> = manifest.tries.iter().map(|t| t.activity.as_str()).collect();
    let bytes: u64 = demos.iter().map(|d| d.bytes).sum();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# BEHAVIOR demonstrations: the planner's, with physics\n"
    );
    let _ = writeln!(
        s,
        "**Provenance: {}.** Every episode here was chosen by this project's task planner \
         running its physical primitives; none is a person's demonstration, and none should \
         be reported as human data. Each recording's header says so too (`provenance`: \
         `{{\"kind\": \"planner\", …}}`).\n",
        manifest.provenance
    );
    let _ = writeln!(
        s,
        "- robot: {}\n- made by: {}\n- demonstrations: {}, of {} activities ({} activities tried), \
         from {} tries ({:.0} % kept)\n- recordings: {:.1} MB in `episodes/`\n- generation: \
         {:.0} s of wall time\n- each kept only if its goal held at the end and a replay from \
         its header matched every checkpoint bit for bit\n",
        manifest.robot,
        manifest.made_by,
        demos.len(),
        activities.len(),
        tried.len(),
        manifest.tries.len(),
        100.0 * demos.len() as f64 / manifest.tries.len().max(1) as f64,
        bytes as f64 / 1e6,
        manifest.wall_s,
    );
    let _ = writeln!(s, "Regenerate or extend (resumes where it stopped):\n");
    let _ = writeln!(
        s,
        "```\nbehavior demos generate --out {} --robot {}\n```\n",
        dir.display(),
        manifest.robot
    );
    let _ = writeln!(s, "## Over all demonstrations\n");
    let _ = writeln!(s, "| statistic | median | mean | min | max | plot |");
    let _ = writeln!(s, "|---|---:|---:|---:|---:|---|");
    for m in &MEASURES {
        let values: Vec<f64> = demos.iter().map(m.of).collect();
        let (lo, hi) = range(&values);
        let _ = writeln!(
            s,
            "| {} | {:.1} | {:.1} | {:.1} | {:.1} | ![](plots/{}.png) |",
            m.title,
            median(values.clone()),
            mean(&values),
            lo,
            hi,
            m.stem
        );
    }
    let _ = writeln!(s, "\n## Per activity (means)\n");
    let _ = writeln!(
        s,
        "| activity | demos | homes | duration s | navigated m | hands m | rooms |"
    );
    let _ = writeln!(s, "|---|---:|---:|---:|---:|---:|---:|");
    let mut by_activity: BTreeMap<&str, Vec<&Demo>> = BTreeMap::new();
    for d in demos {
        by_activity.entry(&d.activity).or_default().push(d);
    }
    for (activity, list) in &by_activity {
        let homes: BTreeSet<&str> = list.iter().map(|d| d.scene.as_str()).collect();
        let avg = |f: fn(&Demo) -> f64| mean(&list.iter().map(|d| f(d)).collect::<Vec<_>>());
        let _ = writeln!(
            s,
            "| {activity} | {} | {} | {:.1} | {:.1} | {:.1} | {:.1} |",
            list.len(),
            homes.len(),
            avg(MEASURES[0].of),
            avg(MEASURES[1].of),
            avg(MEASURES[2].of),
            avg(MEASURES[3].of),
        );
    }
    let missing: Vec<&str> = tried.difference(&activities).copied().collect();
    if !missing.is_empty() {
        let _ = writeln!(s, "\n## Tried, none kept\n");
        for activity in missing {
            let why = manifest
                .tries
                .iter()
                .rev()
                .find(|t| t.activity == activity)
                .map_or("", |t| t.outcome.as_str());
            let _ = writeln!(s, "- {activity}: last try {why}");
        }
    }
    s
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

fn range(values: &[f64]) -> (f64, f64) {
    if values.is_empty() {
        return (0.0, 0.0);
    }
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (lo, hi)
}

/// A histogram of `values` in [`BINS`] bars from their least to their greatest, as a PNG.
fn histogram(values: &[f64], title: &str, path: &Path) -> Result<()> {
    let mut img = RgbImage::from_pixel(WIDTH, HEIGHT, Rgb([255, 255, 255]));
    let black = Rgb([0, 0, 0]);
    let (lo, hi) = range(values);
    let width = if hi > lo {
        (hi - lo) / BINS as f64
    } else {
        1.0
    };
    let mut counts = [0u32; BINS];
    for v in values {
        let bin = (((v - lo) / width) as usize).min(BINS - 1);
        counts[bin] += 1;
    }
    let most = counts.iter().copied().max().unwrap_or(0).max(1);
    let (left, right, top, bottom) = (MARGIN, WIDTH - MARGIN, MARGIN, HEIGHT - MARGIN);
    let bar = (right - left) / BINS as u32;
    for (k, &n) in counts.iter().enumerate() {
        let h = (bottom - top) * n / most;
        let x0 = left + k as u32 * bar;
        for x in x0 + 1..x0 + bar {
            for y in bottom - h..bottom {
                img.put_pixel(x, y, Rgb([60, 120, 190]));
            }
        }
    }
    for x in left..=right {
        img.put_pixel(x, bottom, black);
    }
    for y in top..=bottom {
        img.put_pixel(left, y, black);
    }
    let heading = format!("{title}: {} demonstrations", values.len());
    text(&mut img, &heading, WIDTH as f32 / 2.0, 20.0, 1, black);
    let mid = (bottom + MARGIN / 2) as f32;
    text(&mut img, &format!("{lo:.1}"), left as f32, mid, 1, black);
    text(&mut img, &format!("{hi:.1}"), right as f32, mid, 1, black);
    text(
        &mut img,
        &format!("{most}"),
        (left / 2) as f32,
        top as f32,
        1,
        black,
    );
    img.save(path)
        .with_context(|| format!("cannot write {}", path.display()))
}
