#!/usr/bin/env python3
"""Steps a landing with footsim and plots the ankle's height and the ground's force against time.

    PYTHONPATH=python python3 python/examples/landing_ankle.py --out landing_ankle.png
    python3 landing_ankle.py --set robot.design=robots/drop_weight.ini   # installed footsim

The scenario's foot starts at its file's pose (no seed drawn), the robot on it, and falls onto the
terrain; every step's ankle height and vertical ground force are read from the simulation."""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import footsim  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenario", nargs="?", default="landing_trial.ini")
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE")
    ap.add_argument("--duration", type=float, default=0.4, help="simulated seconds (default 0.4)")
    ap.add_argument("--out", default="landing_ankle.png")
    a = ap.parse_args(argv)

    sc = footsim.Scenario(a.scenario, set=a.set)
    sim = footsim.Sim(sc)
    n = int(round(a.duration / sim.dt))
    t, z, fz = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    t[0], z[0], fz[0] = sim.time, sim.ankle()[2], 0
    for i in range(1, n + 1):
        sim.step()
        t[i], z[i] = sim.time, sim.ankle()[2]
        fz[i] = sim.contacts()[1][:, 2].sum()
    touch = np.flatnonzero(fz > 0)
    touchdown = t[touch[0]] if touch.size else float("nan")
    print(f"{sc.name}: {sim.nbodies} bodies, step {sim.dt:g} s, {n} steps to t = {sim.time:.3f} s")
    print(f"touchdown at t = {touchdown:.4f} s; ankle from {1e3 * z[0]:.2f} mm down to {1e3 * z.min():.2f} mm, "
          f"{1e3 * z[-1]:.2f} mm at the end; peak ground force {fz.max():.0f} N")

    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax1.plot(t, 1e3 * z)
    ax1.set_ylabel("ankle height (mm)")
    ax1.set_title(f"{sc.name}: ankle during the landing")
    ax2.plot(t, fz, color="tab:red")
    ax2.set_ylabel("ground force z (N)")
    ax2.set_xlabel("time (s)")
    for ax in (ax1, ax2):
        ax.axvline(touchdown, color="grey", lw=0.8, ls="--")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print(f"wrote {a.out}")
    sim.close()


if __name__ == "__main__":
    main()
