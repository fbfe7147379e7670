/* mujoco-trial: a footsim landing trial run in MuJoCo instead of ODE, judged by footsim's rules
 * (issue 34 item 4; docs/contact.md). Built only with -DFS_MUJOCO=ON and Debian's libmujoco-dev
 * (MuJoCo 2.2.2); not installed.
 *
 *   mujoco-trial SCENARIO [--seed N]... [--set KEY=VALUE]... [MuJoCo options]
 *
 * For each seed the trial scenario is placed as footsim's trial places it (fs_trial_place: the
 * drawn position, yaw, pitch and roll, and a random terrain's seed; the foot starts at rest, drop_m
 * above the ground), written with footsim's MJCF export (fs_mjcf_write, docs/export.md) to a
 * temporary folder, loaded by MuJoCo and stepped at the scenario's step for its window. Every step
 * is judged by fs_outcome.h's judge with the trial's own rules (fs_trial_rules), fed what footsim
 * feeds it: the robot's lean (the angle of its body's z axis from the vertical), the kinetic energy
 * of every body, the fastest point (each body's COM speed plus its angular speed times its reach,
 * footsim's reach; the robot's its COM height), and the number of foot contacts; at the end the
 * deepest contact's penetration. MuJoCo's derived quantities after mj_step belong to the state at
 * the step's start, so each sample is that state's, time t - h: one consistent state a step late.
 * A step MuJoCo resets for a bad acceleration is a numerical failure.
 *
 * --set reaches the scenario as for `footsim trial`, so footsim's own contact settings (sole.*,
 * material.*) reach the export's solref (docs/export.md). The MuJoCo options change the loaded
 * model: --timeconst S [--dampratio Z] (solref's standard form on every geom, for the direct form
 * the export writes), --solimp D (constant impedance), --mu M (every geom's sliding friction),
 * --impratio R, --cone pyramidal|elliptic, --integrator euler|rk4|implicit, --noslip N.
 * --trace DT prints time, lean, contacts and kinetic energy every DT seconds; --xml FILE keeps the
 * (last seed's) export at FILE.
 *
 * Prints one line per seed (key=value: outcome, rule, end time, peak and final lean, the lean and
 * contacts at 0.5 and 1 s, touchdown) and a count. Exit 2 on bad input (a design the export
 * refuses too), 3 when MuJoCo refuses, 4 when the export cannot be written. */
#include "footsim/experiment/fs_outcome.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/export/fs_export.h"
#include "footsim/sim/fs_model.h"
#include "footsim/sim/fs_sim.h"

#include <mujoco/mujoco.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define DEG (M_PI / 180.0)
enum { MAX_SEEDS = 256, MAX_SET = 64 };

typedef struct options {
    const char *scenario, *xml;
    int seeds[MAX_SEEDS], nseeds;
    const char *set[MAX_SET];
    int nset;
    double timeconst, dampratio, solimp, mu, impratio, trace;
    int cone, integrator, noslip; /* -1: as exported */
} options;

/* What a run measured beside the judge's verdict. */
typedef struct measured {
    double touchdown_s, peak_lean_deg, lean_deg_at[2], end_s, final_lean_deg;
    int contacts_at[2], final_contacts, bad;
} measured;

static int bad_input(const char *what)
{
    fprintf(stderr, "mujoco-trial: %s\n", what);
    return 2;
}

static int number(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !(v >= lo && v <= hi))
        return 0;
    *out = v;
    return 1;
}

