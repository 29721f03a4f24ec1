"""A LeRobot dataset exported by `behavior demos export --lerobot`, read with pyarrow as
LeRobot's loader reads it: an episode recorded from Python, its frames and metadata."""

import json
import os
import struct
import subprocess
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq

from behavior import BehaviorEnv

ROOT = Path(__file__).resolve().parents[2]
# The command-line tool `cargo test` built (the CI runs the Rust tests first), or $BEHAVIOR_BIN.
BIN = Path(os.environ.get("BEHAVIOR_BIN", ROOT / "target" / "debug" / "behavior"))


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", data[16:24])


def test_an_exported_episode_reads_back_with_pyarrow(tmp_path):
    assert BIN.exists(), f"{BIN} is missing: build it with `cargo build -p behavior-cli`"
    env = BehaviorEnv("bringing_in_wood", seed=2)
    env.reset(seed=2)
    recording = tmp_path / "episode.mcap"
    env.record(recording)
    rng = np.random.default_rng(1)
    actions = [rng.uniform(-1, 1, env.action_space.shape).astype(np.float32) for _ in range(10)]
    for action in actions:
        env.step(action)
    env.stop_recording()

    dataset = tmp_path / "dataset"
    out = subprocess.run(
        [str(BIN), "demos", "export", "--lerobot", str(dataset), str(recording),
         "--image-size", "48", "--json"],
        check=True, capture_output=True, text=True,
    )
    assert json.loads(out.stdout)["frames"] == 10

    info = json.loads((dataset / "meta" / "info.json").read_text())
    assert info["codebase_version"] == "v2.1" and info["total_frames"] == 10
    table = pq.read_table(dataset / "data" / "chunk-000" / "episode_000000.parquet")
    assert table.num_rows == 10
    assert set(info["features"]) == set(table.column_names)
    got = np.array(table.column("action").to_pylist(), dtype=np.float32)
    np.testing.assert_array_equal(got, np.stack(actions))
    state = np.array(table.column("observation.state").to_pylist())
    assert state.shape == (10, info["features"]["observation.state"]["shape"][0])
    assert table.column("frame_index").to_pylist() == list(range(10))
    assert table.column("next.done").to_pylist() == [False] * 9 + [True]
    for image in table.column("observation.images.eye").to_pylist():
        assert png_size(image["bytes"]) == (48, 48)
    tasks = [json.loads(line) for line in (dataset / "meta" / "tasks.jsonl").read_text().splitlines()]
    assert tasks == [{"task_index": 0, "task": "bringing in wood"}]
