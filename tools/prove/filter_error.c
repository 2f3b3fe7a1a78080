/* SPDX-License-Identifier: MIT */
/*
 * filter_error.c - a bound, proven by exact interval arithmetic, on the
 * rounding error of the two filters of src/predicates.c that evaluate a
 * polynomial of differences cut to 15 bits (32-bit limbs): the mid
 * incircle tier's determinant P (degree 4) and the perturbed incircle's
 * first term T (degree 3). Run by make prove (tools/prove/prove.sh).
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
 *   filter_error            (exit 0 and "2 passed, 0 failed" when proven)
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

/* Enclosures of the gradient's components over a box (scaled by S^(k-1)). */
typedef int (*gradient_t)(const iv_t *v, iv_t *g);

/* P = za Ka + zb Kb + zc Kc, z = x^2 + y^2, Ka = b x c (vor__incircle_narrow). */
static int incircle_gradient(const iv_t *v, iv_t *g)
{
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
    return 6;
}

/* T = 2 yl (xp yq - yp xq) - xp zq + xq zp (first_term_narrow). */
static int first_term_gradient(const iv_t *v, iv_t *g)
{
    iv_t yl = v[0], xp = v[1], yp = v[2], xq = v[3], yq = v[4];
    iv_t zp = add(square(xp), square(yp)), zq = add(square(xq), square(yq));
    g[0] = times(2, sub(mul(xp, yq), mul(yp, xq)));
    g[1] = add(sub(times(2, mul(yl, yq)), zq), times(2, mul(xq, xp)));
    g[2] = times(2, sub(mul(xq, yp), mul(yl, xq)));
    g[3] = sub(zp, times(2, add(mul(yl, yp), mul(xp, xq))));
    g[4] = times(2, sub(mul(yl, xp), mul(xp, yq)));
    return 5;
}

/* Does h stay at or below `limit` (scaled by S^(k-1)) on the box? */
static int box_ok(gradient_t gradient, const int64_t *lo, const int64_t *hi, int dims,
                  wide_t limit, wide_t *bound)
{
    iv_t v[DIMS_MAX], g[DIMS_MAX];
    for (int k = 0; k < dims; k++) {
        v[k] = iv(lo[k], hi[k]);
    }
    int n = gradient(v, g);
    wide_t up = 0, down = 0;
    for (int k = 0; k < n; k++) {
        up += (g[k].hi > 0) ? g[k].hi : 0;
        down += (g[k].lo < 0) ? -g[k].lo : 0;
    }
    *bound = (up > down) ? up : down;
    return *bound <= limit;
}

/* Branch and bound over [-1, 1]^dims: 1 when h <= limit / S^(k-1)
 * everywhere; *worst the largest accepted box's enclosure, *boxes the
 * boxes looked at. */
static int prove_h(gradient_t gradient, int dims, int degree, wide_t limit, wide_t *worst,
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
        wide_t bound;
        if (box_ok(gradient, lo, hi, dims, limit * scale, &bound)) {
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
static int filter(const char *name, gradient_t gradient, int dims, int degree, int limit,
                  int64_t coefficients, double code_bound)
{
    wide_t worst;
    long boxes;
    if (!prove_h(gradient, dims, degree, limit, &worst, &boxes)) {
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

int main(void)
{
    int passed = 0;
    /* incircle_filter: 12 monomials, the code's bound 3 2^46 + 2^35 */
    passed += filter("mid incircle determinant", incircle_gradient, 6, 4, 17, 12,
                     3.0 * 70368744177664.0 + 34359738368.0);
    /* first_terms: 6 monomials of coefficients 2, 2, 1, 1, 1, 1, bound 2^33 */
    passed += filter("perturbed incircle's first term", first_term_gradient, 5, 3, 15, 8,
                     8589934592.0);
    printf("%d passed, %d failed\n", passed, 2 - passed);
    return (passed == 2) ? 0 : 1;
}
