/* campaign_summary.c: the statistics of a campaign's cells (success rates with Wilson intervals,
 * medians of the metrics of campaign_metric.c) and the law's prediction for each. */
#include "campaign_internal.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/base/fs_stats.h"
#include "footsim/experiment/fs_trial.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { FOLD_CACHE = 64 };

/* ---- statistics --------------------------------------------------------------------------- */

void fs_wilson(int k, int n, double *low, double *high)
{
    const double z = 1.959963984540054; /* the 97.5 % quantile of the standard normal */
    double p = (double)k / n, z2n = z * z / n;
    double centre = (p + z2n / 2) / (1 + z2n);
    double half = z / (1 + z2n) * sqrt(p * (1 - p) / n + z2n / (4.0 * n));
    *low = fmax(0, centre - half);
    *high = fmin(1, centre + half);
    /* at k = 0 or k = n the bound is exactly 0 or 1 (centre and half agree but for rounding) */
    if (k == 0)
        *low = 0;
    if (k == n)
        *high = 1;
}

const char *fs_law_name(int law) { return law == FS_LAW_STANDS ? "stands" : law == FS_LAW_TOPPLES ? "topples" : "n/a"; }

/* The foot's saturation for the drop law, worked out once per foot and load (a sweep's cells share
 * them): its fold moment up to the full footprint's edge moment, and the travel under the weight
 * within which a shape near the ground comes to bear (the arch's ankle drop and the contact layer). */
typedef struct foot_fold {
    const fs_scenario *sc;
    double K, load_N, fold_N_m, travel_m;
} foot_fold;

/* Two scenarios whose foot is the same design, springs and all. */
static int same_foot(const fs_scenario *a, const fs_scenario *b)
{
    return !memcmp(&a->design, &b->design, sizeof a->design) && a->def.contact_layer_m == b->def.contact_layer_m;
}

/* Two scenarios whose arch is the same: a biomimetic foot's K, fold and travel are the model's on
 * rigid ground and do not depend on its sole's contact (a band's ends differ in it); a flat sole's K
 * is its contacts', so for it the whole foot must be the same. */
static int same_arch(const fs_scenario *a, const fs_scenario *b)
{
    if (a->geom.kind != FS_FOOT_BIOMIMETIC || b->geom.kind != FS_FOOT_BIOMIMETIC)
        return same_foot(a, b);
    fs_design_def da;
    memcpy(&da, &a->design, sizeof da);
    da.sole_stiffness_N_per_m = b->design.sole_stiffness_N_per_m;
    da.sole_damping_Ns_per_m = b->design.sole_damping_Ns_per_m;
    da.sole_mu = b->design.sole_mu;
    return !memcmp(&da, &b->design, sizeof da) && a->def.contact_layer_m == b->def.contact_layer_m;
}

static void fold_of(const fs_scenario *sc, double K, double load_N, foot_fold *cache, int *ncache, foot_fold *out)
{
    for (int i = 0; i < *ncache; i++)
        if (cache[i].K == K && cache[i].load_N == load_N && same_arch(cache[i].sc, sc)) {
            *out = cache[i];
            return;
        }
    double g = sc->def.gravity_m_per_s2;
    fs_error err;
    *out = (foot_fold){sc, K, load_N, INFINITY, sc->def.contact_layer_m};
    if (sc->geom.kind == FS_FOOT_BIOMIMETIC) {
        /* up to the moment that puts the centre of pressure at the foot's front: no edge lies further */
        double reach = 0;
        for (int i = 0; i < sc->geom.nspheres; i++)
            reach = fmax(reach, sc->geom.sphere[i].centre.x + sc->geom.sphere[i].radius_m - sc->geom.ankle.x);
        if (fs_pitch_fold_moment(&sc->geom, load_N, g, load_N * reach, &out->fold_N_m, &err) != FS_OK)
            out->fold_N_m = 0; /* no equilibrium at all: nothing held */
        fs_planar_load pl = {.load_N = load_N, .gravity_m_per_s2 = g};
        fs_planar_result res;
        if (fs_planar_equilibrium(&sc->design, &sc->geom, 0, &pl, &res, &err) == FS_OK && res.converged)
            out->travel_m += fmax(0, res.ankle_drop_m);
    }
    if (*ncache < FOLD_CACHE)
        cache[(*ncache)++] = *out;
}

