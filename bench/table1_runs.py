#!/usr/bin/env python3
"""Table 1's physical runs, one line each, to compare two builds run for run.

    bench/table1_runs.py run BINARY ROBOT OUT.tsv [--seeds 6] [--jobs N]
    bench/table1_runs.py compare A.tsv B.tsv

`run` solves the paper's 12 Table 1 activities in physical mode for seeds 0..seeds-1
(`BINARY solve A --mode physical --robot ROBOT --seed N --json`), `jobs` at a time, and writes
per run: activity, seed, success, final Q, steps, and a hash of every primitive's (name,
object, hand, ok, reason, steps) -- everything but wall time. `compare` says which runs differ
and sums both sides. Issue 41's refactors were checked this way: identical files mean the same
primitives did the same things for the same number of steps in every run.
"""

import argparse
import concurrent.futures
import hashlib
import importlib.util
import json
import pathlib
import subprocess
import sys

def table1():
    """Table 1's 12 activities in the paper's order, as the Python baselines name them
    (`python/behavior/baselines/rows.py`, plain Python: loaded by path, no package needed)."""
    path = pathlib.Path(__file__).resolve().parent.parent / "python/behavior/baselines/rows.py"
    spec = importlib.util.spec_from_file_location("table1_rows", path)
    rows = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = rows
    spec.loader.exec_module(rows)
    return rows.ACTIVITIES


def one(binary, robot, activity, seed):
    cmd = [binary, "solve", activity, "--mode", "physical", "--robot", robot,
           "--seed", str(seed), "--json"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=1200)
    try:
        out = json.loads(done.stdout)
    except json.JSONDecodeError:
        return [activity, str(seed), "ERR", done.stderr.strip().splitlines()[-1:] or ""]
    prims = [(p["name"], p["object"], p["hand"], p["ok"], p["reason"], p["steps"])
             for p in out["primitives"]]
    digest = hashlib.sha1(repr(prims).encode()).hexdigest()[:12]
    return [activity, str(seed), str(out["success"]), repr(out["q_final"]),
            str(out["steps"]), digest]


def run(args):
    jobs = [(a, s) for a in table1() for s in range(args.seeds)]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(lambda j: one(args.binary, args.robot, *j), jobs))
    with open(args.out, "w") as f:
        for row in rows:
            f.write("\t".join(map(str, row)) + "\n")
    summary(args.out)


def rows_of(path):
    """The runs of a file, without any columns after the six compared (a wall time)."""
    with open(path) as f:
        return [line.rstrip("\n").split("\t")[:6] for line in f if line.strip()]


def summary(path):
    rows = rows_of(path)
    solved = sum(r[2] == "True" for r in rows)
    q = sum(float(r[3]) for r in rows if r[2] != "ERR")
    print(f"{path}: {len(rows)} runs, {solved} solved, sum of Q {q:.2f}")


def compare(args):
    a, b = rows_of(args.a), rows_of(args.b)
    differ = [(x, y) for x, y in zip(a, b) if x != y]
    for x, y in differ:
        print("differs:", " ".join(x), "|", " ".join(y))
    summary(args.a)
    summary(args.b)
    same = len(a) == len(b) and not differ
    print("identical run for run" if same else f"{len(differ)} runs differ")
    return 0 if same else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("binary")
    r.add_argument("robot")
    r.add_argument("out")
    r.add_argument("--seeds", type=int, default=6)
    r.add_argument("--jobs", type=int, default=1)
    c = sub.add_parser("compare")
    c.add_argument("a")
    c.add_argument("b")
    args = parser.parse_args()
    if args.command == "run":
        run(args)
        return 0
    return compare(args)


if __name__ == "__main__":
    sys.exit(main())
