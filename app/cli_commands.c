/* cli_commands.c: the footsim subcommands. */
#include "cli.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/experiment/fs_walk.h"
#include "footsim/sim/fs_ode.h"
#include "footsim/sim/fs_sim.h"

#include "footsim/base/fs_path.h"

#include <cJSON.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The stiffness model and ODE must agree this closely (issue 2's acceptance bound). */
static const double STIFFNESS_TOLERANCE = 0.01;

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* ---- run -------------------------------------------------------------------------------------- */

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
static int run_once(const cli_args *a)
{
    run_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    fs_run_result res;
    int s = run_scenario(a, &res, w);
    if (s == 0)
        fs_run_free(&res);
    fs_outdir_abort(&w->out); /* a no-op where run_scenario committed or gave it up */
    fs_scenario_free(&w->sc);
    free(w);
    return s;
}

int cli_run(const cli_args *a) { return run_once(a); }

/* ---- model ------------------------------------------------------------------------------------ */

static int print_json(cJSON *root) { return fs_json_print(stdout, root) ? 0 : cli_report(FS_NO_MEMORY, "out of memory"); }

/* Runs a command that reads a design (model, stiffness) on its scenario (fs_scenario_for_design),
 * which lives on the heap for the command and is freed on every path. */
static int with_design(const cli_args *a, int (*command)(const cli_args *a, const fs_scenario *sc))
{
    fs_scenario *sc = cli_zalloc(sizeof *sc);
    if (!sc)
        return FS_NO_MEMORY;
    fs_error err;
    int s = fs_scenario_for_design(a->input, a->set, a->nset, sc, &err) != FS_OK ? fail(&err) : command(a, sc);
    fs_scenario_free(sc);
    free(sc);
    return s;
}

static int model_of(const cli_args *a, const fs_scenario *sc)
{
    fs_error err;
    cJSON *root = fs_model_json(sc, &err);
    if (!root)
        return fail(&err);
    int s = 0;
    if (a->json) {
        s = print_json(root);
    } else {
        const fs_foot_geom *g = &sc->geom;
        printf("%s: %s foot, %d bodies, %d hinges, %d springs, %d contact shapes, %.3f kg\n", a->input,
               g->kind == FS_FOOT_FLAT ? "flat" : "biomimetic", g->nbodies, g->nhinges, g->nsprings,
               g->nspheres + g->nboxes, g->total_mass_kg);
        printf("ankle at (%.4f, %.4f, %.4f) m\n", g->ankle.x, g->ankle.y, g->ankle.z);
        for (int i = 0; i < g->nbodies; i++)
            printf("  body %-12s %.4f kg at (%.4f, %.4f, %.4f) m\n", g->body[i].name, g->body[i].mass_kg,
                   g->body[i].com.x, g->body[i].com.y, g->body[i].com.z);
        printf("'footsim model %s --json' gives every number.\n", a->input);
    }
    cJSON_Delete(root);
    return s;
}

int cli_model(const cli_args *a) { return with_design(a, model_of); }

/* ---- stiffness -------------------------------------------------------------------------------- */

static cJSON *mat_json(const double m[2][2])
{
    cJSON *rows = cJSON_CreateArray();
    for (int r = 0; r < 2; r++)
        cJSON_AddItemToArray(rows, cJSON_CreateDoubleArray(m[r], 2));
    return rows;
}

static void print_mat_row(const char *label, const double m[2][2])
{
    printf("    %-22s [%9.4f %9.4f; %9.4f %9.4f]\n", label, m[0][0], m[0][1], m[1][0], m[1][1]);
}

/* ---- the pitch-stiffness law ---------------------------------------------------------------- */

enum { MAX_ROBOTS = 16 };
/* The lean a landing counts as upright below ([landing] landed_tilt_deg's default). */
static const double LAW_LEAN_DEG = 15;

