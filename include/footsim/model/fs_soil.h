/* fs_soil.h: a deformable soil layer laid over a terrain (the terrain becomes its bedrock), as data
 * and as the laws that give its stresses. The state that changes during a run (the grid of soil
 * nodes and their prints) lives in the simulation (fs_sim_soil.h), never here: a campaign shares
 * one terrain per cell.
 *
 * Two models (docs/soil.md):
 * - bekker: Bekker-Wong pressure-sinkage sigma = (k_c / b + k_phi) z^n on loading, a line of slope
 *   K_e on unloading and reloading, Janosi-Hanamoto shear tau = (c + sigma tan phi)(1 - e^(-j/K))
 *   with the slip j accumulated per node, as in Project Chrono's SCM;
 * - rft: resistive force theory for granular media (Li, Zhang & Goldman, Science 2013): the
 *   stress on a surface element at depth |z| is zeta * alpha_{z,x}(beta, gamma) |z| with nine
 *   generic Fourier coefficients, plus an inertial pressure lambda rho (v.n)^2 (dynamic RFT).
 *
 * The keys are rows of the terrain schema (fs_terrain_keys, docs/keys.md; phi in [0, 90) degrees);
 * fs_soil_check judges what one key cannot (RFT without zeta or density, a model's section without
 * [soil] or the other way round, Bekker moduli with k_c/b_min + k_phi <= 0: no bearing strength),
 * before anything runs, with file:line. */
#ifndef FS_SOIL_H
#define FS_SOIL_H

#include "footsim/io/fs_config.h"

typedef enum fs_soil_model { FS_SOIL_NONE = 0, FS_SOIL_BEKKER = 1, FS_SOIL_RFT = 2 } fs_soil_model;

/* RFT's nine generic coefficients, in this order: A00, A10, B11, B01, B-11, C11, C01, C-11, D10. */
enum { FS_RFT_COEFFS = 9 };

typedef struct fs_soil_def {
    int model;                   /* fs_soil_model */
    double depth_m;              /* the layer's thickness over the bedrock */
    double grid_m;               /* node spacing */
    double coarse_grid_m;        /* the widest spacing a shape may be met on (the flat sole's); 0: grid_m */
    int nodes_across;            /* a shape's spacing leaves at least this many nodes across its narrowest side */
    double margin_m;             /* the grid covers the region the feet can reach plus this */
    double x_min_m, x_max_m;     /* the layer lies over x_min_m <= x <= x_max_m only (a section of the path; by
                                  * default +-1000 m, everywhere): beyond it the ground is the bedrock, rigid */
    double b_min_m;              /* Bekker's b is never taken below this (a patch as it first forms) */
    double slip_speed_m_per_s;   /* shear and drag reach full strength above this slip speed */
    int max_nodes;               /* the grid may hold at most this many nodes (memory cap) */
    /* [bekker] */
    double n;                    /* sinkage exponent */
    double k_c_N_per_m_n1;       /* cohesive modulus, N/m^(n+1) */
    double k_phi_N_per_m_n2;     /* frictional modulus, N/m^(n+2) */
    double cohesion_Pa;
    double friction_deg;         /* internal friction angle phi */
    double shear_K_m;            /* Janosi's shear deformation modulus */
    double K_e_Pa_per_m;         /* elastic unloading and reloading slope */
    double damping_Pa_s_per_m;   /* pressure per sinking speed */
    /* [rft] */
    double rft_coeff[FS_RFT_COEFFS]; /* dimensionless: alpha_z(0, pi/2) = 1 with the generic set */
    double zeta_N_per_m3;        /* the medium's scale: alpha = zeta * the generic fit */
    double density_kg_per_m3;
    double inertial_lambda;      /* the inertial pressure is lambda rho (v.n)^2 */
    double friction_mu;          /* intruder-grain friction on the inertial pressure */
} fs_soil_def;

/* Refuses (FS_BAD_INPUT, "where: what is wrong, and what would be right") what no single key can
 * judge: a [bekker] or [rft] section in a file without a [soil] section (it would be ignored), a
 * section whose x_max_m is not above its x_min_m (an empty soil), a
 * bekker soil without a [bekker] section (the keys' defaults are no soil), an RFT soil without
 * zeta_N_per_m3 or density_kg_per_m3 (pointing at the [rft] header or at [soil] model when the key
 * is absent). cfg (may be NULL: "set in code"; the checks on sections are then skipped) locates the
 * keys. */
fs_status fs_soil_check(const fs_soil_def *d, const fs_config *cfg, const char *path, fs_error *err);

/* The rectangle the grid covers (the region the feet can reach, box, plus margin_m) and the nodes
 * it has; FS_BAD_INPUT when they pass max_nodes (naming the grid, the region and the cap), the
 * message starting with path: where grid_m came from (fs_terrain.soil_grid_at, "FILE:LINE"), or
 * the file. */
fs_status fs_soil_region(const fs_soil_def *d, const double box[4], const char *path, double region[4], double *nodes,
                         fs_error *err);

/* The section and the run's ground: FS_BAD_INPUT, the message starting with where (where [soil] x_min_m
 * came from), when the section [x_min_m, x_max_m] misses the rectangle the soil's grid covers (region,
 * fs_soil_region: no foot would meet the soil) or, extent not NULL (a heightmap's image, x0, x1, y0, y1),
 * the terrain's data. */
fs_status fs_soil_section_check(const fs_soil_def *d, const double region[4], const double *extent, const char *where,
                                fs_error *err);

/* The layer's depth under the plan interval [x0_m, x1_m]: depth_m when it meets the section
 * [x_min_m, x_max_m] (everywhere by default), else 0 (the bedrock is the surface there). */
double fs_soil_depth_over(const fs_soil_def *d, double x0_m, double x1_m);

/* ---- the laws ---------------------------------------------------------------------------------- */

/* Bekker's pressure at sinkage z >= 0 under a patch of width b: (k_c / b + k_phi) z^n, Pa. */
double fs_bekker_pressure(const fs_soil_def *d, double b_m, double z_m);
/* The sinkage at which a patch of width b carries pressure p: (p / (k_c / b + k_phi))^(1/n), m. */
double fs_bekker_sinkage(const fs_soil_def *d, double b_m, double p_Pa);
/* Janosi-Hanamoto: the shear strength c + sigma tan(phi), Pa, and the share of it mobilised after
 * a slip j, 1 - e^(-j/K). */
double fs_soil_shear_strength(const fs_soil_def *d, double sigma_Pa);
double fs_janosi_share(const fs_soil_def *d, double j_m);
/* RFT: the generic alpha_z and alpha_x (dimensionless; times zeta gives N/m^3) at tilt beta and
 * direction of motion gamma, rad (gamma = pi/2: straight down; beta = 0: a horizontal plate). */
void fs_rft_alpha(const fs_soil_def *d, double beta, double gamma, double *alpha_z, double *alpha_x);

#endif
