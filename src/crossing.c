/* SPDX-License-Identifier: MIT */
/*
 * crossing.c - exact predicates on sites and crossing vertices
 * (crossing.h).
 *
 * A predicate is the sign of a determinant with one row per vertex, rows
 * (x, y, 1) for the orientation and (x, y, x^2 + y^2, 1) for the incircle
 * test. For a vertex (X / W, Y / W) each row is multiplied by a positive
 * power of W, which keeps the sign: (X, Y, W) and (X W, Y W, X^2 + Y^2,
 * W^2). The perturbation expands each row into the plain one and one row
 * per perturbation term, exactly as for sites; a term row is scaled by W
 * too: dy (0, 1, 2y, 0) becomes (0, W, 2Y, 0), dx (W, 0, 2X, 0), the
 * squares stay (0, 0, 1, 0). The terms are taken in increasing order of
 * their exponent (the vertex of largest index most significant) until one
 * is nonzero; the term with the three lower vertices' dx, dy and dy^2
 * rows and the top vertex's point row is W W W_top^2 times +-1, so one is.
 *
 * Widths (crossing.h: |X|, |Y| <= 2^96, 0 < W < 2^66): incircle entries
 * below 2^162 (X W), 2^193 (X^2 + Y^2) and 2^132 (W^2), in 224 bits; a
 * 2 x 2 minor of two columns below 2^326, in 352 bits; the determinant,
 * six products of minors, below 2^655, in 672 bits. Orientation entries
 * are smaller, and its determinant below 2^262.
 */
#include "crossing.h"
#include "multiword.h"

#define ENTRY_LIMBS VOR__LIMBS(224u)
#define MINOR_LIMBS VOR__LIMBS(352u)
#define DET_LIMBS VOR__LIMBS(672u)

typedef vor__limb entry_t[ENTRY_LIMBS];

enum term_row { KIND_POINT, KIND_DY, KIND_DY2, KIND_DX, KIND_DX2 };

static bool negative(const vor__limb *a, size_t n)
{
    return (a[n - 1u] >> (VOR__LIMB_WIDTH - 1u)) != 0u;
}

/* r[0..nr) = a[0..na) sign-extended. */
static void widen(vor__limb *r, size_t nr, const vor__limb *a, size_t na)
{
    vor__limb fill = negative(a, na) ? (vor__limb)~(vor__limb)0 : 0u;
    for (size_t i = 0; i < nr; i++) {
        r[i] = (i < na) ? a[i] : fill;
    }
}

/* r[0..nr) = a[0..n) * b[0..n), two's complement, the product fitting in
 * nr limbs (n <= MINOR_LIMBS): the magnitudes' product, negated when the
 * signs differ. */
static void mul_signed(vor__limb *r, size_t nr, const vor__limb *a, const vor__limb *b, size_t n)
{
    vor__limb ma[MINOR_LIMBS];
    vor__limb mb[MINOR_LIMBS];
    bool na = negative(a, n);
    bool nb = negative(b, n);
    for (size_t i = 0; i < n; i++) {
        ma[i] = a[i];
        mb[i] = b[i];
    }
    if (na) {
        vor__mw_neg(ma, n);
    }
    if (nb) {
        vor__mw_neg(mb, n);
    }
    vor__mw_mul(r, nr, ma, n, mb, n);
    if (na != nb) {
        vor__mw_neg(r, nr);
    }
}

void vor__hpoint_site(vor__hpoint_t *h, vor_point_t p)
{
    vor__mw_from_i64(h->x, VOR__HPOINT_LIMBS, p.x);
    vor__mw_from_i64(h->y, VOR__HPOINT_LIMBS, p.y);
    vor__mw_from_i64(h->w, VOR__HPOINT_LIMBS, 1);
}

/* r = u x v for 33-bit differences: below 2^65 in magnitude. */
static void cross128(vor__limb *r, int64_t ux, int64_t uy, int64_t vx, int64_t vy)
{
    vor__limb a[VOR__HPOINT_LIMBS];
    vor__limb b[VOR__HPOINT_LIMBS];
    vor__limb t[VOR__HPOINT_LIMBS];
    vor__mw_from_i64(a, VOR__HPOINT_LIMBS, ux);
    vor__mw_from_i64(b, VOR__HPOINT_LIMBS, vy);
    mul_signed(r, VOR__HPOINT_LIMBS, a, b, VOR__HPOINT_LIMBS);
    vor__mw_from_i64(a, VOR__HPOINT_LIMBS, uy);
    vor__mw_from_i64(b, VOR__HPOINT_LIMBS, vx);
    mul_signed(t, VOR__HPOINT_LIMBS, a, b, VOR__HPOINT_LIMBS);
    vor__mw_sub(r, t, VOR__HPOINT_LIMBS);
}

