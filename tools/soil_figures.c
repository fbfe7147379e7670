/* soil_figures.c: Fig. 11 on soft ground (docs/soil.md): 26 kg set down on the foot on every soil
 * preset, for both feet: the landing trial's scenario with the rig robot (26 kg on a vertical slide,
 * so the foot keeps its attitude as under the paper's test load; scenarios/robots/rig.ini), no
 * drop and no drawn pose, run until at rest or LIMIT_S (5 s). (The static-load scenario's bare force at the
 * ankle turns a foot on soil over: nothing holds its pitch once the heel sinks.) Per run: the
 * ankle's drop, the deepest print under the foot, the foot's tilt (its ankle body's z axis from
 * vertical), the time to rest, the area the soil carries the foot on (fs_sim_soil_area: its nodes
 * times their cells, the sole's edge nodes times the share of its plan they stand for), the soil's share of the
 * ground force (the rest on the bedrock), and for a run that never came to rest what its ankle did over its
 * last second: a creep (its mean height still falling) or a bounce (a swing about a steady mean).
 * Built with footsim (`cmake --build build` makes build/soil-figures); run from the source folder:
 * `build/soil-figures > results/soil/static_load.md` (`build/soil-figures FOOT`: only that foot's rows;
 * `build/soil-figures FOOT SOIL`: one row). A Markdown table on stdout.
 * `build/soil-figures --ramp [FOOT [SOIL]]`: the load set down slowly instead, so that the sinkage is
 * the soil's bearing under a static load and not an impact's overshoot, which a plastic soil keeps:
 * a 1 kg rig carrying a 25 kg [load] at the ankle that rises from 0 over RAMP_S, rest looked for only
 * once it is whole; for the flat sole on a Bekker soil, beside Bekker's closed form for its plate
 * under the whole weight (26 kg and the foot's own). */
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_sim_soil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How long a row may run, s; for a row that never came to rest, the ankle's height is sampled every
 * SAMPLE_S and its last two windows of CREEP_S compared: the mean's fall between them over CREEP_S (a creep,
 * mm/s) and the last window's swing (highest less lowest: a foot that bounces without settling, mm). */
#define LIMIT_S 5.0
#define CREEP_S 0.5
#define SAMPLE_S 0.001 /* NSAMPLES below holds LIMIT_S of them and one each end */
#define RAMP_S 1.0     /* --ramp: the load's rise, s */
static int ramped;     /* --ramp given */
enum { NSAMPLES = 5002 };

static const char *SOILS[] = {"dry_sand", "lete_sand", "sandy_loam", "lean_clay", "snow", "mud", "granular_loose",
                              "granular_close"};

