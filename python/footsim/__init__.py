"""footsim from Python: scenarios, landing trials, simulations stepped with numpy arrays, the
stiffness model and the pitch-stiffness law, frames drawn into arrays.

A thin layer over libfootsim's embeddable interface (footsim/api/fs_api.h) through ctypes: every
number comes from the C library, nothing of footsim's physics, parsing or rules is redone here.

    import footsim
    sc = footsim.Scenario("landing_trial.ini", set={"run.step_s": 2e-4})
    print(sc.trial(seed=1))               # outcome, deciding rule, metrics
    sim = footsim.Sim(sc)
    sim.step(1000)
    pos, force = sim.contacts()           # (n, 3) arrays, m and N

Errors are FootsimError with footsim's own message ("file:line: what is wrong, and what would be
right") and its status (2 bad input, 3 numerical failure, 5 no memory). The library's warnings
(a heightmap covering part of the reach, ODE's messages) arrive as FootsimWarning.

Campaigns run in the library's pool of worker processes, as `footsim campaign` runs them (the same
files, byte for byte), with a progress callback whose False stops the campaign cleanly and
resumably; Ctrl-C does the same and is raised again as KeyboardInterrupt once the workers are gone:

    c = footsim.Campaign("landing_ci.ini", set={"campaign.seeds": 3})
    res = c.run("out/landing", jobs=2, progress=lambda p: print(p.done, p.total) or True)
    print(res.rows[0]["success_rate"])
"""
import ctypes
import json
import math
import os
import signal
import threading
import warnings
from collections import namedtuple
from ctypes import byref, c_char_p, c_double, c_int
from pathlib import Path

import numpy as np

from . import _lib
from ._lib import Error as _Error, lib as _c

__all__ = ["FootsimError", "FootsimWarning", "Scenario", "Sim", "TrialResult", "PitchLaw", "Campaign",
           "CampaignProgress", "CampaignResult", "version", "find_data", "has_renderer", "metric_names"]

STATUS_NAMES = {1: "expectation failed", 2: "bad input", 3: "numerical failure", 4: "cannot write",
                5: "no memory"}


class FootsimError(Exception):
    """A footsim call refused or failed: .status (fs_status: 2 bad input, 3 numerical, 5 no memory)
    and .message, footsim's text ("file:line: ...")."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status
        self.message = message


class FootsimWarning(UserWarning):
    """What the library accepts but doubts (fs_warn): handed to Python's warnings."""


def _warning(text, _user):
    warnings.warn(text.decode(errors="replace"), FootsimWarning, stacklevel=2)


_warning_fn = _lib.WARNING_FN(_warning)  # kept alive with the module
_c.fs_warning_handler(_warning_fn, None)
_c.fs_ode_init()


def _raise(err):
    raise FootsimError(err.status, err.message.decode(errors="replace"))


def _check(status, err):
    if status != 0:
        _raise(err)


def _dp(a):
    return a.ctypes.data_as(_lib.DP)


def version():
    """footsim's version and the git description it was built from: "1.0.0 (git abc1234)"."""
    return _c.fs_version().decode()


def has_renderer():
    """Whether libfootsim-render was found (Sim.render_frame needs it)."""
    return _lib.render_lib is not None


def find_data(name):
    """The file a relative name stands for: as given when it is there, else in $FOOTSIM_DATA, the
    installed data (P/share/footsim) or the source tree, each as given and in its scenarios/,
    scenarios/feet/ or terrains/ folder (as the command looks). Unfound: the name as given, so that
    footsim's own message names it."""
    p = Path(name)
    if p.exists() or p.is_absolute():
        return str(p)
    for d in _lib.data_dirs():
        for sub in ("", "scenarios", "scenarios/feet", "terrains"):
            q = d / sub / p
            if q.exists():
                return str(q)
    return str(p)


def _overrides(set):
    if not set:
        return []
    items = set.items() if isinstance(set, dict) else (s.split("=", 1) for s in set)
    out = []
    for k, v in items:
        if isinstance(v, bool):
            v = int(v)
        out.append(f"{k}={v!r}" if isinstance(v, float) else f"{k}={v}")
    return out


