/* analysis_drop.c: the drop law, the pitch-stiffness law with the touchdown in it (fs_analysis.h,
 * docs/landing.md): the rotational energy the drop leaves the robot with about its ankle against the
 * work the foot's saturating restoring moment does up to the largest lean it holds. Closed forms
 * only; the foot's K, fold moment and support edge come from the caller. */
#include "footsim/analysis/fs_analysis.h"

#include <math.h>
#include <string.h>

void fs_drop_law_apply(const fs_pitch_law *statics, const fs_robot_def *r, double gravity_m_per_s2, double drop_m,
                       double max_lean_rad, const fs_drop_support *sup, fs_drop_law *out)
{
    memset(out, 0, sizeof *out);
    double m = r->mass_kg, W = m * gravity_m_per_s2, h = r->com_height_m, x = fabs(r->com_forward_m);
    double I[3];
    fs_robot_inertia(r, I);
    double I_pitch = r->kind == FS_ROBOT_BIPED ? r->pelvis_inertia_kgm2[1] : I[1];
    out->speed_m_per_s = drop_m > 0 ? sqrt(2 * gravity_m_per_s2 * drop_m) : 0;
    out->inertia_kgm2 = I_pitch + m * (h * h + x * x);
    double L = m * x * out->speed_m_per_s;
    out->energy_J = out->inertia_kgm2 > 0 ? L * L / (2 * out->inertia_kgm2) : 0;
    double edge_moment = W * sup->edge_m;
    out->folds = sup->fold_N_m < edge_moment;
    out->saturation_N_m = out->folds ? sup->fold_N_m : edge_moment;
    out->lean_rad = statics->lean_rad;
    if (statics->held) {
        out->stands = 1;
        return;
    }
    double K = statics->K, Kn = K - W * h, Ms = out->saturation_N_m;
    /* the static law's equilibrium, which must lie on the rising branch: its moment W (x + h theta_0)
       below M_s */
    int below = Kn > 0 && W * (x + h * statics->lean_rad) < Ms;
    if (!below || !(statics->lean_rad < max_lean_rad)) {
        out->lean_rad = below ? statics->lean_rad : INFINITY;
        out->stands = 0;
        return;
    }
    if (isinf(Ms)) { /* no saturation: a restoring moment without end, the static law's verdict */
        out->barrier_J = INFINITY;
        out->stands = statics->stands;
        return;
    }
    /* rising branch, upright to theta_s (K infinite: theta_s = 0 and this is 0) */
    double ts = isinf(K) ? 0 : Ms / K;
    double B = isinf(K) ? 0 : 0.5 * Kn * ts * ts - W * x * ts;
    if (out->folds) {
        /* the fold's plateau M_s against the weight's moment W (x + h theta): zero at theta* */
        double tstar = (Ms / W - x) / h;
        B += 0.5 * W * h * (tstar - ts) * (tstar - ts);
    } else {
        /* the foot turns about the edge: the centre of mass b behind it, c above it */
        double b = sup->edge_m - x - h * ts, c = h + sup->ankle_height_m;
        B += W * (hypot(b, c) - c);
    }
    out->barrier_J = B;
    out->stands = out->energy_J < B;
}
