"""Tests of the Python package over libfootsim (python/footsim): what a user calls, checked against
the physics or against footsim's own answers. Run by ctest (`python`, tests/python.sh) with
FOOTSIM_LIB pointing at the build's library."""
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import footsim

ROOT = Path(__file__).resolve().parents[2]
G = 9.81


def test_scenario_overrides_reach_it():
    sc = footsim.Scenario("landing_trial.ini", set={"run.step_s": 2e-4, "robot.mass_kg": 30})
    assert sc["run.step_s"] == 2e-4 and sc["robot.mass_kg"] == 30
    assert sc.name == "landing_trial" and sc.is_trial
    assert footsim.Scenario("static_load.ini", set=["load.mass_kg=20"])["load.mass_kg"] == 20
    assert not footsim.Scenario("static_load.ini").is_trial


def test_errors_carry_footsim_s_message(tmp_path):
    with pytest.raises(footsim.FootsimError) as e:
        footsim.Scenario("landing_trial.ini", set={"run.step_s": 5})
    assert e.value.status == 2 and "step_s" in e.value.message and "[1e-07, 0.1]" in e.value.message
    bad = tmp_path / "bad.ini"
    bad.write_text(f"[scenario]\ndesign = {ROOT}/scenarios/feet/biomimetic.ini\n[run]\nstep_s = -1\n")
    with pytest.raises(footsim.FootsimError) as e:
        footsim.Scenario(str(bad))
    assert e.value.status == 2 and str(e.value).startswith(f"{bad}:4: ")
    with pytest.raises(footsim.FootsimError) as e:
        footsim.Scenario("static_load.ini")["run.no_such_key"]
    assert "no_such_key" in str(e.value)
    with pytest.raises(footsim.FootsimError) as e:
        footsim.Scenario("static_load.ini").trial(1)
    assert e.value.status == 2 and "footsim run" in str(e.value)


def test_trial_is_footsim_s():
    sc = footsim.Scenario("landing_trial.ini")
    r = sc.trial(seed=3)
    assert r.outcome in ("landed", "fell", "failed_numerics", "undecided") and r.rule and r.seed == 3
    assert list(r.metrics) == footsim.metric_names() and len(r.metrics) == 18
    # the soil's five (sinkage, the print's depth, area, volume and slip) are empty on rigid ground
    soil = ("soil_sinkage_m", "print_depth_m", "print_area_m2", "print_volume_m3", "print_slip_m")
    assert all(math.isnan(r.metrics[k]) for k in soil)
    # the foot falls freely from its 5 mm drop before it touches: sqrt(2 drop / g)
    assert abs(r.metrics["touchdown_s"] - math.sqrt(2 * 0.005 / G)) < 3e-3
    assert r.metrics["end_time_s"] == pytest.approx(r.metrics["steps"] * 1e-4, abs=1e-9)
    again = sc.trial(seed=3)  # same seed, same bits
    assert again.outcome == r.outcome and again.metrics == pytest.approx(r.metrics, rel=0, abs=0, nan_ok=True)


def test_trial_agrees_with_the_command(tmp_path):
    exe = ROOT / "build" / "footsim"
    lib = os.environ.get("FOOTSIM_LIB")
    if lib:
        exe = Path(lib).parent / "footsim"
    if not exe.exists():
        pytest.skip("no footsim command beside the library")
    out = subprocess.run([str(exe), "trial", "scenarios/landing_trial.ini", "--seed", "2", "--out", str(tmp_path / "t")],
                         cwd=ROOT, capture_output=True, text=True)
    assert out.returncode in (0, 1), out.stderr
    import json
    metrics = json.loads((tmp_path / "t" / "trial.json").read_text())
    r = footsim.Scenario("landing_trial.ini").trial(2)
    assert metrics["outcome"] == r.outcome
    assert metrics["peak_force_N"] == pytest.approx(r.metrics["peak_force_N"], rel=1e-12)


def test_sim_at_rest_carries_its_weight():
    sim = footsim.Sim("static_load.ini")
    assert sim.body_names[:2] == ("heel", "talus") and sim.nbodies == 12 and len(sim.spring_names) == 15
    sim.step(3000)
    assert sim.time == pytest.approx(0.3, abs=1e-12)
    assert sim.warnings == 0 and not sim.dead  # a sound run: ODE said nothing
    pos, force = sim.contacts()
    assert pos.shape == force.shape and pos.shape[1] == 3 and len(pos) > 0
    weight = (26 + sim.masses().sum()) * G
    assert force[:, 2].sum() == pytest.approx(weight, rel=0.01)
    assert np.abs(pos[:, 2]).max() < 2e-3
    R = sim.rotations()
    assert np.allclose(R @ R.transpose(0, 2, 1), np.eye(3), atol=1e-9)
    v, w = sim.velocities()
    assert v.shape == (12, 3) and np.abs(v).max() < 0.02
    e = sim.energy()
    assert e["total"] == pytest.approx(e["kinetic"] + e["potential"] + e["elastic"], abs=1e-12) and e["kinetic"] < 1e-3
    f = sim.spring_forces()
    assert f.shape == (15,) and np.all(np.isfinite(f)) and sim.spring_lengths().min() > 0
    out = np.empty((12, 3))
    assert sim.positions(out=out) is out and np.array_equal(out[:, :], sim.positions())
    assert 0 < sim.checks()["max_speed_m_per_s"] < 10
    assert 0.01 < sim.ankle()[2] < 0.1


