#!/usr/bin/env python3
"""Runs a handful of landing trials per foot over seeds and plots each foot's success rate.

    PYTHONPATH=python python3 python/examples/seeds_success.py --seeds 8 --out seeds_success.png

Each trial is footsim's own (Scenario.trial): the pose drawn from the seed, the outcome judged by
footsim's rules. The pitch-stiffness law's verdict for each foot under the robot is printed beside
its rate. A campaign (many cells, statistics, resumable runs in a pool of workers) runs from Python
too: campaign_success.py."""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import footsim  # noqa: E402

FEET = {"biomimetic": "feet/biomimetic.ini", "flat": "feet/flat.ini"}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenario", nargs="?", default="landing_trial.ini")
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE")
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--out", default="seeds_success.png")
    a = ap.parse_args(argv)

    rates = {}
    for foot, design in FEET.items():
        sc = footsim.Scenario(a.scenario, set=a.set + [f"scenario.design={design}"])
        results = [sc.trial(seed) for seed in range(1, a.seeds + 1)]
        landed = sum(r.landed for r in results)
        rates[foot] = landed / len(results)
        law = sc.pitch_law()
        rules = sorted({r.rule for r in results})
        print(f"{foot:10s} landed {landed} of {len(results)} ({rates[foot]:.2f}); law: "
              f"{'stands' if law.stands else 'topples'} (K {law.K:.1f} N m/rad against m g h {law.demand:.1f}); "
              f"decided by: {', '.join(rules)}")

    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.bar(list(rates), list(rates.values()), color=["tab:green", "tab:blue"])
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("success rate (landed)")
    ax.set_title(f"{a.scenario}: {a.seeds} seeds per foot")
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