/* The whole foot's pitch stiffness and, for each shipped robot, what the law says. */
typedef struct pitch_report {
    double load_kg, K_model, K_ode_mu1, K_ode_grip;
    double K_ode_plane;           /* gripping in each chain's plane, free across: the model's contacts */
    int flat;                     /* a flat sole: the model is its contacts' springs */
    int nrobots;
    char robot[MAX_ROBOTS][FS_NAME_MAX];
    fs_robot_def def[MAX_ROBOTS];
    fs_pitch_law law[MAX_ROBOTS];
} pitch_report;

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The names of the .ini files in dir (at most MAX_ROBOTS, malloc'd), sorted; how many. */
static int robot_files(const char *dir, char **names)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) && n < MAX_ROBOTS;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".ini"))
            names[n++] = strdup(e->d_name);
    }
    if (d)
        closedir(d);
    qsort(names, (size_t)n, sizeof names[0], by_name);
    return n;
}

/* The robot files beside the design's folder (scenarios/robots/ for scenarios/feet/X.ini); for a
 * design elsewhere (a folder with no ../robots/ of .ini files), the shipped robots (cli_data_robots:
 * --data, here, the installed data). */
static void shipped_robots(const char *design, double K, double g, pitch_report *p, fs_error *err)
{
    char dir[FS_OUT_PATH];
    const char *slash = strrchr(design, '/');
    char *names[MAX_ROBOTS];
    int n = 0;
    if (fs_path_format(dir, sizeof dir, "", NULL, "%.*s../robots", slash ? (int)(slash + 1 - design) : 0, design) == FS_OK)
        n = robot_files(dir, names);
    if (!n && cli_data_robots(dir, sizeof dir))
        n = robot_files(dir, names);
    for (int i = 0; i < n; i++) {
        char path[FS_OUT_PATH];
        if (names[i] && fs_path_format(path, sizeof path, "", NULL, "%s/%s", dir, names[i]) == FS_OK &&
            fs_robot_load(path, NULL, 0, &p->def[p->nrobots], err) == FS_OK) {
            fs_path_stem(path, p->robot[p->nrobots], FS_NAME_MAX);
            fs_pitch_law_apply(K, &p->def[p->nrobots], g, LAW_LEAN_DEG * M_PI / 180, &p->law[p->nrobots]);
            p->nrobots++;
        }
        free(names[i]);
    }
}

static fs_status pitch_stiffness(const fs_scenario *sc, const char *design, pitch_report *p, fs_error *err)
{
    memset(p, 0, sizeof *p);
    double g = sc->def.gravity_m_per_s2, load_N = sc->design.design_load_kg * g;
    p->load_kg = sc->design.design_load_kg;
    p->flat = sc->geom.kind == FS_FOOT_FLAT;
    fs_status s = fs_pitch_stiffness_foot(sc, load_N, &p->K_model, err);
    if (s == FS_OK)
        s = fs_pitch_stiffness_measure(sc, load_N, 1, 0, p->K_model, &p->K_ode_mu1, err);
    if (s == FS_OK)
        s = fs_pitch_stiffness_measure(sc, load_N, 10, 0, p->K_model, &p->K_ode_grip, err);
    if (s == FS_OK && !p->flat)
        s = fs_pitch_stiffness_measure(sc, load_N, 10, 1, p->K_model, &p->K_ode_plane, err);
    if (s == FS_OK) {
        fs_error ignored;
        shipped_robots(design, p->K_model, g, p, &ignored);
    }
    return s;
}

