/* sim_access.c: what a caller reads of a simulation, fs_sim being opaque (fs_sim.h): functions
 * over the sim's own fields, none of which copies what the step keeps. */
#include "sim_internal.h"

#include <string.h>

const fs_scenario *fs_sim_scenario(const fs_sim *sim) { return sim->sc; }
const fs_foot_geom *fs_sim_geom(const fs_sim *sim) { return sim->geom; }
double fs_sim_time(const fs_sim *sim) { return sim->time_s; }
double fs_sim_step_size(const fs_sim *sim) { return sim->sc->def.step_s; }
double fs_sim_step_taken(const fs_sim *sim) { return sim->step_taken_s; }
int fs_sim_dead(const fs_sim *sim) { return sim->ode_failed; }
int fs_sim_adaptive(const fs_sim *sim) { return sim->saved != NULL; }
void fs_sim_down(const fs_sim *sim, double down[3]) { memcpy(down, sim->down, 3 * sizeof(double)); }
int fs_sim_body_count(const fs_sim *sim) { return fs_sim_nbodies(sim); }
int fs_sim_contact_count(const fs_sim *sim) { return sim->contacts_now; }

int fs_sim_contacts(const fs_sim *sim, double *pos, double *force, int max)
{
    int n = sim->contacts_now < max ? sim->contacts_now : max;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            if (pos)
                pos[3 * i + k] = sim->contact_pos[i][k];
            if (force)
                force[3 * i + k] = sim->feedback[i].f1[k]; /* on the foot (body 1), from the ground */
        }
    return n < 0 ? 0 : n;
}

void fs_sim_contact_totals(const fs_sim *sim, long *contacts, long *collision_tests)
{
    if (contacts)
        *contacts = sim->contacts_total;
    if (collision_tests)
        *collision_tests = sim->collision_tests;
}

void fs_sim_contact_needs(const fs_sim *sim, int *found, int *shapes_touching, int *most_found)
{
    if (found)
        *found = sim->contacts_found_now;
    if (shapes_touching)
        *shapes_touching = sim->shapes_touching_now;
    if (most_found)
        *most_found = sim->most_found_now;
}

fs_spring_state fs_sim_spring_state(const fs_sim *sim, int i) { return fs_spring_measure(&sim->spring[i]); }
const fs_check *fs_sim_checks(const fs_sim *sim) { return &sim->check; }
const fs_step_stats *fs_sim_step_stats(const fs_sim *sim) { return &sim->stats; }
long fs_sim_warnings(const fs_sim *sim) { return sim->warnings; }
