/* fs_report.h: the reports the command prints and writes, for any program: a trial's result and a
 * walk's as JSON (trial.json, walk.json, `--json`), and a design's stiffness report (`footsim
 * stiffness`: each chain's joint stiffness analytic beside measured in ODE, the arch's static check,
 * the whole foot's pitch stiffness and the pitch-stiffness law for each shipped robot).
 *
 * Contract: every JSON builder checks every item it adds (fs_json_put): it returns the whole tree,
 * or NULL with FS_NO_MEMORY in err, never a tree with a field silently missing. The caller frees the
 * tree (cJSON_Delete). Nothing here prints but the *_print functions, to the FILE they are given. */
#ifndef FS_REPORT_H
#define FS_REPORT_H

#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/experiment/fs_walk.h"

#include <stdio.h>

struct cJSON;

/* A trial's result: seed, outcome, rule, failure, robot mass, the drawn pose, every campaign metric
 * by name, the steps taken, and each foot's for a biped. */
struct cJSON *fs_trial_json(const fs_trial_result *r, fs_error *err);

/* A walk's result: steps completed, falls, contacts on and off the rough section, peak force and
 * tilt; with foot (not NULL) its kind ("biomimetic", "flat"). */
struct cJSON *fs_walk_json(const fs_walk_result *r, const char *foot, fs_error *err);

/* The stiffness model and ODE must agree this closely (issue 2's acceptance bound). */
#define FS_STIFFNESS_TOLERANCE 0.01

enum { FS_REPORT_MAX_ROBOTS = 16 };

/* A design's stiffness report. */
typedef struct fs_stiffness_report {
    int flat;                                   /* a flat sole: only its pitch stiffness */
    fs_chain_stiffness chain[FS_CHAINS];        /* biomimetic: analytic and measured */
    double worst;                               /* the largest relative difference of the chains */
    int cable;                                  /* a tension-only spring: the chains are not compared (its kink
                                                   at the rest length: docs/model.md) */
    double static_load_kg;
    fs_planar_result eq[2];                     /* chain 3 under the design load: gripping, frictionless */
    int nonlinear;                              /* a spring not linear and two-sided (fs_spring_law_is_linear) */
    double loaded[2][2];                        /* nonlinear: chain 3's joint stiffness at the gripping
                                                   equilibrium (eqs. 1-3 on each law's tangent at its deflection
                                                   there, fs_stiffness_tangent), N m/rad */
    /* the whole foot against pitching its ankle body under the design load */
    double load_kg, K_model, K_ode_mu1, K_ode_grip;
    double K_ode_plane;                         /* gripping in each chain's plane, free across (biomimetic) */
    int nrobots;                                /* the shipped robots, by file name */
    char robot[FS_REPORT_MAX_ROBOTS][FS_NAME_MAX];
    fs_robot_def def[FS_REPORT_MAX_ROBOTS];
    fs_pitch_law law[FS_REPORT_MAX_ROBOTS];
} fs_stiffness_report;

/* Measures sc (a design's scenario, fs_scenario_for_design of design_path) into r. The robots the
 * law is told for are the .ini files of the design's ../robots/ folder (scenarios/robots/ beside
 * scenarios/feet/), else of robots_dir (NULL: none), sorted by name, at most FS_REPORT_MAX_ROBOTS.
 * An fs_status. */
fs_status fs_stiffness_report_make(const fs_scenario *sc, const char *design_path, const char *robots_dir,
                                   fs_stiffness_report *r, fs_error *err);

/* Whether the chains agree with the model within FS_STIFFNESS_TOLERANCE (a flat sole, or a design with
 * a tension-only spring, which is not compared: 1). */
int fs_stiffness_report_agrees(const fs_stiffness_report *r);

/* The report as text to out, and as JSON (design: how the design is named in both). */
void fs_stiffness_report_print(const fs_stiffness_report *r, const char *design, FILE *out);
struct cJSON *fs_stiffness_report_json(const fs_stiffness_report *r, const char *design, fs_error *err);

#endif
