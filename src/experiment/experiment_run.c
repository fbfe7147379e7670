/* experiment_run.c: a scenario run to rest, its metrics, and writing them. */
#include "footsim/experiment/fs_run.h"

#include "experiment_log.h"

#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"

#include <cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void name_columns(fs_run_result *res, const fs_foot_geom *g, int with_lean)
{
    static const char *fixed[] = {"t_s", "ankle_x_m", "ankle_y_m", "ankle_z_m", "contacts"};
    res->ncols = 0;
    for (int i = 0; i < 5; i++)
        res->col_name[res->ncols++] = fixed[i];
    for (int i = 0; i < g->nhinges; i++) {
        snprintf(res->hinge_col[i], sizeof res->hinge_col[i], "%s_rad", g->hinge[i].name);
        res->col_name[res->ncols++] = res->hinge_col[i];
    }
    for (int i = 0; i < g->nsprings; i++) {
        snprintf(res->spring_col[i], sizeof res->spring_col[i], "%s_N", g->spring[i].name);
        res->col_name[res->ncols++] = res->spring_col[i];
    }
    res->lean_col = with_lean ? res->ncols : 0;
    if (with_lean)
        res->col_name[res->ncols++] = "lean_deg";
}

/* sim's state now as a row of res's columns. */
static void fill_row(const fs_run_result *res, const fs_sim *sim, double *row)
{
    double p[3];
    fs_sim_ankle(sim, p);
    row[0] = fs_sim_time(sim);
    row[1] = p[0];
    row[2] = p[1];
    row[3] = p[2];
    row[4] = fs_sim_contact_count(sim);
    for (int i = 0; i < fs_sim_geom(sim)->nhinges; i++)
        row[5 + i] = fs_sim_hinge_angle(sim, i);
    for (int i = 0; i < fs_sim_geom(sim)->nsprings; i++)
        row[5 + fs_sim_geom(sim)->nhinges + i] = fs_sim_spring_state(sim, i).force_N;
    if (res->lean_col)
        row[res->lean_col] = fs_sim_robot_tilt(sim) * 180 / M_PI;
}

void fs_log_row(fs_run_result *res, const fs_sim *sim)
{
    if (res->nrows == res->capacity)
        return;
    fill_row(res, sim, res->rows + (size_t)res->nrows++ * res->ncols);
}

void fs_log_begin(fs_run_logger *l, fs_run_result *res, const fs_sim *sim)
{
    *l = (fs_run_logger){.res = res, .every = res ? res->every : 1, .timed = fs_sim_adaptive(sim),
                         .interval_s = fs_sim_scenario(sim)->def.log_interval_s};
    if (!res)
        return;
    fs_log_row(res, sim);
    fill_row(res, sim, l->prev);
}

/* The rows due between the last step's state (l->prev) and now's, each interpolated at its time. */
static void log_crossings(fs_run_logger *l, const fs_sim *sim)
{
    fs_run_result *res = l->res;
    double now[FS_TRAJ_MAX_COLS];
    fill_row(res, sim, now);
    double t;
    while (res->nrows < res->capacity && (t = (double)(l->logged + 1) * l->interval_s) <= now[0]) {
        double u = (t - l->prev[0]) / (now[0] - l->prev[0]);
        double *row = res->rows + (size_t)res->nrows++ * res->ncols;
        for (int c = 0; c < res->ncols; c++)
            row[c] = l->prev[c] + u * (now[c] - l->prev[c]);
        row[0] = t;
        row[4] = u < 0.5 ? l->prev[4] : now[4]; /* contacts: a count */
        l->logged++;
    }
    memcpy(l->prev, now, (size_t)res->ncols * sizeof now[0]);
}

void fs_log_last(fs_run_result *res, const fs_sim *sim)
{
    if (res->nrows == 0 || res->rows[(size_t)(res->nrows - 1) * res->ncols] != fs_sim_time(sim))
        fs_log_row(res, sim);
}

fs_status fs_log_open(fs_run_result *res, const fs_scenario *sc, int with_lean, fs_error *err)
{
    const fs_scenario_def *d = &sc->def;
    fs_foot_geom biped; /* the columns are the built geometry's hinges and springs (a biped's two feet and legs) */
    name_columns(res, fs_scenario_geometry(sc, &biped), with_lean);
    long nsteps = (long)ceil(d->duration_s / d->step_s - 1e-9);
    long every = lround(d->log_interval_s / d->step_s);
    if (every < 1)
        every = 1;
    /* the trajectory is kept in memory: bounded before the first step */
    double bytes = ((double)nsteps / every + 2) * res->ncols * sizeof *res->rows;
    if (nsteps > FS_MAX_STEPS || bytes > FS_TRAJ_MAX_BYTES)
        return fs_fail(err, FS_BAD_INPUT, "%s: duration_s / log_interval_s asks for %.3g trajectory rows (%.3g GB); "
                       "at most %.3g GB: a longer log_interval_s or a shorter duration_s", sc->path,
                       (double)nsteps / every + 2, bytes / 1e9, FS_TRAJ_MAX_BYTES / 1e9);
    res->capacity = (int)(nsteps / every + 2);
    res->every = every;
    res->rows = malloc((size_t)res->capacity * res->ncols * sizeof *res->rows);
    if (!res->rows)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for %d trajectory rows; a longer log_interval_s",
                       sc->path, res->capacity);
    return FS_OK;
}

