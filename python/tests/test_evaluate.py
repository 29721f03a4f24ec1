"""The evaluation protocol: its episodes over seen and unseen instances, each episode's metrics
and the summary, from a random agent and from a trained baseline."""

import json

import numpy as np
import pytest

import behavior
from behavior import _core
from behavior import evaluate as protocol

ACTIVITY = "bringing_in_wood"


def test_the_protocols_episodes_split_seen_and_unseen_instances():
    homes = behavior.covering_homes(ACTIVITY)
    assert len(homes) >= 2
    episodes = protocol.episodes(ACTIVITY)
    assert [e.instance_id for e in episodes] == [0, 1, 2, 10, 11, 12, 20, 21, 22]
    assert [e.split for e in episodes] == ["seen"] * 3 + ["unseen_object_poses"] * 3 + [
        "unseen_furniture"] * 3
    assert {e.home for e in episodes[:6]} == {homes[0]}
    assert {e.home for e in episodes[6:]} == {homes[1]}
    with pytest.raises(ValueError, match="0 to 29"):
        protocol.split_of(30)


def test_a_random_agent_is_evaluated_and_summarized(tmp_path):
    out = tmp_path / "eval"
    assert protocol.main(["--policy", "random", "--activities", ACTIVITY, "--instances", "0",
                          "10", "20", "--horizon", "6", "--out", str(out)]) == 0
    per_episode = json.loads((out / "per_episode_metrics.json").read_text())
    aggregated = json.loads((out / "aggregated_metrics.json").read_text())
    assert sorted(per_episode) == ["0", "1", "2"]
    assert [per_episode[k]["instance_id"] for k in "012"] == [0, 10, 20]
    assert all(per_episode[k]["steps"] <= 6 for k in "012"), "six primitives, one step each"
    qs = [per_episode[k]["q_final"] for k in "012"]
    assert aggregated["Episodes"] == 3
    assert aggregated["Success Score"] == pytest.approx(np.mean(qs))
    assert aggregated["Distance Navigated"] == pytest.approx(
        np.mean([per_episode[k]["distance_navigated"] for k in "012"]))
    assert sorted(aggregated["By Split"]) == ["seen", "unseen_furniture", "unseen_object_poses"]
    assert aggregated["By Split"]["seen"]["Success Score"] == pytest.approx(qs[0])


def test_efficiency_is_also_given_relative_to_demonstrations_with_their_provenance(tmp_path):
    # A folder as `behavior demos generate` leaves one: a recording and its manifest.
    demos = tmp_path / "demos"
    (demos / "episodes").mkdir(parents=True)
    recording = demos / "episodes" / "first.mcap"
    env = behavior.BehaviorEnv(ACTIVITY, seed=0)
    env.reset(seed=0)
    env.record(recording)
    rng = np.random.default_rng(3)
    for _ in range(20):
        env.step(rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
    env.stop_recording()
    home = behavior.covering_homes(ACTIVITY)[0]
    manifest = {"robot": "behavior", "demos": [{"file": "episodes/first.mcap"}]}
    (demos / "demos.json").write_text(json.dumps(manifest))

    out = tmp_path / "eval"
    assert protocol.main(["--policy", "random", "--activities", ACTIVITY, "--instances", "0",
                          "10", "--horizon", "6", "--out", str(out),
                          "--reference", str(demos)]) == 0
    per_episode = json.loads((out / "per_episode_metrics.json").read_text())
    aggregated = json.loads((out / "aggregated_metrics.json").read_text())
    # Instance 0 is seed 0 in the first home, as the reference: compared on its instance.
    assert per_episode["0"]["reference"] == "instance"
    assert per_episode["1"]["reference"] == "activity", "seed 10 was not demonstrated"
    ratio = per_episode["0"]["relative"]["simulated_time"]
    assert ratio == pytest.approx(per_episode["0"]["sim_time_s"] * 30 / 20), "steps over 20"
    relative = aggregated["Relative"]
    assert relative["Simulated Time"] == pytest.approx(np.mean(
        [per_episode[k]["relative"]["simulated_time"] for k in "01"]))
    assert aggregated["Simulated Time"] == pytest.approx(np.mean(
        [per_episode[k]["sim_time_s"] for k in "01"])), "the absolute means stay"
    [reference] = aggregated["References"]
    assert reference["instance"] == f"{home} seed 0"
    assert reference["provenance"] == {"kind": "unstated"}, "a script's episode, said so"

    with pytest.raises(SystemExit):
        protocol.main(["--policy", "random", "--activities", ACTIVITY, "--reference",
                       str(tmp_path)])


def test_a_model_without_its_settings_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit):
        protocol.main(["--model", str(tmp_path / "model.zip")])
    assert "with its result.json beside it" in capsys.readouterr().err


def test_bad_metrics_and_unknown_activities_are_refused():
    good = json.dumps(behavior.BehaviorEnv(ACTIVITY).metrics())
    assert json.loads(_core.aggregate([(ACTIVITY, good)]))["episodes"] == 1
    with pytest.raises(ValueError, match="episode 1's metrics: key must be a string"):
        _core.aggregate([(ACTIVITY, good), (ACTIVITY, "{not json")])
    with pytest.raises(ValueError, match="episode 0's metrics: missing field `success`"):
        _core.aggregate([(ACTIVITY, json.dumps({"steps": 1, "q_final": 0.5}))])
    with pytest.raises(ValueError, match="not an official activity"):
        behavior.covering_homes("no_such_activity")


def test_a_trained_baseline_is_evaluated_as_it_was_trained(tmp_path):
    pytest.importorskip("stable_baselines3")
    from behavior.baselines import ppo
    from behavior.baselines.training import TrainConfig

    config = TrainConfig(ACTIVITY, "ap_nophys_fullobs", timesteps=256, horizon=8, masked=True,
                         out=tmp_path / "run")
    ppo.train(config)
    out = tmp_path / "eval"
    assert protocol.main(["--model", str(config.out / "model.zip"), "--instances", "0", "20",
                          "--out", str(out)]) == 0
    per_episode = json.loads((out / "per_episode_metrics.json").read_text())
    assert [m["task"] for m in per_episode.values()] == [ACTIVITY, ACTIVITY]
    assert all(m["steps"] <= 8 for m in per_episode.values()), "the run's own horizon"
