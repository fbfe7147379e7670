/* campaign_reports.c: trial.json, walk.json and the stiffness report (fs_report.h), moved out of
 * the command (app/) so that any program makes them, every JSON item checked. */
#include "footsim/campaign/fs_report.h"

#include "footsim/base/fs_path.h"
#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- checked JSON --------------------------------------------------------------------------- */

/* A builder's adds, each checked; ok stays 1 while every one was put. */
static int num(cJSON *o, const char *name, double v) { return fs_json_put(o, name, cJSON_CreateNumber(v)); }
static int text(cJSON *o, const char *name, const char *s) { return fs_json_put(o, name, cJSON_CreateString(s)); }
static int boolean(cJSON *o, const char *name, int b) { return fs_json_put(o, name, cJSON_CreateBool(b)); }

/* root when ok, else NULL (root freed) with FS_NO_MEMORY. */
static cJSON *whole(cJSON *root, int ok, const char *what, fs_error *err)
{
    if (root && ok)
        return root;
    cJSON_Delete(root);
    fs_fail(err, FS_NO_MEMORY, "out of memory for %s", what);
    return NULL;
}

/* An object put into parent under name (NULL when it could not be). */
static cJSON *child(cJSON *parent, const char *name, cJSON *item) { return fs_json_put(parent, name, item) ? item : NULL; }

/* ---- trial and walk ------------------------------------------------------------------------- */

cJSON *fs_trial_json(const fs_trial_result *r, fs_error *err)
{
    cJSON *o = cJSON_CreateObject();
    int ok = o != NULL;
    ok = ok && num(o, "seed", r->draw.seed) && text(o, "outcome", fs_outcome_name(r->outcome)) &&
         text(o, "rule", fs_rule_name(r->rule)) && text(o, "failure", r->failure) &&
         num(o, "robot_mass_kg", r->robot_mass_kg);
    double pose[5] = {r->draw.x_m, r->draw.y_m, r->draw.yaw_deg, r->draw.pitch_deg, r->draw.roll_deg};
    ok = ok && fs_json_put(o, "pose_x_y_m_yaw_pitch_roll_deg", cJSON_CreateDoubleArray(pose, 5));
    for (int m = 0; ok && m < FS_CAMPAIGN_NMETRICS; m++) /* the metrics, named as campaigns name them */
        ok = num(o, fs_campaign_metrics[m].name, fs_metric_value(r, m));
    cJSON *steps = ok ? child(o, "steps_taken", cJSON_CreateObject()) : NULL; /* fixed or error-controlled */
    ok = steps && num(steps, "accepted", (double)r->steps) && num(steps, "rejected", (double)r->rejected_steps) &&
         num(steps, "ode_steps", (double)r->ode_steps) && num(steps, "least_s", r->step_least_s) &&
         num(steps, "median_s", r->step_median_s) && num(steps, "largest_s", r->step_largest_s);
    if (ok && r->nfeet > 1) { /* a biped: each foot's own, right then left */
        cJSON *feet = child(o, "feet", cJSON_CreateArray());
        ok = feet != NULL;
        for (int f = 0; ok && f < r->nfeet; f++) {
            cJSON *e = child(feet, NULL, cJSON_CreateObject());
            ok = e && text(e, "foot", f ? "left" : "right") && num(e, "touchdown_s", r->foot[f].touchdown_s) &&
                 num(e, "ankle_drop_m", r->foot[f].ankle_drop_m) && num(e, "slip_m", r->foot[f].slip_m) &&
                 num(e, "mean_contacts", r->foot[f].mean_contacts) &&
                 num(e, "final_contacts", r->foot[f].final_contacts) &&
                 num(e, "final_force_N", r->foot[f].final_force_N);
        }
    }
    return whole(o, ok, "the trial's JSON", err);
}

