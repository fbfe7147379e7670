/* cli_plot.c: charts drawn by gnuplot from a script footsim writes beside its data, and the plot
 * command: a run's time series (trajectory.csv) or a campaign's chart again (summary.json), with the
 * folder read (and --out's) locked as a run or campaign locks it. FOOTSIM_TEST_PLOT_DELAY=S makes
 * plot hold its locks S seconds before it reads (tests). */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_config.h"
#include "footsim/io/fs_gnuplot.h"
#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"
#include "footsim/io/fs_png.h"

#include <cjson/cJSON.h>
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

int cli_have_program(const char *name)
{
    const char *path = getenv("PATH");
    char full[FS_OUT_PATH];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        size_t n = strcspn(p, ":");
        /* an entry too long is skipped, never cut short to another folder */
        if (fs_path_format(full, sizeof full, "", NULL, "%.*s/%s", n ? (int)n : 1, n ? p : ".", name) == FS_OK &&
            access(full, X_OK) == 0)
            return 1;
        p += n + (p[n] == ':');
    }
    return 0;
}

/* gnuplot while it draws: the signals that stop footsim (SIGINT, SIGTERM, SIGHUP) are passed to it
 * first, so that it is never left drawing without the command that started it. Static on purpose:
 * a handler takes no argument, and one child draws at a time. */
static volatile sig_atomic_t gnuplot_pid, gnuplot_stopped;
static const int stop_signals[3] = {SIGINT, SIGTERM, SIGHUP};
static struct sigaction before_gnuplot[3];

/* Kills gnuplot (it cannot be asked to stop: it would finish its plot), then does what the signal
 * did before: the caller's handler (a campaign keeping its journal, the results' cleanup, which
 * ends the process), or the default. */
static void stop_gnuplot(int sig)
{
    if (gnuplot_pid > 0)
        kill((pid_t)gnuplot_pid, SIGKILL);
    gnuplot_stopped = sig;
    for (int i = 0; i < 3; i++) {
        if (stop_signals[i] != sig)
            continue;
        const struct sigaction *old = &before_gnuplot[i];
        if (!(old->sa_flags & SA_SIGINFO) && old->sa_handler != SIG_DFL && old->sa_handler != SIG_IGN) {
            old->sa_handler(sig);
        } else if (!(old->sa_flags & SA_SIGINFO) && old->sa_handler == SIG_DFL) {
            signal(sig, SIG_DFL);
            raise(sig);
        }
    }
}

/* Runs gnuplot -e VAR SCRIPT in dir; returns its wait status, or -1 when it could not start. A
 * signal that stops footsim meanwhile stops it (stop_gnuplot); a signal ignored stays ignored. */
static int run_gnuplot(const char *dir, const char *var, const char *script)
{
    struct sigaction forward;
    memset(&forward, 0, sizeof forward);
    forward.sa_handler = stop_gnuplot;
    sigemptyset(&forward.sa_mask);
    for (int i = 0; i < 3; i++)
        sigaddset(&forward.sa_mask, stop_signals[i]);
    sigset_t block, was;
    sigemptyset(&block);
    for (int i = 0; i < 3; i++)
        sigaddset(&block, stop_signals[i]);
    fflush(stdout);
    fflush(stderr);
    /* blocked until gnuplot_pid is set: a signal in between would find no child to stop */
    sigprocmask(SIG_BLOCK, &block, &was);
    gnuplot_stopped = 0;
    int caught[3] = {0};
    for (int i = 0; i < 3; i++)
        if (sigaction(stop_signals[i], NULL, &before_gnuplot[i]) == 0 && before_gnuplot[i].sa_handler != SIG_IGN)
            caught[i] = sigaction(stop_signals[i], &forward, NULL) == 0;
    pid_t parent = getpid(), pid = fork();
    if (pid == 0) {
        for (int i = 0; i < 3; i++) /* the child's own signals as they were */
            if (caught[i])
                sigaction(stop_signals[i], &before_gnuplot[i], NULL);
        sigprocmask(SIG_SETMASK, &was, NULL);
#ifdef __linux__
        /* a footsim killed outright (SIGKILL) cannot pass it on: the kernel does */
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent)
            _exit(127);
#else
        (void)parent;
#endif
        if (chdir(dir) == 0)
            execlp("gnuplot", "gnuplot", "-e", var, script, (char *)NULL);
        _exit(127);
    }
    gnuplot_pid = pid > 0 ? pid : 0;
    sigprocmask(SIG_SETMASK, &was, NULL);
    int status = -1;
    /* a signal the caller handles (a campaign's SIGINT, SIGTERM) must not end the wait: gnuplot,
     * killed, is reaped here */
    if (pid > 0)
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
    sigprocmask(SIG_BLOCK, &block, NULL);
    gnuplot_pid = 0;
    for (int i = 0; i < 3; i++)
        if (caught[i])
            sigaction(stop_signals[i], &before_gnuplot[i], NULL);
    sigprocmask(SIG_SETMASK, &was, NULL);
    return pid > 0 ? status : -1;
}

