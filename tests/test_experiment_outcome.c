/* Tests of the rules that judge a landing trial (fs_outcome.h), each on a history of states built
 * by hand: no simulation, so each rule is seen deciding exactly where its definition says. */
#include "fs_test.h"

#include "footsim/base/fs_error.h"
#include "footsim/experiment/fs_outcome.h"

#define DEG (M_PI / 180.0)
static const double H = 1e-3; /* the histories' sample interval, s */

/* The shipped defaults (docs/keys.md), a 3 s window. */
static fs_outcome_rules rules(void)
{
    return (fs_outcome_rules){.fall_lean_rad = 45 * DEG, .landed_lean_rad = 15 * DEG, .lost_ground_s = 0.25,
                              .sink_bound_m = 1e-3, .rest_speed_m_per_s = 1e-2, .rest_hold_s = 0.1, .window_s = 3,
                              .motion_window_s = 0.5, .motion_decay = 0.9, .motion_floor_J = 1.35e-3};
}

/* A state of a history: lean (deg), kinetic energy, fastest speed, contacts, as functions of time. */
typedef struct history {
    double (*lean_deg)(double t);
    double (*kinetic_J)(double t);
    double (*speed)(double t);
    int (*contacts)(double t);
} history;

/* Feeds the history from t = H until the judge stops it or the window ends, then finishes with
 * penetration_m; returns the time it stopped. */
static double judge(fs_judge *j, const fs_outcome_rules *r, const history *h, double penetration_m)
{
    fs_judge_init(j, r);
    fs_outcome_sample s = {0};
    long n = lround(r->window_s / H);
    for (long i = 1; i <= n; i++) {
        double t = i * H;
        s = (fs_outcome_sample){t, h->lean_deg(t) * DEG, h->kinetic_J(t), h->speed(t), h->contacts(t), 1};
        if (fs_judge_step(j, &s))
            break;
    }
    fs_judge_finish(j, &s, penetration_m);
    return s.t_s;
}

/* Falls 5 mm (touchdown at 32 ms), then as each test says. */
static int in_contact_after_touchdown(double t) { return t >= 0.032 ? 4 : 0; }
static double still(double t) { return t < 0.2 ? 0.3 : 1e-3; }
static double still_energy(double t) { return t < 0.2 ? 1.0 : 1e-6; }
static double upright(double t) { return t < 0.2 ? 2.0 : 1.0; }
static double rocking_speed(double t) { (void)t; return 0.05; }

/* Leaning past 45 degrees decides at once, however the rest of the history goes. */
static double toppling(double t) { return 60 * t * t; } /* 45 deg at t = 0.866 s */
static void leaning_past_the_fall_angle_is_a_fall_at_once(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    history h = {toppling, still_energy, rocking_speed, in_contact_after_touchdown};
    double t = judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_FELL && j.rule == FS_RULE_LEANED);
    CHECK_NEAR(t, sqrt(45.0 / 60), 1.5 * H);
    /* just under the angle for the whole window: not this rule */
    r.fall_lean_rad = 61 * DEG, r.window_s = 1; /* the lean reaches 60 deg at t = 1 */
    judge(&j, &r, &h, 0);
    CHECK(j.rule != FS_RULE_LEANED);
}

/* No contact for lost_ground_s after touchdown is a fall; a shorter flight (a hop) is not. */
static int hops(double t) { return t >= 0.032 && !(t >= 0.05 && t < 0.25) ? 4 : 0; } /* 0.2 s off */
static int leaves(double t) { return t >= 0.032 && t < 0.5 ? 4 : 0; }
static void losing_the_ground_for_good_is_a_fall(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    history h = {upright, still_energy, rocking_speed, leaves};
    double t = judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_FELL && j.rule == FS_RULE_LOST_GROUND);
    CHECK_NEAR(t, 0.5 - H + 0.25, 1.5 * H); /* last contact at 0.499 s */
    h.contacts = hops, h.speed = still;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_LANDED && j.rule == FS_RULE_AT_REST);
    /* before touchdown the foot has no ground to lose: a long fall is not this rule */
    r.lost_ground_s = 0.01;
    h.contacts = in_contact_after_touchdown;
    judge(&j, &r, &h, 0);
    CHECK(j.rule == FS_RULE_AT_REST);
}

