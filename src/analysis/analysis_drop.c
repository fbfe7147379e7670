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
    fs_robot_whole_inertia(r, I);
    double I_pitch = I[1];
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

/* the inertia I_G (principal, along the frame's axes) times v */
static fs_vec3 inertia_times(const double I[3], fs_vec3 v) { return fs_v3(I[0] * v.x, I[1] * v.y, I[2] * v.z); }

/* about the line through p along the unit u: the body's moment of inertia */
static double inertia_about(double m, const double I[3], fs_vec3 G, fs_vec3 p, fs_vec3 u)
{
    fs_vec3 r = fs_sub(G, p);
    fs_vec3 across = fs_sub(r, fs_scale(u, fs_dot(r, u)));
    return fs_dot(u, inertia_times(I, u)) + m * fs_dot(across, across);
}

double fs_rocking_kept_J(double mass_kg, const double I_G[3], fs_vec3 G, fs_vec3 pivot, fs_vec3 axis, double energy_J,
                         fs_vec3 s1, fs_vec3 s2)
{
    double la = fs_norm(axis), ls = fs_norm(fs_sub(s2, s1));
    if (!(energy_J > 0) || !(la > 0) || !(ls > 0))
        return 0;
    fs_vec3 a = fs_scale(axis, 1 / la), u = fs_scale(fs_sub(s2, s1), 1 / ls), rP = fs_sub(G, pivot);
    if (fs_cross(a, rP).z > 0) /* the sense that lowers G */
        a = fs_scale(a, -1);
    double Ia = inertia_about(mass_kg, I_G, G, pivot, a), IS = inertia_about(mass_kg, I_G, G, s1, u);
    if (!(Ia > 0) || !(IS > 0))
        return 0;
    double omega = sqrt(2 * energy_J / Ia);
    fs_vec3 rS = fs_sub(G, s1);
    double wS = omega * fs_dot(u, fs_add(inertia_times(I_G, a), fs_scale(fs_cross(rS, fs_cross(a, rP)), mass_kg))) / IS;
    /* G's velocity wS u x r_S against the side's outward normal (right of s1 -> s2, from above) */
    fs_vec3 vG = fs_scale(fs_cross(u, rS), wS);
    return vG.x * u.y - vG.y * u.x > 0 ? 0.5 * IS * wS * wS : 0;
}

double fs_pitch_engaged_share(const double *engage_rad, int n, double K, double W, double x, double h)
{
    if (n <= 0 || n > FS_MAX_FEET * FS_CHAINS)
        return NAN;
    double at[FS_MAX_FEET * FS_CHAINS];
    for (int i = 0; i < n; i++)
        at[i] = engage_rad[i];
    for (int i = 1; i < n; i++) /* in the order they engage */
        for (int j = i; j > 0 && at[j] < at[j - 1]; j--) {
            double t = at[j];
            at[j] = at[j - 1], at[j - 1] = t;
        }
    double k = K / n, sum = 0;
    for (int m = 1; m <= n && isfinite(at[m - 1]); m++) {
        sum += at[m - 1];
        double den = m * k - W * h, theta = (W * x + k * sum) / den;
        /* a chain engaging at theta itself bears there: it joins (the lean stays where it is) */
        if (den > 0 && theta >= at[m - 1] && (m == n || theta < at[m]))
            return theta > 0 ? k * (m * theta - sum) / (K * theta) : (double)m / n;
    }
    return NAN;
}

double fs_contact_damping_ratio(double k_N_per_m, double c_Ns_per_m, double mass_kg)
{
    return k_N_per_m > 0 && mass_kg > 0 ? c_Ns_per_m / (2 * sqrt(k_N_per_m * mass_kg)) : INFINITY;
}

/* x'' + 2 zeta w x' + w^2 x = 0 from x = 0, x' = v: x = v / w_d e^(-zeta w t) sin(w_d t), w_d = w
   sqrt(1 - zeta^2), back at x = 0 at t = pi / w_d with x' = -v e^(-zeta w pi / w_d) */
double fs_contact_restitution(double zeta)
{
    if (!(zeta < 1))
        return 0;
    if (!(zeta > 0))
        return 1;
    return exp(-M_PI * zeta / sqrt(1 - zeta * zeta));
}

/* Each impact at speed u reverses the ankle's vertical speed to e u and leaves (1 + e) m x u of
   angular momentum about it (the impulse through the ankle; plastic: m x u); the rebounds come in
   at e v, e^2 v, ..., so at most (1 + e) m x v (1 + e + e^2 + ...) = m x v (1 + e) / (1 - e) in all,
   energy quadratic in it */
double fs_contact_rebound_gain(double e)
{
    if (!(e > 0))
        return 1;
    if (!(e < 1))
        return INFINITY;
    double r = (1 + e) / (1 - e);
    return r * r;
}

double fs_pitch_contact_series(double K_N_m_per_rad, double spread_m2, double k_N_per_m, double k_ref_N_per_m)
{
    if (!(k_N_per_m < k_ref_N_per_m) || !(spread_m2 > 0) || !(k_N_per_m > 0) || !(K_N_m_per_rad > 0))
        return K_N_m_per_rad;
    double extra = (1 / k_N_per_m - (isfinite(k_ref_N_per_m) ? 1 / k_ref_N_per_m : 0)) / spread_m2;
    return isinf(K_N_m_per_rad) ? 1 / extra : 1 / (1 / K_N_m_per_rad + extra);
}