/* The chart drawn in dir into png; shown_png and shown_dir name them in messages (where the user
 * will find them: a campaign draws in its partial folder). */
static int draw(const char *dir, const char *script, const char *png, const char *shown_dir, const char *shown_png,
                const char *who)
{
    char temp[FS_OUT_PATH + 64], abs_temp[PATH_MAX + FS_OUT_PATH + 64], cwd[PATH_MAX];
    if (!cli_have_program("gnuplot")) {
        fprintf(stderr, "footsim %s: gnuplot is not installed: no chart %s (apt-get install gnuplot-nox "
                        "draws it; or run 'gnuplot %s' in %s later)\n", who, shown_png, script, shown_dir);
        return -1;
    }
    fs_error err;
    if (fs_temp_name(png, temp, sizeof temp, &err) != FS_OK)
        return cli_report(err.status, err.message);
    /* gnuplot runs in dir: it is given the temporary file's absolute name */
    if (temp[0] == '/' || !getcwd(cwd, sizeof cwd))
        snprintf(abs_temp, sizeof abs_temp, "%s", temp);
    else
        snprintf(abs_temp, sizeof abs_temp, "%s/%s", cwd, temp);
    char *var = NULL;
    size_t len = 0;
    FILE *v = open_memstream(&var, &len);
    if (!v)
        return cli_report(FS_NO_MEMORY, "out of memory");
    fputs("out = ", v);
    fs_gp_string(v, abs_temp);
    if (fclose(v) != 0) {
        free(var);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    int status = run_gnuplot(dir, var, script);
    free(var);
    if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
        remove(temp);
        if (gnuplot_stopped)
            fprintf(stderr, "footsim %s: gnuplot stopped by %s: no chart %s\n", who,
                    gnuplot_stopped == SIGINT ? "SIGINT" : gnuplot_stopped == SIGTERM ? "SIGTERM" : "SIGHUP", shown_png);
        else if (status != -1 && WIFSIGNALED(status) && (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM))
            fprintf(stderr, "footsim %s: gnuplot stopped by %s: no chart %s\n", who,
                    WTERMSIG(status) == SIGINT ? "SIGINT" : "SIGTERM", shown_png); /* Ctrl-C reaches the group */
        else
            fprintf(stderr, "footsim %s: gnuplot failed: no chart %s (the data and script %s are in %s)\n", who,
                    shown_png, script, shown_dir);
        return -1;
    }
    /* gnuplot says nothing when it could not write all of it (a full disk): the file must be a
     * whole PNG before it joins the results */
    if (fs_png_check(temp, png, &err) != FS_OK || fs_commit_temp(temp, png, &err) != FS_OK) {
        remove(temp);
        return cli_report(err.status, err.message);
    }
    return 0;
}