static void pitch_print(const pitch_report *p)
{
    printf("whole foot against pitching its ankle body under %.1f kg at the ankle (docs/landing.md), N m/rad:\n"
           "  model: %-46s %8.2f\n"
           "  measured in ODE, friction 1 (the landing trials')     %8.2f (%+.2f %%)\n"
           "  %-53s %8.2f\n",
           p->load_kg,
           p->flat ? "the sole's corners on the contacts' springs" : "each chain rolls in its plane, free across it",
           p->K_model, p->K_ode_mu1, 100 * (p->K_ode_mu1 / p->K_model - 1),
           p->flat ? "measured in ODE, friction 10" : "measured in ODE, friction 10 (toes held across too)", p->K_ode_grip);
    if (!p->flat)
        printf("  %-53s %8.2f (%+.2f %%)\n", "measured in ODE, the model's contacts (grip in plane)", p->K_ode_plane,
               100 * (p->K_ode_plane / p->K_model - 1));
    if (p->nrobots)
        printf("the law, K (the model's, an Achilles tendon in series) against m g h of each robot:\n");
    for (int i = 0; i < p->nrobots; i++) {
        const fs_pitch_law *l = &p->law[i];
        if (l->held)
            printf("  %-22s %5.1f kg: pitch held by its slide; stands\n", p->robot[i], p->def[i].mass_kg);
        else {
            char lean[48] = "no rest: too high";
            if (isfinite(l->lean_rad))
                snprintf(lean, sizeof lean, "lean at rest %.1f deg", l->lean_rad * 180 / M_PI);
            printf("  %-22s %5.1f kg, centre of mass %.3f m up, %.3f m ahead: needs %6.2f, has %6.2f; critical height "
                   "%.3f m; %s: %s\n",
                   p->robot[i], p->def[i].mass_kg, p->def[i].com_height_m, p->def[i].com_forward_m, l->demand, l->K,
                   l->critical_height_m, lean, l->stands ? "stands" : "topples");
        }
    }
}

static void pitch_json(cJSON *root, const pitch_report *p)
{
    cJSON *o = cJSON_AddObjectToObject(root, "pitch_stiffness");
    cJSON_AddNumberToObject(o, "load_kg", p->load_kg);
    cJSON_AddStringToObject(o, "model", p->flat ? "flat sole on its contacts" : "chains rolling in their planes");
    cJSON_AddNumberToObject(o, "model_N_m_per_rad", p->K_model);
    cJSON_AddNumberToObject(o, "ode_mu1_N_m_per_rad", p->K_ode_mu1);
    cJSON_AddNumberToObject(o, "ode_mu10_N_m_per_rad", p->K_ode_grip);
    if (!p->flat)
        cJSON_AddNumberToObject(o, "ode_in_plane_N_m_per_rad", p->K_ode_plane);
    cJSON *robots = cJSON_AddArrayToObject(o, "robots");
    for (int i = 0; i < p->nrobots; i++) {
        cJSON *r = cJSON_CreateObject();
        cJSON_AddStringToObject(r, "robot", p->robot[i]);
        cJSON_AddNumberToObject(r, "mass_kg", p->def[i].mass_kg);
        cJSON_AddNumberToObject(r, "com_height_m", p->def[i].com_height_m);
        cJSON_AddBoolToObject(r, "pitch_held", p->law[i].held);
        cJSON_AddNumberToObject(r, "K_N_m_per_rad", p->law[i].K);
        cJSON_AddNumberToObject(r, "demand_N_m_per_rad", p->law[i].demand);
        cJSON_AddNumberToObject(r, "critical_com_height_m", p->law[i].critical_height_m);
        cJSON_AddNumberToObject(r, "lean_at_rest_rad", p->law[i].lean_rad);
        cJSON_AddBoolToObject(r, "stands", p->law[i].stands);
        cJSON_AddItemToArray(robots, r);
    }
}

/* A flat sole has no joints or arch: only its pitch stiffness, which its contacts give. */
static int flat_stiffness(const cli_args *a, const fs_scenario *sc)
{
    pitch_report pitch;
    fs_error err;
    if (pitch_stiffness(sc, a->input, &pitch, &err) != FS_OK)
        return fail(&err);
    if (a->json) {
        cJSON *root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "design", a->input);
        pitch_json(root, &pitch);
        print_json(root);
        cJSON_Delete(root);
    } else {
        printf("%s: a flat sole: no joints or springs; its pitch stiffness is its contacts' (sole and ground in "
               "series)\n", a->input);
        pitch_print(&pitch);
        printf("for a rigid sole the law's height is not the limit: a centre of mass that passes over the "
               "footprint's edge tips it first (docs/landing.md)\n");
    }
    return 0;
}

