/* SPDX-License-Identifier: MIT */
/*
 * wide.h - the tests' own two's complement integers of WIDE_LIMBS 32-bit
 * limbs, least significant first, written apart from the library's
 * src/multiword.h so that exact results are checked with other code.
 * A test file defines WIDE_LIMBS before including this header, for the
 * width its values need (8: 256 bits, test_predicates.c; 64: 2048 bits,
 * test_centroid.c and test_clip.c; 128: 4096 bits, test_interpolate.c).
 * Every operation is exact while its result fits;
 * r may be one of the operands. Temporaries are static (test files run
 * on one thread), to keep the targets' stacks small.
 */
#ifndef VOR_TEST_WIDE_H
#define VOR_TEST_WIDE_H

#include <stdbool.h>
#include <stdint.h>

#ifndef WIDE_LIMBS
#error "define WIDE_LIMBS (32-bit limbs of a wide_t) before including wide.h"
#endif

typedef struct {
    uint32_t v[WIDE_LIMBS];
} wide_t;

static inline void wide_set(wide_t *r, int64_t x)
{
    uint64_t u = (uint64_t)x;
    r->v[0] = (uint32_t)u;
    r->v[1] = (uint32_t)(u >> 32);
    for (unsigned i = 2; i < WIDE_LIMBS; i++) {
        r->v[i] = (x < 0) ? 0xFFFFFFFFu : 0u;
    }
}

/* r = the non-negative number of the n limbs w (the library's outputs). */
static inline void wide_words(wide_t *r, const uint32_t *w, uint32_t n)
{
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        r->v[i] = (i < n) ? w[i] : 0u;
    }
}

static inline void wide_add(wide_t *r, const wide_t *a)
{
    uint64_t carry = 0;
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        uint64_t s = (uint64_t)r->v[i] + a->v[i] + carry;
        r->v[i] = (uint32_t)s;
        carry = s >> 32;
    }
}

static inline void wide_neg(wide_t *r)
{
    uint64_t carry = 1;
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        uint64_t s = (uint64_t)(uint32_t)~r->v[i] + carry;
        r->v[i] = (uint32_t)s;
        carry = s >> 32;
    }
}

static inline void wide_sub(wide_t *r, const wide_t *a)
{
    static wide_t t;
    t = *a;
    wide_neg(&t);
    wide_add(r, &t);
}

/* r = a b, the low WIDE_LIMBS limbs. */
static inline void wide_mul(wide_t *r, const wide_t *a, const wide_t *b)
{
    static wide_t t;
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        t.v[i] = 0;
    }
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        uint64_t carry = 0;
        if (a->v[i] == 0u) {
            continue;
        }
        for (unsigned j = 0; (i + j) < WIDE_LIMBS; j++) {
            uint64_t p = ((uint64_t)a->v[i] * b->v[j]) + t.v[i + j] + carry;
            t.v[i + j] = (uint32_t)p;
            carry = p >> 32;
        }
    }
    *r = t;
}

static inline void wide_mul_i64(wide_t *r, const wide_t *a, int64_t k)
{
    static wide_t b;
    wide_set(&b, k);
    wide_mul(r, a, &b);
}

static inline bool wide_negative(const wide_t *a)
{
    return (a->v[WIDE_LIMBS - 1u] >> 31) != 0u;
}

/* Signed comparison: -1, 0 or 1. */
static inline int wide_compare(const wide_t *a, const wide_t *b)
{
    bool an = wide_negative(a), bn = wide_negative(b);
    if (an != bn) {
        return an ? -1 : 1;
    }
    for (unsigned i = WIDE_LIMBS; i-- > 0;) {
        if (a->v[i] != b->v[i]) {
            return (a->v[i] < b->v[i]) ? -1 : 1;
        }
    }
    return 0;
}

static inline bool wide_equal(const wide_t *a, const wide_t *b)
{
    return wide_compare(a, b) == 0;
}

static inline bool wide_zero(const wide_t *a)
{
    for (unsigned i = 0; i < WIDE_LIMBS; i++) {
        if (a->v[i] != 0u) {
            return false;
        }
    }
    return true;
}

#endif
