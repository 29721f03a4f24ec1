//! `behavior demos generate`: the planner's physical demonstrations, made, checked and kept.
//!
//! For each activity the generator goes through its covering homes in turn (home 1 seed 0,
//! home 2 seed 0, …, home 1 seed 1, …), so that a few demonstrations already come from several
//! homes. Each try samples the instance, records the planner's physical solution (MCAP, its
//! provenance the planner's), and keeps it only if the goal holds at the end and a replay of
//! the file from its header reproduces every checkpoint bit for bit. A kept recording is moved
//! under `episodes/ACTIVITY/` only when whole; the manifest (`demos.json`, every try and every
//! kept demonstration with its statistics) is rewritten after each try by a rename, so a
//! generator stopped at any moment leaves a readable folder, and a rerun with the same folder
//! goes on from where it stopped (tries already made are not made again; the recording of a
//! try cut short is removed and the try made again).

use super::card;
use crate::prelude::{Prelude, counting_bar};
use crate::sample::all_covering;
use crate::solve::{planner, solve_env};
use anyhow::{Context, Result, bail};
use behavior_assets::Scene;
use behavior_bddl::Activity;
use behavior_env::Env;
use behavior_env::record::{RecordingSetup, read, replay_with};
use behavior_planning::{Limits, Mode, RecordedCall, RunError, Solution, Solver, Watcher};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

/// The manifest's file name in the output folder.
pub const MANIFEST: &str = "demos.json";
/// A demonstration's checkpoints (digest and full state) come every this many steps, and at its
/// last: a home's full state is about 1.4 MB before compression, and at the usual 100 steps the
/// states were nine tenths of a demonstration's file.
const DEMO_CHECKPOINT_EVERY: u32 = 1000;

#[derive(clap::Args)]
pub struct GenerateArgs {
    /// The dataset's folder: made if missing; one made before is resumed.
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Demonstrations kept per activity.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    per_activity: u32,
    /// Only these activities (official names or BDDL files), comma-separated or repeated;
    /// default: every official one.
    #[arg(long = "activities", value_delimiter = ',', value_name = "A,B,...")]
    activities: Vec<String>,
    /// The embodiment: behavior, fetch or r1.
    #[arg(long, default_value = "behavior")]
    robot: String,
    /// Tries per activity at most (each a home and seed), kept or not.
    #[arg(long, default_value_t = 15, value_parser = clap::value_parser!(u32).range(1..=10000))]
    tries: u32,
    /// Print the manifest as JSON at the end.
    #[arg(long)]
    json: bool,
}

/// What a dataset of demonstrations holds: `demos.json`.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Manifest {
    /// The robot of every demonstration.
    pub robot: String,
    /// Who chose the actions: the planner, always (never people).
    pub provenance: String,
    /// The crate version that made them (a replay needs the same build's physics).
    pub made_by: String,
    /// The demonstrations kept.
    pub demos: Vec<Demo>,
    /// Every try, kept or not.
    pub tries: Vec<Try>,
    /// Seconds spent generating, over every run of the generator on this folder.
    pub wall_s: f64,
}

/// One demonstration kept, with the statistics the paper gives of its human demonstrations.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Demo {
    /// The activity's problem name.
    pub activity: String,
    /// The home.
    pub scene: String,
    /// The seed of the instance.
    pub seed: u64,
    /// The recording, relative to the dataset's folder.
    pub file: String,
    /// The recording's size, bytes.
    pub bytes: u64,
    /// Action steps (30 per simulated second).
    pub steps: u32,
    /// Simulated duration, s.
    pub sim_time_s: f64,
    /// The base's distance travelled, m.
    pub distance_navigated_m: f64,
    /// The left (or only) hand's displacement while touching or holding, m.
    pub hand_left_m: f64,
    /// The right hand's, m (0 for a one-handed robot).
    pub hand_right_m: f64,
    /// The rooms the base stood in, in the order first entered.
    pub rooms_visited: Vec<String>,
    /// Primitives run.
    pub primitives: usize,
    /// Wall time of the solve, s.
    pub solve_s: f64,
    /// Checkpoints the replay compared, all identical.
    pub checkpoints: u32,
}

/// One try: an activity, home and seed, and what came of it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Try {
    /// The activity's problem name.
    pub activity: String,
    /// The home (empty where none covers the activity).
    pub scene: String,
    /// The seed of the instance.
    pub seed: u64,
    /// Whether a demonstration was kept.
    pub kept: bool,
    /// `kept`, or why not (the first failed primitive and its reason, a sampling failure, a
    /// replay that differed).
    pub outcome: String,
}

