"""The Gymnasium environment over the Rust episode loop (``behavior._core.Env``)."""

import os
from typing import Any, Optional

import gymnasium
import numpy as np
from gymnasium import spaces

from . import _core

# Seeds drawn for episodes reset without one stay within what the Rust side takes (u64) and
# numpy draws (int64).
_SEED_BOUND = 2**63 - 1
# The state-only observations (the default).
STATE_OBSERVATIONS = ("proprioception", "task_obs")
# The key prefix of the overview camera that ``render()`` shows (not an observation).
_RENDER_PREFIX = "render/"


def _options(robot, scene, seed, max_steps, clutter, observations, image_size,
             render_size=None, primitives=None, primitive_mode="symbolic",
             image_profile="realistic"):
    """The native module's options: every key, as ``behavior._core.Env`` reads them."""
    if isinstance(observations, str):
        raise ValueError(f"observations is a list of names, not the string {observations!r}")
    return {
        "robot": robot,
        "scene": scene,
        "seed": seed,
        "max_steps": max_steps,
        "clutter": clutter,
        "observations": list(observations),
        "image_size": image_size,
        "image_profile": image_profile,
        "render_size": render_size,
        "primitives": primitives,
        "primitive_mode": primitive_mode,
    }


def _action_box(bounds) -> spaces.Box:
    """The continuous action space: each number within its ``(low, high)`` from the engine
    ([-1, 1], or a joint's limits where the number is the joint's position, as the R1's)."""
    low, high = (np.array(b, dtype=np.float32) for b in zip(*bounds))
    return spaces.Box(low, high, dtype=np.float32)


def _box(value: np.ndarray) -> spaces.Box:
    """The space of one observation, from its first value: images of integers within their
    type's range, the rest unbounded."""
    if np.issubdtype(value.dtype, np.integer):
        info = np.iinfo(value.dtype)
        return spaces.Box(info.min, info.max, shape=value.shape, dtype=value.dtype)
    return spaces.Box(-np.inf, np.inf, shape=value.shape, dtype=value.dtype)