static int stiffness_of(const cli_args *a, const fs_scenario *sc)
{
    fs_error err;
    if (sc->geom.kind == FS_FOOT_FLAT)
        return flat_stiffness(a, sc);
    fs_chain_stiffness k[FS_CHAINS];
    fs_stiffness_analytic(&sc->geom, k);
    if (fs_stiffness_measure(sc, k, &err) != FS_OK)
        return fail(&err);
    double worst = 0;
    for (int i = 0; i < FS_CHAINS; i++)
        worst = fmax(worst, k[i].rel_diff);
    /* the arch under the design load, on ground that grips (rolling) and on ground that does not */
    fs_planar_result eq[2];
    for (int f = 0; f < 2; f++) {
        fs_planar_load load = {sc->design.design_load_kg * sc->def.gravity_m_per_s2, sc->def.gravity_m_per_s2, 0, f};
        if (fs_planar_equilibrium(&sc->design, &sc->geom, 2, &load, &eq[f], &err) != FS_OK)
            return fail(&err);
    }
    /* the whole foot against pitching its ankle body, under the design load: the model, and ODE on
       the default ground's friction and on gripping ground */
    pitch_report pitch;
    if (pitch_stiffness(sc, a->input, &pitch, &err) != FS_OK)
        return fail(&err);
    if (a->json) {
        cJSON *root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "design", a->input);
        cJSON_AddStringToObject(root, "units", "N m/rad; joints (midfoot, MTP); positive turns the distal link up");
        cJSON *chains = cJSON_AddArrayToObject(root, "chains");
        for (int i = 0; i < FS_CHAINS; i++) {
            cJSON *c = cJSON_CreateObject();
            cJSON_AddNumberToObject(c, "chain", i + 1);
            cJSON_AddItemToObject(c, "analytic", mat_json((const double(*)[2])k[i].exact));
            cJSON_AddItemToObject(c, "paper_eq4", mat_json((const double(*)[2])k[i].eq4));
            cJSON_AddItemToObject(c, "measured", mat_json((const double(*)[2])k[i].measured));
            cJSON_AddNumberToObject(c, "rel_diff", k[i].rel_diff);
            cJSON_AddItemToArray(chains, c);
        }
        cJSON_AddNumberToObject(root, "max_rel_diff", worst);
        pitch_json(root, &pitch);
        cJSON_AddNumberToObject(root, "tolerance", STIFFNESS_TOLERANCE);
        cJSON *st = cJSON_AddObjectToObject(root, "static_check");
        cJSON_AddNumberToObject(st, "load_kg", sc->design.design_load_kg);
        cJSON_AddNumberToObject(st, "chain", 3);
        for (int f = 0; f < 2; f++) {
            cJSON *o = cJSON_AddObjectToObject(st, f ? "frictionless" : "gripping");
            cJSON_AddBoolToObject(o, "converged", eq[f].converged);
            cJSON_AddBoolToObject(o, "stable", eq[f].stable);
            cJSON_AddNumberToObject(o, "ankle_drop_m", eq[f].ankle_drop_m);
            cJSON_AddNumberToObject(o, "ankle_joint_rad", eq[f].ankle_joint_rad);
            cJSON_AddNumberToObject(o, "midfoot_rad", eq[f].midfoot_rad);
            cJSON_AddNumberToObject(o, "mtp_rad", eq[f].mtp_rad);
            cJSON_AddNumberToObject(o, "ball_clearance_m", eq[f].ball_clearance_m);
            cJSON_AddItemToObject(o, "spring_force_N", cJSON_CreateDoubleArray(eq[f].spring_force_N, 3));
        }
        print_json(root);
        cJSON_Delete(root);
    } else {
        printf("%s: joint stiffness per chain, N m/rad, joints (midfoot, MTP)\n", a->input);
        for (int i = 0; i < FS_CHAINS; i++) {
            printf("  chain %d (relative difference, measured against exact: %.2e)\n", i + 1, k[i].rel_diff);
            print_mat_row("exact geometry", (const double(*)[2])k[i].exact);
            print_mat_row("paper eq. 4 (on-axis)", (const double(*)[2])k[i].eq4);
            print_mat_row("measured in ODE", (const double(*)[2])k[i].measured);
        }
        printf("largest relative difference %.2e (must be below %.0e): %s\n", worst, STIFFNESS_TOLERANCE,
               worst <= STIFFNESS_TOLERANCE ? "agree" : "DISAGREE");
        printf("static check of chain 3 under %.1f kg (planar model, all chains alike):\n", sc->design.design_load_kg);
        for (int f = 0; f < 2; f++)
            printf("  %-12s %s, %s; ankle drop %.3f mm, midfoot %+.2f deg, MTP %+.2f deg, ball %.2f mm above the "
                   "ground\n",
                   f ? "frictionless" : "gripping", eq[f].converged ? "equilibrium found" : "NO EQUILIBRIUM",
                   eq[f].stable ? "stable" : "UNSTABLE", eq[f].ankle_drop_m * 1e3, eq[f].midfoot_rad * 180 / M_PI,
                   eq[f].mtp_rad * 180 / M_PI, eq[f].ball_clearance_m * 1e3);
        pitch_print(&pitch);
    }
    return worst <= STIFFNESS_TOLERANCE ? 0 : FS_EXPECTATION_FAILED;
}

