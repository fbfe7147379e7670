/* model_soil.c: a soil's relations between keys, the region its grid covers, and its laws. */
#include "footsim/model/fs_soil.h"

#include <math.h>
#include <stdio.h>

/* Where to point at a key an rft soil must give: its own line when given (with a value of 0),
 * else the [rft] header, else [soil] model's line; *absent says which. */
static const char *where_rft_key(const fs_config *cfg, const char *name, char *buf, size_t size, int *absent)
{
    *absent = cfg && !fs_config_has(cfg, "rft", name);
    if (*absent && fs_config_where_section(cfg, "rft", buf, size))
        return buf;
    return fs_config_where(cfg, *absent ? "soil" : "rft", *absent ? "model" : name, buf, size);
}

fs_status fs_soil_check(const fs_soil_def *d, const fs_config *cfg, const char *path, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    static const char *const model_section[] = {"bekker", "rft"};
    for (int i = 0; cfg && i < 2 && !fs_config_has(cfg, "soil", NULL); i++)
        if (fs_config_where_section(cfg, model_section[i], where, sizeof where))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] has no effect without a [soil] section (the ground stays "
                           "rigid); add [soil] with model = %s and depth_m = the layer's thickness, or remove [%s]",
                           where, model_section[i], model_section[i], model_section[i]);
    if (d->model == FS_SOIL_NONE)
        return FS_OK;
    if (d->model == FS_SOIL_BEKKER && cfg && !fs_config_has(cfg, "bekker", NULL))
        return fs_fail(err, FS_BAD_INPUT, "%s: a bekker soil needs a [bekker] section with the soil's moduli (n, "
                       "k_c_N_per_m_n1, k_phi_N_per_m_n2, cohesion_Pa, friction_deg, shear_K_m, K_e_Pa_per_m); the "
                       "keys' defaults are no measured soil: start from a preset in terrains/soils/ (dry_sand, "
                       "lete_sand, sandy_loam, lean_clay, snow, mud)",
                       fs_config_where(cfg, "soil", "model", where, sizeof where));
    /* Bekker's pressure (k_c/b + k_phi) z^n must rise with the sinkage for every patch width b the grid
     * can give: b = 2 A / P, finite, and at least [soil] b_min_m (sim_soil_grid.c). k_c/b + k_phi is
     * monotonic in b: with k_c >= 0 it falls towards k_phi but stays above it for every finite b, so it
     * is positive for all of them when k_c/b_min + k_phi is (k_c > 0 or k_phi > 0); with k_c < 0 it is
     * least at b_min. Either way k_c/b_min + k_phi > 0 is the condition. The keys' ranges keep both
     * moduli >= 0, so what this refuses is both 0: a soil with no bearing strength, through which the
     * foot falls to the bedrock, almost surely a slip. */
    if (d->model == FS_SOIL_BEKKER && !(d->k_c_N_per_m_n1 / d->b_min_m + d->k_phi_N_per_m_n2 > 0))
        return fs_fail(err, FS_BAD_INPUT, "%s: a bekker soil with k_c_N_per_m_n1 = %g and k_phi_N_per_m_n2 = %g "
                       "bears no load: Bekker's pressure (k_c/b + k_phi) z^n is not above 0 for every patch width b "
                       "from [soil] b_min_m = %g m up, and the foot would fall through to the bedrock; give "
                       "k_phi_N_per_m_n2 > 0 or k_c_N_per_m_n1 > 0 (the soil's moduli from a plate test: "
                       "terrains/soils/ has measured soils, dry_sand's are 990 and 1528430)",
                       fs_config_where(cfg, "bekker", "k_phi_N_per_m_n2", where, sizeof where), d->k_c_N_per_m_n1,
                       d->k_phi_N_per_m_n2, d->b_min_m);
    if (!(d->x_max_m > d->x_min_m))
        return fs_fail(err, FS_BAD_INPUT, "%s: the soil's section is empty: x_max_m = %g m is not above x_min_m = %g m; "
                       "make x_max_m the end of the soil along x, past x_min_m (leave both out for a soil everywhere)",
                       fs_config_where(cfg, "soil", "x_max_m", where, sizeof where), d->x_max_m, d->x_min_m);
    int absent = 0;
    if (d->model == FS_SOIL_RFT && !(d->zeta_N_per_m3 > 0)) {
        where_rft_key(cfg, "zeta_N_per_m3", where, sizeof where, &absent);
        return fs_fail(err, FS_BAD_INPUT, "%s: an rft soil needs [rft] zeta_N_per_m3 > 0, the medium's scale from one "
                       "plate test (about 1e6 N/m^3 for dry sand or glass beads; terrains/soils/ has presets)%s",
                       where, absent ? ": add zeta_N_per_m3 = ... to [rft]" : "");
    }
    if (d->model == FS_SOIL_RFT && !(d->density_kg_per_m3 > 0)) {
        where_rft_key(cfg, "density_kg_per_m3", where, sizeof where, &absent);
        return fs_fail(err, FS_BAD_INPUT, "%s: an rft soil needs [rft] density_kg_per_m3 > 0, the medium's bulk density "
                       "(about 1500-1700 kg/m^3 for dry sand)%s", where,
                       absent ? ": add density_kg_per_m3 = ... to [rft]" : "");
    }
    (void)path;
    return FS_OK;
}

