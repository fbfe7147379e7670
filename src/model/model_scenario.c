/* model_scenario.c: the scenario schema and loading a scenario with its design. */
#include "footsim/model/fs_scenario.h"

#include "footsim/base/fs_path.h"

#include <limits.h>
#include <math.h>
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
    {"scenario", "terrain", FS_KEY_PATH, F(terrain_path), 0, 0, 0, 0, NULL, "", "",
     "terrain file, relative to the scenario's folder; none: a flat plane of default material"},
    {"scenario", "kind", FS_KEY_CHOICE, F(kind), 0, 0, 0, 0, "experiment|walk", "", "experiment",
     "experiment: run, trial and campaign use it; walk: the walking machine (footsim walk)"},
    NUM("start", "x_m", start_x_m, -100, 100, 0, "m", "0", "where the foot's heel contact starts"),
    NUM("start", "y_m", start_y_m, -100, 100, 0, "m", "0", "where the foot's heel contact starts"),
    NUM("start", "yaw_deg", yaw_deg, -180, 180, 0, "deg", "0", "the foot turned about z"),
    NUM("start", "pitch_deg", pitch_deg, -45, 45, 0, "deg", "0", "the foot pitched, toe down positive"),
    NUM("start", "roll_deg", roll_deg, -45, 45, 0, "deg", "0", "the foot rolled about x, left side up positive"),
    NUM("start", "drop_m", drop_m, 0, 10, 0, "m", "0", "gap between the foot's lowest point and the highest terrain under it"),
    NUM("start", "region_margin_m", region_margin_m, 0, 10, 0, "m", "0.05", "the heightfield covers the footprint plus this margin"),
    NUM("load", "mass_kg", load_kg, 0, 1e4, 0, "kg", "26", "mass whose weight acts vertically at the ankle (Table I)"),
    NUM("load", "tilt_deg", tilt_deg, -45, 45, 0, "deg", "0", "the foot tilted against the load: load and gravity turned about the lateral axis"),
    NUM("load", "ramp_s", ramp_s, 0, 100, 0, "s", "0.02", "the load rises linearly over this time"),
    NUM("run", "duration_s", duration_s, 0, 1e5, POS, "s", "1.0", "longest simulated time"),
    NUM("run", "step_s", step_s, FS_STEP_MIN_S, FS_STEP_MAX_S, 0, "s", "1e-4", "integration step"),
    {"run", "impact_substeps", FS_KEY_INTEGER, F(impact_substeps), 1, 1000, 0, 0, NULL, "", "1",
     "1: off; else a step around a touchdown is taken as this many equal substeps (contacts, springs and checks "
     "at the substep), so that a large step_s still resolves the impact (docs/bench.md)"},
    NUM("run", "impact_window_s", impact_window_s, 0, 10, 0, "s", "0.03",
        "with impact_substeps: substeps from the step in which a foot shape without contact could reach the ground "
        "within the step and this long (or first touches it) until this long after"),
    NUM("run", "tolerance_m", tolerance_m, 0, 1, 0, "m", "0",
        "0: fixed steps of step_s; > 0: an error-controlled step, which keeps each step's local error (step doubling: "
        "how far any body's point ends apart after one step and after two half steps) below this, the step "
        "varying from step_min_s to step_max_s (docs/bench.md, \"An error-controlled step\")"),
    NUM("run", "step_max_s", step_max_s, FS_STEP_MIN_S, FS_STEP_MAX_S, 0, "s", "1e-2",
        "with tolerance_m: the largest step (a pair of half steps)"),
    NUM("run", "step_min_s", step_min_s, FS_STEP_MIN_S, FS_STEP_MAX_S, 0, "s", "1e-5",
        "with tolerance_m: the least ODE step (half the least pair); a step that misses the tolerance at it is kept "
        "and counted"),
    {"run", "error_estimate", FS_KEY_CHOICE, F(error_estimate), 0, 0, 0, 0, "doubling|embedded", "", "doubling",
     "with tolerance_m: doubling: each step taken whole and as two half steps, their ends compared (3 ODE steps a "
     "step); embedded: one ODE step, its error from each body's change of velocity over it (ODE's semi-implicit "
     "Euler against the explicit Euler step it embeds) and that change's own change since the last step "
     "(docs/bench.md)"},
    {"run", "stepper", FS_KEY_CHOICE, F(stepper), 0, 0, 0, 0, "step|quickstep", "", "step",
     "step: dWorldStep (direct); quickstep: dWorldQuickStep (iterative)"},
    {"run", "iterations", FS_KEY_INTEGER, F(iterations), 1, 10000, 0, 0, NULL, "", "50", "dWorldQuickStep iterations"},
    {"run", "springs", FS_KEY_CHOICE, F(springs), 0, 0, 0, 0, "implicit|explicit", "", "implicit",
     "spring-damper implementation: implicit (soft DBall rows) or explicit (forces)"},
    {"run", "damping_correction", FS_KEY_INTEGER, F(damping_correction), 0, 1, 0, 0, NULL, "", "1",
     "1: an implicit spring-damper's damping (tendons, contacts, hinge springs) is its c whatever the step, where "
     "k step_s <= c; 0: plain implicit Euler, which damps by c + k step_s (docs/model.md)"},
    NUM("run", "gravity_m_per_s2", gravity_m_per_s2, 0, 100, 0, "m/s^2", "9.81", "gravitational acceleration"),
    NUM("run", "log_interval_s", log_interval_s, 0, 10, POS, "s", "1e-3", "time between trajectory rows"),
    NUM("run", "rest_speed_m_per_s", rest_speed_m_per_s, 0, 10, 0, "m/s", "1e-4", "the run stops once every body is slower than this ..."),
    NUM("run", "rest_hold_s", rest_hold_s, 0, 100, 0, "s", "0.05", "... for this long after the load has risen"),
    NUM("run", "settle_band_m", settle_band_m, 0, 1, POS, "m", "1e-5", "settled once the ankle stays this close to its final height"),
    NUM("run", "joint_erp", joint_erp, 0, 1, 0, "", "0.2", "error reduction of ODE's hinges and contacts' defaults"),
    NUM("run", "joint_cfm", joint_cfm, 0, 1, 0, "", "1e-10", "constraint force mixing of ODE's hinges"),
    NUM("run", "contact_layer_m", contact_layer_m, 0, 1e-3, 0, "m",
        "1e-9", "depth ODE lets contacts sink before pushing back; keeps stiff contacts from chattering on and off"),
    {"run", "tile_cells", FS_KEY_INTEGER, F(tile_cells), 2, 4096, 0, 0, NULL, "", "8",
     "a heightfield is built as square tiles of this many cells a side (speed only)"},
    {"robot", "design", FS_KEY_PATH, F(robot_path), 0, 0, 0, 0, NULL, "", "",
     "the robot's file (scenarios/robots/*.ini, keys below under Robot files), relative to the scenario's folder; "
     "none: no robot"},
    NUM("landing", "x_range_m", land_x_range_m, 0, 10, 0, "m", "0.01", "landing position drawn within +- this of start.x_m"),
    NUM("landing", "y_range_m", land_y_range_m, 0, 10, 0, "m", "0.01", "landing position drawn within +- this of start.y_m"),
    NUM("landing", "yaw_range_deg", land_yaw_range_deg, 0, 180, 0, "deg", "10", "yaw drawn within +- this"),
    NUM("landing", "tilt_range_deg", land_tilt_range_deg, 0, 45, 0, "deg", "2", "pitch and roll each drawn within +- this"),
    NUM("landing", "landed_tilt_deg", landed_tilt_deg, 0, 90, POS, "deg", "15", "landed: upright means leaning less than this (docs/landing.md)"),
    NUM("landing", "fall_tilt_deg", fall_tilt_deg, 0, 180, POS, "deg", "45", "fell: the lean passed this (the trial stops)"),
    NUM("landing", "lost_ground_s", lost_ground_s, 0, 100, POS, "s", "0.25",
        "fell: after touchdown the foot had no contact for this long (a 0.25 s flight is a 77 mm hop)"),
    NUM("landing", "motion_window_s", motion_window_s, 0, 100, POS, "s", "0.5",
        "landed at the end of the window: the mean kinetic energy over its last this-long span ..."),
    NUM("landing", "motion_decay", motion_decay, 0, 1, POS, "", "0.9",
        "... is at most this times the mean over the span before (the motion is dying out)"),
    NUM("landing", "impulse_window_s", impulse_window_s, 0, 10, POS, "s", "0.05",
        "the impact impulse is the most momentum the ground takes out of the fall within this long after touchdown "
        "(docs/landing.md)"),
    {"walk", "steps", FS_KEY_INTEGER, F(walk_steps), 1, 1000, 0, 0, NULL, "", "8", "walking machine: steps to take"},
    NUM("walk", "step_length_m", step_length_m, 0, 10, POS, "m", "0.06", "forward travel of the foot each step"),
    NUM("walk", "period_s", walk_period_s, 0, 100, POS, "s", "1.0", "one step: stance then swing"),
    NUM("walk", "stance_fraction", stance_fraction, 0, 1, POS, "", "0.6", "share of the period the foot stands (60 % in human gait)"),
    NUM("walk", "lift_m", lift_m, 0, 1, POS, "m", "0.02", "the actuator lifts the foot this high in swing"),
    NUM("walk", "press_m", press_m, 0, 1, 0, "m", "0.004", "and lowers the carriage this far below first contact in stance"),
    NUM("walk", "suspension_k_N_per_m", suspension_k_N_per_m, 0, 1e9, POS, "N/m", "3e4", "the leg's suspension to the carriage"),
    NUM("walk", "suspension_c_Ns_per_m", suspension_c_Ns_per_m, 0, 1e7, 0, "N s/m", "1000", "its damping"),
    NUM("walk", "fall_tilt_deg", walk_fall_tilt_deg, 0, 180, POS, "deg", "30", "a step fails when the ankle body tilts more than this"),
    {"run", "max_contacts", FS_KEY_INTEGER, F(max_contacts), 1, FS_MAX_SHAPE_CONTACTS, 0, 0, NULL, "", "64",
     "contact points kept per foot shape against the terrain (after merging duplicates)"},
    NUM("check", "max_speed_m_per_s", check_max_speed_m_per_s, 0, 1e6, POS, "m/s", "100",
        "blown up: any point of a body faster than this (a 10 m fall lands at 14 m/s)"),
    NUM("check", "max_loop_error_m", check_max_loop_error_m, 0, 1, POS, "m", "1e-3",
        "drifting: a hinge's two anchors this far apart (the shortest link is 15 mm)"),
    NUM("check", "energy_margin_J", check_energy_margin_J, 0, 1e9, POS, "J", "1",
        "drifting: energy above its start plus the load's and drivers' work by more than this ..."),
    NUM("check", "energy_margin_rel", check_energy_margin_rel, 0, 10, 0, "", "0.1",
        "... plus this fraction of the work put in (docs/bench.md derives both)"),
    {"check", "energy_every", FS_KEY_INTEGER, F(check_energy_every), 1, 1000000, 0, 0, NULL, "", "1",
     "the energy check runs every this many steps (the other checks every step)"},
    {"run", "collide", FS_KEY_CHOICE, F(collide_all), 0, 0, 0, 0, "ground|all", "", "ground",
     "ground: each foot shape against the terrain only; all: every pair of shapes, foot against foot too "
     "(slower; what footsim bench speed compares)"},
    {"run", "heightfield_contacts", FS_KEY_CHOICE, F(heightfield_ode), 0, 0, 0, 0, "footsim|ode", "", "footsim",
     "a foot shape against a heightfield: footsim's own tests (a sole's corners, edges and the lattice's vertices "
     "inside it, a few a face and an edge; a sphere's nearest points, one a face, edge or corner it rests on: "
     "docs/model.md) or ODE's, with every vertex inside a box added (slower)"},
    NUM("run", "auto_disable_s", auto_disable_s, 0, 100, 0, "s", "0",
        "0: off; else ODE stops stepping a body slower than rest_speed_m_per_s (turning slower than that "
        "over 1 cm) for this long"),
    NUM("run", "min_inertia_kg_m2", min_inertia_kg_m2, 0, 1e-2, 0, "kg m^2", "0",
        "0: off; else each foot body's inertia tensor I becomes I + d 1, d = max(0, this - I's smallest principal "
        "moment): no moment below this, none raised by more; masses kept (for QuickStep's mass ratio: docs/bench.md)"),
};
const int fs_scenario_nkeys = (int)(sizeof fs_scenario_keys / sizeof fs_scenario_keys[0]);

