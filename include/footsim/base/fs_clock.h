/* fs_clock.h: seconds on the monotonic clock (CLOCK_MONOTONIC), what profiling, fs_track_run
 * and the benchmarks time with. Timing never changes a result. */
#ifndef FS_CLOCK_H
#define FS_CLOCK_H

double fs_clock_s(void);

#endif
