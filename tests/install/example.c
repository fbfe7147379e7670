/* example.c: a program built against an installed footsim, as a user would build one
 * (tests/cli_install.sh: cc example.c $(pkg-config --cflags --libs footsim)). It computes the
 * analytic joint stiffness of the shipped biomimetic design and steps the shipped static-load
 * scenario for 0.05 s through the simulation's accessors (fs_sim is opaque: the program needs
 * neither its size nor ODE's header; cli_install.sh compiles it with an ode/ode.h that fails).
 * Usage: example PREFIX/share/footsim */
#include "footsim/analysis/fs_analysis.h"
#include "footsim/base/fs_version.h"
#include "footsim/sim/fs_sim.h"

#include <stdio.h>

static int fail(const fs_error *err)
{
    fprintf(stderr, "example: %s\n", err->message);
    return err->status;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: example PREFIX/share/footsim\n");
        return 2;
    }
    static fs_scenario sc;
    fs_sim *sim;
    fs_error err;
    char path[1024];
    printf("footsim %s\n", fs_version());

    snprintf(path, sizeof path, "%s/scenarios/feet/biomimetic.ini", argv[1]);
    if (fs_scenario_for_design(path, NULL, 0, &sc, &err) != FS_OK)
        return fail(&err);
    fs_chain_stiffness k[FS_CHAINS];
    fs_stiffness_analytic(&sc.geom, k);
    const double(*K)[2] = (const double(*)[2])k[0].exact;
    printf("chain 1 exact geometry [%9.4f %9.4f; %9.4f %9.4f]\n", K[0][0], K[0][1], K[1][0], K[1][1]);
    fs_scenario_free(&sc);

    snprintf(path, sizeof path, "%s/scenarios/static_load.ini", argv[1]);
    if (fs_scenario_load(path, NULL, 0, &sc, &err) != FS_OK)
        return fail(&err);
    fs_ode_init();
    if (fs_sim_new(&sc, NULL, &sim, &err) != FS_OK)
        return fail(&err);
    int steps = (int)(0.05 / sc.def.step_s + 0.5);
    for (int i = 0; i < steps; i++)
        if (fs_sim_step(sim, &err) != FS_OK)
            return fail(&err);
    double ankle[3];
    fs_sim_ankle(sim, ankle);
    printf("static_load: %d steps to t = %.3f s, ankle at z = %.6f m\n", steps, fs_sim_time(sim), ankle[2]);
    fs_sim_free(sim);
    fs_scenario_free(&sc);
    fs_ode_close();
    return 0;
}
