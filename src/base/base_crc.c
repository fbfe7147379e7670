/* base_crc.c: CRC-32, bit by bit (fs_crc.h); journals are small, so no table is kept. */
#include "footsim/base/fs_crc.h"

uint32_t fs_crc32(uint32_t crc, const void *data, size_t n)
{
    const unsigned char *p = data;
    crc = ~crc;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}
