/* Tests of analysis_reference.c, the planar dynamic reference: it agrees with its own linearisation,
 * conserves energy when nothing dissipates, and does not depend on its tolerance. */
#include "fs_test.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_track.h"

#include <stdlib.h>

static const char *DESIGN = "scenarios/feet/biomimetic.ini";
enum { CHAIN = 2 }; /* the middle toe: unsplayed, in the heel's plane */

static int load_design(const char *const *set, int nset, fs_design_def *d, fs_foot_geom *g)
{
    fs_error err;
    if (fs_design_load(DESIGN, set, nset, d, g, &err) == FS_OK)
        return 1;
    fprintf(stderr, "  %s\n", err.message);
    fs_test_failures++;
    return 0;
}

/* The design with no damping: nothing dissipates. */
static int load_undamped(fs_design_def *d, fs_foot_geom *g)
{
    const char *set[] = {"springs.c_d1_Ns_per_m=0", "springs.c_d2_Ns_per_m=0", "springs.c_d3_Ns_per_m=0"};
    return load_design(set, 3, d, g);
}

/* Undamped and unloaded, started at rest a small way along a mode: it swings at the mode's
 * linearised frequency. The amplitude, 1e-6 rad, keeps the nonlinear shift (of order the amplitude
 * squared) near 1e-12, and the crossings are timed to far better than 0.1 % of a period. */
static void test_small_oscillation_frequency(void)
{
    fs_design_def d;
    fs_foot_geom g;
    if (!load_undamped(&d, &g))
        return;
    fs_error err;
    double omega[2], shape[2][2];
    CHECK(fs_reference_modes(&d, &g, CHAIN, omega, shape, &err) == FS_OK);
    CHECK(omega[0] > 0 && omega[1] > omega[0]);
    for (int k = 0; k < 2; k++) {
        const double amp = 1e-6, period = 2 * M_PI / omega[k];
        const int per = 400, periods = 10, n = per * periods + 1;
        fs_reference_def def = {CHAIN, 0, 0, 0, 0, 1e-12, {amp * shape[k][0], amp * shape[k][1]}};
        fs_reference_state *s = calloc((size_t)n, sizeof *s);
        REQUIRE(fs_reference_run(&d, &g, &def, period / per, n, s, &err) == FS_OK);
        /* the ankle joint angle swings about 0: time its upward zero crossings */
        double first = -1, last = -1;
        int crossings = 0;
        for (int i = 1; i < n; i++) {
            double a = s[i - 1].joint_rad[0], b = s[i].joint_rad[0];
            if (a < 0 && b >= 0) {
                double t = s[i - 1].t_s + (s[i].t_s - s[i - 1].t_s) * a / (a - b);
                if (first < 0)
                    first = t;
                last = t;
                crossings++;
            }
        }
        CHECK(crossings >= periods - 1);
        double measured = (last - first) / (crossings - 1);
        printf("  mode %d: omega %.6g rad/s, shape (%.4f, %.4f), period %.9g s measured %.9g s\n", k + 1, omega[k],
               shape[k][0], shape[k][1], period, measured);
        CHECK_NEAR(measured / period, 1.0, 1e-3);
        free(s);
    }
}

/* Undamped and unloaded, but gravity on and started well away from the neutral pose: nothing
 * dissipates, so the total energy stays what it was up to the integrator's error (tolerance 1e-12
 * per step over some 1e4 steps: 1e-8 of the energy at most). This checks the velocity terms and
 * the loop's acceleration terms, which the small-oscillation test cannot see. */
static void test_energy_conserved(void)
{
    fs_design_def d;
    fs_foot_geom g;
    if (!load_undamped(&d, &g))
        return;
    fs_error err;
    enum { N = 201 };
    static fs_reference_state s[N];
    fs_reference_def def = {CHAIN, 0, 0, 9.81, 0, 1e-12, {-0.03, 0.03}};
    fs_status st = fs_reference_run(&d, &g, &def, 1e-4, N, s, &err);
    if (st != FS_OK)
        fprintf(stderr, "  %s\n", err.message);
    CHECK(st == FS_OK);
    double E0 = s[0].energy_J, swing = 0, drift = 0;
    for (int i = 0; i < N; i++) {
        drift = fmax(drift, fabs(s[i].energy_J - E0));
        swing = fmax(swing, fabs(s[i].joint_rad[1] - s[0].joint_rad[1]));
    }
    printf("  energy %.9g J, drift %.3g J, midfoot swing %.3g rad\n", E0, drift, swing);
    CHECK(swing > 0.01); /* it did move a lot */
    CHECK(drift <= 1e-8 * fabs(E0));
}