static int has_section(const fs_key *keys, int n, const char *assignment)
{
    const char *dot = strchr(assignment, '.');
    size_t len = dot ? (size_t)(dot - assignment) : strlen(assignment);
    for (int i = 0; i < n; i++)
        if (strlen(keys[i].section) == len && !strncmp(keys[i].section, assignment, len))
            return 1;
    return 0;
}

/* Which of the four files an override belongs to: 0 scenario, 1 terrain, 2 design, 3 robot. */
static int override_target(const char *assignment)
{
    if (!strncmp(assignment, "robot.", 6))
        return strncmp(assignment + 6, "design", 6) || (assignment[12] != '=' && assignment[12] != 0) ? 3 : 0;
    if (has_section(fs_scenario_keys, fs_scenario_nkeys, assignment))
        return 0;
    return has_section(fs_terrain_keys, fs_terrain_nkeys, assignment) ? 1 : 2;
}

/* Samples the terrain over the region the foot can reach. A heightmap the foot never reaches would
 * give flat-ground results without a word: refused. One that covers only part of the foot's region
 * is warned about (fs_warn) when `warn` (a scenario read from its file, not each trial's copy). */
static fs_status crop_terrain(fs_scenario *sc, int warn, fs_error *err)
{
    double box[4];
    fs_scenario_reach(sc, box);
    double m = sc->def.region_margin_m;
    const fs_terrain *t = &sc->terrain;
    double e[4], outside = fs_terrain_outside(t, box, e);
    if (outside > 0 && (box[1] < e[0] || box[0] > e[1] || box[3] < e[2] || box[2] > e[3]))
        return fs_fail(err, FS_BAD_INPUT, "%s: the heightmap covers x %.4g..%.4g m, y %.4g..%.4g m, and the foot "
                       "(x %.3g..%.3g m, y %.3g..%.3g m) is off it: the run would be on flat ground; move the "
                       "heightmap (x0_m, y0_m) or the foot (start.x_m, y_m)", t->path, e[0], e[1], e[2], e[3], box[0],
                       box[1], box[2], box[3]);
    if (warn && outside > 0)
        fs_warn("%s: the heightmap covers x %.4g..%.4g m, y %.4g..%.4g m (%s); %.0f %% of the "
                "foot's region (x %.3g..%.3g m, y %.3g..%.3g m) is outside it, where the ground only draws out the "
                "image's edge; move the heightmap (x0_m, y0_m) or the foot (start.x_m, y_m) to keep the foot on the "
                "data", t->path, e[0], e[1], e[2], e[3], t->placed_at, fmax(1, round(outside * 100)), box[0], box[1],
                box[2], box[3]);
    fs_status s = fs_terrain_crop(&sc->terrain, box[0] - m, box[1] + m, box[2] - m, box[3] + m, err);
    if (s == FS_OK && sc->terrain.def.soil.model != FS_SOIL_NONE) /* the soil's grid over the same region */
        s = fs_soil_region(&sc->terrain.def.soil, box,
                           sc->terrain.soil_grid_at[0] ? sc->terrain.soil_grid_at : sc->terrain.path,
                           sc->terrain.soil_region, NULL, err);
    if (s == FS_OK && sc->terrain.def.soil.model != FS_SOIL_NONE) /* a section the feet never reach: refused */
        s = fs_soil_section_check(&sc->terrain.def.soil, sc->terrain.soil_region,
                                  t->def.kind == FS_TERRAIN_HEIGHTMAP ? e : NULL,
                                  sc->terrain.soil_section_at[0] ? sc->terrain.soil_section_at : sc->terrain.path, err);
    return s;
}