static int parse(int argc, char **argv, options *o)
{
    *o = (options){.timeconst = -1, .dampratio = 1, .solimp = -1, .mu = -1, .impratio = -1, .cone = -1,
                   .integrator = -1, .noslip = -1};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x;
        if (a[0] != '-') {
            if (o->scenario)
                return bad_input("give one trial scenario");
            o->scenario = a;
            continue;
        }
        if (!v)
            return bad_input("an option needs a value; see the comment at the top of tools/mujoco_trial.c");
        i++;
        if (!strcmp(a, "--seed")) {
            if (o->nseeds == MAX_SEEDS || !number(v, 0, 2147483647, &x) || x != floor(x))
                return bad_input("--seed: give a whole number from 0 to 2147483647 (at most 256 seeds)");
            o->seeds[o->nseeds++] = (int)x;
        } else if (!strcmp(a, "--set")) {
            if (o->nset == MAX_SET)
                return bad_input("at most 64 --set");
            o->set[o->nset++] = v;
        } else if (!strcmp(a, "--xml")) {
            o->xml = v;
        } else if (!strcmp(a, "--timeconst")) {
            if (!number(v, 1e-6, 10, &o->timeconst))
                return bad_input("--timeconst: a time constant in seconds, 1e-6 to 10");
        } else if (!strcmp(a, "--dampratio")) {
            if (!number(v, 1e-3, 100, &o->dampratio))
                return bad_input("--dampratio: a damping ratio, 1e-3 to 100");
        } else if (!strcmp(a, "--solimp")) {
            if (!number(v, 1e-4, 0.9999, &o->solimp))
                return bad_input("--solimp: the impedance d, 1e-4 to 0.9999");
        } else if (!strcmp(a, "--mu")) {
            if (!number(v, 0, 10, &o->mu))
                return bad_input("--mu: a friction coefficient, 0 to 10");
        } else if (!strcmp(a, "--impratio")) {
            if (!number(v, 1e-3, 1e4, &o->impratio))
                return bad_input("--impratio: 1e-3 to 1e4");
        } else if (!strcmp(a, "--trace")) {
            if (!number(v, 1e-4, 100, &o->trace))
                return bad_input("--trace: an interval in seconds");
        } else if (!strcmp(a, "--noslip")) {
            if (!number(v, 0, 1000, &x))
                return bad_input("--noslip: iterations, 0 to 1000");
            o->noslip = (int)x;
        } else if (!strcmp(a, "--cone")) {
            o->cone = !strcmp(v, "pyramidal") ? mjCONE_PYRAMIDAL : !strcmp(v, "elliptic") ? mjCONE_ELLIPTIC : -2;
            if (o->cone == -2)
                return bad_input("--cone: pyramidal or elliptic");
        } else if (!strcmp(a, "--integrator")) {
            o->integrator = !strcmp(v, "euler") ? mjINT_EULER : !strcmp(v, "rk4") ? mjINT_RK4
                          : !strcmp(v, "implicit") ? mjINT_IMPLICIT : -2;
            if (o->integrator == -2)
                return bad_input("--integrator: euler, rk4 or implicit");
        } else {
            fprintf(stderr, "mujoco-trial: unknown option %s\n", a);
            return 2;
        }
    }
    if (!o->scenario)
        return bad_input("usage: mujoco-trial SCENARIO [--seed N]... [--set KEY=VALUE]... [MuJoCo options]");
    if (!o->nseeds)
        o->seeds[o->nseeds++] = 1;
    return 0;
}

/* The options' changes to the loaded model. */
static void adjust(mjModel *m, const options *o)
{
    for (int g = 0; g < m->ngeom; g++) {
        if (o->timeconst > 0) {
            m->geom_solref[mjNREF * g] = o->timeconst;
            m->geom_solref[mjNREF * g + 1] = o->dampratio;
        }
        if (o->solimp > 0)
            m->geom_solimp[mjNIMP * g] = m->geom_solimp[mjNIMP * g + 1] = o->solimp;
        if (o->mu >= 0)
            m->geom_friction[3 * g] = o->mu;
    }
    if (o->impratio > 0)
        m->opt.impratio = o->impratio;
    if (o->cone >= 0)
        m->opt.cone = o->cone;
    if (o->integrator >= 0)
        m->opt.integrator = o->integrator;
    if (o->noslip >= 0)
        m->opt.noslip_iterations = o->noslip;
}

/* The placed scenario's export, loaded by MuJoCo (NULL when it cannot be; status the export's). */
static mjModel *load(const fs_scenario *sc, const char *keep, fs_status *status)
{
    char dir[] = "/tmp/mujoco_trial_XXXXXX", path[64], hpath[96], msg[1000] = "";
    const char *file = keep;
    *status = FS_IO;
    if (!keep) {
        if (!mkdtemp(dir)) {
            perror("mujoco-trial: a temporary folder");
            return NULL;
        }
        snprintf(path, sizeof path, "%s/trial.xml", dir);
        file = path;
    }
    fs_error err;
    mjModel *m = NULL;
    *status = fs_mjcf_write(sc, 1, file, &err);
    if (*status == FS_OK)
        m = mj_loadXML(file, NULL, msg, sizeof msg);
    else
        fprintf(stderr, "mujoco-trial: export: %s\n", err.message);
    if (!m && *msg)
        fprintf(stderr, "mujoco-trial: MuJoCo %s refused %s: %s\n", mj_versionString(), file, msg);
    if (!keep) {
        fs_mjcf_hfield_path(path, hpath, sizeof hpath);
        remove(hpath);
        remove(path);
        rmdir(dir);
    }
    return m;
}

/* Each MuJoCo body's reach (footsim's: the farthest joint, anchor or shape from its COM; the
 * robot's, its COM height), by name from a footsim sim of the same scenario; 0 for the others. */
static void reaches(const mjModel *m, const fs_sim *sim, double *reach)
{
    for (int b = 0; b < m->nbody; b++)
        reach[b] = 0;
    const fs_foot_geom *g = fs_sim_geom(sim);
    const fs_model *model = fs_sim_model(sim);
    for (int i = 0; i < g->nbodies; i++) {
        int b = mj_name2id(m, mjOBJ_BODY, g->body[i].name);
        if (b >= 0)
            reach[b] = model->body[i].reach_m;
    }
    int r = mj_name2id(m, mjOBJ_BODY, "robot");
    if (r >= 0)
        reach[r] = fs_sim_scenario(sim)->def.robot.com_height_m;
}