cJSON *fs_walk_json(const fs_walk_result *r, const char *foot, fs_error *err)
{
    cJSON *o = cJSON_CreateObject();
    int ok = o && num(o, "steps_completed", r->steps_completed) && num(o, "falls", r->falls) &&
             num(o, "rough_steps", r->rough_steps) && num(o, "rough_contacts_mean", r->rough_contacts_mean) &&
             num(o, "flat_contacts_mean", r->flat_contacts_mean) && num(o, "peak_force_N", r->peak_force_N) &&
             num(o, "peak_tilt_deg", r->peak_tilt_deg);
    if (ok && r->soil) { /* on a soil: each step's record (fs_walk.h) */
        cJSON *steps = child(o, "soil_steps", cJSON_CreateArray());
        ok = steps != NULL;
        for (int i = 0; ok && i < r->nsteps; i++) {
            const fs_walk_step *w = &r->step[i];
            cJSON *e = child(steps, NULL, cJSON_CreateObject());
            ok = e && num(e, "step", i + 1) && num(e, "sinkage_m", w->sinkage_m) && num(e, "slip_m", w->slip_m) &&
                 num(e, "soil_slip_m", w->soil_slip_m) && num(e, "soil_work_J", w->soil_work_J) && num(e, "extra_press_m", w->extra_press_m) &&
                 num(e, "load_N", w->load_N) && fs_json_put(e, "on_soil", cJSON_CreateBool(w->on_soil));
        }
    }
    ok = ok && (!foot || text(o, "foot", foot));
    return whole(o, ok, "the walk's JSON", err);
}

/* ---- the stiffness report ------------------------------------------------------------------- */

/* The lean a landing counts as upright below ([landing] landed_tilt_deg's default). */
static const double LAW_LEAN_DEG = 15;

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The names of the .ini files in dir (at most FS_REPORT_MAX_ROBOTS, malloc'd), sorted; how many. */
static int robot_files(const char *dir, char **names)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) && n < FS_REPORT_MAX_ROBOTS;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".ini") && (names[n] = strdup(e->d_name)) != NULL)
            n++;
    }
    if (d)
        closedir(d);
    qsort(names, (size_t)n, sizeof names[0], by_name);
    return n;
}

/* The robot files beside the design's folder (scenarios/robots/ for scenarios/feet/X.ini), else
 * those of robots_dir; the law for each on a foot of stiffness K. */
static void shipped_robots(const char *design, const char *robots_dir, double K, double g, fs_stiffness_report *p)
{
    char dir[FS_PATH_MAX];
    const char *slash = strrchr(design, '/');
    char *names[FS_REPORT_MAX_ROBOTS];
    int n = 0;
    if (fs_path_format(dir, sizeof dir, "", NULL, "%.*s../robots", slash ? (int)(slash + 1 - design) : 0, design) == FS_OK)
        n = robot_files(dir, names);
    if (!n && robots_dir && fs_path_format(dir, sizeof dir, "", NULL, "%s", robots_dir) == FS_OK)
        n = robot_files(dir, names);
    for (int i = 0; i < n; i++) {
        char path[2 * FS_PATH_MAX];
        fs_error ignored;
        if (fs_path_format(path, sizeof path, "", NULL, "%s/%s", dir, names[i]) == FS_OK &&
            fs_robot_load(path, NULL, 0, &p->def[p->nrobots], &ignored) == FS_OK) {
            fs_path_stem(path, p->robot[p->nrobots], FS_NAME_MAX);
            fs_pitch_law_apply(K, &p->def[p->nrobots], g, LAW_LEAN_DEG * M_PI / 180, &p->law[p->nrobots]);
            p->nrobots++;
        }
        free(names[i]);
    }
}

