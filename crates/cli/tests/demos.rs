//! `behavior demos export --lerobot` as a user runs it: an agent's episode and the planner's
//! solution (with its recorded primitives) made into a LeRobot dataset in each layout (v3.0,
//! v2.1), read back with the Parquet reader; bad input refused without touching what exists.
//! (LeRobot's own loader reads a v3.0 export in the Python suite.)

#![cfg(feature = "lerobot")]

mod support;

use arrow_array::{
    Array, BinaryArray, BooleanArray, FixedSizeListArray, Float32Array, Int64Array, ListArray,
    RecordBatch, StringArray, StructArray,
};
use behavior_env::record::{Recording, read};
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use serde_json::Value;
use std::path::{Path, PathBuf};
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

/// An agent's episode and the planner's symbolic solution of throwing_away_leftovers,
/// recorded under names that start with `tag`.
fn two_recordings(tag: &str) -> [PathBuf; 2] {
    let run = scratch(&format!("{tag}-run.mcap"));
    let solved = scratch(&format!("{tag}-solved.mcap"));
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
    [run, solved]
}

/// Exports the two recordings in `format` with 32-pixel images; returns the dataset's folder
/// and the summary printed.
fn export_both(format: &str, files: &[PathBuf; 2]) -> (PathBuf, Value) {
    let dir = scratch(&format!("demos-dataset-{format}"));
    let _ = std::fs::remove_dir_all(&dir);
    let out = behavior_ok(&[
        "demos",
        "export",
        "--lerobot",
        dir.to_str().unwrap(),
        files[0].to_str().unwrap(),
        files[1].to_str().unwrap(),
        "--format",
        format,
        "--image-size",
        "32",
        "--json",
    ]);
    (dir, serde_json::from_slice(&out.stdout).unwrap())
}

#[test]
fn recordings_export_to_a_lerobot_v3_dataset_that_reads_back() {
    let files = two_recordings("demos-v3");
    let (dir, summary) = export_both("lerobot-v3", &files);
    let recordings = files.each_ref().map(|f| read(f).unwrap());
    let steps = recordings.each_ref().map(|r| r.frames.len());
    assert_eq!(summary["format"], "lerobot-v3");
    let info = json_file(&dir.join("meta/info.json"));
    assert_eq!(info["codebase_version"], "v3.0");
    assert_eq!(
        info["data_path"],
        "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet"
    );
    check_info_and_summary(&info, &summary, steps);

    // One row per episode: its task, where its frames lie, its provenance.
    let episodes = table(&dir.join("meta/episodes/chunk-000/file-000.parquet"));
    assert_eq!(episodes.num_rows(), 2);
    let from = column::<Int64Array>(&episodes, "dataset_from_index");
    let to = column::<Int64Array>(&episodes, "dataset_to_index");
    assert_eq!((from.value(0), to.value(0)), (0, steps[0] as i64));
    assert_eq!(
        (from.value(1), to.value(1)),
        (steps[0] as i64, (steps[0] + steps[1]) as i64)
    );
    let tasks = column::<ListArray>(&episodes, "tasks").value(1);
    let tasks = tasks.as_any().downcast_ref::<StringArray>().unwrap();
    assert_eq!(tasks.value(0), "throwing away leftovers");
    let provenance = column::<StringArray>(&episodes, "provenance");
    let provenance: Vec<Value> = (0..2)
        .map(|k| serde_json::from_str(provenance.value(k)).unwrap())
        .collect();
    check_provenance(&provenance);
    let means = column::<ListArray>(&episodes, "stats/action/mean");
    assert_eq!(means.value(0).len(), 26, "a mean per action dimension");

    // The tasks as pandas writes a frame indexed by the task's text.
    let file = std::fs::File::open(dir.join("meta/tasks.parquet")).unwrap();
    let builder = ParquetRecordBatchReaderBuilder::try_new(file).unwrap();
    let pandas = builder.schema().metadata().get("pandas").cloned();
    let pandas: Value = serde_json::from_str(&pandas.expect("pandas metadata")).unwrap();
    assert_eq!(pandas["index_columns"][0], "__index_level_0__");
    let tasks = table(&dir.join("meta/tasks.parquet"));
    let names = column::<StringArray>(&tasks, "__index_level_0__");
    assert_eq!(names.value(1), "throwing away leftovers");

    // The statistics over both episodes count every frame.
    let stats = json_file(&dir.join("meta/stats.json"));
    assert_eq!(stats["action"]["count"][0], steps[0] + steps[1]);
    assert_eq!(
        stats["observation.images.eye"]["mean"]
            .as_array()
            .unwrap()
            .len(),
        3
    );

    // Both episodes in one data file, one after the other.
    let data = table(&dir.join("data/chunk-000/file-000.parquet"));
    let frames = [data.slice(0, steps[0]), data.slice(steps[0], steps[1])];
    check_frames(&recordings, &frames);
}

