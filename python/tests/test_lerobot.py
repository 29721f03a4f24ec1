"""A LeRobot dataset exported from Python by `behavior.export_lerobot` (the library function
`behavior demos export --lerobot` calls too): in v3.0, loaded by LeRobot's own `LeRobotDataset`
from the local folder (no hub); in v2.1, read with pyarrow as LeRobot 0.3's loader reads it; and
the export's refusals."""

import json
import os
import struct
import subprocess
import sys

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


def test_a_v2_1_export_reads_back_with_pyarrow(tmp_path):
    recording = tmp_path / "episode.mcap"
    actions = record_episode(recording)

    dataset = tmp_path / "dataset"
    summary = export_lerobot(dataset, [recording], image_size=48, format="lerobot-v2.1")
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


# Run in a process of its own: LeRobot reads the Hugging Face settings when imported, and this
# one must find no hub (offline) and keep its cache in the test's folder.
LOAD_WITH_LEROBOT = """
import json, sys
from lerobot.datasets.lerobot_dataset import LeRobotDataset
ds = LeRobotDataset("local/behavior", root=sys.argv[1])
first, last = ds[0], ds[len(ds) - 1]
print(json.dumps({
    "episodes": ds.num_episodes, "frames": ds.num_frames, "fps": ds.fps,
    "robot": ds.meta.robot_type,
    "task": last["task"],
    "last_action": last["action"].tolist(),
    "last_episode": int(last["episode_index"]),
    "image": list(first["observation.images.eye"].shape),
    "provenance": json.loads(ds.meta.episodes[1]["provenance"]),
    "action_count": int(ds.meta.stats["action"]["count"][0]),
}))
"""


def test_a_v3_export_loads_in_lerobots_own_dataset_class(tmp_path):
    first, second = tmp_path / "a.mcap", tmp_path / "b.mcap"
    record_episode(first, steps=6)
    actions = record_episode(second, steps=4)
    dataset = tmp_path / "dataset"
    summary = export_lerobot(dataset, [first, second], image_size=32)
    assert summary["format"] == "lerobot-v3" and summary["frames"] == 10

    env = dict(os.environ, HF_HUB_OFFLINE="1", HF_HOME=str(tmp_path / "hf"))
    run = subprocess.run([sys.executable, "-c", LOAD_WITH_LEROBOT, str(dataset)],
                         capture_output=True, text=True, env=env, timeout=600)
    assert run.returncode == 0, run.stderr
    got = json.loads(run.stdout.strip().splitlines()[-1])
    assert (got["episodes"], got["frames"], got["fps"]) == (2, 10, 30)
    assert got["robot"] == "behavior" and got["task"] == "bringing in wood"
    assert got["last_episode"] == 1
    np.testing.assert_array_equal(np.array(got["last_action"], np.float32), actions[-1])
    assert got["image"] == [3, 32, 32], "channels first, as LeRobot hands images to policies"
    assert got["provenance"]["scene"] and got["provenance"]["by"]["kind"] == "unstated"
    assert got["action_count"] == 10


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
    with pytest.raises(ValueError, match="format must be one of lerobot-v3, lerobot-v2.1"):
        export_lerobot(dataset, [recording], image_size=None, format="lerobot-v9")
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