fs_status fs_stiffness_report_make(const fs_scenario *sc, const char *design_path, const char *robots_dir,
                                   fs_stiffness_report *r, fs_error *err)
{
    memset(r, 0, sizeof *r);
    r->flat = sc->geom.kind == FS_FOOT_FLAT;
    double g = sc->def.gravity_m_per_s2;
    fs_status s = FS_OK;
    if (!r->flat) {
        fs_stiffness_analytic(&sc->geom, r->chain);
        s = fs_stiffness_measure(sc, r->chain, err);
        for (int i = 0; s == FS_OK && i < FS_CHAINS; i++)
            r->worst = fmax(r->worst, r->chain[i].rel_diff);
        /* a cable at its rest length has a kink there: the probe, which turns each joint both ways,
           measures across it, the model counts it taut (docs/model.md): they are not compared */
        for (int i = 0; i < sc->geom.nsprings; i++)
            r->cable |= sc->geom.spring[i].law.tension_only;
        /* the arch under the design load, on ground that grips (rolling) and on ground that does not */
        r->static_load_kg = sc->design.design_load_kg;
        for (int f = 0; s == FS_OK && f < 2; f++) {
            fs_planar_load load = {sc->design.design_load_kg * g, g, 0, f};
            s = fs_planar_equilibrium(&sc->design, &sc->geom, 2, &load, &r->eq[f], err);
        }
        /* a nonlinear law's stiffness depends on its deflection: chain 3's at the loaded (gripping) pose
           too, every chain's springs deflected as chain 3's there (the static check's chains alike) */
        for (int i = 0; i < sc->geom.nsprings; i++)
            r->nonlinear |= !fs_spring_law_is_linear(&sc->geom.spring[i].law);
        if (s == FS_OK && r->nonlinear) {
            double x[FS_MAX_SPRINGS] = {0};
            fs_chain_stiffness at[FS_CHAINS];
            for (int i = 0; i < FS_CHAINS; i++)
                for (int w = 0; w < 3; w++)
                    x[sc->geom.chain[i].spring[w]] = r->eq[0].spring_deflection_m[w];
            fs_stiffness_tangent(&sc->geom, x, at);
            memcpy(r->loaded, at[2].exact, sizeof r->loaded);
        }
    }
    /* the whole foot against pitching its ankle body, under the design load: the model, and ODE on
       the default ground's friction and on gripping ground */
    double load_N = sc->design.design_load_kg * g;
    r->load_kg = sc->design.design_load_kg;
    if (s == FS_OK)
        s = fs_pitch_stiffness_foot(sc, load_N, &r->K_model, err);
    if (s == FS_OK)
        s = fs_pitch_stiffness_measure(sc, load_N, 1, 0, r->K_model, &r->K_ode_mu1, err);
    if (s == FS_OK)
        s = fs_pitch_stiffness_measure(sc, load_N, 10, 0, r->K_model, &r->K_ode_grip, err);
    if (s == FS_OK && !r->flat)
        s = fs_pitch_stiffness_measure(sc, load_N, 10, 1, r->K_model, &r->K_ode_plane, err);
    if (s == FS_OK)
        shipped_robots(design_path, robots_dir, r->K_model, g, r);
    return s;
}

int fs_stiffness_report_agrees(const fs_stiffness_report *r)
{
    return r->flat || r->cable || r->worst <= FS_STIFFNESS_TOLERANCE;
}

static void print_mat_row(FILE *out, const char *label, const double m[2][2])
{
    fprintf(out, "    %-22s [%9.4f %9.4f; %9.4f %9.4f]\n", label, m[0][0], m[0][1], m[1][0], m[1][1]);
}

static void pitch_print(const fs_stiffness_report *p, FILE *out)
{
    fprintf(out, "whole foot against pitching its ankle body under %.1f kg at the ankle (docs/landing.md), N m/rad:\n"
                 "  model: %-46s %8.2f\n"
                 "  measured in ODE, friction 1 (the landing trials')     %8.2f (%+.2f %%)\n"
                 "  %-53s %8.2f\n",
            p->load_kg,
            p->flat ? "the sole's corners on the contacts' springs" : "each chain rolls in its plane, free across it",
            p->K_model, p->K_ode_mu1, 100 * (p->K_ode_mu1 / p->K_model - 1),
            p->flat ? "measured in ODE, friction 10" : "measured in ODE, friction 10 (toes held across too)",
            p->K_ode_grip);
    if (!p->flat)
        fprintf(out, "  %-53s %8.2f (%+.2f %%)\n", "measured in ODE, the model's contacts (grip in plane)",
                p->K_ode_plane, 100 * (p->K_ode_plane / p->K_model - 1));
    if (p->nrobots)
        fprintf(out, "the law, K (the model's, an Achilles tendon in series) against m g h of each robot:\n");
    for (int i = 0; i < p->nrobots; i++) {
        const fs_pitch_law *l = &p->law[i];
        if (l->held)
            fprintf(out, "  %-22s %5.1f kg: pitch held by its slide; stands\n", p->robot[i], p->def[i].mass_kg);
        else {
            char lean[48] = "no rest: too high";
            if (isfinite(l->lean_rad))
                snprintf(lean, sizeof lean, "lean at rest %.1f deg", l->lean_rad * 180 / M_PI);
            fprintf(out, "  %-22s %5.1f kg, centre of mass %.3f m up, %.3f m ahead: needs %6.2f, has %6.2f; critical "
                         "height %.3f m; %s: %s\n",
                    p->robot[i], p->def[i].mass_kg, p->def[i].com_height_m, p->def[i].com_forward_m, l->demand, l->K,
                    l->critical_height_m, lean, l->stands ? "stands" : "topples");
        }
    }
}

