/* fs_trial.h: one landing trial: a passive robot (a body standing for torso and leg) on a foot,
 * let fall onto a terrain from a drawn pose, with no control, until it has landed or fallen.
 *
 * A trial scenario is an ordinary scenario file with a [robot] section (the body, and how it is
 * joined to the ankle: rigidly or through an Achilles spring-damper) and a [landing] section
 * (the ranges the pose is drawn from, and the rules that decide the outcome). The seed decides
 * the draw and, on a random terrain, the terrain's own seed: the same scenario, overrides and
 * seed give a bit-identical result on any machine and in any process.
 *
 * Outcome: the rules of fs_outcome.h, on the robot's lean, the foot's contact, the bodies' motion
 * and the deepest foot shape; the result names the rule that decided (docs/landing.md). */
#ifndef FS_TRIAL_H
#define FS_TRIAL_H

#include "footsim/experiment/fs_outcome.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_observer.h"
#include "footsim/model/fs_scenario.h"

/* The drawn start of a trial. */
typedef struct fs_trial_draw {
    int seed;
    double x_m, y_m, yaw_deg, pitch_deg, roll_deg;
} fs_trial_draw;

typedef struct fs_trial_result {
    fs_trial_draw draw;
    int outcome;                 /* fs_outcome */
    int rule;                    /* fs_rule: what decided it */
    double robot_mass_kg;        /* the robot dropped (every body above the ankle) */
    char failure[512];           /* for FS_FAILED_NUMERICS: what happened, and when */
    double end_time_s;           /* simulated time when the trial ended */
    double touchdown_s;          /* first contact */
    double peak_tilt_deg, final_tilt_deg;   /* the body's lean from upright */
    double peak_force_N;         /* peak vertical ground force on the foot */
    double impact_impulse_Ns;    /* momentum the ground took out of the fall: the largest vertical
                                    ground impulse beyond the weight, from the step it first pushed,
                                    within landing.impulse_window_s of touchdown (docs/landing.md) */
    double settle_time_s;        /* from touchdown until at rest (until the end when it never was) */
    double mean_contacts, final_contacts;   /* foot-terrain contact points, mean after touchdown */
    double ankle_drop_m;         /* ankle height at touchdown minus at the end */
    double slip_m;               /* horizontal travel of the ankle from touchdown to the end */
    long steps;
    /* on a soil, at the end (NAN on rigid ground): how deep the feet reach below the soil's
       undisturbed surface (fs_sim_soil_sinkage: the deepest node they press, the bedrock at most),
       and the prints left (fs_soil_grid_print_of: their deepest plastic sinkage, area and volume,
       and the slip accumulated on their nodes, the mean by area) */
    double soil_sinkage_m, print_depth_m, print_area_m2, print_volume_m3, print_slip_m;
    /* the steps taken (fs_step_stats): with run.tolerance_m the error-controlled step's, else the
       fixed step's (none rejected, least = median = largest = step_s) */
    long rejected_steps, ode_steps;
    double step_least_s, step_median_s, step_largest_s;
    /* each foot's own (a biped's two: 0 right, 1 left, each from its own touchdown; the trial's
       ankle_drop_m is then their mean, slip_m the larger, the contacts their sums). One foot: its
       foot[0] is the trial's own */
    int nfeet;
    struct {
        double touchdown_s, ankle_drop_m, slip_m, mean_contacts, final_contacts;
        double final_force_N;    /* the ground's vertical force on it in the last step */
    } foot[FS_MAX_FEET];
} fs_trial_result;

/* The pose drawn for seed from sc's [landing] ranges (pure function of the two). */
void fs_trial_draw_pose(const fs_scenario *sc, int seed, fs_trial_draw *draw);

/* A copy of the loaded trial scenario base placed for seed (fs_trial_place; draw may be NULL), on
 * the heap for the caller (trials are re-entrant): *out, freed with fs_trial_placed_free (NULL is
 * nothing); *out NULL on failure. */
fs_status fs_trial_placed(const fs_scenario *base, int seed, fs_trial_draw *draw, fs_scenario **out, fs_error *err);
void fs_trial_placed_free(fs_scenario *sc);

/* What the terrain offers under the footprint for one seed (the drop law's support; docs/landing.md).
 * The foot of sc, placed for seed (its drawn x, y and yaw; its drawn tilt left out), settles rigidly
 * on the seed's terrain: each contact shape is a point (a sphere: its lowest point over the highest
 * of the terrain under its centre and four points a radius away; a sole: 11 by 7 points over its
 * bottom face, corners included),
 * and the foot comes to rest (small tilts) on the plane over those points that is lowest under the
 * robot's centre of mass (com_forward_m ahead of the ankle along the foot, moved by its height
 * times the tilt): the upper hull's facet over it. Shapes within travel_m of that plane (the arch's
 * and contacts' give under the weight) bear; their contact points make the support polygon, and the
 * edge is where the line from the ankle through the centre of mass leaves it, the side the nearest of
 * its sides. The centre of mass is
 * not over the support (over 0) when it stands beyond every facet (the foot tips off) or the bearing
 * points span no area. A biped's two feet settle as one rigid support (both feet's shapes, the
 * ankle the midpoint of its two ankles), its toes and heels counted over both.
 * A biomimetic foot's chains give: a toe or midfoot sphere ahead of the ankle at a corner of the
 * rest, whose rise above the rest the others make is more than travel_m, folds away when its chain,
 * of pitch stiffness chain_k_N_m_per_rad about the ankle (k = chain_k / a^2 at a shape a ahead of
 * it), holds less than the share of the weight (everything the ground carries: robot and feet) that
 * corner carries over that rise; the foot then rests on the others, the folded shape bearing. One
 * shape at a time, the most loaded corner first, as long as the others still hold the centre of
 * mass. A folded shape is not the first contact the rocking (settle_m, first_x_m, first_y_m) is
 * taken from. 0: rigid chains (a flat sole has none). */
