/* analysis_diff.h (internal): the first and second derivatives of a scalar function of a few
 * variables by central differences, for the statics' potential energies (analysis_planar.c,
 * analysis_pitch.c). Steps of 1e-7 for the gradient and 1e-5 for the Hessian (differences of the
 * gradient, then symmetrised) suit energies of a joule's scale in radians. */
#ifndef FS_ANALYSIS_DIFF_H
#define FS_ANALYSIS_DIFF_H

enum { FS_DIFF_MAX = 3 };

typedef double (*fs_diff_fn)(void *ctx, const double *q);

void fs_diff_gradient(fs_diff_fn f, void *ctx, int n, const double *q, double *grad);
void fs_diff_hessian(fs_diff_fn f, void *ctx, int n, const double *q, double H[FS_DIFF_MAX][FS_DIFF_MAX]);

#endif
