//! A LeRobot dataset in either of the two layouts LeRobot reads (reference:
//! primitives-and-formats §2), its frames as Parquet (snappy, as LeRobot writes them):
//!
//! - **v3.0**, what LeRobot 0.4 and the BEHAVIOR Challenge's demonstrations use: episodes one
//!   after another in `data/chunk-CCC/file-FFF.parquet` (a new file past 100 MB), one row per
//!   episode in `meta/episodes/chunk-000/file-000.parquet` (where its frames lie, its statistics,
//!   and — a column of our own that LeRobot keeps — its provenance), `meta/tasks.parquet`,
//!   `meta/stats.json` and `meta/info.json` ([`super::v30`]);
//! - **v2.1**: one file per episode (`data/chunk-CCC/episode_EEEEEE.parquet`) and JSON-lines
//!   metadata (`meta/tasks.jsonl`, `episodes.jsonl`, `episodes_stats.jsonl`), as LeRobot 0.3 and
//!   the datasets made with it.
//!
//! Images are PNG bytes inside the Parquet (feature dtype `image`: the struct `{bytes, path}`
//! that Hugging Face `datasets` writes), so the dataset needs no video codec.
//!
//! This module only writes what it is given; `mod.rs` re-simulates the recordings.

use super::{ExportError, Format, stats, v30};
use arrow_array::builder::{BinaryBuilder, FixedSizeListBuilder, Float32Builder, StringBuilder};
use arrow_array::{
    Array, ArrayRef, BooleanArray, Float32Array, Int64Array, RecordBatch, StructArray,
};
use arrow_schema::{DataType, Field, Fields, Schema};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;
use serde_json::{Value, json};
use stats::ImageStats;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

type Result<T> = std::result::Result<T, ExportError>;

/// Frames per second: the action rate of every recording.
pub(super) const FPS: u32 = 30;
/// Episodes per `data/chunk-CCC` folder (v2.1), files per chunk folder (v3.0): LeRobot's default.
pub(super) const CHUNK_SIZE: usize = 1000;
/// A v3.0 data file takes episodes until it holds this many megabytes (uncompressed, as
/// LeRobot measures them): LeRobot's default.
pub(super) const DATA_FILE_MB: usize = 100;

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
    /// Where it came from and who acted, kept with the episode's metadata (LeRobot keeps
    /// unknown keys and columns).
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

/// What the metadata says of one episode written.
pub(super) struct Written {
    /// Its index in the dataset.
    pub index: usize,
    /// Its task.
    pub task: String,
    /// Its frames.
    pub length: usize,
    /// The dataset's index of its first frame.
    pub from: usize,
    /// Its features' statistics.
    pub stats: serde_json::Map<String, Value>,
    /// Where it came from.
    pub provenance: Value,
    /// v3.0: the chunk and file its frames are in.
    pub file: (usize, usize),
}

/// A dataset being written into a folder of its own.
pub(super) struct Dataset {
    dir: PathBuf,
    format: Format,
    robot: String,
    shapes: Shapes,
    tasks: Vec<String>,
    episodes: Vec<Written>,
    frames: usize,
    /// v3.0: the data file being filled, and its megabytes so far.
    data: Option<(ParquetFile, f64)>,
}

