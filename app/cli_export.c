/* cli_export.c: footsim export --mjcf DESIGN [--scenario S]: the foot as MuJoCo MJCF (fs_export.h). */
#include "cli.h"

#include "footsim/base/fs_path.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/io/fs_output.h"
#include "footsim/export/fs_export.h"

#include <errno.h>
#include <stdio.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

/* What an export works on, too large for the stack: on the heap, one per command. */
typedef struct export_work {
    fs_scenario sc;
    char design[PATH_MAX + 32], full[PATH_MAX]; /* realpath fills up to PATH_MAX */
} export_work;

static int export_mjcf(const cli_args *a, export_work *w)
{
    fs_scenario *sc = &w->sc;
    char *design = w->design, *full = w->full;
    fs_error err;
    fs_status s;
    if (a->scenario) {
        /* the scenario with DESIGN as its foot: DESIGN first among the overrides, so --set still wins */
        const char *over[CLI_MAX_SET + 1];
        /* a scenario's paths are relative to its folder: give DESIGN's whole path */
        if (!realpath(a->input, full)) {
            fprintf(stderr, "footsim: export: %s: %s; give an existing design file\n", a->input, strerror(errno));
            return FS_BAD_INPUT;
        }
        if (fs_path_format(design, sizeof w->design, a->input, &err, "scenario.design=%s", full) != FS_OK)
            return cli_report(err.status, err.message);
        over[0] = design;
        for (int i = 0; i < a->nset; i++)
            over[i + 1] = a->set[i];
        s = fs_scenario_load(a->scenario, over, a->nset + 1, sc, &err);
    } else {
        s = fs_scenario_for_design(a->input, a->set, a->nset, sc, &err);
    }
    if (s != FS_OK)
        return cli_report(err.status, err.message);
    /* --seed N: a landing trial's start as that trial draws it (pose, and a random terrain's seed) */
    long seed = -1;
    if (a->seed) {
        char *end;
        seed = strtol(a->seed, &end, 10);
        if (!a->scenario || *end || end == a->seed || seed < 0 || seed > 2147483647L) {
            fs_scenario_free(sc);
            return cli_report(FS_BAD_INPUT, a->scenario ? "--seed: give a whole number from 0 to 2147483647"
                                                        : "--seed: give a trial scenario with --scenario too");
        }
        if ((s = fs_scenario_require(sc, "trial", &err)) != FS_OK || (s = fs_trial_place(sc, (int)seed, NULL, &err)) != FS_OK) {
            fs_scenario_free(sc);
            return cli_report(err.status, err.message);
        }
    }
    char out[FS_OUT_PATH];
    if (a->out) {
        if (fs_path_format(out, sizeof out, "--out", &err, "%s", a->out) != FS_OK) {
            fs_scenario_free(sc);
            return cli_report(err.status, err.message);
        }
    } else {
        char stem[FS_NAME_MAX];
        fs_path_stem(a->input, stem, sizeof stem);
        if (fs_make_dirs("results/export", &err) != FS_OK) {
            fs_scenario_free(sc);
            return cli_report(err.status, err.message);
        }
        char tail[32] = "";
        if (seed >= 0)
            snprintf(tail, sizeof tail, "-seed%ld", seed);
        snprintf(out, sizeof out, "results/export/%s%s%s%s.xml", stem, a->scenario ? "-" : "", a->scenario ? sc->name : "", tail);
    }
    /* an existing file is replaced only when footsim exported it (its first bytes), or --replace */
    static const char mjcf_signature[] = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- footsim export";
    s = fs_check_file_target(out, "--out", (const unsigned char *)mjcf_signature, sizeof mjcf_signature - 1,
                             "an MJCF file footsim exported", a->replace, &err);
    if (s != FS_OK) {
        fs_scenario_free(sc);
        return cli_report(err.status, err.message);
    }
    s = fs_mjcf_write(sc, a->scenario != NULL, out, &err);
    int hfield = a->scenario && fs_terrain_is_heightfield(&sc->terrain), cables = 0;
    for (int k = 0; k < 3; k++)
        cables += sc->design.tension_only[k];
    fs_scenario_free(sc);
    if (s != FS_OK)
        return cli_report(err.status, err.message);
    char hpath[FS_OUT_PATH];
    fs_mjcf_hfield_path(out, hpath, sizeof hpath);
    printf("wrote %s%s%s (MuJoCo MJCF; docs/export.md says what maps one to one)\n", out, hfield ? " and " : "",
           hfield ? hpath : "");
    if (cables) /* a cable maps in kind, not in stiffness (docs/export.md, Spring laws) */
        printf("note: %d spring kind%s a cable, exported as a one-sided tendon limit at its rest length; MuJoCo "
               "sets a limit's stiffness per unit of the mass its constraint moves, so its force is not k x (2.9 "
               "times k x in test_export_mujoco); the linear springs map exactly\n",
               cables, cables > 1 ? "s are" : " is");
    return 0;
}

int cli_export(const cli_args *a)
{
    if (!a->mjcf)
        return cli_report(FS_BAD_INPUT, "export: give the format, --mjcf (MuJoCo's MJCF, the one written so far)");
    export_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    int s = export_mjcf(a, w);
    fs_scenario_free(&w->sc); /* a no-op where export_mjcf freed it */
    free(w);
    return s;
}
