/* fs_scenario.h: an experiment described by a file: which foot, what ground, what load, and
 * how to integrate. fs_scenario_load reads and checks the file and the design it names, and
 * refuses anything wrong before any simulation starts. What it accepts but doubts is a warning
 * (fs_warn, fs_error.h; the command prints "footsim: warning: ..."): a heightmap that covers only part of the region the foot can
 * reach (one it never reaches is refused).
 *
 * Overrides ("section.key=value") go to the scenario, the terrain, the design or the robot,
 * whichever has that key (their sections are distinct, but for [robot]: `design` is the
 * scenario's, the rest the robot file's), so `--set springs.k_d1_N_per_m=9000` reaches the foot,
 * `--set material.mu=0.5` the ground and `--set robot.mass_kg=30` the robot through the scenario. */
#ifndef FS_SCENARIO_H
#define FS_SCENARIO_H

#include "footsim/model/fs_design.h"
#include "footsim/model/fs_robot.h"
#include "footsim/model/fs_terrain.h"
#include "footsim/io/fs_provenance.h"

/* The most steps one run, trial or walk may take (docs/keys.md): refused before it starts. */
enum { FS_MAX_STEPS = 1000000000 };
/* run.step_s's range (a campaign's [robot.NAME] step_s is checked against it too). */
#define FS_STEP_MIN_S 1e-7
#define FS_STEP_MAX_S 0.1
/* The most contacts one foot shape finds against the terrain in a step: run.max_contacts keeps up
 * to this many (all of them: the reference its default is checked against). */
enum { FS_MAX_SHAPE_CONTACTS = 256 };

typedef enum fs_stepper { FS_STEPPER_STEP = 0, FS_STEPPER_QUICKSTEP = 1 } fs_stepper;

/* [run] error_estimate: how the error-controlled step (tolerance_m) estimates a step's error (the
 * order of the key's choices; sim_adapt.c). */
typedef enum fs_error_estimate { FS_ESTIMATE_DOUBLING = 0, FS_ESTIMATE_EMBEDDED = 1 } fs_error_estimate;

/* [scenario] kind: what the scenario is run by (the order of the key's choices). */
typedef enum fs_scenario_kind { FS_SCENARIO_EXPERIMENT = 0, FS_SCENARIO_WALK = 1 } fs_scenario_kind;

