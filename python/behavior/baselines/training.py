"""Training one baseline on one activity: the environment as a row of Table 1 sets it up, the
learning curve (each episode's final Q against the steps taken), the trained policy evaluated,
and what a run leaves in its folder:

- ``curve.csv``: ``timesteps,q,success`` for every training episode, as it ended;
- ``model.zip``: the policy (Stable-Baselines3's format);
- ``result.json``: the configuration, wall time, and the trained policy's Q: ``q`` and
  ``success_rate`` over ``EVALUATION_EPISODES`` episodes with actions sampled from the policy
  (as in training), and ``q_likeliest_actions`` taking the likeliest action every time (which can
  repeat a primitive that fails forever, where sampling moves on).

Training follows the paper's setup: one instance of the activity (the instance sampled with
seed ``instance``) for every episode, unless ``sampled`` asks for a new one each episode. The
reward is ΔQ (the environment's). An episode ends when the goal holds or after ``horizon``
actions (primitives, or continuous steps).
"""

import argparse
import csv
import json
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import List, Optional, Tuple

import gymnasium
import numpy as np
import torch
from gymnasium.wrappers import TimeLimit
from stable_baselines3.common.callbacks import BaseCallback
from stable_baselines3.common.logger import configure
from stable_baselines3.common.monitor import Monitor
from stable_baselines3.common.vec_env import DummyVecEnv

from ..env import BehaviorEnv
from .extractor import BehaviorExtractor
from .rows import CONTINUOUS_HORIZON, PRIMITIVE_HORIZON, ROWS
from .rows import row as row_named

# Episodes the trained policy is evaluated on.
EVALUATION_EPISODES = 10


@dataclass
class TrainConfig:
    """One training run."""

    activity: str
    row: str
    seed: int = 0
    timesteps: int = 20_000
    robot: str = "behavior"
    # The instance (sampling seed) every episode starts from, unless `sampled`.
    instance: int = 0
    sampled: bool = False
    # Actions per episode; None for the row's default.
    horizon: Optional[int] = None
    n_envs: int = 1
    image_size: int = 128
    # PPO only: sb3-contrib's MaskablePPO with the feasible actions' mask.
    masked: bool = False
    # Torch's threads (1 lets two runs share two cores).
    threads: int = 1
    out: Path = field(default_factory=lambda: Path("runs"))

    def episode_horizon(self) -> int:
        if self.horizon is not None:
            return self.horizon
        primitives = row_named(self.row).action_space == "primitives"
        return PRIMITIVE_HORIZON if primitives else CONTINUOUS_HORIZON


class FixedInstance(gymnasium.Wrapper):
    """Every episode starts from the same instance, the one sampled with seed ``instance``: the
    first reset samples it, the others restore its start (the same, bit for bit, without
    sampling again). Wraps a ``BehaviorEnv`` directly."""

    def __init__(self, env: BehaviorEnv, instance: int):
        super().__init__(env)
        self.instance = instance
        self._start = None

    def reset(self, *, seed=None, options=None):
        if self._start is None:
            out = self.env.reset(seed=self.instance, options=options)
            self._start = self.env.checkpoint()
            return out
        return self.env.restore(self._start)


def make_env(config: TrainConfig) -> gymnasium.Env:
    """The environment of a run: the row's action space and observations, the horizon, the
    instance (sampled runs draw each episode's from the seeds the algorithm gives)."""
    env = row_named(config.row).env(config.activity, robot=config.robot, seed=config.instance,
                                    image_size=config.image_size)
    if not config.sampled:
        env = FixedInstance(env, config.instance)
    return Monitor(TimeLimit(env, max_episode_steps=config.episode_horizon()))


def vector_env(config: TrainConfig) -> DummyVecEnv:
    """`n_envs` environments stepped in turn (Stable-Baselines3's interface)."""
    return DummyVecEnv([lambda: make_env(config)] * config.n_envs)


class QCurve(BaseCallback):
    """Records each training episode's final Q and success as it ends."""

    def __init__(self):
        super().__init__()
        self.points: List[Tuple[int, float, bool]] = []

    def _on_step(self) -> bool:
        for done, info in zip(self.locals["dones"], self.locals["infos"]):
            if done:
                self.points.append((self.num_timesteps, float(info["q"]), bool(info["success"])))
        return True


def policy_kwargs() -> dict:
    """The original baseline's network: `BehaviorExtractor`, then the algorithm's MLP heads."""
    return {"features_extractor_class": BehaviorExtractor}


def evaluate(model, config: TrainConfig, episodes: int, deterministic: bool) -> Tuple[float, float]:
    """The trained policy's mean final Q and success rate over `episodes` episodes from the
    training instance, sampling its actions or taking the likeliest (`deterministic`; the
    environment is deterministic too, so then one episode tells)."""
    env = make_env(config)
    scored = run_episodes(model, env, episodes, deterministic, config.masked)
    env.close()
    return scored