/* r = s W + e T (|s| < 2^31, |e| < 2^33, |W|, |T| < 2^66). */
static void coordinate(vor__limb *r, int64_t s, const vor__limb *w, int64_t e, const vor__limb *t)
{
    vor__limb a[VOR__HPOINT_LIMBS];
    vor__limb p[VOR__HPOINT_LIMBS];
    vor__mw_from_i64(a, VOR__HPOINT_LIMBS, s);
    mul_signed(r, VOR__HPOINT_LIMBS, a, w, VOR__HPOINT_LIMBS);
    vor__mw_from_i64(a, VOR__HPOINT_LIMBS, e);
    mul_signed(p, VOR__HPOINT_LIMBS, a, t, VOR__HPOINT_LIMBS);
    vor__mw_add(r, p, VOR__HPOINT_LIMBS);
}

bool vor__hpoint_crossing(vor__hpoint_t *h, vor_point_t a, vor_point_t b, vor_point_t c,
                          vor_point_t d)
{
    /* a + t (b - a) with t = ((c - a) x (d - c)) / ((b - a) x (d - c)) */
    int64_t bax = (int64_t)b.x - a.x;
    int64_t bay = (int64_t)b.y - a.y;
    int64_t dcx = (int64_t)d.x - c.x;
    int64_t dcy = (int64_t)d.y - c.y;
    vor__limb w[VOR__HPOINT_LIMBS];
    vor__limb t[VOR__HPOINT_LIMBS];
    cross128(w, bax, bay, dcx, dcy);
    if (vor__mw_sign(w, VOR__HPOINT_LIMBS) == 0) {
        return false;
    }
    cross128(t, (int64_t)c.x - a.x, (int64_t)c.y - a.y, dcx, dcy);
    coordinate(h->x, a.x, w, bax, t);
    coordinate(h->y, a.y, w, bay, t);
    for (size_t i = 0; i < VOR__HPOINT_LIMBS; i++) {
        h->w[i] = w[i];
    }
    if (negative(w, VOR__HPOINT_LIMBS)) { /* W > 0: the same point */
        vor__mw_neg(h->x, VOR__HPOINT_LIMBS);
        vor__mw_neg(h->y, VOR__HPOINT_LIMBS);
        vor__mw_neg(h->w, VOR__HPOINT_LIMBS);
    }
    return true;
}

/* ------------------------------------------------------------------ */
/* Determinants                                                        */

/* r = a b - c d for entries (a 2 x 2 minor). */
static void minor2(vor__limb *r, const vor__limb *a, const vor__limb *b, const vor__limb *c,
                   const vor__limb *d)
{
    vor__limb x[MINOR_LIMBS];
    vor__limb y[MINOR_LIMBS];
    vor__limb t[MINOR_LIMBS];
    widen(x, MINOR_LIMBS, a, ENTRY_LIMBS);
    widen(y, MINOR_LIMBS, b, ENTRY_LIMBS);
    mul_signed(r, MINOR_LIMBS, x, y, MINOR_LIMBS);
    widen(x, MINOR_LIMBS, c, ENTRY_LIMBS);
    widen(y, MINOR_LIMBS, d, ENTRY_LIMBS);
    mul_signed(t, MINOR_LIMBS, x, y, MINOR_LIMBS);
    vor__mw_sub(r, t, MINOR_LIMBS);
}

/* acc += s m n for minors m, n (s = +-1). */
static void add_product(vor__limb *acc, const vor__limb *m, const vor__limb *n, int s)
{
    vor__limb p[DET_LIMBS];
    vor__limb mm[MINOR_LIMBS];
    vor__limb mn[MINOR_LIMBS];
    bool neg = negative(m, MINOR_LIMBS) != negative(n, MINOR_LIMBS);
    for (size_t i = 0; i < MINOR_LIMBS; i++) {
        mm[i] = m[i];
        mn[i] = n[i];
    }
    if (negative(mm, MINOR_LIMBS)) {
        vor__mw_neg(mm, MINOR_LIMBS);
    }
    if (negative(n, MINOR_LIMBS)) {
        vor__mw_neg(mn, MINOR_LIMBS);
    }
    /* the magnitudes (below 2^326) multiplied unsigned */
    vor__mw_mul(p, DET_LIMBS, mm, MINOR_LIMBS, mn, MINOR_LIMBS);
    bool subtract = s < 0;
    if (neg != subtract) {
        vor__mw_sub(acc, p, DET_LIMBS);
    } else {
        vor__mw_add(acc, p, DET_LIMBS);
    }
}