/* Relations between the scenario's keys that no single key can judge, checked where the file is
 * read (cfg, for file:line) and again when a definition edited in code is compiled (cfg NULL): an
 * unset log interval follows the step; the walking machine's phases each last a step; a run's
 * length in steps is bounded before anything is built (counters and buffers are sized by it). */
static fs_status check_relations(fs_scenario *sc, const fs_config *cfg, fs_error *err)
{
    fs_scenario_def *d = &sc->def;
    char where[FS_PATH_MAX + 80], where_step[FS_PATH_MAX + 80];
    if (sc->log_interval_default_s > 0 && d->log_interval_s == sc->log_interval_followed_s)
        d->log_interval_s = fmax(sc->log_interval_default_s, d->step_s); /* not set (in the file or since) */
    sc->log_interval_followed_s = d->log_interval_s;
    if (d->log_interval_s < d->step_s)
        return fs_fail(err, FS_BAD_INPUT, "%s: log_interval_s = %g is shorter than step_s = %g (from %s); make it at "
                       "least one step", fs_config_where(cfg, "run", "log_interval_s", where, sizeof where),
                       d->log_interval_s, d->step_s, fs_config_where(cfg, "run", "step_s", where_step, sizeof where_step));
    if (d->tolerance_m > 0) {
        const char *why = d->impact_substeps > 1 ? "impact_substeps is the fixed step's way to resolve a touchdown"
                          : d->auto_disable_s > 0 ? "ODE's auto-disable keeps a state a rejected step cannot restore"
                          : d->step_min_s * 2 > d->step_max_s ? "step_min_s must be at most half step_max_s"
                                                               : NULL;
        if (why)
            return fs_fail(err, FS_BAD_INPUT, "%s: tolerance_m = %g cannot be used here: %s; give tolerance_m = 0 "
                           "(fixed steps) or change that setting", fs_config_where(cfg, "run", "tolerance_m", where,
                           sizeof where), d->tolerance_m, why);
    }
    int walk = d->kind == FS_SCENARIO_WALK;
    if (walk) {
        double stance = d->walk_period_s * d->stance_fraction, swing = d->walk_period_s - stance;
        if (stance < d->step_s || (swing > 0 && swing < d->step_s))
            return fs_fail(err, FS_BAD_INPUT, "%s: period_s = %g gives a stance of %g s and a swing of %g s, one "
                           "shorter than step_s = %g; make each phase at least one step",
                           fs_config_where(cfg, "walk", "period_s", where, sizeof where), d->walk_period_s, stance,
                           swing, d->step_s);
    }
    double steps = (walk ? d->walk_steps * d->walk_period_s : d->duration_s) / d->step_s;
    if (steps > FS_MAX_STEPS)
        return fs_fail(err, FS_BAD_INPUT, "%s: %s / step_s = %.4g steps; a run may take at most %.0e: %s, or a longer "
                       "step_s", fs_config_where(cfg, walk ? "walk" : "run", walk ? "period_s" : "duration_s", where,
                                                 sizeof where),
                       walk ? "steps x period_s" : "duration_s", steps, (double)FS_MAX_STEPS,
                       walk ? "fewer or shorter steps" : "a shorter duration_s");
    return FS_OK;
}

