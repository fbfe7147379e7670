/* cli_run.c: `footsim run SCENARIO`: a scenario run until the foot is at rest, its metrics.json and
 * trajectory.csv in a results folder put in place whole, and its frames when asked. */
#include "cli.h"

#include "footsim/experiment/fs_run.h"
#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_ode.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* What a run works on, too large for the stack (a scenario, a results folder's paths): on the heap,
 * one per command (no state outlives it), freed on every path by its owner. */
typedef struct run_work {
    fs_scenario sc;
    fs_outdir out;
} run_work;

/* FOOTSIM_TEST_ODE_ERROR: what an ODE internal error does, inside ODE's guard as in a step. */
static fs_status ode_test_failure(void *arg, fs_error *err)
{
    (void)arg, (void)err;
    fs_ode_fail("FOOTSIM_TEST_ODE_ERROR");
    return FS_OK; /* not reached: the guard returns FS_NUMERICAL */
}

static int run_scenario(const cli_args *a, fs_run_result *res, run_work *w)
{
    fs_scenario *sc = &w->sc;
    fs_outdir *out = &w->out;
    fs_error err;
    if (fs_scenario_load(a->input, a->set, a->nset, sc, &err) != FS_OK || fs_scenario_require(sc, "run", &err) != FS_OK)
        return fail(&err);
    if (!a->frames && (a->fps || a->size || a->camera || a->exaggerate))
        fprintf(stderr, "footsim run: warning: %s is unused without --frames; add --frames to draw frames\n",
                a->fps ? "--fps" : a->size ? "--size" : a->camera ? "--camera" : "--exaggerate");
    char dir[FS_OUT_PATH];
    if (!a->out && (!strcmp(sc->name, ".") || !strcmp(sc->name, "..") || !sc->name[0]))
        return cli_report(FS_BAD_INPUT, "run: the scenario's name cannot name a results folder; give --out DIR");
    int bad = cli_results_dir(a, "runs", sc->name, dir, sizeof dir);
    if (bad)
        return bad;
    /* the folder must be one footsim may replace, and the frame options right, before anything is
     * simulated; everything goes to a partial folder beside it, swapped in whole at the end */
    if (fs_outdir_open(out, dir, a->replace, "--out", &err) != FS_OK)
        return fail(&err);
    cli_frames *frames = NULL;
    fs_run_observer observer, *obs = NULL;
    if (a->frames) {
        int fs = cli_frames_open(a, sc, out->partial, &frames, &observer);
        if (fs) {
            fs_outdir_abort(out);
            return fs;
        }
        obs = &observer;
    }
    fs_provenance prov; /* what made the results: the files, the --set, the settings */
    fs_status rs = fs_scenario_provenance(sc, a->set, a->nset, &prov, &err);
    if (rs == FS_OK && getenv("FOOTSIM_TEST_ODE_ERROR")) /* tests: an ODE internal error comes back as exit 3 */
        rs = fs_ode_guard(ode_test_failure, NULL, NULL, &err);
    if (rs == FS_OK)
        rs = fs_run(sc, obs, res, &err);
    int fstatus = frames ? cli_frames_close(frames, rs == FS_OK, out->path) : 0;
    if (rs == FS_OK && !fstatus && (rs = fs_run_write(sc, res, &prov, out->partial, &err)) == FS_OK)
        rs = fs_outdir_commit(out, &err);
    fs_provenance_free(&prov);
    if (rs != FS_OK || fstatus) {
        fs_outdir_abort(out);
        fs_run_free(res);
        return fstatus ? fstatus : fail(&err);
    }
    char settled[96];
    if (res->at_rest)
        snprintf(settled, sizeof settled, "settled after %.3f s (at rest at t = %.3f s)", res->settle_time_s,
                 res->end_time_s);
    else
        snprintf(settled, sizeof settled, "not at rest when the run stopped at t = %.3f s", res->end_time_s);
    /* the load: the scenario's, or for a landing trial run as a plain run its robot on the ankle */
    char load[160];
    if (sc->def.robot.mass_kg > 0)
        snprintf(load, sizeof load, "a %.1f kg robot on the ankle from the nominal pose (no drawn pose or landing "
                 "rules: `footsim trial` judges a landing)", sc->def.robot.mass_kg);
    else
        snprintf(load, sizeof load, "%.1f kg at %.0f deg", sc->def.load_kg, sc->def.tilt_deg);
    printf("%s: %s foot, %s: ankle drop %.3f mm, %s\n  results: %s/metrics.json, %s/trajectory.csv\n", sc->name,
           sc->geom.kind == FS_FOOT_FLAT ? "flat" : "biomimetic", load, res->ankle_drop_m * 1e3, settled, out->path,
           out->path);
    return 0;
}

/* One run of a (a scenario file, or footsim's own for demo), its work on the heap. */
int cli_run(const cli_args *a)
{
    run_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    fs_run_result res;
    memset(&res, 0, sizeof res); /* freed also when the run failed before it began */
    int s = run_scenario(a, &res, w);
    if (s == 0)
        fs_run_free(&res);
    fs_outdir_abort(&w->out); /* a no-op where run_scenario committed or gave it up */
    fs_scenario_free(&w->sc);
    free(w);
    return s;
}