/* Sign of the 4 x 4 determinant of rows e[r][0..4), by the Laplace
 * expansion along columns 0, 1: the six 2 x 2 minors of those columns
 * times the complementary minors of columns 2, 3. */
static int det4_sign(entry_t e[4][4])
{
    static const unsigned pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    static const int signs[6] = {1, -1, 1, 1, -1, 1};
    vor__limb acc[DET_LIMBS];
    vor__limb left[MINOR_LIMBS];
    vor__limb right[MINOR_LIMBS];
    for (size_t i = 0; i < DET_LIMBS; i++) {
        acc[i] = 0;
    }
    for (unsigned k = 0; k < 6u; k++) {
        unsigned i = pairs[k][0];
        unsigned j = pairs[k][1];
        unsigned p = pairs[5u - k][0]; /* the complementary rows */
        unsigned q = pairs[5u - k][1];
        minor2(left, e[i][0], e[j][1], e[j][0], e[i][1]);
        minor2(right, e[p][2], e[q][3], e[q][2], e[p][3]);
        add_product(acc, left, right, signs[k]);
    }
    return vor__mw_sign(acc, DET_LIMBS);
}

/* Sign of the 3 x 3 determinant of rows e[r][0..3), along column 2. */
static int det3_sign(entry_t e[3][4])
{
    static const unsigned pairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    static const int signs[3] = {1, -1, 1};
    vor__limb acc[DET_LIMBS];
    vor__limb left[MINOR_LIMBS];
    vor__limb right[MINOR_LIMBS];
    for (size_t i = 0; i < DET_LIMBS; i++) {
        acc[i] = 0;
    }
    for (unsigned k = 0; k < 3u; k++) {
        unsigned i = pairs[k][0];
        unsigned j = pairs[k][1];
        minor2(left, e[i][0], e[j][1], e[j][0], e[i][1]);
        widen(right, MINOR_LIMBS, e[k][2], ENTRY_LIMBS);
        add_product(acc, left, right, signs[k]);
    }
    return vor__mw_sign(acc, DET_LIMBS);
}

/* ------------------------------------------------------------------ */
/* Rows                                                                */

static void entry_zero(vor__limb *r)
{
    for (size_t i = 0; i < ENTRY_LIMBS; i++) {
        r[i] = 0;
    }
}

static void entry_from(vor__limb *r, const vor__limb *a)
{
    widen(r, ENTRY_LIMBS, a, VOR__HPOINT_LIMBS);
}

/* r = a b for hpoint values (below 2^66 + 2^97 bits: in the entry). */
static void entry_product(vor__limb *r, const vor__limb *a, const vor__limb *b)
{
    vor__limb x[ENTRY_LIMBS];
    vor__limb y[ENTRY_LIMBS];
    widen(x, ENTRY_LIMBS, a, VOR__HPOINT_LIMBS);
    widen(y, ENTRY_LIMBS, b, VOR__HPOINT_LIMBS);
    mul_signed(r, ENTRY_LIMBS, x, y, ENTRY_LIMBS);
}

/* The incircle row of kind k for h, scaled as the file comment says. */
static void incircle_row(entry_t row[4], const vor__hpoint_t *h, enum term_row k)
{
    for (unsigned c = 0; c < 4u; c++) {
        entry_zero(row[c]);
    }
    if (k == KIND_POINT) {
        vor__limb t[ENTRY_LIMBS];
        entry_product(row[0], h->x, h->w);
        entry_product(row[1], h->y, h->w);
        entry_product(row[2], h->x, h->x);
        entry_product(t, h->y, h->y);
        vor__mw_add(row[2], t, ENTRY_LIMBS);
        entry_product(row[3], h->w, h->w);
    } else if ((k == KIND_DY) || (k == KIND_DX)) {
        entry_from(row[(k == KIND_DY) ? 1u : 0u], h->w);
        entry_from(row[2], (k == KIND_DY) ? h->y : h->x);
        vor__mw_add(row[2], row[2], ENTRY_LIMBS); /* 2Y or 2X */
    } else {
        row[2][0] = 1u;
    }
}

/* The orientation row of kind k (KIND_POINT, KIND_DY or KIND_DX). */
static void orient_row(entry_t row[4], const vor__hpoint_t *h, enum term_row k)
{
    for (unsigned c = 0; c < 4u; c++) {
        entry_zero(row[c]);
    }
    if (k == KIND_POINT) {
        entry_from(row[0], h->x);
        entry_from(row[1], h->y);
        entry_from(row[2], h->w);
    } else {
        row[(k == KIND_DY) ? 1u : 0u][0] = 1u;
    }
}