pub fn run(args: GenerateArgs, data_dir: Option<&Path>) -> Result<ExitCode> {
    let prelude = Prelude::load(data_dir)?;
    crate::episode::robot_kind(&args.robot)?;
    let names = prelude.activity_names(&args.activities)?;
    std::fs::create_dir_all(args.out.join("episodes"))
        .with_context(|| format!("cannot make {}", args.out.display()))?;
    let mut manifest = load_manifest(&args.out, &args.robot)?;
    remove_partials(&args.out.join("episodes"))?;
    let bar = counting_bar(names.len(), args.json);
    let began = Instant::now();
    let wall_before = manifest.wall_s;
    for name in &names {
        bar.set_message(name.clone());
        let source = prelude.source(name)?;
        let activity = Arc::new(prelude.load_activity(&source)?);
        let ctx = Tries {
            prelude: &prelude,
            definition: &source.text,
            activity: &activity,
            robot: &args.robot,
            out: &args.out,
        };
        generate_for(&ctx, &args, &mut manifest, |m| {
            m.wall_s = wall_before + began.elapsed().as_secs_f64();
            save_manifest(&args.out, m)
        })?;
        bar.inc(1);
    }
    bar.finish_and_clear();
    manifest.wall_s = wall_before + began.elapsed().as_secs_f64();
    save_manifest(&args.out, &manifest)?;
    card::write(&args.out, &manifest)?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&manifest)?);
    } else {
        let activities: BTreeSet<&str> =
            manifest.demos.iter().map(|d| d.activity.as_str()).collect();
        println!(
            "{}: {} demonstrations of {} activities kept from {} tries ({} robot, the planner's, physical) in {:.0} s; card in README.md",
            args.out.display(),
            manifest.demos.len(),
            activities.len(),
            manifest.tries.len(),
            manifest.robot,
            manifest.wall_s
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// What every try of one activity shares.
struct Tries<'a> {
    prelude: &'a Prelude,
    /// The activity's BDDL text, kept in each recording.
    definition: &'a str,
    activity: &'a Arc<Activity>,
    robot: &'a str,
    out: &'a Path,
}

/// Tries homes and seeds for one activity until `per_activity` demonstrations are kept or the
/// tries run out; `save` is called after each try.
fn generate_for(
    ctx: &Tries<'_>,
    args: &GenerateArgs,
    manifest: &mut Manifest,
    mut save: impl FnMut(&mut Manifest) -> Result<()>,
) -> Result<()> {
    let name = &ctx.activity.name;
    let library = ctx.prelude.library();
    let homes = all_covering(ctx.activity, &library, &ctx.prelude.knowledge().taxonomy)?;
    if homes.is_empty() {
        let said = manifest.tries.iter().any(|t| t.activity == *name);
        if !said {
            manifest.tries.push(Try {
                activity: name.clone(),
                scene: String::new(),
                seed: 0,
                kept: false,
                outcome: "no home has the rooms it needs".into(),
            });
            save(manifest)?;
        }
        return Ok(());
    }
    for t in 0..args.tries {
        let kept = manifest
            .demos
            .iter()
            .filter(|d| d.activity == *name)
            .count();
        if kept >= args.per_activity as usize {
            break;
        }
        let home = &homes[t as usize % homes.len()];
        let seed = u64::from(t) / homes.len() as u64;
        let tried = |x: &Try| x.activity == *name && x.scene == home.name && x.seed == seed;
        if manifest.tries.iter().any(tried) {
            continue;
        }
        let (attempt, demo) = try_one(ctx, home, seed)?;
        manifest.tries.push(attempt);
        manifest.demos.extend(demo);
        save(manifest)?;
    }
    Ok(())
}

/// One try: sample, solve while recording, replay; the demonstration if kept.
fn try_one(ctx: &Tries<'_>, home: &Scene, seed: u64) -> Result<(Try, Option<Demo>)> {
    let name = ctx.activity.name.clone();
    let mut attempt = Try {
        activity: name.clone(),
        scene: home.name.clone(),
        seed,
        kept: false,
        outcome: String::new(),
    };
    let taxonomy = Arc::new(ctx.prelude.knowledge().taxonomy.clone());
    let library = ctx.prelude.library();
    let mut env = solve_env(
        ctx.activity,
        home.clone(),
        &library,
        ctx.robot,
        &taxonomy,
        Mode::Physical,
    )?;
    if let Err(e) = env.reset(seed) {
        attempt.outcome = format!("not sampled: {e}");
        return Ok((attempt, None));
    }
    let relative = format!("episodes/{name}/{}-seed{seed}.mcap", home.name);
    let partial = ctx
        .out
        .join(format!("episodes/.partial-{}.mcap", std::process::id()));
    let setup =
        RecordingSetup::new(ctx.definition, DEMO_CHECKPOINT_EVERY).by(planner(Mode::Physical));
    env.record_to(&partial, setup)?;
    let mut rooms = RoomsVisited::default();
    let mut quiet = |_: &_| {};
    let began = Instant::now();
    let solution = Solver::new(
        &mut env,
        Mode::Physical,
        Limits::default(),
        Some(&mut rooms),
        &mut quiet,
    )
    .solve();
    let solve_s = began.elapsed().as_secs_f64();
    env.finish_recording()?;
    let kept = solution
        .map_err(|e| format!("the episode failed: {e}"))
        .and_then(|solution| match solution.success {
            true => verify(ctx, &partial).map(|checkpoints| (solution, checkpoints)),
            false => Err(not_solved(&solution)),
        });
    let (solution, checkpoints) = match kept {
        Ok(kept) => kept,
        Err(why) => {
            let _ = std::fs::remove_file(&partial);
            attempt.outcome = why;
            return Ok((attempt, None));
        }
    };
    let path = ctx.out.join(&relative);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot make {}", dir.display()))?;
    }
    std::fs::rename(&partial, &path)
        .with_context(|| format!("cannot move the recording to {}", path.display()))?;
    let metrics = env.metrics().context("a solved episode has metrics")?;
    attempt.kept = true;
    attempt.outcome = "kept".into();
    let demo = Demo {
        activity: name,
        scene: home.name.clone(),
        seed,
        file: relative,
        bytes: std::fs::metadata(&path).map_or(0, |m| m.len()),
        steps: metrics.steps,
        sim_time_s: metrics.sim_time_s,
        distance_navigated_m: metrics.distance_navigated,
        hand_left_m: metrics.hand_displacement_left,
        hand_right_m: metrics.hand_displacement_right,
        rooms_visited: rooms.rooms,
        primitives: solution.primitives.len(),
        solve_s,
        checkpoints,
    };
    Ok((attempt, Some(demo)))
}

