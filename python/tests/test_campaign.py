"""Campaigns from Python (footsim.Campaign) over the library's campaign runner: the same files as the
command's, byte for byte, from the same pool of worker processes (jobs=2); a progress callback that
says False stops the campaign cleanly and resumably; Ctrl-C (SIGINT) reaches the library through the
callback and comes back as KeyboardInterrupt. Run by ctest (`python`, tests/python.sh)."""
import os
import re
import signal
import subprocess
import threading
from pathlib import Path

import pytest

import footsim

ROOT = Path(__file__).resolve().parents[2]
FILES = ("summary.json", "summary.csv", "summary.md", "trials.csv", "schema.sql", "chart.dat", "chart.gp")


def _exe():
    lib = os.environ.get("FOOTSIM_LIB")
    return (Path(lib).parent if lib else ROOT / "build") / "footsim"


@pytest.fixture
def small(tmp_path):
    """2 feet x 1 terrain x 3 seeds = 6 short trials (tests/small_campaign.sh's campaign)."""
    trial = (ROOT / "scenarios" / "campaign_test_trial.ini").read_text()
    trial = trial.replace("design = feet/", f"design = {ROOT}/scenarios/feet/")
    trial = trial.replace("terrain = ../terrains/", f"terrain = {ROOT}/terrains/")
    trial = trial.replace("design = robots/", f"design = {ROOT}/scenarios/robots/")
    (tmp_path / "trial.ini").write_text(trial)
    ini = tmp_path / "small.ini"
    ini.write_text(f"[campaign]\ntrial = trial.ini\nseeds = 3\n\n[foot.bio]\nfile = {ROOT}/scenarios/feet/biomimetic.ini"
                   f"\n\n[foot.flat]\nfile = {ROOT}/scenarios/feet/flat.ini\n\n[terrain.bumpy]\n"
                   f"file = {ROOT}/terrains/simply_uneven.ini\n")
    return ini


SET = {"run.duration_s": 0.15}


def test_campaign_is_the_command_s(small, tmp_path):
    c = footsim.Campaign(str(small), set=SET)
    assert (c.name, c.ntrials, c.ncells) == ("small", 6, 2)
    seen = []
    res = c.run(tmp_path / "py", jobs=2, progress=lambda p: seen.append(p) or True)
    assert res.status == "done" and not res.stopped
    assert [(r["foot"], r["trials"]) for r in res.rows] == [("bio", 3), ("flat", 3)]
    # the callback saw every trial end, counted against the whole campaign
    assert seen and seen[-1].done == 6 and all(p.total == 6 for p in seen)
    assert [p.done for p in seen] == sorted(p.done for p in seen)
    cmd = subprocess.run([str(_exe()), "campaign", str(small), "-j", "2", "--out", str(tmp_path / "cli"),
                          "--set", "run.duration_s=0.15"], capture_output=True, text=True)
    assert cmd.returncode == 0, cmd.stderr
    for f in FILES:
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    # run again: the folder holds these results already, nothing runs
    again = c.run(tmp_path / "py", jobs=2)
    assert again.status == "already" and again.rows == res.rows


def test_false_stops_cleanly_and_resumably(small, tmp_path):
    c = footsim.Campaign(str(small), set=SET)
    out = tmp_path / "stop"

    def stop_after_two(p):
        return p.done < 2

    res = c.run(out, jobs=2, progress=stop_after_two)
    assert res.stopped and res.summary is None
    assert not out.exists()  # nothing written but the journal
    journal = (tmp_path / "stop.journal" / "journal").read_text().splitlines()
    kept = [line for line in journal if re.match(r"[0-9]+ [0-9a-f]{8} [0-9]", line)]
    assert 2 <= len(kept) < 6
    says = []
    done = c.run(out, jobs=2, progress=lambda p: says.append(p.say) if p.say else True)
    assert done.status == "done" and not (tmp_path / "stop.journal").exists()
    assert any(s and s.startswith("resuming from") and f"{len(kept)} of 6 trials done" in s for s in says)
    whole = c.run(tmp_path / "whole", jobs=1)
    for f in FILES:
        assert (out / f).read_bytes() == (tmp_path / "whole" / f).read_bytes(), f


def test_ctrl_c_reaches_the_library(small, tmp_path):
    c = footsim.Campaign(str(small), set={"run.duration_s": 1.0})
    out = tmp_path / "int"
    calls = []

    def progress(p):
        calls.append(p)
        if len(calls) == 1:  # SIGINT from outside, as a terminal's Ctrl-C, while C code runs
            threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT)).start()
        return True

    with pytest.raises(KeyboardInterrupt):
        c.run(out, jobs=2, progress=progress)
    assert not out.exists() and c.ntrials == 6
    # the workers are gone, and the run goes on from its journal (or from nothing when none had ended)
    res = c.run(out, jobs=2)
    assert res.status == "done" and len(res.rows) == 2


def test_a_bad_campaign_is_refused_before_anything_runs(small, tmp_path):
    with pytest.raises(footsim.FootsimError) as e:
        footsim.Campaign(str(small), set={"campaign.seeds": 0})
    assert e.value.status == 2 and "seeds" in e.value.message
    c = footsim.Campaign(str(small), set=SET)
    with pytest.raises(footsim.FootsimError) as e:
        c.run(tmp_path / "x", shard=(3, 2))
    assert e.value.status == 2 and not (tmp_path / "x").exists()
