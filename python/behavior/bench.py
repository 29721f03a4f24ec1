"""``python -m behavior.bench``: what stepping from Python costs beyond the Rust step, and
what a vector environment gains.

For the Rust environment alone and for the Gymnasium class, it takes N steps of random actions
and reports the wall time per step from Python, the time per step inside Rust's ``Env::step``
(measured by the native module around exactly that call), and their difference: the binding's
own cost (argument conversion, releasing and retaking the interpreter's lock, building the
observation dict) and, for Gymnasium, the wrapper's. Then environment steps per second of one
``BehaviorEnv`` taking the episodes of a ``BehaviorVecEnv`` of ``--vector`` environments in
turn, and of that vector environment taking them together, and their ratio; last, steps per
second of one ``BehaviorEnv`` that also observes the robot camera's RGB, depth and semantic
segmentation at 128² (the original's onboard sensing).
"""

import argparse
import json
import time

import numpy as np

from . import _core
from .env import STATE_OBSERVATIONS, BehaviorEnv, _options
from .vector import BehaviorVecEnv


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
    parser.add_argument("--vector", type=int, default=2, help="environments in the vector one")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    rows = {}
    raw = _core.Env(args.activity, _options(args.robot, None, 0, 10**6, True,
                                            STATE_OBSERVATIONS, 128))
    actions = np.random.default_rng(0).uniform(
        -1, 1, size=(args.steps, raw.action_dim)).astype(np.float32)
    raw.reset(0)
    rows["core.Env"] = _measure(raw.step, raw, actions)
    env = BehaviorEnv(args.activity, robot=args.robot, max_steps=10**6)
    env.reset(seed=0)
    rows["BehaviorEnv"] = _measure(env.step, env._env, actions)
    rates = _rates(args, env, actions)
    rates["with_images"] = _with_images(args, actions)
    if args.json:
        print(json.dumps({"per_step": rows, "steps_per_s": rates}))
        return
    print(f"{args.activity}, {args.robot}, {args.steps} steps of random actions")
    for name, r in rows.items():
        print(f"  {name:12s} {r['wall_us']:9.1f} µs/step from Python, {r['rust_us']:9.1f} in Rust, "
              f"overhead {r['overhead_us']:6.1f} µs")
    print(f"  one BehaviorEnv: {rates['single']:.0f} steps/s; BehaviorVecEnv of {args.vector}: "
          f"{rates['vector']:.0f} environment steps/s, {rates['ratio']:.2f}x")
    print(f"  BehaviorEnv with the robot camera's rgb, depth and seg at 128²: "
          f"{rates['with_images']:.0f} steps/s")


def _with_images(args, actions):
    """Steps per second of a ``BehaviorEnv`` observing the original's onboard images too (a
    tenth of the steps: each is drawn)."""
    env = BehaviorEnv(args.activity, robot=args.robot, max_steps=10**6,
                      observations=STATE_OBSERVATIONS + ("rgb", "depth", "seg"))
    env.reset(seed=1)
    steps = actions[: max(1, len(actions) // 10)]
    start = time.perf_counter()
    for a in steps:
        env.step(a)
    return len(steps) / (time.perf_counter() - start)


def _rates(args, env, actions):
    """Environment steps per second: one environment stepping the vector's episodes one after
    the other (seeds 1 … N, each with its share of the actions), against the vector stepping
    them together."""
    n = args.vector
    batches = np.stack([actions[k::n][: len(actions) // n] for k in range(n)], axis=1)
    elapsed = 0.0
    for k in range(n):
        env.reset(seed=1 + k)
        start = time.perf_counter()
        for a in batches[:, k]:
            env.step(a)
        elapsed += time.perf_counter() - start
    single = batches.shape[0] * n / elapsed
    envs = BehaviorVecEnv(args.activity, num_envs=n, robot=args.robot, max_steps=10**6)
    envs.reset(seed=1)
    start = time.perf_counter()
    for batch in batches:
        envs.step(batch)
    vector = batches.shape[0] * n / (time.perf_counter() - start)
    return {"single": single, "vector": vector, "ratio": vector / single}

if __name__ == "__main__":
    main()
