/* Tests of the drop law (analysis_drop.c, docs/landing.md) against closed forms and integrals worked
 * out here apart from it, of the arch's fold (analysis_pitch.c) and of the support a seed's terrain
 * gives (experiment_support.c). */
#include "fs_test.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_trial.h"

static const double G = 9.81;

static fs_robot_def robot(double m, double h, double x, double I_pitch)
{
    fs_robot_def r;
    memset(&r, 0, sizeof r);
    r.mass_kg = m, r.com_height_m = h, r.com_forward_m = x;
    r.inertia_kgm2[0] = r.inertia_kgm2[1] = I_pitch, r.inertia_kgm2[2] = 0.1 * I_pitch;
    r.joint = FS_ROBOT_RIGID, r.mount = FS_ROBOT_FREE;
    return r;
}

static void apply(double K, const fs_robot_def *r, double drop, const fs_drop_support *s, fs_pitch_law *pl,
                  fs_drop_law *dl)
{
    fs_pitch_law_apply(K, r, G, 15 * M_PI / 180, pl);
    fs_drop_law_apply(pl, r, G, drop, 15 * M_PI / 180, s, dl);
}

/* With nothing to saturate (no fold, no edge) the restoring moment rises without end: the drop law
 * is the static law whatever the drop; at zero drop the rotational energy is exactly zero; and a
 * drop's energy is (m x v)^2 / (2 I_A) with v^2 = 2 g drop and I_A = I + m (h^2 + x^2). */
static void no_saturation_is_the_static_law(void)
{
    const fs_drop_support none = {INFINITY, 0.03, INFINITY};
    const double Ks[] = {5, 12.79, 40, 80, 300}, hs[] = {0.02, 0.05, 0.1, 0.2, 0.3}, xs[] = {0, 0.03, -0.02};
    const double drops[] = {0, 0.005, 0.5};
    int compared = 0, stands = 0;
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            for (int c = 0; c < 3; c++)
                for (int d = 0; d < 3; d++) {
                    fs_robot_def r = robot(26, hs[b], xs[c], 1.4);
                    fs_pitch_law pl;
                    fs_drop_law dl;
                    apply(Ks[a], &r, drops[d], &none, &pl, &dl);
                    CHECK(dl.stands == pl.stands);
                    compared++, stands += pl.stands;
                    if (drops[d] == 0)
                        CHECK(dl.energy_J == 0);
                    double IA = 1.4 + 26 * (hs[b] * hs[b] + xs[c] * xs[c]);
                    double L = 26 * fabs(xs[c]) * sqrt(2 * G * drops[d]);
                    CHECK_NEAR(dl.energy_J, L * L / (2 * IA), 1e-12 * (1 + L * L / IA));
                }
    CHECK(compared == 225 && stands > 0 && stands < compared); /* both verdicts were met */
}

/* A rigid foot (K infinite) on its edge is a rigid block about its corner: the work to carry the
 * centre of mass, b behind the corner and c above it, over the corner is m g (sqrt(b^2 + c^2) - c),
 * and the block topples when the rotational energy the drop gives reaches it: at the drop
 * d* = I_A B / (g (m x)^2). Closed forms on both sides: round-off of 1e-15 against the 1e-3 by which
 * the drops straddle d*. The small-angle form m g b^2 / (2 c) is 3.7 % larger here: the check fails
 * on it. */
static void rigid_block_is_the_energy_criterion(void)
{
    const double m = 26, c = 0.1, x = 0.03, e = 0.07, I = 0.2;
    fs_robot_def r = robot(m, c, x, I);
    fs_drop_support edge = {e, 0, INFINITY};
    fs_pitch_law pl;
    fs_drop_law dl;
    apply(INFINITY, &r, 0, &edge, &pl, &dl);
    double b = e - x, B = m * G * (sqrt(b * b + c * c) - c);
    CHECK_NEAR(dl.barrier_J, B, 1e-12 * B);
    CHECK(fabs(m * G * b * b / (2 * c) - B) > 0.03 * B); /* the small-angle form would fail the check above */
    CHECK(dl.stands && !dl.folds);
    double IA = I + m * (c * c + x * x), dstar = IA * B / (G * (m * x) * (m * x));
    apply(INFINITY, &r, 0.999 * dstar, &edge, &pl, &dl);
    CHECK(dl.stands);
    apply(INFINITY, &r, 1.001 * dstar, &edge, &pl, &dl);
    CHECK(!dl.stands);
}