typedef struct fs_scenario_def {
    int kind;                  /* fs_scenario_kind: an experiment (run, trial) or the walking machine */
    char design_path[FS_PATH_MAX];
    char terrain_path[FS_PATH_MAX];
    double start_x_m, start_y_m, yaw_deg, pitch_deg, roll_deg; /* where the foot starts */
    double drop_m;             /* gap between the foot's lowest point and the terrain under it */
    double region_margin_m;    /* the heightfield is cut to the footprint plus this margin */
    double load_kg;            /* applied vertically at the ankle */
    double tilt_deg;           /* the load and gravity turned about the lateral axis; positive
                                  tilts the foot toe-up relative to them */
    double ramp_s;             /* the load rises linearly over this time */
    double duration_s, step_s;
    int impact_substeps;       /* > 1: a step around a touchdown is taken as this many substeps (fs_sim_step) */
    double impact_window_s;    /* ... from a touchdown foreseen within the step until this long after it */
    double tolerance_m;        /* > 0: an error-controlled step (fs_sim_step) of at most step_max_s ... */
    double step_max_s, step_min_s; /* ... and an ODE step of at least step_min_s; 0: fixed steps of step_s */
    int error_estimate;        /* fs_error_estimate: with tolerance_m, step doubling or the embedded pair */
    int stepper, iterations;
    int springs;               /* fs_spring_impl */
    int damping_correction;    /* 1: soft rows' dampers less k h (fs_spring_soft), 0: plain implicit Euler */
    double gravity_m_per_s2;
    double log_interval_s;
    double rest_speed_m_per_s; /* at rest once every body is slower than this ... */
    double rest_hold_s;        /* ... for this long, after the ramp: the run then stops */
    double settle_band_m;      /* settled once the ankle stays this close to its final height */
    int max_contacts;          /* per foot geom against the ground */
    double joint_erp, joint_cfm; /* ODE's hinge error reduction and constraint force mixing */
    double contact_layer_m;    /* ODE's contact surface layer */
    int tile_cells;            /* heightfield tiles' size, cells a side */
    char robot_path[FS_PATH_MAX]; /* [robot] design: the robot's file, or "" for none */
    fs_robot_def robot;        /* read from it (fs_robot.h) */
    /* [landing]: the drawn pose and the rules of a landing trial */
    double land_x_range_m, land_y_range_m, land_yaw_range_deg, land_tilt_range_deg;
    double landed_tilt_deg, fall_tilt_deg;
    double lost_ground_s, motion_window_s, motion_decay; /* the rules of fs_outcome.h */
    double impulse_window_s;   /* the impact impulse is read within this long after touchdown */
    /* [walk]: the walking machine (Fig. 16) */
    int walk_steps;
    double step_length_m, walk_period_s, stance_fraction, lift_m, press_m;
    double suspension_k_N_per_m, suspension_c_Ns_per_m, walk_fall_tilt_deg;
    /* [check]: the bounds of the state checks after every step (fs_check.h) */
    double check_max_speed_m_per_s, check_max_loop_error_m, check_energy_margin_J, check_energy_margin_rel;
    int check_energy_every;
    /* what a run may skip (the speed benchmark measures both ways) */
    int collide_all;           /* 0: foot shapes against the ground only; 1: every pair, foot-foot too */
    int heightfield_ode;       /* 0: footsim's own contacts with a heightfield (sim_lattice.h); 1: ODE's */
    double auto_disable_s;     /* > 0: ODE disables bodies slower than rest_speed_m_per_s for this long */
    double min_inertia_kg_m2;  /* > 0: each foot body's inertia raised so that its smallest principal
                                  moment is at least this (fs_sim_build; for QuickStep); 0: off */
} fs_scenario_def;

typedef struct fs_scenario {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];    /* the file's base name without .ini */
    fs_scenario_def def;
    fs_design_def design;
    fs_foot_geom geom;
    fs_terrain terrain;        /* cut to the region the foot can reach */
    int is_trial;              /* the file (or --set) gives [robot] or [landing]: a landing trial */
    /* an unset log interval follows the step (its default or the step, the longer): the default,
       0 when the file or --set gave one; the value it was given last, so that an edit in code of
       def.log_interval_s counts as setting it */
    double log_interval_default_s, log_interval_followed_s;
    /* where the design gives each spring kind's law (fs_design_load_located; "" for a scenario
       not loaded from files), for checks after loading that name its line */
    char law_where[3][FS_DESIGN_WHERE_MAX];
} fs_scenario;

extern const fs_key fs_scenario_keys[];
extern const int fs_scenario_nkeys;

fs_status fs_scenario_load(const char *path, const char *const *overrides, int noverrides, fs_scenario *sc,
                           fs_error *err);

/* A scenario with every default but the design, for commands that take a design alone. */
fs_status fs_scenario_for_design(const char *design_path, const char *const *overrides, int noverrides,
                                 fs_scenario *sc, fs_error *err);

/* Refuses (FS_BAD_INPUT) a scenario that is not for `command` ("run", "trial", "walk"), naming
 * the command it is for: a walk scenario is for walk only, a landing trial ([robot] or [landing])
 * for trial (and run, which drops it), any other for run. */
fs_status fs_scenario_require(const fs_scenario *sc, const char *command, fs_error *err);

/* Releases what a loaded scenario holds (its terrain's samples). */
void fs_scenario_free(fs_scenario *sc);