/* The judge's sample of the state MuJoCo's derived quantities describe (the last step's start). */
static void sample_of(const mjModel *m, const mjData *d, const double *reach, int robot, fs_outcome_sample *s)
{
    double ke = 0, vmax = 0;
    for (int b = 1; b < m->nbody; b++) {
        mjtNum v[6];
        mj_objectVelocity(m, d, mjOBJ_BODY, b, v, 0); /* [angular; linear] at the body's frame origin */
        /* the export puts each body's frame at its COM; the inertia is principal in ximat's frame */
        const mjtNum *R = d->ximat + 9 * b, *I = m->body_inertia + 3 * b;
        double rot = 0;
        for (int k = 0; k < 3; k++) {
            double wk = R[k] * v[0] + R[3 + k] * v[1] + R[6 + k] * v[2];
            rot += I[k] * wk * wk;
        }
        double lin = v[3] * v[3] + v[4] * v[4] + v[5] * v[5], ang = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        ke += 0.5 * m->body_mass[b] * lin + 0.5 * rot;
        vmax = fmax(vmax, sqrt(lin) + reach[b] * ang);
    }
    double up = robot >= 0 ? d->xmat[9 * robot + 8] : 1;
    *s = (fs_outcome_sample){d->time - m->opt.timestep, acos(fmax(-1.0, fmin(1.0, up))), ke, vmax, d->ncon, 1};
}

/* The deepest contact's penetration, m (0 with none). */
static double penetration(const mjData *d)
{
    double worst = 0;
    for (int i = 0; i < d->ncon; i++)
        worst = fmax(worst, -d->contact[i].dist);
    return worst;
}

/* Each contact's shape, depth and normal force, and their ratio: the stiffness MuJoCo's soft
 * contact gives it in N/m (its solref is per unit of the mass the contact moves). */
static void trace_contacts(const mjModel *m, const mjData *d)
{
    for (int i = 0; i < d->ncon; i++) {
        const mjContact *c = &d->contact[i];
        int g = m->geom_bodyid[c->geom1] ? c->geom1 : c->geom2;
        mjtNum f[6];
        mj_contactForce(m, d, i, f);
        const char *name = mj_id2name(m, mjOBJ_GEOM, g);
        printf("    %-16s depth %.4f mm, normal force %8.2f N, force/depth %.3g N/m\n", name ? name : "?",
               -c->dist * 1e3, f[0], c->dist < 0 ? f[0] / -c->dist : 0.0);
    }
}