fs_status fs_scenario_load(const char *path, const char *const *overrides, int noverrides, fs_scenario *sc,
                           fs_error *err)
{
    enum { MAX_OVERRIDES = 256 };
    if (noverrides > MAX_OVERRIDES)
        return fs_fail(err, FS_BAD_INPUT, "--set: at most %d overrides", MAX_OVERRIDES);
    const char *part[4][MAX_OVERRIDES];
    int n[4] = {0, 0, 0, 0};
    for (int i = 0; i < noverrides; i++) {
        int t = override_target(overrides[i]);
        part[t][n[t]++] = overrides[i];
    }
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", path);
    fs_path_stem(path, sc->name, sizeof sc->name);
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    for (int i = 0; s == FS_OK && i < n[0]; i++)
        s = fs_config_override(&cfg, part[0][i], err);
    for (int i = 0; s == FS_OK && i < fs_robot_nkeys; i++)
        if (fs_config_has(&cfg, "robot", fs_robot_keys[i].name)) { /* the inline keys of before robot files */
            char where[FS_PATH_MAX + 80];
            s = fs_fail(err, FS_BAD_INPUT, "%s: '%s' is a key of a robot file, not of a scenario: put the robot's keys "
                        "in a file (as scenarios/robots/single_tall.ini) and name it here with `design = "
                        "robots/NAME.ini`", fs_config_where(&cfg, "robot", fs_robot_keys[i].name, where, sizeof where),
                        fs_robot_keys[i].name);
        }
    if (s == FS_OK)
        s = fs_config_bind(&cfg, fs_scenario_keys, fs_scenario_nkeys, &sc->def, err);
    if (s == FS_OK && !fs_config_has(&cfg, "run", "log_interval_s"))
        sc->log_interval_default_s = sc->log_interval_followed_s = sc->def.log_interval_s;
    /* which command the file is for: a landing trial has a [robot] or [landing] section */
    sc->is_trial = fs_config_has(&cfg, "robot", NULL) || fs_config_has(&cfg, "landing", NULL);
    if (s == FS_OK)
        s = check_relations(sc, &cfg, err);
    char robot_where[FS_PATH_MAX + 80] = "";
    if (s == FS_OK)
        fs_config_where(&cfg, "robot", "design", robot_where, sizeof robot_where);
    if (s == FS_OK)
        s = fs_robot_load(sc->def.robot_path, part[3], n[3], &sc->def.robot, err);
    if (s == FS_OK && sc->def.kind == FS_SCENARIO_WALK && sc->def.robot.kind == FS_ROBOT_BIPED)
        s = fs_fail(err, FS_BAD_INPUT, "%s: %s is a biped, and the walking machine carries one body on one foot: "
                    "name a single robot (robots/single_tall_achilles.ini)", robot_where, sc->def.robot_path);
    sc->is_trial |= sc->def.robot.mass_kg > 0; /* a robot given by --set alone */
    if (s == FS_OK)
        s = fs_design_load_located(sc->def.design_path, part[2], n[2], &sc->design, &sc->geom, sc->law_where, err);
    if (s == FS_OK)
        s = fs_terrain_load(sc->def.terrain_path, part[1], n[1], &sc->terrain, err);
    if (s == FS_OK && sc->terrain.def.soil.model != FS_SOIL_NONE) /* the relations a soil adds, with file:line */
        s = check_relations(sc, &cfg, err);
    fs_config_free(&cfg);
    if (s == FS_OK)
        s = crop_terrain(sc, 1, err);
    return s;
}

