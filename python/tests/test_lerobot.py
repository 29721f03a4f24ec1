"""A LeRobot dataset exported from Python by `behavior.export_lerobot` (the library function
`behavior demos export --lerobot` calls too), read with pyarrow as LeRobot's loader reads it: an
episode recorded from Python, its frames and metadata; and the export's refusals."""

import json
import struct

import numpy as np
import pyarrow.parquet as pq
import pytest

from behavior import BehaviorEnv, export_lerobot


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", data[16:24])


def record_episode(path, steps=10):
    """Records `steps` random actions of bringing_in_wood (seed 2) to `path`; returns them."""
    env = BehaviorEnv("bringing_in_wood", seed=2)
    env.reset(seed=2)
    env.record(path)
    rng = np.random.default_rng(1)
    actions = [rng.uniform(-1, 1, env.action_space.shape).astype(np.float32) for _ in range(steps)]
    for action in actions:
        env.step(action)
    env.stop_recording()
    return actions


def test_an_exported_episode_reads_back_with_pyarrow(tmp_path):
    recording = tmp_path / "episode.mcap"
    actions = record_episode(recording)

    dataset = tmp_path / "dataset"
    summary = export_lerobot(dataset, [recording], image_size=48)
    assert summary["frames"] == 10 and summary["episodes"] == 1
    assert summary["teleoperated"] == 0 and summary["images"] is True
    assert summary["recordings"] == [[str(recording), 10]]

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


def test_the_export_refuses_what_it_cannot_write_and_leaves_nothing(tmp_path):
    recording = tmp_path / "episode.mcap"
    record_episode(recording, steps=3)

    taken = tmp_path / "taken"
    taken.mkdir()
    (taken / "keep.txt").write_text("mine")
    with pytest.raises(FileExistsError, match="exists and is not empty"):
        export_lerobot(taken, [recording], image_size=None)
    assert [p.name for p in taken.iterdir()] == ["keep.txt"]

    dataset = tmp_path / "dataset"
    with pytest.raises(ValueError, match="16–1024 pixels, not 8"):
        export_lerobot(dataset, [recording], image_size=8)
    not_a_recording = tmp_path / "notes.mcap"
    not_a_recording.write_text("not MCAP")
    with pytest.raises(ValueError, match="notes.mcap"):
        export_lerobot(dataset, [recording, not_a_recording], image_size=None)
    with pytest.raises(OSError, match="missing.mcap"):
        export_lerobot(dataset, [tmp_path / "missing.mcap"], image_size=None)
    # Nothing half-written under the dataset's name or beside it.
    assert not dataset.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["episode.mcap", "notes.mcap", "taken"]
