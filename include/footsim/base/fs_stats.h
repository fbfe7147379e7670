/* fs_stats.h: the few statistics footsim takes of plain numbers, in one place.
 *
 * fs_median sorts values in place and returns the median (the mean of the two middle values for
 * an even count; NAN for none), as campaign summaries report it. fs_median_low returns the lower
 * middle value instead, always one of the values: what a benchmark reports as "the run of median
 * time". fs_compare_doubles orders doubles ascending for qsort. */
#ifndef FS_STATS_H
#define FS_STATS_H

int fs_compare_doubles(const void *a, const void *b);
double fs_median(double *values, int n);
double fs_median_low(double *values, int n);

#endif