impl Dataset {
    /// Starts a dataset in `dir` (which must not exist yet).
    pub fn create(dir: &Path, format: Format, robot: &str, shapes: Shapes) -> Result<Dataset> {
        let meta = dir.join("meta");
        std::fs::create_dir_all(&meta).map_err(write_error(&meta))?;
        Ok(Dataset {
            dir: dir.to_path_buf(),
            format,
            robot: robot.to_string(),
            shapes,
            tasks: Vec::new(),
            episodes: Vec::new(),
            frames: 0,
            data: None,
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

    /// Writes one episode's frames.
    pub fn add(&mut self, episode: &Episode) -> Result<()> {
        let index = self.episodes.len();
        let task_index = match self.tasks.iter().position(|t| *t == episode.task) {
            Some(i) => i,
            None => {
                self.tasks.push(episode.task.clone());
                self.tasks.len() - 1
            }
        };
        let columns = Columns::of(episode, self.shapes, index, task_index, self.frames)?;
        let file = match self.format {
            Format::V21 => {
                let path = self.dir.join(format!(
                    "data/chunk-{:03}/episode_{index:06}.parquet",
                    index / CHUNK_SIZE
                ));
                let mut out = ParquetFile::create(&path, columns.schema.clone(), None)?;
                out.append(columns.batch(&path)?)?;
                out.close()?;
                (index / CHUNK_SIZE, 0)
            }
            Format::V30 => self.append_v30(&columns)?,
        };
        self.episodes.push(Written {
            index,
            task: episode.task.clone(),
            length: episode.action.len(),
            from: self.frames,
            stats: columns.stats,
            provenance: episode.provenance.clone(),
            file,
        });
        self.frames += episode.action.len();
        Ok(())
    }

    /// Appends an episode's frames to the v3.0 data file being filled, or to a new one when
    /// that one is full; returns the (chunk, file) they went to.
    fn append_v30(&mut self, columns: &Columns) -> Result<(usize, usize)> {
        let files = self
            .episodes
            .last()
            .map_or(0, |e| e.file.0 * CHUNK_SIZE + e.file.1 + 1);
        let full = self
            .data
            .as_ref()
            .is_none_or(|(_, mb)| *mb >= DATA_FILE_MB as f64);
        if full {
            if let Some((file, _)) = self.data.take() {
                file.close()?;
            }
            let path = self
                .dir
                .join(v30::data_path(files / CHUNK_SIZE, files % CHUNK_SIZE));
            self.data = Some((
                ParquetFile::create(&path, columns.schema.clone(), None)?,
                0.0,
            ));
        }
        let (file, mb) = self.data.as_mut().expect("a data file is open");
        let batch = columns.batch(&file.path)?;
        *mb += batch.get_array_memory_size() as f64 / (1024.0 * 1024.0);
        file.append(batch)?;
        let number = if full { files } else { files - 1 };
        Ok((number / CHUNK_SIZE, number % CHUNK_SIZE))
    }

    /// Writes the metadata; returns the episodes and frames written.
    pub fn finish(mut self) -> Result<(usize, usize)> {
        if let Some((file, _)) = self.data.take() {
            file.close()?;
        }
        let meta = self.dir.join("meta");
        let mut info = json!({
            "robot_type": self.robot,
            "fps": FPS,
            "total_episodes": self.episodes.len(),
            "total_frames": self.frames,
            "total_tasks": self.tasks.len(),
            "chunks_size": CHUNK_SIZE,
            "video_path": null,
            "splits": {"train": format!("0:{}", self.episodes.len())},
            "features": features(self.shapes),
        });
        match self.format {
            Format::V21 => {
                info["codebase_version"] = json!("v2.1");
                info["total_videos"] = json!(0);
                info["total_chunks"] = json!(self.episodes.len().div_ceil(CHUNK_SIZE));
                info["data_path"] =
                    json!("data/chunk-{episode_chunk:03d}/episode_{episode_index:06d}.parquet");
                self.write_jsonl_meta(&meta)?;
            }
            Format::V30 => {
                info["codebase_version"] = json!("v3.0");
                info["data_files_size_in_mb"] = json!(DATA_FILE_MB);
                info["video_files_size_in_mb"] = json!(v30::VIDEO_FILE_MB);
                info["data_path"] = json!(v30::DATA_PATH);
                v30::write_meta(&self.dir, &self.tasks, &self.episodes)?;
            }
        }
        let info_path = meta.join("info.json");
        let text = serde_json::to_string_pretty(&info).expect("JSON values serialize");
        std::fs::write(&info_path, text).map_err(write_error(&info_path))?;
        Ok((self.episodes.len(), self.frames))
    }

    /// v2.1's metadata: the tasks, the episodes and their statistics, a JSON line each.
    fn write_jsonl_meta(&self, meta: &Path) -> Result<()> {
        let tasks = self
            .tasks
            .iter()
            .enumerate()
            .map(|(i, t)| json!({"task_index": i, "task": t}));
        write_lines(&meta.join("tasks.jsonl"), tasks)?;
        let episodes = self.episodes.iter().map(|e| {
            json!({"episode_index": e.index, "tasks": [e.task], "length": e.length,
                "provenance": e.provenance})
        });
        write_lines(&meta.join("episodes.jsonl"), episodes)?;
        let stats = self
            .episodes
            .iter()
            .map(|e| json!({"episode_index": e.index, "stats": e.stats}));
        write_lines(&meta.join("episodes_stats.jsonl"), stats)
    }
}

/// A Parquet file being written, snappy-compressed as LeRobot writes them.
pub(super) struct ParquetFile {
    path: PathBuf,
    writer: ArrowWriter<File>,
}

impl ParquetFile {
    /// Creates the file (and its folder), with `metadata` among its key-value metadata.
    pub fn create(
        path: &Path,
        schema: Arc<Schema>,
        metadata: Option<(&str, String)>,
    ) -> Result<ParquetFile> {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(write_error(dir))?;
        }
        let file = File::create(path).map_err(write_error(path))?;
        // The Arrow schema's metadata is what arrow-rs keeps among the file's key-value
        // metadata, where pyarrow and pandas read it.
        let schema = match metadata {
            Some((key, value)) => Arc::new(Schema::new_with_metadata(
                schema.fields().clone(),
                std::collections::HashMap::from([(key.to_string(), value)]),
            )),
            None => schema,
        };
        let props = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .build();
        let writer = ArrowWriter::try_new(file, schema, Some(props))
            .map_err(|source| parquet_error(path, source))?;
        Ok(ParquetFile {
            path: path.to_path_buf(),
            writer,
        })
    }

    /// Appends rows.
    pub fn append(&mut self, batch: RecordBatch) -> Result<()> {
        self.writer
            .write(&batch)
            .map_err(|source| parquet_error(&self.path, source))
    }

    /// Writes the footer.
    pub fn close(self) -> Result<()> {
        self.writer
            .close()
            .map(|_| ())
            .map_err(|source| parquet_error(&self.path, source))
    }
}

/// A Parquet failure at `path`.
fn parquet_error(path: &Path, source: parquet::errors::ParquetError) -> ExportError {
    ExportError::Parquet {
        path: path.to_path_buf(),
        source,
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
                stats::of_rows(rows.iter().map(|r| r.iter().map(|&v| f64::from(v)))),
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
                stats::of_rows(values.iter().map(|&v| std::iter::once(v))),
            );
            fields.push(Field::new(name, dtype, false));
            c.arrays.push(array);
        }
        c.schema = Arc::new(Schema::new(fields));
        Ok(c)
    }

    /// The columns as one batch of rows (for the file at `path`, named in an error).
    fn batch(&self, path: &Path) -> Result<RecordBatch> {
        RecordBatch::try_new(self.schema.clone(), self.arrays.clone())
            .map_err(|e| parquet_error(path, e.into()))
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
/// its statistics ([`ImageStats`]).
fn images(frames: &[Vec<u8>], side: u32) -> Result<(Field, ArrayRef, Value)> {
    let mut bytes = BinaryBuilder::new();
    let mut paths = StringBuilder::new();
    let mut channels = ImageStats::new();
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
        channels.add(rgb);
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
    Ok((field, Arc::new(array), channels.finish()))
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
