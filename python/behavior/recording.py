"""Recordings of episodes (MCAP, as ``behavior run --record`` writes them): made with
``BehaviorEnv.record(path)``, read and re-simulated with ``replay(path)``, exported as a LeRobot
dataset with ``export_lerobot(dataset, recordings)``."""

import json
import os

from . import _core


def replay(path: "str | os.PathLike", verify: bool = True) -> dict:
    """Reads a recording and, with ``verify``, re-simulates it, comparing the state at every
    checkpoint bit for bit: ``activity``, ``scene``, ``seed``, ``robot``, ``action_space``,
    ``frames`` (steps), ``checkpoints``, ``q`` (after each step), ``q_final``, ``identical`` and
    ``first_difference`` (``None`` without ``verify``) and ``damage`` (where reading stopped in a
    cut or damaged file, whose steps before it are still read). A file that is not a recording
    raises ``ValueError``; one that cannot be read, ``OSError``."""
    return json.loads(_core.replay(os.fspath(path), verify))


def export_lerobot(
    dataset: "str | os.PathLike",
    recordings: "list[str | os.PathLike]",
    image_size: "int | None" = 128,
    format: str = "lerobot-v3",
) -> dict:
    """Writes ``recordings`` (one episode each, all of one robot) as a LeRobot dataset in the
    new folder ``dataset``, in ``format``: ``"lerobot-v3"`` (LeRobot 0.4's layout, many
    episodes to a file) or ``"lerobot-v2.1"`` (an episode to a file), as ``behavior demos export
    --lerobot`` does: each
    recording is re-simulated, so the dataset holds what the agent observed at every step
    (proprioception, ``task_obs`` and, unless ``image_size`` is ``None``, the robot's camera
    re-rendered at ``image_size`` pixels, 16–1024). A recording that does not re-simulate bit
    for bit, or is cut, is refused, and nothing is left under ``dataset``.

    Returns ``dataset``, ``format``, ``episodes``, ``frames``, ``teleoperated``, ``planned``
    (episodes whose recordings say the planner acted), ``images`` and ``recordings`` (each file
    with its frames). Raises ``FileExistsError`` when ``dataset`` is
    there and not empty, ``ValueError`` for a recording that cannot be exported, ``OSError`` for
    files that cannot be read or written."""
    paths = [os.fspath(r) for r in recordings]
    return json.loads(_core.export_lerobot(os.fspath(dataset), paths, image_size, format))