int cli_stiffness(const cli_args *a) { return with_design(a, stiffness_of); }

/* ---- trial ------------------------------------------------------------------------------------ */

/* A trial's result as JSON (footsim trial --json, and trial.json in its folder). */
static cJSON *trial_json(const fs_trial_result *r)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "seed", r->draw.seed);
    cJSON_AddStringToObject(o, "outcome", fs_outcome_name(r->outcome));
    cJSON_AddStringToObject(o, "rule", fs_rule_name(r->rule));
    cJSON_AddStringToObject(o, "failure", r->failure);
    cJSON_AddNumberToObject(o, "robot_mass_kg", r->robot_mass_kg);
    double pose[5] = {r->draw.x_m, r->draw.y_m, r->draw.yaw_deg, r->draw.pitch_deg, r->draw.roll_deg};
    cJSON_AddItemToObject(o, "pose_x_y_m_yaw_pitch_roll_deg", cJSON_CreateDoubleArray(pose, 5));
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) /* the metrics, named as campaigns name them */
        cJSON_AddNumberToObject(o, fs_campaign_metrics[m].name, fs_metric_value(r, m));
    cJSON *steps = cJSON_AddObjectToObject(o, "steps_taken"); /* fixed or error-controlled (run.tolerance_m) */
    cJSON_AddNumberToObject(steps, "accepted", (double)r->steps);
    cJSON_AddNumberToObject(steps, "rejected", (double)r->rejected_steps);
    cJSON_AddNumberToObject(steps, "ode_steps", (double)r->ode_steps);
    cJSON_AddNumberToObject(steps, "least_s", r->step_least_s);
    cJSON_AddNumberToObject(steps, "median_s", r->step_median_s);
    cJSON_AddNumberToObject(steps, "largest_s", r->step_largest_s);
    if (r->nfeet > 1) { /* a biped: each foot's own, right then left */
        cJSON *feet = cJSON_AddArrayToObject(o, "feet");
        for (int f = 0; f < r->nfeet; f++) {
            cJSON *e = cJSON_CreateObject();
            cJSON_AddStringToObject(e, "foot", f ? "left" : "right");
            cJSON_AddNumberToObject(e, "touchdown_s", r->foot[f].touchdown_s);
            cJSON_AddNumberToObject(e, "ankle_drop_m", r->foot[f].ankle_drop_m);
            cJSON_AddNumberToObject(e, "slip_m", r->foot[f].slip_m);
            cJSON_AddNumberToObject(e, "mean_contacts", r->foot[f].mean_contacts);
            cJSON_AddNumberToObject(e, "final_contacts", r->foot[f].final_contacts);
            cJSON_AddNumberToObject(e, "final_force_N", r->foot[f].final_force_N);
            cJSON_AddItemToArray(feet, e);
        }
    }
    return o;
}

