"""Recording episodes from Python and replaying them bit for bit; damaged and foreign files
refused or read up to the damage."""

import numpy as np
import pytest

import behavior
from behavior import BehaviorEnv

ACTIVITY = "bringing_in_wood"


def test_a_continuous_episode_replays_bit_for_bit(tmp_path):
    env = BehaviorEnv(ACTIVITY, seed=4)
    env.reset(seed=4)
    path = tmp_path / "run.mcap"
    env.record(path, checkpoint_every=5)
    rng = np.random.default_rng(0)
    qs = []
    for _ in range(12):
        _, _, _, _, info = env.step(rng.uniform(-1, 1, env.action_space.shape))
        qs.append(info["q"])
    env.stop_recording()
    assert not env.unwrapped._env.recording
    read = behavior.replay(path, verify=False)
    # The definition's problem name, as the file holds the definition itself.
    assert read["activity"] == f"{ACTIVITY}_0"
    assert (read["seed"], read["robot"]) == (4, "behavior")
    assert read["frames"] == 12 and read["identical"] is None and read["damage"] is None
    assert read["q"] == pytest.approx(qs)
    replayed = behavior.replay(path)
    assert replayed["identical"] is True and replayed["first_difference"] is None
    assert replayed["frames"] == 12 and replayed["checkpoints"] >= 3


def test_symbolic_primitives_replay_through_their_edits(tmp_path):
    env = BehaviorEnv(ACTIVITY, action_space="primitives")
    env.reset(seed=0)
    path = tmp_path / "primitives.mcap"
    env.record(path)
    rng = np.random.default_rng(1)
    for _ in range(6):
        env.step(int(rng.choice(np.flatnonzero(env.action_masks()))))
    last_q = env.unwrapped.metrics()["q_final"]
    env.reset(seed=1)  # finishes the recording
    replayed = behavior.replay(path)
    assert replayed["identical"] is True and replayed["frames"] == 6
    assert replayed["q_final"] == pytest.approx(last_q)


def test_damaged_and_foreign_files_are_reported(tmp_path):
    env = BehaviorEnv(ACTIVITY)
    path = tmp_path / "run.mcap"
    env.record(path, checkpoint_every=1)
    for _ in range(40):
        env.step(np.zeros(env.action_space.shape, dtype=np.float32))
    env.close()
    whole = path.read_bytes()
    cut = tmp_path / "cut.mcap"
    cut.write_bytes(whole[: len(whole) * 2 // 3])
    read = behavior.replay(cut, verify=False)
    assert read["damage"] and read["frames"] < 40
    not_mcap = tmp_path / "notes.mcap"
    not_mcap.write_text("not a recording")
    with pytest.raises(ValueError, match="notes.mcap: no readable header: .* Bad magic number"):
        behavior.replay(not_mcap)
    with pytest.raises(OSError, match="cannot read"):
        behavior.replay(tmp_path / "missing.mcap")
    with pytest.raises(OSError, match="cannot write the recording"):
        env.record(tmp_path / "no" / "such" / "folder.mcap")
    with pytest.raises(ValueError, match="checkpoint_every must be at least 1"):
        env.record(tmp_path / "x.mcap", checkpoint_every=0)