#[test]
fn recordings_export_to_a_lerobot_v2_1_dataset_that_reads_back() {
    let files = two_recordings("demos-v21");
    let (dir, summary) = export_both("lerobot-v2.1", &files);
    let recordings = files.each_ref().map(|f| read(f).unwrap());
    let steps = recordings.each_ref().map(|r| r.frames.len());
    assert_eq!(summary["format"], "lerobot-v2.1");
    let info = json_file(&dir.join("meta/info.json"));
    assert_eq!(info["codebase_version"], "v2.1");
    check_info_and_summary(&info, &summary, steps);
    let episodes = lines(&dir.join("meta/episodes.jsonl"));
    assert_eq!(episodes[1]["tasks"][0], "throwing away leftovers");
    assert_eq!(episodes[1]["length"], steps[1]);
    let provenance: Vec<Value> = episodes.iter().map(|e| e["provenance"].clone()).collect();
    check_provenance(&provenance);
    assert_eq!(lines(&dir.join("meta/episodes_stats.jsonl")).len(), 2);
    let frames = [0, 1].map(|k| table(&dir.join(format!("data/chunk-000/episode_{k:06}.parquet"))));
    check_frames(&recordings, &frames);
}

/// What both layouts' `info.json` and the summary say alike.
fn check_info_and_summary(info: &Value, summary: &Value, steps: [usize; 2]) {
    assert_eq!(summary["episodes"], 2);
    assert_eq!(summary["frames"], steps[0] + steps[1]);
    assert_eq!(summary["teleoperated"], 0);
    assert_eq!(
        summary["planned"], 1,
        "the solve's recording is the planner's"
    );
    assert_eq!(info["fps"], 30);
    assert_eq!(info["total_episodes"], 2);
    assert_eq!(info["total_frames"], steps[0] + steps[1]);
    assert_eq!(info["total_tasks"], 2);
    assert_eq!(info["features"]["action"]["shape"][0], 26);
    assert_eq!(
        info["features"]["observation.images.eye"]["shape"],
        serde_json::json!([32, 32, 3])
    );
}

/// The agent's episode has no stated provenance; the solve's is the planner's, symbolic.
fn check_provenance(provenance: &[Value]) {
    assert_eq!(provenance[0]["by"]["kind"], "unstated");
    assert_eq!(provenance[0]["teleoperated"], serde_json::json!({}));
    assert_eq!(provenance[1]["activity"], "throwing_away_leftovers_0");
    assert_eq!(provenance[1]["by"]["kind"], "planner");
    assert_eq!(provenance[1]["by"]["mode"], "symbolic");
}

/// Each episode's frames against its recording: the actions bit for bit, the indices, ΔQ, the
/// images, and the solved episode's success on its last frame.
fn check_frames(recordings: &[Recording; 2], frames: &[RecordBatch; 2]) {
    let mut first_index = 0;
    for (k, (recording, batch)) in recordings.iter().zip(frames).enumerate() {
        let n = recording.frames.len();
        assert_eq!(batch.num_rows(), n, "episode {k}");
        let actions = column::<FixedSizeListArray>(batch, "action");
        for (row, frame) in recording.frames.iter().enumerate() {
            let values = actions.value(row);
            let values = values.as_any().downcast_ref::<Float32Array>().unwrap();
            assert_eq!(
                values.values().to_vec(),
                frame.action,
                "episode {k} frame {row}"
            );
        }
        let state = column::<FixedSizeListArray>(batch, "observation.state");
        assert_eq!(state.value_length(), 22);
        let done = column::<BooleanArray>(batch, "next.done");
        assert!(done.value(n - 1) && (0..n - 1).all(|i| !done.value(i)));
        let index = column::<Int64Array>(batch, "index");
        assert_eq!(index.value(0), first_index as i64);
        assert_eq!(
            column::<Int64Array>(batch, "episode_index").value(0),
            k as i64
        );
        first_index += n;
        // ΔQ sums to the change of Q over the episode.
        let reward: f32 = column::<Float32Array>(batch, "next.reward")
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
        let images = column::<StructArray>(batch, "observation.images.eye");
        let bytes = images.column_by_name("bytes").unwrap();
        let bytes = bytes.as_any().downcast_ref::<BinaryArray>().unwrap();
        for row in 0..n {
            let png = image::load_from_memory(bytes.value(row)).unwrap();
            assert_eq!((png.width(), png.height()), (32, 32));
        }
    }
    // The planner's solution succeeded, and the dataset says so on its last frame.
    let success = column::<BooleanArray>(&frames[1], "next.success");
    assert!(success.value(success.len() - 1));
}

/// A Parquet file read whole with the Parquet crate's Arrow reader, as one batch.
fn table(file: &Path) -> RecordBatch {
    let reader = ParquetRecordBatchReaderBuilder::try_new(std::fs::File::open(file).unwrap())
        .unwrap()
        .with_batch_size(1 << 20)
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