/* The last logged time at which the ankle was farther than band from its final height. */
static double settle_time(const fs_run_result *res, double band)
{
    double zf = res->ankle_end_m[2], t = 0;
    for (int r = 0; r < res->nrows; r++) {
        const double *row = res->rows + (size_t)r * res->ncols;
        if (fabs(row[3] - zf) > band)
            t = row[0];
    }
    return t;
}

static void measure_end(fs_run_result *res, const fs_sim *sim)
{
    fs_sim_ankle(sim, res->ankle_end_m);
    res->end_time_s = fs_sim_time(sim);
    res->ankle_drop_m = res->ankle_start_m[2] - res->ankle_end_m[2];
    for (int i = 0; i < fs_sim_geom(sim)->nhinges; i++)
        res->hinge_angle_rad[i] = fs_sim_hinge_angle(sim, i);
    for (int i = 0; i < fs_sim_geom(sim)->nsprings; i++) {
        fs_spring_state st = fs_sim_spring_state(sim, i);
        res->spring_force_N[i] = st.force_N;
        res->spring_length_m[i] = st.length_m;
    }
    res->contacts_end = fs_sim_contact_count(sim);
    fs_sim_contact_totals(sim, &res->contacts_total, &res->collision_tests);
    res->energy_end_J = fs_sim_energy(sim, NULL, NULL, NULL);
}

int fs_log_after_step(void *user, fs_sim *sim)
{
    fs_run_logger *l = user;
    if (l->timed)
        log_crossings(l, sim);
    else if (++l->step % l->every == 0)
        fs_log_row(l->res, sim);
    return 0;
}

/* At rest once every body is slow for rest_hold_s, after the load has fully risen. */
typedef struct rest_rule {
    const fs_scenario_def *d;
    double since_s; /* when every body became slow, or -1 */
} rest_rule;

static int at_rest(void *user, fs_sim *sim)
{
    rest_rule *r = user;
    if (fs_sim_time(sim) >= r->d->ramp_s && fs_sim_max_speed(sim) < r->d->rest_speed_m_per_s) {
        if (r->since_s < 0)
            r->since_s = fs_sim_time(sim);
        return fs_sim_time(sim) - r->since_s >= r->d->rest_hold_s;
    }
    r->since_s = -1;
    return 0;
}

fs_status fs_run(const fs_scenario *sc, const fs_run_observer *obs, fs_run_result *res, fs_error *err)
{
    const fs_scenario_def *d = &sc->def;
    memset(res, 0, sizeof *res);
    long nsteps = (long)ceil(d->duration_s / d->step_s - 1e-9);
    fs_status opened = fs_log_open(res, sc, 0, err);
    if (opened != FS_OK)
        return opened;
    fs_sim_options opts = fs_observer_sim_options(obs);
    fs_sim *sim;
    fs_status s = fs_sim_new(sc, &opts, &sim, err);
    if (s != FS_OK)
        return s;
    fs_sim_ankle(sim, res->ankle_start_m);
    res->energy_start_J = fs_sim_energy(sim, NULL, NULL, NULL);
    fs_run_logger logger;
    fs_log_begin(&logger, res, sim);
    rest_rule rest = {d, -1};
    const fs_step_hook hooks[] = {{"logged", fs_log_after_step, &logger}, {"at rest", at_rest, &rest}};
    fs_drive_spec spec = {.max_steps = nsteps, .hooks = hooks, .nhooks = 2, .obs = obs};
    fs_drive_result r;
    s = fs_drive(sim, &spec, &r, err);
    res->steps = (int)r.steps;
    res->at_rest = r.stopped_by == 1;
    if (s == FS_OK) {
        fs_log_last(res, sim);
        measure_end(res, sim);
        res->settle_time_s = settle_time(res, d->settle_band_m);
    }
    fs_sim_free(sim);
    return s;
}

void fs_run_free(fs_run_result *res)
{
    free(res->rows);
    res->rows = NULL;
}

/* ---- output --------------------------------------------------------------------------------- */

static cJSON *vec3_json(const double v[3]) { return cJSON_CreateDoubleArray(v, 3); }