/* A band end's contact in the laws (fs_analysis.h, fs_pitch_contact_series): the end's contact
 * stiffness per point k against the band's stiffest k_ref, and the rebound gain of its restitution.
 * Without a band (on = 0) the laws are those of a rigid, plastic contact, as they always were. */
typedef struct law_contact {
    int on;
    double k_N_per_m, k_ref_N_per_m, restitution, gain;
} law_contact;

static const law_contact no_contact = {0, 0, 0, 0, 1};

/* Two materials in contact: stiffness or damping in series, as the sim's contacts take them. */
static double in_series(double a, double b) { return a > 0 && b > 0 ? a * b / (a + b) : 0; }

static double contact_k(const fs_scenario *sc)
{
    return in_series(sc->design.sole_stiffness_N_per_m, sc->terrain.def.stiffness_N_per_m);
}

/* Scenario sc's contact, against the band's stiffest k_ref. The mass one point decelerates is the
 * robot's and the foot's over the foot's spheres (docs/contact.md's convention, the MJCF export's:
 * 26.27 kg / 12 = 2.19 kg for Table I under single_tall, so that the band's ends are the damping
 * ratios 0.22 and 1.12 it names); a flat sole has no series term (its K is its contacts' already). */
static law_contact contact_of(const fs_scenario *sc, double k_ref)
{
    law_contact lc = no_contact;
    lc.on = 1;
    lc.k_N_per_m = sc->geom.kind == FS_FOOT_BIOMIMETIC ? contact_k(sc) : k_ref;
    lc.k_ref_N_per_m = k_ref;
    fs_foot_geom two; /* a biped's two feet, its body counted in its total already */
    const fs_foot_geom *g = fs_scenario_geometry(sc, &two);
    double carried = g->nfeet > 1 ? g->total_mass_kg : sc->def.robot.mass_kg + g->total_mass_kg;
    double m = g->nspheres > 0 ? carried / g->nspheres : 0;
    double c = in_series(sc->design.sole_damping_Ns_per_m, sc->terrain.def.damping_Ns_per_m);
    lc.restitution = fs_contact_restitution(fs_contact_damping_ratio(contact_k(sc), c, m));
    lc.gain = fs_contact_rebound_gain(lc.restitution);
    return lc;
}

/* The feet robot r stands on, which share its weight: a biped's two, else one. */
static int feet_of(const fs_robot_def *r) { return r->kind == FS_ROBOT_BIPED ? 2 : 1; }

/* The share of the foot's pitch stiffness its chains give at the robot's static lean
 * (fs_pitch_engaged_share): a toe whose ground lies g below the rest plane and a ahead of the ankle
 * comes to bear once the foot has pitched forward by g / a. The share bearing at rest when the robot
 * leans back or no lean is held. */
static double engaged_share(const fs_trial_support *sup, double K, double W, double x, double h)
{
    int n = sup->toes;
    if (n <= 0 || n > FS_MAX_FEET * FS_CHAINS || !(K > 0))
        return 1;
    double share = (double)sup->toes_bearing / n;
    if (x < 0)
        return share;
    double at[FS_MAX_FEET * FS_CHAINS];
    for (int i = 0; i < n; i++)
        at[i] = sup->toe_gap_m[i] <= 0 ? 0 : sup->toe_ahead_m[i] > 0 ? sup->toe_gap_m[i] / sup->toe_ahead_m[i] : INFINITY;
    double engaged = fs_pitch_engaged_share(at, n, K, W, x, h);
    return isnan(engaged) ? share : engaged;
}

