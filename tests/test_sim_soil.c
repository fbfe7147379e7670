/* The soil (fs_soil.h, fs_soil_grid.h, fs_sim_soil.h) against closed forms, each tolerance derived
 * from the grid spacing and the step:
 * - the flat sole under a dead load on two Bekker soils (dry sand, sandy loam) at two loads: z = (p / (k_c/b + k_phi))^(1/n);
 * - the load removed: the sole rises by the pressure's drop over K_e;
 * - a print's volume: the surface's dent, the plastic sinkage summed over the nodes, and the sole's
 *   area times the closed form's plastic sinkage, all three alike;
 * - halving the grid moves the static sinkage by less than the grid's bound; the same for the links'
 *   capsules on their own spacing ([soil] nodes_across);
 * - a plate dragged at constant normal load: Janosi's 1 - e^(-j/K) at j = K, 2K, 3K;
 * - RFT: alpha_z(0, pi/2) = 1, alpha_x(0, pi/2) = 0 (and four values derived from the fit), a plate
 *   at a depth and tilt against the formula, the inertial term against rho v^2; its forces never push
 *   along the motion;
 * - a foot through a thin layer stops on the bedrock;
 * - a soil section ([soil] x_min_m, x_max_m): a foot landing beside it lands as on rigid ground, to the bit,
 *   and the walking machine over it never touches a node beyond it, its steps off it taking no soil;
 * - a soil landing's impact impulse is its fall's momentum;
 * - the biomimetic foot's soil shapes are its design's [soil_shapes] radii;
 * - shapes stacked over the same nodes outgrow the step's claims, and the lowest one's force is the
 *   one it has alone, to the bit;
 * - validation: n <= 0, a negative modulus, Bekker moduli with no bearing strength (k_c = k_phi = 0),
 *   phi of 90 degrees, depth 0, RFT without zeta or density, a grid over max_nodes are refused with
 *   file:line (or the key) before anything runs. */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/experiment/fs_walk.h"
#include "footsim/sim/fs_observer.h"
#include "footsim/sim/fs_sim_soil.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <stdlib.h>
#include <unistd.h>

/* ---- the flat sole on Bekker soils ----------------------------------------------------------- */

typedef struct sole_run {
    double W_N, A_m2, P_m, sink_m, sigma_Pa, rebound_m, print_m3, dent_m3, grid_print_m3, plastic_m, print_area_m2;
    double b_m, spacing_m; /* the sole's nodes' spacing */
    double yaw_deg, load_N, foot_kg, ramp_s; /* its turn, the load taken away, its body's mass, and over how long */
    long nodes;
} sole_run;

/* The flat sole's bottom now, m. */
static double sole_bottom(const fs_sim *sim)
{
    dVector3 l;
    dGeomBoxGetLengths(sim->shape[0], l);
    return dGeomGetPosition(sim->shape[0])[2] - 0.5 * l[2];
}

/* Steps until every body is slower than 1e-5 m/s (after the ramp) or 'most' steps. */
static void settle(fs_sim *sim, int most)
{
    fs_error err;
    for (int k = 0; k < most; k++) {
        REQUIRE(fs_sim_step(sim, &err) == FS_OK);
        if (sim->time_s > 0.05 && fs_sim_max_speed(sim) < 1e-5)
            break;
    }
}

/* The flat foot (turning locked, so that the sole stays level whatever the load's point) under
 * load_kg on a soil file, grid grid_m, the sole's nodes coarse_m apart (soil.coarse_grid_m; 0: on
 * grid_m): its sinkage at rest, then with the load removed, then lifted. */
