/* api_trial.c: landing trials, the stiffness model and the pitch-stiffness law behind the handles
 * of footsim/api/fs_api.h. */
#include "footsim/api/fs_api.h"
#include "footsim/analysis/fs_analysis.h"
#include "footsim/campaign/fs_campaign.h"
#include "footsim/experiment/fs_trial.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

fs_trial_result *fs_trial_open(const fs_scenario *sc, int seed, fs_error *err)
{
    if (fs_scenario_require(sc, "trial", err) != FS_OK)
        return NULL;
    fs_trial_result *r = calloc(1, sizeof *r);
    if (!r) {
        fs_fail(err, FS_NO_MEMORY, "%s: no memory for the trial's result", sc->path);
        return NULL;
    }
    if (fs_trial_run_scenario(sc, seed, NULL, r, err) != FS_OK) {
        free(r);
        return NULL;
    }
    return r;
}

void fs_trial_close(fs_trial_result *r) { free(r); }

const char *fs_trial_outcome(const fs_trial_result *r) { return fs_outcome_name(r->outcome); }
const char *fs_trial_rule(const fs_trial_result *r) { return fs_rule_name(r->rule); }
const char *fs_trial_failure(const fs_trial_result *r) { return r->failure; }
int fs_trial_seed(const fs_trial_result *r) { return r->draw.seed; }

int fs_trial_metric_count(void) { return FS_CAMPAIGN_NMETRICS; }

const char *fs_trial_metric_name(int m)
{
    return m >= 0 && m < FS_CAMPAIGN_NMETRICS ? fs_campaign_metrics[m].name : NULL;
}

int fs_trial_metric_find(const char *name)
{
    for (int m = 0; name && m < FS_CAMPAIGN_NMETRICS; m++)
        if (!strcmp(fs_campaign_metrics[m].name, name))
            return m;
    return -1;
}

double fs_trial_metric(const fs_trial_result *r, int m)
{
    return m >= 0 && m < FS_CAMPAIGN_NMETRICS ? fs_metric_value(r, m) : NAN;
}

fs_status fs_scenario_chain_stiffness(const fs_scenario *sc, int chain, double exact[4], double eq4[4], fs_error *err)
{
    if (sc->geom.kind == FS_FOOT_FLAT)
        return fs_fail(err, FS_BAD_INPUT, "%s: the flat foot has no toe chains; the stiffness model is the "
                       "biomimetic foot's (design kind = biomimetic)", sc->path);
    if (chain < 0 || chain >= FS_CHAINS)
        return fs_fail(err, FS_BAD_INPUT, "chain: %d is not a chain; give 0 to %d", chain, FS_CHAINS - 1);
    fs_chain_stiffness K[FS_CHAINS];
    fs_stiffness_analytic(&sc->geom, K);
    for (int i = 0; i < 4; i++) {
        if (exact)
            exact[i] = K[chain].exact[i / 2][i % 2];
        if (eq4)
            eq4[i] = K[chain].eq4[i / 2][i % 2];
    }
    return FS_OK;
}

fs_status fs_scenario_pitch_stiffness(const fs_scenario *sc, double load_N, double *K_N_m_per_rad, fs_error *err)
{
    if (!(load_N >= 0) || !isfinite(load_N))
        return fs_fail(err, FS_BAD_INPUT, "load_N: %g is not a load; give a finite force of 0 N or more", load_N);
    return fs_pitch_stiffness_foot(sc, load_N, K_N_m_per_rad, err);
}

fs_status fs_scenario_pitch_law(const fs_scenario *sc, double K_foot, double *K, double *demand,
                                double *critical_height_m, double *lean_rad, int *stands, fs_error *err)
{
    const fs_robot_def *robot = &sc->def.robot;
    double g = sc->def.gravity_m_per_s2;
    if (robot->mass_kg <= 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: the law is for a robot and this scenario has none (mass 0): name one "
                       "in [robot] with design = robots/single_tall.ini (or drop_weight, rig)", sc->path);
    if (isnan(K_foot)) {
        /* as a campaign's law: the foot under the robot's weight; an arch that folds has none left */
        fs_error ignored;
        if (fs_pitch_stiffness_foot(sc, robot->mass_kg * g, &K_foot, &ignored) != FS_OK)
            K_foot = 0;
    } else if (!(K_foot >= 0))
        return fs_fail(err, FS_BAD_INPUT, "K_foot: %g N m/rad is not a stiffness; give 0 or more (NAN: the "
                       "scenario's foot)", K_foot);
    fs_pitch_law law;
    fs_pitch_law_apply(K_foot, robot, g, sc->def.landed_tilt_deg * M_PI / 180, &law);
    if (K)
        *K = law.held ? INFINITY : law.K;
    if (demand)
        *demand = law.demand;
    if (critical_height_m)
        *critical_height_m = law.held ? INFINITY : law.critical_height_m;
    if (lean_rad)
        *lean_rad = law.lean_rad;
    if (stands)
        *stands = law.stands;
    return FS_OK;
}