/* The drop law on one seed's support for robot r (its centre of mass at height h): the foot's K and
 * fold counted for the chains that bear at the static lean (engaged_share); the foot's tilt at rest leans the robot (its centre of
 * mass moves h tan(tilt) along the foot) and uses up that much of the lean bound, its roll too. A
 * biped's K_foot and fold are each foot's under half the weight: its chains are both feet's (the
 * share over ten), its fold both feet's, and its pitch law puts each foot's share in series with its
 * ankle (fs_pitch_law_apply). */
static int seed_stands(const fs_scenario *sc, const fs_robot_def *r0, double h, double K_foot, const foot_fold *ff,
                       const fs_trial_support *sup, const law_contact *lc, fs_drop_law *dl)
{
    memset(dl, 0, sizeof *dl);
    dl->energy_J = dl->barrier_J = dl->saturation_N_m = NAN;
    if (!sup->over)
        return 0;
    fs_robot_def r = *r0;
    r.com_height_m = h;
    r.com_forward_m = r0->com_forward_m + h * tan(sup->tilt_forward_rad);
    double g = sc->def.gravity_m_per_s2, bound = sc->def.landed_tilt_deg * M_PI / 180;
    int feet = feet_of(&r);
    double frac = engaged_share(sup, feet * K_foot, r.mass_kg * g, r.com_forward_m, h);
    double side = bound * bound - sup->tilt_side_rad * sup->tilt_side_rad;
    double lean_bound = sqrt(fmax(0, side)) - (r.com_forward_m >= 0 ? 1 : -1) * sup->tilt_forward_rad;
    fs_pitch_law pl;
    double K_eff = K_foot * frac;
    if (lc->on) /* the end's contact in series with the bearing chains (each foot's points its own) */
        K_eff = fs_pitch_contact_series(K_eff, sup->spread_m2 / feet, lc->k_N_per_m, lc->k_ref_N_per_m);
    fs_pitch_law_apply(K_eff, &r, g, lean_bound, &pl);
    fs_drop_support ds = {sup->edge_m, sup->ankle_height_m, feet * ff->fold_N_m * frac};
    fs_drop_law_apply(&pl, &r, g, sc->def.drop_m, lean_bound, &ds, dl);
    if (lc->on && lc->gain != 1) { /* a lively contact's rebounds (fs_contact_rebound_gain) */
        dl->energy_J *= lc->gain;
        dl->stands = dl->stands && !(dl->energy_J >= dl->barrier_J);
    }
    /* rocking onto its rest frees the weight times how far the base under the centre of mass sank;
       the rest's impact is plastic and keeps only the angular momentum about the side the body then
       turns on (fs_rocking_kept_J): about no side may that carry the centre of mass over it (a rigid
       tip about it), and the most kept adds to the drop's energy against the pitch's work */
    double W = r.mass_kg * g, settle = W * sup->settle_m, c = h + sup->ankle_height_m, I[3], kept = 0;
    fs_robot_whole_inertia(&r, I);
    fs_vec3 G = fs_v3(0, 0, c), pivot = fs_v3(sup->first_x_m, sup->first_y_m, 0);
    fs_vec3 axis = fs_v3(sup->rock_axis_x, sup->rock_axis_y, 0);
    int tips = 0;
    for (int i = 0; i < sup->ncorners; i++) {
        int j = (i + 1) % sup->ncorners;
        fs_vec3 s1 = fs_v3(sup->corner_x_m[i], sup->corner_y_m[i], 0), s2 = fs_v3(sup->corner_x_m[j], sup->corner_y_m[j], 0);
        double k = fs_rocking_kept_J(r.mass_kg, I, G, pivot, axis, settle, s1, s2);
        fs_vec3 u = fs_sub(s2, s1);
        double b = fabs(s1.x * u.y - s1.y * u.x) / fs_norm(u); /* G's ground point from the side */
        tips |= k >= W * (hypot(b, c) - c);
        kept = fmax(kept, k);
    }
    dl->energy_J += kept;
    dl->stands = dl->stands && dl->energy_J < dl->barrier_J && !tips;
    return dl->stands;
}