int cli_gnuplot_to(const char *dir, const char *script, const char *png, const char *who)
{
    return draw(dir, script, png, dir, png, who);
}

int cli_gnuplot_shown(const char *dir, const char *shown_dir, const char *script, const char *png_name,
                      const char *who)
{
    char png[2 * FS_PATH_MAX], shown_png[2 * FS_PATH_MAX];
    snprintf(png, sizeof png, "%s/%s", dir, png_name);
    snprintf(shown_png, sizeof shown_png, "%s/%s", shown_dir, png_name);
    return draw(dir, script, png, shown_dir, shown_png, who);
}

int cli_gnuplot(const char *dir, const char *script, const char *png_name, const char *who)
{
    char png[FS_OUT_PATH];
    fs_error err;
    if (fs_path_format(png, sizeof png, "the chart", &err, "%s/%s", dir, png_name) != FS_OK)
        return cli_report(err.status, err.message);
    int s = cli_gnuplot_shown(dir, dir, script, png_name, who);
    return s < 0 ? 0 : s;
}

/* ---- footsim plot ----------------------------------------------------------------------------- */

static int is_file(const char *dir, const char *name)
{
    char path[FS_OUT_PATH];
    struct stat st;
    return fs_path_format(path, sizeof path, "", NULL, "%s/%s", dir, name) == FS_OK && stat(path, &st) == 0 &&
           S_ISREG(st.st_mode);
}

/* A run's trajectory: its columns (by kind) and the ankle's first height. */
enum { PLOT_MAX_COLS = 256 };
typedef struct trajectory {
    char path[PATH_MAX + 32];     /* as gnuplot in the output folder reads it */
    char names[16384];            /* the header line, cut into names */
    const char *col[PLOT_MAX_COLS];
    int ncols, ankle_z, contacts, lean;
    double z0_m;
    char title[512];
    /* a landing trial's folder (trial.json beside): when it touched down and when its rule decided
       it (NAN: not a trial, or no touchdown), and what it decided ("landed (at_rest)") */
    double touchdown_s, decided_s;
    char decided[128];
} trajectory;

static int column_of(const trajectory *t, const char *name)
{
    for (int c = 0; c < t->ncols; c++)
        if (!strcmp(t->col[c], name))
            return c + 1;
    return 0;
}

static int ends_with(const char *s, const char *end)
{
    size_t n = strlen(s), m = strlen(end);
    return n > m && !strcmp(s + n - m, end);
}

/* The number a column's name ends with before its unit ("mtp3_rad": 3, "d2_chain4_N": 4), 0 when none. */
static int trailing_number(const char *name)
{
    const char *u = strrchr(name, '_');
    const char *p = u ? u : name + strlen(name);
    while (p > name && isdigit((unsigned char)p[-1]))
        p--;
    return atoi(p);
}

/* Reads the header and the first row of dir/trajectory.csv. Exit status (2: not a trajectory). */
static int read_trajectory(const char *dir, trajectory *t)
{
    char path[FS_OUT_PATH], row[16384];
    fs_error err;
    FILE *f = fs_path_format(path, sizeof path, "plot", &err, "%s/trajectory.csv", dir) != FS_OK ? NULL
            : fs_open_regular(path, 1L << 40, "a trajectory.csv written by footsim run", &err);
    if (!f)
        return cli_report(err.status, err.message);
    int ok = fgets(t->names, sizeof t->names, f) && strchr(t->names, '\n') && fgets(row, sizeof row, f);
    fclose(f);
    t->ncols = 0;
    for (char *p = ok ? strtok(t->names, ",\r\n") : NULL; p && t->ncols < PLOT_MAX_COLS; p = strtok(NULL, ",\r\n"))
        t->col[t->ncols++] = p;
    t->ankle_z = column_of(t, "ankle_z_m");
    t->contacts = column_of(t, "contacts");
    t->lean = column_of(t, "lean_deg");
    char *p = row;
    for (int c = 1; ok && c < t->ankle_z; c++)
        p = strchr(p, ',') ? strchr(p, ',') + 1 : p;
    char *end = NULL;
    t->z0_m = ok && t->ankle_z ? strtod(p, &end) : NAN;
    if (!ok || t->ncols < 1 || strcmp(t->col[0], "t_s") || !t->ankle_z || !t->contacts || end == p || !isfinite(t->z0_m))
        return cli_report(FS_BAD_INPUT, "plot: not a trajectory written by footsim run (a header t_s,ankle_x_m,"
                                        "ankle_y_m,ankle_z_m,contacts,... and rows of numbers): give the folder a "
                                        "run wrote, e.g. footsim run scenarios/static_load.ini, then footsim plot "
                                        "results/runs/static_load");
    return 0;
}