/* Simpson's rule on n (even) intervals: exact for the linear and quadratic pieces, 1e-12 on the
 * trigonometric one at n = 2000. */
typedef double (*fn)(double t, const double *p);
static double simpson(fn f, const double *p, double a, double b, int n)
{
    double h = (b - a) / n, s = f(a, p) + f(b, p);
    for (int i = 1; i < n; i++)
        s += (i % 2 ? 4 : 2) * f(a + i * h, p);
    return s * h / 3;
}

/* p: K, W, h, x, M_s, e, ankle height */
static double rising(double t, const double *p) { return p[0] * t - p[1] * (p[3] + p[2] * t); }
static double plateau(double t, const double *p) { return p[4] - p[1] * (p[3] + p[2] * t); }
/* about the edge, turned by phi past the saturation at theta_s = p[7]: the weight's moment about the
   edge from the centre of mass b behind it and c above it, b and c turned by phi */
static double about_edge(double phi, const double *p)
{
    double b = p[5] - p[3] - p[2] * p[7], c = p[2] + p[6];
    return p[1] * (b * cos(phi) - c * sin(phi));
}

/* The work to the largest lean, against the integral of the net restoring moment taken here: a
 * compliant foot that reaches its edge (rising, then turning about the edge until the centre of
 * mass is over it) and one whose arch folds first (rising, then the fold's plateau until the
 * weight's moment meets it). The energy test is then E < B: checked on both sides of it. */
static void barrier_is_the_work_to_the_largest_lean(void)
{
    const double m = 26, W = m * G, h = 0.2, x = 0.03, K = 138, e = 0.0774, za = 0.0257;
    fs_robot_def r = robot(m, h, x, 0.65);
    fs_pitch_law pl;
    fs_drop_law dl;
    fs_drop_support edge = {e, za, INFINITY};
    apply(K, &r, 0, &edge, &pl, &dl);
    double ts = W * e / K, p[8] = {K, W, h, x, W * e, e, za, ts};
    double b = e - x - h * ts, c = h + za;
    double B = simpson(rising, p, 0, ts, 2) + simpson(about_edge, p, 0, atan2(b, c), 2000);
    CHECK(!dl.folds);
    CHECK_NEAR(dl.saturation_N_m, W * e, 1e-12 * W * e);
    CHECK_NEAR(dl.barrier_J, B, 1e-9 * fabs(B) + 1e-12);
    /* zero drop: the weight's step alone carries it over exactly when the work is negative (here it
       is: -4 mJ; at 0.1 m it is +1.1 J) */
    CHECK(dl.stands == (B > 0));

    const double fold = 15;
    fs_drop_support folding = {e, za, fold};
    apply(K, &r, 0, &folding, &pl, &dl);
    double tf = fold / K, tstar = (fold / W - x) / h, q[8] = {K, W, h, x, fold, e, za, tf};
    double Bf = simpson(rising, q, 0, tf, 2) + simpson(plateau, q, tf, tstar, 2);
    CHECK(dl.folds);
    CHECK_NEAR(dl.barrier_J, Bf, 1e-9 * fabs(Bf) + 1e-12);
    /* the drop that carries it over: E = B at d* (x ahead, the impulse through the ankle) */
    double IA = 0.65 + m * (h * h + x * x), dstar = IA * Bf / (G * (m * x) * (m * x));
    if (Bf > 0) {
        apply(K, &r, 0.999 * dstar, &folding, &pl, &dl);
        CHECK(dl.stands);
        apply(K, &r, 1.001 * dstar, &folding, &pl, &dl);
        CHECK(!dl.stands);
    }
    /* an equilibrium past the fold does not stand, whatever the static law says */
    fs_drop_support weak = {e, za, 0.5 * W * x};
    apply(K, &r, 0, &weak, &pl, &dl);
    CHECK(pl.stands && !dl.stands);
}

/* The arch's fold: the model holds moments up to it (the continuation's last equilibrium) and a
 * stiffer arch holds more; at zero moment the model is the pitch-stiffness model unchanged. */