/* The paper's Fig. 11 transient (26 kg at the ankle, 20 ms ramp) at tolerances 1e-10 and 5e-11:
 * the ankle paths differ by less than 1e-9 m. */
static void test_tolerance_halved(void)
{
    fs_design_def d;
    fs_foot_geom g;
    if (!load_design(NULL, 0, &d, &g))
        return;
    fs_error err;
    enum { N = 201 };
    static fs_reference_state a[N], b[N];
    fs_reference_def def = {CHAIN, 26 * 9.81, 0.02, 9.81, 0, 1e-10, {0, 0}};
    REQUIRE(fs_reference_run(&d, &g, &def, 1e-3, N, a, &err) == FS_OK);
    def.tolerance = 5e-11;
    REQUIRE(fs_reference_run(&d, &g, &def, 1e-3, N, b, &err) == FS_OK);
    double diff = 0;
    for (int i = 0; i < N; i++)
        for (int k = 0; k < 3; k++)
            diff = fmax(diff, fabs(a[i].ankle_m[k] - b[i].ankle_m[k]));
    printf("  ankle drop at 0.2 s %.6g m; tolerance halved moves it by %.3g m\n", a[0].ankle_m[2] - a[N - 1].ankle_m[2],
           diff);
    CHECK(a[0].ankle_m[2] - a[N - 1].ankle_m[2] > 1e-6);
    CHECK(diff < 1e-9);
}

/* ODE's pinned chain at a fine step against the reference over the Fig. 11 transient. */
static void test_ode_against_reference(void)
{
    const char *set[] = {"run.step_s=1e-5", "run.stepper=step", "run.springs=implicit"};
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 3, &sc, &err) == FS_OK);
    const double T = 0.2, dt = 1e-5;
    fs_reference_def def = {CHAIN, sc.def.load_kg * sc.def.gravity_m_per_s2, sc.def.ramp_s, sc.def.gravity_m_per_s2,
                            0, 1e-10, {0, 0}};
    fs_track ref, run;
    CHECK(fs_track_reference(&sc.design, &sc.geom, &def, dt, (int)lround(T / dt) + 1, &ref, &err) == FS_OK);
    fs_sim_options opts = {.pinned_chain = CHAIN + 1};
    REQUIRE(fs_track_run(&sc, &opts, T, &run, &err) == FS_OK);
    fs_track_error e;
    CHECK(fs_track_compare(&run, &ref, &e, &err) == FS_OK);
    double travel = 0, swing = 0, speed = 0, rate = 0;
    for (int i = 0; i < ref.n; i++) {
        if (i > 0) {
            double v[3] = {ref.ankle[i][0] - ref.ankle[i - 1][0], ref.ankle[i][1] - ref.ankle[i - 1][1],
                           ref.ankle[i][2] - ref.ankle[i - 1][2]};
            speed = fmax(speed, sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / dt);
            for (int k = 0; k < FS_TRACK_ANGLES; k++)
                rate = fmax(rate, fabs(ref.angle[i][k] - ref.angle[i - 1][k]) / dt);
        }
        double d[3] = {ref.ankle[i][0] - ref.ankle[0][0], ref.ankle[i][1] - ref.ankle[0][1], ref.ankle[i][2] - ref.ankle[0][2]};
        travel = fmax(travel, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        for (int k = 0; k < FS_TRACK_ANGLES; k++)
            swing = fmax(swing, fabs(ref.angle[i][k]));
    }
    printf("  ankle travel %.4g m (fastest %.3g m/s), largest angle %.4g rad (fastest %.3g rad/s)\n", travel, speed,
           swing, rate);
    printf("  ODE error max %.3g m rms %.3g m, angles max %.3g rad rms %.3g rad\n",
           e.max_m, e.rms_m, e.max_rad, e.rms_rad);
    CHECK(e.compared == run.n);
    /* the bound, 0.1 mm, says little about a 45-micron travel; the physics says more: ODE's
     * step is first order and the load acts as it was at the start of each step, so the error is
     * of the order of one step's travel at the fastest: allow two. */
    CHECK(e.max_m <= 1e-4);
    CHECK(e.max_m <= 2 * sc.def.step_s * speed);
    CHECK(e.max_rad <= 2 * sc.def.step_s * rate);
    fs_track_free(&ref);
    fs_track_free(&run);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN({"ode_against_reference", test_ode_against_reference}, {"small_oscillation_frequency", test_small_oscillation_frequency},
             {"energy_conserved", test_energy_conserved}, {"tolerance_halved", test_tolerance_halved})