static void sole_on(const char *soil, double load_kg, double grid_m, double coarse_m, double yaw_deg, sole_run *out)
{
    static fs_scenario sc;
    fs_error err;
    char terrain[200], load[64], grid[64], coarse[64], yaw[64];
    snprintf(terrain, sizeof terrain, "scenario.terrain=../terrains/soils/%s", soil);
    snprintf(load, sizeof load, "load.mass_kg=%g", load_kg);
    snprintf(grid, sizeof grid, "soil.grid_m=%g", grid_m);
    snprintf(coarse, sizeof coarse, "soil.coarse_grid_m=%g", coarse_m);
    snprintf(yaw, sizeof yaw, "start.yaw_deg=%g", yaw_deg);
    const char *set[] = {"scenario.design=feet/flat.ini", terrain, load, grid, coarse, yaw};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 6, &sc, &err) == FS_OK);
    fs_sim sim;
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    dBodySetMaxAngularSpeed(sim.body[0], 0);
    const fs_soil_grid *g = fs_sim_soil_grid(&sim);
    REQUIRE(g != NULL);
    settle(&sim, 20000);
    dVector3 l;
    dGeomBoxGetLengths(sim.shape[0], l);
    out->A_m2 = l[0] * l[1];
    out->P_m = 2 * (l[0] + l[1]);
    out->W_N = (load_kg + sc.geom.total_mass_kg) * sc.def.gravity_m_per_s2;
    out->yaw_deg = yaw_deg, out->load_N = load_kg * sc.def.gravity_m_per_s2, out->foot_kg = sc.geom.total_mass_kg;
    double depth = sc.terrain.def.soil.depth_m, bottom = sole_bottom(&sim);
    out->sink_m = depth - bottom;
    out->b_m = g->b_m[0];
    out->nodes = g->nodes[0];
    out->spacing_m = g->dx * (g->shape[0].stride > 1 ? g->shape[0].stride : 1);
    double f[3];
    fs_sim_ground_force(&sim, f);
    out->sigma_Pa = f[2] / out->A_m2;
    /* the load taken away slowly (over 0.05 s, so that the sole does not spring off its print): it
     * rises on the unloading line */
    const int unload_steps = 500;
    double load_N = sim.load_N;
    out->ramp_s = unload_steps * sc.def.step_s;
    for (int k = 1; k <= unload_steps; k++) {
        sim.load_N = load_N * (1 - (double)k / unload_steps);
        REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
    }
    settle(&sim, 20000);
    out->rebound_m = sole_bottom(&sim) - bottom;
    /* lifted clear: every node shows its print */
    const dReal *p = dBodyGetPosition(sim.body[0]);
    dBodySetPosition(sim.body[0], p[0], p[1], p[2] + 0.05);
    dBodySetLinearVel(sim.body[0], 0, 0, 0);
    REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
    CHECK(fs_sim_soil_nodes(&sim, -1) == 0);
    long marked;
    out->grid_print_m3 = fs_soil_grid_print(g, &out->plastic_m, &marked);
    fs_soil_print pr;
    fs_soil_grid_print_of(g, &pr);
    CHECK(pr.volume_m3 == out->grid_print_m3 && pr.deepest_m == out->plastic_m && pr.nodes == marked);
    out->print_area_m2 = pr.area_m2;
    double dent = 0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const fs_soil_node *n = fs_soil_grid_node(g, i, j);
            if (n)
                dent += n->h0_m - fs_soil_grid_surface(g, g->x0 + i * g->dx, g->y0 + j * g->dx);
        }
    out->dent_m3 = dent * g->dx * g->dx;
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* How far the count of the sole's nodes, times a cell ds^2, may be from its area A, as a share of A.
 * Each node stands for the square cell C of side ds around it. A node inside the plan K has its cell
 * inside K + C, and every point of K - C (K shrunk by C) lies in the cell of a node inside K, so the
 * count's area lies between those of K - C and K + C. For a rectangle turned yaw to the grid, C's
 * reach across each side is h = ds (|cos yaw| + |sin yaw|) / 2: K + C has area A + P h + ds^2 (the
 * four corners' rounding make up one cell), K - C (a - 2h)(b - 2h) >= A - P h. So |N ds^2 - A| <=
 * P h + ds^2 (the corners' cell: 1.4e-4 of A on 1 mm, 9e-3 on 8 mm). */
static double area_bound(const sole_run *r, double ds)
{
    double yaw = r->yaw_deg * M_PI / 180, h = 0.5 * ds * (fabs(cos(yaw)) + fabs(sin(yaw)));
    return (r->P_m * h + ds * ds) / r->A_m2;
}

/* How far the sole's rebound may be from the load's pressure over K_e, m (drop_m that closed form).
 * - Area: the sole's nodes carry its plan's area to within one cell, ds^2 (coverage,
 *   a_box_carries_its_plans_area), every node at the same sinkage and so the same pressure: the
 *   pressure's drop is the load over that area, ds^2 / A of drop_m.
 * - The loaded rest: settle stops it below 1e-5 m/s, not quite at rest (a creep on the plastic
 *   branch, its damping carrying a share; a swing's turning point): the elastic line starts from the
 *   pressure it stood on then, sigma_Pa (its ground force over A), not from W / A, and the rebound
 *   moves by their difference over K_e.
 * - The unloaded rest: the load is taken away over ramp_s, which the sole follows at u = drop_m /
 *   ramp_s on its elastic branch, a spring K_e A on the foot's body (mass m) with damping R A:
 *   w = sqrt(K_e A / m), zeta = R A / (2 m w). Following it the sole lags by delta = R u / K_e; when
 *   the ramp stops, it is left delta below rest and rising at u, and swings about its rest within the
 *   envelope sqrt(delta^2 + ((u - zeta w delta) / w_d)^2), w_d = w sqrt(1 - zeta^2): settle may stop
 *   it anywhere within that (it stops at a turning point: 0.22 % of drop_m, measured, against 0.90 %
 *   for the envelope on the presets, ramp_s 0.05 s). The step (w h = 0.22) moves the swing's
 *   frequency by about (w h)^2 / 24, 0.2 %: inside the envelope's margin. */
static double rebound_bound(const sole_run *r, const fs_soil_def *d, double drop_m)
{
    double Ke = d->K_e_Pa_per_m, R = d->damping_Pa_s_per_m, A = r->A_m2, ds = r->spacing_m;
    double w = sqrt(Ke * A / r->foot_kg), zeta = R * A / (2 * r->foot_kg * w), wd = w * sqrt(1 - zeta * zeta);
    double u = drop_m / r->ramp_s, delta = R * u / Ke;
    return drop_m * ds * ds / A + fabs(r->sigma_Pa - r->W_N / A) / Ke + hypot(delta, (u - zeta * w * delta) / wd);
}

/* The sinkage the sole may have on a grid of spacing ds, at most and at least, m. Its nodes carry its
 * exact area (coverage: a_box_carries_its_plans_area), so under a dead load only Bekker's b = 2A/P
 * moves with the grid: the patch's perimeter is counted on the nodes' open sides, a staircase, which
 * along a side at angle a to the grid is (|cos a| + |sin a|) its length, at most sqrt(2) times, give
 * or take a cell at each of the side's ends: P_grid in [P - 8 ds, sqrt(2) P + 8 ds]. The sinkage
 * (p / (k_c/b + k_phi))^(1/n) at the two ends of b's range bounds it. */
static void sole_sinkage_range(const char *soil, const sole_run *r, double ds, double *lo, double *hi)
{
    static fs_terrain t;
    fs_error err;
    char path[200];
    snprintf(path, sizeof path, "terrains/soils/%s", soil);
    REQUIRE(fs_terrain_load(path, NULL, 0, &t, &err) == FS_OK);
    double p = r->W_N / r->A_m2;
    double wide = fs_bekker_sinkage(&t.def.soil, 2 * r->A_m2 / (r->P_m - 8 * ds), p);
    double narrow = fs_bekker_sinkage(&t.def.soil, 2 * r->A_m2 / (sqrt(2) * r->P_m + 8 * ds), p);
    *lo = fmin(wide, narrow), *hi = fmax(wide, narrow); /* which is which: k_c's sign */
    fs_terrain_free(&t);
}

/* The sole under load_kg on soil against Bekker's closed form, its rebound and its print,
 * with tolerances from the spacing of the sole's nodes (grid_m, or coarse_m when it serves the sole). */
static void sole_against_bekker(const char *soil, double load_kg, double grid_m, double coarse_m,
                                double yaw_deg, sole_run *out)
{
    sole_run r;
    sole_on(soil, load_kg, grid_m, coarse_m, yaw_deg, &r);
    double grid = r.spacing_m;
    static fs_terrain t;
    fs_error err;
    char path[200];
    snprintf(path, sizeof path, "terrains/soils/%s", soil);
    REQUIRE(fs_terrain_load(path, NULL, 0, &t, &err) == FS_OK);
    double b = r.A_m2 * 2 / r.P_m, p = r.W_N / r.A_m2;
    double z = fs_bekker_sinkage(&t.def.soil, b, p);
    /* the sole's nodes carry its area (coverage), so the grid moves the sinkage only through the
     * patch's perimeter in b (sole_sinkage_range); the rest is 1e-5 m/s for the settling's time */
    double lo, hi;
    sole_sinkage_range(soil, &r, grid, &lo, &hi);
    printf("  %s, %g kg, nodes %g mm apart: sinkage %.3f mm, closed form %.3f mm (b %.4f m, grid's %.4f m), within "
           "%.3f to %.3f mm\n",
           soil, load_kg, grid * 1e3, r.sink_m * 1e3, z * 1e3, b, r.b_m, (lo - 1e-5) * 1e3, (hi + 1e-5) * 1e3);
    CHECK(r.sink_m >= lo - 1e-5 && r.sink_m <= hi + 1e-5);
    double tol = fmax(hi - z, z - lo) + 1e-5;
    /* load removed: the sole rises by the pressure's drop over K_e, the foot's own weight left on it */
    double Ke = t.def.soil.K_e_Pa_per_m, drop = r.load_N / (r.A_m2 * Ke), rb = rebound_bound(&r, &t.def.soil, drop);
    printf("    rebound %.4f mm, the load's pressure over K_e %.4f mm, within %.4f mm (loaded rest off by %.2e mm)\n",
           r.rebound_m * 1e3, drop * 1e3, rb * 1e3, fabs(r.sigma_Pa - r.W_N / r.A_m2) / Ke * 1e3);
    CHECK_NEAR(r.rebound_m, drop, rb);
    /* the print: its dent in the surface equals the plastic sinkage summed over the nodes, and
     * the sole's area times the closed form's plastic sinkage z - p / K_e */
    double sp = z - p / Ke;
    printf("    print %.4g m^3 (surface %.4g m^3), area x plastic sinkage %.4g m^3\n", r.grid_print_m3, r.dent_m3,
           r.A_m2 * sp);
    CHECK_NEAR(r.dent_m3, r.grid_print_m3, 1e-12);
    /* the print's area is the sole's, to within the count's error (area_bound) */
    CHECK_NEAR(r.print_area_m2, r.A_m2, r.A_m2 * area_bound(&r, grid));
    CHECK_NEAR(r.grid_print_m3, r.A_m2 * sp, r.A_m2 * sp * (area_bound(&r, grid) + tol / sp));
    fs_terrain_free(&t);
    if (out)
        *out = r;
}

static void sole_sinks_as_bekker_says(void)
{
    const char *soils[2] = {"dry_sand.ini", "sandy_loam.ini"};
    const double loads[2] = {13, 26};
    for (int s = 0; s < 2; s++)
        for (int k = 0; k < 2; k++)
            sole_against_bekker(soils[s], loads[k], 1e-3, 0, 0, NULL);
}

/* The presets' grid (0.5 mm) serves the flat sole every 16th node (coarse_grid_m 8 mm, docs/soil.md,
 * Grid spacing): the same law as on an 8 mm grid, whose sinkage the halving test bounds against 4 mm. */
static void the_sole_on_its_coarse_grid(void)
{
    sole_run c, g;
    sole_against_bekker("dry_sand.ini", 26, 5e-4, 8e-3, 7, &c);
    CHECK_NEAR(c.spacing_m, 8e-3, 1e-12);
    sole_on("dry_sand.ini", 26, 8e-3, 0, 7, &g);
    /* the same nodes at the same points (i 16 dx against i 8 mm: rounding apart), so the same state:
     * far closer than the halving test's bound between 8 and 4 mm */
    printf("  every 16th node of 0.5 mm: sinkage %.6f mm on %ld nodes; an 8 mm grid: %.6f mm on %ld nodes\n",
           c.sink_m * 1e3, c.nodes, g.sink_m * 1e3, g.nodes);
    CHECK(c.nodes == g.nodes);
    CHECK_NEAR(c.sink_m, g.sink_m, 1e-6);
    CHECK_NEAR(c.grid_print_m3, g.grid_print_m3, 1e-6 * g.grid_print_m3);
}

static void halving_the_grid_moves_sinkage_little(void)
{
    /* turned 7 degrees, so that the sole's edges cut the grid's rows at every offset; 8 mm is the
     * sole's spacing (coarse_grid_m), 4 mm half of it */
    sole_run a, b;
    sole_on("dry_sand.ini", 26, 8e-3, 0, 7, &a);
    sole_on("dry_sand.ini", 26, 4e-3, 0, 7, &b);
    /* both within the range b's perimeter allows on the coarser grid (which holds the finer's), plus
     * 1e-5 m/s for the settling's time; were the coverage to miscount the area by a cell along each
     * side (P ds / 2, 19 % at 8 mm), the sinkage would move 1/n of that, about 6 mm */
    double lo, hi;
    sole_sinkage_range("dry_sand.ini", &a, 8e-3, &lo, &hi);
    double bound = hi - lo + 2e-5;
    printf("  sinkage on an 8 mm grid %.4f mm, on 4 mm %.4f mm: %.4f mm apart, bound %.4f mm (b's range: %.4f to "
           "%.4f mm)\n",
           a.sink_m * 1e3, b.sink_m * 1e3, fabs(a.sink_m - b.sink_m) * 1e3, bound * 1e3, lo * 1e3, hi * 1e3);
    CHECK(fabs(a.sink_m - b.sink_m) <= bound);
    CHECK(a.sink_m >= lo - 1e-5 && a.sink_m <= hi + 1e-5);
    CHECK(b.sink_m >= lo - 1e-5 && b.sink_m <= hi + 1e-5);
}

/* ---- a link's capsule on its own spacing ---------------------------------------------------- */

/* A capsule of radius r and length L (its segment's) along x, turned 7 degrees about z (so that its
 * edges cut the grid's rows at every offset), alone on a grid of soil (0.5 mm, no damping) and met on
 * every stride-th node: pressed down 10 um a step until the soil carries W; its sinkage then (linear
 * between the two steps around W), m. */
static double capsule_sinkage(const char *soil, double r, double L, int stride, double W, double *dx)
{
    static fs_terrain t;
    static fs_soil_grid g;
    fs_error err;
    const char *set[] = {"soil.grid_m=5e-4", "bekker.damping_Pa_s_per_m=0"};
    REQUIRE(fs_terrain_load(soil, set, 2, &t, &err) == FS_OK);
    double box[4] = {-0.06, 0.06, -0.06, 0.06};
    REQUIRE(fs_soil_region(&t.def.soil, box, t.path, t.soil_region, NULL, &err) == FS_OK);
    memset(&g, 0, sizeof g);
    REQUIRE(fs_soil_grid_init(&g, &t, (const double(*)[4])box, 1, &err) == FS_OK);
    fs_soil_shape *s = &g.shape[g.nshapes++];
    memset(s, 0, sizeof *s);
    s->kind = FS_SOIL_CAPSULE;
    s->a[0] = -0.5 * L, s->b[0] = 0.5 * L, s->radius_m = r, s->stride = stride;
    const double h = 1e-4, step = 1e-5, c = cos(7 * M_PI / 180), sn = sin(7 * M_PI / 180);
    double depth = t.def.soil.depth_m, z = 0, F = 0, sink = -1;
    fs_soil_body b = {.p = {1.3e-4, 0.7e-4, depth + r}, .R = {c, -sn, 0, sn, c, 0, 0, 0, 1}, .v = {0, 0, -step / h},
                      .mass_kg = 1e6};
    while (z < 0.09) {
        z += step;
        b.p[2] = depth + r - z;
        REQUIRE(fs_soil_grid_step(&g, &b, h, &err) == FS_OK);
        double Fz = g.force[0][2];
        if (Fz >= W) {
            sink = z - step * (Fz - W) / (Fz - F);
            break;
        }
        F = Fz;
    }
    *dx = g.dx * stride;
    fs_soil_grid_free(&g);
    fs_terrain_free(&t);
    return sink;
}

/* Each link's capsule is met on the widest spacing that leaves [soil] nodes_across nodes across it
 * (fs_soil_stride; docs/soil.md, Grid spacing). Halving that spacing moves its static sinkage under
 * Fig. 11's load by less than a bound from the spacing, on two Bekker soils. */
static void halving_the_capsules_spacing_moves_sinkage_little(void)
{
    static fs_terrain t;
    fs_error err;
    const char *across = getenv("FS_TEST_NODES_ACROSS"); /* to try another rule by hand */
    char set_across[64];
    snprintf(set_across, sizeof set_across, "soil.nodes_across=%s", across ? across : "6");
    const char *set[] = {set_across};
    REQUIRE(fs_terrain_load("terrains/soils/lete_sand.ini", set, across ? 1 : 0, &t, &err) == FS_OK);
    const fs_soil_def d = t.def.soil;
    fs_terrain_free(&t);
    if (!across) { /* the default rule's spacings for the feet's widths (0.5 mm grid, 8 mm at most) */
        CHECK(d.nodes_across == 6);
        CHECK(fs_soil_stride(&d, 0.006) == 2 && fs_soil_stride(&d, 0.0075) == 2 && fs_soil_stride(&d, 0.008) == 2);
        CHECK(fs_soil_stride(&d, 0.010) == 2 && fs_soil_stride(&d, 0.012) == 4 && fs_soil_stride(&d, 0.070) == 16);
        CHECK(fs_soil_stride(&d, 0.024) == 8 && fs_soil_stride(&d, 0.0479) == 8 && fs_soil_stride(&d, 0.048) == 16);
        CHECK(fs_soil_stride(&d, 0.0059) == 1);
    }
    /* each capsule as the foot's (docs/soil.md, The feet's shapes): radius and plan area at rest,
     * its segment's length from them, A = 2 r L + pi r^2: phalanges 2-5, phalanx 1, metatarsals 2-5,
     * metatarsal 1, heel */
    const double radius[5] = {0.003, 0.00375, 0.004, 0.005, 0.006}, plan[5] = {1.10e-4, 1.72e-4, 3.61e-4, 5.73e-4, 4.01e-4};
    const char *soils[2] = {"terrains/soils/lete_sand.ini", "terrains/soils/sandy_loam.ini"};
    int halved = 0;
    for (int c = 0; c < 5; c++) {
        int st = fs_soil_stride(&d, 2 * radius[c]);
        if (st < 2)
            continue; /* on grid_m already */
        halved++;
        for (int k = 0; k < 2; k++) {
            double r = radius[c], L = (plan[c] - M_PI * r * r) / (2 * r);
            /* Fig. 11's load, 26 kg and the foot's ~1 kg, spread over the twelve links' 30.3 cm² (the
             * talus above them): each capsule carries its plan area's share */
            double W = 27 * 9.81 * plan[c] / 30.3e-4;
            REQUIRE(fs_terrain_load(soils[k], NULL, 0, &t, &err) == FS_OK);
            double n = t.def.soil.n, kc = t.def.soil.k_c_N_per_m_n1, kphi = t.def.soil.k_phi_N_per_m_n2,
                   bmin = t.def.soil.b_min_m;
            fs_terrain_free(&t);
            double dx1, dx2;
            double z1 = capsule_sinkage(soils[k], r, L, st / 2, W, &dx1), z2 = capsule_sinkage(soils[k], r, L, st, W, &dx2);
            REQUIRE(z1 > 0 && z2 > 0);
            /* The patch is the capsule's section at the undisturbed surface: half width a, area A,
             * perimeter P. A grid counts the nodes within it: those within half a spacing of its edge
             * may fall either way, so its area is A to within P dx / 2, and its Bekker b = 2 A / P
             * (perimeter counted on the grid: within 4 dx of its limit, the box of its nodes) to
             * within that and 4 dx / P. The load fixed, the pressure moves as 1 / A and Bekker's
             * k_c / b + k_phi by the share kappa of k_c / b in it; the sinkage, as (p / k)^(1/n),
             * by 1/n of their sum (less where the capsule's round bottom is deeper than its edge:
             * the bound holds). The two grids differ by at most the sum of their bounds, plus the
             * 10 um press's interpolation. */
            double zm = fmax(z1, z2), a = zm < r ? sqrt(2 * r * zm - zm * zm) : r;
            double A = 2 * a * L + M_PI * a * a, P = 2 * L + 2 * M_PI * a, b = fmax(2 * A / P, bmin);
            double kappa = (kc / b) / (kc / b + kphi), bound = 1e-5;
            for (int g = 0; g < 2; g++) {
                double dx = g ? dx2 : dx1, dA = P * dx / (2 * A);
                bound += zm / n * (dA + kappa * (dA + 4 * dx / P));
            }
            printf("  capsule r %g mm, L %.1f mm, %.1f N on %s: sinkage %.4f mm on %g mm, %.4f mm on %g mm: "
                   "%.4f mm apart, bound %.4f mm\n",
                   r * 1e3, L * 1e3, W, soils[k] + 15, z1 * 1e3, dx1 * 1e3, z2 * 1e3, dx2 * 1e3, fabs(z1 - z2) * 1e3,
                   bound * 1e3);
            CHECK(fabs(z1 - z2) <= bound);
        }
    }
    CHECK(halved > 0);
}

/* ---- a plate meeting the grid directly -------------------------------------------------------- */

/* A grid over [-0.1, 0.1]^2 of the soil in file (its grid_m) with one plate L x W x 2 half as its shape. */
static void plate_grid(const char *file, const char *const *set, int nset, double L, double W, double half,
                       fs_terrain *t, fs_soil_grid *g)
{
    fs_error err;
    REQUIRE(fs_terrain_load(file, set, nset, t, &err) == FS_OK);
    double box[4] = {-0.1, 0.1, -0.1, 0.1};
    REQUIRE(fs_soil_region(&t->def.soil, box, t->path, t->soil_region, NULL, &err) == FS_OK);
    memset(g, 0, sizeof *g);
    REQUIRE(fs_soil_grid_init(g, t, (const double(*)[4])box, 1, &err) == FS_OK);
    fs_soil_shape *s = &g->shape[g->nshapes++];
    memset(s, 0, sizeof *s);
    s->kind = FS_SOIL_BOX;
    s->half[0] = 0.5 * L, s->half[1] = 0.5 * W, s->half[2] = half;
    s->R[0] = s->R[4] = s->R[8] = 1;
}

/* A body at (x, 0, z), turned by beta about y, moving at v, heavy (no cap on the shear). */
static fs_soil_body plate_body(double x, double z, double beta, double vx, double vz)
{
    fs_soil_body b = {.p = {x, 0, z}, .v = {vx, 0, vz}, .mass_kg = 1e6};
    double c = cos(beta), s = sin(beta);
    double R[9] = {c, 0, s, 0, 1, 0, -s, 0, c};
    memcpy(b.R, R, sizeof R);
    return b;
}

/* Coverage (fs_soil_grid.h): a box's nodes carry its plan's area wherever its edges fall on the grid.
 * The flat sole's plate (70 x 100 x 10 mm), level or pitched 5 degrees, its bottom 10 mm into the soil
 * everywhere (so that every node under its plan is pressed), turned 0, 7 and 30 degrees about z and
 * moved by quarters of a cell, met every 4th, 8th and 16th node of 0.5 mm (2, 4 and 8 mm). The rows
 * partition the plan exactly (each strip's area, the first and last taking all below and above
 * them), so the weighted area is the plan's save rounding and a row whose span holds no node (a
 * corner's sliver, narrower than a cell over less than a cell's height): bound one cell, ds^2. The
 * count of nodes alone would miss by up to half a cell along the perimeter, P ds / 2 (about 20 cells
 * at 8 mm): the check fails if the weighting miscounts, and one unweighted count must be off by more
 * than the bound (else the test would prove nothing). */
static void a_box_carries_its_plans_area(void)
{
    static fs_terrain t;
    static fs_soil_grid g;
    const double L = 0.07, W = 0.1, half = 0.005, pitch = 5 * M_PI / 180;
    const char *set[] = {"soil.grid_m=5e-4"};
    const int strides[3] = {4, 8, 16};
    const double yaws[3] = {0, 7, 30};
    double worst = 0, worst_count = 0;
    for (int k = 0; k < 3; k++)
        for (int tilt = 0; tilt < 2; tilt++)
            for (int y = 0; y < 3; y++)
                for (int q = 0; q < 4; q++) {
                    plate_grid("terrains/soils/dry_sand.ini", set, 1, L, W, half, &t, &g);
                    g.shape[0].stride = strides[k];
                    double ds = strides[k] * g.dx, b = tilt ? pitch : 0, a = yaws[y] * M_PI / 180;
                    fs_soil_body body = plate_body(0.25 * q * ds, t.def.soil.depth_m - 0.01 + half, b, 0, 0);
                    /* yaw about z after the pitch about y: R = Rz(a) Ry(b) */
                    double ca = cos(a), sa = sin(a), Ry[9];
                    memcpy(Ry, body.R, sizeof Ry);
                    for (int c = 0; c < 3; c++) {
                        body.R[c] = ca * Ry[c] - sa * Ry[3 + c];
                        body.R[3 + c] = sa * Ry[c] + ca * Ry[3 + c];
                    }
                    body.p[1] = 0.25 * (3 - q) * ds;
                    fs_error err;
                    REQUIRE(fs_soil_grid_step(&g, &body, 1e-4, &err) == FS_OK);
                    /* the plan of the pitched plate: its length over the pitch plus the two ends' faces */
                    double plan = (L * cos(b) + 2 * half * sin(b)) * W, P = 2 * (L + W);
                    double err_w = fabs(g.area_m2[0] - plan), err_n = fabs(g.nodes[0] * ds * ds - plan);
                    worst = fmax(worst, err_w / (ds * ds));
                    worst_count = fmax(worst_count, err_n / (ds * ds));
                    CHECK(err_w <= ds * ds);
                    CHECK(err_n <= P * ds / 2 + ds * ds);
                    fs_soil_grid_free(&g);
                    fs_terrain_free(&t);
                }
    printf("  weighted area within %.3g cells of the plan's; the node count alone within %.3g cells\n", worst,
           worst_count);
    CHECK(worst_count > 1);
}

/* A plate longer than 3K (80.2 mm against 60 mm, so that its reference holds at every j asked) pressed
 * into dry sand to 20 mm, its load W read there, then dragged along x at a constant normal load: after
 * each step the plate is raised or lowered by (F_z - W) / (K_e A), the elastic branch's give for the
 * load's excess, which undoes the load a row of nodes brings as it enters at the front or leaves at the
 * back (a load servo, as a shear box's; the rig has no dynamics of its own, and a free body on the
 * plate would let its vertical motion take the check's step budget). Fast (0.1 m/s: 6000 steps to
 * 3K) because the law has no rate in it above slip_speed_m_per_s (1 mm/s) and the test's damping is 0. */
static void plate_dragged_follows_janosi(void)
{
    static fs_terrain t;
    static fs_soil_grid g;
    const double L = 0.0802, W = 0.03, h = 1e-4, v = 0.1;
    const char *set[] = {"soil.grid_m=5e-4", "bekker.damping_Pa_s_per_m=0"};
    plate_grid("terrains/soils/dry_sand.ini", set, 2, L, W, 0.001, &t, &g);
    double K = t.def.soil.shear_K_m, depth = t.def.soil.depth_m, s0 = 0.02, Ke = t.def.soil.K_e_Pa_per_m;
    fs_error err;
    /* pressed to s0: every node under it yields at sigma = Bekker(s0); its load is W from then on */
    fs_soil_body b = plate_body(-0.06, depth - s0 + 0.001, 0, 0, 0);
    REQUIRE(fs_soil_grid_step(&g, &b, h, &err) == FS_OK);
    double load = g.force[0][2], dist = 0, worst = 0;
    /* The load's tolerance: between two corrections one row of nodes enters or leaves, a row's share of
     * the load, at most dx / (L - dx) (the plate, 80.2 mm, cuts its node lines at different steps at
     * its two ends, so rows come and go one at a time and the servo works) */
    double load_tol = g.dx / (L - g.dx);
    for (int m = 1; m <= 3; m++) {
        while (dist < m * K - 1e-12) {
            b.v[0] = v;
            REQUIRE(fs_soil_grid_step(&g, &b, h, &err) == FS_OK);
            worst = fmax(worst, fabs(g.force[0][2] / load - 1));
            b.p[2] += (g.force[0][2] - load) / (Ke * g.nodes[0] * g.dx * g.dx);
            b.p[0] += v * h;
            dist += v * h;
        }
        /* Janosi integrated over the plate: the nodes under it from the start have slipped D, those met
         * since, their distance from the front (less than D): at most min(D, L) of the plate's length */
        double D = dist, Lm = fmin(D, L), e = exp(-D / K);
        double want = ((L - Lm) * (1 - e) + Lm - K * (1 - exp(-Lm / K))) / L;
        double area = g.nodes[0] * g.dx * g.dx, tau_max = fs_soil_shear_strength(&t.def.soil, g.force[0][2] / area);
        double got = -g.force[0][0] / (tau_max * area);
        /* Tolerance from the grid and the step: a node's slip is counted in steps of v h (v h / K of
         * 1 - e^(-j/K) at most), and the plate's ends fall between node lines, a row (dx / L of the
         * plate) in or out at each end: 2 dx / L + v h / K */
        double tol = 2 * g.dx / L + v * h / K;
        printf("  j = %dK: tau / tau_max %.4f, closed form %.4f (1 - e^(-j/K) = %.4f), within %.4f; normal load "
               "%.2f N, at most %.2e off it so far (bound %.4f)\n", m, got, want, 1 - e, tol, load, worst, load_tol);
        CHECK_NEAR(got, want, tol);
        CHECK(worst <= load_tol);
    }
    fs_soil_grid_free(&g);
    fs_terrain_free(&t);
}

static void rft_alpha_has_its_symmetries(void)
{
    static fs_terrain t;
    fs_error err;
    REQUIRE(fs_terrain_load("terrains/soils/granular_close.ini", NULL, 0, &t, &err) == FS_OK);
    double az, ax;
    fs_rft_alpha(&t.def.soil, 0, M_PI / 2, &az, &ax);
    CHECK_NEAR(az, 1.0, 1e-12);
    CHECK_NEAR(ax, 0.0, 1e-12);
    /* derived from the fit's nine terms: a plate moving sideways, flat and upright */
    fs_rft_alpha(&t.def.soil, 0, 0, &az, &ax);
    CHECK_NEAR(az, 0.375, 1e-12);
    CHECK_NEAR(ax, 0.136, 1e-12);
    fs_rft_alpha(&t.def.soil, M_PI / 2, 0, &az, &ax);
    CHECK_NEAR(az, 0.037, 1e-12);
    CHECK_NEAR(ax, 0.370, 1e-12);
    /* pushed straight down, a tilt of either sign gives the same lift and opposite thrust */
    double az2, ax2;
    fs_rft_alpha(&t.def.soil, 0.4, M_PI / 2, &az, &ax);
    fs_rft_alpha(&t.def.soil, -0.4, M_PI / 2, &az2, &ax2);
    CHECK_NEAR(az, az2, 1e-12);
    CHECK_NEAR(ax, -ax2, 1e-12);
    fs_terrain_free(&t);
}

/* The plate's force pushed down at speed vz with its centre at depth d and tilt beta. */
static void rft_plate_force(double d, double beta, double vz, double F[3], double *area)
{
    static fs_terrain t;
    static fs_soil_grid g;
    const double L = 0.04, W = 0.04;
    const char *set[] = {"soil.grid_m=5e-4"};
    plate_grid("terrains/soils/granular_close.ini", set, 1, L, W, 1e-4, &t, &g);
    /* the plate's underside centre at depth d: its body centre 0.1 mm above along its normal */
    fs_soil_body b = plate_body(0, t.def.soil.depth_m - d + 1e-4 * cos(beta), beta, 0, vz);
    b.p[0] = 1e-4 * sin(beta);
    fs_error err;
    REQUIRE(fs_soil_grid_step(&g, &b, 1e-4, &err) == FS_OK);
    memcpy(F, g.force[0], 3 * sizeof(double));
    *area = L * W;
    fs_soil_grid_free(&g);
    fs_terrain_free(&t);
}

static void rft_plate_at_depth_and_tilt(void)
{
    static fs_terrain t;
    fs_error err;
    REQUIRE(fs_terrain_load("terrains/soils/granular_close.ini", NULL, 0, &t, &err) == FS_OK);
    double zeta = t.def.soil.zeta_N_per_m3;
    const double betas[2] = {0, 0.5}, d = 0.03;
    for (int k = 0; k < 2; k++) {
        double F[3], A, az, ax;
        rft_plate_force(d, betas[k], -0.01, F, &A);
        fs_rft_alpha(&t.def.soil, betas[k], M_PI / 2, &az, &ax);
        /* over a plate wholly below the surface the depth is linear: its mean is the centre's */
        double fz = zeta * az * d * A, fx = zeta * ax * d * A;
        /* the grid's cells along the edge (dx / L each way), the plate's 0.2 mm thickness seen at the
         * tilt (its end face, twice as deep and seen at 1 / sin(beta) of its plan), and the inertial term
         * at 1 cm/s (rho v^2 = 0.16 Pa) */
        double tol = (2 * 5e-4 / 0.04 + 4 * 2e-4 / 0.04 + 1e-4);
        printf("  RFT plate at %.0f mm, tilt %.2f rad: Fz %.3f N (formula %.3f), Fx %.3f N (formula %.3f)\n", d * 1e3,
               betas[k], F[2], fz, F[0], fx);
        CHECK_NEAR(F[2], fz, fz * tol);
        /* the thrust pushes the plate away from where its underside looks: turned by beta > 0 about y,
         * its underside's normal leans toward -x, so the push is toward +x */
        CHECK_NEAR(F[0], fx, fabs(fx) * tol + fz * 1e-9);
    }
    /* the inertial term: at 2 m/s the force exceeds the slow one by lambda rho v^2 over the area */
    double Fs[3], Ff[3], A;
    rft_plate_force(0.002, 0, -0.01, Fs, &A);
    rft_plate_force(0.002, 0, -2.0, Ff, &A);
    double want = t.def.soil.inertial_lambda * t.def.soil.density_kg_per_m3 * 4.0 * A;
    printf("  inertial: %.3f N at 2 m/s, lambda rho v^2 A = %.3f N\n", Ff[2] - Fs[2], want);
    CHECK_NEAR(Ff[2] - Fs[2], want, want * (2 * 5e-4 / 0.04) + 1e-6);
    fs_terrain_free(&t);
}

/* RFT's forces are dissipative by construction: a plate (40 x 40 mm, tilted 0.3 rad) pressed into
 * the closely packed medium to 30 mm, then moved at 2 cm/s in each of 72 directions in the plane of
 * its tilt (a fresh medium each time): moving into the medium the force may not push along the
 * motion, F.v <= 0 (the normal stress resists, the drag opposes, a thrust across the motion does no
 * work); rising, the medium gives back only its elastic branch's vertical stress, so the sideways
 * force may not push along the sideways motion, F_x v_x <= 0. Before, the sideways stress took the
 * fit's sign whichever way the plate moved, a rising element was taken for one moving sideways (its
 * angle below horizontal clamped to 0) at up to 2.7 times the stress (the vertical stress
 * mobilised over the smaller sideways law), and in the biped on flat feet in this medium
 * (results/soil/campaign) the soles chattered sideways at about 100 N a step until the trial
 * stopped on the energy check. Rounding: 1e-9 W. */
static void rft_forces_never_push_along_the_motion(void)
{
    static fs_terrain t;
    static fs_soil_grid g;
    const double L = 0.04, beta = 0.3, d = 0.03, h = 1e-4, speed = 0.02;
    const char *set[] = {"soil.grid_m=1e-3"};
    int pushed = 0, rising = 0;
    double worst = -INFINITY, worst_side = -INFINITY;
    for (int k = 0; k < 72; k++) {
        double th = 2 * M_PI * (k + 0.5) / 72, vx = speed * cos(th), vz = speed * sin(th);
        plate_grid("terrains/soils/granular_close.ini", set, 1, L, L, 1e-4, &t, &g);
        fs_soil_body b = plate_body(1e-4 * sin(beta), t.def.soil.depth_m - d + 1e-4 * cos(beta), beta, 0, -0.01);
        fs_error err;
        REQUIRE(fs_soil_grid_step(&g, &b, h, &err) == FS_OK); /* pressed: the nodes yield at the law */
        b.v[0] = vx, b.v[2] = vz;
        REQUIRE(fs_soil_grid_step(&g, &b, h, &err) == FS_OK);
        const double *F = g.force[0];
        if (vz < 0) {
            worst = fmax(worst, F[0] * vx + F[2] * vz);
            pushed += F[0] * vx + F[2] * vz > 1e-9;
        } else {
            rising++;
            worst_side = fmax(worst_side, F[0] * vx);
            pushed += F[0] * vx > 1e-9;
        }
        fs_soil_grid_free(&g);
        fs_terrain_free(&t);
    }
    printf("  RFT plate moved in 72 directions: %d pushed along the motion; most power %.3g W sinking, sideways "
           "%.3g W rising (%d rising)\n", pushed, worst, worst_side, rising);
    CHECK(pushed == 0);
    CHECK(rising == 36);
}

/* A soil landing's impact impulse is the momentum its fall brings (the impulse at rigid ground's,
 * test_experiment_touchdown): the biomimetic foot on the rig (26 kg on a vertical slide) released 5
 * mm above LETE sand sinks some 19 mm, and the soil's force stays below the weight for the first
 * tens of ms, so that a count that ended landing.impulse_window_s (50 ms) after touchdown read 0.
 * With the count lasting until the robot's centre of mass stops falling, it reads at least the
 * fall's momentum less what the rest speed leaves, M (v - 0.01), and at most M (v + up) with up
 * the fastest rise energy allows after sinking the ankle's drop, sqrt(v^2 + 2 g drop), times 1.02
 * for the foot's own mass, as for rigid ground. */
static void soil_landing_impulse_is_the_falls_momentum(void)
{
    const char *set[] = {"scenario.design=feet/biomimetic.ini", "robot.design=robots/rig.ini",
                         "scenario.terrain=../terrains/soils/lete_sand.ini", "run.duration_s=0.4",
                         "landing.tilt_range_deg=0"};
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 5, 1, NULL, &r, &err) == FS_OK);
    const double g = 9.81, v = sqrt(2 * g * 0.005), M = r.robot_mass_kg;
    double up = sqrt(v * v + 2 * g * r.ankle_drop_m);
    printf("  impulse %.3f N s on LETE sand (touchdown %.4f s, ankle drop %.2f mm), bounds [%.3f, %.3f]\n",
           r.impact_impulse_Ns, r.touchdown_s, r.ankle_drop_m * 1e3, M * (v - 0.01), 1.02 * M * (v + up));
    CHECK(r.impact_impulse_Ns >= M * (v - 0.01));
    CHECK(r.impact_impulse_Ns <= 1.02 * M * (v + up));
}