/* The highest centre of mass (below the static law's critical height) at which the drop law stands
 * on at least half of the supports: bisection, the law being monotone in it on these robots. */
static double drop_critical(const fs_scenario *sc, double K_foot, const fs_trial_support *sup, int n,
                            const foot_fold *ff, const law_contact *lc, double hmax)
{
    double lo = 0, hi = hmax;
    for (int it = 0; it < 40 && isfinite(hi); it++) {
        double h = 0.5 * (lo + hi);
        int stands = 0;
        for (int k = 0; k < n; k++) {
            fs_drop_law dl;
            stands += seed_stands(sc, &sc->def.robot, h, K_foot, ff, &sup[k], lc, &dl);
        }
        if (2 * stands >= n)
            lo = h;
        else
            hi = h;
    }
    return lo > 0 ? lo : NAN;
}

/* The law for a cell's foot and robot: the foot's pitch stiffness under the weight it carries (all
 * of it; a biped's feet half each) (a flat sole's from its contacts, fs_pitch_stiffness_foot); an
 * arch that folds under the weight has none left. The drop law's too, seed by seed on what each
 * seed's terrain offers (fs_trial_support_of: a biped's on both feet). */
static void law_of(const fs_campaign *c, const fs_scenario *sc, const law_contact *lc, fs_campaign_row *row,
                   foot_fold *cache, int *ncache)
{
    row->law = row->drop_law = FS_LAW_NONE;
    row->law_K = row->law_critical_m = NAN;
    row->drop_energy_J = row->drop_barrier_J = row->drop_saturation_N_m = row->drop_critical_m = NAN;
    const fs_robot_def *r = &sc->def.robot;
    double g = sc->def.gravity_m_per_s2, K, max_lean = sc->def.landed_tilt_deg * M_PI / 180;
    fs_error err;
    if (r->mass_kg <= 0)
        return;
    double load = r->mass_kg * g / feet_of(r); /* on each foot */
    /* a band's ends (and a sweep's cells) share the arch and its load: its K worked out once (the fold
       cache's; a flat sole's K is its contacts', worked out each time) */
    fs_status s = FS_NUMERICAL;
    for (int i = 0; i < *ncache && s != FS_OK && sc->geom.kind == FS_FOOT_BIOMIMETIC; i++)
        if (cache[i].load_N == load && cache[i].K > 0 && same_arch(cache[i].sc, sc))
            K = cache[i].K, s = FS_OK;
    if (s != FS_OK)
        s = fs_pitch_stiffness_foot(sc, load, &K, &err);
    fs_pitch_law law;
    fs_pitch_law_apply(s == FS_OK ? K : 0, r, g, max_lean, &law);
    row->law = law.stands ? FS_LAW_STANDS : FS_LAW_TOPPLES;
    row->law_K = law.held ? INFINITY : law.K;
    row->law_critical_m = law.held ? INFINITY : law.critical_height_m;
    if (law.held) { /* a slide holds the lean: whatever the drop, it stands */
        row->drop_law = FS_LAW_STANDS;
        row->drop_seeds = row->drop_stands = c->seeds;
        return;
    }
    fs_trial_support *sup = malloc((size_t)c->seeds * sizeof *sup);
    double *E = malloc((size_t)c->seeds * sizeof *E), *B = malloc((size_t)c->seeds * sizeof *B);
    double *M = malloc((size_t)c->seeds * sizeof *M);
    foot_fold ff;
    fold_of(sc, s == FS_OK ? K : 0, load, cache, ncache, &ff);
    int n = 0, nv = 0, ok = sup && E && B && M;
    /* a chain's share of the foot's pitch stiffness, with which a chain folds over what it meets */
    double chain_k = sc->geom.kind == FS_FOOT_BIOMIMETIC && s == FS_OK ? K / FS_CHAINS : 0;
    for (int k = 0; ok && k < c->seeds; k++) {
        ok = fs_trial_support_of(sc, c->first_seed + k, ff.travel_m, chain_k, &sup[n], &err) == FS_OK;
        if (!ok)
            break;
        fs_drop_law dl;
        row->drop_stands += seed_stands(sc, r, r->com_height_m, s == FS_OK ? K : 0, &ff, &sup[n], lc, &dl);
        if (!isnan(dl.barrier_J)) /* a seed whose support holds no centre of mass has none */
            E[nv] = dl.energy_J, B[nv] = dl.barrier_J, M[nv++] = dl.saturation_N_m;
        n++;
    }
    if (ok && n > 0 && lc->on && s == FS_OK) {
        /* the static law on the end's contact: the foot's K in series with the contacts of the first
           seed's support (on level ground every seed's) */
        double spread = sup[0].spread_m2 / feet_of(r); /* each foot's points */
        fs_pitch_law_apply(fs_pitch_contact_series(K, spread, lc->k_N_per_m, lc->k_ref_N_per_m), r, g,
                           max_lean, &law);
        row->law = law.stands ? FS_LAW_STANDS : FS_LAW_TOPPLES;
        row->law_K = law.K;
        row->law_critical_m = law.critical_height_m;
    }
    if (ok && n > 0) {
        row->drop_seeds = n;
        row->drop_law = 2 * row->drop_stands >= n ? FS_LAW_STANDS : FS_LAW_TOPPLES;
        row->drop_energy_J = fs_median(E, nv);
        row->drop_barrier_J = fs_median(B, nv);
        row->drop_saturation_N_m = fs_median(M, nv);
        row->drop_critical_m = drop_critical(sc, s == FS_OK ? K : 0, sup, n, &ff, lc,
                                             isfinite(law.critical_height_m) ? law.critical_height_m : 10);
    } else {
        row->drop_stands = 0;
    }
    free(sup), free(E), free(B), free(M);
}

