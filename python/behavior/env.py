"""The Gymnasium environment over the Rust episode loop (``behavior._core.Env``)."""

from typing import Any, Optional

import gymnasium
import numpy as np
from gymnasium import spaces

from . import _core

# Seeds drawn for episodes reset without one stay within what the Rust side takes (u64) and
# numpy draws (int64).
_SEED_BOUND = 2**63 - 1


class BehaviorEnv(gymnasium.Env):
    """One BEHAVIOR activity with a robot, as Gymnasium's ``Env``.

    - ``activity``: an official activity's name (``behavior.activities()``).
    - ``robot``: ``"behavior"`` (the BehaviorRobot, 26-d actions) or ``"fetch"`` (11-d).
    - ``scene``: a named home; ``None`` for the first that covers the activity.
    - ``seed``: the first episode's seed (building the environment samples it once, to learn
      the observation's shapes).
    - ``max_steps``: the episode's step limit (default the Rust side's).
    - ``clutter``: whether the home holds its everyday clutter.

    Observations: a ``Dict`` of ``proprioception`` (22 numbers for the BehaviorRobot, 49 for
    Fetch) and ``task_obs`` (456: the robot's pose and 50 object slots), float32. Actions: a
    ``Box`` in [-1, 1]. Reward: the change of Q, the goal's success score. ``terminated``: the
    goal holds; ``truncated``: the step limit. ``info``: ``steps``, ``q``, ``success`` and
    ``conjuncts`` (whether each top-level conjunct of the goal holds).
    """

    metadata = {"render_modes": []}

    def __init__(
        self,
        activity: str = "bringing_in_wood",
        robot: str = "behavior",
        scene: Optional[str] = None,
        seed: int = 0,
        max_steps: Optional[int] = None,
        clutter: bool = True,
        render_mode: Optional[str] = None,
    ):
        if render_mode is not None:
            raise ValueError(f"render_mode {render_mode!r} is not offered yet (none is)")
        self._env = _core.Env(
            activity, robot=robot, scene=scene, seed=seed, max_steps=max_steps, clutter=clutter
        )
        first, _ = self._env.reset(seed)
        self.observation_space = spaces.Dict(
            {
                name: spaces.Box(-np.inf, np.inf, shape=value.shape, dtype=value.dtype)
                for name, value in first.items()
            }
        )
        dim = self._env.action_dim
        self.action_space = spaces.Box(-1.0, 1.0, shape=(dim,), dtype=np.float32)
        self.render_mode = render_mode

    @property
    def activity(self) -> str:
        return self._env.activity

    @property
    def robot(self) -> str:
        return self._env.robot

    @property
    def scene(self) -> str:
        return self._env.scene

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """Starts an episode: a new instance of the activity sampled with the episode's seed
        (``seed`` if given, else drawn from the environment's generator)."""
        super().reset(seed=seed)
        episode_seed = seed if seed is not None else int(self.np_random.integers(_SEED_BOUND))
        if episode_seed < 0:
            raise ValueError(f"seed must be a non-negative integer, not {episode_seed}")
        return self._env.reset(episode_seed)

    def step(self, action: Any):
        """One action step (1/30 s of simulated time)."""
        values = np.asarray(action, dtype=np.float32)
        if values.shape != self.action_space.shape:
            raise ValueError(
                f"the action must have shape {self.action_space.shape}, not {values.shape}"
            )
        return self._env.step(values)

    def metrics(self) -> dict:
        """The episode's metrics so far (as ``behavior run --json`` reports them)."""
        import json

        text = self._env.metrics_json()
        return {} if text is None else json.loads(text)
