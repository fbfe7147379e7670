/* sim_check.c: the state checks after every step (finite, speed, loop closure, energy). */
#include "footsim/sim/fs_check.h"

#include "footsim/sim/fs_sim.h"
#include "sim_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* One failed check: what, where, the value and its bound. */
typedef struct finding {
    fs_check_kind kind;
    const char *where;
    double value, bound;
} finding;

fs_check_class fs_check_class_of(fs_check_kind kind)
{
    if (kind == FS_CHECK_NONFINITE || kind == FS_CHECK_SPEED)
        return FS_CHECK_BLOWN_UP;
    return kind == FS_CHECK_OK ? FS_CHECK_STABLE : FS_CHECK_DRIFTING;
}

const char *fs_check_class_name(fs_check_class c)
{
    static const char *names[] = {"stable", "drifting", "blown_up"};
    return c >= 0 && c <= 2 ? names[c] : "unknown";
}

const char *fs_check_kind_name(fs_check_kind k)
{
    static const char *names[] = {"", "non_finite", "speed", "loop_closure", "energy"};
    return k >= 0 && k <= 4 ? names[k] : "unknown";
}

/* Body i of the foot, or the robot for i = nbodies. */
static dBodyID body_of(const fs_sim *sim, int i, const char **name)
{
    int robot = i == sim->geom->nbodies;
    *name = robot ? "robot" : sim->geom->body[i].name;
    return robot ? fs_sim_robot_body(sim) : sim->body[i];
}

static int finite3(const dReal *v) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

/* 1 and 2: every body finite, and no point of it faster than the bound. */
static int check_bodies(fs_sim *sim, finding *f)
{
    double bound = sim->sc->def.check_max_speed_m_per_s;
    for (int i = 0; i < fs_sim_nbodies(sim); i++) {
        const char *name;
        dBodyID b = body_of(sim, i, &name);
        if (!finite3(dBodyGetPosition(b)) || !finite3(dBodyGetLinearVel(b)) || !finite3(dBodyGetAngularVel(b))) {
            *f = (finding){FS_CHECK_NONFINITE, name, NAN, 0};
            return 1;
        }
        double v = fs_sim_body_speed(sim, i);
        sim->check.max_speed_m_per_s = fmax(sim->check.max_speed_m_per_s, v);
        if (v > bound) {
            *f = (finding){FS_CHECK_SPEED, name, v, bound};
            return 1;
        }
    }
    return 0;
}

static double anchor_gap(dJointID j)
{
    dVector3 a, b;
    dJointGetHingeAnchor(j, a);
    dJointGetHingeAnchor2(j, b);
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* 3: each hinge's two anchors together (the robot's ankle hinge too); the worst is kept. */
static int check_loops(fs_sim *sim, finding *f)
{
    double bound = sim->sc->def.check_max_loop_error_m, worst = 0;
    const char *where = "";
    for (int i = 0; i < sim->geom->nhinges; i++) {
        double gap = anchor_gap(sim->hinge[i]);
        if (!(gap <= worst))
            worst = gap, where = sim->geom->hinge[i].name;
    }
    /* a pinned chain's hinges to the world (fs_design_pinned_chain) */
    for (int i = 0; i < sim->geom->npins; i++) {
        double gap = anchor_gap(sim->pin[i]);
        if (!(gap <= worst))
            worst = gap, where = i ? "toe pin" : "heel pin";
    }
    if (sim->robot && sim->sc->def.robot.joint == FS_ROBOT_ACHILLES) {
        double gap = anchor_gap(sim->robot_joint);
        if (!(gap <= worst))
            worst = gap, where = "robot ankle";
    }
    sim->check.max_loop_error_m = fmax(sim->check.max_loop_error_m, worst);
    if (worst > bound) {
        *f = (finding){FS_CHECK_LOOP, where, worst, bound};
        return 1;
    }
    return 0;
}

/* The load's work over the step just taken, and its force and point for the next one. */
static void account_load(fs_sim *sim)
{
    fs_check *c = &sim->check;
    double p[3], f = fs_sim_load_now_N(sim), w = 0;
    fs_sim_ankle(sim, p);
    for (int k = 0; k < 3; k++) {
        if (c->started)
            w += c->load_next[k] * (p[k] - c->ankle_prev[k]);
        c->ankle_prev[k] = p[k];
        c->load_next[k] = f * sim->down[k];
    }
    c->work_J += w;
    c->work_abs_J += fabs(w);
}

void fs_check_set_work(fs_sim *sim, fs_check_work_fn fn, void *user)
{
    sim->check.work_fn = fn;
    sim->check.work_user = user;
}

/* A driver's work over the step just taken, from the reference on. */
static void account_driver(fs_sim *sim)
{
    fs_check *c = &sim->check;
    if (!c->work_fn)
        return;
    double w = c->work_fn(c->work_user, sim);
    if (!c->started)
        return;
    c->work_J += w;
    c->work_abs_J += fabs(w);
}