/* At rest (every body slower than the rest speed for rest_hold_s): landed when upright and in
 * contact; fell when not upright; the trial stops when the hold is complete. */
static double leaning_20(double t) { return t < 0.2 ? 10 : 20; }
static void at_rest_upright_is_landed_and_tilted_is_a_fall(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    history h = {upright, still_energy, still, in_contact_after_touchdown};
    double t = judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_LANDED && j.rule == FS_RULE_AT_REST);
    CHECK_NEAR(t, 0.2 + r.rest_hold_s, 1.5 * H); /* slow from 0.2 s, held for 0.1 s */
    h.lean_deg = leaning_20;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_FELL && j.rule == FS_RULE_RESTED_TILTED);
}

/* Sinking deeper than the terrain's bound is a fall, judged at the end; soft ground's bound lets
 * the same depth land. */
static void sinking_past_the_bound_is_a_fall(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    history h = {upright, still_energy, still, in_contact_after_touchdown};
    judge(&j, &r, &h, 2e-3);
    CHECK(j.outcome == FS_FELL && j.rule == FS_RULE_SANK);
    judge(&j, &r, &h, 0.9e-3);
    CHECK(j.outcome == FS_LANDED);
    r.sink_bound_m = 5e-3; /* terrains/soft.ini */
    judge(&j, &r, &h, 2e-3);
    CHECK(j.outcome == FS_LANDED);
}

/* Rocking upright until the window ends: landed when the mean kinetic energy of the last 0.5 s is
 * at most 0.9 of the 0.5 s before (decaying as exp(-t / tau)); undecided when it is not (steady
 * rocking, or growing); a lean past 15 degrees at the end is never landed. */
static double tau_s;
static double rocking_energy(double t) { return 0.05 * exp(-t / tau_s) * (1 + sin(2 * M_PI * 4 * t)); }
static double leaning_16(double t) { return t < 0.2 ? 2 : 16; }
static void rocking_that_dies_out_is_landed_steady_rocking_undecided(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    history h = {upright, rocking_energy, rocking_speed, in_contact_after_touchdown};
    /* the spans' means differ by exp(-0.5 / tau): 0.9 at tau = 4.75 s */
    tau_s = 3;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_LANDED && j.rule == FS_RULE_DYING);
    tau_s = 6;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_UNDECIDED && j.rule == FS_RULE_WINDOW);
    tau_s = -5; /* growing */
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_UNDECIDED);
    tau_s = 3;
    h.lean_deg = leaning_16;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_UNDECIDED);
    /* motion as slow as rest counts as died out, whatever its trend */
    tau_s = 1e9;
    h.lean_deg = upright;
    r.motion_floor_J = 0.2;
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_LANDED && j.rule == FS_RULE_DYING);
}

/* Out of contact when the window ends is never landed. */
static int lifted_at_end(double t) { return t >= 0.032 && t < 2.9 ? 4 : 0; }
static void out_of_contact_at_the_end_is_not_landed(void)
{
    fs_outcome_rules r = rules();
    fs_judge j;
    tau_s = 1;
    history h = {upright, rocking_energy, rocking_speed, lifted_at_end};
    judge(&j, &r, &h, 0);
    CHECK(j.outcome == FS_UNDECIDED);
}

/* Names: every rule and outcome has one, and an unknown number says so. */
static void every_rule_and_outcome_has_a_name(void)
{
    for (int i = 0; i < FS_NRULES; i++)
        CHECK(strcmp(fs_rule_name(i), "unknown"));
    for (int i = 0; i < FS_NOUTCOMES; i++)
        CHECK(strcmp(fs_outcome_name(i), "unknown"));
    CHECK(!strcmp(fs_rule_name(FS_NRULES), "unknown") && !strcmp(fs_outcome_name(-1), "unknown"));
}

FS_TEST_MAIN(TEST(leaning_past_the_fall_angle_is_a_fall_at_once), TEST(losing_the_ground_for_good_is_a_fall),
             TEST(at_rest_upright_is_landed_and_tilted_is_a_fall), TEST(sinking_past_the_bound_is_a_fall),
             TEST(rocking_that_dies_out_is_landed_steady_rocking_undecided),
             TEST(out_of_contact_at_the_end_is_not_landed), TEST(every_rule_and_outcome_has_a_name))
