/* model_robot.c: the robot file's schema and loading it (fs_robot.h). */
#include "footsim/model/fs_robot.h"

#include <stddef.h>
#include <stdio.h>

#define F(member) offsetof(fs_robot_def, member)
#define NUM(name, member, lo, hi, flags, unit, dflt, help) \
    {"robot", name, FS_KEY_NUMBER, F(member), lo, hi, flags, 0, NULL, unit, dflt, help}
#define POS FS_KEY_OPEN_MIN

const fs_key fs_robot_keys[] = {
    NUM("mass_kg", mass_kg, 0, 1e4, 0, "kg", "26", "the passive body on the ankle; half of the paper's 52 kg person is 26"),
    NUM("com_height_m", com_height_m, 0, 10, POS, "m", "0.3", "its centre of mass above the ankle"),
    NUM("com_forward_m", com_forward_m, -1, 1, 0, "m", "0.03", "its centre of mass ahead of the ankle"),
    {"robot", "inertia_kgm2", FS_KEY_LIST, F(inertia_kgm2), 0, 1e4, FS_KEY_OPEN_MIN, 3, NULL, "kg m^2", "1.4, 1.4, 0.1",
     "its principal moments of inertia about x, y, z at the centre of mass"},
    {"robot", "joint", FS_KEY_CHOICE, F(joint), 0, 0, 0, 0, "rigid|achilles", "", "rigid",
     "rigid: fixed to the ankle body; achilles: an ankle hinge with a heel-to-leg spring-damper"},
    NUM("achilles_k_N_per_m", achilles_k_N_per_m, 0, 1e9, POS, "N/m", "1e6",
        "Achilles tendon stiffness (2 cm behind the ankle: k (0.02 m)^2 must beat m g com_height)"),
    NUM("achilles_c_Ns_per_m", achilles_c_Ns_per_m, 0, 1e7, 0, "N s/m", "2000", "Achilles tendon damping"),
    NUM("achilles_leg_anchor_m", achilles_leg_anchor_m, 0, 10, POS, "m", "0.1", "where the tendon meets the leg, above the ankle"),
    NUM("inertia_height_m", inertia_height_m, 0, 10, 0, "m", "0",
        "0: inertia_kgm2 as given; else the moments are the body's at this COM height and those about x and y "
        "scale with (com_height_m / this)^2 (a sweep of the height stretches the same body)"),
    {"robot", "mount", FS_KEY_CHOICE, F(mount), 0, 0, 0, 0, "free|vertical", "", "free",
     "free: all six degrees of freedom; vertical: on a vertical slide, only up and down (the walking machine's carriage)"},
};
const int fs_robot_nkeys = (int)(sizeof fs_robot_keys / sizeof fs_robot_keys[0]);

fs_status fs_robot_load(const char *path, const char *const *overrides, int noverrides, fs_robot_def *def,
                        fs_error *err)
{
    fs_config cfg = {.path = "(no robot)"};
    fs_status s = *path ? fs_config_load(&cfg, path, err) : FS_OK;
    for (int i = 0; s == FS_OK && i < noverrides; i++)
        s = fs_config_override(&cfg, overrides[i], err);
    if (s == FS_OK)
        s = fs_config_bind(&cfg, fs_robot_keys, fs_robot_nkeys, def, err);
    if (s == FS_OK && !*path && !fs_config_has(&cfg, "robot", "mass_kg"))
        def->mass_kg = 0; /* no file: no robot, unless --set gives it a mass */
    fs_config_free(&cfg);
    return s;
}

void fs_robot_inertia(const fs_robot_def *r, double I[3])
{
    double f = r->inertia_height_m > 0 ? r->com_height_m / r->inertia_height_m : 1;
    I[0] = r->inertia_kgm2[0] * f * f;
    I[1] = r->inertia_kgm2[1] * f * f;
    I[2] = r->inertia_kgm2[2];
}
