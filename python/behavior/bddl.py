"""The BDDL tools, as ``behavior bddl`` offers them on the command line: check definition files,
evaluate an activity's goal on a state, list its options. A definition is an official
activity's name (``"storing_food"``) or a file's path.

    >>> from behavior import bddl
    >>> bddl.check("storing_food").ok
    True
    >>> result = bddl.evaluate("storing_food", [])
    >>> result["success"], result["q"]
    (False, 0.0)
"""

import json
import os
from dataclasses import dataclass
from typing import Iterable, List, Optional, Sequence, Tuple

from . import _core


@dataclass(frozen=True)
class CheckReport:
    """What checking a definition found."""

    errors: int
    warnings: int
    # The diagnostics, each with where it is (file, line, column) and an excerpt.
    text: str

    @property
    def ok(self) -> bool:
        return self.errors == 0


def check(definition: "str | os.PathLike") -> CheckReport:
    """Checks a problem or domain file (or an official activity) against the official taxonomy
    and domain."""
    return CheckReport(*_core.bddl_check(os.fspath(definition)))


def evaluate(definition: "str | os.PathLike", facts: Iterable[Sequence[str]]) -> dict:
    """The goal of `definition` on a state given by the facts that hold, each a predicate and
    its objects (``("ontop", "apple.n.01_1", "table.n.02_1")``, ``("cooked", "apple.n.01_1")``):
    ``success``, ``q`` (the success score), ``q_exact`` (as a fraction), ``volume`` (the
    activity's volume: the fewest literals of an option) and ``conjuncts`` (each top-level conjunct and whether it holds)."""
    state = json.dumps({"facts": [list(f) for f in facts]})
    return json.loads(_core.bddl_evaluate(os.fspath(definition), state))


def options(definition: "str | os.PathLike", limit: int = 20
            ) -> Tuple[Optional[int], List[List[str]]]:
    """The goal's volume (the fewest literals of an option; ``None`` if it can never hold) and
    its first `limit` options (the ways it can hold, smallest first), each a list of
    literals."""
    if limit < 0:
        raise ValueError(f"limit must be at least 0, not {limit}")
    return _core.bddl_options(os.fspath(definition), limit)
