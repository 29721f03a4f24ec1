//! A LeRobot dataset, format v2.1 (reference: primitives-and-formats §2): one Parquet file of
//! frames per episode (`data/chunk-CCC/episode_EEEEEE.parquet`, snappy as LeRobot writes them)
//! and the metadata LeRobot's loader reads offline (`meta/info.json`, `tasks.jsonl`,
//! `episodes.jsonl`, `episodes_stats.jsonl`). Images are PNG bytes inside the Parquet (feature
//! dtype `image`: the struct `{bytes, path}` that Hugging Face `datasets` writes), so the
//! dataset needs no video codec. v2.1 rather than v3.0 because it keeps an episode to a file;
//! LeRobot converts it (`lerobot.scripts.convert_dataset_v21_to_v30`).
//!
//! This module only writes what it is given; `mod.rs` re-simulates the recordings.

use super::ExportError;
use arrow_array::builder::{BinaryBuilder, FixedSizeListBuilder, Float32Builder, StringBuilder};
use arrow_array::{
    Array, ArrayRef, BooleanArray, Float32Array, Int64Array, RecordBatch, StructArray,
};
use arrow_schema::{DataType, Field, Fields, Schema};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;
use serde_json::{Value, json};
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

type Result<T> = std::result::Result<T, ExportError>;

/// Frames per second: the action rate of every recording.
pub(super) const FPS: u32 = 30;
/// Episodes per `data/chunk-CCC` folder, as LeRobot's default.
const CHUNK_SIZE: usize = 1000;

/// One episode's frames: frame k is the observation before the episode's k-th action, the
/// action, and what followed it.
#[derive(Default)]
pub(super) struct Episode {
    /// What was to be done: the activity's name.
    pub task: String,
    /// Proprioception, one vector per frame.
    pub state: Vec<Vec<f32>>,
    /// `task_obs` (the full-observability vector), one per frame.
    pub environment: Vec<Vec<f32>>,
    /// The robot's camera as RGB (height × width × 3), one per frame, if images are written.
    pub images: Vec<Vec<u8>>,
    /// The action, one per frame.
    pub action: Vec<Vec<f32>>,
    /// ΔQ of the step.
    pub reward: Vec<f32>,
    /// Whether the goal held after the step.
    pub success: Vec<bool>,
    /// Where it came from, kept in `episodes.jsonl` (LeRobot keeps unknown keys).
    pub provenance: Value,
}

/// The vector sizes every episode of the dataset must share.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shapes {
    /// Proprioception's length.
    pub state: usize,
    /// `task_obs`'s length.
    pub environment: usize,
    /// The action's length.
    pub action: usize,
    /// Image side in pixels; none when the dataset has no images.
    pub image: Option<u32>,
}

/// A dataset being written into a folder of its own.
pub(super) struct Dataset {
    dir: PathBuf,
    robot: String,
    shapes: Shapes,
    tasks: Vec<String>,
    episodes: Vec<Value>,
    stats: Vec<Value>,
    frames: usize,
}

impl Dataset {
    /// Starts a dataset in `dir` (which must not exist yet).
    pub fn create(dir: &Path, robot: &str, shapes: Shapes) -> Result<Dataset> {
        let meta = dir.join("meta");
        std::fs::create_dir_all(&meta).map_err(write_error(&meta))?;
        Ok(Dataset {
            dir: dir.to_path_buf(),
            robot: robot.to_string(),
            shapes,
            tasks: Vec::new(),
            episodes: Vec::new(),
            stats: Vec::new(),
            frames: 0,
        })
    }

    /// The robot every episode must be of.
    pub fn robot(&self) -> &str {
        &self.robot
    }

    /// The sizes every episode must have.
    pub fn shapes(&self) -> Shapes {
        self.shapes
    }

