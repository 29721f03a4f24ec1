"""Table 1's oracle rows, SR^ca @ T − k s: SAC on the robot's continuous actions, every episode
starting from a demonstration's state ``k`` simulated seconds before the demonstration reached
its goal, so that the agent has only the last stretch of the activity left to do.

As the paper: the start states come from demonstrations (here the planner's, made by
``behavior demos generate``; the paper's were people's in VR), ``k`` is 1, 2, 3 or 10 s, an
episode lasts at most three times ``k``, the reward counts goal literals (one per literal
reached, minus one per literal undone: ΔQ times the goal's literal count), and the trained
policy is scored by its success rate over 100 evaluation episodes (``SR``).

``python -m behavior.baselines.oracle ACTIVITY --demos DIR --before 1 --seed 0``

A run leaves what the other baselines leave (``curve.csv``, ``progress.csv``, ``model.zip``,
``result.json``), the result also naming each demonstration and the step its start was taken at.
"""

import argparse
import json
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import List, Optional

import gymnasium
from gymnasium.wrappers import TimeLimit
from stable_baselines3.common.logger import configure
from stable_baselines3.common.monitor import Monitor
from stable_baselines3.common.vec_env import DummyVecEnv

from ..env import BehaviorEnv
from ..recording import replay
from . import sac, training
from .rows import FULL, IMAGES

# The paper's offsets before success, in simulated seconds.
OFFSETS_S = (1, 2, 3, 10)
# Action steps per simulated second.
STEPS_PER_SECOND = 30
# An episode lasts at most this many times the offset.
HORIZON_FACTOR = 3
# Episodes the trained policy is evaluated on.
EVALUATION_EPISODES = 100


@dataclass(frozen=True)
class DemoStart:
    """Where one demonstration's start state is taken."""

    # The recording.
    file: str
    # Its home and sampling seed.
    scene: str
    seed: int
    # The first step after which the goal held.
    success_step: int
    # The step the start state is taken after (success_step minus the offset, at least 0).
    step: int


def success_step(q_after_each_step: List[Optional[float]]) -> Optional[int]:
    """The first step after which Q was 1 (steps count from 1), or ``None``."""
    for index, q in enumerate(q_after_each_step):
        if q is not None and q >= 1.0:
            return index + 1
    return None


def demonstrations(folder: Path, activity: str) -> List[Path]:
    """The recordings of `activity` in a folder made by ``behavior demos generate`` (its
    ``demos.json`` manifest), in the manifest's order. A folder without a manifest, or with no
    demonstration of the activity, raises ``ValueError``."""
    manifest = folder / "demos.json"
    if not manifest.is_file():
        raise ValueError(f"{folder} has no demos.json: make it with `behavior demos generate`")
    demos = json.loads(manifest.read_text()).get("demos", [])
    files = [folder / d["file"] for d in demos if _activity_of(d["activity"]) == label(activity)]
    if not files:
        raise ValueError(f"{manifest} lists no demonstration of {activity}")
    return files


def label(activity: str) -> str:
    """An activity's name, also for a definition file (its file name without ``.bddl``)."""
    return Path(activity).stem if activity.endswith(".bddl") else activity


def _activity_of(problem: str) -> str:
    """An activity's name from a problem name (``storing_food_0`` → ``storing_food``)."""
    stem, _, number = problem.rpartition("_")
    return stem if stem and number.isdigit() else problem


def demo_start(file: Path, before_s: float) -> DemoStart:
    """Where the start state `before_s` seconds before `file`'s success is; a recording that
    never reaches its goal raises ``ValueError``."""
    header = replay(file, verify=False)
    done = success_step(header["q"])
    if done is None:
        raise ValueError(f"{file} never reaches its goal: it has no state before success")
    step = max(0, done - round(before_s * STEPS_PER_SECOND))
    return DemoStart(str(file), header["scene"], int(header["seed"]), done, step)


class DemoStarts(gymnasium.Wrapper):
    """Every episode starts from one of the demonstrations' start states, in turn; the reward
    counts goal literals (ΔQ times the goal's literal count). Wraps a ``BehaviorEnv`` directly,
    built in the demonstrations' home."""

    def __init__(self, env: BehaviorEnv, starts: List[DemoStart]):
        super().__init__(env)
        self.literals = env.goal_literals
        self._checkpoints = [env.checkpoint_from_recording(s.file, s.step) for s in starts]
        self._next = 0
        self._q = 0.0

    def reset(self, *, seed=None, options=None):
        checkpoint = self._checkpoints[self._next % len(self._checkpoints)]
        self._next += 1
        obs, info = self.env.restore(checkpoint)
        self._q = float(info["q"])
        return obs, info

    def step(self, action):
        obs, _, terminated, truncated, info = self.env.step(action)
        q = float(info["q"])
        reward = (q - self._q) * self.literals
        self._q = q
        return obs, reward, terminated, truncated, info


@dataclass
class OracleConfig:
    """One run of an oracle row."""

    activity: str
    # Seconds before the demonstrations' success the episodes start.
    before_s: float
    demos: Path
    seed: int = 0
    timesteps: int = 5_000
    robot: str = "behavior"
    # "state" (the robot's and the task objects' state) or "images" (RGB-D + proprioception,
    # the paper's Q^ca observations; about 1 s a step on a CPU).
    observations: str = "state"
    image_size: int = 128
    # How many of the activity's demonstrations in the first one's home give start states.
    max_demos: int = 5
    evaluation_episodes: int = EVALUATION_EPISODES
    threads: int = 1
    out: Path = field(default_factory=lambda: Path("runs"))

    def horizon(self) -> int:
        return round(HORIZON_FACTOR * self.before_s * STEPS_PER_SECOND)


