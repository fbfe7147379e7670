/* experiment_support.c: what a seed's drawn terrain offers under the drawn footprint (fs_trial.h):
 * the shapes that bear when the foot is lowered onto it, their support polygon, and where the line
 * from the ankle through the robot's centre of mass leaves it. Geometry only: nothing simulated. */
#include "footsim/experiment/fs_trial.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a sole's bottom face is sampled on a grid of SOLE_NX by SOLE_NY points, corners included, each
   the highest of SUB x SUB points over its share of the face: where the terrain rises under it (a
   bump under the middle of the sole) it bears there, not at a corner */
enum { SOLE_NX = 11, SOLE_NY = 7, SUB = 5, MAX_POINTS = FS_MAX_SPHERES + SOLE_NX * SOLE_NY * FS_MAX_BOXES };
/* every foot's shapes (a biped's two): their hull's corners fit fs_trial_support's */
_Static_assert((int)MAX_POINTS <= (int)FS_SUPPORT_MAX_CORNERS, "the support's corners fit");

typedef struct point { double x, y; } point;

static double cross(point o, point a, point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

static int by_x(const void *pa, const void *pb)
{
    const point *a = pa, *b = pb;
    return a->x < b->x ? -1 : a->x > b->x ? 1 : a->y < b->y ? -1 : a->y > b->y;
}

/* Andrew's monotone chain: the convex hull of p[n] counter-clockwise into h; its size (< 3: no area). */
static int hull(point *p, int n, point *h)
{
    qsort(p, (size_t)n, sizeof *p, by_x);
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
            k--;
        h[k++] = p[i];
    }
    for (int i = n - 2, low = k + 1; i >= 0; i--) {
        while (k >= low && cross(h[k - 2], h[k - 1], p[i]) <= 0)
            k--;
        h[k++] = p[i];
    }
    return n > 1 ? k - 1 : n;
}

/* The rest over the points not folded away (skip): the plane z = D + b . ((x, y) - (x0, y0)) on or
 * above every such point's q and lowest under the centre of mass (the upper hull's facet over it,
 * found among the triples of points), the centre of mass's ground point moved with the tilt by its
 * height hc times the slope, so twice more; the facet's corners and their shares of the weight (the
 * centre of mass's barycentric coordinates). 0 when no facet holds the centre of mass. */
typedef struct rest {
    double plane[3]; /* D, b_x, b_y */
    int facet[3];
    double share[3];
    point com;
} rest;

static int rest_on(const point *at, const double *q, const int *skip, int n, point a, point fwd, double xf, double hc,
                   point origin, rest *r)
{
    r->plane[0] = NAN, r->plane[1] = r->plane[2] = 0;
    r->com = (point){a.x + xf * fwd.x, a.y + xf * fwd.y};
    for (int pass = 0; pass < 3; pass++) {
        double best = INFINITY;
        int found = 0;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n && !skip[i]; j++)
                for (int k = j + 1; k < n && !skip[j]; k++) {
                    if (skip[k])
                        continue;
                    double ux = at[j].x - at[i].x, uy = at[j].y - at[i].y, vx = at[k].x - at[i].x,
                           vy = at[k].y - at[i].y, det = ux * vy - uy * vx;
                    if (fabs(det) < 1e-10)
                        continue;
                    /* the centre of mass inside the triangle (barycentric coordinates) */
                    double wx = r->com.x - at[i].x, wy = r->com.y - at[i].y;
                    double l1 = (wx * vy - wy * vx) / det, l2 = (ux * wy - uy * wx) / det;
                    if (l1 < 0 || l2 < 0 || l1 + l2 > 1)
                        continue;
                    double du = q[j] - q[i], dv = q[k] - q[i];
                    double bx = (du * vy - dv * uy) / det, by = (ux * dv - vx * du) / det;
                    double z0 = q[i] - bx * (at[i].x - origin.x) - by * (at[i].y - origin.y);
                    int above = 1;
                    for (int m = 0; m < n && above; m++)
                        above = skip[m] || z0 + bx * (at[m].x - origin.x) + by * (at[m].y - origin.y) >= q[m] - 1e-12;
                    double under_com = z0 + bx * (r->com.x - origin.x) + by * (r->com.y - origin.y);
                    if (above && under_com < best) {
                        best = under_com, found = 1;
                        r->plane[0] = z0, r->plane[1] = bx, r->plane[2] = by;
                        r->facet[0] = i, r->facet[1] = j, r->facet[2] = k;
                        r->share[0] = 1 - l1 - l2, r->share[1] = l1, r->share[2] = l2;
                    }
                }
        if (!found && pass == 0)
            return 0; /* a later pass that finds none keeps the last facet */
        r->com.x = a.x + xf * fwd.x - hc * r->plane[1];
        r->com.y = a.y + xf * fwd.y - hc * r->plane[2];
    }
    return 1;
}

