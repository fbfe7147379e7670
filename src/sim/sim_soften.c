/* sim_soften.c: the softness (ERP, CFM) of the contacts and of the hinges' angular springs for a
 * step of h, from their k and c (fs_spring_soft): set when the sim is built and again whenever the
 * step changes (substeps, the error-controlled step). */
#include "sim_internal.h"

/* The contact template's softness for a step of h, from the sole's and terrain's k and c in series. */
void fs_sim_soften_contacts(fs_sim *sim, double h)
{
    double erp, cfm;
    fs_spring_soft(h, sim->contact_k_N_per_m, sim->contact_c_Ns_per_m, sim->sc->def.damping_correction, &erp, &cfm);
    sim->contact_template.surface.soft_erp = erp;
    sim->contact_template.surface.soft_cfm = cfm;
}

/* A hinge stop's ERP and CFM from k and c for a step of h. */
void fs_sim_soften_stop(const fs_sim *sim, dJointID j, double k, double c, double h)
{
    double erp, cfm;
    fs_spring_soft(h, k, c, sim->sc->def.damping_correction, &erp, &cfm);
    dJointSetHingeParam(j, dParamStopERP, erp);
    dJointSetHingeParam(j, dParamStopCFM, cfm);
}

int fs_hinge_has_spring(const fs_hinge_geom *h) { return h->k_N_m_per_rad > 0 || h->c_N_m_s_per_rad > 0; }

void fs_sim_set_step(fs_sim *sim, double h)
{
    if (h == sim->step_now_s)
        return;
    fs_sim_soften_contacts(sim, h);
    for (int i = 0; i < sim->geom->nhinges; i++) {
        const fs_hinge_geom *g = &sim->geom->hinge[i];
        if (fs_hinge_has_spring(g))
            fs_sim_soften_stop(sim, sim->hinge[i], g->k_N_m_per_rad, g->c_N_m_s_per_rad, h);
    }
    sim->step_now_s = h;
}
