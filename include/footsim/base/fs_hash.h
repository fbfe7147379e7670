/* fs_hash.h: the 64-bit FNV-1a hash footsim names its inputs and states by (provenance, the
 * configuration's settings, the determinism hashes). Not cryptographic: it tells files and states
 * apart, it does not defend against forgery. */
#ifndef FS_HASH_H
#define FS_HASH_H

#include <stddef.h>

/* FNV-1a over n bytes, continuing from h (start with FS_HASH_START). */
#define FS_HASH_START 0xcbf29ce484222325ULL
unsigned long long fs_hash_bytes(unsigned long long h, const void *data, size_t n);

#endif
