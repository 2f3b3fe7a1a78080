/* raster_reference.c - see raster_reference.h. Slow on purpose: plain
 * schoolbook arithmetic on fixed arrays, one formula per distance. */
#include "raster_reference.h"

void ref_big_set(ref_big_t *r, uint64_t v)
{
    for (int i = 0; i < REF_LIMBS; i++) {
        r->limb[i] = 0;
    }
    r->limb[0] = (uint32_t)v;
    r->limb[1] = (uint32_t)(v >> 32);
}

void ref_big_mul(ref_big_t *r, const ref_big_t *a, const ref_big_t *b)
{
    uint32_t out[REF_LIMBS];
    for (int i = 0; i < REF_LIMBS; i++) {
        out[i] = 0;
    }
    for (int i = 0; i < REF_LIMBS; i++) {
        /* long multiplication with 16-bit halves: no 64-bit multiply needed */
        for (int j = 0; i + j < REF_LIMBS; j++) {
            uint32_t x = a->limb[i], y = b->limb[j];
            if (x == 0u || y == 0u) {
                continue;
            }
            uint64_t p = (uint64_t)(x & 0xFFFFu) * (y & 0xFFFFu) +
                         (((uint64_t)(x >> 16) * (y & 0xFFFFu)) << 16) +
                         (((uint64_t)(x & 0xFFFFu) * (y >> 16)) << 16) +
                         (((uint64_t)(x >> 16) * (y >> 16)) << 32);
            /* p < 2^64 always; add p at limb i + j with carries */
            uint64_t carry = p;
            for (int k = i + j; k < REF_LIMBS && carry != 0u; k++) {
                uint64_t s = (uint64_t)out[k] + (uint32_t)carry;
                out[k] = (uint32_t)s;
                carry = (carry >> 32) + (s >> 32);
            }
        }
    }
    for (int i = 0; i < REF_LIMBS; i++) {
        r->limb[i] = out[i];
    }
}

void ref_big_add(ref_big_t *r, const ref_big_t *a)
{
    uint32_t carry = 0;
    for (int i = 0; i < REF_LIMBS; i++) {
        uint64_t s = (uint64_t)r->limb[i] + a->limb[i] + carry;
        r->limb[i] = (uint32_t)s;
        carry = (uint32_t)(s >> 32);
    }
}

int ref_big_compare(const ref_big_t *a, const ref_big_t *b)
{
    for (int i = REF_LIMBS - 1; i >= 0; i--) {
        if (a->limb[i] != b->limb[i]) {
            return a->limb[i] < b->limb[i] ? -1 : 1;
        }
    }
    return 0;
}

static uint64_t abs_difference(int32_t p, int32_t q)
{
    return p > q ? (uint64_t)((int64_t)p - q) : (uint64_t)((int64_t)q - p);
}

void ref_euclid_square(ref_big_t *r, int32_t qx, int32_t qy, const vor_point_t *s)
{
    ref_big_t dx, dy;
    ref_big_set(&dx, abs_difference(qx, s->x));
    ref_big_set(&dy, abs_difference(qy, s->y));
    ref_big_mul(r, &dx, &dx);
    ref_big_t y2;
    ref_big_mul(&y2, &dy, &dy);
    ref_big_add(r, &y2);
}

uint32_t ref_nearest(const vor_raster_sites_t *sites, int32_t qx, int32_t qy)
{
    ref_big_t best, d;
    uint32_t best_site = 0;
    ref_euclid_square(&best, qx, qy, &sites->points[0]);
    for (uint32_t k = 1; k < sites->count; k++) {
        ref_euclid_square(&d, qx, qy, &sites->points[k]);
        if (ref_big_compare(&d, &best) < 0) {
            best = d;
            best_site = k;
        }
    }
    return best_site;
}

uint32_t ref_distance(const vor_raster_sites_t *sites, uint32_t k, int32_t qx, int32_t qy)
{
    ref_big_t d, r2, rb;
    ref_euclid_square(&d, qx, qy, &sites->points[k]);
    /* binary search for the largest r in [0, 2^32 - 1] with r^2 <= d */
    uint64_t lo = 0, hi = 0xFFFFFFFFu;
    while (lo < hi) {
        uint64_t mid = lo + (hi - lo + 1u) / 2u;
        ref_big_set(&rb, mid);
        ref_big_mul(&r2, &rb, &rb);
        if (ref_big_compare(&r2, &d) <= 0) {
            lo = mid;
        } else {
            hi = mid - 1u;
        }
    }
    return (uint32_t)lo;
}