/* ---- the links' shapes, from the design file ------------------------------------------------------ */

/* The biomimetic foot's soil shapes are the design's [soil_shapes]: twelve capsules, the heel's, the
 * talus's and each metatarsal's and phalanx's radius the key's (the chain's scale times it for the last
 * two) or, at 0 (the shipped file's: it leaves them at their defaults, so that its input hash, which
 * the CI baseline's provenance holds, stays), the contact sphere's (half link_width_m for the talus);
 * each capsule's plan area 2 r L + pi r^2 over its segment's plan length L; a radius set with --set
 * moves only its shapes. Broken, with the shapes taking the spheres' radii whatever the keys say, the
 * phalanges keep 3 mm under the 5 mm set here. */
static void the_links_soil_shapes_are_the_design_files(void)
{
    static fs_scenario sc;
    static fs_soil_shape sh[FS_SOIL_MAX_SHAPES];
    fs_error err;
    const char *const sets[][2] = {{"soil_shapes.phalanx_radius_m=0.005", "soil_shapes.heel_radius_m=0.007"},
                                   {"soil_shapes.talus_radius_m=0.006", "soil_shapes.metatarsal_radius_m=0.0045"},
                                   {NULL, NULL}};
    for (int run = 0; run < 3; run++) {
        int nset = sets[run][0] ? 2 : 0;
        REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", nset ? sets[run] : NULL, nset, &sc, &err) == FS_OK);
        const fs_design_def *d = &sc.design;
        int n = fs_soil_foot_shapes(&sc.geom, NULL, sh, FS_SOIL_MAX_SHAPES);
        CHECK(n == 2 + 2 * FS_CHAINS);
        for (int i = 0; i < n; i++) {
            const fs_soil_shape *s = &sh[i];
            int chain = 0;
            sscanf(s->name + strcspn(s->name, "0123456789"), "%d", &chain);
            double scale = chain > 0 ? fs_design_chain_scale(d, chain - 1) : 1, want = -1;
            if (!strcmp(s->name, "heel"))
                want = d->soil_heel_radius_m > 0 ? d->soil_heel_radius_m : d->heel_radius_m;
            else if (!strcmp(s->name, "talus"))
                want = d->soil_talus_radius_m > 0 ? d->soil_talus_radius_m : 0.5 * d->link_width_m;
            else if (!strncmp(s->name, "metatarsal", 10))
                want = scale * (d->soil_metatarsal_radius_m > 0 ? d->soil_metatarsal_radius_m : d->ball_radius_m);
            else if (!strncmp(s->name, "phalanx", 7))
                want = scale * (d->soil_phalanx_radius_m > 0 ? d->soil_phalanx_radius_m : d->toe_radius_m);
            double L = hypot(s->b[0] - s->a[0], s->b[1] - s->a[1]);
            double area = 2 * s->radius_m * L + M_PI * s->radius_m * s->radius_m;
            if (fabs(s->radius_m - want) > 1e-15 || fabs(s->plan_area_m2 - area) > 1e-15)
                printf("  run %d, %s: radius %.6g m, want %.6g; area %.6g m^2\n", run, s->name, s->radius_m, want,
                       s->plan_area_m2);
            CHECK(s->kind == FS_SOIL_CAPSULE && fabs(s->radius_m - want) <= 1e-15);
            CHECK(fabs(s->plan_area_m2 - area) <= 1e-15);
        }
        fs_scenario_free(&sc);
    }
}