/* dst becomes a copy of src owning its own terrain data (fs_terrain_copy), to edit and compile
 * without touching src. */
fs_status fs_scenario_copy(fs_scenario *dst, const fs_scenario *src, fs_error *err);

/* Compiles a loaded scenario again after its definitions were edited in code (the start pose in
 * sc->def, the terrain's seed in sc->terrain.def, as a landing trial does; a spring's stiffness or
 * a link's mass in sc->design, as bench stability does; a swept key, as a campaign does): each
 * definition checked against its schema's ranges, the relations between keys that loading checks
 * (named "set in code": an unset log interval follows the step, a run's steps bounded, a terrain's
 * ranges in order), then the foot's geometry, the terrain's drawn features and its samples cut to
 * the region the foot can reach from the new pose. Reads no file; gives the same bits as loading
 * the file with the same edits as --set. Edits that change which files a scenario uses (design,
 * terrain, heightmap) need fs_scenario_load. */
fs_status fs_scenario_compile(fs_scenario *sc, fs_error *err);

/* The schema entry of the number "section.key" of a scenario, design, robot or terrain file (also
 * of an integer key when integers), or of one element of a list key, "section.key[i]" with i from 1
 * (fs_list_element): then *element is its 0-based index, else -1. NULL when no schema has it (for
 * a list key named with a bad index, *element is -2). */
const fs_key *fs_scenario_key(const char *name, int integers, int *element);

/* The number a key "section.key" of the scenario, its design, robot or terrain sets, or one element
 * of a list key "section.key[i]" (fs_scenario_key), as a typed field of sc's definitions: for code
 * that varies a model (a search, a sweep) by editing its definitions and compiling
 * (fs_scenario_compile). NULL when no schema has that key as a number; *key (may be NULL) gets its
 * schema entry, for its range (an element's) and unit. */
double *fs_scenario_number(fs_scenario *sc, const char *name, const fs_key **key);

/* Sets the number or integer key "section.key" of sc's definitions to value, as a sweep does
 * before compiling: FS_BAD_INPUT when no schema has that key as a number or integer, or value is
 * not a whole number for an integer key. Ranges are checked by fs_scenario_compile. */
fs_status fs_scenario_set(fs_scenario *sc, const char *name, double value, fs_error *err);

/* Notes the files sc was read from in p (fs_provenance.h), each once: the scenario file, its
 * design, its terrain, the terrain's heightmap image (by its bytes) and its robot. */
fs_status fs_scenario_inputs(const fs_scenario *sc, fs_provenance *p, fs_error *err);

/* The record of a result of sc alone (a run, a trial): inputs relative to the scenario file's
 * folder, the overrides sc was loaded with, its inputs and its settings; no seeds (the caller sets
 * them). fs_provenance_free releases it, also after a failure. */
fs_status fs_scenario_provenance(const fs_scenario *sc, const char *const *overrides, int noverrides,
                                 fs_provenance *p, fs_error *err);

/* sc's step and solver settings as results record them: "step_s 0.0001, stepper step, iterations
 * 50, springs implicit, contact_layer_m 0.0005, window 3 s" (window: duration_s). */
void fs_scenario_settings(const fs_scenario *sc, char *buf, size_t size);

/* The geometry a simulation of sc builds: sc->geom, or for a biped robot its two feet and legs
 * (fs_robot_biped_geometry) made in *biped, which the result then points to. */
const fs_foot_geom *fs_scenario_geometry(const fs_scenario *sc, fs_foot_geom *biped);

/* The rectangle [xmin, xmax] x [ymin, ymax] the foot (a biped's two) covers at its start pose. */
void fs_scenario_footprint(const fs_scenario *sc, double box[4]);

/* The rectangle the run's foot can reach: its footprint at the start and, for the walking machine,
 * the path ahead of it (walk_steps times step_length_m along x). The terrain is sampled over it. */
void fs_scenario_reach(const fs_scenario *sc, double box[4]);

#endif
