/* cli_walk.c: `footsim walk SCENARIO`: the walking machine: steps, falls, contacts on and off the rough
 * section; with --out or --frames its folder (walk.json, frames), whole. */
#include "cli.h"

#include "footsim/campaign/fs_report.h"
#include "footsim/experiment/fs_walk.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

static cJSON *walk_json_of(const void *r, fs_error *err) { return fs_walk_json(r, NULL, err); }

typedef struct walk_job {
    const fs_scenario *sc;
    fs_walk_result *r;
    cli_surface *surface; /* the soil's surface at the end, for surface.* */
    const fs_provenance *prov;
} walk_job;

static fs_status run_walk_job(void *user, const fs_run_observer *obs, fs_error *err)
{
    walk_job *w = user;
    return fs_walk_run(w->sc, cli_surface_observer(w->surface, obs), w->r, err);
}

static fs_status write_walk_surface(void *user, const char *dir, fs_error *err)
{
    const walk_job *w = user;
    return (fs_status)cli_surface_write(w->surface, dir, w->prov, err);
}

/* What a walk works on, too large for the stack: on the heap, one per command. */
typedef struct walk_work {
    fs_scenario sc;
    fs_outdir out;
    cli_surface surface;
} walk_work;

int cli_walk(const cli_args *a)
{
    walk_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    fs_scenario *sc = &w->sc;
    fs_error err;
    fs_walk_result r;
    char dir[FS_OUT_PATH], shown[FS_OUT_PATH] = "";
    int s = 0;
    if (fs_scenario_load(a->input, a->set, a->nset, sc, &err) != FS_OK || fs_scenario_require(sc, "walk", &err) != FS_OK)
        s = fail(&err);
    const char *foot = sc->geom.kind == FS_FOOT_FLAT ? "flat" : "biomimetic";
    if (!s && (a->frames || a->out)) {
        /* a folder of its own (default results/walks/NAME/): walk.json and the frames, whole */
        s = cli_results_dir(a, "walks", sc->name, dir, sizeof dir);
        fs_provenance prov = {.ninputs = 0}; /* what made the result: the files, the --set, the settings */
        walk_job job = {sc, &r, &w->surface, &prov};
        if (!s && fs_scenario_provenance(sc, a->set, a->nset, &prov, &err) != FS_OK)
            s = fail(&err);
        cli_folder_job j = {dir, sc, run_walk_job, &job, "walk.json", walk_json_of, &r, &prov, write_walk_surface, NULL};
        if (!s)
            s = cli_in_folder(a, &j, &w->out, shown, sizeof shown);
        fs_provenance_free(&prov);
    } else if (!s && fs_walk_run(sc, NULL, &r, &err) != FS_OK) {
        s = fail(&err);
    }
    fs_outdir_abort(&w->out); /* a no-op where in_folder did it already */
    int surface = w->surface.s.nx > 0;
    cli_surface_free(&w->surface);
    fs_scenario_free(sc);
    free(w);
    if (s)
        return s;
    if (a->json) {
        cJSON *o = fs_walk_json(&r, foot, &err);
        s = o ? cli_print_json(o) : fail(&err);
        cJSON_Delete(o);
        if (s)
            return s;
    } else {
        printf("%s: %s foot: %d steps completed, %d falls; contact points at mid-stance %.1f on the rough "
               "section (%d steps), %.1f off it; peak ground force %.0f N; ankle tilt up to %.1f deg\n",
               a->input, foot, r.steps_completed, r.falls, r.rough_contacts_mean, r.rough_steps, r.flat_contacts_mean,
               r.peak_force_N, r.peak_tilt_deg);
        /* each step's record, labelled by where its stance was: over the soil, or on the rigid ground
           beyond a soil section (fs_walk_step.on_soil) */
        for (int i = 0; r.soil && i < r.nsteps; i++)
            printf("  step %d %s: sinkage %.2f mm at the stance's end, slip %.2f mm (ankle), %.2f mm (soil "
                   "under the foot), the soil took %.3f J; pressed %.2f mm past press_m, ground force %.0f N\n", i + 1,
                   r.step[i].on_soil ? "on the soil" : "on rigid ground", r.step[i].sinkage_m * 1e3,
                   r.step[i].slip_m * 1e3, r.step[i].soil_slip_m * 1e3, r.step[i].soil_work_J,
                   r.step[i].extra_press_m * 1e3, r.step[i].load_N);
        if (shown[0])
            printf("  results: %s/walk.json%s%s\n", shown,
                   surface ? ", the soil's final surface in surface.png, .csv and .ini" : "", a->frames ? ", frames/" : "");
    }
    return 0;
}