def test_torque_turns_the_foot():
    sc = footsim.Scenario("landing_trial.ini")
    spins = []
    for tz in (0, 5, -5):
        sim = footsim.Sim(sc)
        sim.apply_torque("talus", [0, 0, tz])
        sim.step(10)
        assert len(sim.contacts()[0]) == 0  # still in the air
        spins.append(sim.velocities()[1][sim.body("talus"), 2])
    assert abs(spins[0]) < 1e-9 and spins[1] > 1e-3 and spins[2] < -1e-3
    with pytest.raises(footsim.FootsimError):
        sim.apply_torque(sim.nbodies, [0, 0, 1])
    with pytest.raises(KeyError):
        sim.body("nose")


def test_a_blow_up_is_raised_with_its_time():
    sim = footsim.Sim(footsim.Scenario("static_load.ini", set={"run.springs": "explicit", "run.step_s": 1e-3}))
    with pytest.raises(footsim.FootsimError) as e:
        sim.step(1000)
    assert e.value.status == 3 and " s" in str(e.value)


def test_stiffness_and_law():
    sc = footsim.Scenario("landing_trial.ini")
    exact, eq4 = sc.chain_stiffness(0)
    assert exact.shape == (2, 2) and np.allclose(exact, exact.T) and np.all(np.linalg.eigvalsh(exact) > 0)
    law = sc.pitch_law()
    m, h, g = sc["robot.mass_kg"], sc["robot.com_height_m"], sc["run.gravity_m_per_s2"]
    assert law.demand == pytest.approx(m * g * h, rel=1e-12)
    assert law.critical_height_m == pytest.approx(law.K / (m * g), rel=1e-12)
    assert not law.stands  # docs/landing.md: Table I's foot topples under single_tall
    assert law.K == pytest.approx(sc.pitch_stiffness(m * g), rel=1e-12)  # a rigid joint adds nothing in series
    stiff = sc.pitch_law(K_foot=1e6)
    assert stiff.stands and stiff.lean_rad == pytest.approx(m * g * sc["robot.com_forward_m"] / (1e6 - m * g * h))
    with pytest.raises(footsim.FootsimError):
        footsim.Scenario("static_load.ini", set={"scenario.design": "feet/flat.ini"}).chain_stiffness(0)
    design = footsim.Scenario.for_design("biomimetic.ini")
    assert np.array_equal(design.chain_stiffness(0)[0], exact)  # the trial's foot is that design
    soft = footsim.Scenario.for_design("biomimetic.ini", set={"springs.k_d1_N_per_m": 1000})
    assert soft.chain_stiffness(0)[0][0, 0] < exact[0, 0]  # a softer midfoot spring, a softer chain


@pytest.mark.skipif(not footsim.has_renderer(), reason="built without libfootsim-render")
def test_render_frame_draws_the_foot():
    sim = footsim.Sim(footsim.Scenario("landing_trial.ini"))
    img = sim.render_frame(160, 120, camera="side")
    assert img.shape == (120, 160, 4) and img.dtype == np.uint8
    background = img[0, -1, :3]
    drawn = np.any(img[:, :, :3] != background, axis=2).mean()
    assert 0.05 < drawn < 0.95  # something drawn, not everything
    sim.step(300)
    later = sim.render_frame(160, 120, camera="side")
    assert not np.array_equal(img, later)  # the foot moved (the camera follows only 'follow' and 'foot')
    with pytest.raises(footsim.FootsimError):
        sim.render_frame(160, 120, camera="nowhere")


def _example(name, args, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / f"{name}.png"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "python"), MPLCONFIGDIR=str(tmp_path))
    if env.get("FOOTSIM_LIB"):  # the example runs in tmp_path
        env["FOOTSIM_LIB"] = os.path.abspath(env["FOOTSIM_LIB"])
    p = subprocess.run([sys.executable, str(ROOT / "python" / "examples" / f"{name}.py"), *args, "--out", str(out)],
                       cwd=tmp_path, env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    return p.stdout


def test_examples_run(tmp_path):
    text = _example("landing_ankle", ["--duration", "0.06"], tmp_path)
    assert "touchdown at t = 0.03" in text
    text = _example("seeds_success", ["--seeds", "1"], tmp_path)
    assert "biomimetic" in text and "flat" in text
    text = _example("campaign_success", ["--seeds", "1", "-j", "2", "--set", "run.duration_s=0.3", "--dir",
                                         str(tmp_path / "camp")], tmp_path)
    assert text.count(" landed ") == 12 and (tmp_path / "camp" / "summary.json").is_file()


def test_installed_package_finds_its_library_and_data(tmp_path):
    """make install's package, imported from elsewhere with only PYTHONPATH set, loads the
    installed libfootsim (not the build's) and finds the installed scenarios."""
    build = Path(os.environ.get("FOOTSIM_LIB", ROOT / "build" / "libfootsim.so")).resolve().parent
    if not (build / "cmake_install.cmake").exists():
        pytest.skip("no build folder to install from")
    prefix = tmp_path / "prefix"
    p = subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    site = prefix / "lib" / "python3" / "dist-packages"
    assert (site / "footsim" / "__init__.py").exists()
    env = {k: v for k, v in os.environ.items() if k not in ("FOOTSIM_LIB", "FOOTSIM_DATA", "PYTHONPATH")}
    env.update(PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")
    code = ("import footsim, footsim._lib as l; sc = footsim.Scenario('static_load.ini'); "
            "print(l.lib_path.resolve()); print(sc.path); print(footsim.version())")
    p = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    lib_path, sc_path, _ = p.stdout.splitlines()
    assert lib_path.startswith(str(prefix.resolve())) and sc_path.startswith(str(prefix.resolve()))
