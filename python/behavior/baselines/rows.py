"""The rows of the paper's Table 1 as configurations, its 12 activities, and the paper's figures
for the row we reproduce.

Each row is an action space (``ca``: the robot's continuous actions; ``ap``: action primitives),
how primitives run (``NoPhys``: symbolic, checked then set; otherwise planned and executed with
physics) and what the agent sees (``FullObs``: the robot's state and every task object's pose
and states, ``proprioception`` + ``task_obs``; otherwise the robot camera's RGB-D and
proprioception). The continuous rows train SAC, the primitive rows PPO.
"""

from dataclasses import dataclass
from typing import Dict, Optional, Tuple

# The observations of the rows without full observability: the robot camera's RGB-D and the
# robot's own state.
IMAGES = ("rgb", "depth", "proprioception")
# Full observability: the robot's state and every task object's.
FULL = ("proprioception", "task_obs")

# Episode lengths: twice the longest plan our task planner finds for Table 1's activities
# (25 primitives) for primitives; 1,000 steps (33 s) for continuous control.
PRIMITIVE_HORIZON = 50
CONTINUOUS_HORIZON = 1000


@dataclass(frozen=True)
class Row:
    """One row of Table 1."""

    # The paper's name for it.
    title: str
    # "continuous" or "primitives".
    action_space: str
    # For primitives: "symbolic" or "physical".
    primitive_mode: str
    observations: Tuple[str, ...]
    # "ppo" or "sac".
    algorithm: str

    def env(self, activity: str, *, robot: str, seed: int, image_size: int,
            scene: Optional[str] = None):
        """A ``BehaviorEnv`` of `activity` set up as this row: its action space, how primitives
        run and what the agent sees."""
        from ..env import BehaviorEnv

        return BehaviorEnv(activity, robot=robot, scene=scene, seed=seed,
                           action_space=self.action_space, primitive_mode=self.primitive_mode,
                           observations=self.observations, image_size=image_size)


ROWS: Dict[str, Row] = {
    "ca": Row("Q^ca", "continuous", "physical", IMAGES, "sac"),
    "ap": Row("Q^ap", "primitives", "physical", IMAGES, "ppo"),
    "ca_fullobs": Row("Q^ca_FullObs", "continuous", "physical", FULL, "sac"),
    "ap_fullobs": Row("Q^ap_FullObs", "primitives", "physical", FULL, "ppo"),
    "ap_nophys": Row("Q^ap_NoPhys", "primitives", "symbolic", IMAGES, "ppo"),
    "ap_nophys_fullobs": Row("Q^ap_NoPhys,FullObs", "primitives", "symbolic", FULL, "ppo"),
}

# Table 1's 12 activities, in the paper's order.
ACTIVITIES = (
    "bringing_in_wood",
    "collect_misplaced_items",
    "moving_boxes_to_storage",
    "organizing_file_cabinet",
    "throwing_away_leftovers",
    "putting_dishes_away_after_cleaning",
    "putting_leftovers_away",
    "re-shelving_library_books",
    "laying_tile_floors",
    "setting_up_candles",
    "picking_up_trash",
    "storing_food",
)

# The paper's Q for the row Q^ap_NoPhys,FullObs.
PAPER_AP_NOPHYS_FULLOBS: Dict[str, float] = {
    "bringing_in_wood": 1.0,
    "collect_misplaced_items": 0.95,
    "moving_boxes_to_storage": 0.83,
    "organizing_file_cabinet": 0.0,
    "throwing_away_leftovers": 0.56,
    "putting_dishes_away_after_cleaning": 0.94,
    "putting_leftovers_away": 0.55,
    "re-shelving_library_books": 0.56,
    "laying_tile_floors": 0.0,
    "setting_up_candles": 0.5,
    "picking_up_trash": 0.67,
    "storing_food": 1.0,
}


def paper_q(row: str, activity: str) -> Optional[float]:
    """The paper's Q for a row and activity, where we have it."""
    if row == "ap_nophys_fullobs":
        return PAPER_AP_NOPHYS_FULLOBS.get(activity)
    return None


def row(name: str) -> Row:
    """The row of this name (``ROWS``' keys), or a ``ValueError`` listing them."""
    try:
        return ROWS[name]
    except KeyError:
        raise ValueError(f"row must be one of {', '.join(ROWS)}, not {name!r}") from None
