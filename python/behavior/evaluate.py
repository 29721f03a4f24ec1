"""The benchmark's evaluation protocol (BEHAVIOR's `behavior/benchmark/behavior_benchmark.py`): per activity nine episodes over seen
and unseen instances, each episode's metrics, and their summary.

Instances are named by the original's ids: 0–9 *seen poses* (seeds 0–9 in the activity's first
covering home, where training samples by default), 10–19 *unseen object poses* (seeds 10–19 in
that home: the same furniture, objects placed anew), 20–29 *unseen furniture* (seeds 20–29 in its
second covering home). Every activity is covered by several of our homes, so each takes the
original's one-scene choice of ids, 0 1 2 10 11 12 20 21 22 (an activity only one home covers
takes its unseen-furniture episodes in that home, and says so).

Writes, as the original does, ``per_episode_metrics.json`` (episode index → its metrics, with
``task``, ``instance_id``, ``home``, ``split``) and ``aggregated_metrics.json`` (Success Score,
Success Score Top 5, and the means of Simulated Time, Kinematic and Logical Disarrangement,
Distance Navigated and Displacement of Hands; also per split). The summary is the Rust
``aggregate``'s.

With ``--reference`` (recordings of demonstrations, or a folder made by ``behavior demos
generate``), each episode's efficiency metrics are also given relative to the best reference on
the same activity and instance (home and seed), else on the activity (``reference``:
``"instance"`` or ``"activity"``; ``relative``), the summary adds their means (``Relative``)
beside the absolute ones, and lists every reference with who made it (``References``:
``provenance``, the recording header's — a person, the planner, or unstated): the planner's
demonstrations are no human data.

``python -m behavior.evaluate --model runs/ppo/ap_nophys_fullobs/storing_food/0/model.zip``
evaluates a baseline trained by ``behavior.baselines`` (its settings read from the
``result.json`` beside it); ``--policy random`` a uniformly random agent (among the feasible
primitives, with primitives).
"""

import argparse
import json
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Dict, List, Optional, Sequence

import numpy as np
from gymnasium.wrappers import TimeLimit

from . import _core
from .baselines.rows import ACTIVITIES, PRIMITIVE_HORIZON, ROWS
from .baselines.rows import row as row_named
from .env import BehaviorEnv

# The episodes of an activity, as the original's instance ids (its one-scene choice).
INSTANCE_IDS = (0, 1, 2, 10, 11, 12, 20, 21, 22)
# The original's names of the summary's entries, from ours.
SUMMARY_NAMES = {
    "episodes": "Episodes",
    "success_score": "Success Score",
    "success_score_top5": "Success Score Top 5",
    "simulated_time": "Simulated Time",
    "kinematic_disarrangement": "Kinematic Disarrangement",
    "logical_disarrangement": "Logical Disarrangement",
    "distance_navigated": "Distance Navigated",
    "displacement_of_hands": "Displacement of Hands",
}


@dataclass(frozen=True)
class Episode:
    """One episode of the protocol."""

    activity: str
    instance_id: int
    home: str
    # "seen", "unseen_object_poses" or "unseen_furniture".
    split: str

    @property
    def seed(self) -> int:
        return self.instance_id