void fs_stiffness_report_print(const fs_stiffness_report *r, const char *design, FILE *out)
{
    if (r->flat) {
        fprintf(out, "%s: a flat sole: no joints or springs; its pitch stiffness is its contacts' (sole and ground in "
                     "series)\n", design);
        pitch_print(r, out);
        fprintf(out, "for a rigid sole the law's height is not the limit: a centre of mass that passes over the "
                     "footprint's edge tips it first (docs/landing.md)\n");
        return;
    }
    fprintf(out, "%s: joint stiffness per chain, N m/rad, joints (midfoot, MTP)\n", design);
    for (int i = 0; i < FS_CHAINS; i++) {
        const fs_chain_stiffness *k = &r->chain[i];
        fprintf(out, "  chain %d (relative difference, measured against exact: %.2e)\n", i + 1, k->rel_diff);
        print_mat_row(out, "exact geometry", (const double(*)[2])k->exact);
        print_mat_row(out, "paper eq. 4 (on-axis)", (const double(*)[2])k->eq4);
        print_mat_row(out, "measured in ODE", (const double(*)[2])k->measured);
    }
    if (r->cable)
        fprintf(out, "largest relative difference %.2e: not compared (a tension-only spring sits at its kink at the "
                     "rest length: the model counts it taut, the probe turns each joint both ways across it; "
                     "docs/model.md)\n", r->worst);
    else
        fprintf(out, "largest relative difference %.2e (must be below %.0e): %s\n", r->worst, FS_STIFFNESS_TOLERANCE,
                r->worst <= FS_STIFFNESS_TOLERANCE ? "agree" : "DISAGREE");
    fprintf(out, "static check of chain 3 under %.1f kg (planar model, all chains alike):\n", r->static_load_kg);
    for (int f = 0; f < 2; f++) {
        const fs_planar_result *e = &r->eq[f];
        fprintf(out, "  %-12s %s, %s; ankle drop %.3f mm, midfoot %+.2f deg, MTP %+.2f deg, ball %.2f mm above the "
                     "ground\n",
                f ? "frictionless" : "gripping", e->converged ? "equilibrium found" : "NO EQUILIBRIUM",
                e->stable ? "stable" : "UNSTABLE", e->ankle_drop_m * 1e3, e->midfoot_rad * 180 / M_PI,
                e->mtp_rad * 180 / M_PI, e->ball_clearance_m * 1e3);
    }
    if (r->nonlinear && r->eq[0].converged) {
        const double *x = r->eq[0].spring_deflection_m;
        fprintf(out, "  chain 3's K at the gripping equilibrium (eqs. 1-3 on each law's tangent at d1, d2, d3 deflected "
                     "%+.4f, %+.4f, %+.4f mm) [%9.4f %9.4f; %9.4f %9.4f] N m/rad\n",
                x[0] * 1e3, x[1] * 1e3, x[2] * 1e3, r->loaded[0][0], r->loaded[0][1], r->loaded[1][0],
                r->loaded[1][1]);
    } else if (r->nonlinear) {
        fprintf(out, "  chain 3's K under the load: not taken (no gripping equilibrium)\n");
    }
    pitch_print(r, out);
}

static cJSON *mat_json(const double m[2][2])
{
    cJSON *rows = cJSON_CreateArray();
    int ok = rows != NULL;
    for (int i = 0; ok && i < 2; i++)
        ok = fs_json_put(rows, NULL, cJSON_CreateDoubleArray(m[i], 2));
    if (!ok)
        cJSON_Delete(rows);
    return ok ? rows : NULL;
}