/* ---- a soil section ----------------------------------------------------------------------------- */

/* The flat foot on the rig set down (landing_trial, no drop range) on terrain, its touchdown taken in
 * substeps (so that the forecast that starts them is exercised), with the extra settings. */
static void rig_on(const char *terrain, const char *const *extra, int nextra, fs_scenario *sc)
{
    fs_error err;
    const char *set[10] = {"scenario.design=feet/flat.ini", "robot.design=robots/rig.ini", terrain,
                           "landing.x_range_m=0", "landing.y_range_m=0", "landing.yaw_range_deg=0",
                           "landing.tilt_range_deg=0", "run.impact_substeps=4"};
    int n = 8;
    for (int k = 0; k < nextra && n < 10; k++)
        set[n++] = extra[k];
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, n, sc, &err) == FS_OK);
}

/* A foot beside a soil section lands on the bedrock, the rigid ground: with no soil node under any of
 * its shapes the soil adds no force, and its start height (drop_m over the ground under it) and the
 * touchdown forecast read the bedrock there, so every step is the rigid ground's arithmetic: its
 * ankle and contacts the same, to the bit, as on terrains/flat.ini (whose material is the default, as
 * the soil preset's bedrock's). The section lies in the grid's region (refused otherwise), beyond the
 * foot's reach by at least [soil] margin_m less 5 mm. No tile of the grid is ever made. Broken, with
 * the start lift taking the layer's depth everywhere the foot starts 100 mm higher; with the forecast
 * doing so, the substeps start sooner. */
