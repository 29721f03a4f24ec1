#!/usr/bin/env python3
"""Join our goal-evaluation benchmark with the reference one and summarise.

Usage: join.py OURS.json REFERENCE.json

Both files hold the array printed by `behavior bddl bench --json` /
`bddl_reference_bench.py`: [{"activity", "goal_eval_ns", "q_ns", "success",
"q", ...}, ...]. Rows carrying "error" (or lacking timings) are reported and
left out of the statistics. Ratios are reference / ours, i.e. how many times
faster our implementation is. Standard library only.
"""

import json
import statistics
import sys

Q_TOLERANCE = 1e-9


def load(path):
    with open(path) as f:
        rows = json.load(f)
    return {row["activity"]: row for row in rows}


def usable(row):
    return row is not None and "error" not in row and "goal_eval_ns" in row and "q_ns" in row


def ratio(ref_ns, ours_ns):
    return ref_ns / ours_ns if ours_ns > 0 else float("inf")


def summarise(label, ours, ref, ratios):
    if not ratios:
        print(f"{label}: no activity measured on both sides")
        return
    print(
        f"{label}: median ours {statistics.median(ours):,.0f} ns, "
        f"median reference {statistics.median(ref):,.0f} ns, "
        f"median ratio {statistics.median(ratios):,.1f}x, min ratio {min(ratios):,.1f}x"
    )


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    ours, ref = load(argv[1]), load(argv[2])
    activities = sorted(set(ours) | set(ref))

    header = ("activity", "ours goal ns", "ref goal ns", "ratio", "ours Q ns", "ref Q ns", "ratio")
    width = max([len(header[0])] + [len(a) for a in activities])
    line = f"{{:<{width}}} {{:>13}} {{:>13}} {{:>8}} {{:>13}} {{:>13}} {{:>8}}"
    print(line.format(*header))

    goal = {"ours": [], "ref": [], "ratio": []}
    q = {"ours": [], "ref": [], "ratio": []}
    problems, success_compared, success_diffs, q_diffs = [], 0, [], []
    for act in activities:
        o, r = ours.get(act), ref.get(act)
        if not (usable(o) and usable(r)):
            for side, row in (("ours", o), ("reference", r)):
                if row is None:
                    problems.append(f"{act}: missing from {side}")
                elif not usable(row):
                    problems.append(f"{act}: {side} error: {row.get('error', 'no timings')}")
            continue
        g_ratio = ratio(r["goal_eval_ns"], o["goal_eval_ns"])
        q_ratio = ratio(r["q_ns"], o["q_ns"])
        for bucket, key, rat in ((goal, "goal_eval_ns", g_ratio), (q, "q_ns", q_ratio)):
            bucket["ours"].append(o[key])
            bucket["ref"].append(r[key])
            bucket["ratio"].append(rat)
        print(line.format(
            act,
            f"{o['goal_eval_ns']:,.0f}", f"{r['goal_eval_ns']:,.0f}", f"{g_ratio:,.1f}x",
            f"{o['q_ns']:,.0f}", f"{r['q_ns']:,.0f}", f"{q_ratio:,.1f}x",
        ))
        if "success" in o and "success" in r:
            success_compared += 1
            if bool(o["success"]) != bool(r["success"]):
                success_diffs.append((act, o["success"], r["success"]))
        if "q" in o and "q" in r and abs(o["q"] - r["q"]) > Q_TOLERANCE:
            q_diffs.append((act, o["q"], r["q"]))

    print()
    print(f"activities compared: {len(goal['ratio'])} of {len(activities)}")
    summarise("goal evaluation", goal["ours"], goal["ref"], goal["ratio"])
    summarise("Q (ground options)", q["ours"], q["ref"], q["ratio"])
    print(f"success agrees: {success_compared - len(success_diffs)} of {success_compared}")
    for act, ours_s, ref_s in success_diffs:
        print(f"  {act}: ours {ours_s}, reference {ref_s}")
    print(f"Q differs by > {Q_TOLERANCE:g}: {len(q_diffs)}")
    for act, oq, rq in q_diffs:
        # Expected for a few activities: the reference truncates option enumeration.
        print(f"  {act}: ours {oq:.6f}, reference {rq:.6f}")
    if problems:
        print(f"not compared: {len(problems)}")
        for p in problems:
            print(f"  {p}")


if __name__ == "__main__":
    main(sys.argv)