static int fill_json(FILE *f, const void *user) { return fs_json_print(f, user); }

/* A command's results in a folder of its own: run(user, observer) with frames of framed (when
 * --frames), then name (the result as JSON, to_json(result)) beside them, swapped in whole at the
 * end; dir_out gets the folder as shown. */
typedef struct folder_job {
    const char *dir;                 /* the folder asked for */
    const fs_scenario *framed;       /* the scenario the frames are framed on */
    fs_status (*run)(void *user, const fs_run_observer *obs, fs_error *err);
    void *user;
    const char *name;                /* the JSON file */
    cJSON *(*to_json)(const void *result);
    const void *result;
    const fs_provenance *provenance; /* what made the result, put into the JSON (NULL: none) */
    /* more files beside the JSON (a trial's trajectory.csv), written into dir; NULL: none */
    fs_status (*write_more)(void *user, const char *dir, fs_error *err);
    /* what every frame says (a trial's seed), and the last once the run ended (and its outcome);
       NULL: nothing */
    void (*frame_label)(const void *user, const void *result, int ended, char *label, size_t size);
} folder_job;

/* out: the caller's results folder (on the heap with the rest of its work), aborted here when it
 * was not committed. */
static int in_folder(const cli_args *a, const folder_job *j, fs_outdir *out, char *dir_out, size_t size)
{
    fs_error err;
    if (fs_outdir_open(out, j->dir, a->replace, "--out", &err) != FS_OK)
        return fail(&err);
    cli_frames *frames = NULL;
    fs_run_observer observer, *obs = NULL;
    int s = 0;
    char label[128] = "";
    if (a->frames && !(s = cli_frames_open(a, j->framed, out->partial, &frames, &observer)))
        obs = &observer;
    if (frames && j->frame_label) {
        j->frame_label(j->user, j->result, 0, label, sizeof label);
        cli_frames_label(frames, label);
    }
    fs_status rs = s ? FS_OK : j->run(j->user, obs, &err);
    int fstatus = 0;
    if (frames && j->frame_label && rs == FS_OK) {
        j->frame_label(j->user, j->result, 1, label, sizeof label);
        fstatus = cli_frames_finish(frames, label);
    }
    if (frames) {
        int closed = cli_frames_close(frames, rs == FS_OK && !fstatus, out->path);
        fstatus = fstatus ? fstatus : closed;
    }
    if (!s && rs == FS_OK && !fstatus) {
        cJSON *o = j->to_json(j->result);
        if (j->provenance)
            cJSON_AddItemToObject(o, "provenance", fs_provenance_json(j->provenance));
        rs = fs_write_in(out->partial, j->name, fill_json, o, &err);
        cJSON_Delete(o);
        if (rs == FS_OK && j->write_more)
            rs = j->write_more(j->user, out->partial, &err);
        if (rs == FS_OK)
            rs = fs_outdir_commit(out, &err);
    }
    fs_outdir_abort(out);
    if (!s && rs != FS_OK)
        s = fail(&err);
    snprintf(dir_out, size, "%s", out->path);
    return s ? s : fstatus;
}

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

