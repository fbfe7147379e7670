/* base_stats.c: medians and the order of doubles (fs_stats.h). */
#include "footsim/base/fs_stats.h"

#include <math.h>
#include <stdlib.h>

int fs_compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double fs_median(double *values, int n)
{
    if (n <= 0)
        return NAN;
    qsort(values, (size_t)n, sizeof *values, fs_compare_doubles);
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

double fs_median_low(double *values, int n)
{
    if (n <= 0)
        return NAN;
    qsort(values, (size_t)n, sizeof *values, fs_compare_doubles);
    return values[(n - 1) / 2];
}