/* The title: what metrics.json says of the run, else the folder. */
static void run_title(const char *dir, trajectory *t)
{
    char path[FS_OUT_PATH], *text = NULL;
    size_t len;
    fs_error err;
    cJSON *m = fs_path_format(path, sizeof path, "plot", &err, "%s/metrics.json", dir) != FS_OK ? NULL : fs_read_regular(path, 1 << 20, "metrics.json", &text, &len, &err) == FS_OK ? cJSON_Parse(text) : NULL;
    free(text);
    const char *sc = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(m, "scenario"));
    const char *foot = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(m, "foot"));
    const cJSON *load = cJSON_GetObjectItemCaseSensitive(m, "load_kg"), *tilt = cJSON_GetObjectItemCaseSensitive(m, "tilt_deg");
    if (sc && foot && cJSON_IsNumber(load) && cJSON_IsNumber(tilt))
        snprintf(t->title, sizeof t->title, "Run %s: %s foot, %g kg load at the ankle, tilted %g deg", sc, foot,
                 load->valuedouble, tilt->valuedouble);
    else
        snprintf(t->title, sizeof t->title, "Run %s", dir);
    cJSON_Delete(m);
    /* a landing trial's: its seed and outcome in the title, its touchdown and decision marked */
    t->touchdown_s = t->decided_s = NAN;
    t->decided[0] = 0;
    text = NULL;
    cJSON *j = fs_path_format(path, sizeof path, "plot", &err, "%s/trial.json", dir) != FS_OK ? NULL : fs_read_regular(path, 1 << 20, "trial.json", &text, &len, &err) == FS_OK ? cJSON_Parse(text) : NULL;
    free(text);
    const char *outcome = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(j, "outcome"));
    const char *rule = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(j, "rule"));
    const cJSON *seed = cJSON_GetObjectItemCaseSensitive(j, "seed"), *td = cJSON_GetObjectItemCaseSensitive(j, "touchdown_s"),
                *end = cJSON_GetObjectItemCaseSensitive(j, "end_time_s");
    if (outcome && rule && cJSON_IsNumber(seed)) {
        snprintf(t->decided, sizeof t->decided, "%s (%s)", outcome, rule);
        snprintf(t->title, sizeof t->title, "Trial %s, seed %d: %s", dir, seed->valueint, t->decided);
        t->touchdown_s = cJSON_IsNumber(td) ? td->valuedouble : NAN;
        t->decided_s = cJSON_IsNumber(end) ? end->valuedouble : NAN;
    }
    cJSON_Delete(j);
}

/* A landing trial's marks on every panel: a dashed line at touchdown, a red one where its rule
 * decided it, labelled with the outcome (text as data). */
static void trial_marks(FILE *f, const trajectory *t)
{
    if (isfinite(t->touchdown_s))
        fprintf(f, "set arrow 1 from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lw 1.5 lc rgb '#606060'\n"
                   "set label 1 'touchdown' at %.9g, graph 0.96 offset 0.5, 0 textcolor rgb '#606060'\n",
                t->touchdown_s, t->touchdown_s, t->touchdown_s);
    if (isfinite(t->decided_s) && t->decided[0]) {
        fputs("decided = ", f);
        fs_gp_string(f, t->decided);
        fprintf(f, "\nset arrow 2 from %.9g, graph 0 to %.9g, graph 1 nohead lw 1.5 lc rgb '#c02020'\n"
                   "set label 2 decided at %.9g, graph 0.88 right offset -0.5, 0 textcolor rgb '#c02020'\n",
                t->decided_s, t->decided_s, t->decided_s);
    }
}