static void fold_moment_of_the_arch(void)
{
    static fs_scenario sc, stiff;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    const char *set[] = {"springs.scale=10"};
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", set, 1, &stiff, &err) == FS_OK);
    double W = 26 * G, cap = W * 0.0774, f1, f10;
    REQUIRE(fs_pitch_fold_moment(&sc.geom, W, G, cap, &f1, &err) == FS_OK);
    REQUIRE(fs_pitch_fold_moment(&stiff.geom, W, G, cap, &f10, &err) == FS_OK);
    printf("fold moments under 26 kg: Table I %.4g N m, ten times its springs %.4g (cap %.4g)\n", f1, f10, cap);
    CHECK(f1 > 0 && f1 < cap);
    CHECK(f10 > f1);
}

/* On level ground every heel and toe sphere bears and the midfoot's do not (they stand 5-8 mm
 * up); the edge along the foot through the centre of mass is where the line from the ankle meets
 * the segment from the big toe's contact to the little toe's (the middle toes lie behind it), and
 * the nearest side the nearest of the four the heel spheres and outer toes make, worked out here
 * from the design's spheres; the drawn yaw turns foot and line together; the foot rests untilted
 * and nothing sinks as it settles. */
static void support_on_level_ground(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", NULL, 0, &sc, &err) == FS_OK);
    const fs_foot_geom *g = &sc.geom;
    fs_vec3 big = fs_v3(0, 0, 0), little = big;
    for (int i = 0; i < g->nspheres; i++) {
        if (g->sphere[i].body == g->chain[0].phalanx)
            big = g->sphere[i].centre;
        if (g->sphere[i].body == g->chain[FS_CHAINS - 1].phalanx)
            little = g->sphere[i].centre;
    }
    double y = g->ankle.y, xe = little.x + (big.x - little.x) * (y - little.y) / (big.y - little.y);
    /* the nearest side from the centre of mass (3 cm ahead of the ankle): of the four sides the two
       heel spheres and the two outer toes make */
    fs_vec3 heel_l = fs_v3(0, 0, 0), heel_r = heel_l, com = fs_add(g->ankle, fs_v3(sc.def.robot.com_forward_m, 0, 0));
    for (int i = 0; i < g->nspheres; i++)
        if (g->sphere[i].body == FS_BODY_HEEL) {
            if (g->sphere[i].centre.y > 0)
                heel_l = g->sphere[i].centre;
            else
                heel_r = g->sphere[i].centre;
        }
    const fs_vec3 ring[4] = {heel_r, little, big, heel_l};
    double side = INFINITY;
    for (int k = 0; k < 4; k++) {
        fs_vec3 u = ring[k], v = ring[(k + 1) % 4];
        side = fmin(side, fabs((v.x - u.x) * (com.y - u.y) - (v.y - u.y) * (com.x - u.x)) / hypot(v.x - u.x, v.y - u.y));
    }
    /* the bearing points' spread along the foot (the contacts' pitch stiffness per unit k): the two
       heel and five toe spheres about their mean x */
    double mean = 0, spread = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < g->nspheres; i++) {
            int bears = g->sphere[i].body == FS_BODY_HEEL;
            for (int c = 0; c < FS_CHAINS; c++)
                bears |= g->sphere[i].body == g->chain[c].phalanx;
            if (bears && pass == 0)
                mean += g->sphere[i].centre.x / 7;
            else if (bears)
                spread += (g->sphere[i].centre.x - mean) * (g->sphere[i].centre.x - mean);
        }
    for (int seed = 1; seed <= 3; seed++) {
        fs_trial_support s;
        REQUIRE(fs_trial_support_of(&sc, seed, 1e-3, 0, &s, &err) == FS_OK);
        CHECK(s.bearing == 7 && s.toes_bearing == 5 && s.toes == 5 && s.heel_bearing && s.over);
        CHECK_NEAR(s.spread_m2, spread, 1e-12);
        CHECK_NEAR(s.edge_m, xe - g->ankle.x, 1e-12);
        CHECK_NEAR(s.ankle_height_m, g->ankle.z, 1e-12);
        CHECK_NEAR(s.side_m, side, 1e-12);
        /* level: no rock (the plane through three points, to round-off) */
        CHECK_NEAR(s.settle_m, 0, 1e-12);
        CHECK_NEAR(s.tilt_forward_rad, 0, 1e-12);
        CHECK_NEAR(s.tilt_side_rad, 0, 1e-12);
    }
    fs_scenario_free(&sc);
}

/* A biped's two feet settle as one rigid support. On level ground every heel and toe sphere of both
 * feet bears (14, ten toes) and none of the midfoot's; the feet stand side by side, so the polygon's
 * front is the line through the two feet's foremost toes and its back the line through their heels,
 * worked out here from the design's spheres (a foot's big and little toe alone, as one foot's edge is
 * found, would give another edge: the check fails on one foot's polygon), and the line from the
 * ankles' midpoint through the centre of mass meets the front there. */
