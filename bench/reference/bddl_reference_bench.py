#!/usr/bin/env python3
"""Time goal evaluation in the reference BDDL implementation (PyPI bddl==1.0.1).

Counterpart of `behavior bddl bench --json`: for every official activity the
goal is compiled against an in-memory state made of the positive, non-`inroom`
literals of `:init`, and two operations are timed:

  goal_eval_ns  one `evaluate_goal_conditions(goal)` call
  q_ns          Q = max over the ground goal options of the fraction of the
                option's literals that currently hold

Output: one JSON array on stdout, sorted by activity:
  [{"activity", "goal_eval_ns", "q_ns", "success", "q", "n_options"}, ...]
(an activity the reference cannot handle gets {"activity", "error"} instead).
Progress goes to stderr.

Usage (in a venv with bddl==1.0.1 and its imports: future numpy networkx ipython):
  python bddl_reference_bench.py [--activities a,b,c] [--quick]
"""

import argparse
import gc
import json
import os
import statistics
import sys
import time

import bddl
from bddl.activity import (
    Conditions,
    evaluate_goal_conditions,
    get_goal_conditions,
    get_ground_goal_state_options,
    get_object_scope,
)
from bddl.backend_abc import BDDLBackend
from bddl.logic_base import BinaryAtomicFormula, UnaryAtomicFormula

BINARY_PREDICATES = ("inside", "nextto", "ontop", "under", "touching", "onfloor")
UNARY_PREDICATES = (
    "cooked", "burnt", "soaked", "open", "dusty", "stained",
    "sliced", "toggled_on", "frozen",
)

FULL_TARGET_NS = 20_000_000  # one repeat should last at least ~20 ms
FULL_REPEATS = 7
QUICK_TARGET_NS = 1_000_000
QUICK_REPEATS = 1


class SimObject:
    """Stand-in for a simulator object.

    It must not be a `str`: the reference atomic formulas treat a `str` scope
    value as a quantifier variable bound to an instance name, and follow it.
    """

    __slots__ = ("name",)

    def __init__(self, name):
        self.name = name

    def __repr__(self):
        return f"SimObject({self.name!r})"


def _make_unary(pred):
    class Unary(UnaryAtomicFormula):
        STATE_NAME = pred

        def _evaluate(self, obj):
            return (pred, obj.name) in self.backend.facts

        def _sample(self, obj, binary_state):
            return False

    Unary.__name__ = Unary.__qualname__ = f"Unary_{pred}"
    return Unary


def _make_binary(pred):
    class Binary(BinaryAtomicFormula):
        STATE_NAME = pred

        def _evaluate(self, obj1, obj2):
            return (pred, obj1.name, obj2.name) in self.backend.facts

        def _sample(self, obj1, obj2, binary_state):
            return False

    Binary.__name__ = Binary.__qualname__ = f"Binary_{pred}"
    return Binary


PREDICATE_CLASSES = {
    **{p: _make_unary(p) for p in UNARY_PREDICATES},
    **{p: _make_binary(p) for p in BINARY_PREDICATES},
}


class SetBackend(BDDLBackend):
    """Backend whose world state is a set of ground facts (tuples)."""

    def __init__(self, facts):
        self.facts = facts

    def get_predicate_class(self, predicate_name):
        # KeyError is what the reference turns into UnsupportedPredicateError.
        return PREDICATE_CLASSES[predicate_name]


def initial_facts(conds):
    """Positive, non-`inroom` literals of `:init` as tuples."""
    return {
        tuple(lit)
        for lit in conds.parsed_initial_conditions
        if lit and lit[0] not in ("not", "inroom")
    }


def ground_q(options):
    return max(sum(lit.evaluate() for lit in opt) / len(opt) for opt in options)


def time_per_call(fn, target_ns, repeats):
    """Median ns per call of `fn` over `repeats` batches of >= target_ns each."""
    # Same policy as timeit: no cyclic GC pauses inside a measurement.
    gc_was_enabled = gc.isenabled()
    gc.disable()
    try:
        n = 1
        while True:  # grow the batch until it is long enough to time reliably
            t0 = time.perf_counter_ns()
            for _ in range(n):
                fn()
            elapsed = time.perf_counter_ns() - t0
            if elapsed >= target_ns:
                break
            # Extrapolate from this batch, but at most 10x per step.
            n = min(10 * n, max(2 * n, int(1.2 * n * target_ns / max(elapsed, 1))))
        samples = []
        for _ in range(repeats):
            t0 = time.perf_counter_ns()
            for _ in range(n):
                fn()
            samples.append((time.perf_counter_ns() - t0) / n)
        return statistics.median(samples)
    finally:
        if gc_was_enabled:
            gc.enable()


def bench_activity(activity, target_ns, repeats):
    conds = Conditions(activity, 0, "igibson")
    backend = SetBackend(initial_facts(conds))
    scope = get_object_scope(conds)
    for name in scope:
        scope[name] = SimObject(name)
    goal = get_goal_conditions(conds, backend, scope)
    options = get_ground_goal_state_options(conds, backend, scope, goal)

    success, _ = evaluate_goal_conditions(goal)
    q = ground_q(options)
    goal_ns = time_per_call(lambda: evaluate_goal_conditions(goal), target_ns, repeats)
    q_ns = time_per_call(lambda: ground_q(options), target_ns, repeats)
    return {
        "activity": activity,
        "goal_eval_ns": goal_ns,
        "q_ns": q_ns,
        "success": bool(success),
        "q": q,
        "n_options": len(options),
    }


def official_activities():
    manifest = os.path.join(os.path.dirname(bddl.__file__), "activity_manifest.txt")
    with open(manifest) as f:
        return sorted(line.strip() for line in f if line.strip())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--activities", help="comma-separated subset of activities")
    ap.add_argument("--quick", action="store_true",
                    help="1 short repeat per measurement (smoke run)")
    args = ap.parse_args()

    activities = (
        sorted(a for a in args.activities.split(",") if a)
        if args.activities else official_activities()
    )
    target_ns, repeats = (
        (QUICK_TARGET_NS, QUICK_REPEATS) if args.quick else (FULL_TARGET_NS, FULL_REPEATS)
    )

    results = []
    started = time.perf_counter()
    for i, activity in enumerate(activities, 1):
        try:
            row = bench_activity(activity, target_ns, repeats)
            note = (f"goal {row['goal_eval_ns']:.0f} ns, Q {row['q_ns']:.0f} ns, "
                    f"{row['n_options']} options")
        except Exception as e:  # keep going; the row records the failure
            row = {"activity": activity, "error": f"{type(e).__name__}: {e}"}
            note = "ERROR " + row["error"]
        results.append(row)
        print(f"[{i}/{len(activities)}] {activity}: {note}", file=sys.stderr, flush=True)
    print(f"done in {time.perf_counter() - started:.1f} s", file=sys.stderr)

    json.dump(results, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
