"""Table 1's oracle rows (SR^ca @ T − 1, 2, 3 and 10 s) over several activities: one
``behavior.baselines.oracle`` run per activity, offset and seed, each in its own process, then

- ``summary.json``: every run's result (settings, start states, success rate, wall times) and
  the zero action's success rate from the same start states;
- ``table.md``: per activity and offset the success rate over the seeds (mean, then each
  seed's), the zero action's in brackets (what the start state reaches by itself), beside the
  paper's where we have it;
- ``curves.png``: per activity the training episodes' success against the steps taken, one line
  per offset (the mean over seeds).

A run whose ``result.json`` exists is kept, so an interrupted table resumes. Runs go ``--jobs``
at a time on this machine, or with ``--ray ADDRESS`` (``local`` for a Ray instance started
here) as Ray tasks, one CPU each, on every machine of the cluster: each needs the package
installed and the demonstrations and output folders at the same paths (a shared filesystem).
``--report`` trains nothing and summarizes the runs already done.

``python -m behavior.baselines.oracle_table --demos DIR --activities A B C D --out runs/oracle``
"""

import argparse
import json
import sys
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np

from .oracle import OFFSETS_S, OracleConfig, label, make_env, starts_for
from .table1 import CURVE_BINS, curve, run_process

# The paper's success rates for these rows, by activity and offset, where we have them: its
# Table 1's oracle rows are not in this project's reference material, so none yet.
PAPER_SR: Dict[Tuple[str, float], float] = {}

Run = Tuple[str, float, int]


def run_dir(out: Path, activity: str, before_s: float, seed: int) -> Path:
    return out / label(activity) / f"T-{before_s:g}s" / str(seed)


def command(args: argparse.Namespace, run: Run) -> List[str]:
    activity, before_s, seed = run
    return [
        sys.executable, "-m", "behavior.baselines.oracle", activity,
        "--demos", str(args.demos), "--before", f"{before_s:g}", "--seed", str(seed),
        "--timesteps", str(args.timesteps), "--robot", args.robot,
        "--evaluation-episodes", str(args.evaluation_episodes),
        "--out", str(run_dir(args.out, *run)), *args.extra,
    ]


def run_all(args: argparse.Namespace, runs: List[Run]) -> List[dict]:
    """Every run, resumed where done, on this machine or on Ray."""
    jobs = [(command(args, r), run_dir(args.out, *r)) for r in runs]
    if args.ray is not None:
        import ray

        if not ray.is_initialized():
            ray.init(address=None if args.ray == "local" else args.ray,
                     include_dashboard=False, log_to_driver=False)
        remote = ray.remote(num_cpus=1)(run_process)
        results = ray.get([remote.remote(c, f) for c, f in jobs])
    else:
        with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            results = list(pool.map(lambda job: run_process(*job), jobs))
    for (activity, before_s, seed), r in zip(runs, results):
        print(f"{activity} T-{before_s:g}s seed {seed}: SR {r['success_rate']:.2f} "
              f"({r['wall_s']:.0f} s training)", flush=True)
    return results


def zero_action_success(args: argparse.Namespace, activity: str, before_s: float) -> float:
    """The success rate of doing nothing (the zero action every step) from the run's start
    states: what the start state reaches by itself, e.g. an object let go just before the
    demonstration's success falling into place. The environment is deterministic: one
    episode per start state tells."""
    config = OracleConfig(activity, before_s, args.demos, robot=args.robot)
    starts = starts_for(config)
    env = make_env(config, starts)
    successes = []
    for _ in starts:
        env.reset()
        done, info = False, {}
        while not done:
            _, _, terminated, truncated, info = env.step(np.zeros(env.action_space.shape,
                                                                  np.float32))
            done = terminated or truncated
        successes.append(bool(info["success"]))
    env.close()
    return float(np.mean(successes))


def _cell(results: List[dict]) -> str:
    if not results:
        return "not run"
    rates = [r["success_rate"] for r in results]
    return f"{np.mean(rates):.2f} ({' '.join(f'{x:.2f}' for x in rates)})"


def _paper(activity: str, before_s: float) -> Optional[str]:
    paper = PAPER_SR.get((activity, before_s))
    return None if paper is None else f"{paper:.2f}"


