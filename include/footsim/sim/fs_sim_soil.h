/* fs_sim_soil.h: a simulation's soil (fs_soil_grid.h), when its terrain has one ([soil] model not
 * none): what the experiments read of it. Without a soil every function here says so (NULL, 0) and
 * nothing of a rigid run's arithmetic changes: the soil's hooks in the step, the measures and the
 * start pose are all behind `sim->soil != NULL`.
 *
 * The soil's forces are applied as explicit forces and torques on the bodies inside each step and
 * substep (sim_advance.c's contact stage), after the rigid contacts are made and before the ODE step;
 * the ground force a step reports (fs_sim_ground_force, fs_sim_foot_force) includes them, a foot
 * that the soil holds is supported (fs_sim_support), and its first soil contact is its touchdown
 * (fs_sim_first_touch). */
#ifndef FS_SIM_SOIL_H
#define FS_SIM_SOIL_H

#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_soil_grid.h"

/* The feet's shapes for a soil, made from a foot's geometry (sim_soil.c says which: the flat sole's
 * box, a capsule per link of the radius the design file's [soil_shapes] gives): at most max of them
 * into out, each in its body's frame with the body's origin at com[body] (NULL: at the design's
 * origin, the shapes then in design coordinates), with its plan area at rest; how many. What a sim on
 * a soil meets the soil with, and what `footsim model` prints. */
int fs_soil_foot_shapes(const fs_foot_geom *g, const fs_vec3 *com, fs_soil_shape *out, int max);

/* The soil's grid, or NULL without a soil. */
const fs_soil_grid *fs_sim_soil_grid(const fs_sim *sim);

/* The soil nodes carrying foot (0, 1; -1: every foot) in the last (sub)step; 0 without a soil. */
int fs_sim_soil_nodes(const fs_sim *sim, int foot);

/* The area the soil carries foot on (-1: every foot) in the last (sub)step, m^2: its nodes, each
 * with its cell (a coarse node's too: fs_soil_shape.stride; a box's edge nodes with the share of
 * its plan they stand for: fs_soil_grid.h, coverage); 0 without a soil. */
double fs_sim_soil_area(const fs_sim *sim, int foot);
/* How deep foot (-1: any) reaches below the soil's undisturbed surface now, m: the deepest of the
 * nodes its shapes carried in the last (sub)step (never past the bedrock); 0 without a soil or
 * when the soil does not carry it. It visits every stored node: for once a step of a gait, not
 * every step. */
double fs_sim_soil_sinkage(const fs_sim *sim, int foot);
/* The slip accumulated on those nodes (the shear displacement j each keeps, from every step that
 * loaded it), m, their mean by area; 0 without a soil or when the soil does not carry foot. It too
 * visits every stored node. */
double fs_sim_soil_slip(const fs_sim *sim, int foot);

/* Whether any of foot's (-1: every foot's) soil shapes lies over the soil's section now (its plan's extent
 * along x, as the last (sub)step placed it, meets [soil] x_min_m..x_max_m: always, without a section); 0
 * without a soil. */
int fs_sim_soil_over(const fs_sim *sim, int foot);

/* What holds the feet now: contact points plus soil nodes (the outcome rules' support). */
int fs_sim_support(const fs_sim *sim);

/* The soil's force on foot (-1: every foot) in the last (sub)step, N (0 without a soil). */
void fs_sim_soil_force(const fs_sim *sim, int foot, double force[3]);

/* The soil's surface under (x, y) now, m: its print, or the shape pressing it; without a soil the
 * terrain's surface. */
double fs_sim_ground_surface(const fs_sim *sim, double x, double y);

#endif
