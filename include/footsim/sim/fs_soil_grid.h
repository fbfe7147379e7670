/* fs_soil_grid.h: the state of a soil during one simulation (fs_soil.h gives its laws and keys):
 * a regular grid of nodes over the region the feet can reach, each with its undisturbed surface
 * height, plastic sinkage, the pressure it yielded at and the slip accumulated on it, and the
 * forces it gives the bodies whose soil shapes reach below its surface.
 *
 * Storage follows the feet: the region is an index of 16 x 16-node tiles, and a tile is taken from
 * a pool the first time a shape comes below the soil's top over it. The pool is allocated at
 * fs_soil_grid_init for the tiles under the shapes' start, and doubles (realloc) when it runs out,
 * never past the region's tiles or max_nodes: the only allocation a step may make, a few times in
 * a run, said in docs/soil.md. Prints persist for the whole run (a node never forgets its plastic
 * sinkage).
 *
 * Each shape is met on a spacing chosen from its own width (fs_soil_shape.stride, fs_soil_stride:
 * [soil] nodes_across nodes across its narrowest side, at most coarse_grid_m): a tile it makes keeps
 * only every stride-th node each way, each standing for stride x stride nodes (its area, its print);
 * a tile under a finer shape is made finer, its new nodes taking the state of the coarse node they
 * were read from, so a tile has the finest spacing of the shapes that reached it. docs/soil.md, Grid
 * spacing, says which shape gets which and why.
 *
 * Each step (and each substep) fs_soil_grid_step casts a vertical line through every node under a
 * shape's plan (its bounding box's rows, each cut to where the row meets the plan of the shape's part
 * that reaches below the soil's top), finds the shape's lowest surface there (capsules and boxes in
 * closed form), gives a node to the lowest shape over it, and computes per node (SCM's way, explicit).
 * A box's nodes carry its plan's exact area (coverage): a node at the edge of the box's plan (the hull
 * of its corners) stands for the part of the plan between it and the edge, so that where the edges fall
 * on the grid moves neither the area nor the force (docs/soil.md, Grid spacing); a capsule's nodes
 * carry their cells (its depth falls to 0 at its plan's edge):
 * - bekker: the elastic trial K_e (s - s_p); past the yield pressure, Bekker's (k_c / b + k_phi) s^n
 *   with b = 2 A / P of the shape's loaded patch (at least b_min_m), the yield raised and the plastic
 *   sinkage moved to s - sigma / K_e; damping - R v_z added, never tension; Janosi shear from the slip
 *   j accumulated on the node, against the slip velocity (full above slip_speed_m_per_s, in
 *   proportion below: the regularisation that keeps a resting foot from chattering). The viscous
 *   slope this gives a shape, sum of tau A / max(|v_t|, slip_speed), is an explicit damper: it is
 *   capped at half its body's mass over the step (c h / m <= 0.5, inside explicit damping's
 *   stability bound c h / m < 2) by scaling the shape's shear down, which widens the viscous zone
 *   of a light link (a toe) instead of letting it chatter;
 * - rft: the same elastic-plastic frame with RFT's zeta alpha_z(beta, gamma) |z| as the yield law,
 *   alpha_x's drag in proportion to the vertical stress mobilised, and the inertial pressure
 *   lambda rho (v.n)^2 with its friction on elements moving into the medium.
 * Forces are summed per shape into a force and a torque about its body's origin. Depth is measured
 * from the undisturbed surface and never past the bedrock (the rigid contacts hold a foot there).
 * Plain C, no ODE: the sim's glue (sim_soil.c) reads the bodies and applies the forces. */
#ifndef FS_SOIL_GRID_H
#define FS_SOIL_GRID_H

#include "footsim/model/fs_terrain.h"

enum { FS_SOIL_TILE = 16, FS_SOIL_MAX_SHAPES = 64 };

typedef enum fs_soil_shape_kind { FS_SOIL_CAPSULE = 0, FS_SOIL_BOX = 1 } fs_soil_shape_kind;

/* A body's shape for the soil, in its body's frame (origin at the body's origin). */
typedef struct fs_soil_shape {
    int kind;               /* fs_soil_shape_kind */
    int body;               /* the caller's body index */
    int foot;               /* 0 or 1 */
    char name[32];
    double a[3], b[3];      /* capsule: its segment's ends; box: a is its centre */
    double radius_m;        /* capsule */
    double half[3];         /* box: half lengths along its axes */
    double R[9];            /* box: its axes in the body frame (columns), row-major */
    double plan_area_m2;    /* the area it presents from below at rest (stated, docs/soil.md) */
    int stride;             /* its nodes are every stride-th of the grid's, each carrying (stride dx)^2: a power of
                             * two dividing FS_SOIL_TILE (0 or 1: every node; fs_soil_stride) */
} fs_soil_shape;