def table(args: argparse.Namespace, results: List[dict],
          still: Dict[Tuple[str, float], float]) -> str:
    """Success rates per activity (rows) and offset (columns), SAC's over the seeds then, in
    brackets, the zero action's."""
    offsets = args.offsets
    header = "| activity | " + " | ".join(f"SR @ T−{k:g} s" for k in offsets)
    lines = [header + " | wall s / run |", "|---" * (len(offsets) + 2) + "|"]
    for activity in args.activities:
        mine = [r for r in results if r["activity"] == activity]
        name = label(activity)
        cells = []
        for k in offsets:
            cell = _cell([r for r in mine if r["before_s"] == k])
            if (activity, k) in still:
                cell += f" [{still[(activity, k)]:.2f}]"
            paper = _paper(name, k)
            cells.append(cell if paper is None else f"{cell}; paper {paper}")
        walls = [r["wall_s"] + r["evaluation_wall_s"] for r in mine]
        wall = f"{np.mean(walls):.0f}" if walls else ""
        lines.append(f"| {name} | " + " | ".join(cells) + f" | {wall} |")
    means = []
    for k in offsets:
        rates = [r["success_rate"] for r in results if r["before_s"] == k]
        means.append(f"{np.mean(rates):.2f}" if rates else "—")
    lines.append("| **mean** | " + " | ".join(means) + " | |")
    return "\n".join(lines) + "\n"


def plot(args: argparse.Namespace, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = len(args.activities)
    cols = min(4, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3.3 * rows), sharey=True,
                             squeeze=False)
    x = (np.arange(CURVE_BINS) + 0.5) * args.timesteps / CURVE_BINS
    for ax, activity in zip(axes.flat, args.activities):
        for k in args.offsets:
            folders = [run_dir(args.out, activity, k, s) for s in args.seeds]
            curves = [curve(f, args.timesteps, "success") for f in folders
                      if (f / "result.json").exists()]
            if curves:
                with warnings.catch_warnings():
                    # Bins where no training episode ended are NaN, and left out of the line.
                    warnings.simplefilter("ignore", RuntimeWarning)
                    ax.plot(x, np.nanmean(curves, axis=0), label=f"T−{k:g} s")
        ax.set_title(label(activity), fontsize=10)
        ax.set_ylim(-0.05, 1.05)
        ax.set_xlabel("steps")
    for ax in axes[:, 0]:
        ax.set_ylabel("training episodes' success")
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    axes.flat[0].legend(loc="upper right", fontsize=8)
    fig.suptitle(f"SR^ca @ T − k s: SAC from demonstrations' states, {len(args.seeds)} seeds")
    fig.tight_layout()
    fig.savefig(path, dpi=80)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--demos", type=Path, required=True,
                   help="a folder made by `behavior demos generate`")
    p.add_argument("--activities", nargs="+", required=True)
    p.add_argument("--offsets", type=float, nargs="+", default=list(OFFSETS_S),
                   help="seconds before success (default: the paper's 1 2 3 10)")
    p.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2])
    p.add_argument("--timesteps", type=int, default=5_000)
    p.add_argument("--evaluation-episodes", type=int, default=100)
    p.add_argument("--robot", default="behavior", choices=["behavior", "fetch", "r1"])
    p.add_argument("--jobs", type=int, default=2, help="runs at a time here (one core each)")
    p.add_argument("--ray", default=None, metavar="ADDRESS",
                   help="run on Ray instead: `local`, `auto` or a cluster's address")
    p.add_argument("--out", type=Path, default=Path("runs/oracle"))
    p.add_argument("--report", action="store_true",
                   help="train nothing; summarize the runs already done")
    p.add_argument("extra", nargs="*", help="more options for each run (after --)")
    args = p.parse_args(argv)
    runs = [(a, k, s) for s in args.seeds for k in args.offsets for a in args.activities]
    if args.report:
        results = [json.loads((run_dir(args.out, *r) / "result.json").read_text())
                   for r in runs if (run_dir(args.out, *r) / "result.json").exists()]
    else:
        results = run_all(args, runs)
    still = {(a, k): zero_action_success(args, a, k) for a in args.activities
             for k in args.offsets if any(r["activity"] == a and r["before_s"] == k
                                          for r in results)}
    for r in results:
        r["zero_action_success_rate"] = still[(r["activity"], r["before_s"])]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "summary.json").write_text(json.dumps(results, indent=2) + "\n")
    markdown = table(args, results, still)
    (args.out / "table.md").write_text(markdown)
    plot(args, args.out / "curves.png")
    print(markdown)
    print(f"written: {args.out / 'summary.json'}, table.md, curves.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
