"""The vector environment: N environments of one activity stepped in Rust threads."""

from typing import Any, Optional

import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from . import _core
from .env import _SEED_BOUND, STATE_OBSERVATIONS, _action_box, _box, _options


class BehaviorVecEnv(VectorEnv):
    """``num_envs`` environments of one activity as Gymnasium 1.x's ``VectorEnv``.

    Every step runs the environments' steps in parallel, one Rust thread each (at most one per
    core), with the interpreter's lock released, and returns batched arrays: observations
    ``(num_envs, ...)``, rewards, ``terminated`` and ``truncated`` ``(num_envs,)``, and ``info``
    with ``steps``, ``q`` and ``success`` arrays (and their ``_name`` masks).

    Autoreset is Gymnasium's default, "next step": the step after an environment's episode ended
    resets it, ignoring its action, and returns the new episode's first observation with reward
    0, neither terminated nor truncated. ``reset(seed=s)`` starts environment k with ``s + k``;
    the episodes an environment starts by itself after that get seeds derived from its own, so
    a run is the same for the same seed and actions. Arguments as ``BehaviorEnv``'s (continuous
    actions; no rendering).
    """

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP, "render_modes": []}

    def __init__(
        self,
        activity: str = "bringing_in_wood",
        num_envs: int = 2,
        robot: str = "behavior",
        scene: Optional[str] = None,
        seed: int = 0,
        max_steps: Optional[int] = None,
        clutter: bool = True,
        observations=STATE_OBSERVATIONS,
        image_size: int = 128,
        render_mode: Optional[str] = None,
        image_profile: str = "realistic",
    ):
        if render_mode is not None:
            raise ValueError(f"the vector environment renders nothing, not {render_mode!r}")
        self._env = _core.VecEnv(
            activity,
            num_envs,
            _options(robot, scene, seed, max_steps, clutter, observations, image_size,
                     image_profile=image_profile),
        )
        first, _ = self._env.reset(seed)
        self.num_envs = num_envs
        self.single_observation_space = spaces.Dict(
            {name: _box(value[0]) for name, value in first.items()}
        )
        self.single_action_space = _action_box(self._env.action_bounds)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self.render_mode = render_mode

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """Resets every environment: k with ``seed + k`` (``seed`` drawn from the vector
        environment's generator when not given)."""
        if seed is not None and not isinstance(seed, (int, np.integer)):
            raise ValueError(
                f"seed must be one integer (environment k gets seed + k), not {seed!r}"
            )
        super().reset(seed=seed)
        first = seed if seed is not None else int(self.np_random.integers(_SEED_BOUND))
        if first < 0:
            raise ValueError(f"seed must be a non-negative integer, not {first}")
        return self._env.reset(first)

    def step(self, actions: Any):
        """One step of every environment (see the class docs for autoreset)."""
        values = np.asarray(actions, dtype=np.float32)
        if values.shape != self.action_space.shape:
            raise ValueError(
                f"the actions must have shape {self.action_space.shape}, not {values.shape}"
            )
        return self._env.step(values)


def make_vec(activity: str, num_envs: int = 2, **kwargs) -> BehaviorVecEnv:
    """``num_envs`` environments of ``activity`` stepped in Rust threads (see
    ``BehaviorVecEnv``); keyword arguments as ``BehaviorEnv``'s."""
    return BehaviorVecEnv(activity, num_envs=num_envs, **kwargs)
