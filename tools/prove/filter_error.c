/* SPDX-License-Identifier: MIT */
/*
 * filter_error.c - bounds, proven by exact interval arithmetic, on the
 * rounding errors of the two filters of src/predicates.c that evaluate a
 * polynomial of differences cut to 15 bits (32-bit limbs): the mid
 * incircle tier's determinant P (degree 4), against its bound and its
 * finer bound from the points' sizes, and the perturbed incircle's first
 * term T (degree 3). Run by make prove (tools/prove/prove.sh).
 *
 * A filter takes each entry d = 2^s u + r, 0 <= r < 2^s, |u| <= A = 2^14,
 * and evaluates the polynomial F of the u exactly; F(d) = 2^(ks) F(u + rho)
 * with rho = r / 2^s in [0, 1) per entry (k the degree). So the error, in
 * units of 2^(ks), is F(u + rho) - F(u): its first-order part is the
 * gradient at u times rho, and the rest is at most the sum over F's
 * monomials of |c| ((A + 1)^k - A^k - k A^(k-1)) (every derivative of a
 * monomial is largest at the box's corner). The code bounds the first
 * order as crudely, by |c| k A^(k-1) per monomial. Here, with rho >= 0,
 * the first order lies between -(the sum of the gradient's negative
 * components) and the sum of its positive ones, and by homogeneity that
 * is A^(k-1) h(u / A), h(v) = max(sum of g_i(v)^+, sum of g_i(v)^-) for v
 * in [-1, 1]^n. This program proves h <= H by branch and bound: the cube
 * is split until each box's interval enclosure of every g_i (natural
 * interval extension, exact in integers: the box corners are multiples
 * of 2^-SCALE_BITS) gives at most H. Prints each filter's proven error
 * bound beside the code's; fails if a bound cannot be proven below the
 * code's.
 *
 * Third, the incircle filter's finer bound (vor__incircle_point_bound,
 * src/predicates.h), 4 (6abc + a^2 (b + c) + b^2 (c + a) + c^2 (a + b))
 * with a, b, c the sizes max(|x|, |y|) + 1 of the three points u: with
 * p' = p + rho (a point's entries and their remainders), the error is
 * the sum over the three terms L(p) X(q, r) (L = x^2 + y^2, X the cross
 * product) of (L(p') - L(p)) X(q', r') + L(p) (X(q', r') - X(q, r)).
 * There |L(p') - L(p)| = |2 p'.rho - |rho|^2| <= 2 h(p') + 2, with h(p')
 * = max(p'x+ + p'y+, p'x- + p'y-) the largest |p'.t| over t in [0, 1]^2,
 * and |X(q', r')| <= 2bc; |X(q', r') - X(q, r)| <= 2 (b - 1) + 2 (c - 1)
 * + 1 and L(p) <= 2 (a - 1)^2. With p' = a p^ (p^ in [-1, 1]^2) the first
 * parts sum to at most 2abc G + 4 (ab + bc + ca), G = the sum over the
 * terms of h(p^) |X(q^, r^)|, and the second parts to 4 sum a^2 (b + c) -
 * 16 (ab + bc + ca) + 8 (a + b + c) - 6 sum (a - 1)^2; as ab + bc + ca >=
 * a + b + c for sizes >= 1, the error is below 2abc G + 4 sum a^2 (b + c).
 * This program proves G <= 9 on [-1, 1]^6 by the same branch and bound
 * (a search finds 8, at corners), so the error is below 4 (4.5abc + sum
 * a^2 (b + c)): the code's 6abc has room, and a bound with 5abc would
 * hold too.
 *   filter_error            (exit 0 and "3 passed, 0 failed" when proven)
 */
#include <stdint.h>
#include <stdio.h>

#define SCALE_BITS 12
#define S ((int64_t)1 << SCALE_BITS) /* the cube [-1, 1] is [-S, S] */
#define DIMS_MAX 6
#define STACK_MAX 4096

typedef __int128 wide_t;
typedef struct {
    wide_t lo;
    wide_t hi;
} iv_t;

static iv_t iv(wide_t lo, wide_t hi)
{
    iv_t r = {lo, hi};
    return r;
}
static iv_t add(iv_t a, iv_t b)
{
    return iv(a.lo + b.lo, a.hi + b.hi);
}
static iv_t sub(iv_t a, iv_t b)
{
    return iv(a.lo - b.hi, a.hi - b.lo);
}
static iv_t times(wide_t c, iv_t a) /* c >= 0 */
{
    return iv(c * a.lo, c * a.hi);
}
static iv_t mul(iv_t a, iv_t b)
{
    wide_t p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    iv_t r = {p[0], p[0]};
    for (int k = 1; k < 4; k++) {
        r.lo = (p[k] < r.lo) ? p[k] : r.lo;
        r.hi = (p[k] > r.hi) ? p[k] : r.hi;
    }
    return r;
}
static iv_t square(iv_t a)
{
    wide_t l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.lo >= 0) {
        return iv(l, h);
    }
    if (a.hi <= 0) {
        return iv(h, l);
    }
    return iv(0, (l > h) ? l : h);
}

