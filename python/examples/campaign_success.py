#!/usr/bin/env python3
"""Runs a small landing campaign from Python and plots each cell's success rate with its 95 % interval.

    PYTHONPATH=python python3 python/examples/campaign_success.py --seeds 3 -j 2 --out campaign_success.png

The campaign (default scenarios/landing_ci.ini: 2 feet x 3 terrains x 2 robots) runs in footsim's
pool of worker processes through footsim.Campaign, as `footsim campaign` runs it: the same files
(summary.json, trials.csv, ...) in --dir (default results/campaigns/<name>), resumable after
Ctrl-C. The chart is drawn here with matplotlib (python3-matplotlib); without it the campaign still
runs and the script says that it drew nothing."""
import argparse
import sys
import time

import footsim


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("campaign", nargs="?", default="landing_ci.ini")
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("--dir", default=None, help="the campaign's results folder")
    ap.add_argument("--out", default="campaign_success.png")
    a = ap.parse_args(argv)

    c = footsim.Campaign(a.campaign, set=a.set + [f"campaign.seeds={a.seeds}"])
    print(f"campaign {c.name}: {c.ncells} cells x {a.seeds} seeds = {c.ntrials} trials in {a.jobs} workers")
    t0 = time.monotonic()

    def progress(p):
        if p.say:
            print(p.say)
        return True

    res = c.run(a.dir, jobs=a.jobs, progress=progress)
    print(f"{res.status} in {time.monotonic() - t0:.1f} s: {res.dir}")
    for r in res.rows:
        print(f"  {r['foot']:10s} {r['terrain']:14s} {r['robot']:12s} landed {r['landed']} of {r['trials']} "
              f"({r['success_rate']:.2f}, 95 % CI [{r['ci_low']:.2f}, {r['ci_high']:.2f}]); law: {r['law_prediction']}")

    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed (apt-get install python3-matplotlib): no chart drawn")
        return 0
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = res.rows
    labels = [f"{r['terrain']}\n{r['robot']}" for r in rows if r["foot"] == rows[0]["foot"]]
    feet = list(dict.fromkeys(r["foot"] for r in rows))
    width = 0.8 / len(feet)
    fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(labels)), 4))
    for k, foot in enumerate(feet):
        mine = [r for r in rows if r["foot"] == foot]
        x = [i + (k - (len(feet) - 1) / 2) * width for i in range(len(mine))]
        rate = [r["success_rate"] for r in mine]
        err = [[r["success_rate"] - r["ci_low"] for r in mine], [r["ci_high"] - r["success_rate"] for r in mine]]
        ax.bar(x, rate, width, yerr=err, capsize=3, label=foot)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("success rate (landed), 95 % CI")
    ax.set_title(f"{c.name}: {a.seeds} seeds per cell")
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print(f"wrote {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
