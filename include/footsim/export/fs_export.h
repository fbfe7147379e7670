/* fs_export.h: a scenario's model (fs_model.h) written out: as MuJoCo MJCF (docs/export.md) and as
 * the JSON of `footsim model --json`. The export layer sits above the sim layer and reads the
 * model, never an ODE world.
 *
 * The model is the one a simulation is made of (fs_model_compile), so every number is the one ODE
 * simulates: each body with its mass and full inertia about its centre of mass (its frame is
 * ODE's body frame), the hinges as a kinematic tree rooted at the heel (or the robot when there
 * is one) with a free joint (a slide for a robot on the vertical carriage), a hinge that would
 * close a loop as two `connect` equalities on its axis, each spring-damper as a spatial tendon
 * between two sites at its anchors (stiffness, damping, springlength = rest length), the contact
 * spheres and the sole box as geoms of the same sizes, gravity and the timestep. Numbers are
 * written with %.17g, so they read back exactly.
 *
 * Without a scenario (with_scenario 0) the foot is written in its design pose (the coordinates
 * of `footsim model --json`) and nothing else. With one, the foot is in the scenario's start
 * pose (lifted drop_m above the terrain) and the ground follows (planes and boxes as geoms, a
 * heightfield as an `hfield` asset whose samples go to a binary file beside the XML), with the
 * robot as a body and the static load as a point mass welded at the ankle. Contact parameters
 * are converted as docs/export.md says (solref in the direct form, a constant solimp).
 *
 * Written with libxml2's xmlwriter; the file (and the heightfield file, first) through
 * fs_write_file: whole or not at all. MuJoCo 2.2.2 (Debian 12) loads the result. */
#ifndef FS_EXPORT_H
#define FS_EXPORT_H

#include "footsim/model/fs_scenario.h"

#include <stddef.h>

/* sc's model at the design pose (no ground; masses, inertias, poses, joints, springs, shapes) as
 * JSON, in SI units and world coordinates (`footsim model --json`); read from the model, as a
 * simulation is made of it. The caller frees it with cJSON_Delete; NULL with err set on failure. */
struct cJSON *fs_model_json(const fs_scenario *sc, fs_error *err);

/* The impedance the export gives every contact (solimp dmin = dmax), docs/export.md. */
#define FS_MJCF_IMPEDANCE 0.95

/* An MJCF document in memory: xml (NUL-terminated, xml_len bytes) and, for a heightfield ground,
 * its samples in MuJoCo's binary hfield format (hfield_len bytes; NULL otherwise). */
typedef struct fs_mjcf {
    char *xml;
    size_t xml_len;
    unsigned char *hfield;
    size_t hfield_len;
} fs_mjcf;

/* Compiles sc's model and writes it as MJCF; hfield_file is the name the XML gives the heightfield
 * file (relative to the XML's folder). FS_BAD_INPUT, FS_NO_MEMORY as fs_model_compile. */
fs_status fs_mjcf_build(const fs_scenario *sc, int with_scenario, const char *hfield_file, fs_mjcf *out,
                        fs_error *err);
void fs_mjcf_free(fs_mjcf *m);

/* The heightfield file's name for an XML path: path without ".xml", then ".hfield.bin". */
void fs_mjcf_hfield_path(const char *path, char *out, size_t size);

/* fs_mjcf_build, then the heightfield file (when there is one) and path, each whole or not at
 * all (FS_IO when one cannot be written; FS_BAD_INPUT for a target footsim must not write). */
fs_status fs_mjcf_write(const fs_scenario *sc, int with_scenario, const char *path, fs_error *err);

#endif