static cJSON *trial_json_of(const void *r) { return trial_json(r); }

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
    folder_job j = {dir, placed, run_trial_job, &t, "trial.json", trial_json_of, r, &prov,
                    write_trial_log, trial_frame_label};
    if (!s)
        s = in_folder(a, &j, &w->out, dir_out, size);
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
        cJSON *o = trial_json(&r);
        print_json(o);
        cJSON_Delete(o);
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

/* ---- walk ------------------------------------------------------------------------------------- */

static cJSON *walk_json(const void *result)
{
    const fs_walk_result *r = result;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "steps_completed", r->steps_completed);
    cJSON_AddNumberToObject(o, "falls", r->falls);
    cJSON_AddNumberToObject(o, "rough_steps", r->rough_steps);
    cJSON_AddNumberToObject(o, "rough_contacts_mean", r->rough_contacts_mean);
    cJSON_AddNumberToObject(o, "flat_contacts_mean", r->flat_contacts_mean);
    cJSON_AddNumberToObject(o, "peak_force_N", r->peak_force_N);
    cJSON_AddNumberToObject(o, "peak_tilt_deg", r->peak_tilt_deg);
    if (r->soil) { /* on a soil: each step's record (fs_walk.h) */
        cJSON *steps = cJSON_AddArrayToObject(o, "soil_steps");
        for (int i = 0; i < r->nsteps; i++) {
            const fs_walk_step *w = &r->step[i];
            cJSON *e = cJSON_CreateObject();
            cJSON_AddNumberToObject(e, "step", i + 1);
            cJSON_AddNumberToObject(e, "sinkage_m", w->sinkage_m);
            cJSON_AddNumberToObject(e, "slip_m", w->slip_m);
            cJSON_AddNumberToObject(e, "soil_work_J", w->soil_work_J);
            cJSON_AddNumberToObject(e, "extra_press_m", w->extra_press_m);
            cJSON_AddNumberToObject(e, "load_N", w->load_N);
            cJSON_AddItemToArray(steps, e);
        }
    }
    return o;
}

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
        folder_job j = {dir, sc, run_walk_job, &job, "walk.json", walk_json, &r, &prov, write_walk_surface, NULL};
        if (!s)
            s = in_folder(a, &j, &w->out, shown, sizeof shown);
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
        cJSON *o = walk_json(&r);
        cJSON_AddStringToObject(o, "foot", foot);
        print_json(o);
        cJSON_Delete(o);
    } else {
        printf("%s: %s foot: %d steps completed, %d falls; contact points at mid-stance %.1f on the rough "
               "section (%d steps), %.1f off it; peak ground force %.0f N; ankle tilt up to %.1f deg\n",
               a->input, foot, r.steps_completed, r.falls, r.rough_contacts_mean, r.rough_steps, r.flat_contacts_mean,
               r.peak_force_N, r.peak_tilt_deg);
        for (int i = 0; r.soil && i < r.nsteps; i++)
            printf("  step %d on the soil: sinkage %.2f mm at the stance's end, slip %.2f mm, the soil took %.3f J; "
                   "pressed %.2f mm past press_m, ground force %.0f N\n", i + 1, r.step[i].sinkage_m * 1e3,
                   r.step[i].slip_m * 1e3, r.step[i].soil_work_J, r.step[i].extra_press_m * 1e3, r.step[i].load_N);
        if (shown[0])
            printf("  results: %s/walk.json%s%s\n", shown,
                   surface ? ", the soil's final surface in surface.png, .csv and .ini" : "", a->frames ? ", frames/" : "");
    }
    return 0;
}

/* ---- keys and demo ---------------------------------------------------------------------------- */

