/* experiment_track.c: a run's path sampled at every step, and the distance between two paths. */
#include "footsim/experiment/fs_track.h"

#include "footsim/sim/fs_drive.h"

#include "footsim/sim/fs_check.h"
#include "footsim/sim/fs_sim_soil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static fs_status track_alloc(fs_track *t, double dt_s, int n, int nangles, int timed, fs_error *err)
{
    memset(t, 0, sizeof *t);
    t->sinkage_end_m = NAN;
    t->dt_s = dt_s;
    t->n = n;
    t->nangles = nangles;
    t->ankle = calloc((size_t)n, sizeof *t->ankle);
    t->angle = calloc((size_t)n, sizeof *t->angle);
    if (timed)
        t->t_s = calloc((size_t)n, sizeof *t->t_s);
    if (!t->ankle || !t->angle || (timed && !t->t_s)) {
        fs_track_free(t);
        return fs_fail(err, FS_NO_MEMORY, "out of memory for a path of %d samples", n);
    }
    return FS_OK;
}

void fs_track_free(fs_track *t)
{
    free(t->ankle);
    free(t->angle);
    free(t->t_s);
    memset(t, 0, sizeof *t);
}

static void sample(const fs_sim *sim, fs_track *t, int i)
{
    if (i >= t->n)
        return;
    if (t->t_s)
        t->t_s[i] = fs_sim_time(sim);
    fs_sim_ankle(sim, t->ankle[i]);
    for (int k = 0; k < t->nangles; k++)
        t->angle[i][k] = fs_sim_hinge_angle(sim, k);
}

/* A path sampled after every step (a hook that never stops the run). */
typedef struct sampler {
    fs_track *t;
    int i;
} sampler;

static int sample_step(void *user, fs_sim *sim)
{
    sampler *p = user;
    sample(sim, p->t, ++p->i);
    return 0;
}

fs_status fs_track_run(const fs_scenario *sc, const fs_sim_options *opts, double duration_s, fs_track *out,
                       fs_error *err)
{
    double h = sc->def.step_s;
    int steps = (int)ceil(duration_s / h - 1e-9), timed = sc->def.tolerance_m > 0;
    /* an error-controlled step takes at most one sample a pair of least steps */
    int samples = timed ? (int)ceil(duration_s / (2 * sc->def.step_min_s)) + 2 : steps + 1;
    int nangles = sc->geom.nhinges < FS_TRACK_ANGLES ? sc->geom.nhinges : FS_TRACK_ANGLES;
    fs_status s = track_alloc(out, h, samples, nangles, timed, err);
    if (s != FS_OK)
        return s;
    fs_sim *sim = NULL;
    s = fs_sim_new(sc, opts, &sim, err);
    if (s == FS_OK) {
        sample(sim, out, 0);
        sampler p = {out, 0};
        const fs_step_hook hooks[] = {{"sampled", sample_step, &p}};
        fs_drive_spec spec = {.max_steps = steps, .hooks = hooks, .nhooks = 1};
        fs_drive_result r;
        double start = fs_clock_s();
        s = fs_drive(sim, &spec, &r, err);
        out->wall_s = fs_clock_s() - start;
        out->check_class = fs_check_class_of(fs_sim_checks(sim)->first_drift);
        out->first_drift = fs_sim_checks(sim)->first_drift;
        out->max_loop_error_m = fs_sim_checks(sim)->max_loop_error_m;
        out->n = timed ? p.i + 1 : out->n;
        out->steps = fs_sim_step_stats(sim)->taken;
        out->rejected = fs_sim_step_stats(sim)->rejected;
        out->ode_steps = fs_sim_step_stats(sim)->ode_steps;
        out->sinkage_end_m = fs_sim_soil_grid(sim) ? fs_sim_soil_sinkage(sim, -1) : NAN;
    }
    fs_sim_free(sim);
    if (s != FS_OK)
        fs_track_free(out);
    return s;
}

fs_status fs_track_reference(const fs_design_def *d, const fs_foot_geom *g, const fs_reference_def *def, double dt_s,
                             int n, fs_track *out, fs_error *err)
{
    fs_reference_state *r = calloc((size_t)n, sizeof *r);
    if (!r)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for a reference of %d samples", n);
    fs_status s = fs_reference_run(d, g, def, dt_s, n, r, err);
    if (s == FS_OK)
        s = track_alloc(out, dt_s, n, FS_TRACK_ANGLES, 0, err);
    for (int i = 0; s == FS_OK && i < n; i++) {
        memcpy(out->ankle[i], r[i].ankle_m, sizeof out->ankle[i]);
        memcpy(out->angle[i], r[i].joint_rad, sizeof out->angle[i]);
    }
    free(r);
    return s;
}

/* ref's state at run's sample i, into ankle and angle: sample i * stride, or with run's own sample
 * times ref interpolated linearly at sample i's time (ref on its fixed grid); 0 past ref's end. */
static int ref_at(const fs_track *run, const fs_track *ref, long i, long stride, double ankle[3],
                  double angle[FS_TRACK_ANGLES])
{
    long j = i * stride;
    double u = 0;
    if (run->t_s) {
        double x = run->t_s[i] / ref->dt_s;
        j = (long)floor(x);
        u = x - (double)j;
    }
    if (j >= ref->n || (u > 0 && j + 1 >= ref->n))
        return 0;
    for (int k = 0; k < 3; k++)
        ankle[k] = u > 0 ? ref->ankle[j][k] + u * (ref->ankle[j + 1][k] - ref->ankle[j][k]) : ref->ankle[j][k];
    for (int k = 0; k < ref->nangles; k++)
        angle[k] = u > 0 ? ref->angle[j][k] + u * (ref->angle[j + 1][k] - ref->angle[j][k]) : ref->angle[j][k];
    return 1;
}

fs_status fs_track_compare(const fs_track *run, const fs_track *ref, fs_track_error *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    double ratio = run->dt_s / ref->dt_s;
    long stride = lround(ratio);
    if (!run->t_s && (stride < 1 || fabs(ratio - (double)stride) > 1e-6 * ratio))
        return fs_fail(err, FS_BAD_INPUT, "a step of %g s does not fall on the reference's %g s samples; give a whole "
                       "multiple of it", run->dt_s, ref->dt_s);
    if (run->nangles != ref->nangles)
        return fs_fail(err, FS_BAD_INPUT, "paths with %d and %d hinge angles cannot be compared", run->nangles,
                       ref->nangles);
    int nangles = run->nangles;
    double sum_m = 0, sum_rad = 0;
    double b[3], angle[FS_TRACK_ANGLES];
    for (long i = 0; i < run->n && ref_at(run, ref, i, stride, b, angle); i++) {
        const double *a = run->ankle[i];
        double d = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        out->max_m = fmax(out->max_m, d);
        out->end_dz_m = a[2] - b[2];
        sum_m += d * d;
        for (int k = 0; k < nangles; k++) {
            double e = fabs(run->angle[i][k] - angle[k]);
            out->max_rad = fmax(out->max_rad, e);
            sum_rad += e * e;
        }
        out->compared++;
    }
    if (out->compared) {
        out->rms_m = sqrt(sum_m / out->compared);
        out->rms_rad = nangles ? sqrt(sum_rad / (out->compared * nangles)) : NAN;
    }
    if (!nangles)
        out->max_rad = NAN;
    return FS_OK;
}
