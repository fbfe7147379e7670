/* model_scenario.c: the scenario schema and loading a scenario with its design. */
#include "footsim/fs_scenario.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define F(member) offsetof(fs_scenario_def, member)
#define NUM(sec, name, member, lo, hi, flags, unit, dflt, help) \
    {sec, name, FS_KEY_NUMBER, F(member), lo, hi, flags, 0, NULL, unit, dflt, help}
#define POS FS_KEY_OPEN_MIN

const fs_key fs_scenario_keys[] = {
    {"scenario", "design", FS_KEY_PATH, F(design_path), 0, 0, 0, 0, NULL, "", "feet/biomimetic.ini",
     "design file, relative to the scenario's folder"},
    NUM("ground", "mu", ground_mu, 0, 10, 0, "", "1.0", "friction coefficient of the ground (combined with the sole's as sqrt(mu_sole mu_ground))"),
    NUM("ground", "stiffness_N_per_m", ground_stiffness_N_per_m, 0, 1e12, POS, "N/m", "1e8",
        "ground contact stiffness (in series with the sole's)"),
    NUM("ground", "damping_Ns_per_m", ground_damping_Ns_per_m, 0, 1e9, 0, "N s/m", "2e4", "ground contact damping (in series with the sole's)"),
    NUM("load", "mass_kg", load_kg, 0, 1e4, 0, "kg", "26", "mass whose weight acts vertically at the ankle (Table I)"),
    NUM("load", "tilt_deg", tilt_deg, -45, 45, 0, "deg", "0", "the foot tilted against the load: load and gravity turned about the lateral axis"),
    NUM("load", "ramp_s", ramp_s, 0, 100, 0, "s", "0.02", "the load rises linearly over this time"),
    NUM("run", "duration_s", duration_s, 0, 1e5, POS, "s", "1.0", "longest simulated time"),
    NUM("run", "step_s", step_s, 1e-7, 0.1, 0, "s", "1e-4", "integration step"),
    {"run", "stepper", FS_KEY_CHOICE, F(stepper), 0, 0, 0, 0, "step|quickstep", "", "step",
     "step: dWorldStep (direct); quickstep: dWorldQuickStep (iterative)"},
    {"run", "iterations", FS_KEY_INTEGER, F(iterations), 1, 10000, 0, 0, NULL, "", "50", "dWorldQuickStep iterations"},
    {"run", "springs", FS_KEY_CHOICE, F(springs), 0, 0, 0, 0, "implicit|explicit", "", "implicit",
     "spring-damper implementation: implicit (soft DBall rows) or explicit (forces)"},
    NUM("run", "gravity_m_per_s2", gravity_m_per_s2, 0, 100, 0, "m/s^2", "9.81", "gravitational acceleration"),
    NUM("run", "log_interval_s", log_interval_s, 0, 10, POS, "s", "1e-3", "time between trajectory rows"),
    NUM("run", "rest_speed_m_per_s", rest_speed_m_per_s, 0, 10, 0, "m/s", "1e-4", "the run stops once every body is slower than this ..."),
    NUM("run", "rest_hold_s", rest_hold_s, 0, 100, 0, "s", "0.05", "... for this long after the load has risen"),
    NUM("run", "settle_band_m", settle_band_m, 0, 1, POS, "m", "1e-5", "settled once the ankle stays this close to its final height"),
    NUM("run", "joint_erp", joint_erp, 0, 1, 0, "", "0.2", "error reduction of ODE's hinges and contacts' defaults"),
    NUM("run", "joint_cfm", joint_cfm, 0, 1, 0, "", "1e-10", "constraint force mixing of ODE's hinges"),
    NUM("run", "contact_layer_m", contact_layer_m, 0, 1e-3, 0, "m",
        "1e-9", "depth ODE lets contacts sink before pushing back; keeps stiff contacts from chattering on and off"),
    {"run", "max_contacts", FS_KEY_INTEGER, F(max_contacts), 1, 64, 0, 0, NULL, "", "4", "contact points per foot shape against the ground"},
};
const int fs_scenario_nkeys = (int)(sizeof fs_scenario_keys / sizeof fs_scenario_keys[0]);

static int scenario_has_section(const char *assignment)
{
    const char *dot = strchr(assignment, '.');
    size_t n = dot ? (size_t)(dot - assignment) : strlen(assignment);
    for (int i = 0; i < fs_scenario_nkeys; i++)
        if (strlen(fs_scenario_keys[i].section) == n && !strncmp(fs_scenario_keys[i].section, assignment, n))
            return 1;
    return 0;
}

void fs_split_overrides(const char *const *overrides, int n, const char **scen, int *nscen, const char **design,
                        int *ndesign)
{
    *nscen = *ndesign = 0;
    for (int i = 0; i < n; i++) {
        if (scenario_has_section(overrides[i]))
            scen[(*nscen)++] = overrides[i];
        else
            design[(*ndesign)++] = overrides[i];
    }
}

static void base_name(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (n >= size)
        n = size - 1;
    memcpy(out, base, n);
    out[n] = 0;
}

fs_status fs_scenario_load(const char *path, const char *const *overrides, int noverrides, fs_scenario *sc,
                           fs_error *err)
{
    enum { MAX_OVERRIDES = 256 };
    if (noverrides > MAX_OVERRIDES)
        return fs_fail(err, FS_BAD_INPUT, "--set: at most %d overrides", MAX_OVERRIDES);
    const char *scen[MAX_OVERRIDES], *design[MAX_OVERRIDES];
    int nscen, ndesign;
    fs_split_overrides(overrides, noverrides, scen, &nscen, design, &ndesign);
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", path);
    base_name(path, sc->name, sizeof sc->name);
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    for (int i = 0; s == FS_OK && i < nscen; i++)
        s = fs_config_override(&cfg, scen[i], err);
    if (s == FS_OK)
        s = fs_config_bind(&cfg, fs_scenario_keys, fs_scenario_nkeys, &sc->def, err);
    if (s == FS_OK && sc->def.log_interval_s < sc->def.step_s) {
        char where[FS_PATH_MAX + 80];
        s = fs_fail(err, FS_BAD_INPUT, "%s: log_interval_s = %g is shorter than step_s = %g; make it at least one step",
                    fs_config_where(&cfg, "run", "log_interval_s", where, sizeof where), sc->def.log_interval_s,
                    sc->def.step_s);
    }
    fs_config_free(&cfg);
    if (s == FS_OK)
        s = fs_design_load(sc->def.design_path, design, ndesign, &sc->design, &sc->geom, err);
    return s;
}

fs_status fs_scenario_for_design(const char *design_path, const char *const *overrides, int noverrides,
                                 fs_scenario *sc, fs_error *err)
{
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", design_path);
    base_name(design_path, sc->name, sizeof sc->name);
    fs_config empty = {.path = "(scenario defaults)"};
    /* Every key but the design path (the first) takes its default. */
    fs_status s = fs_config_bind(&empty, fs_scenario_keys + 1, fs_scenario_nkeys - 1, &sc->def, err);
    if (s != FS_OK)
        return s;
    snprintf(sc->def.design_path, sizeof sc->def.design_path, "%s", design_path);
    return fs_design_load(design_path, overrides, noverrides, &sc->design, &sc->geom, err);
}
