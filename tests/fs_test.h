/* fs_test.h: footsim's tiny test harness. Each test file defines TEST functions and lists them in
 * FS_TEST_MAIN; the runner prints each failure with its file and line and ends with the line
 * "N passed, N failed" that CI reads.
 *
 * CHECK records a failure and goes on; REQUIRE records it and ends the test function at once (what
 * follows would run on data that was never made: a failed load, build or run). */
#ifndef FS_TEST_H
#define FS_TEST_H

#include "footsim/sim/fs_ode.h"

#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>

static int fs_test_failures;
static jmp_buf fs_test_abort; /* where a failed REQUIRE returns to: the runner */

#define CHECK(cond)                                                                          \
    do {                                                                                     \
        if (!(cond)) {                                                                       \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);         \
            fs_test_failures++;                                                              \
        }                                                                                    \
    } while (0)

#define REQUIRE(cond)                                                                        \
    do {                                                                                     \
        if (!(cond)) {                                                                       \
            fprintf(stderr, "%s:%d: requirement failed, test ended: %s\n", __FILE__, __LINE__, #cond); \
            fs_test_failures++;                                                              \
            longjmp(fs_test_abort, 1);                                                       \
        }                                                                                    \
    } while (0)

/* |actual - expected| <= tol, with all three printed on failure. */
#define CHECK_NEAR(actual, expected, tol)                                                    \
    do {                                                                                     \
        double a_ = (actual), e_ = (expected), t_ = (tol);                                   \
        if (!(fabs(a_ - e_) <= t_)) {                                                        \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %.9g within %.3g\n", __FILE__, __LINE__, \
                    #actual, a_, e_, t_);                                                    \
            fs_test_failures++;                                                              \
        }                                                                                    \
    } while (0)

/* A refusal's message starts with "path:line: " (unless line is 0) and contains words. */
static inline void fs_check_refusal(const char *message, const char *path, int line, const char *words)
{
    char prefix[1100];
    snprintf(prefix, sizeof prefix, "%s:%d: ", path, line);
    if ((line > 0 && strncmp(message, prefix, strlen(prefix))) || !strstr(message, words)) {
        fprintf(stderr, "  expected '%s...%s' in: %s\n", line > 0 ? prefix : "", words, message);
        fs_test_failures++;
    }
}

/* Runs one test function; a failed REQUIRE inside it comes back here. */
static inline void fs_test_run_one(void (*fn)(void))
{
    if (!setjmp(fs_test_abort))
        fn();
}

typedef struct fs_test_case { const char *name; void (*fn)(void); } fs_test_case;

/* Whether a test's name contains one of the names given (argv[1 ..]). */
static inline int fs_test_named(const char *name, int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strstr(name, argv[i]))
            return 1;
    return 0;
}

/* How many of the names given match no test (each said): a case renamed fails the run that names it. */
static inline int fs_test_unmatched(const fs_test_case *cases, int n, int argc, char **argv)
{
    int unmatched = 0;
    for (int a = 1; a < argc; a++) {
        int found = 0;
        for (int i = 0; i < n; i++)
            found |= strstr(cases[i].name, argv[a]) != NULL;
        if (!found) {
            printf("FAIL no test's name contains '%s'\n", argv[a]);
            unmatched++;
        }
    }
    return unmatched;
}

/* `test_x NAME...` runs only the tests whose name contains one of the NAMEs (each must name one). */
#define FS_TEST_MAIN(...)                                                                    \
    int main(int argc, char **argv)                                                          \
    {                                                                                        \
        fs_test_case cases[] = {__VA_ARGS__};                                                \
        int n = (int)(sizeof cases / sizeof cases[0]), passed = 0, failed = 0;               \
        fs_ode_init();                                                                       \
        for (int i = 0; i < n; i++) {                                                        \
            if (argc > 1 && !fs_test_named(cases[i].name, argc, argv))                      \
                continue;                                                                    \
            int before = fs_test_failures;                                                   \
            fs_test_run_one(cases[i].fn);                                                    \
            int ok = fs_test_failures == before;                                             \
            printf("%s %s\n", ok ? "ok  " : "FAIL", cases[i].name);                          \
            ok ? passed++ : failed++;                                                        \
        }                                                                                    \
        fs_ode_close();                                                                      \
        failed += fs_test_unmatched(cases, n, argc, argv);                                   \
        printf("%d passed, %d failed\n", passed, failed);                                    \
        return failed ? 1 : 0;                                                               \
    }

#define TEST(fn) {#fn, fn}

#endif
