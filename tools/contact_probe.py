#!/usr/bin/python3
"""The foot's static pitch and roll stiffness in footsim (ODE) under the 26 kg static load, for
docs/contact.md: is the stiff foot's landing decided by statics? Python package footsim (from the
build tree: PYTHONPATH=python, libfootsim from build/) and Debian's python3-numpy.

    /usr/bin/python3 tools/contact_probe.py SCALE [MU...] [section.key=value...]

For each friction coefficient MU (sqrt(mu_sole mu_ground), the ground's 1; default 1 and 0) the
static_load scenario with springs.scale=SCALE is loaded, and torques of +-0.2 N m about the world's
x axis (roll) and y axis (pitch) are ramped onto the talus over 0.05 s and held; after 0.8 s the
talus's turn about that axis is read. K = 2 tau / (turn(+) - turn(-)), printed beside m g h = 76.5
N m/rad, what single_tall (26 kg, 0.3 m) asks of either. A section.key=value argument is set in the
scenario too (the band's pad: sole.stiffness_N_per_m=100100 sole.damping_Ns_per_m=208.011)."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import footsim  # noqa: E402
import numpy as np  # noqa: E402

TAU = 0.2


def turn(scale, mu, axis, tau, sets=()):
    sc = footsim.Scenario(footsim.find_data("static_load.ini"),
                          set=[f"springs.scale={scale}", f"sole.mu={mu * mu:.6g}", "run.duration_s=100", *sets])
    sim = footsim.Sim(sc)
    talus = sim.body_names.index("talus")
    torque = np.zeros(3)
    torque[axis] = tau
    for _ in range(int(round(0.8 / sim.dt))):
        sim.apply_torque(talus, torque * min(1.0, sim.time / 0.05))
        sim.step(1)
    R = sim.rotations()[talus]
    spin = np.abs(sim.velocities()[1]).max()
    sim.close()
    sc.close()
    # roll: the turn of the talus's y axis about world x; pitch: of its x axis about world y
    return (math.atan2(R[2, 1], R[1, 1]) if axis == 0 else math.atan2(-R[2, 0], R[0, 0])), spin


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    scale = float(sys.argv[1])
    sets = [a for a in sys.argv[2:] if "=" in a]
    mus = [float(m) for m in sys.argv[2:] if "=" not in m] or [1.0, 0.0]
    demand = 26 * 9.81 * 0.3
    for mu in mus:
        for axis, name in ((0, "roll"), (1, "pitch")):
            (p, sp), (m, sm) = turn(scale, mu, axis, TAU, sets), turn(scale, mu, axis, -TAU, sets)
            K = 2 * TAU / (p - m)
            print(f"springs.scale {scale:g}, mu {mu:g}{''.join(' ' + x for x in sets)}: {name} stiffness {K:.1f} N m/rad, {K / demand:.1f} times "
                  f"single_tall's m g h = {demand:.1f} (residual spin {max(sp, sm):.1e} rad/s)")


if __name__ == "__main__":
    main()
