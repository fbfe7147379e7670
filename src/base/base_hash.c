/* base_hash.c: FNV-1a (fs_hash.h). */
#include "footsim/base/fs_hash.h"

unsigned long long fs_hash_bytes(unsigned long long h, const void *data, size_t n)
{
    const unsigned char *s = data;
    for (size_t i = 0; i < n; i++)
        h = (h ^ s[i]) * 0x100000001b3ULL;
    return h;
}
