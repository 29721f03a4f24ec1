//! LeRobot v3.0's metadata: the episodes' table, the tasks' table and the dataset's statistics.

use super::ExportError;
use super::dataset::{ParquetFile, Written, write_error};
use super::stats;
use arrow_array::builder::{Float64Builder, Int64Builder, ListBuilder, StringBuilder};
use arrow_array::{ArrayRef, Int64Array, RecordBatch, StringArray};
use arrow_schema::{Field, Schema};
use serde_json::{Value, json};
use std::collections::BTreeSet;
use std::path::Path;
use std::sync::Arc;

type Result<T> = std::result::Result<T, ExportError>;

/// Where the frames lie, as `meta/info.json` says it to LeRobot.
pub(super) const DATA_PATH: &str = "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet";
/// The video files' size LeRobot's default (no video is written: images are in the frames).
pub(super) const VIDEO_FILE_MB: usize = 200;
/// The episodes' table: one file holds every episode's row.
const EPISODES_PATH: &str = "meta/episodes/chunk-000/file-000.parquet";

/// The data file `file` of chunk `chunk`, relative to the dataset.
pub(super) fn data_path(chunk: usize, file: usize) -> String {
    format!("data/chunk-{chunk:03}/file-{file:03}.parquet")
}

/// Writes `meta/episodes/…`, `meta/tasks.parquet` and `meta/stats.json`.
pub(super) fn write_meta(dir: &Path, tasks: &[String], episodes: &[Written]) -> Result<()> {
    write_episodes(&dir.join(EPISODES_PATH), episodes)?;
    write_tasks(&dir.join("meta/tasks.parquet"), tasks)?;
    let features: BTreeSet<&String> = episodes.iter().flat_map(|e| e.stats.keys()).collect();
    let all: serde_json::Map<String, Value> = features
        .into_iter()
        .map(|feature| {
            let each: Vec<&Value> = episodes
                .iter()
                .filter_map(|e| e.stats.get(feature))
                .collect();
            (feature.clone(), stats::aggregate(&each))
        })
        .collect();
    let path = dir.join("meta/stats.json");
    let text = serde_json::to_string_pretty(&all).expect("JSON values serialize");
    std::fs::write(&path, text).map_err(write_error(&path))
}

/// The episodes' table: index, tasks, length, where its frames lie, its statistics as
/// `stats/FEATURE/STAT` columns, where its own row lies, and its provenance (JSON text).
fn write_episodes(path: &Path, episodes: &[Written]) -> Result<()> {
    let ints = |f: &dyn Fn(&Written) -> usize| -> ArrayRef {
        Arc::new(Int64Array::from_iter_values(
            episodes.iter().map(|e| f(e) as i64),
        ))
    };
    let mut tasks = ListBuilder::new(StringBuilder::new());
    for e in episodes {
        tasks.values().append_value(&e.task);
        tasks.append(true);
    }
    let mut columns: Vec<(String, ArrayRef)> = vec![
        ("episode_index".into(), ints(&|e| e.index)),
        ("tasks".into(), Arc::new(tasks.finish())),
        ("length".into(), ints(&|e| e.length)),
        ("data/chunk_index".into(), ints(&|e| e.file.0)),
        ("data/file_index".into(), ints(&|e| e.file.1)),
        ("dataset_from_index".into(), ints(&|e| e.from)),
        ("dataset_to_index".into(), ints(&|e| e.from + e.length)),
    ];
    columns.extend(stats_columns(episodes));
    columns.push(("meta/episodes/chunk_index".into(), ints(&|_| 0)));
    columns.push(("meta/episodes/file_index".into(), ints(&|_| 0)));
    let provenance = episodes.iter().map(|e| Some(e.provenance.to_string()));
    columns.push((
        "provenance".into(),
        Arc::new(StringArray::from_iter(provenance)),
    ));
    write_table(path, columns, None)
}

