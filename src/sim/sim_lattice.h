/* sim_lattice.h (private to the sim layer): footsim's own contacts of a box (a sole) with a
 * heightfield terrain's lattice, and of a sphere (a toe), in place of ODE's tests
 * (run.heightfield_contacts).
 *
 * The surface is fs_terrain_height's: each lattice cell split along its rising diagonal into two
 * triangles; outside the cropped lattice there is no ground, as there are no tiles there. Every
 * contact's normal points out of the ground into the shape (the way to push the shape) and its
 * depth is the distance along that normal by which the two overlap.
 *
 * A box (the sole, its local z its thickness) gets: each corner below the surface, along the
 * surface's normal there; each stretch of an edge that passes beneath a lattice edge, at its
 * deepest crossing, along the two edges' common normal (a sole's edge across a rock's steep flank,
 * between lattice vertices, which no corner or vertex finds); and the lattice vertices inside the
 * box, pushed out through its nearest face (a vertex that came in by a side face is pushed back
 * out sideways, not through the sole), the deepest of each patch of a face. So a box has at most a
 * few contacts a face and an edge, spread over them, however fine the lattice, where ODE's test
 * returns one for every triangle plane a corner is under.
 *
 * A sphere gets a contact at each point of the surface nearest its centre among those around it (a
 * local minimum of the distance over the surface) closer than its radius: one on a face, an edge or
 * a corner, one on each side of a hollow, where ODE's test returns one for every triangle it
 * reaches; a centre under the surface is pushed out along the normal above it.
 *
 * fs_lattice_vertex_contacts is what footsim adds to ODE's box test (run.heightfield_contacts =
 * ode), which misses the lattice's vertices poking up through a box's faces: every vertex inside
 * the box (until g is full), pushed out through the nearer of its top and bottom faces. */
#ifndef FS_SIM_LATTICE_H
#define FS_SIM_LATTICE_H

#include "sim_internal.h"

void fs_lattice_box_contacts(const fs_terrain *t, dGeomID box, gathered *g);
void fs_lattice_sphere_contacts(const fs_terrain *t, dGeomID sphere, gathered *g);
void fs_lattice_vertex_contacts(const fs_terrain *t, dGeomID box, gathered *g);

#endif
