/* fuzz_file.h: the fuzzers' one helper: an input written to a temporary file, since footsim's
 * parsers read files. */
#ifndef FUZZ_FILE_H
#define FUZZ_FILE_H

#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

/* Writes data to /tmp/footsim-fuzz-<pid><ext> and puts the path in path; 0 if it cannot. */
static int fuzz_write_temp(const uint8_t *data, size_t size, const char *ext, char *path, size_t n)
{
    snprintf(path, n, "/tmp/footsim-fuzz-%ld%s", (long)getpid(), ext);
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    return 1;
}

#endif