enum { FS_SUPPORT_MAX_CORNERS = 192 }; /* two feet's soles' 11 x 7 points each and all their spheres fit */
typedef struct fs_trial_support {
    int bearing;               /* contact points that bear (a sole's grid points count one each) */
    int toes_bearing, toes;    /* of the toes' spheres (a biomimetic foot's phalanges): bearing, all */
    int heel_bearing;          /* a heel sphere bears */
    int over;                  /* the centre of mass stands over the polygon (inside it) */
    double tilt_forward_rad;   /* the foot at rest pitched towards the toes (the robot's lean it adds) */
    double tilt_side_rad;      /* and rolled */
    double edge_m;             /* from the ankle to the polygon's edge through the centre of mass (ahead,
                                  or behind for a centre of mass behind the ankle at rest), m */
    double ankle_height_m;     /* the ankle above the terrain at that edge, m */
    double side_m;             /* from the centre of mass to the polygon's nearest side, m */
    double spread_m2;          /* sum over the bearing points of the squared distance along the foot
                                  from their mean, m^2: the contacts' pitch stiffness per unit of each
                                  point's (fs_pitch_contact_series) */
    double settle_m;           /* how far the foot's base under the centre of mass sinks as the foot
                                  rocks from its first contact (lowered flat) onto its rest, m */
    /* the rocking's geometry, in the foot's frame (x along the foot, y to its left) from the ground
       point under the centre of mass at rest: the first contact, the axis of the rest plane's tilt
       (horizontal; zero when it is level) and the support polygon's corners, counter-clockwise */
    double first_x_m, first_y_m, rock_axis_x, rock_axis_y;
    int ncorners;
    double corner_x_m[FS_SUPPORT_MAX_CORNERS], corner_y_m[FS_SUPPORT_MAX_CORNERS];
    /* each toe (of `toes`): how far below the rest plane its ground lies past the travel (0: it
       bears), and how far ahead of the ankle along the foot it stands, m */
    double toe_gap_m[FS_MAX_FEET * FS_CHAINS], toe_ahead_m[FS_MAX_FEET * FS_CHAINS];
} fs_trial_support;
fs_status fs_trial_support_of(const fs_scenario *sc, int seed, double travel_m, double chain_k_N_m_per_rad,
                              fs_trial_support *out, fs_error *err);

/* Places a loaded trial scenario for seed: draws the pose (draw may be NULL), puts it and the seed
 * into sc's definitions (the start pose; the terrain's seed, so every trial lands on new ground)
 * and compiles sc again (fs_scenario_compile). A scenario is placed once, from its loaded ranges. */
fs_status fs_trial_place(fs_scenario *sc, int seed, fs_trial_draw *draw, fs_error *err);

/* The rules a trial of sc is judged by (fs_outcome.h: sc's [landing] and [run] keys, the terrain's
 * sink bound, and the rest floor from the mass of everything sim moves; sim built from sc). For a
 * run of the same trial in another engine judged as footsim judges it (tools/mujoco_trial.c). */
void fs_trial_rules(const fs_scenario *sc, const fs_sim *sim, fs_outcome_rules *rules);

/* Loads the trial scenario with overrides (checked as usual: FS_BAD_INPUT, nothing run), draws
 * the pose for seed, runs the trial and fills out. A numerical failure is not an error of the
 * call: it returns FS_OK with out->outcome = FS_FAILED_NUMERICS and out->failure set. obs
 * (fs_observer.h) may be NULL; an observer's own failure is returned as its status. */
fs_status fs_trial_run(const char *scenario_path, const char *const *overrides, int noverrides, int seed,
                       const fs_run_observer *obs, fs_trial_result *out, fs_error *err);

/* Runs seed's trial of a loaded trial scenario: on a copy of it, placed for seed (fs_trial_place),
 * so sc itself is left as it was and serves every seed (a campaign loads each foot and terrain
 * once). Otherwise as fs_trial_run. */
fs_status fs_trial_run_scenario(const fs_scenario *sc, int seed, const fs_run_observer *obs, fs_trial_result *out,
                                fs_error *err);

/* The same, keeping the trial's time series in log (fs_run.h's columns and the robot's lean,
 * lean_deg, every log_interval_s, and at the end) when log is not NULL: fs_run_free releases it,
 * fs_run_write_trajectory writes it. The trial's result is the same bits with or without it. */
fs_status fs_trial_run_logged(const fs_scenario *sc, int seed, const fs_run_observer *obs, fs_run_result *log,
                              fs_trial_result *out, fs_error *err);

/* Whether r holds measurements: not a numerical failure, nor a trial whose worker was lost (hung,
 * killed), which have only their draw and their failure text. */
static inline int fs_trial_measured(const fs_trial_result *r)
{
    return r->outcome != FS_FAILED_NUMERICS && r->outcome != FS_HUNG && r->outcome != FS_KILLED;
}

#endif
