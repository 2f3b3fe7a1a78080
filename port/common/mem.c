/* SPDX-License-Identifier: MIT */
/*
 * port/common/mem.c - memcpy, memmove, memset, memcmp and strlen for
 * firmware linked with -nostdlib.
 *
 * GCC may emit calls to these even in freestanding code (structure copies,
 * zeroing loops, a loop that looks for a NUL), so firmware without a C
 * library needs them. They are weak: a C library or a faster
 * implementation linked in wins.
 * Byte loops, small and obviously correct; vor's hot paths do not use them.
 */
#include <stddef.h>

#if defined(__GNUC__) && !defined(__clang__)
/* Keep GCC from recognising the loops below as memset/memcpy and turning
 * them into calls to themselves. */
#define VOR_PORT_MEM_FN \
    __attribute__((weak, optimize("no-tree-loop-distribute-patterns")))
#elif defined(__GNUC__)
#define VOR_PORT_MEM_FN __attribute__((weak))
#else
#define VOR_PORT_MEM_FN
#endif

VOR_PORT_MEM_FN void *memcpy(void *dst, const void *src, size_t n);
VOR_PORT_MEM_FN void *memmove(void *dst, const void *src, size_t n);
VOR_PORT_MEM_FN void *memset(void *dst, int c, size_t n);
VOR_PORT_MEM_FN int memcmp(const void *a, const void *b, size_t n);
VOR_PORT_MEM_FN size_t strlen(const char *s);

VOR_PORT_MEM_FN void *memcpy(void *dst, const void *src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    while (n-- > 0u) {
        *d++ = *s++;
    }
    return dst;
}

VOR_PORT_MEM_FN void *memmove(void *dst, const void *src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    if (d < s) {
        while (n-- > 0u) {
            *d++ = *s++;
        }
    } else if (d > s) {
        while (n-- > 0u) {
            d[n] = s[n];
        }
    }
    return dst;
}

VOR_PORT_MEM_FN void *memset(void *dst, int c, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    while (n-- > 0u) {
        *d++ = (unsigned char)c;
    }
    return dst;
}

VOR_PORT_MEM_FN int memcmp(const void *a, const void *b, size_t n)
{
    const unsigned char *p = (const unsigned char *)a;
    const unsigned char *q = (const unsigned char *)b;
    for (; n > 0u; n--, p++, q++) {
        if (*p != *q) {
            return *p < *q ? -1 : 1;
        }
    }
    return 0;
}

VOR_PORT_MEM_FN size_t strlen(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0') {
        n++;
    }
    return n;
}
