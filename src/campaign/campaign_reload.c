/* campaign_reload.c: what a campaign's chart needs, read back from its summary.json, so that the
 * chart can be drawn again without running a trial (footsim plot CAMPAIGN_DIR). */
#include "campaign_internal.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The index of name among items[0..*n), appended when new; -1 when there is no room. */
static int item_index(fs_campaign_item *items, int *n, int max, const char *name)
{
    for (int i = 0; i < *n; i++)
        if (!strcmp(items[i].name, name))
            return i;
    if (*n == max)
        return -1;
    memset(&items[*n], 0, sizeof items[*n]);
    snprintf(items[*n].name, sizeof items[*n].name, "%s", name);
    return (*n)++;
}

/* The sweep's shape from the terrains' names ("BASE@v1[,v2]") and values: nbase, nvalues, and each
 * point's base and indices, in the order campaign_file.c makes them. 0 when they do not fit it. */
static int sweep_shape(fs_campaign *c)
{
    int n = c->nterrains, nbase = 0, first_of_next = n;
    char base[FS_NAME_MAX] = "";
    for (int t = 0; t < n; t++) {
        char name[FS_NAME_MAX];
        snprintf(name, sizeof name, "%.*s", (int)strcspn(c->terrain[t].name, "@"), c->terrain[t].name);
        if (!t || strcmp(name, base)) {
            if (nbase == 1)
                first_of_next = t;
            snprintf(base, sizeof base, "%s", name);
            nbase++;
        }
    }
    int per_base = first_of_next, nv1 = 1;
    if (c->nsweep == 2)
        while (nv1 < per_base && c->terrain[nv1].sweep_value[0] == c->terrain[0].sweep_value[0])
            nv1++;
    if (nbase < 1 || per_base % nv1 || per_base * nbase != n)
        return 0;
    c->nbase = nbase, c->nvalues[0] = per_base / nv1, c->nvalues[1] = nv1;
    for (int t = 0; t < n; t++) {
        fs_campaign_item *p = &c->terrain[t];
        p->base = t / per_base, p->point[0] = t % per_base / nv1, p->point[1] = t % nv1;
        /* every base terrain has the same points, in the same order */
        const fs_campaign_item *q0 = &c->terrain[p->point[0] * nv1], *q1 = &c->terrain[p->point[1]];
        if (p->sweep_value[0] != q0->sweep_value[0] || (c->nsweep == 2 && p->sweep_value[1] != q1->sweep_value[1]))
            return 0;
    }
    return 1;
}

