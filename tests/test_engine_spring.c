/* Tests of sim_spring.c: both spring-damper implementations against the damped oscillator. */
#include "fs_test.h"

#include "sim/sim_spring.h"
#include "footsim/base/fs_error.h"

#include <ode/ode.h>
#include <string.h>

enum { MAX_PEAKS = 64 };

typedef struct oscillation { double omega_d, sigma; int peaks; } oscillation;

/* A mass m on a spring (k, c) to a fixed anchor, released 1 cm from rest; the damped frequency
 * and decay rate read off the peaks of its displacement. */
static oscillation oscillate(fs_spring_impl impl, int correct, double m, double k, double c, double h, double duration)
{
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, 0);
    dBodyID b = dBodyCreate(world);
    dMass mass;
    dMassSetSphereTotal(&mass, m, 0.01);
    dBodySetMass(b, &mass);
    const double rest = 0.1, x0 = 0.01;
    dBodySetPosition(b, rest + x0, 0, 0);
    fs_spring s;
    double p1[3] = {rest + x0, 0, 0}, p2[3] = {0, 0, 0};
    fs_spring_init(&s, world, impl, b, NULL, p1, p2, k, c, rest);
    s.damping_correction = correct;
    double prev2 = x0, prev1 = x0, t = 0;
    double tp[MAX_PEAKS], xp[MAX_PEAKS];
    int n = 0;
    long steps = lround(duration / h);
    for (long i = 0; i < steps && n < MAX_PEAKS; i++) {
        fs_spring_prepare(&s, h);
        dWorldStep(world, h);
        t += h;
        double x = dBodyGetPosition(b)[0] - rest;
        /* a peak of |x| at the previous sample: refine it with a parabola through three samples */
        if (i >= 2 && fabs(prev1) > fabs(prev2) && fabs(prev1) >= fabs(x)) {
            double denom = prev2 - 2 * prev1 + x;
            double off = denom != 0 ? 0.5 * (prev2 - x) / denom : 0;
            tp[n] = t - h + off * h;
            xp[n] = fabs(prev1 - 0.25 * (prev2 - x) * off);
            n++;
        }
        prev2 = prev1;
        prev1 = x;
    }
    dWorldDestroy(world);
    oscillation o = {0, 0, n};
    if (n >= 2) {
        o.omega_d = M_PI * (n - 1) / (tp[n - 1] - tp[0]);
        o.sigma = log(xp[0] / xp[n - 1]) / (tp[n - 1] - tp[0]);
    }
    return o;
}

/* Frequency and decay within 1 % at h = 1e-4 s. Plain implicit Euler would add a numerical decay
 * of about omega0^2 h / 2 = 0.06 1/s here, 0.6 % of the physical sigma = 10 1/s; both
 * implementations err by O(sigma h) and O((omega h)^2), far below 1 %. */
static void check_oscillator(fs_spring_impl impl)
{
    const double m = 10, k = 12000, c = 200, h = 1e-4;
    double omega0 = sqrt(k / m), sigma = c / (2 * m), omega_d = sqrt(omega0 * omega0 - sigma * sigma);
    oscillation o = oscillate(impl, 1, m, k, c, h, 0.8);
    fprintf(stderr, "  %s: frequency %+.3f %%, decay %+.3f %%\n", impl == FS_SPRING_IMPLICIT ? "implicit" : "explicit",
            100 * (o.omega_d / omega_d - 1), 100 * (o.sigma / sigma - 1));
    CHECK(o.peaks >= 6);
    CHECK_NEAR(o.omega_d / omega_d, 1.0, 0.01);
    CHECK_NEAR(o.sigma / sigma, 1.0, 0.01);
}

static void implicit_spring_is_a_damped_oscillator(void) { check_oscillator(FS_SPRING_IMPLICIT); }
static void explicit_spring_is_a_damped_oscillator(void) { check_oscillator(FS_SPRING_EXPLICIT); }

/* ERP = hk/(hk + C) and CFM = 1/(hk + C), reset when the step changes: C = c - hk corrected while
 * hk <= c (ERP = hk/c, CFM = 1/c), 0 beyond it (ERP 1, CFM 1/(hk)); C = c uncorrected. */