static double height_on(const rest *r, point origin, point p)
{
    return r->plane[0] + r->plane[1] * (p.x - origin.x) + r->plane[2] * (p.y - origin.y);
}

fs_status fs_trial_support_of(const fs_scenario *base, int seed, double travel_m, double chain_k_N_m_per_rad,
                              fs_trial_support *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    fs_scenario *sc;
    fs_status s = fs_trial_placed(base, seed, NULL, &sc, err);
    if (s == FS_OK) {
        fs_foot_geom two; /* a biped's feet; its ankles' midpoint stands for the ankle */
        const fs_foot_geom *g = fs_scenario_geometry(sc, &two);
        fs_vec3 ankle = g->nfeet > 1 ? fs_scale(fs_add(g->foot[0].ankle, g->foot[1].ankle), 0.5) : g->ankle;
        double yaw = sc->def.yaw_deg * M_PI / 180, c = cos(yaw), sn = sin(yaw);
        double x0 = sc->def.start_x_m, y0 = sc->def.start_y_m;
        /* each shape's contact point on the ground (x, y), its lowest point's height in the design
           frame, the terrain's highest under it, and whether it is a toe or the heel */
        point at[MAX_POINTS];
        double low[MAX_POINTS], under[MAX_POINTS];
        int toe[MAX_POINTS], heel[MAX_POINTS], chained[MAX_POINTS], n = 0;
        for (int i = 0; i < g->nspheres; i++, n++) {
            double r = g->sphere[i].radius_m, lx = g->sphere[i].centre.x, ly = g->sphere[i].centre.y;
            at[n].x = x0 + c * lx - sn * ly;
            at[n].y = y0 + sn * lx + c * ly;
            low[n] = g->sphere[i].centre.z - r;
            under[n] = fs_terrain_height(&sc->terrain, at[n].x, at[n].y);
            const double dx[4] = {r, -r, 0, 0}, dy[4] = {0, 0, r, -r};
            for (int k = 0; k < 4; k++)
                under[n] = fmax(under[n], fs_terrain_height(&sc->terrain, at[n].x + dx[k], at[n].y + dy[k]));
            /* the body in its own foot's numbering (a biped's left foot's from foot[1].first_body on) */
            int body = g->sphere[i].body;
            body -= g->nfeet > 1 && body >= g->foot[1].first_body ? g->foot[1].first_body : 0;
            heel[n] = body == FS_BODY_HEEL;
            toe[n] = chained[n] = 0;
            for (int ch = 0; g->kind == FS_FOOT_BIOMIMETIC && ch < FS_CHAINS; ch++) {
                toe[n] |= body == g->chain[ch].phalanx;
                chained[n] |= body == g->chain[ch].phalanx || body == g->chain[ch].metatarsal;
            }
            out->toes += toe[n];
        }
        for (int b = 0; b < g->nboxes; b++)
            for (int k = 0; k < SOLE_NX * SOLE_NY; k++, n++) {
                /* the highest of SUB x SUB points over the grid point's share of the face (its
                   corners' share reaching out to the face's edge): a bump between grid points counts */
                double lx0 = g->box[b].centre.x + ((double)(k % SOLE_NX) / (SOLE_NX - 1) - 0.5) * g->box_size.x;
                double ly0 = g->box[b].centre.y + ((double)(k / SOLE_NX) / (SOLE_NY - 1) - 0.5) * g->box_size.y;
                double hx = 0.5 * g->box_size.x / (SOLE_NX - 1), hy = 0.5 * g->box_size.y / (SOLE_NY - 1);
                under[n] = -INFINITY;
                for (int u = 0; u < SUB; u++)
                    for (int v = 0; v < SUB; v++) {
                        double lx = fmin(fmax(lx0 + hx * (2.0 * u / (SUB - 1) - 1), g->box[b].centre.x - 0.5 * g->box_size.x),
                                         g->box[b].centre.x + 0.5 * g->box_size.x);
                        double ly = fmin(fmax(ly0 + hy * (2.0 * v / (SUB - 1) - 1), g->box[b].centre.y - 0.5 * g->box_size.y),
                                         g->box[b].centre.y + 0.5 * g->box_size.y);
                        point w = {x0 + c * lx - sn * ly, y0 + sn * lx + c * ly};
                        double z = fs_terrain_height(&sc->terrain, w.x, w.y);
                        if (z > under[n] || (u == SUB / 2 && v == SUB / 2 && z >= under[n]))
                            under[n] = z, at[n] = w;
                    }
                low[n] = g->box[b].centre.z - 0.5 * g->box_size.z;
                toe[n] = heel[n] = chained[n] = 0;
            }
        /* the rest: the foot settles (small tilts) on the plane over the shapes' points lowest under
           the centre of mass (rest_on). A chain's shape at a corner of that rest (a toe, or a midfoot
           sphere on a metatarsal) folds away when its chain cannot hold its share of the weight over
           its rise above the rest the others make: its chain's pitch stiffness chain_k about the
           ankle, a ahead of it, is k = chain_k / a^2 there, and it folds when the rise is more than
           the travel (within it the shape bears with the others) and k times the rise is below the
           share (the foot then rests on the others, the folded shape still bearing);
           one shape at a time, the most loaded first, while the others still hold the centre of mass */
        double q[MAX_POINTS], xf = sc->def.robot.com_forward_m, hc = sc->def.robot.com_height_m;
        for (int i = 0; i < n; i++)
            q[i] = under[i] - low[i];
        point a = {x0 + c * ankle.x - sn * ankle.y, y0 + sn * ankle.x + c * ankle.y};
        point fwd = {c, sn}, origin = {x0, y0};
        /* everything the ground carries (a biped's geometry counts its body already) */
        double W = (g->nfeet > 1 ? g->total_mass_kg : sc->def.robot.mass_kg + g->total_mass_kg) * sc->def.gravity_m_per_s2;
        int skip[MAX_POINTS] = {0};
        rest rs, without;
        int held = rest_on(at, q, skip, n, a, fwd, xf, hc, origin, &rs);
        for (int round = 0; held && chain_k_N_m_per_rad > 0 && round < n; round++) {
            int fold = -1;
            double most = 0;
            for (int v = 0; v < 3; v++) {
                int p = rs.facet[v];
                double ahead = c * (at[p].x - a.x) + sn * (at[p].y - a.y), R = W * rs.share[v];
                if (!chained[p] || ahead <= 0 || R <= most)
                    continue;
                skip[p] = 1;
                if (rest_on(at, q, skip, n, a, fwd, xf, hc, origin, &without)) {
                    double rise = q[p] - height_on(&without, origin, at[p]);
                    if (rise > travel_m && chain_k_N_m_per_rad / (ahead * ahead) * rise < R)
                        fold = p, most = R;
                }
                skip[p] = 0;
            }
            if (fold < 0)
                break;
            skip[fold] = 1;
            held = rest_on(at, q, skip, n, a, fwd, xf, hc, origin, &rs);
        }
        /* the rest (rs.plane: its value at (x0, y0), slope along x and y; NAN, 0, 0 when none holds) */
        const double *plane = rs.plane;
        point com = rs.com;
        out->over = !isnan(plane[0]);
        /* the foot's tilt: its lean towards the centre of mass's side, and sideways */
        out->tilt_forward_rad = -atan(plane[1] * fwd.x + plane[2] * fwd.y);
        out->tilt_side_rad = atan(-plane[1] * fwd.y + plane[2] * fwd.x);
        point p[MAX_POINTS], h[2 * MAX_POINTS];
        int np = 0;
        for (int i = 0; out->over && i < n; i++)
            if (height_on(&rs, origin, at[i]) - q[i] <= travel_m) {
                p[np++] = at[i];
                out->toes_bearing += toe[i];
                out->heel_bearing |= heel[i];
            }
        out->bearing = np;
        double mean = 0;
        for (int i = 0; i < np; i++)
            mean += (c * (p[i].x - a.x) + sn * (p[i].y - a.y)) / np;
        for (int i = 0; i < np; i++) {
            double d = c * (p[i].x - a.x) + sn * (p[i].y - a.y) - mean;
            out->spread_m2 += d * d;
        }
        for (int i = 0, t = 0; out->over && i < n; i++)
            if (toe[i] && t < FS_MAX_FEET * FS_CHAINS) {
                double gap = height_on(&rs, origin, at[i]) - q[i] - travel_m;
                out->toe_gap_m[t] = fmax(0, gap);
                out->toe_ahead_m[t++] = c * (at[i].x - a.x) + sn * (at[i].y - a.y);
            }
        int nh = hull(p, np, h);
        /* the edge: where the line from the ankle through the centre of mass leaves the polygon */
        double along = (com.x - a.x) * fwd.x + (com.y - a.y) * fwd.y, dir = along >= 0 ? 1 : -1;
        point f = {dir * fwd.x, dir * fwd.y};
        out->edge_m = NAN;
        for (int i = 0; i < nh && out->over; i++) {
            point u = h[i], v = h[(i + 1) % nh];
            double ex = v.x - u.x, ey = v.y - u.y, den = f.x * ey - f.y * ex;
            if (fabs(den) < 1e-15)
                continue;
            double t = ((u.x - a.x) * ey - (u.y - a.y) * ex) / den, w = ((u.x - a.x) * f.y - (u.y - a.y) * f.x) / den;
            if (w >= 0 && w <= 1 && !(t <= out->edge_m))
                out->edge_m = t;
        }
        out->over = out->over && nh >= 3 && !isnan(out->edge_m);
        /* the nearest side of the polygon from the centre of mass, and how far the foot's base under
           the centre of mass sank while it rocked from its first contact (lowered flat until one
           shape touched: the highest of the points) onto its rest */
        out->side_m = INFINITY;
        for (int i = 0; i < nh && out->over; i++) {
            point u = h[i], v = h[(i + 1) % nh];
            out->side_m = fmin(out->side_m, cross(u, v, com) / hypot(v.x - u.x, v.y - u.y));
        }
        out->over = out->over && out->side_m > 0; /* moved by the tilt past the bearing points: it tips off */
        double first = -INFINITY;
        int ifirst = 0;
        for (int i = 0; i < n; i++) /* a shape whose chain folded away touches first, and folds: no rock about it */
            if (!skip[i] && q[i] > first)
                first = q[i], ifirst = i;
        /* the rocking's geometry in the foot's frame, from the centre of mass's ground point */
        out->first_x_m = c * (at[ifirst].x - com.x) + sn * (at[ifirst].y - com.y);
        out->first_y_m = -sn * (at[ifirst].x - com.x) + c * (at[ifirst].y - com.y);
        if (out->over) {
            /* the plane z = ... + b . (x, y) is the level one turned about the horizontal (b_y, -b_x) */
            out->rock_axis_x = c * plane[2] - sn * plane[1];
            out->rock_axis_y = -sn * plane[2] - c * plane[1];
            for (int i = 0; i < nh && out->ncorners < FS_SUPPORT_MAX_CORNERS; i++, out->ncorners++) {
                out->corner_x_m[out->ncorners] = c * (h[i].x - com.x) + sn * (h[i].y - com.y);
                out->corner_y_m[out->ncorners] = -sn * (h[i].x - com.x) + c * (h[i].y - com.y);
            }
        }
        out->settle_m = out->over ? first - height_on(&rs, origin, com) : NAN;
        double ex = a.x + out->edge_m * f.x, ey = a.y + out->edge_m * f.y;
        out->ankle_height_m = out->over ? ankle.z + plane[1] * (a.x - ex) + plane[2] * (a.y - ey) : NAN;
    }
    fs_trial_placed_free(sc);
    return s;
}
