/* base_clock.c: the monotonic clock (fs_clock.h). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "footsim/base/fs_clock.h"

#include <time.h>

double fs_clock_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
