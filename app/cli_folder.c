/* cli_folder.c: a trial's or a walk's results in a folder of their own (cli.h: cli_in_folder): the run
 * with its frames, then its JSON (the library's, fs_report.h) and files beside, put in place whole. */
#include "cli.h"

#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/io/fs_provenance.h"

#include <cjson/cJSON.h>
#include <stdio.h>

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

static int fill_json(FILE *f, const void *user) { return fs_json_print(f, user); }


/* cli_in_folder: out: the caller's results folder (on the heap with the rest of its work), aborted here when it
 * was not committed. */
int cli_in_folder(const cli_args *a, const cli_folder_job *j, fs_outdir *out, char *dir_out, size_t size)
{
    fs_error err;
    if (fs_outdir_open(out, j->dir, a->replace, "--out", &err) != FS_OK)
        return fail(&err);
    cli_frames *frames = NULL;
    fs_run_observer observer, *obs = NULL;
    int s = 0;
    char label[128] = "";
    if (a->frames && !(s = cli_frames_open(a, j->framed, out->partial, &frames, &observer)))
        obs = &observer;
    if (frames && j->frame_label) {
        j->frame_label(j->user, j->result, 0, label, sizeof label);
        cli_frames_label(frames, label);
    }
    fs_status rs = s ? FS_OK : j->run(j->user, obs, &err);
    int fstatus = 0;
    if (frames && j->frame_label && rs == FS_OK) {
        j->frame_label(j->user, j->result, 1, label, sizeof label);
        fstatus = cli_frames_finish(frames, label);
    }
    if (frames) {
        int closed = cli_frames_close(frames, rs == FS_OK && !fstatus, out->path);
        fstatus = fstatus ? fstatus : closed;
    }
    if (!s && rs == FS_OK && !fstatus) {
        cJSON *o = j->to_json(j->result, &err);
        rs = o ? FS_OK : err.status;
        if (o && j->provenance && !fs_json_put(o, "provenance", fs_provenance_json(j->provenance)))
            rs = fs_fail(&err, FS_NO_MEMORY, "out of memory for %s's provenance", j->name);
        if (rs == FS_OK)
            rs = fs_write_in(out->partial, j->name, fill_json, o, &err);
        cJSON_Delete(o);
        if (rs == FS_OK && j->write_more)
            rs = j->write_more(j->user, out->partial, &err);
        if (rs == FS_OK)
            rs = fs_outdir_commit(out, &err);
    }
    fs_outdir_abort(out);
    if (!s && rs != FS_OK)
        s = fail(&err);
    snprintf(dir_out, size, "%s", out->path);
    return s ? s : fstatus;
}