/* An upper bound, over a box, of the quantity a branch and bound holds
 * below its limit (scaled by S^(k-1)). */
typedef wide_t (*enclosure_t)(const iv_t *v);

/* The first order of a filter's error: with every rho >= 0 it lies
 * between -(the sum of the gradient's negative components) and the sum of
 * its positive ones, of the n enclosures g. */
static wide_t first_order(const iv_t *g, int n)
{
    wide_t up = 0, down = 0;
    for (int k = 0; k < n; k++) {
        up += (g[k].hi > 0) ? g[k].hi : 0;
        down += (g[k].lo < 0) ? -g[k].lo : 0;
    }
    return (up > down) ? up : down;
}

/* P = za Ka + zb Kb + zc Kc, z = x^2 + y^2, Ka = b x c (vor__incircle_narrow). */
static wide_t incircle_first_order(const iv_t *v)
{
    iv_t g[6];
    iv_t ax = v[0], ay = v[1], bx = v[2], by = v[3], cx = v[4], cy = v[5];
    iv_t za = add(square(ax), square(ay)), zb = add(square(bx), square(by));
    iv_t zc = add(square(cx), square(cy));
    iv_t ka = sub(mul(bx, cy), mul(by, cx)), kb = sub(mul(cx, ay), mul(cy, ax));
    iv_t kc = sub(mul(ax, by), mul(ay, bx));
    g[0] = add(sub(times(2, mul(ax, ka)), mul(zb, cy)), mul(zc, by));
    g[1] = sub(add(times(2, mul(ay, ka)), mul(zb, cx)), mul(zc, bx));
    g[2] = add(sub(times(2, mul(bx, kb)), mul(zc, ay)), mul(za, cy));
    g[3] = sub(add(times(2, mul(by, kb)), mul(zc, ax)), mul(za, cx));
    g[4] = add(sub(times(2, mul(cx, kc)), mul(za, by)), mul(zb, ay));
    g[5] = sub(add(times(2, mul(cy, kc)), mul(za, bx)), mul(zb, ax));
    return first_order(g, 6);
}

/* T = 2 yl (xp yq - yp xq) - xp zq + xq zp (first_term_narrow). */
static wide_t first_term_first_order(const iv_t *v)
{
    iv_t g[5];
    iv_t yl = v[0], xp = v[1], yp = v[2], xq = v[3], yq = v[4];
    iv_t zp = add(square(xp), square(yp)), zq = add(square(xq), square(yq));
    g[0] = times(2, sub(mul(xp, yq), mul(yp, xq)));
    g[1] = add(sub(times(2, mul(yl, yq)), zq), times(2, mul(xq, xp)));
    g[2] = times(2, sub(mul(xq, yp), mul(yl, xq)));
    g[3] = sub(zp, times(2, add(mul(yl, yp), mul(xp, xq))));
    g[4] = times(2, sub(mul(yl, xp), mul(xp, yq)));
    return first_order(g, 5);
}

/* h over a box of one point: max(x+ + y+, x- + y-) at its far corners. */
static wide_t h_max(iv_t x, iv_t y)
{
    wide_t up = ((x.hi > 0) ? x.hi : 0) + ((y.hi > 0) ? y.hi : 0);
    wide_t down = ((x.lo < 0) ? -x.lo : 0) + ((y.lo < 0) ? -y.lo : 0);
    return (up > down) ? up : down;
}
static wide_t magnitude_max(iv_t a)
{
    return (-a.lo > a.hi) ? -a.lo : a.hi;
}

/* G = h(a) |X(b, c)| + h(b) |X(c, a)| + h(c) |X(a, b)| (scaled by S^3). */
static wide_t point_products(const iv_t *v)
{
    iv_t ax = v[0], ay = v[1], bx = v[2], by = v[3], cx = v[4], cy = v[5];
    iv_t ka = sub(mul(bx, cy), mul(by, cx)), kb = sub(mul(cx, ay), mul(cy, ax));
    iv_t kc = sub(mul(ax, by), mul(ay, bx));
    return h_max(ax, ay) * magnitude_max(ka) + h_max(bx, by) * magnitude_max(kb) +
           h_max(cx, cy) * magnitude_max(kc);
}

/* Branch and bound over [-1, 1]^dims: 1 when h <= limit / S^(k-1)
 * everywhere; *worst the largest accepted box's enclosure, *boxes the
 * boxes looked at. */