static void support_of_a_biped(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"robot.design=robots/biped.ini"};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &sc, &err) == FS_OK);
    const fs_foot_geom *g = &sc.geom; /* one foot; the biped's are it and its mirror image */
    double front = -INFINITY, back = INFINITY;
    for (int i = 0; i < g->nspheres; i++) {
        int toe = 0;
        for (int c = 0; c < FS_CHAINS; c++)
            toe |= g->sphere[i].body == g->chain[c].phalanx;
        if (toe)
            front = fmax(front, g->sphere[i].centre.x);
        if (g->sphere[i].body == FS_BODY_HEEL)
            back = fmin(back, g->sphere[i].centre.x);
    }
    double com = g->ankle.x + sc.def.robot.com_forward_m;
    fs_trial_support s;
    REQUIRE(fs_trial_support_of(&sc, 1, 1e-3, 0, &s, &err) == FS_OK);
    CHECK(s.bearing == 14 && s.toes_bearing == 10 && s.toes == 10 && s.heel_bearing && s.over);
    CHECK_NEAR(s.edge_m, front - g->ankle.x, 1e-12);
    CHECK_NEAR(s.side_m, fmin(front - com, com - back), 1e-12);
    CHECK_NEAR(s.ankle_height_m, g->ankle.z, 1e-12);
    CHECK_NEAR(s.settle_m, 0, 1e-12);
    CHECK_NEAR(s.tilt_forward_rad, 0, 1e-12);
    CHECK_NEAR(s.tilt_side_rad, 0, 1e-12);
    fs_scenario_free(&sc);
}

/* A biped's moments about its centre of mass (fs_robot_whole_inertia), worked out here for straight
 * legs (no knee bend): the pelvis (its own moments, its centre com_forward_m's share ahead) and four
 * square bars, thigh over shank, hip_width_m / 2 to each side. The legs' sideways reach is in the roll
 * moment and not in the pitch moment (the check fails if the two are swapped or the legs left out). */
static void biped_whole_inertia(void)
{
    fs_robot_def r;
    memset(&r, 0, sizeof r);
    r.kind = FS_ROBOT_BIPED;
    r.hip_width_m = 0.2, r.thigh_length_m = 0.2, r.shank_length_m = 0.25, r.knee_bend_deg = 0, r.leg_width_m = 0.06;
    r.pelvis_mass_kg = 36.76, r.thigh_mass_kg = 5.2, r.shank_mass_kg = 2.42, r.pelvis_com_height_m = 0.15;
    r.pelvis_inertia_kgm2[0] = 0.47, r.pelvis_inertia_kgm2[1] = 0.35, r.pelvis_inertia_kgm2[2] = 0.26;
    r.com_forward_m = 0.03;
    double mp = r.pelvis_mass_kg, mt = r.thigh_mass_kg, ms = r.shank_mass_kg, M = mp + 2 * (mt + ms);
    double Ls = r.shank_length_m, Lt = r.thigh_length_m, w = r.leg_width_m, y = 0.5 * r.hip_width_m;
    /* centres: the pelvis ahead by M x / mp (the legs stand straight over the ankles), up by
       Ls + Lt + its own height; each thigh at Ls + Lt / 2, each shank at Ls / 2 */
    double xp = M * r.com_forward_m / mp, zp = Ls + Lt + r.pelvis_com_height_m, zt = Ls + 0.5 * Lt, zs = 0.5 * Ls;
    double xG = mp * xp / M, zG = (mp * zp + 2 * mt * zt + 2 * ms * zs) / M;
    double bar_t = mt * (Lt * Lt + w * w) / 12, bar_s = ms * (Ls * Ls + w * w) / 12, sq_t = mt * w * w / 6, sq_s = ms * w * w / 6;
    double dzp = zp - zG, dxp = xp - xG, dzt = zt - zG, dzs = zs - zG;
    double legs_z = 2 * (mt * (dzt * dzt + xG * xG) + ms * (dzs * dzs + xG * xG));
    double want_pitch = 0.35 + mp * (dxp * dxp + dzp * dzp) + 2 * (bar_t + bar_s) + legs_z;
    double want_roll = 0.47 + mp * dzp * dzp + 2 * (bar_t + bar_s) + 2 * (mt * dzt * dzt + ms * dzs * dzs) +
                       2 * (mt + ms) * y * y;
    double want_yaw = 0.26 + mp * dxp * dxp + 2 * (sq_t + sq_s) + 2 * (mt + ms) * (xG * xG + y * y);
    double I[3];
    fs_robot_whole_inertia(&r, I);
    CHECK_NEAR(I[0], want_roll, 1e-12);
    CHECK_NEAR(I[1], want_pitch, 1e-12);
    CHECK_NEAR(I[2], want_yaw, 1e-12);
    /* a single body's are fs_robot_inertia's */
    fs_robot_def one = robot(26, 0.3, 0.03, 2.5);
    double J[3], K[3];
    fs_robot_whole_inertia(&one, J);
    fs_robot_inertia(&one, K);
    CHECK(J[0] == K[0] && J[1] == K[1] && J[2] == K[2]);
}