/* A body's state: its origin, rotation (row-major, world = R body), velocity and spin (world), and
 * its mass, which bounds the shear's regularisation (fs_soil_grid_step). */
typedef struct fs_soil_body { double p[3], R[9], v[3], w[3], mass_kg; } fs_soil_body;

typedef struct fs_soil_node {
    double h0_m;            /* the undisturbed surface (bedrock + depth) */
    double sp_m;            /* plastic sinkage: the print's depth here */
    double yield_Pa;        /* the pressure it yielded at */
    double slip_m;          /* shear displacement accumulated on it */
    double zb_m;            /* this step: the lowest shape surface over it */
    double n[3];            /* ... that surface's outward normal (set for an RFT soil only, whose law reads it) */
    double sigma_Pa;        /* this step: its normal stress */
    long stamp;             /* the step that set zb (0: never) */
    int shape;              /* ... and whose shape it is */
} fs_soil_node;

/* A node a shape claimed in this step's first pass: the later passes (its patch's perimeter, its
 * forces) read the shape's claims in the order they were made, the order of its rows. */
typedef struct fs_soil_claim {
    fs_soil_node *node;
    int i, j, st;           /* the node's grid indices and its tile's stride */
    double w;               /* the share of its cell it carries: 1, or for a box's node at its plan's edge the
                             * part of the plan it stands for (fs_soil_grid_step: coverage) */
    long key;               /* its place in the claims' order, j (nx + FS_SOIL_TILE) + i: the perimeter finds a
                             * node's neighbours among its shape's claims by it */
} fs_soil_claim;

typedef struct fs_soil_grid {
    const fs_terrain *terrain;
    fs_soil_def d;
    double x0, y0, dx;      /* node (i, j) at (x0 + i dx, y0 + j dx) */
    int nx, ny;             /* nodes over the region */
    int i_lo, i_hi;         /* the columns the soil lies over ([soil] x_min_m <= x0 + i dx <= x_max_m; 0 and
                             * nx - 1 without a section): no node beyond them is ever claimed, and no tile
                             * wholly beyond them is made */
    int tx, ty;             /* tiles over it */
    int *tile;              /* tx * ty: the pool slot of each tile, or -1 */
    unsigned char *stride;  /* tx * ty: the spacing of a made tile's nodes, in grid nodes (1: every node; s: only
                             * nodes with i and j multiples of s exist, each standing for s x s nodes) */
    int *slot_tile;         /* the tile index of each pool slot */
    fs_soil_node *pool;     /* ntiles * FS_SOIL_TILE^2 nodes */
    int ntiles, cap_tiles, max_tiles;
    int grows;              /* how many times the pool grew during the run */
    fs_soil_claim *claim;   /* the step's claims (scratch): as many as the pool's nodes, doubled when a
                             * step needs more (shapes overlapping in plan), counted in claim_grows */
    long cap_claims;
    int claim_grows;
    double top_m;           /* the highest undisturbed surface: a shape above it meets nothing */
    int nshapes;
    fs_soil_shape shape[FS_SOIL_MAX_SHAPES];
    long stamp;
    /* the last step's results, per shape: force and torque about its body's origin (world), nodes */
    double force[FS_SOIL_MAX_SHAPES][3], torque[FS_SOIL_MAX_SHAPES][3];
    int nodes[FS_SOIL_MAX_SHAPES];
    double area_m2[FS_SOIL_MAX_SHAPES]; /* ... and their area (nodes times their cells, a box's edge nodes
                                         * times the share of the plan they stand for) */
    double b_m[FS_SOIL_MAX_SHAPES];
    double tan_phi;         /* tan of the friction angle, once */
    double work_J;          /* work the soil's forces have taken out of the bodies (sum of -F.v h) */
    struct fs_soil_undo *undo; /* under an error-controlled step, the log of what the steps since the
                                * mark changed (fs_soil_grid_keep); NULL otherwise */
} fs_soil_grid;

/* Sets the grid over t's soil region (t->soil_region) and allocates its index and a pool for the
 * tiles under boxes[0 .. nboxes - 1] ([xmin, xmax, ymin, ymax] each: the shapes at the start).
 * FS_NO_MEMORY, or FS_BAD_INPUT past max_nodes (fs_soil_region checks it first). */
fs_status fs_soil_grid_init(fs_soil_grid *g, const fs_terrain *t, const double (*boxes)[4], int nboxes, fs_error *err);
void fs_soil_grid_free(fs_soil_grid *g);

/* One step of h: forces on every shape from the bodies' states (indexed by shape.body). FS_NO_MEMORY
 * when the pool cannot grow (then no force is given). */
fs_status fs_soil_grid_step(fs_soil_grid *g, const fs_soil_body *bodies, double h, fs_error *err);