/// Each feature's statistics as columns of lists, one row per episode: `count` as integers,
/// the rest as doubles, an image's (3, 1, 1) lists nested three deep as LeRobot writes them.
fn stats_columns(episodes: &[Written]) -> Vec<(String, ArrayRef)> {
    let Some(first) = episodes.first() else {
        return Vec::new();
    };
    let mut columns = Vec::new();
    for (feature, keyed) in &first.stats {
        let Some(keyed) = keyed.as_object() else {
            continue;
        };
        for key in keyed.keys() {
            let values: Vec<&Value> = episodes.iter().map(|e| &e.stats[feature][key]).collect();
            let nested = values[0]
                .as_array()
                .and_then(|a| a.first())
                .is_some_and(Value::is_array);
            let array: ArrayRef = if key == "count" {
                let mut b = ListBuilder::new(Int64Builder::new());
                for v in &values {
                    b.values().append_slice(
                        &stats::flat(v).iter().map(|&n| n as i64).collect::<Vec<_>>(),
                    );
                    b.append(true);
                }
                Arc::new(b.finish())
            } else if nested {
                let mut b =
                    ListBuilder::new(ListBuilder::new(ListBuilder::new(Float64Builder::new())));
                for v in &values {
                    for channel in stats::flat(v) {
                        b.values().values().values().append_value(channel);
                        b.values().values().append(true);
                        b.values().append(true);
                    }
                    b.append(true);
                }
                Arc::new(b.finish())
            } else {
                let mut b = ListBuilder::new(Float64Builder::new());
                for v in &values {
                    b.values().append_slice(&stats::flat(v));
                    b.append(true);
                }
                Arc::new(b.finish())
            };
            columns.push((format!("stats/{feature}/{key}"), array));
        }
    }
    columns
}

/// The tasks' table as pandas writes a frame indexed by the task's text: LeRobot reads it with
/// `pandas.read_parquet` and takes a task's text from the index, which the `pandas` metadata
/// names.
fn write_tasks(path: &Path, tasks: &[String]) -> Result<()> {
    let columns: Vec<(String, ArrayRef)> = vec![
        (
            "task_index".into(),
            Arc::new(Int64Array::from_iter_values(0..tasks.len() as i64)),
        ),
        (
            "__index_level_0__".into(),
            Arc::new(StringArray::from_iter_values(tasks)),
        ),
    ];
    let pandas = json!({
        "index_columns": ["__index_level_0__"],
        "column_indexes": [{"name": null, "field_name": null, "pandas_type": "unicode",
            "numpy_type": "object", "metadata": {"encoding": "UTF-8"}}],
        "columns": [
            {"name": "task_index", "field_name": "task_index", "pandas_type": "int64",
                "numpy_type": "int64", "metadata": null},
            {"name": null, "field_name": "__index_level_0__", "pandas_type": "unicode",
                "numpy_type": "object", "metadata": null}
        ],
        "attributes": {},
        "creator": {"library": "behavior", "version": env!("CARGO_PKG_VERSION")},
        "pandas_version": "2.2.0"
    });
    write_table(path, columns, Some(("pandas", pandas.to_string())))
}

/// A one-batch Parquet file of named columns.
fn write_table(
    path: &Path,
    columns: Vec<(String, ArrayRef)>,
    metadata: Option<(&str, String)>,
) -> Result<()> {
    let fields: Vec<Field> = columns
        .iter()
        .map(|(name, array)| Field::new(name, array.data_type().clone(), true))
        .collect();
    let schema = Arc::new(Schema::new(fields));
    let arrays = columns.into_iter().map(|(_, a)| a).collect();
    let batch = RecordBatch::try_new(schema.clone(), arrays).map_err(|e| ExportError::Parquet {
        path: path.to_path_buf(),
        source: e.into(),
    })?;
    let mut file = ParquetFile::create(path, schema, metadata)?;
    file.append(batch)?;
    file.close()
}