/* A flat sole on level ground bears over its whole bottom face (11 x 7 points), untilted, its edge
 * the sole's front; on simply uneven ground the 8 mm bump under its forefoot (at x = 6 cm) lifts it:
 * resting on the bump and its heel it tilts by about atan(8 / 60), 7.6 degrees; the four corners
 * alone would have left it level on the ground around the bump (the check fails on them). */
static void support_of_a_flat_sole(void)
{
    static fs_scenario sc, bump;
    fs_error err;
    const char *set[] = {"scenario.design=feet/flat.ini"};
    const char *set2[] = {"scenario.design=feet/flat.ini", "scenario.terrain=../terrains/simply_uneven.ini"};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &sc, &err) == FS_OK);
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set2, 2, &bump, &err) == FS_OK);
    fs_trial_support s;
    REQUIRE(fs_trial_support_of(&sc, 1, 1e-3, 0, &s, &err) == FS_OK);
    const fs_foot_geom *g = &sc.geom;
    CHECK(s.bearing == 77 && s.over);
    CHECK_NEAR(s.edge_m, g->box[0].centre.x + 0.5 * g->box_size.x - g->ankle.x, 1e-12);
    CHECK_NEAR(s.tilt_forward_rad, 0, 1e-12);
    REQUIRE(fs_trial_support_of(&bump, 1, 1e-3, 0, &s, &err) == FS_OK);
    printf("flat sole on the bump, seed 1: tilt %.2f deg, %d points bear\n", s.tilt_forward_rad * 180 / M_PI, s.bearing);
    CHECK(fabs(s.tilt_forward_rad) > 2 * M_PI / 180 && fabs(s.tilt_forward_rad) < 15 * M_PI / 180);
    fs_scenario_free(&sc);
    fs_scenario_free(&bump);
}

/* A chain folds over what it meets. The drop weight's foot (Table I) on the simply uneven ground's
 * bump, seed 6: the bump lifts the ground under the outer chains, and settled on it as a rigid body
 * the foot tilts 5 degrees nose-up with one toe bearing. A chain of the foot's stiffness (its share
 * of the pitch stiffness, K / 5 about the ankle: about 700 N/m at a shape 6 cm ahead) holds a few
 * newtons over that rise, less than its share of the weight, so it folds: the foot rests level on
 * its heels and toes, every toe bearing. Chains a thousand times stiffer hold their share and the
 * foot rests as the rigid body does (the check fails if the rule ignores the stiffness); on level
 * ground, where every shape lies within the travel of the rest, nothing folds, to the bit. The
 * travel is the campaign's for this foot (the contact layer and the arch's drop, about 0.53 mm). */