/* Undoing steps, for an error-controlled step that rejects one (run.tolerance_m; sim_adapt.c).
 * fs_soil_grid_keep (once, after init) makes every later fs_soil_grid_step log, before it changes
 * them, each node it is the first since the mark to change (a node's first claim in a step: its stamp
 * is not yet the step's) and each tile it makes finer (its nodes and stride whole); fs_soil_grid_mark
 * starts the log afresh at the state now; fs_soil_grid_undo replays it backwards and drops the tiles
 * made since the mark, which puts back every node (print, yield, slip, and the step's own zb, normal,
 * stress, stamp), the tiles, the stamp, the work and the per-shape forces, nodes and areas bit for
 * bit, and leaves the mark in place (undo again to come back to it again). Not put back: the
 * pool's and the claims' capacity and their growth counters (memory, not state). The log is sized
 * at keep and whenever the pool grows for four steps' changes of every node of the pool (a step
 * changes a node once, or twice when a tile it stands in is made finer in it), and doubles should a
 * caller take more steps between a mark and an undo (the error-controlled step takes at most two):
 * FS_NO_MEMORY then if it cannot. */
fs_status fs_soil_grid_keep(fs_soil_grid *g, fs_error *err);
void fs_soil_grid_mark(fs_soil_grid *g);
void fs_soil_grid_undo(fs_soil_grid *g);

/* The stride for a shape width_m wide on the narrowest side of its plan: the largest power of two
 * s <= FS_SOIL_TILE with s grid_m <= coarse_grid_m and at least nodes_across of its nodes across the
 * width, s grid_m nodes_across <= width_m (1 when coarse_grid_m is 0 or the shape is narrower). */
int fs_soil_stride(const fs_soil_def *d, double width_m);

/* The soil's surface at node (i, j) now (the print, or the shape pressing it this step), m; its
 * undisturbed surface and plastic sinkage; NULL node when (i, j) lies outside the region. In a tile
 * of stride s every node reads the stored node nearest it (each stands for s x s nodes). */
const fs_soil_node *fs_soil_grid_node(const fs_soil_grid *g, int i, int j);
double fs_soil_grid_surface(const fs_soil_grid *g, double x, double y);
/* The undisturbed surface at (x, y): the terrain plus the layer's depth (the terrain alone beyond the
 * soil's section, fs_soil_depth_over). */
double fs_soil_grid_undisturbed(const fs_soil_grid *g, double x, double y);

/* Over every stored node: the prints' volume (sum of plastic sinkage times dx^2), m^3, the deepest
 * plastic sinkage, m, and how many nodes carry a print (sp > 0). */
double fs_soil_grid_print(const fs_soil_grid *g, double *deepest_m, long *nodes);

/* The same with the prints' area and slip: every node with a print (sp > 0) counted with its cell
 * (a coarse node's stride x stride cells), its slip (the shear displacement j accumulated on it)
 * averaged over the print by area (0 without a print). */
typedef struct fs_soil_print {
    double volume_m3, deepest_m, area_m2, mean_slip_m;
    long nodes;
} fs_soil_print;
void fs_soil_grid_print_of(const fs_soil_grid *g, fs_soil_print *p);

/* The surface the soil keeps (its undisturbed height less its print, the elastic part given back as
 * a foot lifts) on the grid's nodes over the tiles the feet reached and one node around them (so
 * that its edge is undisturbed soil, where the region allows): nx x ny heights z_m[j nx + i]
 * at (x0 + i dx, y0 + j dx), and each node's print (plastic sinkage) in sink_m. Nothing reached:
 * nx = ny = 0 and no memory. FS_NO_MEMORY (s empty) when the heights cannot be had. s is zeroed or
 * an earlier copy: its memory is reused when the extent is the same (an observer copying at every
 * frame allocates only when the feet reach a new tile), else freed and allocated anew. */
typedef struct fs_soil_surface {
    int nx, ny;
    double x0, y0, dx;
    double *z_m, *sink_m;
} fs_soil_surface;
fs_status fs_soil_grid_surface_copy(const fs_soil_grid *g, fs_soil_surface *s, fs_error *err);
void fs_soil_surface_free(fs_soil_surface *s);

/* A shape's plan extent where body places it, [xmin, xmax, ymin, ymax] (its bounding box's), and its lowest
 * point, m. */
void fs_soil_shape_box(const fs_soil_shape *s, const fs_soil_body *body, double box[4], double *zmin);

/* A vertical line at (x, y) against a shape placed by body: its lowest point below z_top on the
 * shape (returned, or +INFINITY when it misses) and the outward normal there. */
double fs_soil_shape_lowest(const fs_soil_shape *s, const fs_soil_body *body, double x, double y, double n[3]);

#endif