/* One panel: the columns whose names pass `pick`, coloured by their number (chain), dashed by kind. */
static void plot_columns(FILE *f, const trajectory *t, const char *title, const char *ylabel, const char *scale,
                         int (*pick)(const char *name, int *dash, int *keyed))
{
    /* a column's name (the file's: anyone's text) keys it through a variable, as data */
    for (int c = 0; c < t->ncols; c++) {
        int dash = 1, keyed = 1;
        if (!pick(t->col[c], &dash, &keyed) || !keyed || dash > 1 || ends_with(t->col[c], "_N"))
            continue;
        char key[sizeof t->names];
        snprintf(key, sizeof key, "%.*s", (int)(strrchr(t->col[c], '_') - t->col[c]), t->col[c]);
        fprintf(f, "column%d = ", c + 1);
        fs_gp_string(f, key);
        fputc('\n', f);
    }
    fprintf(f, "set title '%s'\nset ylabel '%s'\nplot ", title, ylabel);
    int n = 0;
    for (int c = 0; c < t->ncols; c++) {
        int dash = 1, keyed = 1;
        if (!pick(t->col[c], &dash, &keyed))
            continue;
        int chain = trailing_number(t->col[c]);
        char colour[32], key[80];
        snprintf(colour, sizeof colour, chain ? "%d" : "rgb 'black'", chain);
        if (!keyed)
            snprintf(key, sizeof key, "notitle");
        else if (dash > 1 || ends_with(t->col[c], "_N")) /* one entry per chain for the springs */
            snprintf(key, sizeof key, "title 'chain %d'", chain);
        else
            snprintf(key, sizeof key, "title column%d", c + 1);
        fprintf(f, "%sdata using 1:(column(%d)%s) with lines lw 1.5 dt %d lc %s %s", n++ ? ", \\\n     " : "", c + 1,
                scale, dash, colour, key);
    }
    fputs(n ? "\n" : "NaN notitle\n", f);
}

static int pick_midfoot(const char *name, int *dash, int *keyed)
{
    (void)dash, (void)keyed;
    return ends_with(name, "_rad") && (strncmp(name, "mtp", 3) != 0);
}

static int pick_mtp(const char *name, int *dash, int *keyed)
{
    (void)dash, (void)keyed;
    return ends_with(name, "_rad") && !strncmp(name, "mtp", 3);
}

/* Spring-dampers "dK_chainN_N": colour the chain, dash type K; the key names the chains once. */
static int pick_spring(const char *name, int *dash, int *keyed)
{
    int k = 0, chain = 0;
    if (!ends_with(name, "_N") || sscanf(name, "d%d_chain%d", &k, &chain) != 2)
        return 0;
    *dash = k;
    *keyed = k == 1;
    return 1;
}

