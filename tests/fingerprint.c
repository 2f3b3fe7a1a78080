/* SPDX-License-Identifier: MIT */
/*
 * fingerprint.c - an order-independent fingerprint of a set of triangles,
 * for the tests that compare two triangulations (test.h).
 */
#include "test.h"

static uint64_t mix(uint64_t x)
{
    x ^= x >> 31;
    x *= 0x7FB5D329728EA185ull;
    x ^= x >> 27;
    x *= 0x81DADEF4BC2DD44Dull;
    x ^= x >> 33;
    return x;
}

void test_fingerprint_add(test_fingerprint_t *f, const uint32_t ids[3])
{
    unsigned first = 0;
    for (unsigned i = 1; i < 3; i++) {
        first = (ids[i] < ids[first]) ? i : first;
    }
    uint64_t a = ids[first], b = ids[(first + 1) % 3], c = ids[(first + 2) % 3];
    uint64_t key = (a << 42) ^ (b << 21) ^ c;
    f->count++;
    f->sum1 += mix(key);
    f->sum2 += mix(key ^ 0x9E3779B97F4A7C15ull);
}

test_fingerprint_t test_fingerprint_of(const vor_t *d, const uint32_t *map)
{
    test_fingerprint_t f = {0, 0, 0};
    vor_triangle_iter_t it;
    uint32_t ids[3];
    vor_triangles_begin(&it, d);
    while (vor_triangles_next(&it, ids)) {
        if (map != NULL) {
            ids[0] = map[ids[0]];
            ids[1] = map[ids[1]];
            ids[2] = map[ids[2]];
        }
        test_fingerprint_add(&f, ids);
    }
    return f;
}

bool test_same_fingerprint(test_fingerprint_t a, test_fingerprint_t b)
{
    return a.count == b.count && a.sum1 == b.sum1 && a.sum2 == b.sum2;
}