    /// Writes one episode's Parquet file.
    pub fn add(&mut self, episode: &Episode) -> Result<()> {
        let n = episode.action.len();
        let index = self.episodes.len();
        let task_index = match self.tasks.iter().position(|t| *t == episode.task) {
            Some(i) => i,
            None => {
                self.tasks.push(episode.task.clone());
                self.tasks.len() - 1
            }
        };
        let columns = Columns::of(episode, self.shapes, index, task_index, self.frames)?;
        let path = self.dir.join(format!(
            "data/chunk-{:03}/episode_{index:06}.parquet",
            index / CHUNK_SIZE
        ));
        columns.write(&path)?;
        self.stats
            .push(json!({"episode_index": index, "stats": columns.stats}));
        let mut entry = json!({"episode_index": index, "tasks": [episode.task], "length": n});
        entry["provenance"] = episode.provenance.clone();
        self.episodes.push(entry);
        self.frames += n;
        Ok(())
    }

    /// Writes the metadata; returns the episodes and frames written.
    pub fn finish(self) -> Result<(usize, usize)> {
        let meta = self.dir.join("meta");
        let info = json!({
            "codebase_version": "v2.1",
            "robot_type": self.robot,
            "fps": FPS,
            "total_episodes": self.episodes.len(),
            "total_frames": self.frames,
            "total_tasks": self.tasks.len(),
            "total_videos": 0,
            "total_chunks": self.episodes.len().div_ceil(CHUNK_SIZE),
            "chunks_size": CHUNK_SIZE,
            "data_path": "data/chunk-{episode_chunk:03d}/episode_{episode_index:06d}.parquet",
            "video_path": null,
            "splits": {"train": format!("0:{}", self.episodes.len())},
            "features": features(self.shapes),
        });
        let info_path = meta.join("info.json");
        let text = serde_json::to_string_pretty(&info).expect("JSON values serialize");
        std::fs::write(&info_path, text).map_err(write_error(&info_path))?;
        let tasks = self
            .tasks
            .iter()
            .enumerate()
            .map(|(i, t)| json!({"task_index": i, "task": t}));
        write_lines(&meta.join("tasks.jsonl"), tasks)?;
        write_lines(&meta.join("episodes.jsonl"), self.episodes.iter().cloned())?;
        write_lines(&meta.join("episodes_stats.jsonl"), self.stats.into_iter())?;
        Ok((self.episodes.len(), self.frames))
    }
}

/// The `features` of `info.json`.
fn features(shapes: Shapes) -> Value {
    let vector = |dtype: &str, n: usize| json!({"dtype": dtype, "shape": [n], "names": null});
    let mut f = json!({
        "observation.state": vector("float32", shapes.state),
        "observation.environment_state": vector("float32", shapes.environment),
        "action": vector("float32", shapes.action),
        "next.reward": vector("float32", 1),
        "next.done": vector("bool", 1),
        "next.success": vector("bool", 1),
        "timestamp": vector("float32", 1),
        "frame_index": vector("int64", 1),
        "episode_index": vector("int64", 1),
        "index": vector("int64", 1),
        "task_index": vector("int64", 1),
    });
    if let Some(side) = shapes.image {
        f[IMAGE] = json!({"dtype": "image", "shape": [side, side, 3],
            "names": ["height", "width", "channels"]});
    }
    f
}

/// The camera's feature name.
const IMAGE: &str = "observation.images.eye";

/// An episode as Arrow columns, with each feature's statistics.
struct Columns {
    schema: Arc<Schema>,
    arrays: Vec<ArrayRef>,
    stats: serde_json::Map<String, Value>,
}

