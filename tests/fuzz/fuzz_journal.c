/* libFuzzer target: campaign journals (issue 33), read as a resume reads them (the damaged end
 * reported in a tail) and as merge reads them (refused): any input must be refused or read
 * cleanly, no crash, leak or undefined behaviour, and a tail must stay within the file. */
#include "footsim/campaign/fs_campaign.h"

#include "fuzz_file.h"

#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[128];
    if (!fuzz_write_temp(data, size, ".journal", path, sizeof path))
        return 0;
    for (int with_tail = 0; with_tail < 2; with_tail++) {
        fs_journal_head h;
        fs_trial_result *results;
        unsigned char *done;
        int ndone;
        fs_journal_tail tail;
        fs_error err;
        fs_status s = fs_journal_read(path, &h, &results, &done, &ndone, with_tail ? &tail : NULL, &err);
        fuzz_said(s, &err);
        if (s != FS_OK)
            continue;
        if (with_tail && (tail.good_bytes < 0 || tail.good_bytes > (long long)size))
            abort(); /* a resume would cut the file to a length it does not have */
        free(results);
        free(done);
        fs_journal_head_free(&h);
    }
    unlink(path);
    return 0;
}
