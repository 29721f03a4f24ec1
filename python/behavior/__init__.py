"""BEHAVIOR in Rust, for Python.

Importing the package registers one Gymnasium environment per official activity,
``behavior/<activity>-v0`` (the official data is fetched from PyPI on first use, then cached)::

    import gymnasium as gym
    import behavior  # noqa: F401  (registers the environments)

    env = gym.make("behavior/bringing_in_wood-v0", robot="fetch")
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

``behavior.BehaviorEnv`` is the environment class; ``behavior.make_vec(activity, num_envs)``
(or ``gymnasium.make_vec(id, num_envs, vectorization_mode="vector_entry_point")``) steps several
in Rust threads; ``behavior.activities()`` lists the activities and
``behavior.covering_homes(activity)`` the homes that hold what one needs; ``behavior.bddl``
checks definitions, evaluates goals on states and lists their options;
``env.unwrapped.record(path)`` records an episode, ``behavior.replay(path)`` re-simulates it and
``behavior.export_lerobot(dataset, recordings)`` writes recordings as a LeRobot dataset;
``behavior.evaluate`` runs the benchmark's evaluation protocol; ``behavior.baselines`` (the ``baselines`` extra) trains
the paper's RL baselines; ``behavior.ray`` (the ``ray`` extra) runs on a Ray cluster.
"""

from gymnasium.envs.registration import register, registry

from . import bddl
from ._core import activities, covering_homes
from .env import BehaviorEnv
from .recording import export_lerobot, replay
from .vector import BehaviorVecEnv, make_vec

__all__ = ["BehaviorEnv", "BehaviorVecEnv", "activities", "bddl", "covering_homes",
           "export_lerobot", "make_vec", "register_envs", "replay"]


def register_envs():
    """Registers ``behavior/<activity>-v0`` for every official activity (done on import)."""
    for name in activities():
        env_id = f"behavior/{name}-v0"
        if env_id not in registry:
            register(
                id=env_id,
                entry_point="behavior.env:BehaviorEnv",
                vector_entry_point="behavior.vector:BehaviorVecEnv",
                kwargs={"activity": name},
            )


register_envs()