/* One seed's trial: 0, or 2 / 3 / 4 when it cannot be run. */
static int run(const options *o, const fs_scenario *base, int seed, int *counts)
{
    static fs_scenario sc;
    fs_error err;
    if (fs_scenario_copy(&sc, base, &err) != FS_OK || fs_trial_place(&sc, seed, NULL, &err) != FS_OK) {
        fprintf(stderr, "mujoco-trial: %s\n", err.message);
        return err.status == FS_BAD_INPUT ? 2 : 3;
    }
    fs_sim *sim = NULL; /* for the rules and the reaches, as the export builds it */
    fs_sim_options so = {.with_ground = 1, .keep_robot_body = 1};
    if (fs_sim_new(&sc, &so, &sim, &err) != FS_OK) {
        fprintf(stderr, "mujoco-trial: %s\n", err.message);
        fs_scenario_free(&sc);
        return 3;
    }
    fs_outcome_rules rules;
    fs_trial_rules(&sc, sim, &rules);
    fs_status exported;
    mjModel *m = load(&sc, o->xml, &exported);
    if (!m) { /* a design the export refuses is bad input, as footsim export says */
        fs_sim_free(sim);
        fs_scenario_free(&sc);
        return exported == FS_OK ? 3 : (int)exported; /* 2 bad input, 4 cannot write; MuJoCo's refusal 3 */
    }
    adjust(m, o);
    mjData *d = mj_makeData(m);
    double *reach = calloc((size_t)m->nbody, sizeof *reach);
    if (!d || !reach) {
        fprintf(stderr, "mujoco-trial: out of memory\n");
        free(reach);
        mj_deleteData(d);
        mj_deleteModel(m);
        fs_sim_free(sim);
        fs_scenario_free(&sc);
        return 3;
    }
    reaches(m, sim, reach);
    int robot = mj_name2id(m, mjOBJ_BODY, "robot");
    fs_judge judge;
    fs_judge_init(&judge, &rules);
    measured r = {.touchdown_s = -1, .lean_deg_at = {-1, -1}, .contacts_at = {-1, -1}};
    const double at[2] = {0.5, 1.0};
    long steps = (long)ceil(sc.def.duration_s / sc.def.step_s - 1e-9);
    double next_trace = 0;
    fs_outcome_sample s = {0};
    for (long i = 0; i < steps; i++) {
        mj_step(m, d);
        if (d->warning[mjWARN_BADQACC].number > 0) {
            r.bad = 1;
            break;
        }
        sample_of(m, d, reach, robot, &s);
        double lean = s.lean_rad / DEG;
        r.peak_lean_deg = fmax(r.peak_lean_deg, lean);
        if (r.touchdown_s < 0 && d->ncon > 0)
            r.touchdown_s = s.t_s;
        for (int k = 0; k < 2; k++)
            if (r.contacts_at[k] < 0 && s.t_s >= at[k])
                r.lean_deg_at[k] = lean, r.contacts_at[k] = d->ncon;
        if (o->trace > 0 && s.t_s >= next_trace - 1e-12) {
            /* the robot's z axis leaning toward world x (forward) and y (left) */
            const mjtNum *R = robot >= 0 ? d->xmat + 9 * robot : NULL;
            printf("  t=%.4f lean_deg=%.3f (toward x %.3f, y %.3f) contacts=%d kinetic_J=%.4g\n", s.t_s, lean,
                   R ? asin(R[2]) / DEG : 0, R ? asin(R[5]) / DEG : 0, d->ncon, s.kinetic_J);
            trace_contacts(m, d);
            next_trace += o->trace;
        }
        if (fs_judge_step(&judge, &s))
            break;
    }
    const char *outcome, *rule;
    if (r.bad) {
        outcome = fs_outcome_name(FS_FAILED_NUMERICS), rule = fs_rule_name(FS_RULE_NUMERICS);
        counts[FS_FAILED_NUMERICS]++;
    } else {
        mj_forward(m, d); /* the state after the last step, for the end's sample */
        sample_of(m, d, reach, robot, &s);
        s.t_s = d->time;
        fs_judge_finish(&judge, &s, penetration(d));
        outcome = fs_outcome_name(judge.outcome), rule = fs_rule_name(judge.rule);
        counts[judge.outcome]++;
    }
    printf("seed=%d outcome=%s rule=%s end_s=%.4f peak_lean_deg=%.2f final_lean_deg=%.2f lean_0.5s_deg=%.2f "
           "contacts_0.5s=%d lean_1s_deg=%.2f contacts_1s=%d final_contacts=%d touchdown_s=%.5f\n",
           seed, outcome, rule, d->time, r.peak_lean_deg, s.lean_rad / DEG, r.lean_deg_at[0], r.contacts_at[0],
           r.lean_deg_at[1], r.contacts_at[1], d->ncon, r.touchdown_s);
    fflush(stdout);
    free(reach);
    mj_deleteData(d);
    mj_deleteModel(m);
    fs_sim_free(sim);
    fs_scenario_free(&sc);
    return 0;
}

int main(int argc, char **argv)
{
    static options o;
    int s = parse(argc, argv, &o);
    if (s)
        return s;
    static fs_scenario base;
    fs_error err;
    if (fs_scenario_load(o.scenario, o.set, o.nset, &base, &err) != FS_OK ||
        fs_scenario_require(&base, "trial", &err) != FS_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 2;
    }
    printf("MuJoCo %s: %s", mj_versionString(), o.scenario);
    for (int i = 0; i < o.nset; i++)
        printf(" --set %s", o.set[i]);
    printf(" | timeconst %s", o.timeconst > 0 ? "" : "as exported (direct solref)");
    if (o.timeconst > 0)
        printf("%g s dampratio %g", o.timeconst, o.dampratio);
    printf(" | solimp %g | mu %g | impratio %g | cone %s | integrator %s | noslip %d\n",
           o.solimp > 0 ? o.solimp : FS_MJCF_IMPEDANCE, o.mu, o.impratio,
           o.cone == mjCONE_ELLIPTIC ? "elliptic" : o.cone == mjCONE_PYRAMIDAL ? "pyramidal" : "as exported",
           o.integrator == mjINT_EULER ? "euler" : o.integrator == mjINT_RK4 ? "rk4" : o.integrator == mjINT_IMPLICIT
           ? "implicit" : "as exported", o.noslip);
    int counts[FS_NOUTCOMES] = {0};
    for (int i = 0; i < o.nseeds; i++)
        if ((s = run(&o, &base, o.seeds[i], counts)) != 0)
            break;
    printf("landed %d, fell %d, undecided %d, failed_numerics %d of %d\n", counts[FS_LANDED], counts[FS_FELL],
           counts[FS_UNDECIDED], counts[FS_FAILED_NUMERICS], o.nseeds);
    fs_scenario_free(&base);
    return s;
}
