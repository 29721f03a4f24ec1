"""Recordings of episodes (MCAP, as ``behavior run --record`` writes them): made with
``BehaviorEnv.record(path)``, read and re-simulated with ``replay(path)``."""

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