static int run(const char *foot, const char *soil)
{
    static fs_scenario sc;
    fs_error err;
    char design[128], terrain[128], duration[64];
    snprintf(design, sizeof design, "scenario.design=feet/%s.ini", foot);
    snprintf(duration, sizeof duration, "run.duration_s=%g", LIMIT_S);
    snprintf(terrain, sizeof terrain, "scenario.terrain=../terrains/soils/%s.ini", soil);
    char ramp[64];
    snprintf(ramp, sizeof ramp, "load.ramp_s=%g", RAMP_S);
    const char *set[] = {design, terrain, "robot.design=robots/rig.ini", "start.drop_m=0", duration,
                         "landing.x_range_m=0", "landing.y_range_m=0", "landing.yaw_range_deg=0",
                         "landing.tilt_range_deg=0", "robot.mass_kg=1", "load.mass_kg=25", ramp};
    if (fs_scenario_load("scenarios/landing_trial.ini", set, ramped ? 12 : 9, &sc, &err) != FS_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    fs_sim *sim;
    if (fs_sim_new(&sc, NULL, &sim, &err) != FS_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    double a0[3], a[3];
    fs_sim_ankle(sim, a0);
    double rest_since = -1, wall = fs_clock_s();
    static double z_at[NSAMPLES]; /* the ankle's height every SAMPLE_S */
    int nz = 0;
    long steps = 0;
    const char *end = "window";
    while (fs_sim_time(sim) < sc.def.duration_s - 1e-9) {
        if (fs_sim_step(sim, &err) != FS_OK) {
            end = "numerical";
            break;
        }
        steps++;
        if (fs_sim_time(sim) >= nz * SAMPLE_S - 1e-9 && nz < NSAMPLES) {
            double p[3];
            fs_sim_ankle(sim, p);
            z_at[nz++] = p[2];
        }
        int slow = fs_sim_max_speed(sim) < 1e-3 && (!ramped || fs_sim_time(sim) >= RAMP_S);
        if (slow && rest_since < 0)
            rest_since = fs_sim_time(sim);
        if (!slow)
            rest_since = -1;
        if (rest_since >= 0 && fs_sim_time(sim) - rest_since > 0.05) {
            end = "rest";
            break;
        }
    }
    wall = fs_clock_s() - wall;
    fs_sim_ankle(sim, a);
    const fs_soil_grid *g = fs_sim_soil_grid(sim);
    double R[9], f[3], held[3], deepest;
    fs_sim_body_pose(sim, fs_sim_geom(sim)->ankle_body, NULL, R);
    fs_sim_ground_force(sim, f);
    fs_sim_soil_force(sim, -1, held);
    fs_soil_grid_print(g, &deepest, NULL);
    int back = (int)lround(CREEP_S / SAMPLE_S); /* the last two windows of CREEP_S */
    char creep[48] = "-";
    if (end[0] != 'r' && nz > 2 * back) {
        double m1 = 0, m2 = 0, lo = INFINITY, hi = -INFINITY;
        for (int k = nz - 2 * back; k < nz - back; k++)
            m1 += z_at[k] / back;
        for (int k = nz - back; k < nz; k++) {
            m2 += z_at[k] / back;
            lo = fmin(lo, z_at[k]), hi = fmax(hi, z_at[k]);
        }
        double sinking = (m1 - m2) / CREEP_S * 1e3;
        snprintf(creep, sizeof creep, "%.3f mm/s, swing %.2f mm", fabs(sinking) < 5e-4 ? 0 : sinking, (hi - lo) * 1e3);
    }
    double area = fs_sim_soil_area(sim, -1);
    /* the fifth column: the foot's tilt, or (--ramp) the sole's plate under the whole weight, Bekker's
     * sinkage for b = 2 A / P (docs/soil.md, The model), "-" for a foot of links, an RFT soil or a
     * sinkage past the layer (on the bedrock) */
    char fifth[32] = "-";
    const fs_soil_def *sd = &sc.terrain.def.soil;
    if (!ramped)
        snprintf(fifth, sizeof fifth, "%.1f", acos(fmin(1, fmax(-1, R[8]))) * 180 / M_PI);
    else if (sc.geom.nboxes && sd->model == FS_SOIL_BEKKER) {
        double A = sc.geom.box_size.x * sc.geom.box_size.y, P = 2 * (sc.geom.box_size.x + sc.geom.box_size.y);
        double W = (sc.def.load_kg + sc.def.robot.mass_kg + sc.geom.total_mass_kg) * sc.def.gravity_m_per_s2;
        double z = fs_bekker_sinkage(sd, 2 * A / P, W / A);
        if (z < sd->depth_m)
            snprintf(fifth, sizeof fifth, "%.1f", z * 1e3);
    }
    printf("| %s | %s | %.1f | %.1f | %s | %s%.3f | %s | %.1f | %.0f %% | %.2f |\n", foot, soil, (a0[2] - a[2]) * 1e3,
           deepest * 1e3, fifth, end[0] == 'r' ? "" : "> ", end[0] == 'r' ? rest_since : fs_sim_time(sim), creep,
           area * 1e4, f[2] != 0 ? 100 * held[2] / f[2] : 0, steps ? 1e3 * wall / steps : 0);
    fflush(stdout);
    fs_sim_free(sim);
    fs_scenario_free(&sc);
    return 0;
}

int main(int argc, char **argv)
{
    fs_ode_init();
    ramped = argc > 1 && !strcmp(argv[1], "--ramp");
    const char *only = argc > 1 + ramped ? argv[1 + ramped] : NULL;      /* a foot's name: only its rows */
    const char *only_soil = argc > 2 + ramped ? argv[2 + ramped] : NULL; /* and a soil's: only that row */
    if (ramped)
        printf("| foot | soil | ankle drop (mm) | deepest print (mm) | Bekker's closed form, the sole (mm) | at rest (s) "
               "| not at rest: mean sinking, swing (last 0.5 s) | carried on (cm^2) | soil's share | ms a step "
               "|\n|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    else
        printf("| foot | soil | ankle drop (mm) | deepest print (mm) | tilt (deg) | at rest (s) | not at rest: mean "
               "sinking, swing (last 0.5 s) | carried on (cm^2) | soil's share | ms a step |\n"
               "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    int bad = 0;
    for (size_t s = 0; s < sizeof SOILS / sizeof SOILS[0]; s++)
        for (int f = 0; f < 2; f++)
            if ((!only || !strcmp(only, f ? "flat" : "biomimetic")) && (!only_soil || !strcmp(only_soil, SOILS[s])))
                bad |= run(f ? "flat" : "biomimetic", SOILS[s]);
    return bad;
}
