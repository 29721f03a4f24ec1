#!/usr/bin/env python3
"""Physical solve-all, one line per activity run, and two such tables compared.

    behavior solve-all --mode physical --robot behavior --json > OUT.json
    python3 bench/solve_all_table.py tsv OUT.json > OUT.tsv
    python3 bench/solve_all_table.py compare BEFORE.tsv AFTER.tsv
    python3 bench/solve_all_table.py markdown OUT.json   # the guide's per-activity table

A line: activity, scene, seed, success, final Q, steps, wall seconds, and for an unsolved run
its first failed primitive and why (the task planner goes on after a failure, so the first one
is where the trouble began, not always what stopped it), or why it stopped.
"""
import json
import sys
from collections import Counter

COLUMNS = ["activity", "scene", "seed", "success", "q_final", "steps", "wall_s",
           "first_failed_primitive", "reason"]


def rows(report):
    for run in report["runs"]:
        failed = next((p for p in run["primitives"] if not p["ok"]), None)
        first = f"{failed['name']} {failed['object']}" if failed else ""
        reason = failed["reason"] if failed else run["stopped"]
        if run["success"]:
            reason = run["stopped"]
        yield [run["activity"], run["scene"], str(run["seed"]), str(run["success"]),
               str(round(run["q_final"], 4)), str(run["steps"]), str(round(run["wall_s"], 2)),
               first, reason]


def tsv(path):
    report = json.load(open(path))
    print("# " + " ".join(sys.argv))
    print("\t".join(COLUMNS))
    for row in rows(report):
        print("\t".join(row))


def markdown(path):
    """The guide's per-activity table: one row per activity, its last run (the first solved,
    with --seeds K), and for an unsolved one what the planner gave up on and why."""
    report = json.load(open(path))
    last = {}
    for run in report["runs"]:
        last[run["activity"]] = run
    print("| activity | seed | solved | Q | wall s | what stopped it |")
    print("|---|---|---|---|---|---|")
    for name, run in last.items():
        why = ""
        if not run["success"]:
            given = run["given_up"]
            why = f"{given[0]['literal']}: {given[0]['reason']}" if given else run["stopped"]
            why = why.replace("|", "/")
        mark = "yes" if run["success"] else "no"
        print(f"| {name.removesuffix('_0')} | {run['seed']} | {mark} | {run['q_final']:.2f} | "
              f"{run['wall_s']:.1f} | {why} |")


def read(path):
    out = {}
    for line in open(path):
        if line.startswith("#") or line.startswith("activity\t"):
            continue
        cells = line.rstrip("\n").split("\t")
        out[cells[0]] = dict(zip(COLUMNS, cells)) if len(cells) == len(COLUMNS) else {
            "activity": cells[0], "success": cells[2], "q_final": cells[3],
            "wall_s": cells[5], "first_failed_primitive": cells[6], "reason": cells[7]}
    return out


def compare(before_path, after_path):
    before, after = read(before_path), read(after_path)
    solved = lambda t: {a for a, r in t.items() if r["success"] == "True"}
    b, a = solved(before), solved(after)
    print(f"solved: {len(b)} -> {len(a)} of {len(after)}")
    print("newly solved:", ", ".join(sorted(a - b)) or "none")
    print("no longer solved:", ", ".join(sorted(b - a)) or "none")
    walls = sorted(float(r["wall_s"]) for r in after.values())
    print(f"median wall {walls[len(walls) // 2]:.2f} s, max {walls[-1]:.1f} s, "
          f"total {sum(walls) / 60:.1f} min")
    kinds = Counter()
    for r in after.values():
        if r["success"] != "True":
            primitive = r["first_failed_primitive"].split(" ")[0] or "(none)"
            kinds[primitive] += 1
    print("first failures:", ", ".join(f"{k} {n}" for k, n in kinds.most_common()))


if __name__ == "__main__":
    if sys.argv[1:2] == ["tsv"]:
        tsv(sys.argv[2])
    elif sys.argv[1:2] == ["markdown"]:
        markdown(sys.argv[2])
    elif sys.argv[1:2] == ["compare"]:
        compare(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