static void a_foot_beside_a_section_lands_as_on_rigid_ground(void)
{
    static fs_scenario probe, soil_sc, rigid_sc;
    rig_on("scenario.terrain=../terrains/soils/lete_sand.ini", NULL, 0, &probe);
    char x_min[64], x_max[64];
    snprintf(x_min, sizeof x_min, "soil.x_min_m=%.6f", probe.terrain.soil_region[1] - 0.005);
    snprintf(x_max, sizeof x_max, "soil.x_max_m=%.6f", probe.terrain.soil_region[1] + 0.1);
    const char *section[] = {x_min, x_max};
    rig_on("scenario.terrain=../terrains/soils/lete_sand.ini", section, 2, &soil_sc);
    rig_on("scenario.terrain=../terrains/flat.ini", NULL, 0, &rigid_sc);
    fs_error err;
    fs_sim *a, *b;
    REQUIRE(fs_sim_new(&soil_sc, NULL, &a, &err) == FS_OK);
    REQUIRE(fs_sim_new(&rigid_sc, NULL, &b, &err) == FS_OK);
    REQUIRE(fs_sim_soil_grid(a) != NULL);
    int same = 1, steps = 0, touched = 0;
    double pa[3], pb[3];
    fs_sim_ankle(a, pa);
    fs_sim_ankle(b, pb);
    same &= pa[2] == pb[2];
    for (; steps < 3000 && same; steps++) { /* 0.3 s: the landing and its settling */
        REQUIRE(fs_sim_step(a, &err) == FS_OK);
        REQUIRE(fs_sim_step(b, &err) == FS_OK);
        fs_sim_ankle(a, pa);
        fs_sim_ankle(b, pb);
        same &= pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2];
        same &= fs_sim_contact_count(a) == fs_sim_contact_count(b);
        touched |= fs_sim_soil_nodes(a, -1) > 0 || fs_sim_soil_grid(a)->ntiles > 0;
    }
    printf("  section from x = %.3f m: %d steps alike, ankle %.6f / %.6f m, %d contacts, %d tiles made\n",
           soil_sc.terrain.def.soil.x_min_m, steps, pa[2], pb[2], fs_sim_contact_count(a), fs_sim_soil_grid(a)->ntiles);
    CHECK(same && steps == 3000);
    CHECK(!touched);
    CHECK(fs_sim_contact_count(a) > 0); /* it stands on the bedrock's contacts */
    fs_sim_free(a);
    fs_sim_free(b);
    fs_scenario_free(&probe);
    fs_scenario_free(&soil_sc);
    fs_scenario_free(&rigid_sc);
}

