/* Tests of io_config.c through the design and scenario loaders: every bad input is refused with
 * "file:line: what is wrong" and FS_BAD_INPUT, before anything is built. And io_gnuplot.c: a name
 * written with fs_gp_string is read back by gnuplot byte for byte, and runs nothing. */
#include "fs_test.h"

#include "footsim/model/fs_scenario.h"
#include "footsim/io/fs_gnuplot.h"
#include "footsim/io/fs_input.h"

#include <cJSON.h>

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

/* Loads n bytes (NUL bytes allowed) as a design; expects refusal at `line` with `words`. */
static void refused_bytes(const char *bytes, size_t n, int line, const char *words)
{
    char path[128];
    snprintf(path, sizeof path, "%s/design.ini", dir);
    FILE *f = fopen(path, "wb");
    fwrite(bytes, 1, n, f);
    fclose(f);
    static fs_design_def def;
    static fs_foot_geom geom;
    fs_error err = {0};
    CHECK(fs_design_load(path, NULL, 0, &def, &geom, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, line, words);
}

/* Loads text as a design; expects refusal at `line` (0: a --set or no line) with `words` in it. */
static void refused_design(const char *text, int line, const char *words) { refused_bytes(text, strlen(text), line, words); }

static void good_files_load(void)
{
    static fs_design_def def;
    static fs_foot_geom geom;
    fs_error err;
    REQUIRE(fs_design_load("scenarios/feet/biomimetic.ini", NULL, 0, &def, &geom, &err) == FS_OK);
    REQUIRE(fs_design_load("scenarios/feet/flat.ini", NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.kind == FS_FOOT_FLAT);
    static fs_scenario sc;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_scenario_load("scenarios/tilt10.ini", NULL, 0, &sc, &err) == FS_OK);
    CHECK_NEAR(sc.def.tilt_deg, 10, 0);
    /* a design giving one key takes the defaults for the rest: Table I */
    REQUIRE(fs_design_load(write_file("one.ini", "; one key\n[links]\nl1_m = 0.02\n"), NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.l1_m == 0.02 && def.l2_m == 0.02 && def.l3_m == 0.04 && def.l4_m == 0.015);
    CHECK(def.k_N_per_m[0] == 12000 && def.c_Ns_per_m[2] == 200 && def.design_load_kg == 26);
    /* CRLF line ends and a byte order mark are read as the same file */
    REQUIRE(fs_design_load(write_file("crlf.ini", "\xEF\xBB\xBF[links]\r\nl1_m = 0.03\r\n"), NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.l1_m == 0.03);
}

/* Issue 16, finding 2: files that were silently misread are refused where they go wrong. */
static void misread_files_are_refused(void)
{
    refused_design("[links]\rl1_m = 0.03\r", 1, "carriage return that does not end a line");
    refused_design("[links] l1_m = 0.03\n", 1, "text after ']'");
    refused_design("[links]\nl1_m = 0.03\n[ghost]\n", 3, "[ghost] has no keys");
    refused_design("[links]\n[chains]\nscale = 1, 1, 1, 1, 1\n", 1, "[links] has no keys");
    refused_design("", 1, "no keys");
    refused_design(" \n\t\n\n", 1, "no keys");
    refused_design("\xEF\xBB\xBF", 1, "no keys");
    refused_design("; only a comment\n", 1, "no keys");
    static const char tilt[] = "[links]\nl1_m = 0.03\0garbage\n";
    refused_bytes(tilt, sizeof tilt - 1, 2, "a NUL byte (column 12)");
    /* a NUL hiding an over-long line whose tail would have read as a key of its own */
    char hidden[600];
    size_t n = (size_t)snprintf(hidden, sizeof hidden, "[foot]\nkind = biomimetic");
    hidden[n++] = 0;
    memset(hidden + n, 'x', 300);
    n += 300;
    n += (size_t)snprintf(hidden + n, sizeof hidden - n, "kind = flat\n");
    refused_bytes(hidden, n, 2, "a NUL byte");
    char nuls[100] = {0};
    refused_bytes(nuls, sizeof nuls, 1, "a NUL byte (column 1)");
}

/* Issue 16, finding 8: reading is linear in the keys; a file over the caps is refused. */
static void caps_are_refused(void)
{
    size_t cap = 20 * (FS_CONFIG_MAX_KEYS + 51) + 64;
    char *text = malloc(cap);
    size_t n = (size_t)snprintf(text, cap, "[links]\n");
    for (int i = 0; i <= FS_CONFIG_MAX_KEYS + 50; i++) /* refused at the first key over */
        n += (size_t)snprintf(text + n, cap - n, "k%d = 1\n", i);
    refused_design(text, FS_CONFIG_MAX_KEYS + 2, "more than 10000 keys"); /* the first refusal stands */
    free(text);
    text = calloc(1, FS_CONFIG_MAX_BYTES + 2);
    memset(text, ';', FS_CONFIG_MAX_BYTES + 1);
    refused_design(text, 0, "bytes; an .ini file may have at most 1048576");
    free(text);
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
    snprintf(text, sizeof text, "[links]\nl1_m = 0.02\n%s", longline);
    refused_design(text, 3, "longer than");
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
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", ok, 2, &sc, &err) == FS_OK);
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

/* One element of a list key, counted from 1, in a file and by --set, set over the whole list; the
 * splay and the toes' size as one number each (chains.splay_factor, chains.scale_factor), compiled
 * into the geometry as the products; a bad index or a product out of the list's range refused. */
static void list_elements_and_factors(void)
{
    static fs_design_def def;
    static fs_foot_geom geom, plain;
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_design_load(write_file("el.ini", "[chains]\nsplay_deg = 8, 4, 0, -4, -8\nsplay_deg[2] = 0\nscale[5] = 2\n"),
                           NULL, 0, &def, &geom, &err) == FS_OK);
    CHECK(def.splay_deg[0] == 8 && def.splay_deg[1] == 0 && def.splay_deg[2] == 0 && def.scale[4] == 2);
    CHECK(def.scale[0] == 1.25 && def.scale[3] == 1); /* the rest as the list (the default) gives them */
    const char *set[] = {"chains.splay_deg[5]=-20"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 1, &sc, &err) == FS_OK);
    CHECK(sc.design.splay_deg[4] == -20 && sc.design.splay_deg[3] == -4);
    /* a list element is a number of the scenario, with the list's range */
    const fs_key *k;
    double *el = fs_scenario_number(&sc, "chains.splay_deg[5]", &k);
    CHECK(el == &sc.design.splay_deg[4] && k->max == 45);
    CHECK(!fs_scenario_number(&sc, "chains.splay_deg[6]", NULL) && !fs_scenario_number(&sc, "chains.splay_deg", NULL));
    /* the factor: the chains' planes turned as by the products (a chain's toe lies along its plane,
       so its direction from the MTP joint gives the angle) */
    const char *twice[] = {"chains.splay_factor=2"};
    REQUIRE(fs_design_load("scenarios/feet/biomimetic.ini", twice, 1, &def, &geom, &err) == FS_OK);
    CHECK(fs_design_splay_deg(&def, 0) == 16 && fs_design_splay_deg(&def, 4) == -16);
    double dx = geom.chain[0].toe.x - geom.chain[0].mtp.x, dy = geom.chain[0].toe.y - geom.chain[0].mtp.y;
    CHECK_NEAR(atan2(dy, dx) * 180 / M_PI, 16, 1e-9);
    /* scale_factor: every forefoot length times it, so the phalanx (l4) of chain 2 (scale 1) grows 1.5 times */
    const char *big[] = {"chains.scale_factor=1.5"};
    REQUIRE(fs_design_load("scenarios/feet/biomimetic.ini", NULL, 0, &def, &plain, &err) == FS_OK);
    REQUIRE(fs_design_load("scenarios/feet/biomimetic.ini", big, 1, &def, &geom, &err) == FS_OK);
    fs_vec3 l_big = fs_sub(geom.chain[1].toe, geom.chain[1].mtp), l_plain = fs_sub(plain.chain[1].toe, plain.chain[1].mtp);
    CHECK_NEAR(sqrt(fs_dot(l_big, l_big)) / sqrt(fs_dot(l_plain, l_plain)), 1.5, 1e-12);
    refused_design("[chains]\nsplay_deg[0] = 1\n", 2, "splay_deg[0]: no such element; give one of splay_deg[1] to splay_deg[5]");
    refused_design("[chains]\n\nsplay_deg[6] = 1\n", 3, "no such element");
    refused_design("[chains]\nsplay_deg[x] = 1\n", 2, "not an element's name");
    refused_design("[chains]\nsplay_deg[2] = 50\n", 2, "splay_deg[2] = '50' is out of range");
    refused_design("[links]\nl1_m[1] = 0.02\n", 2, "unknown key 'l1_m[1]'");
    refused_design("[chains]\nsplay_deg = 30, 4, 0, -4, -8\nsplay_factor = 2\n", 3, "must lie in [-45, 45] deg");
    refused_design("[chains]\nscale_factor = 4.5\n", 2, "makes chain 1's scale 5.625");
}

/* Provenance hashes what a file says, not how it is written: a comment, a blank line or other
 * spacing leaves a design's hash as it was, a changed value changes it; a heightmap's image is
 * hashed by its bytes; inputs are recorded relative to the scenario's folder. */
static void provenance_hashes_content(void)
{
    char *text = NULL;
    size_t n = 0;
    fs_error err = {0};
    REQUIRE(fs_read_regular("scenarios/feet/biomimetic.ini", 1 << 20, "a design", &text, &n, &err) == FS_OK);
    unsigned long long h0, h1, h2;
    REQUIRE(fs_ini_hash(write_file("design.ini", text), &h0, &err) == FS_OK);
    /* comments, blank lines and spacing around '=' */
    char *edited = malloc(n + 256);
    REQUIRE(edited);
    char *at = strstr(text, "k_d1_N_per_m = 12000");
    REQUIRE(at);
    snprintf(edited, n + 256, "; a comment added\n\n%.*sk_d1_N_per_m=12000   ; the same value\n%s\n; the end\n",
             (int)(at - text), text, strchr(at, '\n') + 1);
    REQUIRE(fs_ini_hash(write_file("design.ini", edited), &h1, &err) == FS_OK);
    CHECK(h1 == h0);
    snprintf(edited, n + 256, "%.*sk_d1_N_per_m = 12001\n%s", (int)(at - text), text, strchr(at, '\n') + 1);
    REQUIRE(fs_ini_hash(write_file("design.ini", edited), &h2, &err) == FS_OK);
    CHECK(h2 != h0);
    write_file("design.ini", text);
    free(edited);
    free(text);

    /* a scenario on a heightmap: every file, relative to the scenario, the image by its bytes */
    char png[128], cmd[512];
    snprintf(png, sizeof png, "%s/maps", dir);
    snprintf(cmd, sizeof cmd, "mkdir -p %s && cp terrains/heightmaps/dunes.png %s/dunes.png", png, png);
    REQUIRE(system(cmd) == 0);
    write_file("hm.ini", "[terrain]\nkind = heightmap\n[heightmap]\nfile = maps/dunes.png\n");
    const char *scenario = write_file("sc.ini", "[scenario]\ndesign = design.ini\nterrain = hm.ini\n");
    static fs_scenario sc;
    REQUIRE(fs_scenario_load(scenario, NULL, 0, &sc, &err) == FS_OK);
    const char *set[] = {"run.step_s=5e-5"};
    fs_provenance a, b;
    REQUIRE(fs_scenario_provenance(&sc, set, 1, &a, &err) == FS_OK);
    REQUIRE(fs_scenario_provenance(&sc, set, 1, &b, &err) == FS_OK);
    fs_scenario_free(&sc);
    REQUIRE(a.ninputs == 4);
    CHECK(!strcmp(a.inputs[0].path, "sc.ini") && !strcmp(a.inputs[1].path, "design.ini"));
    CHECK(!strcmp(a.inputs[2].path, "hm.ini") && !strcmp(a.inputs[3].path, "maps/dunes.png"));
    CHECK(a.inputs[1].hash == h0);
    CHECK(a.noverrides == 1 && !strcmp(a.overrides[0], "run.step_s=5e-5"));
    CHECK(fs_provenance_equal(&a, &b));
    /* one byte more in the image: another hash, another record */
    snprintf(cmd, sizeof cmd, "printf x >>%s/dunes.png", png);
    REQUIRE(system(cmd) == 0);
    fs_provenance c;
    REQUIRE(fs_provenance_init(&c, scenario, &err) == FS_OK);
    REQUIRE(fs_provenance_add_data(&c, "terrains/heightmaps/dunes.png", &err) == FS_OK);
    snprintf(cmd, sizeof cmd, "%s/dunes.png", png);
    REQUIRE(fs_provenance_add_data(&c, cmd, &err) == FS_OK);
    CHECK(c.ninputs == 2 && c.inputs[0].hash == a.inputs[3].hash && c.inputs[1].hash != a.inputs[3].hash);
    /* read back from its JSON, a record is the same record; with another seed it is not */
    cJSON *json = fs_provenance_json(&a);
    fs_provenance back;
    CHECK(fs_provenance_from_json(json, &back, &err) == FS_OK && fs_provenance_equal(&a, &back));
    fs_provenance_free(&back);
    cJSON_DeleteItemFromObject(json, "inputs");
    CHECK(fs_provenance_from_json(json, &back, &err) == FS_BAD_INPUT);
    fs_provenance_free(&back);
    cJSON_Delete(json);
    b.first_seed = 1, b.nseeds = 1;
    CHECK(!fs_provenance_equal(&a, &b));
    fs_provenance_free(&a);
    fs_provenance_free(&b);
    fs_provenance_free(&c);
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

/* Every byte from 1 to 255 and hostile names (quotes, gnuplot commands, backquotes, macros, line
 * ends, a trailing backslash), each assigned through fs_gp_string and printed back by gnuplot into
 * a file of its own: the file holds the name and a newline, and no command ran (no INJECTED). */
static void gnuplot_reads_names_back(void)
{
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("  gnuplot is not installed: skipped\n");
        return;
    }
    char every[256];
    for (int i = 1; i < 256; i++)
        every[i - 1] = (char)i;
    every[255] = 0;
    const char *names[] = {every, "", "'", "''", "bob's campaign", "x'; system('touch INJECTED'); y='",
                           "'; system(\"touch INJECTED\")", "a`touch INJECTED`b", "@x @campaign", "two\nlines\r\n",
                           "ends in \\", "\"", "'\n'", "\x7f\x01'"};
    enum { N = sizeof names / sizeof names[0] };
    char script[128], path[160], cmd[256];
    snprintf(script, sizeof script, "%s/names.gp", dir);
    FILE *f = fopen(script, "w");
    REQUIRE(f != NULL);
    for (int i = 0; i < N; i++) {
        snprintf(path, sizeof path, "%s/name%d.txt", dir, i);
        fputs("set print ", f);
        fs_gp_string(f, path);
        fprintf(f, "\ns%d = ", i);
        fs_gp_string(f, names[i]);
        fprintf(f, "\nprint s%d\nset print\n", i);
    }
    fclose(f);
    snprintf(cmd, sizeof cmd, "cd %s && gnuplot names.gp", dir);
    CHECK(system(cmd) == 0);
    for (int i = 0; i < N; i++) {
        snprintf(path, sizeof path, "%s/name%d.txt", dir, i);
        char back[512] = "";
        FILE *r = fopen(path, "rb");
        size_t n = r ? fread(back, 1, sizeof back - 1, r) : 0;
        if (r)
            fclose(r);
        size_t len = strlen(names[i]);
        int same = n == len + 1 && !memcmp(back, names[i], len) && back[len] == '\n';
        if (!same)
            fprintf(stderr, "  name %d read back as %zu bytes, not %zu\n", i, n, len + 1);
        CHECK(same);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/INJECTED", dir);
    CHECK(access(path, F_OK) != 0);
    remove(script);
}

FS_TEST_MAIN(TEST(setup), TEST(good_files_load), TEST(unknown_names_are_refused), TEST(malformed_values_are_refused), TEST(misread_files_are_refused), TEST(caps_are_refused),
             TEST(out_of_range_values_are_refused), TEST(missing_files_are_refused),
             TEST(overrides_are_checked_like_files), TEST(list_elements_and_factors), TEST(provenance_hashes_content), TEST(gnuplot_reads_names_back), TEST(teardown))
