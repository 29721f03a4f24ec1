//! `behavior demos export --lerobot` as a user runs it: an agent's episode and the planner's
//! solution (with its recorded primitives) made into a LeRobot dataset, read back with the
//! Parquet reader; bad input refused without touching what exists.

#![cfg(feature = "lerobot")]

mod support;

use arrow_array::{
    Array, BinaryArray, BooleanArray, FixedSizeListArray, Float32Array, Int64Array, RecordBatch,
    StructArray,
};
use behavior_env::record::read;
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use serde_json::Value;
use std::path::Path;
use support::{behavior, behavior_ok, scratch};

/// Runs an export that must fail; returns what it said.
fn refused_export(dir: &Path, recordings: &[&Path]) -> String {
    let mut args = vec!["demos", "export", "--lerobot", dir.to_str().unwrap()];
    args.extend(recordings.iter().map(|r| r.to_str().unwrap()));
    let output = behavior(&args);
    assert!(!output.status.success(), "{args:?} succeeded");
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn json_file(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn lines(path: &Path) -> Vec<Value> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

fn column<'a, T: 'static>(batch: &'a RecordBatch, name: &str) -> &'a T {
    batch
        .column_by_name(name)
        .unwrap_or_else(|| panic!("no column {name}"))
        .as_any()
        .downcast_ref::<T>()
        .unwrap_or_else(|| panic!("{name} has another type"))
}

#[test]
fn recordings_export_to_a_lerobot_dataset_that_reads_back() {
    let run = scratch("demos-run.mcap");
    let solved = scratch("demos-solved.mcap");
    let (run_s, solved_s) = (run.to_str().unwrap(), solved.to_str().unwrap());
    behavior_ok(&[
        "run", "--agent", "random", "--steps", "24", "--record", run_s,
    ]);
    behavior_ok(&[
        "solve",
        "throwing_away_leftovers",
        "--mode",
        "symbolic",
        "--record",
        solved_s,
    ]);
    let dir = scratch("demos-dataset");
    let _ = std::fs::remove_dir_all(&dir);
    let out = behavior_ok(&[
        "demos",
        "export",
        "--lerobot",
        dir.to_str().unwrap(),
        run_s,
        solved_s,
        "--image-size",
        "32",
        "--json",
    ]);
    let summary: Value = serde_json::from_slice(&out.stdout).unwrap();
    let recordings = [read(&run).unwrap(), read(&solved).unwrap()];
    let steps: Vec<usize> = recordings.iter().map(|r| r.frames.len()).collect();
    assert_eq!(summary["episodes"], 2);
    assert_eq!(summary["frames"], steps[0] + steps[1]);
    assert_eq!(summary["teleoperated"], 0);

    let info = json_file(&dir.join("meta/info.json"));
    assert_eq!(info["codebase_version"], "v2.1");
    assert_eq!(info["fps"], 30);
    assert_eq!(info["total_episodes"], 2);
    assert_eq!(info["total_tasks"], 2);
    assert_eq!(info["features"]["action"]["shape"][0], 26);
    assert_eq!(
        info["features"]["observation.images.eye"]["shape"],
        serde_json::json!([32, 32, 3])
    );
    let episodes = lines(&dir.join("meta/episodes.jsonl"));
    assert_eq!(episodes[1]["tasks"][0], "throwing away leftovers");
    assert_eq!(
        episodes[1]["provenance"]["activity"],
        "throwing_away_leftovers_0"
    );
    assert_eq!(episodes[1]["length"], steps[1]);
    assert_eq!(
        episodes[0]["provenance"]["teleoperated"],
        serde_json::json!({})
    );
    assert_eq!(lines(&dir.join("meta/episodes_stats.jsonl")).len(), 2);
    let card = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(card.contains("NOT human demonstrations"), "{card}");

    let mut first_index = 0;
    for (k, recording) in recordings.iter().enumerate() {
        let batch = episode(&dir, k);
        let n = recording.frames.len();
        assert_eq!(batch.num_rows(), n, "episode {k}");
        // The actions are the recording's, bit for bit.
        let actions = column::<FixedSizeListArray>(&batch, "action");
        for (row, frame) in recording.frames.iter().enumerate() {
            let values = actions.value(row);
            let values = values.as_any().downcast_ref::<Float32Array>().unwrap();
            assert_eq!(
                values.values().to_vec(),
                frame.action,
                "episode {k} frame {row}"
            );
        }
        let state = column::<FixedSizeListArray>(&batch, "observation.state");
        assert_eq!(state.value_length(), 22);
        let done = column::<BooleanArray>(&batch, "next.done");
        assert!(done.value(n - 1) && (0..n - 1).all(|i| !done.value(i)));
        let index = column::<Int64Array>(&batch, "index");
        assert_eq!(index.value(0), first_index as i64);
        first_index += n;
        // ΔQ sums to the change of Q over the episode.
        let reward: f32 = column::<Float32Array>(&batch, "next.reward")
            .values()
            .iter()
            .sum();
        let q_end = recording.frames.last().and_then(|f| f.q).unwrap_or(0.0);
        let q_start = recording.start_q.unwrap_or(0.0);
        assert!(
            (f64::from(reward) - (q_end - q_start)).abs() < 1e-4,
            "episode {k}: {reward}"
        );
        // Every frame's image is a 32 × 32 PNG.
        let images = column::<StructArray>(&batch, "observation.images.eye");
        let bytes = images.column_by_name("bytes").unwrap();
        let bytes = bytes.as_any().downcast_ref::<BinaryArray>().unwrap();
        for row in 0..n {
            let png = image::load_from_memory(bytes.value(row)).unwrap();
            assert_eq!((png.width(), png.height()), (32, 32));
        }
    }
    // The planner's solution succeeded, and the dataset says so on its last frame.
    let solved = episode(&dir, 1);
    let success = column::<BooleanArray>(&solved, "next.success");
    assert!(success.value(success.len() - 1));
}

/// Episode `k`'s file, read with the Parquet crate's Arrow reader (a small episode is one batch).
fn episode(dir: &Path, k: usize) -> RecordBatch {
    let file = dir.join(format!("data/chunk-000/episode_{k:06}.parquet"));
    let reader = ParquetRecordBatchReaderBuilder::try_new(std::fs::File::open(&file).unwrap())
        .unwrap()
        .build()
        .unwrap();
    let batches: Vec<RecordBatch> = reader.map(Result::unwrap).collect();
    assert_eq!(batches.len(), 1, "{}", file.display());
    batches[0].clone()
}

#[test]
fn an_export_refuses_a_used_folder_a_cut_recording_and_mixed_robots_and_leaves_things_as_they_were()
{
    let run = scratch("demos-refused.mcap");
    behavior_ok(&[
        "run",
        "--agent",
        "idle",
        "--steps",
        "12",
        "--record",
        run.to_str().unwrap(),
    ]);
    let used = scratch("demos-used");
    std::fs::create_dir_all(&used).unwrap();
    std::fs::write(used.join("keep.txt"), "mine").unwrap();
    let error = refused_export(&used, &[&run]);
    assert!(error.contains("not empty"), "{error}");
    assert_eq!(
        std::fs::read_to_string(used.join("keep.txt")).unwrap(),
        "mine"
    );

    let bytes = std::fs::read(&run).unwrap();
    let cut = scratch("demos-cut.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let fresh = scratch("demos-never");
    let _ = std::fs::remove_dir_all(&fresh);
    let error = refused_export(&fresh, &[&cut]);
    assert!(
        error.contains("demos-cut.mcap") && error.contains("whole episodes"),
        "{error}"
    );
    assert!(!fresh.exists(), "nothing is left of a failed export");

    // One dataset holds one robot's episodes.
    let fetch = scratch("demos-fetch.mcap");
    let fetch_s = fetch.to_str().unwrap();
    behavior_ok(&[
        "run", "--robot", "fetch", "--agent", "idle", "--steps", "6", "--record", fetch_s,
    ]);
    let error = refused_export(&fresh, &[&run, &fetch]);
    assert!(
        error.contains("demos-fetch.mcap") && error.contains("one robot"),
        "{error}"
    );
    assert!(!fresh.exists(), "nothing is left of a failed export");
}
