/* export_fixture.h: a foot whose hinges close a loop, for the MJCF export's tests. No shipped
 * design has one (every chain closes through the ground), so this one is made: mtp5 becomes a
 * second talus-metatarsal4 hinge ("loop") on midfoot4's axis, 4 mm along it, which leaves
 * phalanx5 held by its springs alone. */
#ifndef FS_EXPORT_FIXTURE_H
#define FS_EXPORT_FIXTURE_H

#include "footsim/model/fs_scenario.h"

#include <stdio.h>
#include <string.h>

/* sc: the biomimetic foot (fs_scenario_for_design); returns the loop's hinge, or NULL. */
static inline const fs_hinge_geom *fs_fixture_make_loop(fs_scenario *sc)
{
    fs_foot_geom *g = &sc->geom;
    if (g->nhinges != 11 || strcmp(g->hinge[7].name, "midfoot4") || strcmp(g->hinge[10].name, "mtp5"))
        return NULL;
    fs_hinge_geom *h = &g->hinge[10];
    *h = g->hinge[7];
    snprintf(h->name, sizeof h->name, "loop");
    h->anchor = fs_add(h->anchor, fs_scale(h->axis, 0.004));
    return h;
}

#endif