static int prove_h(enclosure_t enclosure, int dims, int degree, wide_t limit, wide_t *worst,
                   long *boxes)
{
    static int64_t stack_lo[STACK_MAX][DIMS_MAX], stack_hi[STACK_MAX][DIMS_MAX];
    int top = 0;
    for (int k = 0; k < dims; k++) {
        stack_lo[0][k] = -S;
        stack_hi[0][k] = S;
    }
    top = 1;
    *worst = 0;
    *boxes = 0;
    wide_t scale = 1;
    for (int k = 1; k < degree; k++) {
        scale *= S;
    }
    while (top > 0) {
        top--;
        int64_t lo[DIMS_MAX], hi[DIMS_MAX];
        for (int k = 0; k < dims; k++) {
            lo[k] = stack_lo[top][k];
            hi[k] = stack_hi[top][k];
        }
        (*boxes)++;
        iv_t v[DIMS_MAX];
        for (int k = 0; k < dims; k++) {
            v[k] = iv(lo[k], hi[k]);
        }
        wide_t bound = enclosure(v);
        if (bound <= limit * scale) {
            *worst = (bound > *worst) ? bound : *worst;
            continue;
        }
        int widest = 0;
        for (int k = 1; k < dims; k++) {
            widest = (hi[k] - lo[k] > hi[widest] - lo[widest]) ? k : widest;
        }
        if (hi[widest] - lo[widest] < 2 || top + 2 > STACK_MAX) {
            return 0; /* no finer box: not proven at this limit */
        }
        int64_t mid = lo[widest] + (hi[widest] - lo[widest]) / 2;
        for (int half = 0; half < 2; half++) {
            for (int k = 0; k < dims; k++) {
                stack_lo[top][k] = lo[k];
                stack_hi[top][k] = hi[k];
            }
            if (half == 0) {
                stack_hi[top][widest] = mid;
            } else {
                stack_lo[top][widest] = mid;
            }
            top++;
        }
    }
    return 1;
}

static double as_double(wide_t v)
{
    return (double)v;
}

/* One filter: h <= limit proven, then its error bound in units of the
 * filter's 2^(ks) against the code's. */
static int filter(const char *name, enclosure_t enclosure, int dims, int degree, int limit,
                  int64_t coefficients, double code_bound)
{
    wide_t worst;
    long boxes;
    if (!prove_h(enclosure, dims, degree, limit, &worst, &boxes)) {
        printf("filter_error: %s: h <= %d not proven (%ld boxes)\n", name, limit, boxes);
        return 0;
    }
    double scale = 1.0;
    for (int k = 1; k < degree; k++) {
        scale *= (double)S;
    }
    /* the rest beyond the first order: |c| ((A + 1)^k - A^k - k A^(k-1)) */
    wide_t a = (wide_t)1 << 14, power = 1, next = 1;
    for (int k = 0; k < degree; k++) {
        power *= a;
        next *= a + 1;
    }
    wide_t rest = coefficients * (next - power - degree * (power / a));
    /* first order: h A^(k-1), h <= worst / S^(k-1), rounded up */
    wide_t first = (worst * (power / a) + (wide_t)(scale - 1.0)) / (wide_t)scale;
    wide_t error = first + rest;
    int ok = as_double(error) < code_bound;
    printf("filter_error: %s: h <= %.4f (%ld boxes), error < %.6g = 2^%.4f; the code's bound "
           "%.6g = 2^%.4f\n",
           name, as_double(worst) / scale, boxes, as_double(error), __builtin_log2(as_double(error)),
           code_bound, __builtin_log2(code_bound));
    return ok;
}

/* The point bound: G <= limit proven, so that the error stays below
 * 4 (limit / 2 abc + sum a^2 (b + c)) (the file's comment), against the
 * code's 6abc. */
static int point_bound(int limit)
{
    wide_t worst;
    long boxes;
    if (!prove_h(point_products, 6, 4, limit, &worst, &boxes)) {
        printf("filter_error: point bound: G <= %d not proven (%ld boxes)\n", limit, boxes);
        return 0;
    }
    double scale = (double)S * (double)S * (double)S;
    printf("filter_error: point bound: G <= %.4f (%ld boxes), error < 4 (%.4f abc + sum a^2 (b + "
           "c)); the code's bound 4 (6 abc + sum a^2 (b + c))\n",
           as_double(worst) / scale, boxes, as_double(worst) / scale / 2.0);
    return limit < 2 * 6;
}

int main(void)
{
    int passed = 0;
    /* incircle_filter: 12 monomials, the code's bound 3 2^46 + 2^35 */
    passed += filter("mid incircle determinant", incircle_first_order, 6, 4, 17, 12,
                     3.0 * 70368744177664.0 + 34359738368.0);
    /* first_terms: 6 monomials of coefficients 2, 2, 1, 1, 1, 1, bound 2^33 */
    passed += filter("perturbed incircle's first term", first_term_first_order, 5, 3, 15, 8,
                     8589934592.0);
    /* vor__incircle_point_bound: G <= 9, so 4.5abc for the code's 6abc */
    passed += point_bound(9);
    printf("%d passed, %d failed\n", passed, 3 - passed);
    return (passed == 3) ? 0 : 1;
}