int cli_keys(const cli_args *a)
{
    (void)a;
    fs_config_print_keys(fs_design_keys, fs_design_nkeys, "Design files (scenarios/feet/*.ini)", stdout);
    fs_config_print_keys(fs_scenario_keys, fs_scenario_nkeys, "Scenario files (scenarios/*.ini)", stdout);
    fs_config_print_keys(fs_terrain_keys, fs_terrain_nkeys, "Terrain files (terrains/*.ini)", stdout);
    fs_config_print_keys(fs_robot_keys, fs_robot_nkeys, "Robot files (scenarios/robots/*.ini)", stdout);
    printf("### Limits\n\nWhat footsim refuses up front (exit 2, before anything is simulated or written), so that no\n"
           "count overflows and no buffer outgrows memory:\n\n| what | at most |\n|---|---|\n"
           "| an input file (design, scenario, terrain, campaign) | %d bytes, %d keys; regular files only |\n"
           "| a line of an input file | %d characters |\n"
           "| steps of one run, trial or walk (duration_s / step_s; steps x period_s / step_s) | %.0e |\n"
           "| a run's trajectory in memory (rows x columns x 8 bytes) | %.0f MiB |\n"
           "| trials of a campaign (feet x terrains x seeds) | %d |\n"
           "| frames of `run --frames` or `render-compare` (six-digit names) | %d |\n"
           "| frames `render-compare` keeps in memory | half of the machine's memory |\n"
           "| a number | decimal; 0 or a normal double, 2.2e-308 to 1.8e308 in magnitude (hexadecimal and subnormals refused) |\n"
           "| `terrain --height X Y` | metres from -1000 to 1000 |\n\n",
           FS_CONFIG_MAX_BYTES, FS_CONFIG_MAX_KEYS, fs_config_max_line(), (double)FS_MAX_STEPS, FS_TRAJ_MAX_BYTES / (1024.0 * 1024),
           FS_CAMPAIGN_MAX_TRIALS, 999999);
    return 0;
}

int cli_demo(const cli_args *a)
{
    (void)a;
    static const char *const scenarios[] = {"scenarios/static_load.ini", "scenarios/tilt10.ini"};
    for (int i = 0; i < 2; i++) {
        cli_args run = {.command = "run", .input = cli_data_path(scenarios[i])};
        int s = run_once(&run);
        if (s)
            return s;
    }
    cli_args st = {.command = "stiffness", .input = cli_data_path("scenarios/feet/biomimetic.ini")};
    int s = cli_stiffness(&st);
    if (s)
        return s;
    /* the main job, small: both feet landing on even, simply and complex uneven ground */
    printf("\nlanding comparison (2 seeds each, two robots; 'footsim campaign scenarios/landing.ini' runs 50):\n");
    fflush(stdout);
    cli_args camp = {.command = "campaign", .input = cli_data_path("scenarios/landing_ci.ini"), .nset = 1,
                     .set = {"campaign.seeds=2"}, .out = "results/campaigns/demo", .fresh = 1}; /* always shown */
    s = cli_campaign(&camp);
    /* the finding, in one line: the law for the trial scenario's robot (single_tall) on Table I */
    fs_error err;
    double K;
    fs_scenario *sc = s ? NULL : cli_zalloc(sizeof *sc);
    if (!s && !sc)
        return FS_NO_MEMORY;
    if (sc && fs_scenario_load(cli_data_path("scenarios/landing_trial.ini"), NULL, 0, sc, &err) == FS_OK) {
        fs_pitch_law law;
        double g = sc->def.gravity_m_per_s2;
        if (fs_pitch_stiffness_model(&sc->geom, sc->def.robot.mass_kg * g, g, &K, &err) == FS_OK) {
            fs_pitch_law_apply(K, &sc->def.robot, g, sc->def.landed_tilt_deg * M_PI / 180, &law);
            printf("note: the Table I biomimetic foot toppling under single_tall is the documented finding, not a "
                   "fault: that robot needs %.1f N m/rad of pitch stiffness and the foot has %.1f (docs/landing.md, "
                   "the pitch-stiffness law); under drop_weight it lands\n", law.demand, law.K);
        }
    }
    if (sc)
        fs_scenario_free(sc);
    free(sc);
    return s;
}
