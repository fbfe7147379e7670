"""Finding and binding libfootsim (and libfootsim-render when it is there) through ctypes.

Where the library is looked for, first found wins:
  1. $FOOTSIM_LIB (a path to libfootsim.so[.N]); libfootsim-render is looked for beside it;
  2. an installed package: the library folder recorded at install (_paths.py, written by CMake);
  3. the source tree: <repo>/build/libfootsim.so (`make build`), when this package is <repo>/python/footsim;
  4. the system's loader (ldconfig, LD_LIBRARY_PATH): libfootsim.so.1.
"""
import ctypes
import os
from ctypes import POINTER, c_char_p, c_double, c_int, c_long, c_void_p
from pathlib import Path

_HERE = Path(__file__).resolve().parent
SONAME = "libfootsim.so.1"
RENDER_SONAME = "libfootsim-render.so.1"

try:
    from . import _paths  # written at install: where the library and the data went
except ImportError:  # the source tree
    _paths = None


def _candidates():
    env = os.environ.get("FOOTSIM_LIB")
    if env:
        return [Path(env)], True
    found = []
    if _paths is not None:
        found.append((_HERE / _paths.LIBDIR / SONAME).resolve())
    found.append(_HERE.parent.parent / "build" / "libfootsim.so")
    return found, False


def _load():
    paths, explicit = _candidates()
    for p in paths:
        if p.exists():
            return ctypes.CDLL(str(p)), p
    if explicit:
        raise OSError(f"FOOTSIM_LIB={paths[0]}: no such file; point it at libfootsim.so (build/libfootsim.so after `make build`)")
    try:
        return ctypes.CDLL(SONAME), None
    except OSError as e:
        raise OSError(f"footsim: libfootsim not found (looked in {', '.join(str(p) for p in paths)} and the system's "
                      f"library path); build it with `make build` or set FOOTSIM_LIB=path/to/libfootsim.so") from e


lib, lib_path = _load()


def _load_render():
    """libfootsim-render from beside the libfootsim loaded (the system's loader only when that one
    came from it too), so that the two are always of one build; None when it was not built."""
    if lib_path is not None:
        for p in (lib_path.parent / "libfootsim-render.so", lib_path.parent / RENDER_SONAME):
            if p.exists():
                return ctypes.CDLL(str(p))
        return None
    try:
        return ctypes.CDLL(RENDER_SONAME)
    except OSError:
        return None


render_lib = _load_render()


class Error(ctypes.Structure):
    """fs_error: a status and footsim's message (fs_error.h)."""
    _fields_ = [("status", c_int), ("message", ctypes.c_char * 1024)]


ERR = POINTER(Error)
DP = POINTER(c_double)
WARNING_FN = ctypes.CFUNCTYPE(None, c_char_p, c_void_p)
PROGRESS_FN = ctypes.CFUNCTYPE(c_int, c_int, c_int, c_int, c_char_p, c_void_p)


def _sig(l, name, restype, *argtypes):
    f = getattr(l, name)
    f.restype = restype
    f.argtypes = list(argtypes)


for name, res, *args in [
    ("fs_ode_init", None),
    ("fs_version", c_char_p),
    ("fs_warning_handler", None, WARNING_FN, c_void_p),
    ("fs_scenario_open", c_void_p, c_char_p, POINTER(c_char_p), c_int, ERR),
    ("fs_scenario_open_design", c_void_p, c_char_p, POINTER(c_char_p), c_int, ERR),
    ("fs_scenario_close", None, c_void_p),
    ("fs_scenario_title", c_char_p, c_void_p),
    ("fs_scenario_trial", c_int, c_void_p),
    ("fs_scenario_get", c_int, c_void_p, c_char_p, DP, ERR),
    ("fs_sim_open", c_void_p, c_void_p, ERR),
    ("fs_sim_close", None, c_void_p),
    ("fs_sim_advance", c_int, c_void_p, c_long, ERR),
    ("fs_sim_time", c_double, c_void_p),
    ("fs_sim_step_size", c_double, c_void_p),
    ("fs_sim_dead", c_int, c_void_p),
    ("fs_sim_warnings", c_long, c_void_p),
    ("fs_sim_body_count", c_int, c_void_p),
    ("fs_sim_body_name", c_char_p, c_void_p, c_int),
    ("fs_sim_body_index", c_int, c_void_p, c_char_p),
    ("fs_sim_body_masses", None, c_void_p, DP),
    ("fs_sim_poses", None, c_void_p, DP, DP),
    ("fs_sim_velocities", None, c_void_p, DP, DP),
    ("fs_sim_apply_torque", c_int, c_void_p, c_int, DP, ERR),
    ("fs_sim_ankle_position", None, c_void_p, DP),
    ("fs_sim_contact_count", c_int, c_void_p),
    ("fs_sim_contacts", c_int, c_void_p, DP, DP, c_int),
    ("fs_sim_spring_count", c_int, c_void_p),
    ("fs_sim_spring_name", c_char_p, c_void_p, c_int),
    ("fs_sim_spring_forces", None, c_void_p, DP, DP),
    ("fs_sim_energies", c_double, c_void_p, DP, DP, DP),
    ("fs_sim_check_worst", None, c_void_p, DP, DP, DP),
    ("fs_trial_open", c_void_p, c_void_p, c_int, ERR),
    ("fs_trial_close", None, c_void_p),
    ("fs_trial_outcome", c_char_p, c_void_p),
    ("fs_trial_rule", c_char_p, c_void_p),
    ("fs_trial_failure", c_char_p, c_void_p),
    ("fs_trial_seed", c_int, c_void_p),
    ("fs_trial_metric_count", c_int),
    ("fs_trial_metric_name", c_char_p, c_int),
    ("fs_trial_metric", c_double, c_void_p, c_int),
    ("fs_scenario_chain_stiffness", c_int, c_void_p, c_int, DP, DP, ERR),
    ("fs_scenario_pitch_stiffness", c_int, c_void_p, c_double, DP, ERR),
    ("fs_scenario_pitch_law", c_int, c_void_p, c_double, DP, DP, DP, DP, POINTER(c_int), ERR),
    ("fs_campaign_open", c_void_p, c_char_p, POINTER(c_char_p), c_int, ERR),
    ("fs_campaign_close", None, c_void_p),
    ("fs_campaign_title", c_char_p, c_void_p),
    ("fs_campaign_trial_count", c_int, c_void_p),
    ("fs_campaign_cell_count", c_int, c_void_p),
    ("fs_campaign_execute", c_int, c_void_p, c_char_p, c_int, c_int, c_int, c_int, PROGRESS_FN, c_void_p,
     POINTER(c_int), ERR),
]:
    _sig(lib, name, res, *args)

if render_lib is not None:
    _sig(render_lib, "fs_render_sim_open", c_void_p, c_int, c_int, c_char_p, ERR)
    _sig(render_lib, "fs_render_sim_close", None, c_void_p)
    _sig(render_lib, "fs_render_sim_draw", None, c_void_p, c_void_p, POINTER(ctypes.c_ubyte))


def data_dirs():
    """Folders a relative scenario, design or terrain name is looked for in (find_data)."""
    dirs = []
    if os.environ.get("FOOTSIM_DATA"):
        dirs.append(Path(os.environ["FOOTSIM_DATA"]))
    if _paths is not None:
        dirs.append((_HERE / _paths.DATADIR).resolve())
    repo = _HERE.parent.parent
    if (repo / "scenarios").is_dir():
        dirs.append(repo)
    return dirs
