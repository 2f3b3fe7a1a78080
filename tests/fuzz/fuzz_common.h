/* SPDX-License-Identifier: MIT */
/*
 * fuzz_common.h - shared by the libFuzzer harnesses of tests/fuzz/: a
 * reader that turns the fuzz bytes into values (zeros once they run out,
 * so every input is a complete program), coordinates drawn from the
 * patterns that break geometry code, and exact wide-integer arithmetic
 * written apart from the library's (src/multiword.h), so the harnesses are
 * an independent reference. Host-only, header-only.
 */
#ifndef VOR_FUZZ_COMMON_H
#define VOR_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "vor.h"

/* A finding: say what broke, then abort so libFuzzer keeps the input. */
#define FUZZ_REQUIRE(condition, what)                                          \
    do {                                                                       \
        if (!(condition)) {                                                    \
            fprintf(stderr, "fuzz finding: %s (%s:%d)\n", what, __FILE__,      \
                    __LINE__);                                                 \
            abort();                                                           \
        }                                                                      \
    } while (0)

typedef struct {
    const uint8_t *data;
    size_t size;
    size_t at;
} fuzz_reader_t;

static inline uint8_t fuzz_u8(fuzz_reader_t *r)
{
    return r->at < r->size ? r->data[r->at++] : 0u;
}

static inline int fuzz_done(const fuzz_reader_t *r)
{
    return r->at >= r->size;
}

static inline uint32_t fuzz_u32(fuzz_reader_t *r)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
        v = (v << 8) | fuzz_u8(r);
    return v;
}

static inline int32_t fuzz_i32(fuzz_reader_t *r)
{
    return (int32_t)fuzz_u32(r);
}

static inline int32_t fuzz_saturate(int64_t v)
{
    return v < INT32_MIN ? INT32_MIN : v > INT32_MAX ? INT32_MAX : (int32_t)v;
}

/* The values where int32 arithmetic overflows or a tier changes. */
static inline int32_t fuzz_corner(uint8_t b)
{
    static const int32_t corners[] = {INT32_MIN, INT32_MIN + 1, -1073741824, -65536,
                                      -1, 0, 1, 65536, 1073741823, INT32_MAX - 1,
                                      INT32_MAX};
    return corners[b % (sizeof corners / sizeof corners[0])];
}

/* A point in one of the patterns that matter, some relative to *previous
 * (updated): raw int32, int32 corners, near-duplicates, collinear runs,
 * cocircular sets (lattice points of radius 5 and 25 circles), tiny grids,
 * huge spacings. */
static inline vor_point_t fuzz_point(fuzz_reader_t *r, vor_point_t *previous)
{
    static const int8_t circle[][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4},
                                       {-4, 3}, {-5, 0},  {-4, -3}, {-3, -4}, {0, -5},
                                       {3, -4}, {4, -3}};
    uint8_t kind = fuzz_u8(r);
    vor_point_t p;
    switch (kind % 8u) {
    case 0:
        p.x = fuzz_i32(r);
        p.y = fuzz_i32(r);
        break;
    case 1:
        p.x = fuzz_corner(fuzz_u8(r));
        p.y = fuzz_corner(fuzz_u8(r));
        break;
    case 2: /* near-duplicate of the previous point */
        p.x = fuzz_saturate((int64_t)previous->x + (int8_t)fuzz_u8(r) % 3);
        p.y = fuzz_saturate((int64_t)previous->y + (int8_t)fuzz_u8(r) % 3);
        break;
    case 3: { /* the next point of a collinear run through the previous one */
        int64_t step = (int8_t)fuzz_u8(r);
        int64_t slope = (int8_t)fuzz_u8(r) % 4;
        p.x = fuzz_saturate((int64_t)previous->x + step);
        p.y = fuzz_saturate((int64_t)previous->y + step * slope);
        break;
    }
    case 4: { /* on a circle around a fixed centre, scaled by 1 or 5 */
        uint8_t b = fuzz_u8(r);
        int32_t scale = (b & 0x80u) ? 5 : 1;
        p.x = 1000 + circle[(b & 0x7fu) % 12u][0] * scale;
        p.y = -1000 + circle[(b & 0x7fu) % 12u][1] * scale;
        break;
    }
    case 5:
        p.x = fuzz_u8(r) % 8;
        p.y = fuzz_u8(r) % 8;
        break;
    case 6: /* huge spacing: multiples of 2^24 */
        p.x = (int32_t)((uint32_t)(int8_t)fuzz_u8(r) << 24);
        p.y = (int32_t)((uint32_t)(int8_t)fuzz_u8(r) << 24);
        break;
    default:
        p.x = (int8_t)fuzz_u8(r);
        p.y = (int8_t)fuzz_u8(r);
        break;
    }
    *previous = p;
    return p;
}