static int fill_run_script(FILE *f, const void *user)
{
    const trajectory *t = user;
    int hinges = 0, springs = 0;
    for (int c = 0; c < t->ncols; c++)
        hinges += ends_with(t->col[c], "_rad"), springs += ends_with(t->col[c], "_N");
    int panels = 2 + (hinges > 0) * 2 + (springs > 0) + (t->lean > 0), rows = (panels + 1) / 2;
    fputs("# A run's time series: 'gnuplot plot.gp' in this folder draws plot.png.\n"
          "if (!exists(\"out\")) out = 'plot.png'\n# the names shown, as gnuplot strings: data, never code\ndata = ",
          f);
    fs_gp_string(f, t->path);
    fputs("\nrun_title = ", f);
    fs_gp_string(f, t->title);
    fprintf(f, "\nset terminal pngcairo size 1200,%d noenhanced font 'sans,10'\nset output out\n"
               "set datafile separator ','\nset datafile columnheaders\n"
               "set multiplot layout %d,2 title run_title",
            60 + 330 * rows, rows);
    fputc('\n', f);
    trial_marks(f, t);
    fprintf(f, "set grid\nset autoscale xfix\nset xlabel 'time (s)'\nset key outside right top samplen 2 noenhanced\n"
               "set title 'ankle drop: first height minus height (mm)'\nset ylabel 'ankle drop (mm)'\n"
               "plot data using 1:((%.17g - column(%d)) * 1000) with lines lw 2 lc rgb '#1f5fa0' notitle\n"
               "set title 'contact points with the ground'\nset ylabel 'contact points'\nset yrange [0:*]\n"
               "set offsets 0, 0, 1, 0\nplot data using 1:%d with steps lw 2 lc rgb '#2a7a2a' notitle\n"
               "set autoscale y\nset offsets 0, 0, 0, 0\n",
            t->z0_m, t->ankle_z, t->contacts);
    if (hinges) {
        plot_columns(f, t, "joint angles from the neutral pose: ankle and midfoot (deg)", "angle (deg)", " * 180 / pi",
                     pick_midfoot);
        plot_columns(f, t, "joint angles from the neutral pose: MTP, the toes (deg)", "angle (deg)", " * 180 / pi",
                     pick_mtp);
    }
    if (springs)
        plot_columns(f, t, "spring-damper forces, tension positive (N): d1 solid, d2 dashed, d3 dotted",
                     "force (N)", "", pick_spring);
    if (t->lean)
        fprintf(f, "set title 'robot lean from upright (deg)'\nset ylabel 'lean (deg)'\n"
                   "plot data using 1:%d with lines lw 2 lc rgb '#a02020' notitle\n", t->lean);
    fputs("unset multiplot\n", f);
    return 1;
}

/* plot's exit status for cli_gnuplot_to's s: no gnuplot installed is said and not an error (the
 * script is there for later); gnuplot failing is: the chart, plot's one result, was not written. */
static int not_drawn(int s)
{
    return s >= 0 ? s : cli_have_program("gnuplot") ? FS_IO : 0;
}

/* A run's folder: dir/trajectory.csv drawn into out/plot.png, read into t (zeroed). */
static int plot_run_into(const char *dir, const char *out, trajectory *t)
{
    int s = read_trajectory(dir, t);
    if (s)
        return s;
    run_title(dir, t);
    /* gnuplot runs in out: the data by its absolute path unless it is there */
    char here[PATH_MAX], there[PATH_MAX];
    if (!realpath(dir, here) || !realpath(out, there))
        return cli_report(FS_BAD_INPUT, "plot: cannot resolve the folders' paths");
    if (!strcmp(here, there))
        snprintf(t->path, sizeof t->path, "trajectory.csv");
    else
        snprintf(t->path, sizeof t->path, "%s/trajectory.csv", here);
    fs_error err;
    if (fs_write_in(out, "plot.gp", fill_run_script, t, &err) != FS_OK)
        return cli_report(err.status, err.message);
    char png[FS_OUT_PATH];
    if (fs_path_format(png, sizeof png, "--out", &err, "%s/plot.png", out) != FS_OK)
        return cli_report(err.status, err.message);
    s = cli_gnuplot_to(out, "plot.gp", png, "plot");
    if (!s)
        printf("%s: %s (script %s/plot.gp)\n", png, t->title, out);
    return not_drawn(s);
}

/* plot_run_into with its trajectory on the heap (large), for this command only. */
static int plot_run(const char *dir, const char *out)
{
    trajectory *t = cli_zalloc(sizeof *t);
    if (!t)
        return FS_NO_MEMORY;
    int s = plot_run_into(dir, out, t);
    free(t);
    return s;
}