fs_status fs_scenario_require(const fs_scenario *sc, const char *command, fs_error *err)
{
    /* what the file is for: walk (kind = walk), trial ([robot] or [landing]), else run */
    const char *is = sc->def.kind == FS_SCENARIO_WALK ? "walk" : sc->is_trial ? "trial" : "run";
    int ok = !strcmp(command, is) || (!strcmp(command, "run") && !strcmp(is, "trial"));
    if (ok && !strcmp(command, "trial") && sc->def.robot.mass_kg <= 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: a landing trial drops a robot and this scenario has none (mass 0): name "
                       "one in [robot] with design = robots/single_tall.ini (or drop_weight, rig)", sc->path);
    if (ok)
        return FS_OK;
    static const char *what[] = {"a walking-machine scenario ([scenario] kind = walk)",
                                 "a landing trial ([robot] or [landing])", "a run scenario (no [robot] or [landing])"};
    int k = !strcmp(is, "walk") ? 0 : !strcmp(is, "trial") ? 1 : 2;
    return fs_fail(err, FS_BAD_INPUT, "%s: is %s; `footsim %s` does not take it: use `footsim %s %s`", sc->path, what[k],
                   command, is, sc->path);
}

void fs_scenario_free(fs_scenario *sc) { fs_terrain_free(&sc->terrain); }