/* With a band, the laws at each end with the end's contact in them (contact_of, against the band's
 * stiffest contact), and the cell's at the law's worse end: the one where the drop law stands on the
 * fewest seeds (then where the static law topples, then the smaller K, then the measured worse end),
 * so a design "stands" only if it stands across the band. row's counts are kept; its law fields
 * become that end's. */
static void band_law(const fs_campaign *c, int cell, int worse, fs_campaign_row *row, foot_fold *cache, int *ncache)
{
    int nends = fs_campaign_nends(c), pick = worse;
    double k_ref = 0;
    for (int e = 0; e < nends; e++)
        k_ref = fmax(k_ref, contact_k(fs_campaign_pair_of(c, cell, e)));
    fs_campaign_row end_law[FS_BAND_ENDS];
    memset(end_law, 0, sizeof end_law);
    for (int e = 0; e < nends; e++) {
        const fs_scenario *sc = fs_campaign_pair_of(c, cell, e);
        law_contact lc = contact_of(sc, k_ref);
        end_law[e] = *row;
        law_of(c, sc, &lc, &end_law[e], cache, ncache);
        row->end_law[e] = end_law[e].law;
        row->end_drop_law[e] = end_law[e].drop_law;
        row->end_drop_stands[e] = end_law[e].drop_stands;
        row->end_law_K[e] = end_law[e].law_K;
        row->end_drop_energy_J[e] = end_law[e].drop_energy_J;
        row->end_drop_barrier_J[e] = end_law[e].drop_barrier_J;
        row->end_restitution[e] = lc.restitution;
    }
    for (int e = 0; e < nends; e++) {
        const fs_campaign_row *a = &end_law[e], *b = &end_law[pick];
        int fewer = a->drop_stands < b->drop_stands, same = a->drop_stands == b->drop_stands;
        int topples = a->law == FS_LAW_TOPPLES && b->law != FS_LAW_TOPPLES;
        int same_law = a->law == b->law;
        if (fewer || (same && (topples || (same_law && a->law_K < b->law_K))))
            pick = e;
    }
    const fs_campaign_row *p = &end_law[pick];
    row->law = p->law, row->law_K = p->law_K, row->law_critical_m = p->law_critical_m;
    row->drop_law = p->drop_law, row->drop_seeds = p->drop_seeds, row->drop_stands = p->drop_stands;
    row->drop_energy_J = p->drop_energy_J, row->drop_barrier_J = p->drop_barrier_J;
    row->drop_saturation_N_m = p->drop_saturation_N_m, row->drop_critical_m = p->drop_critical_m;
    row->law_end = pick;
}

