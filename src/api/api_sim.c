/* api_sim.c: scenarios and simulations behind opaque handles (footsim/api/fs_api.h). */
#include "footsim/api/fs_api.h"
#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A simulation and the copy of its scenario it reads. The sim is built on the copy, so the box is
 * found back from the handle through the scenario the sim names (its first field). */
typedef struct sim_box {
    fs_scenario sc; /* first: fs_sim_scenario(sim) is the box's address */
    fs_sim *sim;
} sim_box;

static sim_box *box_of(const fs_sim *sim) { return (sim_box *)fs_sim_scenario(sim); }

typedef fs_status (*scenario_loader)(const char *path, const char *const *overrides, int noverrides, fs_scenario *sc,
                                     fs_error *err);

static fs_scenario *open_with(scenario_loader load, const char *path, const char *const *overrides, int noverrides,
                              fs_error *err)
{
    if (!path || noverrides < 0 || (noverrides > 0 && !overrides)) {
        fs_fail(err, FS_BAD_INPUT, "fs_scenario_open: path is NULL or the overrides do not match their count");
        return NULL;
    }
    fs_scenario *sc = calloc(1, sizeof *sc);
    if (!sc) {
        fs_fail(err, FS_NO_MEMORY, "%s: no memory for the scenario", path);
        return NULL;
    }
    if (load(path, overrides, noverrides, sc, err) != FS_OK) {
        fs_scenario_free(sc);
        free(sc);
        return NULL;
    }
    return sc;
}

fs_scenario *fs_scenario_open(const char *path, const char *const *overrides, int noverrides, fs_error *err)
{
    return open_with(fs_scenario_load, path, overrides, noverrides, err);
}

fs_scenario *fs_scenario_open_design(const char *path, const char *const *overrides, int noverrides, fs_error *err)
{
    return open_with(fs_scenario_for_design, path, overrides, noverrides, err);
}

void fs_scenario_close(fs_scenario *sc)
{
    if (!sc)
        return;
    fs_scenario_free(sc);
    free(sc);
}

const char *fs_scenario_title(const fs_scenario *sc) { return sc->name; }

int fs_scenario_trial(const fs_scenario *sc) { return sc->is_trial; }

fs_status fs_scenario_get(const fs_scenario *sc, const char *key, double *value, fs_error *err)
{
    /* fs_scenario_number hands out a field to edit; here it is only read */
    const double *v = key ? fs_scenario_number((fs_scenario *)sc, key, NULL) : NULL;
    if (!v)
        return fs_fail(err, FS_BAD_INPUT, "%s: no key '%s' with a number in the scenario, its design, terrain or robot "
                       "(docs/keys.md lists them as section.key)", sc->path, key ? key : "(null)");
    *value = *v;
    return FS_OK;
}

fs_sim *fs_sim_open(const fs_scenario *sc, fs_error *err)
{
    sim_box *box = calloc(1, sizeof *box);
    if (!box) {
        fs_fail(err, FS_NO_MEMORY, "%s: no memory for the simulation", sc->path);
        return NULL;
    }
    if (fs_scenario_copy(&box->sc, sc, err) != FS_OK) {
        free(box);
        return NULL;
    }
    if (fs_sim_new(&box->sc, NULL, &box->sim, err) != FS_OK) {
        fs_scenario_free(&box->sc);
        free(box);
        return NULL;
    }
    return box->sim;
}

void fs_sim_close(fs_sim *sim)
{
    if (!sim)
        return;
    sim_box *box = box_of(sim);
    fs_sim_free(box->sim);
    fs_scenario_free(&box->sc);
    free(box);
}

fs_status fs_sim_advance(fs_sim *sim, long nsteps, fs_error *err)
{
    for (long i = 0; i < nsteps; i++) {
        fs_status s = fs_sim_step(sim, err);
        if (s != FS_OK)
            return s;
    }
    return FS_OK;
}


const char *fs_sim_body_name(const fs_sim *sim, int i)
{
    if (i < 0 || i >= fs_sim_body_count(sim))
        return NULL;
    return i < fs_sim_geom(sim)->nbodies ? fs_sim_geom(sim)->body[i].name : "robot";
}

int fs_sim_body_index(const fs_sim *sim, const char *name)
{
    for (int i = 0; name && i < fs_sim_body_count(sim); i++)
        if (!strcmp(fs_sim_body_name(sim, i), name))
            return i;
    return -1;
}

void fs_sim_body_masses(const fs_sim *sim, double *mass_kg)
{
    for (int i = 0; i < fs_sim_body_count(sim); i++)
        mass_kg[i] = i < fs_sim_geom(sim)->nbodies ? fs_sim_geom(sim)->body[i].mass_kg : fs_sim_scenario(sim)->def.robot.mass_kg;
}

void fs_sim_poses(const fs_sim *sim, double *pos, double *R)
{
    for (int i = 0; i < fs_sim_body_count(sim); i++)
        fs_sim_body_pose(sim, i, pos ? pos + 3 * i : NULL, R ? R + 9 * i : NULL);
}

void fs_sim_velocities(const fs_sim *sim, double *v, double *w)
{
    for (int i = 0; i < fs_sim_body_count(sim); i++)
        fs_sim_body_velocity(sim, i, v ? v + 3 * i : NULL, w ? w + 3 * i : NULL);
}

fs_status fs_sim_apply_torque(fs_sim *sim, int i, const double torque_N_m[3], fs_error *err)
{
    if (i < 0 || i >= fs_sim_body_count(sim))
        return fs_fail(err, FS_BAD_INPUT, "body: %d is not a body of %s; give 0 to %d", i, fs_sim_scenario(sim)->path,
                       fs_sim_body_count(sim) - 1);
    if (!isfinite(torque_N_m[0]) || !isfinite(torque_N_m[1]) || !isfinite(torque_N_m[2]))
        return fs_fail(err, FS_BAD_INPUT, "torque_N_m: (%g, %g, %g) is not finite; give three finite numbers, N m",
                       torque_N_m[0], torque_N_m[1], torque_N_m[2]);
    fs_sim_body_add_torque(sim, i, torque_N_m);
    return FS_OK;
}

void fs_sim_ankle_position(const fs_sim *sim, double p[3]) { fs_sim_ankle(sim, p); }


int fs_sim_spring_count(const fs_sim *sim) { return fs_sim_geom(sim)->nsprings; }

const char *fs_sim_spring_name(const fs_sim *sim, int i)
{
    return i >= 0 && i < fs_sim_geom(sim)->nsprings ? fs_sim_geom(sim)->spring[i].name : NULL;
}

void fs_sim_spring_forces(const fs_sim *sim, double *force_N, double *length_m)
{
    for (int i = 0; i < fs_sim_geom(sim)->nsprings; i++) {
        fs_spring_state st = fs_sim_spring_state(sim, i);
        if (force_N)
            force_N[i] = st.force_N;
        if (length_m)
            length_m[i] = st.length_m;
    }
}

double fs_sim_energies(const fs_sim *sim, double *kinetic_J, double *potential_J, double *elastic_J)
{
    return fs_sim_energy(sim, kinetic_J, potential_J, elastic_J);
}

void fs_sim_check_worst(const fs_sim *sim, double *max_speed_m_per_s, double *max_loop_error_m,
                        double *max_energy_excess_J)
{
    const fs_check *c = fs_sim_checks(sim);
    if (max_speed_m_per_s)
        *max_speed_m_per_s = c->max_speed_m_per_s;
    if (max_loop_error_m)
        *max_loop_error_m = c->max_loop_error_m;
    if (max_energy_excess_J)
        *max_energy_excess_J = c->max_energy_excess_J;
}