fs_status fs_campaign_reload(const char *path, fs_campaign *c, fs_campaign_row *rows, fs_error *err)
{
    memset(c, 0, sizeof *c);
    cJSON *root = fs_campaign_read_summary(path, err);
    if (!root)
        return FS_BAD_INPUT;
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(root, "rows");
    int nrows = cJSON_GetArraySize(list), ok = nrows > 0;
    snprintf(c->path, sizeof c->path, "%s", path);
    snprintf(c->name, sizeof c->name, "%s", text_of(root, "campaign"));
    c->seeds = (int)number_of(root, "seeds");
    c->first_seed = (int)number_of(root, "first_seed");
    static const char *const sweep_keys[2] = {"sweep", "sweep2"};
    for (int w = 0; w < 2; w++)
        if (cJSON_IsString(cJSON_GetObjectItemCaseSensitive(root, sweep_keys[w])))
            snprintf(c->sweep[c->nsweep++], sizeof c->sweep[0], "%s", text_of(root, sweep_keys[w]));
    /* a band's name and ends (its rows' each end's rate is drawn beside the band's) */
    const cJSON *band = cJSON_GetObjectItemCaseSensitive(root, "band"), *r;
    if (cJSON_IsObject(band)) {
        snprintf(c->band, sizeof c->band, "%s", text_of(band, "name"));
        cJSON_ArrayForEach(r, cJSON_GetObjectItemCaseSensitive(band, "ends"))
            if (c->nends < FS_BAND_ENDS)
                snprintf(c->end[c->nends++].name, sizeof c->end[0].name, "%s", text_of(r, "name"));
        ok = ok && c->nends == FS_BAND_ENDS;
    }
    /* first the names, in the order the rows give them (cell order: foot, terrain, robot) */
    cJSON_ArrayForEach(r, list)
    {
        int t = item_index(c->terrain, &c->nterrains, FS_CAMPAIGN_MAX_TERRAINS, text_of(r, "terrain"));
        ok = ok && item_index(c->foot, &c->nfeet, FS_CAMPAIGN_MAX_FEET, text_of(r, "foot")) >= 0 && t >= 0 &&
             item_index(c->robot, &c->nrobots, FS_CAMPAIGN_MAX_ROBOTS, text_of(r, "robot")) >= 0;
        for (int w = 0; ok && w < c->nsweep; w++)
            c->terrain[t].sweep_value[w] = number_of(r, w ? "sweep_value2" : "sweep_value");
    }
    ok = ok && nrows == fs_campaign_ncells(c) && (!c->nsweep || sweep_shape(c));
    /* then each row where its cell says */
    int cell = 0;
    cJSON_ArrayForEach(r, list)
    {
        if (!ok)
            break;
        fs_campaign_row *row = &rows[cell];
        memset(row, 0, sizeof *row);
        fs_campaign_cell_of(c, cell++, &row->foot, &row->terrain, &row->robot);
        ok = !strcmp(c->foot[row->foot].name, text_of(r, "foot")) &&
             !strcmp(c->terrain[row->terrain].name, text_of(r, "terrain")) &&
             !strcmp(c->robot[row->robot].name, text_of(r, "robot"));
        row->trials = (int)number_of(r, "trials");
        row->landed = (int)number_of(r, "landed");
        row->success_rate = number_of(r, "success_rate");
        row->ci_low = number_of(r, "ci_low");
        row->ci_high = number_of(r, "ci_high");
        const char *law = text_of(r, "law_prediction");
        row->law = !strcmp(law, "stands") ? FS_LAW_STANDS : !strcmp(law, "topples") ? FS_LAW_TOPPLES : FS_LAW_NONE;
        row->law_K = number_of(r, "law_K_N_m_per_rad");
        row->law_critical_m = number_of(r, "law_critical_com_height_m");
        const char *drop = text_of(r, "drop_law_prediction");
        row->drop_law = !strcmp(drop, "stands") ? FS_LAW_STANDS : !strcmp(drop, "topples") ? FS_LAW_TOPPLES : FS_LAW_NONE;
        row->drop_critical_m = number_of(r, "drop_law_critical_com_height_m");
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            row->median[m] = NAN;
        row->band_end = -1;
        row->law_end = -1; /* the laws by end are not read back */
        for (int e = 0; c->band[0] && e < FS_BAND_ENDS; e++) {
            char key[32];
            snprintf(key, sizeof key, "landed_%s", c->end[e].name);
            row->end_landed[e] = (int)number_of(r, key);
            row->end_trials[e] = row->trials;
            snprintf(key, sizeof key, "success_rate_%s", c->end[e].name);
            row->end_rate[e] = number_of(r, key);
            row->band_end = !strcmp(text_of(r, "band_end"), c->end[e].name) ? e : row->band_end;
            ok = ok && row->end_rate[e] >= 0 && row->end_rate[e] <= 1;
        }
        ok = ok && (!c->band[0] || row->band_end >= 0) && row->success_rate >= 0 && row->success_rate <= 1 && row->ci_low <= row->ci_high;
    }
    cJSON_Delete(root);
    if (!ok || c->seeds < 1)
        return fs_fail(err, FS_BAD_INPUT, "%s: its rows are not a campaign's cells (every foot on every terrain "
                       "under every robot, in order, each with a success rate and its interval); give a "
                       "summary.json written by footsim campaign", path);
    return FS_OK;
}

char *fs_campaign_summary_provenance(const char *path)
{
    fs_error err;
    cJSON *root = fs_campaign_read_summary(path, &err);
    fs_provenance p;
    char *text = NULL;
    size_t len = 0;
    if (root && fs_provenance_from_json(cJSON_GetObjectItemCaseSensitive(root, "provenance"), &p, &err) == FS_OK) {
        FILE *f = open_memstream(&text, &len);
        if (f) {
            fs_provenance_line(&p, f);
            if (fclose(f) != 0)
                free(text), text = NULL;
        }
        if (text && len && text[len - 1] == '\n')
            text[len - 1] = 0;
    }
    if (root)
        fs_provenance_free(&p);
    cJSON_Delete(root);
    return text;
}
