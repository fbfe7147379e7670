/* fs_crc.h: CRC-32 (the checksum of zlib, PNG and Ethernet: polynomial 0xEDB88320 reflected,
 * initial and final value 0xFFFFFFFF), for records that must be told apart from damaged ones.
 * fs_crc32(0, data, n) is the checksum of n bytes; fs_crc32(fs_crc32(0, a, n), b, m) that of a
 * then b. The check value of "123456789" is 0xCBF43926. */
#ifndef FS_CRC_H
#define FS_CRC_H

#include <stddef.h>
#include <stdint.h>

uint32_t fs_crc32(uint32_t crc, const void *data, size_t n);

#endif