static void chains_fold_over_a_bump(void)
{
    static fs_scenario flat, bump;
    fs_error err;
    const char *set[] = {"robot.design=robots/drop_weight.ini", "scenario.terrain=../terrains/simply_uneven.ini"};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &flat, &err) == FS_OK);
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 2, &bump, &err) == FS_OK);
    double K, W = (bump.def.robot.mass_kg) * G;
    REQUIRE(fs_pitch_stiffness_model(&bump.geom, W, G, &K, &err) == FS_OK);
    /* the travel as a campaign takes it: the contact layer and the arch's ankle drop under the weight */
    fs_planar_load pl = {.load_N = W, .gravity_m_per_s2 = G};
    fs_planar_result res;
    REQUIRE(fs_planar_equilibrium(&bump.design, &bump.geom, 0, &pl, &res, &err) == FS_OK && res.converged);
    double travel = bump.def.contact_layer_m + fmax(0, res.ankle_drop_m);
    double chain_k = K / FS_CHAINS;
    fs_trial_support rigid, folded, stiff, level, level_rigid;
    REQUIRE(fs_trial_support_of(&bump, 6, travel, 0, &rigid, &err) == FS_OK);
    REQUIRE(fs_trial_support_of(&bump, 6, travel, chain_k, &folded, &err) == FS_OK);
    REQUIRE(fs_trial_support_of(&bump, 6, travel, 1000 * chain_k, &stiff, &err) == FS_OK);
    printf("bump, seed 6: rigid tilt %.3f deg, %d of 5 toes bear; chains of %.3g N m/rad: tilt %.3f deg, %d toes; "
           "a thousand times stiffer: tilt %.3f deg, %d toes\n",
           rigid.tilt_forward_rad * 180 / M_PI, rigid.toes_bearing, chain_k, folded.tilt_forward_rad * 180 / M_PI,
           folded.toes_bearing, stiff.tilt_forward_rad * 180 / M_PI, stiff.toes_bearing);
    CHECK(rigid.over && folded.over && stiff.over);
    CHECK(rigid.toes_bearing <= 1 && fabs(rigid.tilt_forward_rad) > 2 * M_PI / 180);
    CHECK(folded.toes_bearing == 5 && fabs(folded.tilt_forward_rad) < 0.05 * M_PI / 180);
    CHECK(stiff.toes_bearing == rigid.toes_bearing && stiff.tilt_forward_rad == rigid.tilt_forward_rad);
    /* level ground: within the travel every shape bears with the others, none folds */
    REQUIRE(fs_trial_support_of(&flat, 6, travel, 0, &level_rigid, &err) == FS_OK);
    REQUIRE(fs_trial_support_of(&flat, 6, travel, chain_k, &level, &err) == FS_OK);
    CHECK(!memcmp(&level, &level_rigid, sizeof level));
    fs_scenario_free(&flat);
    fs_scenario_free(&bump);
}

/* A biped's two feet are ten chains under its whole weight: with each foot's chains K / 5 (the foot's
 * K, each foot under half the weight), the left foot's the right's again, the moment balance
 * sum (K / 5) (theta - a_i) = W (x + h theta) over ten chains is twice the one over five under W / 2,
 * so the lean and the share are one foot's under half the weight (the check fails if the ten are
 * cut to five, or taken as K / 10 each). */
static void two_feet_engage_as_one_under_half(void)
{
    const double K = 300, W = 255, x = 0.03, h = 0.02;
    const double one[5] = {0, 0.004, 0.011, 0.03, INFINITY};
    double ten[10];
    for (int i = 0; i < 10; i++)
        ten[i] = one[i % 5];
    double a = fs_pitch_engaged_share(one, 5, K, W / 2, x, h), b = fs_pitch_engaged_share(ten, 10, 2 * K, W, x, h);
    printf("engaged, two feet: %.6f, one under half: %.6f\n", b, a);
    CHECK(isfinite(a) && a > 0.2 && a < 1);
    CHECK_NEAR(b, a, 1e-12);
}

/* The rocking's plastic impact (fs_rocking_kept_J) against Housner's rectangular block, worked out
 * apart from it: a uniform block of half-width b and half-height hb (I_G = m (b^2 + hb^2) / 3 about
 * the axis of rocking) turning about one bottom corner lands on the other and keeps the angular
 * momentum about it, omega'/omega = 1 - 3/2 sin^2 alpha, tan alpha = b / hb, so the energy left is
 * the energy before times its square (exact; round-off 1e-15). Checked in a frame turned about the
 * vertical (the axes' handling can fail), for a squat and a tall block (0.15 and 0.97 of the energy
 * kept: the check fails if the two are swapped) and one so squat (sin^2 alpha > 2/3) that it turns
 * back (nothing kept); about the side along the turn and about the pivot's
 * own side the kept momentum carries G inwards: nothing left to tip it. */
