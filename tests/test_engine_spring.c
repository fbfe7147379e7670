/* Tests of sim_spring.c: both spring-damper implementations against the damped oscillator. */
#include "fs_test.h"

#include "footsim/sim/fs_spring.h"
#include "footsim/base/fs_error.h"

#include <ode/ode.h>
#include <string.h>

enum { MAX_PEAKS = 64 };

typedef struct oscillation { double omega_d, sigma; int peaks; } oscillation;

/* A mass m on a spring (k, c) to a fixed anchor, released 1 cm from rest; the damped frequency
 * and decay rate read off the peaks of its displacement. */
static oscillation oscillate(fs_spring_impl impl, double m, double k, double c, double h, double duration)
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

/* Frequency and decay within 1 % at h = 1e-4 s. The implicit (backward Euler) spring adds a
 * numerical decay of about omega0^2 h / 2 = 0.06 1/s here, 0.6 % of the physical sigma = 10 1/s;
 * the explicit one errs by O(sigma h) and O((omega h)^2), far below 1 %. */
static void check_oscillator(fs_spring_impl impl)
{
    const double m = 10, k = 12000, c = 200, h = 1e-4;
    double omega0 = sqrt(k / m), sigma = c / (2 * m), omega_d = sqrt(omega0 * omega0 - sigma * sigma);
    oscillation o = oscillate(impl, m, k, c, h, 0.8);
    CHECK(o.peaks >= 6);
    CHECK_NEAR(o.omega_d / omega_d, 1.0, 0.01);
    CHECK_NEAR(o.sigma / sigma, 1.0, 0.01);
}

static void implicit_spring_is_a_damped_oscillator(void) { check_oscillator(FS_SPRING_IMPLICIT); }
static void explicit_spring_is_a_damped_oscillator(void) { check_oscillator(FS_SPRING_EXPLICIT); }

/* ERP = hk/(hk + c) and CFM = 1/(hk + c), reset when the step changes. */
static void implicit_spring_follows_the_step(void)
{
    dWorldID world = dWorldCreate();
    dBodyID b = dBodyCreate(world);
    fs_spring s;
    double p1[3] = {0.1, 0, 0}, p2[3] = {0, 0, 0};
    fs_spring_init(&s, world, FS_SPRING_IMPLICIT, b, NULL, p1, p2, 12000, 200, 0.1);
    for (int i = 0; i < 2; i++) {
        double h = i == 0 ? 1e-4 : 1e-3;
        fs_spring_prepare(&s, h);
        CHECK_NEAR(dJointGetDBallParam(s.joint, dParamERP), h * 12000 / (h * 12000 + 200), 1e-15);
        CHECK_NEAR(dJointGetDBallParam(s.joint, dParamCFM), 1 / (h * 12000 + 200), 1e-15);
    }
    dWorldDestroy(world);
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
             TEST(implicit_spring_follows_the_step), TEST(spring_reports_its_state))
