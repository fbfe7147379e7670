#!/usr/bin/python3
"""The contact-model runs of docs/contact.md (issue 34 item 4): landing trials of the biomimetic foot
under single_tall (0.3 m) in footsim (ODE) and in MuJoCo 2.2.2 (build/mujoco-trial, the same trial's
MJCF export judged by footsim's rules), over contact settings and spring scales.

    python3 tools/contact_runs.py EXPERIMENT [--build DIR] [--out DIR] [-j N]

EXPERIMENT: band (footsim's contact stiffness and damping over their plausible range, both engines,
21.5 times Table I's springs), mujoco (MuJoCo's own contact settings at footsim's default contact),
friction (footsim's friction coefficient), spheres (the contact spheres' number and size), boundary
(spring scale 10-100 at the band's two ends, both engines), boundary_fine (the same in MuJoCo at a
2e-5 s step), layer (footsim's contact surface layer at 1e-9 m instead of 0.5 mm), mujoco_friction (MuJoCo's cone and
friction one at a time at 2e-5 s). Writes OUT/EXPERIMENT.md (default
results/contact/): every trial's row and each setting's count, with the commands that made them.

The contact band is given as a stiffness k (N/m) and a damping ratio zeta per contact point, the
sole and the ground in series (footsim's rule): the sole's keys are solved for so that, with the
terrain's ground (1e8 N/m, 2e4 N s/m), the series contact has k and c = 2 zeta sqrt(k m), m the mass
a contact point carries in a flat landing (the export's: everything that moves over the 12 spheres,
2.19 kg). Python 3 standard library only.
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys

TRIAL = "scenarios/landing_trial.ini"
GROUND_K, GROUND_C = 1e8, 2e4   # terrains/flat.ini's material
MASS_PER_POINT = (26.0 + 0.27) / 12  # kg: robot and foot over the 12 spheres (docs/export.md)
SEEDS = [1, 2, 3]


PAD_M = 0.003  # the rubber pad's thickness: how deep a sphere may press into it (the sink bound)


def sole(k, zeta):
    """--set values giving the series contact stiffness k and damping ratio zeta. A contact softer
    than 1e6 N/m is a rubber pad: a sphere pressing into it is not sinking into the ground, so the
    sink rule's bound is the pad's thickness (the default 1 mm stands for rigid ground)."""
    c = 2 * zeta * math.sqrt(k * MASS_PER_POINT)
    ks = k * GROUND_K / (GROUND_K - k)
    cs = c * GROUND_C / (GROUND_C - c)
    pad = [f"material.sink_bound_m={PAD_M:g}"] if k < 1e6 else []
    return [f"sole.stiffness_N_per_m={ks:.6g}", f"sole.damping_Ns_per_m={cs:.6g}"] + pad


def zeta_of_default():
    k = 1 / (1 / 1e7 + 1 / GROUND_K)
    c = 1 / (1 / 2e4 + 1 / GROUND_C)
    return k, c / (2 * math.sqrt(k * MASS_PER_POINT))


def run_footsim(build, seed, sets):
    cmd = ["nice", "-n", "10", f"{build}/footsim", "trial", TRIAL, "--seed", str(seed), "--json"]
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 3):
        return cmd, {"outcome": "error", "rule": p.stderr.strip()[:80]}
    r = json.loads(p.stdout)
    return cmd, {"outcome": r["outcome"], "rule": r["rule"], "end_s": r["end_time_s"],
                 "peak_lean_deg": r["peak_tilt_deg"], "final_lean_deg": r["final_tilt_deg"],
                 "final_contacts": r["final_contacts"], "mean_contacts": r["mean_contacts"]}


def run_mujoco(build, seed, sets, opts):
    cmd = ["nice", "-n", "10", f"{build}/mujoco-trial", TRIAL, "--seed", str(seed)] + list(opts)
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    line = next((l for l in p.stdout.splitlines() if l.startswith("seed=")), None)
    if p.returncode != 0 or not line:
        return cmd, {"outcome": "error", "rule": p.stderr.strip()[:80]}
    f = dict(kv.split("=", 1) for kv in line.split())
    return cmd, {"outcome": f["outcome"], "rule": f["rule"], "end_s": float(f["end_s"]),
                 "peak_lean_deg": float(f["peak_lean_deg"]), "final_lean_deg": float(f["final_lean_deg"]),
                 "final_contacts": int(f["final_contacts"]), "contacts_1s": int(f["contacts_1s"]),
                 "lean_0.5s_deg": float(f["lean_0.5s_deg"])}


def experiment(name):
    """(title, list of cases); a case: (label, engine, --set list, MuJoCo options)."""
    cases = []
    scale = ["springs.scale=21.5"]
    k0, z0 = zeta_of_default()
    if name == "band":
        title = (f"21.5 times Table I's springs, single_tall at 0.3 m, flat ground: contact stiffness k and damping "
                 f"ratio zeta per point (sole and ground in series; footsim's default is k = {k0:.3g} N/m, "
                 f"zeta = {z0:.2f}), in both engines")
        settings = [("default", [])]
        for k in (1e5, 3e5, 1e6, k0):
            for z in (0.22, 1.0):
                settings.append((f"k={k:.3g} zeta={z:g}", sole(k, z)))
        for label, sets in settings:
            for engine in ("footsim", "mujoco"):
                cases.append((label, engine, scale + sets, []))
    elif name == "mujoco":
        title = ("21.5 times Table I's springs, single_tall at 0.3 m, flat ground, footsim's default contact: "
                 "MuJoCo's own contact settings (the export writes the direct solref from footsim's k and c, "
                 "solimp 0.95, impratio 100, a pyramidal cone, the implicit integrator)")
        fine = ["run.step_s=2e-5"]
        for label, sets, opts in [("as exported", [], []), ("timeconst 0.5 ms", [], ["--timeconst", "5e-4"]),
                                  ("timeconst 2 ms", [], ["--timeconst", "2e-3"]),
                                  ("timeconst 5 ms", [], ["--timeconst", "5e-3"]),
                                  ("impratio 1", [], ["--impratio", "1"]), ("elliptic cone", [], ["--cone", "elliptic"]),
                                  ("solimp 0.99", [], ["--solimp", "0.99"]), ("noslip 20", [], ["--noslip", "20"]),
                                  ("mu 3", [], ["--mu", "3"]), ("mu 10", [], ["--mu", "10"]),
                                  ("RK4", [], ["--integrator", "rk4"]),
                                  ("step 2e-5 s", fine, []), ("step 1e-5 s", ["run.step_s=1e-5"], []),
                                  ("step 2e-5 s, elliptic cone, mu 3", fine, ["--cone", "elliptic", "--mu", "3"]),
                                  ("step 2e-5 s, timeconst 2 ms", fine, ["--timeconst", "2e-3"]),
                                  ("step 2e-5 s, placed (drop 0.2 mm, no tilt or yaw)",
                                   fine + ["start.drop_m=0.0002", "landing.tilt_range_deg=0", "landing.yaw_range_deg=0"],
                                   [])]:
            cases.append((label, "mujoco", scale + sets, opts))
    elif name == "friction":
        title = ("21.5 times Table I's springs, single_tall at 0.3 m, flat ground, footsim's default contact: the "
                 "friction coefficient (sqrt(mu_sole mu_ground), the ground's 1). ODE's friction box of +-mu N "
                 "per direction holds up to sqrt(2) mu N along its diagonal: mu = 0.707 is the box inside the "
                 "cone of mu = 1")
        for mu in (0.5, 0.707, 3.0):
            sets = scale + [f"sole.mu={mu * mu:.6g}"]
            cases.append((f"mu={mu:g}", "footsim", sets, []))
            cases.append((f"mu={mu:g}", "mujoco", sets, []))
    elif name == "spheres":
        title = ("21.5 times Table I's springs, single_tall at 0.3 m, flat ground, footsim's default contact: the "
                 "contact spheres (one heel sphere instead of two; every sphere's radius doubled)")
        for label, sets in [("one heel sphere", ["contact.heel_width_m=0"]),
                            ("radii doubled", ["contact.heel_radius_m=0.012", "contact.ball_radius_m=0.008",
                                               "contact.toe_radius_m=0.006"])]:
            for engine in ("footsim", "mujoco"):
                cases.append((label, engine, scale + sets, []))
    elif name == "boundary":
        title = ("The stiff end of the envelope, single_tall at 0.3 m, flat ground: spring scale 10-100 at the "
                 "contact band's two ends, in both engines")
        for s in (10, 14.7, 21.5, 31.6, 46.4, 100):
            for label, sets in [("hard sole (default)", []), ("rubber pad k=1e5 zeta=0.22", sole(1e5, 0.22))]:
                for engine in ("footsim", "mujoco"):
                    cases.append((f"scale {s:g}, {label}", engine, [f"springs.scale={s:g}"] + sets, []))
    elif name == "layer":
        title = ("footsim's contact surface layer (run.contact_layer_m, 0.5 mm in landing_trial.ini; MuJoCo has none): "
                 "within it a contact holds the normal speed at zero without a spring force, a rigid, plastic "
                 "support. Single_tall at 0.3 m, flat ground, the layer at 1e-9 m (docs/model.md's stiff layer)")
        thin = ["run.contact_layer_m=1e-9"]
        for label, sets in [("21.5, default contact", ["springs.scale=21.5"]),
                            ("21.5, k=9.09e6 zeta=0.22", ["springs.scale=21.5"] + sole(k0, 0.22)),
                            ("21.5, k=1e5 zeta=1", ["springs.scale=21.5"] + sole(1e5, 1.0)),
                            ("31.6, default contact", ["springs.scale=31.6"]),
                            ("46.4, default contact", ["springs.scale=46.4"]),
                            ("100, default contact", ["springs.scale=100"])]:
            cases.append((label, "footsim", sets + thin, []))
    elif name == "mujoco_friction":
        title = ("21.5 times Table I's springs, single_tall at 0.3 m, flat ground, footsim's default contact: "
                 "MuJoCo's friction at a step of 2e-5 s (mujoco.md: the elliptic cone with mu 3 lands 3/3), one "
                 "change at a time")
        fine = scale + ["run.step_s=2e-5"]
        for label, opts in [("elliptic cone", ["--cone", "elliptic"]), ("mu 3", ["--mu", "3"]),
                            ("elliptic cone, mu 1.5", ["--cone", "elliptic", "--mu", "1.5"])]:
            cases.append((label, "mujoco", fine, opts))
    elif name == "boundary_fine":
        title = ("The stiff end of the envelope in MuJoCo at a step of 2e-5 s (its 1e-4 s is not converged here: "
                 "mujoco.md), single_tall at 0.3 m, flat ground, footsim's default contact")
        for s in (10, 14.7, 21.5, 31.6, 46.4, 100):
            cases.append((f"scale {s:g}", "mujoco", [f"springs.scale={s:g}", "run.step_s=2e-5"], []))
    else:
        sys.exit(f"contact_runs.py: unknown experiment {name}; give band, mujoco, mujoco_friction, friction, "
                 "spheres, boundary, boundary_fine or layer")
    return title, cases


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("experiment")
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/contact")
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--seeds", default="1,2,3")
    a = ap.parse_args()
    seeds = [int(s) for s in a.seeds.split(",")]
    title, cases = experiment(a.experiment)
    jobs = [(c, s) for c in cases for s in seeds]

    def one(job):
        (label, engine, sets, opts), seed = job
        if engine == "footsim":
            return run_footsim(a.build, seed, sets)
        return run_mujoco(a.build, seed, sets, opts)

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.j) as pool:
        results = list(pool.map(one, jobs))
    rows, counts, commands = [], {}, []
    for ((label, engine, sets, opts), seed), (cmd, r) in zip(jobs, results):
        key = (label, engine)
        counts.setdefault(key, {"landed": 0, "fell": 0, "undecided": 0, "other": 0, "settings": " ".join(sets + opts)})
        o = r["outcome"]
        counts[key][o if o in ("landed", "fell", "undecided") else "other"] += 1
        rows.append(f"| {label} | {engine} | {seed} | {o} ({r['rule']}) | {r.get('end_s', float('nan')):.2f} | "
                    f"{r.get('peak_lean_deg', float('nan')):.2f} | {r.get('final_lean_deg', float('nan')):.2f} | "
                    f"{r.get('final_contacts', '')} |")
        commands.append(" ".join(cmd[3:]))
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, a.experiment + ".md")
    with open(path + ".tmp", "w") as f:
        f.write(f"# {a.experiment}\n\n{title}.\n\nMade by `python3 tools/contact_runs.py {a.experiment}"
                f"{' --seeds ' + a.seeds if a.seeds != '1,2,3' else ''}` (docs/contact.md).\n\n")
        f.write("| setting | engine | landed | fell | undecided | other | --set and options |\n|---|---|--:|--:|--:|--:|---|\n")
        for (label, engine), c in counts.items():
            f.write(f"| {label} | {engine} | {c['landed']} | {c['fell']} | {c['undecided']} | {c['other']} | "
                    f"`{c['settings']}` |\n")
        f.write("\n| setting | engine | seed | outcome (rule) | end, s | peak lean, deg | final lean, deg | "
                "contacts at the end |\n|---|---|--:|---|--:|--:|--:|--:|\n")
        f.write("\n".join(rows) + "\n\nCommands (from the worktree's top):\n\n```\n" + "\n".join(commands) + "\n```\n")
    os.replace(path + ".tmp", path)
    print(open(path).read().split("\n| setting | engine | seed")[0])


if __name__ == "__main__":
    main()
