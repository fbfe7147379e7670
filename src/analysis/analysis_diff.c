/* analysis_diff.c: derivatives by central differences (analysis_diff.h). */
#include "analysis_diff.h"

#include <string.h>

void fs_diff_gradient(fs_diff_fn f, void *ctx, int n, const double *q, double *grad)
{
    const double h = 1e-7;
    for (int i = 0; i < n; i++) {
        double qp[FS_DIFF_MAX], qm[FS_DIFF_MAX];
        memcpy(qp, q, (size_t)n * sizeof *q);
        memcpy(qm, q, (size_t)n * sizeof *q);
        qp[i] += h;
        qm[i] -= h;
        grad[i] = (f(ctx, qp) - f(ctx, qm)) / (2 * h);
    }
}

void fs_diff_hessian(fs_diff_fn f, void *ctx, int n, const double *q, double H[FS_DIFF_MAX][FS_DIFF_MAX])
{
    const double h = 1e-5;
    for (int j = 0; j < n; j++) {
        double qp[FS_DIFF_MAX], qm[FS_DIFF_MAX], gp[FS_DIFF_MAX], gm[FS_DIFF_MAX];
        memcpy(qp, q, (size_t)n * sizeof *q);
        memcpy(qm, q, (size_t)n * sizeof *q);
        qp[j] += h;
        qm[j] -= h;
        fs_diff_gradient(f, ctx, n, qp, gp);
        fs_diff_gradient(f, ctx, n, qm, gm);
        for (int i = 0; i < n; i++)
            H[i][j] = (gp[i] - gm[i]) / (2 * h);
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            H[i][j] = H[j][i] = 0.5 * (H[i][j] + H[j][i]);
}
