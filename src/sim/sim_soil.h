/* sim_soil.h: the sim layer's glue to its soil (fs_sim_soil.h): built with the sim, stepped in
 * its contact stage. Private to src/sim/. */
#ifndef SIM_SOIL_H
#define SIM_SOIL_H

#include "footsim/sim/fs_sim_soil.h"

typedef struct fs_sim_soil {
    fs_soil_grid g;
    fs_soil_body body[FS_MAX_BODIES];
    double foot_force[FS_MAX_FEET + 1][3]; /* the last (sub)step's: every foot (0), each (1 + foot) */
    int foot_nodes[FS_MAX_FEET + 1];
    double foot_area_m2[FS_MAX_FEET + 1];
    /* under a tolerance: those three as the last save found them (fs_sim_soil_save) */
    double saved_force[FS_MAX_FEET + 1][3];
    int saved_nodes[FS_MAX_FEET + 1];
    double saved_area_m2[FS_MAX_FEET + 1];
} fs_sim_soil;

/* Makes sim->soil when its terrain has a soil (sim->soil stays NULL otherwise): each foot body's
 * soil shape (sim_soil.c says which) and the grid. Call after the bodies are built. */
fs_status fs_sim_soil_build(fs_sim *sim, fs_error *err);
void fs_sim_soil_destroy(fs_sim *sim);

/* Under a tolerance (sim_adapt.c): the soil's state saved (the grid's undo log marked, and the last
 * step's forces, nodes and areas kept), and put back to that save bit for bit (fs_soil_grid_undo).
 * Nothing without a soil. */
void fs_sim_soil_save(fs_sim *sim);
void fs_sim_soil_restore(fs_sim *sim);

/* One (sub)step of h: the soil's forces on the bodies added, each foot's first soil contact noted. */
fs_status fs_sim_soil_apply(fs_sim *sim, double h, fs_error *err);

#endif
