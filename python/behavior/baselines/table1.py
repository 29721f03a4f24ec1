"""A row of the paper's Table 1 on its 12 activities: one training run per activity and seed
(each a ``behavior.baselines.ppo`` or ``.sac`` process, ``--jobs`` at a time; a run whose
``result.json`` exists is kept, so an interrupted table resumes), then

- ``summary.json``: every run's result;
- ``table.md``: per activity the paper's Q (where we have it) beside ours, the mean over seeds
  and each seed's, with the wall time;
- ``curves.png``: per activity the training episodes' final Q against the steps taken, each
  seed's and their mean, the paper's Q dashed.

``--report`` trains nothing: it summarizes the runs already done (while others still run).

``python -m behavior.baselines.table1 --row ap_nophys_fullobs --seeds 0 1 2 --out runs/table1``
"""

import argparse
import csv
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Dict, List

import numpy as np

from .rows import ACTIVITIES, paper_q, row

# Points on each plotted curve.
CURVE_BINS = 40


def run_dir(out: Path, activity: str, seed: int) -> Path:
    return out / activity / str(seed)


def run_process(command: List[str], folder: Path) -> dict:
    """Runs one training process writing its folder, unless its ``result.json`` is there from
    before (so an interrupted table resumes); returns that result. The process's output goes
    to ``log.txt`` in the folder."""
    done = folder / "result.json"
    if not done.exists():
        folder.mkdir(parents=True, exist_ok=True)
        with open(folder / "log.txt", "w") as log:
            finished = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT)
        if finished.returncode != 0:
            raise RuntimeError(f"{' '.join(command)} failed; see {folder / 'log.txt'}")
    return json.loads(done.read_text())


def train_one(args: argparse.Namespace, activity: str, seed: int) -> dict:
    """One run in its own process (kept if done before)."""
    folder = run_dir(args.out, activity, seed)
    command = [
        sys.executable, "-m", f"behavior.baselines.{row(args.row).algorithm}", activity,
        "--row", args.row, "--seed", str(seed), "--timesteps", str(args.timesteps),
        "--robot", args.robot, "--out", str(folder), *args.extra,
    ]
    result = run_process(command, folder)
    print(f"{activity} seed {seed}: Q {result['q']:.3f} ({result['wall_s']:.0f} s)", flush=True)
    return result


def curve(folder: Path, timesteps: int, column: str = "q") -> np.ndarray:
    """The mean of `column` (``q``: the final Q; ``success``: 1 or 0) over the training
    episodes ending in each of `CURVE_BINS` bins of steps (NaN where none ended)."""
    edges = np.linspace(0, timesteps, CURVE_BINS + 1)
    with open(folder / "curve.csv") as f:
        points = [(int(r["timesteps"]), float(r[column])) for r in csv.DictReader(f)]
    t = np.array([p[0] for p in points])
    q = np.array([p[1] for p in points])
    which = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, CURVE_BINS - 1)
    sums = np.bincount(which, weights=q, minlength=CURVE_BINS)
    counts = np.bincount(which, minlength=CURVE_BINS)
    with np.errstate(invalid="ignore", divide="ignore"):
        return sums / counts


def plot(args: argparse.Namespace, seeds: List[int], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 4, figsize=(16, 10), sharex=True, sharey=True)
    x = (np.arange(CURVE_BINS) + 0.5) * args.timesteps / CURVE_BINS
    for ax, activity in zip(axes.flat, ACTIVITIES):
        curves = [curve(run_dir(args.out, activity, s), args.timesteps) for s in seeds
                  if (run_dir(args.out, activity, s) / "result.json").exists()]
        for c in curves:
            ax.plot(x, c, color="tab:blue", alpha=0.3, linewidth=1)
        if curves:
            with np.errstate(invalid="ignore"):
                mean = np.nanmean(curves, axis=0)
            ax.plot(x, mean, color="tab:blue", linewidth=2, label="ours")
        paper = paper_q(args.row, activity)
        if paper is not None:
            ax.axhline(paper, color="tab:red", linestyle="--", label="paper")
        ax.set_title(activity, fontsize=10)
        ax.set_ylim(-0.05, 1.05)
    for ax in axes[-1]:
        ax.set_xlabel("steps")
    for ax in axes[:, 0]:
        ax.set_ylabel("episode's final Q")
    axes.flat[0].legend(loc="lower right")
    fig.suptitle(f"{row(args.row).title}: training episodes' Q, {len(seeds)} seeds")
    fig.tight_layout()
    fig.savefig(path, dpi=80)


def _paper(row_name: str, activity: str) -> str:
    paper = paper_q(row_name, activity)
    return "—" if paper is None else f"{paper:.2f}"


def table(args: argparse.Namespace, results: Dict[str, List[dict]]) -> str:
    lines = [
        "| activity | paper | ours (mean over seeds) | per seed | wall s / run |",
        "|---|---|---|---|---|",
    ]
    means = []
    for activity in ACTIVITIES:
        qs = [r["q"] for r in results[activity]]
        if not qs:
            lines.append(f"| {activity} | {_paper(args.row, activity)} | not run yet | | |")
            continue
        means.append(np.mean(qs))
        lines.append(
            f"| {activity} | {_paper(args.row, activity)} | {np.mean(qs):.2f} | "
            f"{' '.join(f'{q:.2f}' for q in qs)} | "
            f"{np.mean([r['wall_s'] for r in results[activity]]):.0f} |"
        )
    run = [a for a in ACTIVITIES if results[a]]
    papers = [paper_q(args.row, a) for a in run]
    paper_mean = "—" if None in papers or not run else f"{np.mean(papers):.2f}"
    ours = f"{np.mean(means):.2f}" if means else "—"
    label = "**mean**" if len(run) == len(ACTIVITIES) else f"**mean of the {len(run)} run**"
    lines.append(f"| {label} | {paper_mean} | {ours} | | |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--row", default="ap_nophys_fullobs")
    p.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2])
    p.add_argument("--timesteps", type=int, default=100_000)
    p.add_argument("--robot", default="behavior", choices=["behavior", "fetch", "r1"])
    p.add_argument("--jobs", type=int, default=2, help="runs at a time (one core each)")
    p.add_argument("--out", type=Path, default=Path("runs/table1"))
    p.add_argument("--report", action="store_true",
                   help="train nothing; summarize the runs already done")
    p.add_argument("extra", nargs="*", help="more options for each run (after --)")
    args = p.parse_args(argv)
    row(args.row)
    args.out = args.out / args.row
    jobs = [(a, s) for s in args.seeds for a in ACTIVITIES]
    if args.report:
        done = [json.loads((run_dir(args.out, a, s) / "result.json").read_text())
                for a, s in jobs if (run_dir(args.out, a, s) / "result.json").exists()]
    else:
        with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            done = list(pool.map(lambda job: train_one(args, *job), jobs))
    results: Dict[str, List[dict]] = {a: [] for a in ACTIVITIES}
    for r in done:
        results[r["activity"]].append(r)
    (args.out / "summary.json").write_text(json.dumps(done, indent=2) + "\n")
    markdown = table(args, results)
    (args.out / "table.md").write_text(markdown)
    plot(args, args.seeds, args.out / "curves.png")
    print(markdown)
    print(f"written: {args.out / 'summary.json'}, table.md, curves.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
