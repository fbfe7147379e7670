/* fs_scene.h: a snapshot of a running simulation as plain data, for anything that draws it.
 *
 * The core fills it (fs_sim_scene in fs_sim.h) and never draws; the renderer in render/ reads
 * it and never touches ODE. Everything is in world coordinates (x forward, y left, z up), SI
 * units. Pointers stay valid until the next fs_sim_scene call or the end of the simulation. */
#ifndef FS_SCENE_H
#define FS_SCENE_H

/* room for a biped's two feet and legs (sim_scene.c checks it against the geometry's limits) */
enum { FS_SCENE_MAX_SHAPES = 32, FS_SCENE_MAX_SEGMENTS = 96, FS_SCENE_MAX_CONTACTS = 256, FS_SCENE_MAX_BODIES = 32 };

typedef enum fs_shape_type { FS_SHAPE_SPHERE = 0, FS_SHAPE_BOX = 1 } fs_shape_type;

typedef struct fs_scene_shape {
    int type;           /* fs_shape_type */
    double size[3];     /* sphere: radius in size[0]; box: edge lengths */
    double pos[3];
    double quat[4];     /* w, x, y, z */
    int body;           /* index of the body it belongs to (-1: none of the foot's, the robot) */
} fs_scene_shape;

/* A line between two points: a link (joint to joint on one body, body1 = body2) or a spring
 * (force_N: tension positive) from body1 to body2. A body -1 is the world (a point that never
 * moves). */
typedef struct fs_scene_segment {
    double p1[3], p2[3];
    double force_N;
    int body1, body2;   /* the bodies p1 and p2 are fixed to */
} fs_scene_segment;

/* A body's pose: its centre of mass and orientation (w, x, y, z). */
typedef struct fs_scene_pose {
    double pos[3];
    double quat[4];
} fs_scene_pose;

typedef struct fs_scene_contact {
    double pos[3];
    double force_N[3];  /* on the foot, from the ground */
} fs_scene_contact;

/* The ground as heights on a regular grid: z = heights[j * nx + i] at (x0 + i dx, y0 + j dy).
 * A flat or sloped plane comes as a coarse grid over the region the foot can reach. */
typedef struct fs_scene_ground {
    int nx, ny;
    double x0, y0, dx, dy;
    const double *heights;
    int is_plane;
    const double *sinkage; /* with a soil: each sample's sinkage below the undisturbed surface, m (the
                              frames colour the ground by it); NULL on rigid ground */
} fs_scene_ground;

typedef struct fs_scene {
    double time_s;
    const char *scenario, *foot, *terrain; /* names, for the overlay */
    char design[64], robot_file[64]; /* the design's file name without .ini ("flat" for the flat sole), the
                                        robot's ("" for none) */
    fs_scene_ground ground;
    int nshapes, nlinks, nsprings, ncontacts;
    fs_scene_shape shape[FS_SCENE_MAX_SHAPES];
    fs_scene_segment link[FS_SCENE_MAX_SEGMENTS];
    fs_scene_segment spring[FS_SCENE_MAX_SEGMENTS];
    fs_scene_contact contact[FS_SCENE_MAX_CONTACTS];
    double ankle[3];    /* the load's point */
    double load_N[3];   /* the load acting there now */
    int nbodies;        /* the foot's bodies (0: poses unknown) */
    fs_scene_pose body[FS_SCENE_MAX_BODIES];
    int ankle_body;     /* the body the load acts on */
    int has_robot;      /* the robot: a box (body -1) of its mass and inertia, drawn from the ankle up */
    fs_scene_shape robot;
} fs_scene;

#endif