/* A weight in one of the patterns that matter, some relative to
 * *previous (updated): raw int64, int64 corners, small ones (ties on
 * small grids), the previous one (equal weights: the incircle test) or
 * next to it, a squared int32 radius. */
static inline int64_t fuzz_weight(fuzz_reader_t *r, int64_t *previous)
{
    static const int64_t corners[] = {INT64_MIN, INT64_MIN + 1, -((int64_t)1 << 62), -1, 0, 1,
                                      (int64_t)1 << 62, INT64_MAX - 1, INT64_MAX};
    uint8_t kind = fuzz_u8(r);
    uint64_t raw = 0;
    int64_t w;
    switch (kind % 6u) {
    case 0:
        for (int i = 0; i < 8; i++)
            raw = (raw << 8) | fuzz_u8(r);
        w = (int64_t)raw;
        break;
    case 1:
        w = corners[fuzz_u8(r) % (sizeof corners / sizeof corners[0])];
        break;
    case 2:
        w = (int8_t)fuzz_u8(r) % 8;
        break;
    case 3:
        w = *previous;
        break;
    case 4:
        w = (*previous > INT64_MIN + 2 && *previous < INT64_MAX - 2)
                ? *previous + (int8_t)fuzz_u8(r) % 3
                : *previous;
        break;
    default: {
        int64_t radius = fuzz_i32(r);
        w = radius * radius;
        break;
    }
    }
    *previous = w;
    return w;
}

/* Signed integers of 12 64-bit limbs in two's complement, least
 * significant first, computed modulo 2^768 (exact when the result fits):
 * wide enough for every determinant of int32 points and of fuzz_hpoint.h's
 * crossing vertices. */
#define FUZZ_BIG_LIMBS 12

typedef struct {
    uint64_t limb[FUZZ_BIG_LIMBS];
} fuzz_big_t;

static inline fuzz_big_t fuzz_big_from(__int128 v)
{
    fuzz_big_t b;
    uint64_t fill = v < 0 ? ~0ull : 0ull;
    b.limb[0] = (uint64_t)v;
    b.limb[1] = (uint64_t)((unsigned __int128)v >> 64);
    for (int i = 2; i < FUZZ_BIG_LIMBS; i++)
        b.limb[i] = fill;
    return b;
}

static inline fuzz_big_t fuzz_big_add(fuzz_big_t a, const fuzz_big_t b)
{
    unsigned __int128 carry = 0;
    for (int i = 0; i < FUZZ_BIG_LIMBS; i++) {
        carry += (unsigned __int128)a.limb[i] + b.limb[i];
        a.limb[i] = (uint64_t)carry;
        carry >>= 64;
    }
    return a;
}

static inline int fuzz_big_negative(const fuzz_big_t a)
{
    return (int)(a.limb[FUZZ_BIG_LIMBS - 1] >> 63);
}

static inline fuzz_big_t fuzz_big_negate(fuzz_big_t a)
{
    unsigned __int128 carry = 1;
    for (int i = 0; i < FUZZ_BIG_LIMBS; i++) {
        carry += (uint64_t)~a.limb[i];
        a.limb[i] = (uint64_t)carry;
        carry >>= 64;
    }
    return a;
}

static inline fuzz_big_t fuzz_big_sub(fuzz_big_t a, const fuzz_big_t b)
{
    return fuzz_big_add(a, fuzz_big_negate(b));
}

static inline int fuzz_big_sign(const fuzz_big_t a)
{
    if (fuzz_big_negative(a))
        return -1;
    for (int i = 0; i < FUZZ_BIG_LIMBS; i++)
        if (a.limb[i])
            return 1;
    return 0;
}

/* a * b modulo 2^768: magnitudes multiplied over their nonzero limbs only
 * (most values are far shorter than the type), the sign applied after. */