/* What the walk's observer found in the grid: nodes beyond the section touched (claimed, with a print,
 * yield or slip), tiles made wholly beyond it, and nodes over it with a print. */
typedef struct section_seen { long outside_touched, tiles_outside, inside_prints; } section_seen;

static fs_status look_at_section(void *user, const fs_sim *sim, fs_error *err)
{
    (void)err;
    section_seen *seen = user;
    const fs_soil_grid *g = fs_sim_soil_grid(sim);
    long prints = 0;
    for (int t = 0; t < g->ntiles; t++) {
        int k = g->slot_tile[t], ti = k % g->tx, tj = k / g->tx, st = g->stride[k];
        seen->tiles_outside += (ti + 1) * FS_SOIL_TILE - 1 < g->i_lo || ti * FS_SOIL_TILE > g->i_hi;
        const fs_soil_node *nd = g->pool + (size_t)t * FS_SOIL_TILE * FS_SOIL_TILE;
        for (int lj = 0; lj < FS_SOIL_TILE; lj += st)
            for (int li = 0; li < FS_SOIL_TILE; li += st, nd++) {
                int i = ti * FS_SOIL_TILE + li;
                (void)tj;
                if (i >= g->i_lo && i <= g->i_hi)
                    prints += nd->sp_m > 0;
                else
                    seen->outside_touched += nd->stamp != 0 || nd->sp_m != 0 || nd->yield_Pa != 0 || nd->slip_m != 0;
            }
    }
    seen->inside_prints = prints;
    return FS_OK;
}