class _Handle:
    """A library handle: closed by close(), at the end of a with block, or when collected."""
    _h = None
    _kind = "handle"

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _handle(self):
        if not self._h:
            raise ValueError(f"the {self._kind} is closed")
        return self._h

    _closer = None  # the C function that releases the handle

    def close(self):
        if getattr(self, "_h", None):
            getattr(_c, self._closer)(self._h)
            self._h = None

    def _open_file(self, opener, path, set):
        """Opens a file with overrides through opener (fs_scenario_open, fs_campaign_open, ...)."""
        self.path = find_data(path)
        sets = [s.encode() for s in _overrides(set)]
        arr = (c_char_p * max(len(sets), 1))(*sets)
        err = _Error()
        self._h = opener(self.path.encode(), arr, len(sets), byref(err))
        if not self._h:
            _raise(err)
        self.overrides = tuple(s.decode() for s in sets)


class Scenario(_Handle):
    """A scenario file loaded with overrides: footsim.Scenario("landing_trial.ini",
    set={"run.step_s": 2e-4}) (set may also be a list of "section.key=value"), checked as the
    command's --set is: anything wrong raises FootsimError before anything runs."""
    _kind = "scenario"
    _closer = "fs_scenario_close"

    def __init__(self, path, set=None, _open=None):
        self._open_file(_open or _c.fs_scenario_open, path, set)

    @classmethod
    def for_design(cls, path, set=None):
        """A design file (a foot) alone, every other key at its default, for the stiffness model and
        the law: footsim.Scenario.for_design("feet/biomimetic.ini", set={"springs.k_d1_N_per_m": 9000})."""
        return cls(path, set, _open=_c.fs_scenario_open_design)

    @property
    def name(self):
        return _c.fs_scenario_title(self._handle()).decode()

    @property
    def is_trial(self):
        return bool(_c.fs_scenario_trial(self._handle()))

    def __getitem__(self, key):
        """The number a key "section.key" of the scenario, its design, terrain or robot has."""
        v, err = c_double(), _Error()
        _check(_c.fs_scenario_get(self._handle(), key.encode(), byref(v), byref(err)), err)
        return v.value

    def __repr__(self):
        return f"Scenario({self.path!r}, set={list(self.overrides)!r})" if self._h else "Scenario(closed)"

    def trial(self, seed=1):
        """Runs seed's landing trial (a trial scenario only) and returns its TrialResult."""
        err = _Error()
        h = _c.fs_trial_open(self._handle(), int(seed), byref(err))
        if not h:
            _raise(err)
        try:
            return TrialResult._from(h)
        finally:
            _c.fs_trial_close(h)

    def sim(self):
        """A new simulation of this scenario (Sim(self))."""
        return Sim(self)

    def chain_stiffness(self, chain):
        """Chain chain's (0-4) joint-space stiffness over (midfoot, MTP), N m/rad, as two 2 x 2
        arrays: from the exact geometry and with the paper's eq. 4 lever arms."""
        exact, eq4, err = np.empty(4), np.empty(4), _Error()
        _check(_c.fs_scenario_chain_stiffness(self._handle(), int(chain), _dp(exact), _dp(eq4), byref(err)), err)
        return exact.reshape(2, 2), eq4.reshape(2, 2)

    def pitch_stiffness(self, load_N):
        """The foot's stiffness against pitching its ankle body under load_N at the ankle, N m/rad."""
        K, err = c_double(), _Error()
        _check(_c.fs_scenario_pitch_stiffness(self._handle(), float(load_N), byref(K), byref(err)), err)
        return K.value

    def pitch_law(self, K_foot=None):
        """The pitch-stiffness law for the scenario's robot on a foot of pitch stiffness K_foot
        (None: this scenario's foot under the robot's weight, as a campaign's law): a PitchLaw."""
        out = [c_double() for _ in range(4)]
        stands, err = c_int(), _Error()
        _check(_c.fs_scenario_pitch_law(self._handle(), math.nan if K_foot is None else float(K_foot),
                                        *(byref(o) for o in out), byref(stands), byref(err)), err)
        return PitchLaw(*(o.value for o in out), bool(stands.value))


PitchLaw = namedtuple("PitchLaw", "K demand critical_height_m lean_rad stands")
PitchLaw.__doc__ = """The law for one robot: K (the foot's and the robot's joint in series, N m/rad),
demand (m g h, N m/rad), critical_height_m (K / (m g)), lean_rad (the lean at rest), stands."""


def metric_names():
    """The metrics a trial has, named with their units, in footsim's order."""
    return [_c.fs_trial_metric_name(m).decode() for m in range(_c.fs_trial_metric_count())]