static cJSON *metrics_json(const fs_scenario *sc, const fs_run_result *res)
{
    const fs_foot_geom *g = &sc->geom;
    cJSON *root = cJSON_CreateObject();
    int ok = root != NULL;
    ok &= cJSON_AddStringToObject(root, "scenario", sc->name) != NULL;
    ok &= cJSON_AddStringToObject(root, "design", sc->def.design_path) != NULL;
    ok &= cJSON_AddStringToObject(root, "foot", g->kind == FS_FOOT_FLAT ? "flat" : "biomimetic") != NULL;
    ok &= cJSON_AddNumberToObject(root, "load_kg", sc->def.load_kg) != NULL;
    ok &= cJSON_AddNumberToObject(root, "tilt_deg", sc->def.tilt_deg) != NULL;
    ok &= cJSON_AddNumberToObject(root, "step_s", sc->def.step_s) != NULL;
    ok &= cJSON_AddStringToObject(root, "springs", sc->def.springs == 0 ? "implicit" : "explicit") != NULL;
    ok &= cJSON_AddNumberToObject(root, "steps", res->steps) != NULL;
    ok &= cJSON_AddNumberToObject(root, "end_time_s", res->end_time_s) != NULL;
    ok &= cJSON_AddBoolToObject(root, "at_rest", res->at_rest) != NULL;
    ok &= cJSON_AddNumberToObject(root, "ankle_drop_m", res->ankle_drop_m) != NULL;
    ok &= cJSON_AddNumberToObject(root, "settle_time_s", res->settle_time_s) != NULL;
    ok &= fs_json_put(root, "ankle_start_m", vec3_json(res->ankle_start_m));
    ok &= fs_json_put(root, "ankle_end_m", vec3_json(res->ankle_end_m));
    ok &= cJSON_AddNumberToObject(root, "contacts_end", res->contacts_end) != NULL;
    ok &= cJSON_AddNumberToObject(root, "contacts_total", (double)res->contacts_total) != NULL;
    ok &= cJSON_AddNumberToObject(root, "collision_tests", (double)res->collision_tests) != NULL;
    ok &= cJSON_AddNumberToObject(root, "energy_start_J", res->energy_start_J) != NULL;
    ok &= cJSON_AddNumberToObject(root, "energy_end_J", res->energy_end_J) != NULL;
    if (g->nhinges > 0)
        ok &= cJSON_AddNumberToObject(root, "ankle_joint_rad", res->hinge_angle_rad[0]) != NULL;
    cJSON *chains = cJSON_AddArrayToObject(root, "chains");
    ok &= chains != NULL;
    for (int i = 0; g->kind == FS_FOOT_BIOMIMETIC && i < FS_CHAINS; i++) {
        cJSON *c = cJSON_CreateObject();
        ok &= cJSON_AddNumberToObject(c, "chain", i + 1) != NULL;
        ok &= cJSON_AddNumberToObject(c, "midfoot_rad", res->hinge_angle_rad[g->chain[i].midfoot_hinge]) != NULL;
        ok &= cJSON_AddNumberToObject(c, "mtp_rad", res->hinge_angle_rad[g->chain[i].mtp_hinge]) != NULL;
        static const char *names[3] = {"d1_force_N", "d2_force_N", "d3_force_N"};
        for (int k = 0; k < 3; k++)
            ok &= cJSON_AddNumberToObject(c, names[k], res->spring_force_N[g->chain[i].spring[k]]) != NULL;
        ok &= fs_json_put(chains, NULL, c);
    }
    if (ok)
        return root;
    cJSON_Delete(root); /* a field could not be added (out of memory): no result rather than one short of it */
    return NULL;
}

static fs_status write_json(const char *path, cJSON *root, fs_error *err)
{
    char *text = cJSON_Print(root);
    if (!text)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", path);
    size_t n = strlen(text);
    text[n] = '\n'; /* replace the terminator: the file ends with a newline */
    fs_status s = fs_write_atomic(path, text, n + 1, err);
    free(text);
    return s;
}

static int fill_trajectory(FILE *f, const void *user)
{
    const fs_run_result *res = user;
    for (int c = 0; c < res->ncols; c++)
        fprintf(f, "%s%s", c ? "," : "", res->col_name[c]);
    fputc('\n', f);
    for (int r = 0; r < res->nrows; r++) {
        const double *row = res->rows + (size_t)r * res->ncols;
        for (int c = 0; c < res->ncols; c++)
            fprintf(f, c == 4 ? "%s%.0f" : "%s%.17g", c ? "," : "", row[c]);
        fputc('\n', f);
    }
    return 1;
}

fs_status fs_run_write_trajectory(const fs_run_result *res, const char *path, fs_error *err)
{
    return fs_write_file(path, fill_trajectory, res, err);
}

fs_status fs_run_write(const fs_scenario *sc, const fs_run_result *res, const fs_provenance *prov, const char *dir,
                       fs_error *err)
{
    fs_status s = fs_make_dirs(dir, err);
    if (s != FS_OK)
        return s;
    char path[4096];
    snprintf(path, sizeof path, "%s/trajectory.csv", dir);
    s = fs_run_write_trajectory(res, path, err);
    if (s != FS_OK)
        return s;
    snprintf(path, sizeof path, "%s/metrics.json", dir);
    cJSON *root = metrics_json(sc, res);
    if (root && prov && !fs_json_put(root, "provenance", fs_provenance_json(prov))) {
        cJSON_Delete(root); /* out of memory: no result rather than one without what made it */
        root = NULL;
    }
    if (!root)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", path);
    s = write_json(path, root, err);
    cJSON_Delete(root);
    return s;
}
