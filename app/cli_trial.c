/* cli_trial.c: `footsim trial SCENARIO`: one landing trial for a seed: its pose, outcome, rule and
 * metrics; with --out or --frames its folder (trial.json, trajectory.csv, frames), whole. */
#include "cli.h"

#include "footsim/campaign/fs_report.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

typedef struct trial_job {
    const fs_scenario *sc;
    int seed;
    fs_trial_result *r;
    fs_run_result *log; /* the trial's time series, for trajectory.csv */
    cli_surface *surface; /* the soil's surface at the end, for surface.* */
    const fs_provenance *prov;
} trial_job;

static fs_status run_trial_job(void *user, const fs_run_observer *obs, fs_error *err)
{
    trial_job *t = user;
    return fs_trial_run_logged(t->sc, t->seed, cli_surface_observer(t->surface, obs), t->log, t->r, err);
}

static fs_status write_trial_log(void *user, const char *dir, fs_error *err)
{
    const trial_job *t = user;
    char path[FS_OUT_PATH + 32];
    snprintf(path, sizeof path, "%s/trajectory.csv", dir);
    fs_status s = fs_run_write_trajectory(t->log, path, err);
    return s == FS_OK ? (fs_status)cli_surface_write(t->surface, dir, t->prov, err) : s;
}

static cJSON *trial_json_of(const void *r, fs_error *err) { return fs_trial_json(r, err); }

/* A trial's frames say its seed, and the last its outcome and the rule that decided it. */
static void trial_frame_label(const void *user, const void *result, int ended, char *label, size_t size)
{
    const trial_job *t = user;
    const fs_trial_result *r = result;
    if (ended)
        snprintf(label, size, "SEED %d  %s (%s)", t->seed, fs_outcome_name(r->outcome), fs_rule_name(r->rule));
    else
        snprintf(label, size, "SEED %d", t->seed);
}

/* A trial with a folder of its own (--out, or --frames: default results/trials/NAME-seedN/):
 * trial.json, its time series trajectory.csv (footsim plot draws it) and the frames, swapped in
 * whole at the end. The frames are framed on the pose the
 * seed draws. */
/* What a trial with a folder works on, too large for the stack: on the heap, one per command. */
typedef struct trial_files {
    fs_scenario base, placed;
    fs_outdir out;
    fs_run_result log;
    cli_surface surface;
} trial_files;

static int trial_work(const cli_args *a, int seed, fs_trial_result *r, char *dir_out, size_t size, trial_files *w)
{
    fs_scenario *base = &w->base, *placed = &w->placed;
    fs_error err;
    if (fs_scenario_load(a->input, a->set, a->nset, base, &err) != FS_OK || fs_scenario_require(base, "trial", &err) != FS_OK)
        return fail(&err);
    char dir[FS_OUT_PATH], name[FS_NAME_MAX + 16];
    snprintf(name, sizeof name, "%s-seed%d", base->name, seed); /* room for both */
    int s = cli_results_dir(a, "trials", name, dir, sizeof dir);
    if (a->frames && (fs_scenario_copy(placed, base, &err) != FS_OK || fs_trial_place(placed, seed, NULL, &err) != FS_OK))
        s = fail(&err);
    fs_provenance prov = {.ninputs = 0}; /* what made the result: the files, the --set, the settings, the seed */
    if (!s && fs_scenario_provenance(base, a->set, a->nset, &prov, &err) != FS_OK)
        s = fail(&err);
    prov.first_seed = seed, prov.nseeds = 1;
    trial_job t = {base, seed, r, &w->log, &w->surface, &prov};
    cli_folder_job j = {dir, placed, run_trial_job, &t, "trial.json", trial_json_of, r, &prov,
                    write_trial_log, trial_frame_label};
    if (!s)
        s = cli_in_folder(a, &j, &w->out, dir_out, size);
    fs_provenance_free(&prov);
    return s; /* the scenarios and the folder are the caller's to free */
}