/* 4: the energy above its reference and the work put in, against the margin. */
static int check_energy(fs_sim *sim, finding *f)
{
    fs_check *c = &sim->check;
    const fs_scenario_def *d = &sim->sc->def;
    double e = fs_sim_energy(sim, NULL, NULL, NULL);
    if (!c->started) {
        c->energy_ref_J = e;
        c->energy_bound_J = d->check_energy_margin_J;
        return 0;
    }
    double excess = e - c->energy_ref_J - c->work_J;
    double bound = d->check_energy_margin_J + d->check_energy_margin_rel * c->work_abs_J;
    if (excess > c->max_energy_excess_J) {
        c->max_energy_excess_J = excess;
        c->energy_bound_J = bound;
    }
    if (!(excess <= bound)) {
        /* name the fastest body: where the energy went */
        int fastest = 0;
        for (int i = 1; i < fs_sim_nbodies(sim); i++)
            if (fs_sim_body_speed(sim, i) > fs_sim_body_speed(sim, fastest))
                fastest = i;
        const char *name;
        body_of(sim, fastest, &name);
        *f = (finding){FS_CHECK_ENERGY, name, excess, bound};
        return 1;
    }
    return 0;
}

double fs_check_explicit_step_limit(const fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    double ksum[FS_MAX_BODIES] = {0}, csum[FS_MAX_BODIES] = {0}, limit = INFINITY;
    for (int i = 0; i < g->nsprings; i++)
        for (int e = 0; e < 2; e++) {
            int b = e ? g->spring[i].body2 : g->spring[i].body1;
            ksum[b] += g->spring[i].k_N_per_m;
            csum[b] += g->spring[i].c_Ns_per_m;
        }
    /* symplectic Euler on m x'' = -k x - c x' is stable while k h^2 + 2 c h < 4 m */
    for (int i = 0; i < g->nbodies; i++) {
        double m = g->body[i].mass_kg, k = ksum[i], c = csum[i];
        if (k > 0)
            limit = fmin(limit, (-c + sqrt(c * c + 4 * k * m)) / k);
        else if (c > 0)
            limit = fmin(limit, 2 * m / c);
    }
    return limit;
}

static const char *advice(const fs_sim *sim, fs_check_kind kind, char *buf, size_t size)
{
    const fs_scenario_def *d = &sim->sc->def;
    char springs[96] = "";
    double limit = fs_check_explicit_step_limit(sim);
    if (d->springs == FS_SPRING_EXPLICIT && isfinite(limit))
        snprintf(springs, sizeof springs, "; explicit springs are stable below about %.1e s here", limit);
    int springs_caused = d->springs == FS_SPRING_EXPLICIT && d->step_s > limit;
    if (springs_caused) /* whatever gave first, that is the cause */
        kind = FS_CHECK_SPEED;
    const char *more = kind == FS_CHECK_LOOP ? ", run.stepper = step or more run.iterations"
                       : kind == FS_CHECK_ENERGY
                           ? ", run.springs = implicit, or a larger check.energy_margin_J if something footsim "
                             "does not count puts energy in"
                           : " or run.springs = implicit";
    /* a soil's explicit forces, large on buried links, bound the step lower than rigid ground does,
     * whatever the check that caught it (docs/soil.md, Explicit forces), unless the explicit springs
     * were past their own bound; short, for a trial's failure text (fs_trial_result.failure) */
    const char *soil = sim->soil && d->tolerance_m <= 0 && !springs_caused
                           ? "; on a soil the step is bounded lower (docs/soil.md, Explicit forces), or set "
                             "run.tolerance_m"
                           : "";
    snprintf(buf, size, "try a smaller run.step_s (now %g s%s)%s%s", d->step_s, springs, more, soil);
    return buf;
}

static fs_status report(fs_sim *sim, const finding *f, fs_error *err)
{
    static const char *what[] = {"", "has a non-finite position or velocity", "moves at %.3g m/s, beyond %.3g m/s "
                                 "([check] max_speed_m_per_s)", "has its anchors %.3g m apart, beyond %.3g m "
                                 "([check] max_loop_error_m)", "(the fastest body): the energy exceeds its start "
                                 "plus the work put in by %.3g J, beyond %.3g J ([check] energy_margin_J, "
                                 "energy_margin_rel)"};
    fs_check *c = &sim->check;
    c->failure = f->kind;
    c->failure_time_s = sim->time_s;
    snprintf(c->failure_where, sizeof c->failure_where, "%s", f->where);
    char value[160], tip[448];
    snprintf(value, sizeof value, what[f->kind], f->value, f->bound);
    return fs_fail(err, FS_NUMERICAL, "%s: t = %.6f s: %s '%s' %s: %s; %s", sim->sc->path, sim->time_s,
                   f->kind == FS_CHECK_LOOP ? "hinge" : "body", f->where, value,
                   fs_check_class_of(f->kind) == FS_CHECK_BLOWN_UP ? "the simulation blew up" : "the simulation drifts",
                   advice(sim, f->kind, tip, sizeof tip));
}

fs_status fs_check_step(fs_sim *sim, fs_error *err)
{
    fs_check *c = &sim->check;
    finding loop = {FS_CHECK_OK, "", 0, 0}, energy = loop;
    if (check_bodies(sim, &loop))
        return report(sim, &loop, err);
    check_loops(sim, &loop);
    account_load(sim);
    account_driver(sim);
    if (!c->started || (c->steps + 1) % sim->sc->def.check_energy_every == 0)
        check_energy(sim, &energy);
    c->started = 1;
    c->steps++;
    const finding *f = loop.kind != FS_CHECK_OK ? &loop : &energy;
    if (f->kind == FS_CHECK_OK)
        return FS_OK;
    if (!c->record_drift)
        return report(sim, f, err);
    if (c->first_drift == FS_CHECK_OK) {
        c->first_drift = f->kind;
        c->first_drift_time_s = sim->time_s;
        snprintf(c->drift_where, sizeof c->drift_where, "%s", f->where);
    }
    return FS_OK;
}