def run_episodes(model, env: gymnasium.Env, episodes: int, deterministic: bool,
                 masked: bool = False) -> Tuple[float, float]:
    """`episodes` whole episodes of `model`'s policy in `env`: their mean final Q and success
    rate (with `masked`, the feasible actions' mask given to the policy)."""
    qs, successes = [], []
    for _ in range(episodes):
        obs, info = env.reset()
        done = False
        while not done:
            kwargs = {}
            if masked:
                kwargs["action_masks"] = env.get_wrapper_attr("action_masks")()
            action, _ = model.predict(obs, deterministic=deterministic, **kwargs)
            obs, _, terminated, truncated, info = env.step(action)
            done = terminated or truncated
        qs.append(float(info["q"]))
        successes.append(bool(info["success"]))
    return float(np.mean(qs)), float(np.mean(successes))


def write_curve(out: Path, curve: QCurve) -> None:
    """Writes `curve.csv` in the folder `out` (made if missing)."""
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "curve.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["timesteps", "q", "success"])
        writer.writerows((t, f"{q:.6f}", int(s)) for t, q, s in curve.points)


def write_run(config: TrainConfig, model, curve: QCurve, wall_s: float, algorithm: str) -> dict:
    """Saves the run's curve, model and result in `config.out`; returns the result."""
    out = Path(config.out)
    write_curve(out, curve)
    model.save(out / "model.zip")
    q, success_rate = evaluate(model, config, EVALUATION_EPISODES, deterministic=False)
    q_likeliest, _ = evaluate(model, config, 1, deterministic=True)
    settings = {k: (str(v) if isinstance(v, Path) else v) for k, v in asdict(config).items()}
    result = {
        **settings,
        "algorithm": algorithm,
        "horizon": config.episode_horizon(),
        "wall_s": round(wall_s, 2),
        "training_episodes": len(curve.points),
        "q": q,
        "success_rate": success_rate,
        "q_likeliest_actions": q_likeliest,
    }
    (out / "result.json").write_text(json.dumps(result, indent=2) + "\n")
    return result


def learn(model, config: TrainConfig, algorithm: str) -> dict:
    """Trains `model` for the run's timesteps, recording the curve, then saves and evaluates."""
    curve = QCurve()
    # SB3's own training log (losses, rates) as progress.csv beside the curve (`configure`
    # makes the folder); left to itself, SB3 makes an empty folder in the system's temporary
    # directory for every run.
    model.set_logger(configure(str(config.out), ["csv"]))
    start = time.perf_counter()
    model.learn(total_timesteps=config.timesteps, callback=curve)
    return write_run(config, model, curve, time.perf_counter() - start, algorithm)


def summary_line(config: TrainConfig, result: dict) -> str:
    """One line saying how a run went."""
    return (f"{config.activity} {config.row} seed {config.seed}: Q {result['q']:.3f} "
            f"(success rate {result['success_rate']:.2f}) after {config.timesteps} steps, "
            f"{result['training_episodes']} episodes, {result['wall_s']:.0f} s; in {config.out}")


def set_threads(config: TrainConfig) -> None:
    torch.set_num_threads(max(1, config.threads))


def parser(description: str) -> argparse.ArgumentParser:
    """The command-line options every baseline takes (a `TrainConfig`'s fields)."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("activity", help="an official activity (behavior.activities())")
    p.add_argument("--row", default="ap_nophys_fullobs", choices=sorted(ROWS),
                   help="the Table 1 row: action space, physics, observations")
    p.add_argument("--seed", type=int, default=0, help="the learner's seed")
    p.add_argument("--timesteps", type=int, default=TrainConfig.timesteps,
                   help="actions to train for (primitives or continuous steps)")
    p.add_argument("--robot", default="behavior", choices=["behavior", "fetch", "r1"])
    p.add_argument("--instance", type=int, default=0,
                   help="the instance's sampling seed, the same every episode")
    p.add_argument("--sampled", action="store_true",
                   help="a new instance every episode instead")
    p.add_argument("--horizon", type=int, default=None,
                   help=f"actions per episode (default {PRIMITIVE_HORIZON} primitives, "
                        f"{CONTINUOUS_HORIZON} continuous steps)")
    p.add_argument("--n-envs", type=int, default=1)
    p.add_argument("--image-size", type=int, default=128)
    p.add_argument("--threads", type=int, default=1, help="torch's threads")
    p.add_argument("--out", type=Path, default=None,
                   help="the run's folder (default runs/<algorithm>/<row>/<activity>/<seed>)")
    return p


def config_from(args: argparse.Namespace, algorithm: str) -> TrainConfig:
    """The run the parsed options ask for."""
    out = args.out or Path("runs", algorithm, args.row, args.activity, str(args.seed))
    return TrainConfig(
        activity=args.activity, row=args.row, seed=args.seed, timesteps=args.timesteps,
        robot=args.robot, instance=args.instance, sampled=args.sampled, horizon=args.horizon,
        n_envs=args.n_envs, image_size=args.image_size, threads=args.threads, out=out,
        masked=getattr(args, "masked", False),
    )
