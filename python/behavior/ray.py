"""Rollouts and evaluation on a Ray cluster: each worker is a Ray actor holding its own
environments (``BehaviorVecEnv`` for rollouts, ``BehaviorEnv`` for evaluation).

On one machine ``ray.init()`` starts a local instance; on a cluster, start Ray there
(``ray start --head`` on one machine, ``ray start --address=HEAD:6379`` on the others, the
package installed on each) and pass ``address="auto"`` (or ``"ray://HEAD:10001"`` from outside
it) — or set ``RAY_ADDRESS``. Every worker builds its environments from the same names, so
the same seeds give the same episodes wherever they run.

A policy is any picklable callable from a batch of observations (a dict of ``(N, ...)``
arrays) to a batch of actions ``(N, action_dim)``; ``None`` takes uniform random actions drawn
from the worker's seed.
"""

from typing import Any, Callable, Dict, List, Optional

import numpy as np
import ray
from gymnasium.vector.utils import batch_space

from .env import BehaviorEnv
from .vector import BehaviorVecEnv

Policy = Callable[[Dict[str, np.ndarray]], np.ndarray]


def _connect(address: Optional[str], num_cpus: Optional[int]) -> None:
    if not ray.is_initialized():
        ray.init(address=address, num_cpus=num_cpus, include_dashboard=False,
                 log_to_driver=False)


def _act(policy: Optional[Policy], obs, space, rng: np.random.Generator) -> np.ndarray:
    """A batch of actions in the batched ``space``: the policy's, or uniform random ones."""
    if policy is None:
        return rng.uniform(space.low, space.high).astype(np.float32)
    return np.asarray(policy(obs), dtype=np.float32)


@ray.remote
class RolloutWorker:
    """A Ray actor stepping a ``BehaviorVecEnv`` of its own."""

    def __init__(self, activity: str, num_envs: int, env_kwargs: Dict[str, Any]):
        self.envs = BehaviorVecEnv(activity, num_envs=num_envs, **env_kwargs)

    def rollout(self, steps: int, seed: int, policy: Optional[Policy]) -> Dict[str, np.ndarray]:
        """``steps`` steps of every environment from a reset with ``seed``: the rewards,
        terminations, truncations and Q, ``(steps, num_envs)`` each, and the last ``task_obs``
        (if observed)."""
        rng = np.random.default_rng(seed)
        obs, _ = self.envs.reset(seed=seed)
        out = {k: [] for k in ("rewards", "terminated", "truncated", "q")}
        for _ in range(steps):
            actions = _act(policy, obs, self.envs.action_space, rng)
            obs, rewards, terminated, truncated, info = self.envs.step(actions)
            for key, value in (("rewards", rewards), ("terminated", terminated),
                               ("truncated", truncated), ("q", info["q"])):
                out[key].append(value)
        result = {k: np.stack(v) for k, v in out.items()}
        if "task_obs" in obs:
            result["last_task_obs"] = obs["task_obs"]
        return result


@ray.remote
class EvaluationWorker:
    """A Ray actor running whole episodes of a ``BehaviorEnv`` of its own."""

    def __init__(self, activity: str, env_kwargs: Dict[str, Any]):
        self.env = BehaviorEnv(activity, **env_kwargs)
        self.batched_space = batch_space(self.env.action_space, 1)

    def episode(self, seed: int, policy: Optional[Policy]) -> Dict[str, Any]:
        """One episode from a reset with ``seed`` to its end: its metrics (as ``behavior run
        --json`` reports them) and its seed."""
        rng = np.random.default_rng(seed)
        obs, _ = self.env.reset(seed=seed)
        done = False
        while not done:
            batch = {k: v[None] for k, v in obs.items()}
            action = _act(policy, batch, self.batched_space, rng)[0]
            obs, _, terminated, truncated, _ = self.env.step(action)
            done = terminated or truncated
        return {"seed": seed, **self.env.metrics()}


def rollouts(activity: str, steps: int, num_workers: int = 2, envs_per_worker: int = 1,
             seed: int = 0, policy: Optional[Policy] = None, address: Optional[str] = None,
             num_cpus: Optional[int] = None, **env_kwargs) -> List[Dict[str, np.ndarray]]:
    """``steps`` steps of ``envs_per_worker`` environments on each of ``num_workers`` Ray
    actors, worker w reset with ``seed + w * envs_per_worker`` (so its environment k gets that
    plus k): one dict of ``(steps, envs_per_worker)`` arrays per worker."""
    _connect(address, num_cpus)
    workers = [RolloutWorker.remote(activity, envs_per_worker, env_kwargs)
               for _ in range(num_workers)]
    return ray.get([w.rollout.remote(steps, seed + i * envs_per_worker, policy)
                    for i, w in enumerate(workers)])


def evaluate(activity: str, episodes: int, num_workers: int = 2, seed: int = 0,
             policy: Optional[Policy] = None, address: Optional[str] = None,
             num_cpus: Optional[int] = None, **env_kwargs) -> Dict[str, Any]:
    """``episodes`` episodes, seeds ``seed`` … ``seed + episodes - 1``, spread over
    ``num_workers`` Ray actors: each episode's metrics, the success rate and the mean Q."""
    _connect(address, num_cpus)
    workers = [EvaluationWorker.remote(activity, env_kwargs) for _ in range(num_workers)]
    runs = ray.get([workers[e % num_workers].episode.remote(seed + e, policy)
                    for e in range(episodes)])
    return {
        "activity": activity,
        "episodes": runs,
        "success_rate": float(np.mean([r["success"] for r in runs])),
        "mean_q": float(np.mean([r["q_final"] for r in runs])),
    }