/* The walking machine over terrains/sand_section.ini (LETE sand in a pit flush with the rigid ground,
 * x 0.22 to 0.40 m), 2 mm grid, 8 steps: no node beyond the section is ever touched and no tile is made
 * wholly beyond it (checked every 10 ms); the sand keeps prints; the steps whose stance and swing stay
 * off the section (the first two: the foot, about 0.1 m long, reaches 0.155 m; and the eighth, from
 * 0.41 m) take no energy from the soil and no press past press_m, as on rigid ground, and their records
 * say they were not on the soil, while the steps on the sand sink, press, give the soil energy and are
 * recorded on it. Broken, without the section's columns cut out of a
 * shape's nodes, the foot on the bedrock beyond the pit's far wall claims the nodes there. */
static void a_walk_over_a_section_touches_only_it(void)
{
    const char *set[] = {"scenario.terrain=../terrains/sand_section.ini", "soil.grid_m=0.002", "walk.steps=8"};
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking_sand.ini", set, 3, &sc, &err) == FS_OK);
    section_seen seen = {0, 0, 0};
    fs_run_observer obs = {.interval_s = 0.01, .fn = look_at_section, .user = &seen};
    static fs_walk_result r;
    REQUIRE(fs_walk_run(&sc, &obs, &r, &err) == FS_OK);
    printf("  %d steps completed; nodes beyond the section touched %ld, tiles beyond it %ld, prints on it %ld\n",
           r.steps_completed, seen.outside_touched, seen.tiles_outside, seen.inside_prints);
    for (int k = 0; k < r.nsteps; k++)
        printf("  step %d%s: sinkage %.2f mm, soil energy %.3f J, press %.2f mm, force %.0f N\n", k,
               r.step[k].on_soil ? " on the soil" : "", r.step[k].sinkage_m * 1e3, r.step[k].soil_work_J,
               r.step[k].extra_press_m * 1e3, r.step[k].load_N);
    CHECK(r.steps_completed == 8 && r.nsteps == 8);
    CHECK(seen.outside_touched == 0 && seen.tiles_outside == 0);
    CHECK(seen.inside_prints > 0);
    for (int k = 0; k < 8; k++) {
        int off = k <= 1 || k == 7, on = k == 4 || k == 5;
        if (off) /* and its record says its stance was not on the soil (`footsim walk`: "on rigid ground") */
            CHECK(r.step[k].soil_work_J == 0 && r.step[k].extra_press_m == 0 && r.step[k].sinkage_m == 0 &&
                  !r.step[k].on_soil);
        if (on)
            CHECK(r.step[k].soil_work_J > 0 && r.step[k].extra_press_m > 0 && r.step[k].sinkage_m > 0 &&
                  r.step[k].on_soil);
    }
    fs_scenario_free(&sc);
}

/* ---- the bedrock, and refusals --------------------------------------------------------------- */

static void thin_layer_stops_on_the_bedrock(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"scenario.design=feet/flat.ini", "scenario.terrain=../terrains/soils/dry_sand.ini",
                         "soil.depth_m=0.01", "soil.grid_m=2e-3"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 4, &sc, &err) == FS_OK);
    fs_sim sim;
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    dBodySetMaxAngularSpeed(sim.body[0], 0);
    settle(&sim, 20000);
    /* 26 kg would sink the sole some 40 mm in dry sand: the 10 mm layer ends on the rigid bedrock, whose
     * contacts then carry what the soil does not */
    double f[3], soil[3];
    fs_sim_ground_force(&sim, f);
    fs_sim_soil_force(&sim, -1, soil);
    printf("  sole bottom %.3f mm, contacts %d, soil force %.1f N of %.1f N\n", sole_bottom(&sim) * 1e3,
           sim.contacts_now, soil[2], f[2]);
    CHECK(sim.contacts_now > 0);
    CHECK(fabs(sole_bottom(&sim)) < 1e-3);
    CHECK(soil[2] < f[2]);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* A terrain file at path of text is refused, at its line 'line', with words in the message. */