static void rocking_block_keeps_housners_share(void)
{
    const double m = 26, depth = 0.05, E = 0.7;
    const double shapes[][2] = {{0.05, 0.06}, {0.03, 0.3}, {0.05, 0.03}}; /* b, hb */
    for (int k = 0; k < 3; k++) {
        double b = shapes[k][0], hb = shapes[k][1], Iy = m * (b * b + hb * hb) / 3;
        double I[3] = {m * (depth * depth + hb * hb) / 3, Iy, m * (b * b + depth * depth) / 3};
        /* past sin^2 alpha = 2/3 the ratio is negative: the block turns back onto the first corner */
        double s2a = b * b / (b * b + hb * hb), ratio = 1 - 1.5 * s2a, want = ratio > 0 ? E * ratio * ratio : 0;
        /* the block's frame: x across the sides, y along them; the points' frame turned by yaw, the
           block's principal axes with it (so I_G stays diagonal only when yaw is 0: yaw 90 degrees
           swaps x and y, which the call is given) */
        for (int yaw = 0; yaw < 2; yaw++) {
            double Ir[3] = {yaw ? I[1] : I[0], yaw ? I[0] : I[1], I[2]};
            double cx = yaw ? 0 : 1, sx = yaw ? 1 : 0; /* x of the block is (cx, sx) in the points' frame */
#define PT(X, Y, Z) fs_v3(cx * (X) - sx * (Y), sx * (X) + cx * (Y), (Z))
            fs_vec3 Gc = PT(0, 0, hb), pivot = PT(-b, 0, 0), axis = PT(0, 1, 0);
            /* the far side, its interior (x < b) on the left of s1 -> s2 */
            double kept = fs_rocking_kept_J(m, Ir, Gc, pivot, axis, E, PT(b, -depth, 0), PT(b, depth, 0));
            printf("block b %.2f h %.2f yaw %d: kept %.6f J of %.2f, Housner %.6f\n", b, hb, 90 * yaw, kept, E, want);
            CHECK_NEAR(kept, want, 1e-12);
            if (k == 0)
                CHECK(kept > 0.1 * E && kept < 0.2 * E);
            else if (k == 1)
                CHECK(kept > 0.9 * E);
            else
                CHECK(kept == 0);
            /* the side it turns about already (interior x > -b on the left of s1 -> s2): the turn
               carries G away from it, inwards: nothing to tip over it */
            CHECK(fs_rocking_kept_J(m, Ir, Gc, pivot, axis, E, PT(-b, depth, 0), PT(-b, -depth, 0)) == 0);
            /* the side behind it at y = -depth: the kept momentum about it turns the body inwards */
            CHECK(fs_rocking_kept_J(m, Ir, Gc, pivot, axis, E, PT(-b, -depth, 0), PT(b, -depth, 0)) == 0);
#undef PT
        }
    }
}

/* The chains that come to bear as the foot pitches (fs_pitch_engaged_share) against the lean found
 * apart from it: the piecewise-linear moment M(theta) = K/n sum max(0, theta - e_i) meets the
 * weight's W (x + h theta) where their difference, negative at upright (-W x), first crosses zero,
 * found here by bisection (to 1e-15 rad: the share to 1e-12). Two chains bear at rest and two more
 * engage at 1.1 and 2.9 degrees: the share lies between 2/5 and 4/5, above the 2/5 of the chains
 * bearing at rest (the check fails if the engaging ones are left out), and the same whatever the
 * chains' order. Upright over its support (x = 0) the lean is 0 and the share the bearing 2/5; one
 * chain too soft to hold a 10 cm robot alone, the others never bearing: no equilibrium (NAN). */
static void toes_engage_as_the_foot_pitches(void)
{
    const double K = 60, W = 26 * G, x = 0.03, h = 0.02;
    const double e[5] = {0.05, 0, INFINITY, 0.02, 0}, e2[5] = {0, 0.02, 0, INFINITY, 0.05};
    double lo = 0, hi = 1;
    for (int it = 0; it < 200 && hi - lo > 1e-15; it++) {
        double t = 0.5 * (lo + hi), M = 0;
        for (int i = 0; i < 5; i++)
            M += K / 5 * fmax(0, t - e[i]);
        if (M - W * (x + h * t) < 0)
            lo = t;
        else
            hi = t;
    }
    double theta = 0.5 * (lo + hi), M = 0;
    for (int i = 0; i < 5; i++)
        M += K / 5 * fmax(0, theta - e[i]);
    double want = M / (K * theta), got = fs_pitch_engaged_share(e, 5, K, W, x, h);
    printf("engaged: lean %.4f rad, share %.6f (bisection %.6f; bearing at rest 0.4)\n", theta, got, want);
    CHECK_NEAR(got, want, 1e-12);
    CHECK(got > 0.4 + 1e-3 && got < 0.8);
    CHECK(fs_pitch_engaged_share(e2, 5, K, W, x, h) == got);
    CHECK_NEAR(fs_pitch_engaged_share(e, 5, K, W, 0, h), 0.4, 1e-15);
    const double lone[5] = {0, INFINITY, INFINITY, INFINITY, INFINITY};
    CHECK(isnan(fs_pitch_engaged_share(lone, 5, K, W, x, 0.1))); /* K / 5 = 12 < W h = 25.5 N m */
}