static void implicit_spring_follows_the_step(void)
{
    dWorldID world = dWorldCreate();
    dBodyID b = dBodyCreate(world);
    for (int correct = 0; correct < 2; correct++) {
        fs_spring s;
        double p1[3] = {0.1, 0, 0}, p2[3] = {0, 0, 0};
        fs_spring_init(&s, world, FS_SPRING_IMPLICIT, b, NULL, p1, p2, 12000, 200, 0.1);
        CHECK(s.damping_correction == 1); /* the default */
        s.damping_correction = correct;
        for (int i = 0; i < 3; i++) {
            double h = i == 0 ? 1e-4 : i == 1 ? 1e-3 : 0.1; /* hk = 1.2, 12 and 1200 against c = 200 */
            double denom = correct ? fmax(200, h * 12000) : h * 12000 + 200;
            fs_spring_prepare(&s, h);
            CHECK_NEAR(dJointGetDBallParam(s.joint, dParamERP), h * 12000 / denom, 1e-15);
            CHECK_NEAR(dJointGetDBallParam(s.joint, dParamCFM), 1 / denom, 1e-15);
        }
        dJointDestroy(s.joint);
    }
    dWorldDestroy(world);
}

/* A stiff spring-damper at a step where its own numerical damping k h is half its c (a contact's
 * case: k h is 9 % of c for the sole on the ground at the default step, 90 % at 1e-3 s). m = 10 kg,
 * k = 1e6 N/m, c = 200 N s/m, h = 1e-4 s: omega0 = 316 1/s, sigma = c / 2m = 10 1/s. Corrected,
 * the decay is sigma to O(sigma h) + O((omega0 h)^2), 0.1 % each: within 1 %. Plain implicit
 * Euler decays at (c + k h) / 2m = 15 1/s less O(.), 50 % fast: outside 40 %. */
static void stiff_spring_decays_at_its_own_damping(void)
{
    const double m = 10, k = 1e6, c = 200, h = 1e-4, sigma = c / (2 * m);
    oscillation corrected = oscillate(FS_SPRING_IMPLICIT, 1, m, k, c, h, 0.25);
    oscillation plain = oscillate(FS_SPRING_IMPLICIT, 0, m, k, c, h, 0.25);
    fprintf(stderr, "  k h = c / 2: decay corrected %+.2f %%, plain %+.2f %%\n", 100 * (corrected.sigma / sigma - 1),
            100 * (plain.sigma / sigma - 1));
    CHECK(corrected.peaks >= 20 && plain.peaks >= 20);
    CHECK_NEAR(corrected.sigma / sigma, 1.0, 0.01);
    CHECK(plain.sigma / sigma > 1.4);
    CHECK_NEAR(corrected.omega_d / sqrt(k / m - sigma * sigma), 1.0, 0.01);
}

/* Length, force and energy reported for a spring held stretched by 1 mm. */
static void spring_reports_its_state(void)
{
    dWorldID world = dWorldCreate();
    dBodyID b = dBodyCreate(world);
    dBodySetPosition(b, 0.101, 0, 0);
    for (int impl = 0; impl < 2; impl++) {
        fs_spring s;
        double p1[3] = {0.101, 0, 0}, p2[3] = {0, 0, 0};
        fs_spring_init(&s, world, (fs_spring_impl)impl, b, NULL, p1, p2, 12000, 200, 0.1);
        fs_spring_state st = fs_spring_measure(&s);
        CHECK_NEAR(st.length_m, 0.101, 1e-15);
        CHECK_NEAR(st.force_N, 12.0, 1e-9);
        CHECK_NEAR(st.energy_J, 0.5 * 12000 * 1e-6, 1e-12);
    }
    dWorldDestroy(world);
}

FS_TEST_MAIN(TEST(implicit_spring_is_a_damped_oscillator), TEST(explicit_spring_is_a_damped_oscillator),
             TEST(implicit_spring_follows_the_step), TEST(stiff_spring_decays_at_its_own_damping),
             TEST(spring_reports_its_state))
