/* SPDX-License-Identifier: MIT */
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

/* Index of the highest nonzero limb, -1 for zero. */
static int ref_top(const ref_big_t *a)
{
    int i = REF_LIMBS - 1;
    while (i >= 0 && a->limb[i] == 0u) {
        i--;
    }
    return i;
}

void ref_big_mul(ref_big_t *r, const ref_big_t *a, const ref_big_t *b)
{
    uint32_t out[REF_LIMBS];
    for (int i = 0; i < REF_LIMBS; i++) {
        out[i] = 0;
    }
    int top_a = ref_top(a), top_b = ref_top(b);
    for (int i = 0; i <= top_a; i++) {
        /* long multiplication with 16-bit halves: no 64-bit multiply needed */
        for (int j = 0; j <= top_b && i + j < REF_LIMBS; j++) {
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

void ref_big_sub(ref_big_t *r, const ref_big_t *a)
{
    uint32_t borrow = 0;
    for (int i = 0; i < REF_LIMBS; i++) {
        uint64_t d = (uint64_t)r->limb[i] - a->limb[i] - borrow;
        r->limb[i] = (uint32_t)d;
        borrow = (uint32_t)(d >> 63);
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
    uint64_t ax = abs_difference(qx, s->x), ay = abs_difference(qy, s->y);
    if (ax < 0x80000000u && ay < 0x80000000u) { /* the sum fits 64 bits */
        ref_big_set(r, ax * ax + ay * ay);
        return;
    }
    ref_big_t dx, dy;
    ref_big_set(&dx, ax);
    ref_big_set(&dy, ay);
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

/* ------------------------------------------------ the other metrics */

static void big_copy(ref_big_t *r, const ref_big_t *a)
{
    for (int i = 0; i < REF_LIMBS; i++) {
        r->limb[i] = a->limb[i];
    }
}

/* r = a * v for a small factor. */
static void big_scale(ref_big_t *r, const ref_big_t *a, uint64_t v)
{
    ref_big_t f;
    ref_big_set(&f, v);
    ref_big_mul(r, a, &f);
}

/* r = 2^bits * a. */
static void big_shift(ref_big_t *r, const ref_big_t *a, unsigned bits)
{
    ref_big_t out;
    ref_big_set(&out, 0);
    for (int i = REF_LIMBS - 1; i >= 0; i--) {
        int to = i + (int)(bits / 32u);
        if (to >= REF_LIMBS) {
            continue;
        }
        uint64_t v = (uint64_t)a->limb[i] << (bits % 32u);
        out.limb[to] |= (uint32_t)v;
        if (to + 1 < REF_LIMBS) {
            out.limb[to + 1] |= (uint32_t)(v >> 32);
        }
    }
    big_copy(r, &out);
}

/* floor(sqrt(x)), bit by bit from the top: the largest root whose square
 * stays <= x. */
static void big_isqrt(ref_big_t *root, const ref_big_t *x)
{
    int top = ref_top(x);
    ref_big_set(root, 0);
    if (top < 0) {
        return;
    }
    ref_big_t trial, square;
    for (int bit = (top + 1) * 16; bit >= 0; bit--) {
        big_copy(&trial, root);
        trial.limb[bit / 32] |= 1u << (bit % 32);
        ref_big_mul(&square, &trial, &trial);
        if (ref_big_compare(&square, x) <= 0) {
            big_copy(root, &trial);
        }
    }
}

static uint32_t udiff(int32_t p, int32_t q)
{
    return p > q ? (uint32_t)((int64_t)p - q) : (uint32_t)((int64_t)q - p);
}

/* A signed value as sign and magnitude. */
typedef struct {
    ref_big_t mag;
    int neg;
} ref_signed_t;

/* x1 * y1 + x2 * y2 for |x|, |y| < 2^32 (int64 inputs). */
static void signed_dot(ref_signed_t *r, int64_t x1, int64_t y1, int64_t x2, int64_t y2)
{
    ref_big_t p[2];
    int neg[2];
    int64_t xs[2] = {x1, x2}, ys[2] = {y1, y2};
    for (int i = 0; i < 2; i++) {
        uint64_t ax = (uint64_t)(xs[i] < 0 ? -xs[i] : xs[i]);
        uint64_t ay = (uint64_t)(ys[i] < 0 ? -ys[i] : ys[i]);
        ref_big_t bx;
        ref_big_set(&bx, ax);
        big_scale(&p[i], &bx, ay);
        neg[i] = (xs[i] < 0) != (ys[i] < 0);
    }
    if (neg[0] == neg[1]) {
        big_copy(&r->mag, &p[0]);
        ref_big_add(&r->mag, &p[1]);
        r->neg = neg[0];
    } else if (ref_big_compare(&p[0], &p[1]) >= 0) {
        big_copy(&r->mag, &p[0]);
        ref_big_sub(&r->mag, &p[1]);
        r->neg = neg[0];
    } else {
        big_copy(&r->mag, &p[1]);
        ref_big_sub(&r->mag, &p[0]);
        r->neg = neg[1];
    }
    ref_big_t zero;
    ref_big_set(&zero, 0);
    if (ref_big_compare(&r->mag, &zero) == 0) {
        r->neg = 0;
    }
}

/* A nonnegative rational num / den. */
typedef struct {
    ref_big_t num, den;
} ref_ratio_t;

/* True when a < 2^32; *v = a. */
static int small_value(const ref_big_t *a, uint64_t *v)
{
    for (int i = 1; i < REF_LIMBS; i++) {
        if (a->limb[i] != 0u) {
            return 0;
        }
    }
    *v = a->limb[0];
    return 1;
}

static int ratio_compare(const ref_ratio_t *a, const ref_ratio_t *b)
{
    uint64_t an, ad, bn, bd;
    if (small_value(&a->num, &an) && small_value(&a->den, &ad) && small_value(&b->num, &bn) &&
        small_value(&b->den, &bd)) {
        uint64_t l = an * bd, r = bn * ad;
        return l < r ? -1 : l > r;
    }
    ref_big_t l, r;
    ref_big_mul(&l, &a->num, &b->den);
    ref_big_mul(&r, &b->num, &a->den);
    return ref_big_compare(&l, &r);
}

/* Squared distance from q to the segment a-b, as the smallest of the
 * candidates |q - a|^2, |q - b|^2, and (when the foot of the perpendicular
 * falls strictly inside) |q - a|^2 - dot^2 / L = (|q - a|^2 L - dot^2) / L. */
static void segment_square(ref_ratio_t *r, int32_t qx, int32_t qy, const vor_point_t *a,
                           const vor_point_t *b)
{
    ref_ratio_t other;
    ref_euclid_square(&r->num, qx, qy, a);
    ref_big_set(&r->den, 1);
    ref_euclid_square(&other.num, qx, qy, b);
    ref_big_set(&other.den, 1);
    if (ratio_compare(&other, r) < 0) {
        *r = other;
    }
    ref_big_t length, dx, dy; /* L = |b - a|^2 */
    ref_big_set(&dx, udiff(b->x, a->x));
    ref_big_set(&dy, udiff(b->y, a->y));
    ref_big_mul(&length, &dx, &dx);
    ref_big_t y2;
    ref_big_mul(&y2, &dy, &dy);
    ref_big_add(&length, &y2);
    ref_signed_t dot;
    signed_dot(&dot, (int64_t)qx - a->x, (int64_t)b->x - a->x, (int64_t)qy - a->y,
               (int64_t)b->y - a->y);
    ref_big_t zero_big;
    ref_big_set(&zero_big, 0);
    if (dot.neg || ref_big_compare(&dot.mag, &zero_big) == 0 ||
        ref_big_compare(&dot.mag, &length) >= 0) {
        return;
    }
    ref_big_t qa, dot2;
    ref_euclid_square(&qa, qx, qy, a);
    ref_big_mul(&other.num, &qa, &length);
    ref_big_mul(&dot2, &dot.mag, &dot.mag);
    ref_big_sub(&other.num, &dot2);
    big_copy(&other.den, &length);
    if (ratio_compare(&other, r) < 0) {
        *r = other;
    }
}

/* Sign of (b - a) x (q - a). */
static int orientation(const vor_point_t *a, const vor_point_t *b, int32_t qx, int32_t qy)
{
    ref_signed_t s;
    signed_dot(&s, (int64_t)b->x - a->x, (int64_t)qy - a->y, -((int64_t)b->y - a->y),
               (int64_t)qx - a->x);
    ref_big_t zero;
    ref_big_set(&zero, 0);
    return ref_big_compare(&s.mag, &zero) == 0 ? 0 : s.neg ? -1 : 1;
}

/* Nonzero winding number, counted on the upward vertical ray from q:
 * edges crossing x = qx above q, leftward +1, rightward -1. */
static int inside_polygon(const vor_point_t *p, uint32_t count, int32_t qx, int32_t qy)
{
    int winding = 0;
    for (uint32_t i = 0; i < count; i++) {
        const vor_point_t *a = &p[i], *b = &p[(i + 1u) % count];
        if (a->x <= qx && b->x > qx && orientation(a, b, qx, qy) < 0) {
            winding--; /* rightward, q below it */
        } else if (a->x > qx && b->x <= qx && orientation(a, b, qx, qy) > 0) {
            winding++; /* leftward, q below it */
        }
    }
    return winding != 0;
}

/* Distance image of a polygon site: 0 inside, else its nearest edge. */
static void polygon_square(ref_ratio_t *r, int32_t qx, int32_t qy, const vor_point_t *p,
                           uint32_t count)
{
    if (count >= 3u && inside_polygon(p, count, qx, qy)) {
        ref_big_set(&r->num, 0);
        ref_big_set(&r->den, 1);
        return;
    }
    segment_square(r, qx, qy, &p[0], &p[count > 1u ? 1u : 0u]);
    for (uint32_t i = 1; count >= 3u && i < count; i++) {
        ref_ratio_t e;
        segment_square(&e, qx, qy, &p[i], &p[(i + 1u) % count]);
        if (ratio_compare(&e, r) < 0) {
            *r = e;
        }
    }
}

/* Squared distance to an open polyline divided by its squared weight: the
 * smallest over its segments (one vertex: the point), den times w^2. */
static void polyline_square(ref_ratio_t *r, int32_t qx, int32_t qy, const vor_point_t *p,
                            uint32_t count, int64_t weight)
{
    segment_square(r, qx, qy, &p[0], &p[count > 1u ? 1u : 0u]);
    for (uint32_t i = 1; i + 1u < count; i++) {
        ref_ratio_t e;
        segment_square(&e, qx, qy, &p[i], &p[i + 1u]);
        if (ratio_compare(&e, r) < 0) {
            *r = e;
        }
    }
    ref_big_t w, w2, den;
    ref_big_set(&w, (uint64_t)weight);
    ref_big_mul(&w2, &w, &w);
    ref_big_mul(&den, &r->den, &w2);
    r->den = den;
}

/* a * (a Q) = (a dx + b dy)^2 + (a c - b^2) dy^2: the elliptic form
 * completed to a square, times a > 0 (the same factor for every site). */
static void elliptic_scaled(ref_big_t *r, const vor_raster_sites_t *s, int32_t qx, int32_t qy,
                            const vor_point_t *p)
{
    int64_t dx = (int64_t)qx - p->x, dy = (int64_t)qy - p->y;
    int64_t det = (int64_t)s->form_a * s->form_c - (int64_t)s->form_b * s->form_b;
    int64_t limit = (int64_t)1 << 20;
    if (dx < limit && dx > -limit && dy < limit && dy > -limit && s->form_a < limit &&
        s->form_b < limit && s->form_b > -limit && det < ((int64_t)1 << 21)) {
        int64_t u = s->form_a * dx + s->form_b * dy; /* below 2^41 */
        if (u < ((int64_t)1 << 31) && u > -((int64_t)1 << 31)) {
            ref_big_set(r, (uint64_t)(u * u) + (uint64_t)(det * dy * dy)); /* < 2^62 + 2^61 */
            return;
        }
    }
    ref_signed_t u;
    signed_dot(&u, s->form_a, dx, s->form_b, dy);
    ref_big_mul(r, &u.mag, &u.mag);
    ref_big_t d, y, t;
    ref_big_set(&d, (uint64_t)det);
    ref_big_set(&y, (uint64_t)(dy < 0 ? -dy : dy));
    ref_big_mul(&t, &y, &y);
    ref_big_t term;
    ref_big_mul(&term, &t, &d);
    ref_big_add(r, &term);
}

/* |dx|^p + |dy|^p. */
static void lp_sum(ref_big_t *r, uint32_t ax, uint32_t ay, uint32_t p)
{
    uint32_t bits = 62u / p;
    if ((uint64_t)ax >> bits == 0u && (uint64_t)ay >> bits == 0u) {
        uint64_t sx = 1, sy = 1; /* below 2^(62 / p) each: powers below 2^62 */
        for (uint32_t i = 0; i < p; i++) {
            sx *= ax;
            sy *= ay;
        }
        ref_big_set(r, sx + sy);
        return;
    }
    ref_big_t x, y, px, py;
    ref_big_set(&x, ax);
    ref_big_set(&y, ay);
    ref_big_set(&px, 1);
    ref_big_set(&py, 1);
    for (uint32_t i = 0; i < p; i++) {
        ref_big_t t;
        ref_big_mul(&t, &px, &x);
        px = t;
        ref_big_mul(&t, &py, &y);
        py = t;
    }
    *r = px;
    ref_big_add(r, &py);
}

/* The weighted value u = sqrt(D) / w1 - w2 + 2^31 (>= 0), bracketed at
 * precision 2^-t: u 2^t w1 = sqrt(D 4^t) + (2^31 - w2) 2^t w1 lies in
 * [low, low + 1) with low = floor(sqrt(D 4^t)) + (2^31 - w2) 2^t w1, and
 * equals low when D 4^t is a square (exact). */
typedef struct {
    ref_big_t low;
    int exact;
    uint64_t w1;
} ref_bracket_t;

static void bracket(ref_bracket_t *b, const ref_big_t *d, int64_t w1, int64_t w2, unsigned t)
{
    ref_big_t scaled, root, square, offset;
    big_shift(&scaled, d, 2u * t);
    big_isqrt(&root, &scaled);
    ref_big_mul(&square, &root, &root);
    b->exact = ref_big_compare(&square, &scaled) == 0;
    ref_big_set(&offset, (uint64_t)(((int64_t)1 << 31) - w2));
    big_shift(&offset, &offset, t);
    big_scale(&offset, &offset, (uint64_t)w1);
    b->low = root;
    ref_big_add(&b->low, &offset);
    b->w1 = (uint64_t)w1;
}

/* For D < 2^62, 1 <= w1 <= 2^10, |w2| <= 2^20: *out = 2 floor(sqrt(D)) +
 * (1 when D is a square), and 1; else 0. */
static int small_bracket(const ref_big_t *d, int64_t w1, int64_t w2, uint64_t *out)
{
    for (int i = 2; i < REF_LIMBS; i++) {
        if (d->limb[i] != 0u) {
            return 0;
        }
    }
    uint64_t v = d->limb[0] | ((uint64_t)d->limb[1] << 32);
    if (v >> 62 != 0u || w1 > 1024 || w2 > (1 << 20) || w2 < -(1 << 20)) {
        return 0;
    }
    uint64_t root = 0; /* the largest root with root^2 <= v, bit by bit */
    for (int bit = 30; bit >= 0; bit--) {
        uint64_t trial = root | ((uint64_t)1 << bit);
        if (trial * trial <= v) {
            root = trial;
        }
    }
    *out = 2u * root + (root * root == v);
    return 1;
}

/* Compares sqrt(Da)/w1a - w2a with sqrt(Db)/w1b - w2b by brackets of
 * growing precision; sets *undecided when the precision runs out. */
static int weighted_compare(const ref_big_t *da, int64_t w1a, int64_t w2a, const ref_big_t *db,
                            int64_t w1b, int64_t w2b, int *undecided)
{
    ref_big_t l, r;
    if (w2a == w2b) { /* equal exactly when Da w1b^2 = Db w1a^2 */
        big_scale(&l, da, (uint64_t)(w1b * w1b));
        big_scale(&r, db, (uint64_t)(w1a * w1a));
        if (ref_big_compare(&l, &r) == 0) {
            return 0;
        }
    }
    /* precision 1 in 64-bit integers when everything is small: d = sqrt(D)
     * lies in [r, r + 1) (r = floor, exactly r when D = r^2), so
     * d / w1 - w2 lies in [r - w1 w2, r + 1 - w1 w2) / w1 */
    uint64_t small_a = 0, small_b = 0;
    if (small_bracket(da, w1a, w2a, &small_a) && small_bracket(db, w1b, w2b, &small_b)) {
        int64_t ra = (int64_t)(small_a >> 1), rb = (int64_t)(small_b >> 1);
        int exact_a = (int)(small_a & 1u), exact_b = (int)(small_b & 1u);
        int64_t a_low = (ra - w1a * w2a) * w1b, b_low = (rb - w1b * w2b) * w1a;
        if (exact_a && exact_b) {
            return a_low < b_low ? -1 : a_low > b_low;
        }
        int64_t a_high = (ra + !exact_a - w1a * w2a) * w1b, b_high = (rb + !exact_b - w1b * w2b) * w1a;
        if (a_high < b_low || (a_high == b_low && (!exact_a || !exact_b))) {
            return -1;
        }
        if (b_high < a_low || (b_high == a_low && (!exact_a || !exact_b))) {
            return 1;
        }
    }
    static const unsigned precisions[] = {0, 8, 24, 64, 128, 200, 260};
    for (unsigned i = 0; i < sizeof precisions / sizeof precisions[0]; i++) {
        ref_bracket_t a, b;
        bracket(&a, da, w1a, w2a, precisions[i]);
        bracket(&b, db, w1b, w2b, precisions[i]);
        /* compare the intervals [low, low + 1) / w1, scaled by w1a w1b */
        ref_big_t a_low, a_high, b_low, b_high, one;
        ref_big_set(&one, 1);
        big_scale(&a_low, &a.low, b.w1);
        big_scale(&b_low, &b.low, a.w1);
        if (a.exact && b.exact) {
            return ref_big_compare(&a_low, &b_low);
        }
        big_copy(&a_high, &a.low);
        if (!a.exact) {
            ref_big_add(&a_high, &one);
        }
        big_scale(&a_high, &a_high, b.w1);
        big_copy(&b_high, &b.low);
        if (!b.exact) {
            ref_big_add(&b_high, &one);
        }
        big_scale(&b_high, &b_high, a.w1);
        /* an inexact value lies strictly inside its interval */
        int c = ref_big_compare(&a_high, &b_low);
        if (c < 0 || (c == 0 && (!a.exact || !b.exact))) {
            return -1;
        }
        c = ref_big_compare(&b_high, &a_low);
        if (c < 0 || (c == 0 && (!a.exact || !b.exact))) {
            return 1;
        }
    }
    if (undecided != NULL) {
        *undecided = 1;
    }
    return 0;
}

/* The distance image of site k at q, for the metrics compared as plain
 * integers (sign: FARTHEST ranks by the negated value). */
static void plain_value(ref_big_t *r, const vor_raster_sites_t *s, uint32_t k, int32_t qx,
                        int32_t qy)
{
    const vor_point_t *p = &s->points[k];
    switch (s->metric) {
    case VOR_METRIC_L1:
        ref_big_set(r, (uint64_t)udiff(qx, p->x) + udiff(qy, p->y));
        break;
    case VOR_METRIC_LINF: {
        uint32_t ax = udiff(qx, p->x), ay = udiff(qy, p->y);
        ref_big_set(r, ax > ay ? ax : ay);
        break;
    }
    case VOR_METRIC_LP:
        lp_sum(r, udiff(qx, p->x), udiff(qy, p->y), s->lp_exponent);
        break;
    case VOR_METRIC_ELLIPTIC:
        elliptic_scaled(r, s, qx, qy, p);
        break;
    case VOR_METRIC_HAUSDORFF: {
        ref_big_set(r, 0);
        for (uint32_t i = s->offsets[k]; i < s->offsets[k + 1u]; i++) {
            ref_big_t d;
            ref_euclid_square(&d, qx, qy, &s->points[i]);
            if (ref_big_compare(&d, r) > 0) {
                *r = d;
            }
        }
        break;
    }
    default: /* EUCLID, FARTHEST */
        ref_euclid_square(r, qx, qy, p);
        break;
    }
}

/* The positive and negative parts of an int64, as magnitudes (2^63 for
 * INT64_MIN fits). */
static uint64_t positive_part(int64_t v)
{
    return v > 0 ? (uint64_t)v : 0u;
}

static uint64_t negative_part(int64_t v)
{
    return v < 0 ? 0u - (uint64_t)v : 0u;
}

/* *r = D + extra1 + extra2 for the squared distance from q to s: one side
 * of a power comparison with every negative term moved across, so both
 * sides are sums of non-negative parts (no bias, no signed arithmetic). */
static void power_side(ref_big_t *r, int32_t qx, int32_t qy, const vor_point_t *s,
                       uint64_t extra1, uint64_t extra2)
{
    ref_big_t t;
    if (s != NULL) {
        ref_euclid_square(r, qx, qy, s);
    } else {
        ref_big_set(r, 0);
    }
    ref_big_set(&t, extra1);
    ref_big_add(r, &t);
    ref_big_set(&t, extra2);
    ref_big_add(r, &t);
}

/* Sign of (D_a - w_a) - (D_b - w_b): D_a + w_b+ + w_a- against
 * D_b + w_a+ + w_b-. */
static int power_compare(const vor_raster_sites_t *s, uint32_t a, uint32_t b, int32_t qx,
                         int32_t qy)
{
    ref_big_t left, right;
    int64_t wa = s->power_weights[a], wb = s->power_weights[b];
    power_side(&left, qx, qy, &s->points[a], positive_part(wb), negative_part(wa));
    power_side(&right, qx, qy, &s->points[b], positive_part(wa), negative_part(wb));
    return ref_big_compare(&left, &right);
}

uint32_t ref_nearest_metric(const vor_raster_sites_t *s, int32_t qx, int32_t qy, int *undecided)
{
    uint32_t best = 0;
    switch (s->metric) {
    case VOR_METRIC_POWER:
        for (uint32_t k = 1; k < s->count; k++) {
            if (power_compare(s, k, best, qx, qy) < 0) {
                best = k;
            }
        }
        return best;
    case VOR_METRIC_MULT:
    case VOR_METRIC_ADD:
    case VOR_METRIC_COMPOUND: {
        ref_big_t best_d, d;
        int64_t best_w1 = 1, best_w2 = 0;
        ref_euclid_square(&best_d, qx, qy, &s->points[0]);
        if (s->metric != VOR_METRIC_ADD) {
            best_w1 = s->mult_weights[0];
        }
        if (s->metric != VOR_METRIC_MULT) {
            best_w2 = s->add_weights[0];
        }
        for (uint32_t k = 1; k < s->count; k++) {
            int64_t w1 = s->metric != VOR_METRIC_ADD ? s->mult_weights[k] : 1;
            int64_t w2 = s->metric != VOR_METRIC_MULT ? s->add_weights[k] : 0;
            ref_euclid_square(&d, qx, qy, &s->points[k]);
            if (weighted_compare(&d, w1, w2, &best_d, best_w1, best_w2, undecided) < 0) {
                best = k;
                best_d = d;
                best_w1 = w1;
                best_w2 = w2;
            }
        }
        return best;
    }
    case VOR_METRIC_SEGMENT:
    case VOR_METRIC_POLYGON:
    case VOR_METRIC_POLYLINE: {
        ref_ratio_t best_r, r;
        for (uint32_t k = 0; k < s->count; k++) {
            if (s->metric == VOR_METRIC_SEGMENT) {
                segment_square(&r, qx, qy, &s->points[2u * k], &s->points[2u * k + 1u]);
            } else if (s->metric == VOR_METRIC_POLYLINE) {
                polyline_square(&r, qx, qy, &s->points[s->offsets[k]],
                                s->offsets[k + 1u] - s->offsets[k],
                                s->mult_weights != NULL ? s->mult_weights[k] : 1);
            } else {
                polygon_square(&r, qx, qy, &s->points[s->offsets[k]],
                               s->offsets[k + 1u] - s->offsets[k]);
            }
            if (k == 0u || ratio_compare(&r, &best_r) < 0) {
                best = k;
                best_r = r;
            }
        }
        return best;
    }
    default: {
        ref_big_t best_v, v;
        int farthest = s->metric == VOR_METRIC_FARTHEST;
        plain_value(&best_v, s, 0, qx, qy);
        for (uint32_t k = 1; k < s->count; k++) {
            plain_value(&v, s, k, qx, qy);
            int c = ref_big_compare(&v, &best_v);
            if (farthest ? c > 0 : c < 0) {
                best = k;
                best_v = v;
            }
        }
        return best;
    }
    }
}

/* The reference's exact image of site k's distance at q for the shaped
 * sites (segments, polygons, polylines). */
static void shape_square(ref_ratio_t *r, const vor_raster_sites_t *s, uint32_t k, int32_t qx,
                         int32_t qy)
{
    if (s->metric == VOR_METRIC_SEGMENT) {
        segment_square(r, qx, qy, &s->points[2u * k], &s->points[2u * k + 1u]);
    } else if (s->metric == VOR_METRIC_POLYLINE) {
        polyline_square(r, qx, qy, &s->points[s->offsets[k]], s->offsets[k + 1u] - s->offsets[k],
                        s->mult_weights != NULL ? s->mult_weights[k] : 1);
    } else {
        polygon_square(r, qx, qy, &s->points[s->offsets[k]], s->offsets[k + 1u] - s->offsets[k]);
    }
}

int ref_rank_compare(const vor_raster_sites_t *s, uint32_t a, uint32_t b, int32_t qx, int32_t qy,
                     int *undecided)
{
    switch (s->metric) {
    case VOR_METRIC_POWER:
        return power_compare(s, a, b, qx, qy);
    case VOR_METRIC_MULT:
    case VOR_METRIC_ADD:
    case VOR_METRIC_COMPOUND: {
        ref_big_t da, db;
        ref_euclid_square(&da, qx, qy, &s->points[a]);
        ref_euclid_square(&db, qx, qy, &s->points[b]);
        int64_t w1a = s->metric != VOR_METRIC_ADD ? s->mult_weights[a] : 1;
        int64_t w2a = s->metric != VOR_METRIC_MULT ? s->add_weights[a] : 0;
        int64_t w1b = s->metric != VOR_METRIC_ADD ? s->mult_weights[b] : 1;
        int64_t w2b = s->metric != VOR_METRIC_MULT ? s->add_weights[b] : 0;
        return weighted_compare(&da, w1a, w2a, &db, w1b, w2b, undecided);
    }
    case VOR_METRIC_SEGMENT:
    case VOR_METRIC_POLYGON:
    case VOR_METRIC_POLYLINE: {
        ref_ratio_t ra, rb;
        shape_square(&ra, s, a, qx, qy);
        shape_square(&rb, s, b, qx, qy);
        return ratio_compare(&ra, &rb);
    }
    default: {
        ref_big_t va, vb;
        plain_value(&va, s, a, qx, qy);
        plain_value(&vb, s, b, qx, qy);
        int c = ref_big_compare(&va, &vb);
        return s->metric == VOR_METRIC_FARTHEST ? -c : c;
    }
    }
}

/* ------------------------------------------------- distance values */

/* What "the distance is at least r" means for one site at one pixel:
 *   power:    r^p den <= num (r >= 0): L1, L-infinity (p = 1), Lp, and
 *             every squared distance as a fraction (p = 2)
 *   shifted:  r + w2 < 0, or ((r + w2) w1)^2 <= num: sqrt(num) / w1 - w2
 *             >= r, for the additive and compound weights (signed r) */
typedef struct {
    int shifted;
    uint32_t p;
    ref_big_t num, den;
    int64_t w1, w2;
} ref_floor_t;

static int reaches(const ref_floor_t *d, int64_t r)
{
    ref_big_t v, t, f;
    if (d->shifted) {
        int64_t base = r + d->w2; /* |base| < 2^33 */
        if (base < 0) {
            return 1;
        }
        ref_big_set(&v, (uint64_t)base);
        big_scale(&v, &v, (uint64_t)d->w1);
        ref_big_mul(&t, &v, &v);
        return ref_big_compare(&t, &d->num) <= 0;
    }
    ref_big_set(&f, (uint64_t)r);
    big_copy(&v, &d->den);
    for (uint32_t i = 0; i < d->p; i++) {
        ref_big_mul(&t, &v, &f);
        big_copy(&v, &t);
    }
    return ref_big_compare(&v, &d->num) <= 0;
}

/* POWER: D - w clamped to int32, by bisection on D - w >= r, i.e.
 * D + w- + r- >= w+ + r+ (every part non-negative). */
static uint32_t power_value(const vor_raster_sites_t *s, uint32_t k, int32_t qx, int32_t qy)
{
    int64_t w = s->power_weights[k];
    int64_t lo = INT32_MIN, hi = INT32_MAX; /* P >= INT32_MIN or clamped there */
    while (lo < hi) {
        int64_t mid = lo + (hi - lo + 1) / 2;
        ref_big_t left, right;
        power_side(&left, qx, qy, &s->points[k], negative_part(w), negative_part(mid));
        power_side(&right, qx, qy, NULL, positive_part(w), positive_part(mid));
        if (ref_big_compare(&left, &right) >= 0) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return (uint32_t)lo;
}

uint32_t ref_distance_metric(const vor_raster_sites_t *s, uint32_t k, int32_t qx, int32_t qy)
{
    if (s->metric == VOR_METRIC_POWER) {
        return power_value(s, k, qx, qy);
    }
    ref_floor_t d;
    d.shifted = 0;
    d.p = 2;
    d.w1 = 1;
    d.w2 = 0;
    ref_big_set(&d.den, 1);
    const vor_point_t *p = &s->points[k];
    switch (s->metric) {
    case VOR_METRIC_L1:
    case VOR_METRIC_LINF:
        d.p = 1;
        plain_value(&d.num, s, k, qx, qy);
        break;
    case VOR_METRIC_LP:
        d.p = s->lp_exponent;
        plain_value(&d.num, s, k, qx, qy);
        break;
    case VOR_METRIC_ELLIPTIC: /* r^2 <= Q iff r^2 a <= a Q */
        elliptic_scaled(&d.num, s, qx, qy, p);
        ref_big_set(&d.den, (uint64_t)s->form_a);
        break;
    case VOR_METRIC_MULT: /* r <= sqrt(D) / w iff r^2 w^2 <= D */
        ref_euclid_square(&d.num, qx, qy, p);
        ref_big_set(&d.den, (uint64_t)s->mult_weights[k]);
        big_scale(&d.den, &d.den, (uint64_t)s->mult_weights[k]);
        break;
    case VOR_METRIC_ADD:
    case VOR_METRIC_COMPOUND:
        d.shifted = 1;
        ref_euclid_square(&d.num, qx, qy, p);
        d.w1 = s->metric == VOR_METRIC_COMPOUND ? s->mult_weights[k] : 1;
        d.w2 = s->add_weights[k];
        break;
    case VOR_METRIC_SEGMENT:
    case VOR_METRIC_POLYGON:
    case VOR_METRIC_POLYLINE: {
        ref_ratio_t r;
        if (s->metric == VOR_METRIC_SEGMENT) {
            segment_square(&r, qx, qy, &s->points[2u * k], &s->points[2u * k + 1u]);
        } else if (s->metric == VOR_METRIC_POLYLINE) {
            polyline_square(&r, qx, qy, &s->points[s->offsets[k]],
                            s->offsets[k + 1u] - s->offsets[k],
                            s->mult_weights != NULL ? s->mult_weights[k] : 1);
        } else {
            polygon_square(&r, qx, qy, &s->points[s->offsets[k]],
                           s->offsets[k + 1u] - s->offsets[k]);
        }
        big_copy(&d.num, &r.num);
        big_copy(&d.den, &r.den);
        break;
    }
    default: /* EUCLID, FARTHEST, HAUSDORFF: integer squared distances */
        plain_value(&d.num, s, k, qx, qy);
        break;
    }
    /* the largest r of the output's range that the distance reaches
     * (saturation: the range's top); the bottom always holds */
    int64_t lo = d.shifted ? INT32_MIN : 0, hi = d.shifted ? INT32_MAX : (int64_t)UINT32_MAX;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo + 1) / 2;
        if (reaches(&d, mid)) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return (uint32_t)lo;
}

vor_raster_frame_t ref_frame(int32_t ox, int32_t oy, int32_t sx, int32_t sy, uint32_t w,
                             uint32_t h)
{
    vor_raster_frame_t f;
    f.origin_x = ox;
    f.origin_y = oy;
    f.step_x = sx;
    f.step_y = sy;
    f.width = w;
    f.height = h;
    return f;
}

int32_t ref_centre_x(const vor_raster_frame_t *f, uint32_t i)
{
    return (int32_t)(f->origin_x + (int64_t)i * f->step_x);
}

int32_t ref_centre_y(const vor_raster_frame_t *f, uint32_t j)
{
    return (int32_t)(f->origin_y + (int64_t)j * f->step_y);
}