def starts_for(config: OracleConfig) -> List[DemoStart]:
    """The run's start states: the activity's demonstrations in the home of its first one (an
    environment lives in one home), at most ``max_demos``."""
    starts = [demo_start(f, config.before_s) for f in demonstrations(config.demos, config.activity)]
    home = starts[0].scene
    return [s for s in starts if s.scene == home][: max(1, config.max_demos)]


def make_env(config: OracleConfig, starts: List[DemoStart]) -> gymnasium.Env:
    """The run's environment: continuous actions in the demonstrations' home, episodes from
    their start states, at most ``horizon()`` steps."""
    observations = FULL if config.observations == "state" else IMAGES
    # The episode's own step count goes on from the demonstration's: its limit must leave room.
    room = max(s.step for s in starts) + config.horizon() + 1
    env = BehaviorEnv(config.activity, robot=config.robot, scene=starts[0].scene,
                      seed=starts[0].seed, max_steps=room, observations=observations,
                      image_size=config.image_size)
    return Monitor(TimeLimit(DemoStarts(env, starts), max_episode_steps=config.horizon()))


def evaluate(model, env: gymnasium.Env, episodes: int) -> dict:
    """The policy's success rate and mean final Q over `episodes` episodes, actions sampled
    from it as in training (from one start state a deterministic policy would repeat one
    episode)."""
    q, success_rate = training.run_episodes(model, env, episodes, deterministic=False)
    return {"success_rate": success_rate, "q": q}


def train(config: OracleConfig) -> dict:
    """Trains SAC from the demonstrations' start states, evaluates it, writes the run's folder;
    returns its result."""
    training.set_threads(config)
    starts = starts_for(config)
    images = config.observations == "images"
    model = sac.model(DummyVecEnv([lambda: make_env(config, starts)]), config.seed, images)
    out = Path(config.out)
    model.set_logger(configure(str(out), ["csv"]))
    curve = training.QCurve()
    started = time.perf_counter()
    model.learn(total_timesteps=config.timesteps, callback=curve)
    wall_s = time.perf_counter() - started
    training.write_curve(out, curve)
    model.save(out / "model.zip")
    env = make_env(config, starts)
    scored = evaluate(model, env, config.evaluation_episodes)
    env.close()
    settings = {k: (str(v) if isinstance(v, Path) else v) for k, v in asdict(config).items()}
    result = {
        **settings,
        "row": f"SR^ca @ T-{config.before_s:g}s",
        "algorithm": "sac",
        "hyperparameters": sac.HYPERPARAMETERS,
        "horizon": config.horizon(),
        "goal_literals": env.get_wrapper_attr("literals"),
        "starts": [asdict(s) for s in starts],
        "wall_s": round(wall_s, 2),
        "evaluation_wall_s": round(time.perf_counter() - started - wall_s, 2),
        "training_episodes": len(curve.points),
        "training_successes": sum(1 for _, _, s in curve.points if s),
        **scored,
    }
    (out / "result.json").write_text(json.dumps(result, indent=2) + "\n")
    return result


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("activity", help="an official activity with demonstrations in --demos")
    p.add_argument("--demos", type=Path, required=True,
                   help="a folder made by `behavior demos generate`")
    p.add_argument("--before", type=float, required=True,
                   help="seconds before the demonstrations' success to start (the paper: 1, 2, 3, 10)")
    p.add_argument("--seed", type=int, default=0, help="the learner's seed")
    p.add_argument("--timesteps", type=int, default=OracleConfig.timesteps)
    p.add_argument("--robot", default="behavior", choices=["behavior", "fetch", "r1"])
    p.add_argument("--observations", default="state", choices=["state", "images"])
    p.add_argument("--image-size", type=int, default=128)
    p.add_argument("--max-demos", type=int, default=OracleConfig.max_demos)
    p.add_argument("--evaluation-episodes", type=int, default=EVALUATION_EPISODES)
    p.add_argument("--threads", type=int, default=1, help="torch's threads")
    p.add_argument("--out", type=Path, default=None,
                   help="the run's folder (default runs/oracle/<activity>/T-<k>s/<seed>)")
    return p


def config_from(args: argparse.Namespace) -> OracleConfig:
    if args.before <= 0:
        raise ValueError(f"--before must be a positive number of seconds, not {args.before}")
    out = args.out or Path("runs", "oracle", label(args.activity), f"T-{args.before:g}s",
                           str(args.seed))
    return OracleConfig(
        activity=args.activity, before_s=args.before, demos=args.demos, seed=args.seed,
        timesteps=args.timesteps, robot=args.robot, observations=args.observations,
        image_size=args.image_size, max_demos=args.max_demos,
        evaluation_episodes=args.evaluation_episodes, threads=args.threads, out=out,
    )


def main(argv=None) -> int:
    config = config_from(parser().parse_args(argv))
    result = train(config)
    print(f"{config.activity} T-{config.before_s:g}s seed {config.seed}: success rate "
          f"{result['success_rate']:.2f} over {config.evaluation_episodes} episodes, Q "
          f"{result['q']:.3f}; {result['training_episodes']} training episodes "
          f"({result['training_successes']} successful), {result['wall_s']:.0f} s; in {config.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