fs_status fs_scenario_copy(fs_scenario *dst, const fs_scenario *src, fs_error *err)
{
    *dst = *src;
    return fs_terrain_copy(&dst->terrain, &src->terrain, err);
}

fs_status fs_scenario_compile(fs_scenario *sc, fs_error *err)
{
    char what[FS_PATH_MAX + 32];
    snprintf(what, sizeof what, "%s, edited in code", sc->path);
    fs_status s = fs_config_check(fs_scenario_keys, fs_scenario_nkeys, &sc->def, what, err);
    if (s == FS_OK)
        s = fs_config_check(fs_design_keys, fs_design_nkeys, &sc->design, what, err);
    if (s == FS_OK)
        s = fs_config_check(fs_terrain_keys, fs_terrain_nkeys, &sc->terrain.def, what, err);
    if (s == FS_OK)
        s = fs_config_check(fs_robot_keys, fs_robot_nkeys, &sc->def.robot, what, err);
    if (s == FS_OK)
        fs_robot_derive(&sc->def.robot);
    if (s == FS_OK)
        s = check_relations(sc, NULL, err);
    if (s == FS_OK)
        s = fs_design_geometry(&sc->design, NULL, &sc->geom, err);
    if (s == FS_OK)
        s = fs_terrain_redraw(&sc->terrain, err);
    sc->is_trial |= sc->def.robot.mass_kg > 0;
    return s == FS_OK ? crop_terrain(sc, 0, err) : s;
}

fs_status fs_scenario_inputs(const fs_scenario *sc, fs_provenance *p, fs_error *err)
{
    fs_status s = fs_provenance_add_ini(p, sc->path, err);
    if (s == FS_OK)
        s = fs_provenance_add_ini(p, sc->def.design_path, err);
    if (s == FS_OK)
        s = fs_provenance_add_ini(p, sc->def.terrain_path, err);
    if (s == FS_OK && sc->terrain.def.kind == FS_TERRAIN_HEIGHTMAP)
        s = fs_provenance_add_data(p, sc->terrain.def.heightmap_path, err);
    if (s == FS_OK)
        s = fs_provenance_add_ini(p, sc->def.robot_path, err);
    return s;
}