int vor__orient_h(const vor__hpoint_t *p, const vor__hpoint_t *q, const vor__hpoint_t *r)
{
    entry_t e[3][4];
    orient_row(e[0], p, KIND_POINT);
    orient_row(e[1], q, KIND_POINT);
    orient_row(e[2], r, KIND_POINT);
    return det3_sign(e);
}

int vor__incircle_h(const vor__hpoint_t *p, const vor__hpoint_t *q, const vor__hpoint_t *r,
                    const vor__hpoint_t *s)
{
    entry_t e[4][4];
    incircle_row(e[0], p, KIND_POINT);
    incircle_row(e[1], q, KIND_POINT);
    incircle_row(e[2], r, KIND_POINT);
    incircle_row(e[3], s, KIND_POINT);
    return det4_sign(e);
}

/* ------------------------------------------------------------------ */
/* The perturbation                                                    */

/* rank[k]: how many of ids are below ids[k]. */
static void ranks_of(const uint32_t *ids, unsigned n, unsigned *rank)
{
    for (unsigned k = 0; k < n; k++) {
        rank[k] = 0;
        for (unsigned j = 0; j < n; j++) {
            rank[k] += (ids[j] < ids[k]) ? 1u : 0u;
        }
    }
}

int vor__orient_h_sos(const vor__hpoint_t *const v[3], const uint32_t ids[3])
{
    static const enum term_row kinds[3] = {KIND_POINT, KIND_DY, KIND_DX};
    unsigned rank[3];
    ranks_of(ids, 3u, rank);
    entry_t e[3][4];
    /* the kinds by rank, the top rank's most significant: increasing
     * exponents (nested loops: no division) */
    unsigned digit[3];
    for (unsigned d2 = 0; d2 < 3u; d2++) {
        for (unsigned d1 = 0; d1 < 3u; d1++) {
            for (unsigned d0 = 0; d0 < 3u; d0++) {
                digit[0] = d0;
                digit[1] = d1;
                digit[2] = d2;
                for (unsigned k = 0; k < 3u; k++) {
                    orient_row(e[k], v[k], kinds[digit[rank[k]]]);
                }
                int sign = det3_sign(e);
                if (sign != 0) {
                    return sign;
                }
            }
        }
    }
    return 0; /* distinct ids never get here */
}

/* The incircle term of the kinds digit[rank]: its sign (0 for two square
 * rows, which are equal). */
static int incircle_term(const vor__hpoint_t *const v[4], const unsigned rank[4],
                         const unsigned digit[4])
{
    static const enum term_row kinds[5] = {KIND_POINT, KIND_DY, KIND_DY2, KIND_DX, KIND_DX2};
    unsigned squares = 0;
    for (unsigned r = 0; r < 4u; r++) {
        squares += ((digit[r] == 2u) || (digit[r] == 4u)) ? 1u : 0u;
    }
    if (squares > 1u) {
        return 0;
    }
    entry_t e[4][4];
    for (unsigned k = 0; k < 4u; k++) {
        incircle_row(e[k], v[k], kinds[digit[rank[k]]]);
    }
    return det4_sign(e);
}

int vor__incircle_h_sos(const vor__hpoint_t *const v[4], const uint32_t ids[4])
{
    unsigned rank[4];
    ranks_of(ids, 4u, rank);
    unsigned digit[4];
    for (unsigned d3 = 0; d3 < 5u; d3++) {
        for (unsigned d2 = 0; d2 < 5u; d2++) {
            for (unsigned d1 = 0; d1 < 5u; d1++) {
                for (unsigned d0 = 0; d0 < 5u; d0++) {
                    digit[0] = d0;
                    digit[1] = d1;
                    digit[2] = d2;
                    digit[3] = d3;
                    int sign = incircle_term(v, rank, digit);
                    if (sign != 0) {
                        return sign;
                    }
                }
            }
        }
    }
    return 0; /* distinct ids never get here */
}

int vor__compare_h(const vor__hpoint_t *p, const vor__hpoint_t *q, unsigned axis)
{
    /* p / pw - q / qw has the sign of p qw - q pw (pw, qw > 0) */
    vor__limb a[ENTRY_LIMBS];
    vor__limb b[ENTRY_LIMBS];
    entry_product(a, (axis == 0u) ? p->x : p->y, q->w);
    entry_product(b, (axis == 0u) ? q->x : q->y, p->w);
    vor__mw_sub(a, b, ENTRY_LIMBS);
    return vor__mw_sign(a, ENTRY_LIMBS);
}