impl Columns {
    fn of(
        episode: &Episode,
        shapes: Shapes,
        index: usize,
        task_index: usize,
        first: usize,
    ) -> Result<Columns> {
        let n = episode.action.len();
        let mut c = Columns {
            schema: Arc::new(Schema::empty()),
            arrays: Vec::new(),
            stats: serde_json::Map::new(),
        };
        let mut fields = Vec::new();
        let vectors = [
            ("observation.state", &episode.state, shapes.state),
            (
                "observation.environment_state",
                &episode.environment,
                shapes.environment,
            ),
            ("action", &episode.action, shapes.action),
        ];
        for (name, rows, size) in vectors {
            if rows.len() != n || rows.iter().any(|r| r.len() != size) {
                return Err(ExportError::Shape(format!(
                    "episode {index}: `{name}` is not {n} rows of {size} numbers"
                )));
            }
            let (field, array) = fixed_list(name, rows, size);
            c.stats.insert(
                name.into(),
                stats(rows.iter().map(|r| r.iter().map(|&v| f64::from(v)))),
            );
            fields.push(field);
            c.arrays.push(array);
        }
        if let Some(side) = shapes.image {
            if episode.images.len() != n {
                return Err(ExportError::Shape(format!(
                    "episode {index}: {} images for {n} frames",
                    episode.images.len()
                )));
            }
            let (field, array, image_stats) = images(&episode.images, side)?;
            c.stats.insert(IMAGE.into(), image_stats);
            fields.push(field);
            c.arrays.push(array);
        }
        let scalars = scalar_columns(episode, index, task_index, first);
        for (name, array, dtype, values) in scalars {
            if array.len() != n {
                return Err(ExportError::Shape(format!(
                    "episode {index}: `{name}` has {} values for {n} frames",
                    array.len()
                )));
            }
            c.stats.insert(
                name.into(),
                stats(values.iter().map(|&v| std::iter::once(v))),
            );
            fields.push(Field::new(name, dtype, false));
            c.arrays.push(array);
        }
        c.schema = Arc::new(Schema::new(fields));
        Ok(c)
    }

    fn write(&self, path: &Path) -> Result<()> {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(write_error(dir))?;
        }
        let parquet = |source| ExportError::Parquet {
            path: path.to_path_buf(),
            source,
        };
        let batch = RecordBatch::try_new(self.schema.clone(), self.arrays.clone())
            .map_err(|e| parquet(e.into()))?;
        let file = File::create(path).map_err(write_error(path))?;
        let props = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .build();
        let mut writer =
            ArrowWriter::try_new(file, self.schema.clone(), Some(props)).map_err(parquet)?;
        writer.write(&batch).map_err(parquet)?;
        writer.close().map_err(parquet)?;
        Ok(())
    }
}