fs_status fs_scenario_provenance(const fs_scenario *sc, const char *const *overrides, int noverrides,
                                 fs_provenance *p, fs_error *err)
{
    fs_status s = fs_provenance_init(p, sc->path, err);
    if (s == FS_OK)
        s = fs_provenance_overrides(p, overrides, noverrides, err);
    if (s == FS_OK)
        s = fs_scenario_inputs(sc, p, err);
    fs_scenario_settings(sc, p->settings, sizeof p->settings);
    return s;
}

void fs_scenario_settings(const fs_scenario *sc, char *buf, size_t size)
{
    const fs_scenario_def *d = &sc->def;
    snprintf(buf, size, "step_s %.6g, stepper %s, iterations %d, springs %s, contact_layer_m %.6g, window %.6g s",
             d->step_s, d->stepper ? "quickstep" : "step", d->iterations, d->springs ? "explicit" : "implicit",
             d->contact_layer_m, d->duration_s);
    size_t used = strlen(buf);
    if (d->min_inertia_kg_m2 > 0 && used < size) /* said only when on: results made without it read as before */
        snprintf(buf + used, size - used, ", min_inertia_kg_m2 %.6g", d->min_inertia_kg_m2);
    used = strlen(buf);
    if (!d->damping_correction && used < size) /* the same */
        snprintf(buf + used, size - used, ", damping_correction 0");
    used = strlen(buf);
    if (d->tolerance_m > 0 && used < size) /* the same */
        snprintf(buf + used, size - used, ", tolerance_m %.6g, step_max_s %.6g, step_min_s %.6g%s", d->tolerance_m,
                 d->step_max_s, d->step_min_s, d->error_estimate == FS_ESTIMATE_EMBEDDED ? ", error_estimate embedded" : "");
    used = strlen(buf);
    if (d->impact_substeps > 1 && used < size) /* the same */
        snprintf(buf + used, size - used, ", impact_substeps %d, impact_window_s %.6g", d->impact_substeps,
                 d->impact_window_s);
}

const fs_foot_geom *fs_scenario_geometry(const fs_scenario *sc, fs_foot_geom *biped)
{
    if (sc->def.robot.kind != FS_ROBOT_BIPED || sc->def.robot.mass_kg <= 0)
        return &sc->geom;
    fs_robot_biped_geometry(&sc->def.robot, &sc->geom, biped);
    return biped;
}

void fs_scenario_reach(const fs_scenario *sc, double box[4])
{
    fs_scenario_footprint(sc, box);
    if (sc->def.kind == FS_SCENARIO_WALK) /* the walking machine's path */
        box[1] += sc->def.walk_steps * sc->def.step_length_m;
}

void fs_scenario_footprint(const fs_scenario *sc, double box[4])
{
    fs_foot_geom biped; /* a biped's two feet */
    const fs_foot_geom *g = fs_scenario_geometry(sc, &biped);
    double yaw = sc->def.yaw_deg * M_PI / 180, c = cos(yaw), s = sin(yaw);
    box[0] = box[2] = INFINITY;
    box[1] = box[3] = -INFINITY;
    /* every contact shape's extent, turned by the yaw and moved to the start */
    for (int i = 0; i < g->nspheres + 4 * g->nboxes; i++) {
        double x, y, r;
        if (i < g->nspheres) {
            x = g->sphere[i].centre.x;
            y = g->sphere[i].centre.y;
            r = g->sphere[i].radius_m;
        } else {
            int k = (i - g->nspheres) % 4;
            fs_vec3 c = g->box[(i - g->nspheres) / 4].centre;
            x = c.x + ((k & 1) ? 0.5 : -0.5) * g->box_size.x;
            y = c.y + ((k & 2) ? 0.5 : -0.5) * g->box_size.y;
            r = 0;
        }
        double wx = sc->def.start_x_m + c * x - s * y, wy = sc->def.start_y_m + s * x + c * y;
        box[0] = fmin(box[0], wx - r);
        box[1] = fmax(box[1], wx + r);
        box[2] = fmin(box[2], wy - r);
        box[3] = fmax(box[3], wy + r);
    }
}