class BehaviorEnv(gymnasium.Env):
    """One BEHAVIOR activity with a robot, as Gymnasium's ``Env``.

    - ``activity``: an official activity's name (``behavior.activities()``) or a definition file.
    - ``robot``: ``"behavior"`` (the BehaviorRobot, 26-d actions), ``"fetch"`` (11-d) or
      ``"r1"`` (the Galaxea R1 Pro, the BEHAVIOR Challenge's 23-d joint-position action).
    - ``scene``: a named home; ``None`` for the first that covers the activity.
    - ``seed``: the first episode's seed (building the environment samples it once, to learn
      the observation's shapes).
    - ``max_steps``: the episode's step limit (default the Rust side's).
    - ``clutter``: whether the home holds its everyday clutter.
    - ``observations``: what the agent observes: ``"proprioception"``, ``"task_obs"``,
      ``"lidar"`` and the robot camera's images ``"rgb"`` (``(s, s, 3)`` uint8), ``"depth"``
      (float32, m), ``"normal"``, ``"seg"`` (uint16 categories), ``"ins_seg"`` (uint32),
      ``"highlight"``, ``"flow"``, ``"scene_flow"``, each ``image_size`` pixels square (the
      original's 128 by default).
    - ``image_profile``: how the cameras draw colour: ``"realistic"`` (the default: materials,
      the home's sun with shadows, room lamps) or ``"fast"`` (flat colours, about four times
      faster on a CPU). Depth, segmentation and flow are the same in both.
    - ``action_space``: ``"continuous"`` (the robot's own actions, one step each) or
      ``"primitives"``: the original's ``Discrete(n × K)`` (object ``a % n``, primitive
      ``a // n``), each action one primitive run to its end, ``primitive_mode`` ``"symbolic"``
      (check, then set the outcome) or ``"physical"`` (planned and executed with physics), of
      ``primitive_set`` ``"paper"`` (the paper's six: navigate_to, grasp, place_ontop,
      place_inside, open, close; K = 6), ``"two_hands"`` (the 2.0.x releases' nine) or ``"all"``.
      The reward is then ΔQ over the whole primitive, and ``info`` also says ``primitive``,
      ``object``, ``hand``, ``ok``, ``reason`` and has the ``action_mask`` of feasible actions
      (``action_masks()`` too, for sb3-contrib's MaskablePPO).

    Observations: a ``Dict`` of those asked for, by default ``proprioception`` (22 numbers for
    the BehaviorRobot, 49 for Fetch) and ``task_obs`` (456: the robot's pose and 50 object
    slots), float32. Continuous actions: a ``Box`` in [-1, 1]. Reward: the change of Q, the
    goal's success score. ``terminated``: the
    goal holds; ``truncated``: the step limit. ``info``: ``steps``, ``q``, ``success`` and
    ``conjuncts`` (whether each top-level conjunct of the goal holds).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 30}

    def __init__(
        self,
        activity: str = "bringing_in_wood",
        robot: str = "behavior",
        scene: Optional[str] = None,
        seed: int = 0,
        max_steps: Optional[int] = None,
        clutter: bool = True,
        action_space: str = "continuous",
        primitive_mode: str = "symbolic",
        primitive_set: str = "paper",
        observations=STATE_OBSERVATIONS,
        image_size: int = 128,
        render_mode: Optional[str] = None,
        render_size: int = 256,
        image_profile: str = "realistic",
    ):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', not {render_mode!r}")
        if action_space not in ("continuous", "primitives"):
            raise ValueError(
                f"action_space must be 'continuous' or 'primitives', not {action_space!r}"
            )
        self._primitives = action_space == "primitives"
        self._env = _core.Env(
            activity,
            _options(
                robot, scene, seed, max_steps, clutter, observations, image_size,
                render_size=render_size if render_mode == "rgb_array" else None,
                primitives=primitive_set if self._primitives else None,
                primitive_mode=primitive_mode,
                image_profile=image_profile,
            ),
        )
        self._frame = None
        first, _ = self._env.reset(seed)
        first = self._observed(first)
        self.observation_space = spaces.Dict({name: _box(v) for name, v in first.items()})
        if self._primitives:
            self.action_space = spaces.Discrete(self._env.primitive_count)
        else:
            self.action_space = _action_box(self._env.action_bounds)
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
        obs, info = self._env.reset(episode_seed)
        return self._observed(obs), info

    def checkpoint(self):
        """The episode as it is now (an opaque ``behavior._core.Checkpoint``), to come back to
        with ``restore``."""
        return self._env.checkpoint()

    def restore(self, checkpoint):
        """Goes back to ``checkpoint`` (taken from this environment); the episode continues from
        there bit for bit. Returns ``(obs, info)`` as ``reset`` does: restoring a checkpoint taken
        just after ``reset(seed=s)`` is that reset without sampling the instance again."""
        obs, info = self._env.restore(checkpoint)
        return self._observed(obs), info

    def checkpoint_from_recording(self, path, step: int):
        """The episode recorded in ``path`` (a recording of this activity, robot and home: a
        demonstration) as it stood after its step ``step``, as a checkpoint to ``restore``: the
        start states of Table 1's oracle rows. The recording is re-simulated from its last
        saved state before the step, bit for bit at every checkpoint on the way; one of another
        activity, robot, home, action space or physics rate raises ``ValueError`` saying which,
        a step past its end too."""
        if step < 0:
            raise ValueError(f"step must be a non-negative integer, not {step}")
        return self._env.checkpoint_from_recording(os.fspath(path), step)

    @property
    def goal_literals(self) -> int:
        """How many literals the goal's first option has (a smallest option): ΔQ times this
        counts goal literals reached, one each."""
        return self._env.goal_literals

    def record(self, path, checkpoint_every: int = 30):
        """Records the episode from now on to ``path`` (MCAP: ``behavior.replay`` and
        ``behavior replay --verify`` re-simulate it), with a state digest every
        ``checkpoint_every`` steps, until ``stop_recording()``, the next ``reset`` or ``restore``,
        or ``close()``. Primitives are recorded as the steps they took and the world's edits
        the symbolic ones made."""
        if checkpoint_every < 1:
            raise ValueError(f"checkpoint_every must be at least 1, not {checkpoint_every}")
        self._env.record(os.fspath(path), checkpoint_every)

    def stop_recording(self):
        """Finishes the recording under way (nothing if none is)."""
        self._env.stop_recording()

    def close(self):
        self.stop_recording()
        super().close()

    def step(self, action: Any):
        """One action step (1/30 s of simulated time), or one primitive run to its end."""
        if self._primitives:
            obs, *rest = self._env.step_primitive(self._primitive_index(action))
        else:
            values = np.asarray(action, dtype=np.float32)
            if values.shape != self.action_space.shape:
                raise ValueError(
                    f"the action must have shape {self.action_space.shape}, not {values.shape}"
                )
            obs, *rest = self._env.step(values)
        return (self._observed(obs), *rest)

    def render(self):
        """With ``render_mode="rgb_array"``: the home from above after the last reset or step,
        ``(render_size, render_size, 3)`` uint8; else ``None``."""
        return self._frame

    def _observed(self, obs: dict) -> dict:
        """The agent's observation: the render camera's frame kept aside for ``render()``."""
        frame = obs.pop(_RENDER_PREFIX + "rgb", None)
        if frame is not None:
            self._frame = frame
        return obs

    def action_masks(self) -> np.ndarray:
        """Whether each primitive action's preconditions hold now (sb3-contrib's
        MaskablePPO asks for this)."""
        if not self._primitives:
            raise ValueError("action masks are for action_space='primitives'")
        return self._env.action_mask()

    def primitive_actions(self) -> list:
        """What each primitive action does, in action order: ``(primitive, object)`` names,
        e.g. ``("navigate_to", "printer_1")``. The objects are this episode's."""
        if not self._primitives:
            raise ValueError("primitive actions are for action_space='primitives'")
        return list(self._env.primitive_actions())

    def _primitive_index(self, action: Any) -> int:
        value = np.asarray(action)
        if value.shape != () or not np.issubdtype(value.dtype, np.integer):
            raise ValueError(f"a primitive action is one integer, not {action!r}")
        index = int(value)
        if not 0 <= index < self.action_space.n:
            raise ValueError(
                f"primitive action {index} is out of range: the space has {self.action_space.n}"
            )
        return index

    def metrics(self) -> dict:
        """The episode's metrics so far (as ``behavior run --json`` reports them)."""
        import json

        text = self._env.metrics_json()
        return {} if text is None else json.loads(text)