static int trial_in_folder(const cli_args *a, int seed, fs_trial_result *r, char *dir_out, size_t size, int *surface)
{
    trial_files *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    int s = trial_work(a, seed, r, dir_out, size, w);
    *surface = w->surface.s.nx > 0;
    cli_surface_free(&w->surface);
    fs_outdir_abort(&w->out); /* each is a no-op where trial_work did it already */
    fs_scenario_free(&w->base);
    fs_scenario_free(&w->placed);
    fs_run_free(&w->log);
    free(w);
    return s;
}

int cli_trial(const cli_args *a)
{
    char *end;
    long seed = a->seed ? strtol(a->seed, &end, 10) : 1;
    if (a->seed && (*end || end == a->seed || seed < 0 || seed > 2147483647L))
        return cli_report(FS_BAD_INPUT, "--seed: give a whole number from 0 to 2147483647");
    fs_trial_result r;
    fs_error err;
    char dir[FS_OUT_PATH] = "";
    int surface = 0;
    if (a->frames || a->out) {
        int s = trial_in_folder(a, (int)seed, &r, dir, sizeof dir, &surface);
        if (s)
            return s;
    } else if (fs_trial_run(a->input, a->set, a->nset, (int)seed, NULL, &r, &err) != FS_OK) {
        return fail(&err);
    }
    if (a->json) {
        cJSON *o = fs_trial_json(&r, &err);
        int s = o ? cli_print_json(o) : fail(&err);
        cJSON_Delete(o);
        if (s)
            return s;
    } else {
        char rest[64];
        if (r.rule == FS_RULE_AT_REST || r.rule == FS_RULE_RESTED_TILTED)
            snprintf(rest, sizeof rest, "at rest %.3f s after touchdown", r.settle_time_s);
        else
            snprintf(rest, sizeof rest, "not at rest at the end");
        printf("%s, seed %ld: %s (%s)%s%s\n  robot %.1f kg on the foot; start x %.4f m, y %.4f m, yaw %.1f deg, pitch %.2f "
               "deg, roll %.2f deg\n"
               "  touchdown %.3f s, end %.3f s; lean peak %.1f deg, final %.1f deg; peak force %.0f N, impulse %.2f N s\n"
               "  %s; contacts mean %.1f, final %.0f; ankle drop %.2f mm, slip %.2f mm\n",
               a->input, seed, fs_outcome_name(r.outcome), fs_rule_name(r.rule), r.failure[0] ? ": " : "", r.failure,
               r.robot_mass_kg, r.draw.x_m, r.draw.y_m, r.draw.yaw_deg, r.draw.pitch_deg, r.draw.roll_deg, r.touchdown_s,
               r.end_time_s, r.peak_tilt_deg, r.final_tilt_deg, r.peak_force_N, r.impact_impulse_Ns, rest,
               r.mean_contacts, r.final_contacts, r.ankle_drop_m * 1e3, r.slip_m * 1e3);
        if (r.rejected_steps > 0 || r.step_least_s != r.step_largest_s)
            printf("  %ld steps (%ld rejected, %ld ODE steps), least %.3g s, median %.3g s, largest %.3g s\n", r.steps,
                   r.rejected_steps, r.ode_steps, r.step_least_s, r.step_median_s, r.step_largest_s);
        for (int f = 0; r.nfeet > 1 && f < r.nfeet; f++)
            printf("  %s foot: touchdown %.3f s; contacts mean %.1f, final %.0f; ankle drop %.2f mm, slip %.2f mm; "
                   "ground force at the end %.0f N\n", f ? "left" : "right", r.foot[f].touchdown_s, r.foot[f].mean_contacts,
                   r.foot[f].final_contacts, r.foot[f].ankle_drop_m * 1e3, r.foot[f].slip_m * 1e3, r.foot[f].final_force_N);
        if (dir[0])
            printf("  results: %s/trial.json, %s/trajectory.csv%s%s\n", dir, dir,
                   surface ? ", the soil's final surface in surface.png, .csv and .ini" : "", a->frames ? ", frames/" : "");
    }
    return r.outcome == FS_FAILED_NUMERICS ? FS_NUMERICAL : 0;
}

