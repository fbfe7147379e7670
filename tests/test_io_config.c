/* Tests of io_config.c through the design and scenario loaders: every bad input is refused with
 * "file:line: what is wrong" and FS_BAD_INPUT, before anything is built. */
#include "fs_test.h"

#include "footsim/model/fs_scenario.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];

static const char *write_file(const char *name, const char *text)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

/* Loads text as a design; expects refusal at `line` (0: a --set or no line) with `words` in it. */
static void refused_design(const char *text, int line, const char *words)
{
    const char *path = write_file("design.ini", text);
    static fs_design_def def;
    static fs_foot_geom geom;
    fs_error err = {0};
    CHECK(fs_design_load(path, NULL, 0, &def, &geom, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, line, words);
}

static void good_files_load(void)
{
    static fs_design_def def;
    static fs_foot_geom geom;
    fs_error err;
    CHECK(fs_design_load("scenarios/feet/biomimetic.ini", NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(fs_design_load("scenarios/feet/flat.ini", NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.kind == FS_FOOT_FLAT);
    static fs_scenario sc;
    CHECK(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    CHECK(fs_scenario_load("scenarios/tilt10.ini", NULL, 0, &sc, &err) == FS_OK);
    CHECK_NEAR(sc.def.tilt_deg, 10, 0);
    /* an empty design is the defaults: Table I */
    CHECK(fs_design_load(write_file("empty.ini", "; nothing\n"), NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.l1_m == 0.02 && def.l2_m == 0.02 && def.l3_m == 0.04 && def.l4_m == 0.015);
    CHECK(def.k_N_per_m[0] == 12000 && def.c_Ns_per_m[2] == 200 && def.design_load_kg == 26);
}

static void unknown_names_are_refused(void)
{
    refused_design("[links]\nl1_m = 0.02\n[linkz]\nl2_m = 0.02\n", 4, "unknown section [linkz]");
    refused_design("[links]\nl5_m = 0.02\n", 2, "unknown key 'l5_m' in [links]; keys there are: l1_m");
    refused_design("[foot]\nkind = webbed\n", 2, "allowed: biomimetic|flat");
}

static void malformed_values_are_refused(void)
{
    refused_design("[links]\nl1_m = 0.02x\n", 2, "not a finite number");
    refused_design("[links]\nl1_m =\n", 2, "not a finite number");
    refused_design("[links]\nl1_m = nan\n", 2, "not a finite number");
    refused_design("[links]\nl1_m = inf\n", 2, "not a finite number");
    refused_design("[links]\nl1_m = 1e400\n", 2, "not a finite number");
    refused_design("[chains]\nscale = 1, 1, 1\n", 2, "too few values");
    refused_design("[chains]\nscale = 1, 1, 1, 1, 1, 1\n", 2, "too many values");
    refused_design("[links]\nthis line has no equals sign\n", 2, "not an INI line");
    refused_design("[links]\nl1_m = 0.02\nl1_m = 0.03\n", 3, "given twice (first on line 2)");
    char longline[400];
    memset(longline, 'x', sizeof longline);
    memcpy(longline, "; ", 2);
    longline[sizeof longline - 2] = '\n';
    longline[sizeof longline - 1] = 0;
    char text[512];
    snprintf(text, sizeof text, "[links]\n%s", longline);
    refused_design(text, 2, "longer than");
}

static void out_of_range_values_are_refused(void)
{
    refused_design("[mass]\nheel_kg = -0.05\n", 2, "out of range; allowed: a finite number in (0, 100] kg");
    refused_design("[springs]\nk_d1_N_per_m = 0\n", 2, "out of range");
    refused_design("[links]\nl3_m = -0.04\n", 2, "out of range");
    refused_design("[chains]\nscale = 1, 1, -1, 1, 1\n", 2, "out of range");
    /* a pose whose toe cannot reach the ground */
    refused_design("[links]\nl3_m = 0.005\n", 0, "cannot rest on the ground");
}

static void missing_files_are_refused(void)
{
    static fs_design_def def;
    static fs_foot_geom geom;
    fs_error err;
    CHECK(fs_design_load("no/such/design.ini", NULL, 0, &def, &geom, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "no/such/design.ini: ") == err.message);
    CHECK(fs_design_load(dir, NULL, 0, &def, &geom, &err) == FS_BAD_INPUT);
    static fs_scenario sc;
    const char *path = write_file("scenario.ini", "[scenario]\ndesign = feet/missing.ini\n");
    CHECK(fs_scenario_load(path, NULL, 0, &sc, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, ":2: design = 'feet/missing.ini': no such file") != NULL);
}

static void overrides_are_checked_like_files(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *ok[] = {"springs.k_d1_N_per_m=9000", "run.step_s=5e-5"};
    CHECK(fs_scenario_load("scenarios/static_load.ini", ok, 2, &sc, &err) == FS_OK);
    CHECK(sc.design.k_N_per_m[0] == 9000 && sc.def.step_s == 5e-5);
    const char *bad[][1] = {{"springs.k_d1_N_per_m=-1"}, {"springs.k_d9_N_per_m=1"}, {"nosection=1"},
                            {"run.stepper=rk4"}, {"warp.speed=9"}};
    const char *words[] = {"--set springs.k_d1_N_per_m: ", "unknown key 'k_d9_N_per_m'", "section.key=value",
                           "allowed: step|quickstep", "unknown section [warp]"};
    for (int i = 0; i < 5; i++) {
        err.message[0] = 0;
        CHECK(fs_scenario_load("scenarios/static_load.ini", bad[i], 1, &sc, &err) == FS_BAD_INPUT);
        if (!strstr(err.message, words[i]))
            fprintf(stderr, "  expected '%s' in: %s\n", words[i], err.message), fs_test_failures++;
    }
}

static void setup(void)
{
    snprintf(dir, sizeof dir, "/tmp/footsim-test-XXXXXX");
    CHECK(mkdtemp(dir) != NULL);
}

static void teardown(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
}

FS_TEST_MAIN(TEST(setup), TEST(good_files_load), TEST(unknown_names_are_refused), TEST(malformed_values_are_refused),
             TEST(out_of_range_values_are_refused), TEST(missing_files_are_refused),
             TEST(overrides_are_checked_like_files), TEST(teardown))