/// Why an unsolved try is not kept: its first failed primitive and why, else why it stopped.
fn not_solved(solution: &Solution) -> String {
    match solution.primitives.iter().find(|p| p.reason.is_some()) {
        Some(p) => format!(
            "not solved: {} {}: {}",
            p.name,
            p.object,
            p.reason.as_deref().unwrap_or_default()
        ),
        None => format!("not solved: {}", solution.stopped),
    }
}

/// The recording at `path` replayed from its own header: the checkpoints compared, or why it
/// is not kept.
fn verify(ctx: &Tries<'_>, path: &Path) -> std::result::Result<u32, String> {
    let recording = read(path).map_err(|e| format!("unreadable recording: {e}"))?;
    if let Some(damage) = &recording.damage {
        return Err(format!("damaged recording: {damage}"));
    }
    let config = recording
        .config_from(ctx.prelude.knowledge())
        .map_err(|e| format!("no replay: {e}"))?;
    let report = replay_with::<RecordedCall>(&recording, config)
        .map_err(|e| format!("the replay failed: {e}"))?;
    if !report.identical {
        let step = report.first_difference.unwrap_or_default();
        return Err(format!("the replay differs from step {step}"));
    }
    if report.q_final < 1.0 {
        return Err(format!("the replay ends with Q = {:.3}", report.q_final));
    }
    Ok(report.checkpoints)
}

/// The rooms the robot's base stands in, step by step, in the order first entered.
#[derive(Default)]
struct RoomsVisited {
    rooms: Vec<String>,
}

impl Watcher for RoomsVisited {
    fn stepped(&mut self, env: &Env, _action: &[f32]) -> std::result::Result<(), RunError> {
        let (Some(world), Some(robot)) = (env.world(), env.robot()) else {
            return Ok(());
        };
        let at = robot.embodiment().base_pose(world).translation;
        let room = world.rooms().iter().find(|r| r.contains(at.x, at.y));
        if let Some(room) = room {
            let label = format!("{}_{}", room.kind.name(), room.instance);
            if !self.rooms.contains(&label) {
                self.rooms.push(label);
            }
        }
        Ok(())
    }
}

/// The folder's manifest, or a new one; refused if it is another robot's.
fn load_manifest(out: &Path, robot: &str) -> Result<Manifest> {
    let path = out.join(MANIFEST);
    if !path.exists() {
        return Ok(Manifest {
            robot: robot.to_string(),
            provenance: "the task planner's physical primitives (not people)".into(),
            made_by: format!("behavior {}", env!("CARGO_PKG_VERSION")),
            ..Manifest::default()
        });
    }
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let manifest: Manifest = serde_json::from_str(&text)
        .with_context(|| format!("{} is not a demonstrations manifest", path.display()))?;
    if manifest.robot != robot {
        bail!(
            "{} holds the {} robot's demonstrations, not the {robot} robot's: give another folder",
            out.display(),
            manifest.robot
        );
    }
    Ok(manifest)
}

/// Removes the recordings a generator stopped mid-try left (`episodes/.partial-PID.mcap`):
/// never kept, and the try is made again. One generator at a time works in a folder.
fn remove_partials(episodes: &Path) -> Result<()> {
    let entries = std::fs::read_dir(episodes)
        .with_context(|| format!("cannot read {}", episodes.display()))?;
    for entry in entries.flatten() {
        if entry.file_name().to_string_lossy().starts_with(".partial-") {
            let path = entry.path();
            std::fs::remove_file(&path)
                .with_context(|| format!("cannot remove {}", path.display()))?;
        }
    }
    Ok(())
}

/// Writes the manifest beside its place and renames it there: never half-written.
fn save_manifest(out: &Path, manifest: &Manifest) -> Result<()> {
    let path = out.join(MANIFEST);
    let partial = out.join(format!(".{MANIFEST}.partial"));
    std::fs::write(&partial, serde_json::to_string_pretty(manifest)?)
        .with_context(|| format!("cannot write {}", partial.display()))?;
    std::fs::rename(&partial, &path).with_context(|| format!("cannot write {}", path.display()))
}