/// One column per scalar feature: its name, values, type, and the values as numbers for the
/// statistics.
type Scalar = (&'static str, ArrayRef, DataType, Vec<f64>);

/// The scalar columns of an episode's `n` frames: what followed each action, and where the
/// frame lies (its time, its index in the episode and in the dataset).
fn scalar_columns(episode: &Episode, index: usize, task_index: usize, first: usize) -> Vec<Scalar> {
    let n = episode.action.len();
    let indices = |from: usize| (from..from + n).map(|k| k as i64).collect();
    vec![
        floats("next.reward", episode.reward.clone()),
        booleans("next.done", (0..n).map(|k| k + 1 == n).collect()),
        booleans("next.success", episode.success.clone()),
        floats("timestamp", (0..n).map(|k| k as f32 / FPS as f32).collect()),
        integers("frame_index", indices(0)),
        integers("episode_index", vec![index as i64; n]),
        integers("index", indices(first)),
        integers("task_index", vec![task_index as i64; n]),
    ]
}

fn floats(name: &'static str, values: Vec<f32>) -> Scalar {
    let numbers = values.iter().map(|&v| f64::from(v)).collect();
    (
        name,
        Arc::new(Float32Array::from(values)),
        DataType::Float32,
        numbers,
    )
}

fn booleans(name: &'static str, values: Vec<bool>) -> Scalar {
    let numbers = values.iter().map(|&v| f64::from(u8::from(v))).collect();
    (
        name,
        Arc::new(BooleanArray::from(values)),
        DataType::Boolean,
        numbers,
    )
}

fn integers(name: &'static str, values: Vec<i64>) -> Scalar {
    let numbers = values.iter().map(|&v| v as f64).collect();
    (
        name,
        Arc::new(Int64Array::from(values)),
        DataType::Int64,
        numbers,
    )
}

/// A column of fixed-length float32 vectors (Hugging Face `Sequence(float32, length=size)`).
fn fixed_list(name: &str, rows: &[Vec<f32>], size: usize) -> (Field, ArrayRef) {
    let mut builder = FixedSizeListBuilder::new(Float32Builder::new(), size as i32);
    for row in rows {
        builder.values().append_slice(row);
        builder.append(true);
    }
    let array = builder.finish();
    let field = Field::new(name, array.data_type().clone(), false);
    (field, Arc::new(array))
}

/// The image column: PNG bytes in `{bytes, path}` structs (Hugging Face's `Image` feature), and
/// the per-channel statistics on a 0–1 scale, shaped (3, 1, 1) as LeRobot keeps them.
fn images(frames: &[Vec<u8>], side: u32) -> Result<(Field, ArrayRef, Value)> {
    let mut bytes = BinaryBuilder::new();
    let mut paths = StringBuilder::new();
    let mut channels = Accumulator::new(3);
    for rgb in frames {
        let wrong =
            || ExportError::Shape(format!("an image of {} bytes, not {side}²×3", rgb.len()));
        let image = image::RgbImage::from_raw(side, side, rgb.clone()).ok_or_else(wrong)?;
        let mut png = Vec::new();
        image
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .map_err(|_| wrong())?;
        bytes.append_value(&png);
        paths.append_null();
        for pixel in rgb.chunks_exact(3) {
            channels.add(pixel.iter().map(|&v| f64::from(v) / 255.0));
        }
    }
    let fields = Fields::from(vec![
        Field::new("bytes", DataType::Binary, true),
        Field::new("path", DataType::Utf8, true),
    ]);
    let array = StructArray::try_new(
        fields.clone(),
        vec![Arc::new(bytes.finish()), Arc::new(paths.finish())],
        None,
    )
    .map_err(|e| ExportError::Shape(e.to_string()))?;
    let field = Field::new(IMAGE, DataType::Struct(fields), false);
    let mut stats = channels.finish();
    // Counted in frames, not pixels, as LeRobot counts them.
    for key in ["min", "max", "mean", "std"] {
        let values: Vec<Value> = stats[key]
            .as_array()
            .map(|v| v.iter().map(|c| json!([[c]])).collect())
            .unwrap_or_default();
        stats[key] = Value::Array(values);
    }
    stats["count"] = json!([frames.len()]);
    Ok((field, Arc::new(array), stats))
}

/// Statistics per dimension of rows of numbers: `{min, max, mean, std, count}`.
fn stats<R: Iterator<Item = f64>>(rows: impl Iterator<Item = R>) -> Value {
    let mut accumulator: Option<Accumulator> = None;
    for row in rows {
        let row: Vec<f64> = row.collect();
        accumulator
            .get_or_insert_with(|| Accumulator::new(row.len()))
            .add(row.into_iter());
    }
    accumulator.map_or_else(|| json!({"count": [0]}), Accumulator::finish)
}

struct Accumulator {
    min: Vec<f64>,
    max: Vec<f64>,
    sum: Vec<f64>,
    squares: Vec<f64>,
    count: usize,
}

impl Accumulator {
    fn new(dims: usize) -> Accumulator {
        Accumulator {
            min: vec![f64::INFINITY; dims],
            max: vec![f64::NEG_INFINITY; dims],
            sum: vec![0.0; dims],
            squares: vec![0.0; dims],
            count: 0,
        }
    }

    fn add(&mut self, row: impl Iterator<Item = f64>) {
        for (d, v) in row.enumerate().take(self.sum.len()) {
            self.min[d] = self.min[d].min(v);
            self.max[d] = self.max[d].max(v);
            self.sum[d] += v;
            self.squares[d] += v * v;
        }
        self.count += 1;
    }

    fn finish(self) -> Value {
        let n = self.count.max(1) as f64;
        let mean: Vec<f64> = self.sum.iter().map(|s| s / n).collect();
        let std: Vec<f64> = self
            .squares
            .iter()
            .zip(&mean)
            .map(|(q, m)| (q / n - m * m).max(0.0).sqrt())
            .collect();
        json!({"min": self.min, "max": self.max, "mean": mean, "std": std, "count": [self.count]})
    }
}

/// An I/O failure at `path`, as an [`ExportError::Write`].
pub(super) fn write_error(path: &Path) -> impl Fn(std::io::Error) -> ExportError + '_ {
    move |source| ExportError::Write {
        path: path.to_path_buf(),
        source,
    }
}

fn write_lines(path: &Path, lines: impl Iterator<Item = Value>) -> Result<()> {
    let mut file = File::create(path).map_err(write_error(path))?;
    for line in lines {
        writeln!(file, "{line}").map_err(write_error(path))?;
    }
    Ok(())
}