fs_status fs_scenario_for_design(const char *design_path, const char *const *overrides, int noverrides,
                                 fs_scenario *sc, fs_error *err)
{
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", design_path);
    fs_path_stem(design_path, sc->name, sizeof sc->name);
    fs_config empty = {.path = "(scenario defaults)"};
    /* Every key but the design path (the first) takes its default: a flat plane of default material. */
    fs_status s = fs_config_bind(&empty, fs_scenario_keys + 1, fs_scenario_nkeys - 1, &sc->def, err);
    if (s == FS_OK)
        s = fs_terrain_load("", NULL, 0, &sc->terrain, err);
    if (s == FS_OK) /* the log interval, not given, follows the step */
        sc->log_interval_default_s = sc->log_interval_followed_s = sc->def.log_interval_s;
    if (s == FS_OK)
        s = check_relations(sc, NULL, err);
    if (s != FS_OK)
        return s;
    snprintf(sc->def.design_path, sizeof sc->def.design_path, "%s", design_path);
    return fs_design_load_located(design_path, overrides, noverrides, &sc->design, &sc->geom, sc->law_where, err);
}

const fs_key *fs_scenario_key(const char *name, int integers, int *element)
{
    const fs_key *schema[4] = {fs_scenario_keys, fs_design_keys, fs_robot_keys, fs_terrain_keys};
    const int nkeys[4] = {fs_scenario_nkeys, fs_design_nkeys, fs_robot_nkeys, fs_terrain_nkeys};
    const char *dot = strchr(name, '.');
    *element = -1;
    if (!dot)
        return NULL;
    size_t len = (size_t)(dot - name), nlen = strlen(dot + 1);
    const char *bracket = strchr(dot + 1, '[');
    if (bracket)
        nlen = (size_t)(bracket - dot - 1);
    for (int s = 0; s < 4; s++)
        for (int i = 0; i < nkeys[s]; i++) {
            const fs_key *k = &schema[s][i];
            if (strlen(k->section) != len || strncmp(k->section, name, len) || strlen(k->name) != nlen ||
                strncmp(k->name, dot + 1, nlen))
                continue;
            if (bracket && k->type == FS_KEY_LIST) {
                *element = fs_list_element(bracket, k->count);
                return *element >= 0 ? k : NULL;
            }
            if (!bracket && (k->type == FS_KEY_NUMBER || (integers && k->type == FS_KEY_INTEGER)))
                return k;
        }
    return NULL;
}

/* The field of sc's definitions that the number key "section.key" (or list element
 * "section.key[i]") sets, with its schema entry; NULL when no schema has it. */
static void *number_field(fs_scenario *sc, const char *name, int integers, const fs_key **key)
{
    const fs_key *schema[4] = {fs_scenario_keys, fs_design_keys, fs_robot_keys, fs_terrain_keys};
    const int nkeys[4] = {fs_scenario_nkeys, fs_design_nkeys, fs_robot_nkeys, fs_terrain_nkeys};
    char *def[4] = {(char *)&sc->def, (char *)&sc->design, (char *)&sc->def.robot, (char *)&sc->terrain.def};
    int element;
    const fs_key *k = fs_scenario_key(name, integers, &element);
    for (int s = 0; k && s < 4; s++)
        if (k >= schema[s] && k < schema[s] + nkeys[s]) {
            if (key)
                *key = k;
            return def[s] + k->offset + (element >= 0 ? (size_t)element * sizeof(double) : 0);
        }
    return NULL;
}

double *fs_scenario_number(fs_scenario *sc, const char *name, const fs_key **key)
{
    return number_field(sc, name, 0, key);
}

fs_status fs_scenario_set(fs_scenario *sc, const char *name, double value, fs_error *err)
{
    const fs_key *k;
    void *field = number_field(sc, name, 1, &k);
    if (!field)
        return fs_fail(err, FS_BAD_INPUT, "%s: %s is not a number of a scenario, design, robot or terrain file", sc->path,
                       name);
    if (k->type != FS_KEY_INTEGER) { /* a number, or a list's element */
        *(double *)field = value;
        if (field == &sc->def.log_interval_s) /* set, as by --set: it no longer follows the step */
            sc->log_interval_default_s = 0;
        return FS_OK;
    }
    if (!(value == floor(value) && fabs(value) <= INT_MAX))
        return fs_fail(err, FS_BAD_INPUT, "%s: [%s] %s = %.17g is not a whole number; give an integer", sc->path,
                       k->section, k->name, value);
    *(int *)field = (int)value;
    return FS_OK;
}