static void file_refused(const char *path, const char *text, int line, const char *words)
{
    static fs_terrain t;
    fs_error err;
    FILE *f = fopen(path, "w");
    REQUIRE(f != NULL);
    fputs(text, f);
    fclose(f);
    CHECK(fs_terrain_load(path, NULL, 0, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, line, words);
}

static void bad_soils_are_refused(void)
{
    const struct { const char *set, *key; } bad[] = {
        {"bekker.n=0", "n"},
        {"bekker.k_phi_N_per_m_n2=-1", "k_phi_N_per_m_n2"},
        {"bekker.K_e_Pa_per_m=-5", "K_e_Pa_per_m"},
        {"bekker.friction_deg=90", "friction_deg"},
        {"soil.depth_m=0", "depth_m"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        static fs_terrain t;
        fs_error err;
        const char *set[] = {bad[i].set};
        CHECK(fs_terrain_load("terrains/soils/dry_sand.ini", set, 1, &t, &err) == FS_BAD_INPUT);
        CHECK(strstr(err.message, bad[i].key) != NULL);
    }
    /* an rft soil without its scale or density: file:line of the model */
    static fs_terrain t;
    fs_error err;
    const char *no_zeta[] = {"rft.zeta_N_per_m3=0"}, *no_rho[] = {"rft.density_kg_per_m3=0"};
    CHECK(fs_terrain_load("terrains/soils/granular_loose.ini", no_zeta, 1, &t, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "zeta_N_per_m3") != NULL);
    CHECK(fs_terrain_load("terrains/soils/granular_loose.ini", no_rho, 1, &t, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "density_kg_per_m3") != NULL);
    /* phi given in the file at 90: its file:line */
    char dir[] = "/tmp/fs_soil_XXXXXX";
    REQUIRE(mkdtemp(dir) != NULL);
    char path[300];
    snprintf(path, sizeof path, "%s/t.ini", dir);
    file_refused(path, "[soil]\nmodel = bekker\n\n[bekker]\nfriction_deg = 90\n", 5, "[0, 90)");
    /* a bekker soil with no bearing strength (k_c = k_phi = 0: Bekker's pressure 0 at every sinkage, the
     * foot through to the bedrock): k_phi's file:line; k_c alone, or k_phi alone, bears a load */
    file_refused(path, "[soil]\nmodel = bekker\ndepth_m = 0.1\n\n[bekker]\nn = 1\nk_phi_N_per_m_n2 = 0\n"
                 "k_c_N_per_m_n1 = 0\n", 7, "k_phi_N_per_m_n2 > 0 or k_c_N_per_m_n1 > 0");
    const char *kc_only[] = {"bekker.k_c_N_per_m_n1=1000"}, *kphi_only[] = {"bekker.k_phi_N_per_m_n2=1e5",
                                                                            "bekker.k_c_N_per_m_n1=0"};
    CHECK(fs_terrain_load(path, kc_only, 1, &t, &err) == FS_OK);
    fs_terrain_free(&t);
    CHECK(fs_terrain_load(path, kphi_only, 2, &t, &err) == FS_OK);
    fs_terrain_free(&t);
    /* every shipped Bekker preset passes (the granular ones are RFT's) */
    const char *presets[] = {"dry_sand", "lete_sand", "sandy_loam", "lean_clay", "snow", "mud"};
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        char preset[200];
        snprintf(preset, sizeof preset, "terrains/soils/%s.ini", presets[i]);
        CHECK(fs_terrain_load(preset, NULL, 0, &t, &err) == FS_OK);
        fs_terrain_free(&t);
    }
    /* an empty soil section: x_max_m's file:line */
    file_refused(path, "[soil]\nmodel = bekker\nx_min_m = 0.3\nx_max_m = 0.2\n\n[bekker]\nn = 1\n", 4,
                 "section is empty");
    remove(path);
    /* a section that misses the ground the run covers: where x_min_m came from */
    static fs_scenario far;
    const char *beyond[] = {"scenario.terrain=../terrains/soils/dry_sand.ini", "soil.x_min_m=5", "soil.x_max_m=6"};
    CHECK(fs_scenario_load("scenarios/static_load.ini", beyond, 3, &far, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, "--set soil.x_min_m", 0, "outside the ground the run covers");
    CHECK(strncmp(err.message, "--set soil.x_min_m", 18) == 0);
    rmdir(dir);
    /* a grid past the memory cap, refused when the scenario is read */
    static fs_scenario sc;
    const char *big[] = {"scenario.terrain=../terrains/soils/dry_sand.ini", "soil.grid_m=1e-4", "soil.max_nodes=1000"};
    CHECK(fs_scenario_load("scenarios/static_load.ini", big, 3, &sc, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "max_nodes") != NULL);
}


/* ---- the step's claims -------------------------------------------------------------------------- */

/* Three plates stacked 0.1 mm apart over the same 40 x 40 mm (each on a body of its own) on a grid
 * whose pool and claims start at a single tile's worth: every node is claimed three times, which the
 * claims (sized for the pool's nodes) cannot hold until they grow. The lowest plate takes every node:
 * its force must be, to the bit, the force the same plate gets alone on a fresh grid (the claims keep
 * the order of its rows), and the two above it carry none. */
static void plate_stack(int nplates, double F[3], int nodes[3], int *claim_grows)
{
    static fs_terrain t;
    static fs_soil_grid g;
    fs_error err;
    const char *set[] = {"soil.grid_m=5e-4"};
    REQUIRE(fs_terrain_load("terrains/soils/dry_sand.ini", set, 1, &t, &err) == FS_OK);
    double region[4] = {-0.1, 0.1, -0.1, 0.1}, start[4] = {-1e-3, 1e-3, -1e-3, 1e-3};
    REQUIRE(fs_soil_region(&t.def.soil, region, t.path, t.soil_region, NULL, &err) == FS_OK);
    memset(&g, 0, sizeof g);
    REQUIRE(fs_soil_grid_init(&g, &t, (const double(*)[4])start, 1, &err) == FS_OK);
    fs_soil_body b[3];
    for (int k = 0; k < nplates; k++) {
        fs_soil_shape *s = &g.shape[g.nshapes++];
        memset(s, 0, sizeof *s);
        s->kind = FS_SOIL_BOX;
        s->body = k;
        s->half[0] = s->half[1] = 0.02, s->half[2] = 1e-3;
        s->R[0] = s->R[4] = s->R[8] = 1;
        /* the lowest (the last) 10 mm into the soil, the others 0.1 and 0.2 mm above it */
        b[k] = plate_body(1e-4, t.def.soil.depth_m - 0.01 + 1e-3 + 1e-4 * (nplates - 1 - k), 0, 0, -0.01);
    }
    REQUIRE(fs_soil_grid_step(&g, b, 1e-4, &err) == FS_OK);
    memcpy(F, g.force[nplates - 1], 3 * sizeof(double));
    for (int k = 0; k < nplates; k++)
        nodes[k] = g.nodes[k];
    *claim_grows = g.claim_grows;
    fs_soil_grid_free(&g);
    fs_terrain_free(&t);
}

static void stacked_shapes_outgrow_the_claims(void)
{
    double alone[3], stacked[3];
    int n1[3], n3[3], grows1, grows3;
    plate_stack(1, alone, n1, &grows1);
    plate_stack(3, stacked, n3, &grows3);
    printf("  alone: %d nodes, Fz %.6f N; stacked: %d, %d, %d nodes, Fz %.6f N; the claims grew %d times\n", n1[0],
           alone[2], n3[0], n3[1], n3[2], stacked[2], grows3);
    CHECK(grows3 > 0);
    /* 40 mm at 0.5 mm: 80 or 81 nodes a side, by where the plate's edges fall on the grid */
    CHECK(n1[0] >= 80 * 80 && n1[0] <= 81 * 81 && n3[2] == n1[0] && n3[0] == 0 && n3[1] == 0);
    for (int k = 0; k < 3; k++)
        CHECK(stacked[k] == alone[k]);
}

FS_TEST_MAIN(TEST(rft_alpha_has_its_symmetries), TEST(rft_plate_at_depth_and_tilt), TEST(rft_forces_never_push_along_the_motion),
             TEST(soil_landing_impulse_is_the_falls_momentum), TEST(plate_dragged_follows_janosi), TEST(bad_soils_are_refused),
             TEST(thin_layer_stops_on_the_bedrock), TEST(sole_sinks_as_bekker_says), TEST(halving_the_grid_moves_sinkage_little),
             TEST(the_sole_on_its_coarse_grid), TEST(stacked_shapes_outgrow_the_claims),
             TEST(halving_the_capsules_spacing_moves_sinkage_little), TEST(a_box_carries_its_plans_area),
             TEST(a_foot_beside_a_section_lands_as_on_rigid_ground), TEST(a_walk_over_a_section_touches_only_it),
             TEST(the_links_soil_shapes_are_the_design_files))