/* The band end's contact in the law (fs_analysis.h): the closed forms against hand calculations.
 * Restitution at the pad's damping ratio 0.22: exp(-pi 0.22 / sqrt(1 - 0.0484)) = exp(-0.708510) =
 * 0.492378 (six digits by hand: 1e-6); the band's definition inverts it, zeta = -ln e / sqrt(pi^2 +
 * ln^2 e), which must give e = 0.5 back to round-off (an identity); overdamped (1.12, the hard sole)
 * and critical contacts do not rebound. The pad's damping ratio from its series k and c (the sole's
 * 100100 N/m and 208.011 N s/m with the ground's 1e8 and 2e4: k = 1.00000e5, c = 205.870) under 26.27 kg
 * on 12 spheres (2.18917 kg): 205.870 / (2 sqrt(2.18917e5)) = 0.22000 (1e-4). The rebound gain at
 * e = 0.5 is (1.5 / 0.5)^2 = 9. In series: a rigid foot (K infinite) on two points d = 0.1 m apart
 * turned about their middle is k d^2 / 2 (k S, S = 2 (d/2)^2), to round-off; Table I at 21.5 times (K
 * 298) on the pad's 1e5 against the hard 9.0909e6 with S = 0.0086 m^2: 1 / (1 / 298 + (1e-5 -
 * 1.1e-7) / 0.0086) = 221.94 (to 0.01 by hand); the stiffest end (k = k_ref) gives K back, bit for bit. */
static void contact_closed_forms(void)
{
    CHECK_NEAR(fs_contact_restitution(0.22), 0.492378, 1e-6);
    double e = 0.5, zeta = -log(e) / sqrt(M_PI * M_PI + log(e) * log(e));
    CHECK_NEAR(fs_contact_restitution(zeta), 0.5, 1e-12);
    CHECK(fs_contact_restitution(1.12) == 0 && fs_contact_restitution(1) == 0 && fs_contact_restitution(0) == 1);
    CHECK(fs_contact_restitution(0.3) < fs_contact_restitution(0.2));
    double k = 100100 * 1e8 / (100100 + 1e8), c = 208.011 * 2e4 / (208.011 + 2e4);
    CHECK_NEAR(k, 1.0e5, 1);
    CHECK_NEAR(c, 205.870, 1e-3);
    CHECK_NEAR(fs_contact_damping_ratio(k, c, 26.27 / 12), 0.22000, 1e-4);
    CHECK_NEAR(fs_contact_rebound_gain(0.5), 9, 1e-12);
    CHECK(fs_contact_rebound_gain(0) == 1);
    double d = 0.1, kp = 2e5;
    CHECK_NEAR(fs_pitch_contact_series(INFINITY, 2 * (d / 2) * (d / 2), kp, INFINITY), kp * d * d / 2, 1e-9 * kp * d * d);
    CHECK_NEAR(fs_pitch_contact_series(298, 0.0086, 1e5, 1e7 * 1e8 / (1e7 + 1e8)), 221.94, 0.01);
    double K = 297.77310000000001;
    CHECK(fs_pitch_contact_series(K, 0.0086, 9.0909e6, 9.0909e6) == K);
    CHECK(fs_pitch_contact_series(K, 0.0086, 2e7, 9.0909e6) == K); /* a stiffer contact than the reference */
}

FS_TEST_MAIN(TEST(support_of_a_flat_sole), TEST(two_feet_engage_as_one_under_half), TEST(chains_fold_over_a_bump), TEST(support_of_a_biped), TEST(biped_whole_inertia), TEST(contact_closed_forms), TEST(no_saturation_is_the_static_law), TEST(rigid_block_is_the_energy_criterion),
             TEST(barrier_is_the_work_to_the_largest_lean), TEST(fold_moment_of_the_arch),
             TEST(support_on_level_ground), TEST(rocking_block_keeps_housners_share),
             TEST(toes_engage_as_the_foot_pitches))
