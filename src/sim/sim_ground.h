/* sim_ground.h (private to the sim layer): a terrain built as ODE collision geometry.
 *
 * fs_ground_build puts the model's ground into space (fs_model.h decides its shapes): a plane (flat,
 * slope), a plane and boxes (stepped: sharp edges), or heightfields over the terrain's cropped lattice, turned from ODE's
 * y-up to footsim's z-up, with a base under their lowest sample so nothing passes beneath.
 *
 * A heightfield comes as square tiles of tile_cells cells that share their edge samples: ODE
 * sorts every triangle plane under a box's bounding box against every other one (quadratic), so a
 * flat sole over one large heightfield costs milliseconds a step; over tiles, a fraction of that.
 * Each tile holds a copy of its samples as doubles in ODE's row order (dGeomHeightfieldDataBuildDouble,
 * not a callback a sample: the same heights, bit for bit). fs_ground_destroy (after the space)
 * frees the tiles' data and samples. */
#ifndef FS_GROUND_H
#define FS_GROUND_H

#include "footsim/model/fs_terrain.h"
#include "footsim/sim/fs_model.h"

#include <ode/ode.h>

typedef struct fs_ground fs_ground;

/* The model's ground (fs_model.h: its planes and blocks, or the lattice of its terrain t as tiles). NULL
 * when the terrain needs no heightfield data (planes, steps) or memory ran out (*ok = 0). */
fs_ground *fs_ground_build(dSpaceID space, const fs_model *m, const fs_terrain *t, int tile_cells, int *ok);
/* The terrain t alone as the ground fs_ground_build makes of it (for tests). */
fs_ground *fs_ground_of_terrain(dSpaceID space, const fs_terrain *t, int tile_cells, int *ok);
/* A heightfield terrain's lattice alone as tiles (what fs_ground_build makes of one). */
fs_ground *fs_ground_heightfield(dSpaceID space, const fs_terrain *t, int tile_cells, int *ok);
void fs_ground_destroy(fs_ground *g);

#endif