class TrialResult:
    """A landing trial's result: outcome ("landed", "fell", "failed_numerics", "undecided"), rule
    (what decided it), failure (the message of a numerical failure, else ""), seed, and metrics
    (a dict of the metrics campaigns summarise, by name with units; NaN where the trial lacks one)."""

    __slots__ = ("outcome", "rule", "failure", "seed", "metrics")

    @classmethod
    def _from(cls, h):
        r = cls()
        r.outcome = _c.fs_trial_outcome(h).decode()
        r.rule = _c.fs_trial_rule(h).decode()
        r.failure = _c.fs_trial_failure(h).decode(errors="replace")
        r.seed = _c.fs_trial_seed(h)
        r.metrics = {_c.fs_trial_metric_name(m).decode(): _c.fs_trial_metric(h, m)
                     for m in range(_c.fs_trial_metric_count())}
        return r

    @property
    def landed(self):
        return self.outcome == "landed"

    def __repr__(self):
        return (f"TrialResult(seed={self.seed}, outcome={self.outcome!r}, rule={self.rule!r}, "
                f"touchdown_s={self.metrics['touchdown_s']:.4f}, peak_force_N={self.metrics['peak_force_N']:.1f})")


class Sim(_Handle):
    """A simulation of a scenario (a Scenario, or a file's name) at its start pose, stepped by step(n). Reading it gives numpy
    arrays (world frame, SI units); each reader takes an optional out= array to fill instead. The
    simulation keeps its own copy of the scenario."""
    _kind = "simulation"
    _render = None

    def __init__(self, scenario):
        if isinstance(scenario, (str, Path)):
            scenario = Scenario(scenario)
        err = _Error()
        self._h = _c.fs_sim_open(scenario._handle(), byref(err))
        if not self._h:
            _raise(err)
        self._render = None
        n = _c.fs_sim_body_count(self._h)
        self.body_names = tuple(_c.fs_sim_body_name(self._h, i).decode() for i in range(n))
        self.spring_names = tuple(_c.fs_sim_spring_name(self._h, i).decode()
                                  for i in range(_c.fs_sim_spring_count(self._h)))
        self.dt = _c.fs_sim_step_size(self._h)

    def close(self):
        if getattr(self, "_render", None):
            _lib.render_lib.fs_render_sim_close(self._render[0])
            self._render = None
        if getattr(self, "_h", None):
            _c.fs_sim_close(self._h)
            self._h = None


    def step(self, n=1):
        """Takes n steps of the scenario's step (dt). A failed check or an ODE error raises
        FootsimError (status 3) naming the body or hinge and the time; after an ODE error the
        simulation is dead (dead is True) and only close() remains. Ctrl-C stops it between chunks
        of 1000 steps (KeyboardInterrupt; the steps taken stay taken)."""
        err, n = _Error(), int(n)
        while n > 0:  # in chunks, so that Ctrl-C (Python's handler runs between calls) stops a long run
            k = min(n, 1000)
            _check(_c.fs_sim_advance(self._handle(), k, byref(err)), err)
            n -= k

    @property
    def time(self):
        return _c.fs_sim_time(self._handle())

    @property
    def dead(self):
        return bool(_c.fs_sim_dead(self._handle()))

    @property
    def warnings(self):
        """The warnings the library gave while it built and stepped this simulation (their text
        went to the warning handler)."""
        return _c.fs_sim_warnings(self._handle())

    @property
    def nbodies(self):
        return len(self.body_names)

    def body(self, name):
        """The index of the body called name ("talus", "robot", ...)."""
        i = _c.fs_sim_body_index(self._handle(), name.encode())
        if i < 0:
            raise KeyError(f"{name!r} is not a body of this simulation; its bodies: {', '.join(self.body_names)}")
        return i

    def _out(self, out, shape):
        if out is None:
            return np.empty(shape)
        if out.shape != shape or out.dtype != np.float64 or not out.flags.c_contiguous:
            raise ValueError(f"out: needs a C-contiguous float64 array of shape {shape}")
        return out

    def masses(self):
        """Each body's mass, kg, (nbodies,)."""
        m = np.empty(self.nbodies)
        _c.fs_sim_body_masses(self._handle(), _dp(m))
        return m

    def positions(self, out=None):
        """Each body's centre of mass, m, (nbodies, 3)."""
        p = self._out(out, (self.nbodies, 3))
        _c.fs_sim_poses(self._handle(), _dp(p), None)
        return p

    def rotations(self, out=None):
        """Each body's rotation matrix (world = R body), (nbodies, 3, 3)."""
        R = self._out(out, (self.nbodies, 3, 3))
        _c.fs_sim_poses(self._handle(), None, _dp(R))
        return R

    def velocities(self):
        """Each body's linear velocity, m/s, and angular velocity, rad/s: two (nbodies, 3) arrays."""
        v, w = np.empty((self.nbodies, 3)), np.empty((self.nbodies, 3))
        _c.fs_sim_velocities(self._handle(), _dp(v), _dp(w))
        return v, w

    def ankle(self):
        """The load's point (the ankle), m, (3,)."""
        a = np.empty(3)
        _c.fs_sim_ankle_position(self._handle(), _dp(a))
        return a

    def contacts(self):
        """The last step's ground contacts: points, m, and the ground's force on the foot there, N,
        two (ncontacts, 3) arrays."""
        n = _c.fs_sim_contact_count(self._handle())
        pos, force = np.empty((n, 3)), np.empty((n, 3))
        if n:
            _c.fs_sim_contacts(self._h, _dp(pos), _dp(force), n)
        return pos, force

    def spring_forces(self, out=None):
        """Each spring-damper's force now, N, tension positive, (nsprings,) in spring_names' order."""
        f = self._out(out, (len(self.spring_names),))
        _c.fs_sim_spring_forces(self._handle(), _dp(f), None)
        return f

    def spring_lengths(self, out=None):
        """Each spring-damper's length now, m, (nsprings,)."""
        L = self._out(out, (len(self.spring_names),))
        _c.fs_sim_spring_forces(self._handle(), None, _dp(L))
        return L

    def energy(self):
        """Energy now, J: kinetic, potential (gravity, relative to z = 0), elastic (springs), total."""
        k, p, e = c_double(), c_double(), c_double()
        total = _c.fs_sim_energies(self._handle(), byref(k), byref(p), byref(e))
        return {"kinetic": k.value, "potential": p.value, "elastic": e.value, "total": total}

    def checks(self):
        """The worst values of the state checks so far: the fastest point, m/s, the widest open loop,
        m, and the energy beyond its reference, J."""
        out = [c_double() for _ in range(3)]
        _c.fs_sim_check_worst(self._handle(), *(byref(o) for o in out))
        return dict(zip(("max_speed_m_per_s", "max_loop_error_m", "max_energy_excess_J"), (o.value for o in out)))

    def apply_torque(self, body, torque_N_m):
        """Adds a torque (world frame, N m) to body (a name or an index) for the coming step only."""
        i = self.body(body) if isinstance(body, str) else int(body)
        t = np.ascontiguousarray(torque_N_m, dtype=np.float64)
        if t.shape != (3,):
            raise ValueError("torque_N_m: needs three numbers, N m")
        err = _Error()
        _check(_c.fs_sim_apply_torque(self._handle(), i, _dp(t), byref(err)), err)

    def render_frame(self, width=640, height=480, camera="side", out=None):
        """The simulation now drawn by footsim's renderer: a (height, width, 4) uint8 RGBA array, rows
        top-down. The camera ("side", "front", "three-quarter", "follow", "foot") is framed on the
        first frame drawn and follows the foot after, as the command's --frames; a new size or camera
        starts a new framing. Needs libfootsim-render (has_renderer())."""
        if _lib.render_lib is None:
            raise FootsimError(2, "render_frame: footsim was built without its renderer (libfootsim-render); "
                                  "install libosmesa6-dev and rebuild")
        key = (int(width), int(height), camera)
        if self._render is None or self._render[1] != key:
            if self._render is not None:
                _lib.render_lib.fs_render_sim_close(self._render[0])
                self._render = None
            err = _Error()
            h = _lib.render_lib.fs_render_sim_open(key[0], key[1], camera.encode(), byref(err))
            if not h:
                _raise(err)
            self._render = (h, key)
        img = out if out is not None else np.empty((key[1], key[0], 4), dtype=np.uint8)
        if img.shape != (key[1], key[0], 4) or img.dtype != np.uint8 or not img.flags.c_contiguous:
            raise ValueError(f"out: needs a C-contiguous uint8 array of shape {(key[1], key[0], 4)}")
        _lib.render_lib.fs_render_sim_draw(self._render[0], self._handle(),
                                           img.ctypes.data_as(ctypes.POINTER(ctypes.c_ubyte)))
        return img

    def __repr__(self):
        return f"Sim(t={self.time:.4f} s, {self.nbodies} bodies)" if self._h else "Sim(closed)"