static int pitch_json(cJSON *root, const fs_stiffness_report *p)
{
    cJSON *o = child(root, "pitch_stiffness", cJSON_CreateObject());
    int ok = o && num(o, "load_kg", p->load_kg) &&
             text(o, "model", p->flat ? "flat sole on its contacts" : "chains rolling in their planes") &&
             num(o, "model_N_m_per_rad", p->K_model) && num(o, "ode_mu1_N_m_per_rad", p->K_ode_mu1) &&
             num(o, "ode_mu10_N_m_per_rad", p->K_ode_grip) &&
             (p->flat || num(o, "ode_in_plane_N_m_per_rad", p->K_ode_plane));
    cJSON *robots = ok ? child(o, "robots", cJSON_CreateArray()) : NULL;
    ok = robots != NULL;
    for (int i = 0; ok && i < p->nrobots; i++) {
        cJSON *r = child(robots, NULL, cJSON_CreateObject());
        const fs_pitch_law *l = &p->law[i];
        ok = r && text(r, "robot", p->robot[i]) && num(r, "mass_kg", p->def[i].mass_kg) &&
             num(r, "com_height_m", p->def[i].com_height_m) && boolean(r, "pitch_held", l->held) &&
             num(r, "K_N_m_per_rad", l->K) && num(r, "demand_N_m_per_rad", l->demand) &&
             num(r, "critical_com_height_m", l->critical_height_m) && num(r, "lean_at_rest_rad", l->lean_rad) &&
             boolean(r, "stands", l->stands);
    }
    return ok;
}

cJSON *fs_stiffness_report_json(const fs_stiffness_report *r, const char *design, fs_error *err)
{
    cJSON *root = cJSON_CreateObject();
    int ok = root && text(root, "design", design);
    if (ok && r->flat)
        return whole(root, pitch_json(root, r), "the stiffness report", err);
    ok = ok && text(root, "units", "N m/rad; joints (midfoot, MTP); positive turns the distal link up");
    cJSON *chains = ok ? child(root, "chains", cJSON_CreateArray()) : NULL;
    ok = chains != NULL;
    for (int i = 0; ok && i < FS_CHAINS; i++) {
        const fs_chain_stiffness *k = &r->chain[i];
        cJSON *c = child(chains, NULL, cJSON_CreateObject());
        ok = c && num(c, "chain", i + 1) && fs_json_put(c, "analytic", mat_json((const double(*)[2])k->exact)) &&
             fs_json_put(c, "paper_eq4", mat_json((const double(*)[2])k->eq4)) &&
             fs_json_put(c, "measured", mat_json((const double(*)[2])k->measured)) && num(c, "rel_diff", k->rel_diff);
    }
    ok = ok && num(root, "max_rel_diff", r->worst) && pitch_json(root, r) &&
         num(root, "tolerance", FS_STIFFNESS_TOLERANCE) && (!r->cable || boolean(root, "compared", 0));
    cJSON *st = ok ? child(root, "static_check", cJSON_CreateObject()) : NULL;
    ok = st && num(st, "load_kg", r->static_load_kg) && num(st, "chain", 3);
    for (int f = 0; ok && f < 2; f++) {
        const fs_planar_result *e = &r->eq[f];
        cJSON *o = child(st, f ? "frictionless" : "gripping", cJSON_CreateObject());
        ok = o && boolean(o, "converged", e->converged) && boolean(o, "stable", e->stable) &&
             num(o, "ankle_drop_m", e->ankle_drop_m) && num(o, "ankle_joint_rad", e->ankle_joint_rad) &&
             num(o, "midfoot_rad", e->midfoot_rad) && num(o, "mtp_rad", e->mtp_rad) &&
             num(o, "ball_clearance_m", e->ball_clearance_m) &&
             fs_json_put(o, "spring_force_N", cJSON_CreateDoubleArray(e->spring_force_N, 3));
    }
    /* a nonlinear design: chain 3's joint stiffness at the gripping equilibrium (absent for Table I's laws) */
    cJSON *ld = ok && r->nonlinear && r->eq[0].converged ? child(st, "loaded_stiffness", cJSON_CreateObject()) : NULL;
    if (ok && r->nonlinear && r->eq[0].converged)
        ok = ld && text(ld, "at", "gripping equilibrium") && num(ld, "chain", 3) &&
             fs_json_put(ld, "spring_deflection_m", cJSON_CreateDoubleArray(r->eq[0].spring_deflection_m, 3)) &&
             fs_json_put(ld, "analytic", mat_json((const double(*)[2])r->loaded));
    return whole(root, ok, "the stiffness report", err);
}