static inline fuzz_big_t fuzz_big_mul(const fuzz_big_t a, const fuzz_big_t b)
{
    int negative = fuzz_big_negative(a) != fuzz_big_negative(b);
    fuzz_big_t x = fuzz_big_negative(a) ? fuzz_big_negate(a) : a;
    fuzz_big_t y = fuzz_big_negative(b) ? fuzz_big_negate(b) : b;
    int nx = FUZZ_BIG_LIMBS, ny = FUZZ_BIG_LIMBS;
    while (nx > 0 && x.limb[nx - 1] == 0)
        nx--;
    while (ny > 0 && y.limb[ny - 1] == 0)
        ny--;
    fuzz_big_t r = fuzz_big_from(0);
    for (int i = 0; i < nx; i++) {
        unsigned __int128 carry = 0;
        for (int j = 0; j < ny && i + j < FUZZ_BIG_LIMBS; j++) {
            carry += (unsigned __int128)x.limb[i] * y.limb[j] + r.limb[i + j];
            r.limb[i + j] = (uint64_t)carry;
            carry >>= 64;
        }
        if (i + ny < FUZZ_BIG_LIMBS)
            r.limb[i + ny] = (uint64_t)carry;
    }
    return negative ? fuzz_big_negate(r) : r;
}

/* a * b - c * d */
static inline fuzz_big_t fuzz_big_cross(const fuzz_big_t a, const fuzz_big_t b,
                                        const fuzz_big_t c, const fuzz_big_t d)
{
    return fuzz_big_sub(fuzz_big_mul(a, b), fuzz_big_mul(c, d));
}

/* Exact signs of the three predicates, by the textbook determinants. */
static inline int fuzz_orient(vor_point_t a, vor_point_t b, vor_point_t c)
{
    __int128 det = (__int128)((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) -
                   (__int128)((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
    return (det > 0) - (det < 0);
}

static inline int fuzz_incircle(vor_point_t a, vor_point_t b, vor_point_t c, vor_point_t d)
{
    int64_t adx = (int64_t)a.x - d.x, ady = (int64_t)a.y - d.y;
    int64_t bdx = (int64_t)b.x - d.x, bdy = (int64_t)b.y - d.y;
    int64_t cdx = (int64_t)c.x - d.x, cdy = (int64_t)c.y - d.y;
    __int128 alift = (__int128)adx * adx + (__int128)ady * ady;
    __int128 blift = (__int128)bdx * bdx + (__int128)bdy * bdy;
    __int128 clift = (__int128)cdx * cdx + (__int128)cdy * cdy;
    fuzz_big_t det = fuzz_big_mul(fuzz_big_from((__int128)bdx * cdy - (__int128)cdx * bdy),
                                  fuzz_big_from(alift));
    det = fuzz_big_add(det, fuzz_big_mul(fuzz_big_from((__int128)cdx * ady - (__int128)adx * cdy),
                                         fuzz_big_from(blift)));
    det = fuzz_big_add(det, fuzz_big_mul(fuzz_big_from((__int128)adx * bdy - (__int128)bdx * ady),
                                         fuzz_big_from(clift)));
    return fuzz_big_sign(det);
}

/* The power test: the incircle determinant with each lift less its
 * weight, rows relative to d (lifts below 2^65, weight differences below
 * 2^64, products below 2^131). */
static inline int fuzz_power(vor_point_t a, int64_t wa, vor_point_t b, int64_t wb,
                             vor_point_t c, int64_t wc, vor_point_t d, int64_t wd)
{
    const vor_point_t p[3] = {a, b, c};
    const int64_t w[3] = {wa, wb, wc};
    fuzz_big_t x[3], y[3], z[3];
    for (int i = 0; i < 3; i++) {
        x[i] = fuzz_big_from((int64_t)p[i].x - d.x);
        y[i] = fuzz_big_from((int64_t)p[i].y - d.y);
        z[i] = fuzz_big_sub(fuzz_big_add(fuzz_big_mul(x[i], x[i]), fuzz_big_mul(y[i], y[i])),
                            fuzz_big_sub(fuzz_big_from(w[i]), fuzz_big_from(wd)));
    }
    fuzz_big_t det = fuzz_big_from(0);
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        det = fuzz_big_add(det, fuzz_big_mul(z[i], fuzz_big_cross(x[j], y[k], x[k], y[j])));
    }
    return fuzz_big_sign(det);
}

/* |q - p|^2, exact (< 2^65). */
static inline unsigned __int128 fuzz_distance2(int32_t qx, int32_t qy, vor_point_t p)
{
    int64_t dx = (int64_t)qx - p.x, dy = (int64_t)qy - p.y;
    return (unsigned __int128)((__int128)dx * dx) + (unsigned __int128)((__int128)dy * dy);
}

#endif
