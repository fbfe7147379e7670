/* fs_scenario.h: an experiment described by a file: which foot, what ground, what load, and
 * how to integrate. fs_scenario_load reads and checks the file and the design it names, and
 * refuses anything wrong before any simulation starts.
 *
 * Overrides ("section.key=value") go to the scenario when it has that section and to the design
 * otherwise, so `--set springs.k_d1_N_per_m=9000` reaches the foot through the scenario. */
#ifndef FS_SCENARIO_H
#define FS_SCENARIO_H

#include "footsim/fs_design.h"

typedef enum fs_stepper { FS_STEPPER_STEP = 0, FS_STEPPER_QUICKSTEP = 1 } fs_stepper;

typedef struct fs_scenario_def {
    char design_path[FS_PATH_MAX];
    double ground_mu;
    double ground_stiffness_N_per_m, ground_damping_Ns_per_m;
    double load_kg;            /* applied vertically at the ankle */
    double tilt_deg;           /* the load and gravity turned about the lateral axis; positive
                                  tilts the foot toe-up relative to them */
    double ramp_s;             /* the load rises linearly over this time */
    double duration_s, step_s;
    int stepper, iterations;
    int springs;               /* fs_spring_impl */
    double gravity_m_per_s2;
    double log_interval_s;
    double rest_speed_m_per_s; /* at rest once every body is slower than this ... */
    double rest_hold_s;        /* ... for this long, after the ramp: the run then stops */
    double settle_band_m;      /* settled once the ankle stays this close to its final height */
    int max_contacts;          /* per foot geom against the ground */
    double joint_erp, joint_cfm; /* ODE's hinge error reduction and constraint force mixing */
    double contact_layer_m;    /* ODE's contact surface layer */
} fs_scenario_def;

typedef struct fs_scenario {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];    /* the file's base name without .ini */
    fs_scenario_def def;
    fs_design_def design;
    fs_foot_geom geom;
} fs_scenario;

extern const fs_key fs_scenario_keys[];
extern const int fs_scenario_nkeys;

fs_status fs_scenario_load(const char *path, const char *const *overrides, int noverrides, fs_scenario *sc,
                           fs_error *err);

/* A scenario with every default but the design, for commands that take a design alone. */
fs_status fs_scenario_for_design(const char *design_path, const char *const *overrides, int noverrides,
                                 fs_scenario *sc, fs_error *err);

/* Routes overrides: those whose section the scenario schema knows into *scen, the others into
 * *design (pointers into overrides); counts in *nscen, *ndesign. */
void fs_split_overrides(const char *const *overrides, int n, const char **scen, int *nscen, const char **design,
                        int *ndesign);

#endif