/* A campaign's folder: its chart drawn again from dir/summary.json into out/success.png. */
static int plot_campaign_into(const char *dir, const char *out, fs_campaign *c, fs_campaign_row *rows)
{
    char path[FS_OUT_PATH];
    fs_error err;
    if (fs_path_format(path, sizeof path, "plot", &err, "%s/summary.json", dir) != FS_OK ||
        fs_campaign_reload(path, c, rows, &err) != FS_OK || fs_campaign_write_chart(c, rows, out, &err) != FS_OK ||
        fs_path_format(path, sizeof path, "--out", &err, "%s/success.png", out) != FS_OK)
        return cli_report(err.status, err.message);
    int s = cli_gnuplot_to(out, "chart.gp", path, "plot");
    if (!s)
        printf("%s/success.png: campaign %s, %d cells (feet x terrains x robots: %d x %d x %d; data %s/chart.dat)\n",
               out, c->name, fs_campaign_ncells(c), c->nfeet, c->nterrains, c->nrobots, out);
    return not_drawn(s);
}

/* plot_campaign_into with the campaign and its rows on the heap (large), for this command only. */
static int plot_campaign(const char *dir, const char *out)
{
    struct {
        fs_campaign c;
        fs_campaign_row rows[FS_CAMPAIGN_MAX_FEET * FS_CAMPAIGN_MAX_TERRAINS * FS_CAMPAIGN_MAX_ROBOTS];
    } *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    int s = plot_campaign_into(dir, out, &w->c, w->rows);
    free(w);
    return s;
}

int cli_plot(const cli_args *a)
{
    const char *dir = a->input;
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "footsim plot: %s: %s; give the folder a run or a campaign wrote (footsim plot "
                        "results/runs/static_load)\n", dir, stat(dir, &st) ? strerror(errno) : "not a folder");
        return FS_BAD_INPUT;
    }
    int campaign = is_file(dir, "summary.json"), run = is_file(dir, "trajectory.csv");
    if (!campaign && !run) {
        if (is_file(dir, "trial.json"))
            fprintf(stderr, "footsim plot: %s is a landing trial's folder: trial.json holds its outcome, not a time "
                            "series; plot a run's folder (footsim run SCENARIO writes trajectory.csv) or a "
                            "campaign's (summary.json)\n", dir);
        else
            fprintf(stderr, "footsim plot: %s is not a run's or a campaign's results (no trajectory.csv, no "
                            "summary.json); give the folder footsim run or footsim campaign wrote, e.g. "
                            "results/runs/static_load or results/landing\n", dir);
        return FS_BAD_INPUT;
    }
    const char *out = a->out ? a->out : dir;
    fs_error err;
    if (a->out && fs_outdir_shared(a->out, a->replace, "--out", &err) != FS_OK)
        return cli_report(err.status, err.message);
    /* the folder read and the one written held as a campaign or run holds them: none replaces
     * either between the summary read and the chart written */
    fs_outdir held[2];
    struct stat out_st;
    int two = a->out && !(stat(a->out, &out_st) == 0 && out_st.st_dev == st.st_dev && out_st.st_ino == st.st_ino);
    if (fs_outdir_lock(&held[0], dir, "plot", &err) != FS_OK)
        return cli_report(err.status, err.message);
    if (two && fs_outdir_lock(&held[1], a->out, "--out", &err) != FS_OK) {
        fs_outdir_unlock(&held[0]);
        return cli_report(err.status, err.message);
    }
    if (getenv("FOOTSIM_TEST_PLOT_DELAY")) /* tests: a plot holding its folders */
        sleep((unsigned)atoi(getenv("FOOTSIM_TEST_PLOT_DELAY")));
    int s = campaign ? plot_campaign(dir, out) : plot_run(dir, out);
    if (two)
        fs_outdir_unlock(&held[1]);
    fs_outdir_unlock(&held[0]);
    return s;
}