fs_status fs_soil_region(const fs_soil_def *d, const double box[4], const char *path, double region[4], double *nodes,
                         fs_error *err)
{
    double m = d->margin_m;
    region[0] = box[0] - m, region[1] = box[1] + m, region[2] = box[2] - m, region[3] = box[3] + m;
    double n = (floor((region[1] - region[0]) / d->grid_m) + 2) * (floor((region[3] - region[2]) / d->grid_m) + 2);
    if (nodes)
        *nodes = n;
    if (!(n <= d->max_nodes))
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: the soil's grid_m of %.3g m over the region the feet reach (%.3g x %.3g m with its margin) "
                       "would have %.4g nodes, over [soil] max_nodes = %d; use a coarser grid_m, a smaller margin_m, "
                       "or raise max_nodes", path, d->grid_m, region[1] - region[0], region[3] - region[2], n,
                       d->max_nodes);
    return FS_OK;
}

fs_status fs_soil_section_check(const fs_soil_def *d, const double region[4], const double *extent, const char *where,
                                fs_error *err)
{
    if (d->x_max_m < region[0] || d->x_min_m > region[1])
        return fs_fail(err, FS_BAD_INPUT, "%s: the soil's section, x %g..%g m, lies outside the ground the run covers (x "
                       "%.4g..%.4g m: the region the feet can reach, with [soil] margin_m): no foot would meet the "
                       "soil; put x_min_m and x_max_m across the feet's path", where, d->x_min_m, d->x_max_m,
                       region[0], region[1]);
    if (extent && (d->x_max_m < extent[0] || d->x_min_m > extent[1]))
        return fs_fail(err, FS_BAD_INPUT, "%s: the soil's section, x %g..%g m, lies outside the heightmap (x %.4g..%.4g "
                       "m): its bedrock would be the image's edge drawn out; put the section over the image", where,
                       d->x_min_m, d->x_max_m, extent[0], extent[1]);
    return FS_OK;
}

double fs_soil_depth_over(const fs_soil_def *d, double x0_m, double x1_m)
{
    return x1_m >= d->x_min_m && x0_m <= d->x_max_m ? d->depth_m : 0;
}

double fs_bekker_pressure(const fs_soil_def *d, double b_m, double z_m)
{
    return (d->k_c_N_per_m_n1 / b_m + d->k_phi_N_per_m_n2) * pow(fmax(z_m, 0), d->n);
}

double fs_bekker_sinkage(const fs_soil_def *d, double b_m, double p_Pa)
{
    return pow(fmax(p_Pa, 0) / (d->k_c_N_per_m_n1 / b_m + d->k_phi_N_per_m_n2), 1 / d->n);
}

double fs_soil_shear_strength(const fs_soil_def *d, double sigma_Pa)
{
    return d->cohesion_Pa + fmax(sigma_Pa, 0) * tan(d->friction_deg * M_PI / 180);
}

double fs_janosi_share(const fs_soil_def *d, double j_m) { return 1 - exp(-fabs(j_m) / d->shear_K_m); }

void fs_rft_alpha(const fs_soil_def *d, double beta, double gamma, double *alpha_z, double *alpha_x)
{
    /* sum over m in {-1, 0, 1}, n in {0, 1} of A cos(2 m beta + n gamma) + B sin(...) (alpha_z) and
     * C cos + D sin (alpha_x); the generic fit keeps nine of the terms */
    const double *k = d->rft_coeff;
    double a = 2 * beta, g = gamma;
    *alpha_z = k[0] + k[1] * cos(a) + k[2] * sin(a + g) + k[3] * sin(g) + k[4] * sin(g - a);
    *alpha_x = k[5] * cos(a + g) + k[6] * cos(g) + k[7] * cos(g - a) + k[8] * sin(a);
}