CampaignProgress = namedtuple("CampaignProgress", "done total failed say")
CampaignProgress.__doc__ = """What a campaign's progress callback is given: trials done (a resumed
journal's included) of total, failed (numerically, or their worker lost) and say (a line worth
saying: a lost worker, a resume; else None)."""


class CampaignResult:
    """How Campaign.run ended: status "done", "stopped" (the callback returned False: the finished
    trials are kept in dir + ".journal" and the same run goes on from there) or "already" (dir held
    these results; nothing ran); dir, the results folder; summary, its summary.json (None unless
    written); rows, the summary's rows (a dict a cell: foot, terrain, robot, trials, landed,
    success_rate, ci_low, ci_high, medians ...)."""

    __slots__ = ("status", "dir", "summary")

    def __init__(self, status, dir):
        self.status, self.dir = status, dir
        path = Path(dir) / "summary.json"
        self.summary = json.loads(path.read_text()) if status != "stopped" and path.is_file() else None

    @property
    def stopped(self):
        return self.status == "stopped"

    @property
    def rows(self):
        return self.summary["rows"] if self.summary else []

    def __repr__(self):
        return f"CampaignResult({self.status!r}, {str(self.dir)!r}, {len(self.rows)} rows)"


class Campaign(_Handle):
    """A campaign file loaded with overrides: footsim.Campaign("landing_ci.ini",
    set={"campaign.seeds": 3, "run.step_s": 2e-4}); a campaign section's key changes the campaign
    file, any other goes to every trial (as the command's --set). Every trial scenario is loaded and
    checked here: anything wrong raises FootsimError before anything runs."""
    _kind = "campaign"
    _closer = "fs_campaign_close"

    def __init__(self, path, set=None):
        self._open_file(_c.fs_campaign_open, path, set)

    @property
    def name(self):
        return _c.fs_campaign_title(self._handle()).decode()

    @property
    def ntrials(self):
        return _c.fs_campaign_trial_count(self._handle())

    @property
    def ncells(self):
        return _c.fs_campaign_cell_count(self._handle())

    def __repr__(self):
        return f"Campaign({self.path!r}, set={list(self.overrides)!r})" if self._h else "Campaign(closed)"

    def run(self, out=None, jobs=None, progress=None, shard=None, fresh=False, replace=False):
        """Runs every trial in `jobs` worker processes (None: the CPUs it may use) and writes the
        campaign's files into out (default results/campaigns/<name>, as the command), the same bytes
        as `footsim campaign FILE --out OUT` (no success.png: gnuplot's, drawn by the command).
        progress(CampaignProgress) is called after every trial and at least every 0.2 s; its False
        stops the campaign cleanly (the finished trials kept in OUT.journal; run again to go on).
        Ctrl-C stops it the same way, then raises KeyboardInterrupt. shard=(i, n) runs the i-th of n
        shares (OUT/trials.journal; `footsim merge` joins them); fresh starts over. Returns a
        CampaignResult; a refusal or failure raises FootsimError."""
        out = str(out) if out is not None else os.path.join("results", "campaigns", self.name)
        i, n = (0, 0) if shard is None else (int(shard[0]), int(shard[1]))
        interrupted = []
        raised = []

        def relay(done, total, failed, say, _user):
            if interrupted or raised:
                return 0
            if progress is None:
                return 1
            try:
                p = CampaignProgress(done, total, failed, say.decode(errors="replace") if say else None)
                return 0 if progress(p) is False else 1
            except BaseException as e:  # noqa: BLE001 - raised again once the library is out
                raised.append(e)
                return 0

        # While C code runs, Python's SIGINT handler runs only when the callback next enters Python;
        # there it must not raise through ctypes: a handler of our own notes Ctrl-C, the callback
        # stops the campaign, and the handler that was there runs once the workers are gone.
        previous = None
        if threading.current_thread() is threading.main_thread():
            previous = signal.getsignal(signal.SIGINT)
            if previous in (signal.SIG_IGN, None):
                previous = None
            else:
                signal.signal(signal.SIGINT, lambda signum, frame: interrupted.append(signum))
        fn = _lib.PROGRESS_FN(relay)
        how, err = c_int(), _Error()
        flags = (1 if fresh else 0) | (2 if replace else 0)
        try:
            status = _c.fs_campaign_execute(self._handle(), out.encode(), int(jobs or 0), i, n, flags, fn, None,
                                            byref(how), byref(err))
        finally:
            if previous is not None:
                signal.signal(signal.SIGINT, previous)
        if raised:
            raise raised[0]
        if status != 0:
            _raise(err)
        if interrupted:
            if callable(previous):
                previous(signal.SIGINT, None)  # Python's own raises KeyboardInterrupt
            raise KeyboardInterrupt(f"campaign {self.name} stopped; its finished trials are kept in {out}.journal")
        return CampaignResult({0: "done", 1: "stopped", 2: "already"}.get(how.value, "done"), out)