def split_of(instance_id: int) -> str:
    if not 0 <= instance_id < 30:
        raise ValueError(f"instance ids run 0 to 29, not {instance_id}")
    return ("seen", "unseen_object_poses", "unseen_furniture")[instance_id // 10]


def episodes(activity: str, instance_ids: Sequence[int] = INSTANCE_IDS) -> List[Episode]:
    """The protocol's episodes of `activity`."""
    homes = _core.covering_homes(activity)
    if not homes:
        raise ValueError(f"no named home covers {activity}")
    if len(homes) == 1 and any(i >= 20 for i in instance_ids):
        print(f"{activity}: only {homes[0]} covers it; its unseen-furniture episodes are there",
              file=sys.stderr)
    out = []
    for i in instance_ids:
        split = split_of(i)
        home = homes[1] if split == "unseen_furniture" and len(homes) > 1 else homes[0]
        out.append(Episode(activity, i, home, split))
    return out


# A policy: from the environment (for its masks and spaces) and an observation, an action.
Policy = Callable[[BehaviorEnv, dict], object]


def random_policy(seed: int = 0) -> Policy:
    """Uniform random actions; with primitives, uniform among the feasible ones."""
    rng = np.random.default_rng(seed)

    def act(env: BehaviorEnv, obs: dict):
        if env.action_space.shape == ():
            feasible = np.flatnonzero(env.action_masks())
            return int(rng.choice(feasible)) if len(feasible) else 0
        space = env.action_space
        return rng.uniform(space.low, space.high).astype(np.float32)

    return act


def model_policy(path: Path, masked: bool, algorithm: str) -> Policy:
    """A Stable-Baselines3 model, acting as in training (sampling its actions)."""
    if algorithm == "sac":
        from stable_baselines3 import SAC as Algorithm
    elif masked:
        from sb3_contrib import MaskablePPO as Algorithm
    else:
        from stable_baselines3 import PPO as Algorithm
    model = Algorithm.load(path, device="cpu")

    def act(env: BehaviorEnv, obs: dict):
        kwargs = {"action_masks": env.action_masks()} if masked else {}
        action, _ = model.predict(obs, deterministic=False, **kwargs)
        return action

    return act


def run_episode(env, policy: Policy, seed: int) -> dict:
    """One episode from the instance of `seed` to its end; its metrics."""
    obs, _ = env.reset(seed=seed)
    done = False
    while not done:
        obs, _, terminated, truncated, _ = env.step(policy(env.unwrapped, obs))
        done = terminated or truncated
    return env.unwrapped.metrics()


def _activity_key(name: str) -> str:
    """An activity's name without its problem's instance number (``storing_food_0``)."""
    return re.sub(r"_\d+$", "", name)


def _instance(home: str, seed: int) -> str:
    return f"{home} seed {seed}"


def load_references(paths: Sequence["str | os.PathLike"]) -> List[dict]:
    """The reference recordings named (files, or folders made by ``behavior demos generate``:
    the demonstrations their ``demos.json`` lists), each re-simulated: ``file``, ``activity``,
    ``instance``, ``provenance`` and ``metrics``. One that does not replay identically is refused
    (``ValueError``): its metrics would not be the recorded episode's."""
    files = []
    for path in map(Path, paths):
        if path.is_dir():
            manifest = path / "demos.json"
            if not manifest.is_file():
                raise ValueError(f"{path} is a folder without demos.json (made by `behavior demos "
                                 f"generate`): name its recordings instead")
            files += [path / d["file"] for d in json.loads(manifest.read_text())["demos"]]
        else:
            files.append(path)
    references = []
    for file in files:
        r = json.loads(_core.replay(os.fspath(file), True))
        if r["damage"] or not r["identical"] or r["metrics"] is None:
            raise ValueError(f"{file} does not replay identically (damage: {r['damage']}, first "
                             f"difference: {r['first_difference']}): not a reference")
        references.append({"file": str(file), "activity": _activity_key(r["activity"]),
                           "instance": _instance(r["scene"], r["seed"]),
                           "provenance": r["provenance"], "metrics": r["metrics"]})
    return references


def add_relative(per_episode: List[dict], references: List[dict]) -> dict:
    """Gives each episode its ``reference`` and ``relative`` metrics (the Rust
    ``HumanReference``'s); returns their means under the summary's names."""
    pairs = json.loads(_core.relative_metrics(
        [(r["activity"], r["instance"], json.dumps(r["metrics"])) for r in references],
        [(_activity_key(m["task"]), _instance(m["home"], m["seed"]), json.dumps(m))
         for m in per_episode]))
    for m, pair in zip(per_episode, pairs):
        m.update(pair)
    means = {}
    for key, name in SUMMARY_NAMES.items():
        if key in ("episodes", "success_score", "success_score_top5"):
            continue
        values = [m["relative"][key] for m in per_episode
                  if m["relative"] and m["relative"].get(key) is not None]
        means[name] = float(np.mean(values)) if values else None
    return means


def summary(per_episode: List[dict]) -> dict:
    """The protocol's summary of episodes (each with its ``task``), with the original's names."""
    ours = json.loads(_core.aggregate([(m["task"], json.dumps(m)) for m in per_episode]))
    return {SUMMARY_NAMES.get(k, k): v for k, v in ours.items()}


@dataclass
class Setup:
    """How the agent acts and what it sees: a Table 1 row's environment."""

    row: str = "ap_nophys_fullobs"
    robot: str = "behavior"
    image_size: int = 128
    # Steps (continuous) or primitives per episode; None for the defaults (the environment's
    # for continuous control, `PRIMITIVE_HORIZON` primitives).
    horizon: Optional[int] = None

    def make(self, episode: Episode):
        spec = row_named(self.row)
        env = spec.env(episode.activity, robot=self.robot, scene=episode.home,
                       seed=episode.seed, image_size=self.image_size)
        horizon = self.horizon
        if horizon is None and spec.action_space == "primitives":
            horizon = PRIMITIVE_HORIZON
        return env if horizon is None else TimeLimit(env, max_episode_steps=horizon)


def evaluate(activities: Sequence[str], policy: Policy, setup: Setup,
             instance_ids: Sequence[int] = INSTANCE_IDS, log=print,
             references: Optional[List[dict]] = None) -> Dict[str, object]:
    """Every activity's protocol episodes: ``per_episode`` (a list of metrics dicts, labelled)
    and ``aggregated`` (the summary, overall and per split); with ``references``
    (``load_references``), each episode's metrics relative to them as well."""
    per_episode = []
    for activity in activities:
        envs = {}
        for episode in episodes(activity, instance_ids):
            if episode.home not in envs:
                envs[episode.home] = setup.make(episode)
            metrics = run_episode(envs[episode.home], policy, episode.seed)
            per_episode.append({"task": activity, "instance_id": episode.instance_id,
                                "home": episode.home, "seed": episode.seed,
                                "split": episode.split, **metrics})
            log(f"{activity} instance {episode.instance_id} ({episode.split}, {episode.home}): "
                f"Q {metrics['q_final']:.3f}")
        for env in envs.values():
            env.close()
    aggregated = summary(per_episode)
    splits = sorted({m["split"] for m in per_episode})
    aggregated["By Split"] = {s: summary([m for m in per_episode if m["split"] == s])
                              for s in splits}
    if references:
        aggregated["Relative"] = add_relative(per_episode, references)
        aggregated["References"] = [{k: r[k] for k in ("file", "activity", "instance",
                                                        "provenance")} for r in references]
    return {"per_episode": per_episode, "aggregated": aggregated}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--activities", nargs="+", default=None,
                   help="official activities (default: Table 1's 12; a model's own activity)")
    who = p.add_mutually_exclusive_group(required=True)
    who.add_argument("--model", type=Path, help="a baseline's model.zip")
    who.add_argument("--policy", choices=["random"], help="a built-in agent")
    p.add_argument("--row", default="ap_nophys_fullobs", choices=sorted(ROWS),
                   help="the environment's setup for --policy (a model's own otherwise)")
    p.add_argument("--robot", default="behavior", choices=["behavior", "fetch", "r1"])
    p.add_argument("--horizon", type=int, default=None, help="actions per episode")
    p.add_argument("--instances", type=int, nargs="+", default=list(INSTANCE_IDS),
                   help="instance ids, 0-29")
    p.add_argument("--seed", type=int, default=0, help="the random agent's seed")
    p.add_argument("--out", type=Path, default=Path("runs/evaluation"))
    p.add_argument("--reference", nargs="+", default=[], metavar="DEMO.mcap|DIR",
                   help="demonstrations to measure efficiency against (a folder made by "
                        "`behavior demos generate` stands for its demonstrations)")
    args = p.parse_args(argv)
    setup = Setup(row=args.row, robot=args.robot, horizon=args.horizon)
    activities = args.activities or list(ACTIVITIES)
    if args.model is not None:
        settings = args.model.parent / "result.json"
        if not args.model.is_file() or not settings.is_file():
            p.error(f"--model {args.model}: a baseline's model.zip with its result.json beside "
                    f"it (as behavior.baselines writes them) is needed")
        trained = json.loads(settings.read_text())
        setup = Setup(row=trained["row"], robot=trained["robot"],
                      image_size=trained["image_size"], horizon=args.horizon or trained["horizon"])
        policy = model_policy(args.model, trained["masked"], trained["algorithm"])
        activities = args.activities or [trained["activity"]]
    else:
        policy = random_policy(args.seed)
    for i in args.instances:
        split_of(i)
    try:
        references = load_references(args.reference)
    except (ValueError, OSError) as e:
        p.error(f"--reference: {e}")
    result = evaluate(activities, policy, setup, args.instances, references=references)
    args.out.mkdir(parents=True, exist_ok=True)
    per_episode = {str(i): m for i, m in enumerate(result["per_episode"])}
    (args.out / "per_episode_metrics.json").write_text(json.dumps(per_episode, indent=2) + "\n")
    (args.out / "aggregated_metrics.json").write_text(
        json.dumps(result["aggregated"], indent=2) + "\n")
    print(json.dumps({k: v for k, v in result["aggregated"].items()
                      if k not in ("By Split", "References")}, indent=2))
    for r in result["aggregated"].get("References", []):
        print(f"reference {r['file']} ({r['activity']}, {r['instance']}): "
              f"by {r['provenance'].get('kind', 'unstated')}")
    print(f"written: {args.out / 'per_episode_metrics.json'}, aggregated_metrics.json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