/* A cell's counts, rate, interval and medians over its seeds' results r[0 .. seeds - 1] (v: room for
 * seeds numbers). */
static void count_trials(const fs_campaign *c, const fs_trial_result *r, double *v, fs_campaign_row *row)
{
    for (int s = 0; s < c->seeds; s++) {
        row->trials++;
        row->landed += r[s].outcome == FS_LANDED;
        row->fell += r[s].outcome == FS_FELL;
        row->undecided += r[s].outcome == FS_UNDECIDED;
        row->failed_numerics += r[s].outcome == FS_FAILED_NUMERICS;
        row->hung += r[s].outcome == FS_HUNG || r[s].outcome == FS_KILLED;
        row->killed += r[s].outcome == FS_KILLED;
    }
    row->success_rate = (double)row->landed / row->trials;
    fs_wilson(row->landed, row->trials, &row->ci_low, &row->ci_high);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        int n = 0;
        for (int s = 0; v && s < c->seeds; s++)
            if (fs_trial_measured(&r[s]))
                v[n++] = fs_metric_value(&r[s], m);
        row->nmetric = n;
        /* a metric a trial does not have (NAN: the rest ankle drop of a fall) is left out */
        int k = 0;
        for (int i = 0; i < n; i++)
            if (!isnan(v[i]))
                v[k++] = v[i];
        row->median[m] = fs_median(v, k);
    }
}

void fs_campaign_summarize(const fs_campaign *c, const fs_trial_result *results, fs_campaign_row *rows)
{
    double *v = malloc((size_t)c->seeds * sizeof *v);
    foot_fold cache[FOLD_CACHE];
    int ncache = 0, nends = fs_campaign_nends(c);
    for (int cell = 0; cell < fs_campaign_ncells(c); cell++) {
        fs_campaign_row *row = &rows[cell];
        fs_campaign_row end_row[FS_BAND_ENDS];
        int worse = 0;
        /* each end's row; the cell's is its worse end's (the first on a tie): a design lands only as
           often as it lands across the band */
        for (int e = 0; e < nends; e++) {
            memset(&end_row[e], 0, sizeof end_row[e]);
            count_trials(c, &results[(cell * nends + e) * c->seeds], v, &end_row[e]);
            if (end_row[e].landed < end_row[worse].landed)
                worse = e;
        }
        *row = end_row[worse];
        fs_campaign_cell_of(c, cell, &row->foot, &row->terrain, &row->robot);
        row->band_end = nends > 1 ? worse : -1;
        for (int e = 0; e < nends && nends > 1; e++) {
            row->end_landed[e] = end_row[e].landed;
            row->end_trials[e] = end_row[e].trials;
            row->end_rate[e] = end_row[e].success_rate;
        }
        row->law_end = -1;
        if (c->pair && nends > 1)
            band_law(c, cell, worse, row, cache, &ncache);
        else if (c->pair)
            law_of(c, fs_campaign_pair_of(c, cell, worse), &no_contact, row, cache, &ncache);
        else
            row->law = row->drop_law = FS_LAW_NONE, row->law_K = row->law_critical_m = NAN;
    }
    free(v);
}
