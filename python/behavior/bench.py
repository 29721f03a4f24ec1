"""``python -m behavior.bench``: what stepping from Python costs beyond the Rust step.

For the Rust environment alone and for the Gymnasium class, it takes N steps of random actions
and reports the wall time per step from Python, the time per step inside Rust's ``Env::step``
(measured by the native module around exactly that call), and their difference: the binding's
own cost (argument conversion, releasing and retaking the interpreter's lock, building the
observation dict) and, for Gymnasium, the wrapper's.
"""

import argparse
import json
import time

import numpy as np

from . import _core
from .env import BehaviorEnv


def _measure(step, raw, actions):
    before_s, before_n = raw.rust_step_time
    start = time.perf_counter()
    for a in actions:
        step(a)
    wall = time.perf_counter() - start
    inside_s, inside_n = raw.rust_step_time
    n = inside_n - before_n
    rust = (inside_s - before_s) / n
    return {"steps": n, "wall_us": 1e6 * wall / n, "rust_us": 1e6 * rust,
            "overhead_us": 1e6 * (wall / n - rust)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--activity", default="bringing_in_wood")
    parser.add_argument("--robot", default="behavior")
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    rows = {}
    raw = _core.Env(args.activity, robot=args.robot, max_steps=10**6)
    actions = np.random.default_rng(0).uniform(
        -1, 1, size=(args.steps, raw.action_dim)).astype(np.float32)
    raw.reset(0)
    rows["core.Env"] = _measure(raw.step, raw, actions)
    env = BehaviorEnv(args.activity, robot=args.robot, max_steps=10**6)
    env.reset(seed=0)
    rows["BehaviorEnv"] = _measure(env.step, env._env, actions)
    if args.json:
        print(json.dumps(rows))
        return
    print(f"{args.activity}, {args.robot}, {args.steps} steps of random actions")
    for name, r in rows.items():
        print(f"  {name:12s} {r['wall_us']:9.1f} µs/step from Python, {r['rust_us']:9.1f} in Rust, "
              f"overhead {r['overhead_us']:6.1f} µs")


if __name__ == "__main__":
    main()
