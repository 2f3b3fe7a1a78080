/*
 * raster_euclid.c - the fast exact path for Euclidean point sites.
 *
 * Along a row v (world y relative to the first pixel), the squared
 * distance from pixel u to site (a, b) (coordinates relative to the first
 * pixel centre) is (u - a)^2 + (v - b)^2. Dropping u^2, which every site
 * shares, leaves a line in u:
 *
 *     g(u) = a^2 + (v - b)^2 - 2 a u,
 *
 * so the nearest site along the row is the lower envelope of one line per
 * site, and along the row the winner changes only where two lines cross.
 * The envelope of lines sorted by slope is a stack walk (the "convex hull
 * trick"), and the pixels are then walked with one 64-bit addition each:
 * the difference of the current line and the next one grows by a constant
 * per pixel, and the next site takes over when it stops being negative.
 *
 * Which sites can win in a band of rows? A closed Voronoi cell that meets
 * the band's rectangle R of pixel centres either lies inside R (then so
 * does its site) or crosses the boundary of R, and the cells crossing an
 * edge of R are the envelope of that edge, with ties kept. So the
 * candidates of a band are: the sites inside R, plus the envelopes of R's
 * top and bottom edges (computed per band) and of its left and right edges
 * (pieces of two envelopes of the whole frame edges, computed once). The
 * envelope of each row then takes only the candidates.
 *
 * Bit budget (vor__euclid_fits): every relative coordinate a, b lies in
 * (-2^29, 2^29) and every pixel offset u, v in [0, 2^29). Then |v - b| <
 * 2^30, values a^2 + (v - b)^2 < 2^58 + 2^60 < 2^61, |2 a u| < 2^59, so a
 * line's value and the difference of two lines fit int64; the envelope
 * test multiplies a value difference (< 2^61) by a slope difference
 * (< 2^30) and compares 96-bit products exactly (wide_mul below).
 */
#include "raster.h"

#include "multiword.h"

#define BUDGET ((int64_t)1 << 29)

/* A 32-bit division instruction (Cortex-M3/M4, RV32IM, 64-bit hosts):
 * then run lengths come from one division. Without one (Cortex-M0) the
 * compiler would call a library routine, so the walk steps pixel by
 * pixel instead. */
#if defined(__ARM_FEATURE_IDIV) || defined(__riscv_div) || defined(__x86_64__) ||              \
    defined(__aarch64__)
#define HARDWARE_DIVIDE 1
#else
#define HARDWARE_DIVIDE 0
#endif
#define NARROW ((int64_t)1 << 14)
#define MID ((int64_t)1 << 19)

int vor__euclid_fits(const vor_raster_frame_t *frame, const vor_point_t *points, uint32_t n)
{
    if (vor__offset(frame->width - 1u, frame->step_x) >= BUDGET ||
        vor__offset(frame->height - 1u, frame->step_y) >= BUDGET) {
        return 0;
    }
    for (uint32_t k = 0; k < n; k++) {
        int64_t a = (int64_t)points[k].x - frame->origin_x;
        int64_t b = (int64_t)points[k].y - frame->origin_y;
        if (a <= -BUDGET || a >= BUDGET || b <= -BUDGET || b >= BUDGET) {
            return 0;
        }
    }
    return 1;
}

/* ---------------------------------------------------------------- sort */

/* Site order by (coordinate, id): x when by_y is 0, else y. */
static int precedes(const vor_point_t *p, uint32_t i, uint32_t j, int by_y)
{
    int32_t ci = by_y ? p[i].y : p[i].x;
    int32_t cj = by_y ? p[j].y : p[j].x;
    return ci < cj || (ci == cj && i < j);
}

/* Heapsort of ids[0 .. n): no recursion, no memory. Each sift-down moves
 * one level per step, so it ends within log2(n) steps. */
static void sort_ids(uint32_t *ids, uint32_t n, const vor_point_t *p, int by_y)
{
    for (uint32_t k = 0; k < n; k++) {
        ids[k] = k;
    }
    for (uint32_t phase = 0; phase < 2u; phase++) {
        uint32_t count = (phase == 0u) ? n / 2u : n;
        while (count > 0u) {
            uint32_t size, root;
            if (phase == 0u) { /* heapify: sift down every inner node */
                count--;
                root = count;
                size = n;
            } else { /* take the maximum to the end */
                count--;
                uint32_t t = ids[0];
                ids[0] = ids[count];
                ids[count] = t;
                root = 0;
                size = count;
            }
            for (;;) {
                uint32_t child = 2u * root + 1u;
                if (child >= size) {
                    break;
                }
                if (child + 1u < size && precedes(p, ids[child], ids[child + 1u], by_y)) {
                    child++;
                }
                if (!precedes(p, ids[root], ids[child], by_y)) {
                    break;
                }
                uint32_t t = ids[root];
                ids[root] = ids[child];
                ids[child] = t;
                root = child;
            }
        }
    }
}

/* ---------------------------------------------------------- envelopes */

/* x * y as a 96-bit value hi * 2^32 + lo, for |x| < 2^62 and y < 2^31. */
typedef struct wide {
    int64_t hi;
    uint32_t lo;
} wide_t;

static wide_t wide_mul(int64_t x, uint32_t y)
{
    /* x = xh 2^32 + xl with xl in [0, 2^32), |xh| < 2^30 */
    uint32_t xl = (uint32_t)((uint64_t)x & 0xFFFFFFFFu);
    int32_t xh = (int32_t)((x - (int64_t)xl) / 4294967296); /* exact: constant divisor */
    uint64_t low = vor__mul_u32(xl, y);                     /* < 2^63 */
    wide_t r;
    r.hi = vor__mul_i32(xh, (int32_t)y) + (int64_t)(low >> 32); /* |.| < 2^62 */
    r.lo = (uint32_t)(low & 0xFFFFFFFFu);
    return r;
}

static int wide_greater(wide_t p, wide_t q)
{
    return p.hi > q.hi || (p.hi == q.hi && p.lo > q.lo);
}

/*
 * Lower envelope of the lines val[p] - 2 key[p] t, positions 0 .. m-1,
 * keys non-decreasing. Of lines with equal keys only the lowest is taken
 * (the first of the lowest, which is the smallest site id when equal keys
 * come in id order). A line is dropped only when it lies strictly above
 * the envelope everywhere: one that meets it in a single point is kept, so
 * that ties at that point can be resolved by index. The stack receives
 * the positions of the kept lines; their crossing points do not decrease.
 * Keys fit in (-2^29, 2^29) (differences < 2^30), values in [0, 2^61).
 */
#if defined(__GNUC__)
#define ENVELOPE_INLINE static inline __attribute__((always_inline))
#else
#define ENVELOPE_INLINE static inline
#endif

ENVELOPE_INLINE uint32_t envelope_impl(const int32_t *key, const int64_t *val, uint32_t m,
                                       uint32_t *stack, int narrow)
{
    uint32_t top = 0;
    uint32_t p = 0;
    while (p < m) {
        uint32_t rep = p;
        uint32_t q = p + 1u;
        while (q < m && key[q] == key[p]) {
            if (val[q] < val[rep]) {
                rep = q;
            }
            q++;
        }
        p = q;
        /* pop j (between i and rep) while its crossing with i lies
         * strictly right of its crossing with rep: then j is never lowest */
        while (top >= 2u) {
            uint32_t i = stack[top - 2u], j = stack[top - 1u];
            int greater;
            if (narrow == 1) { /* value differences fit int32, key ones 2^15 */
                int64_t left = vor__mul_i32((int32_t)(val[j] - val[i]), key[rep] - key[j]);
                int64_t right = vor__mul_i32((int32_t)(val[rep] - val[j]), key[j] - key[i]);
                greater = left > right;
            } else if (narrow == 2) { /* values < 2^41, key differences < 2^20 */
                int64_t left = vor__mul_i64_i32(val[j] - val[i], key[rep] - key[j]);
                int64_t right = vor__mul_i64_i32(val[rep] - val[j], key[j] - key[i]);
                greater = left > right;
            } else {
                wide_t left = wide_mul(val[j] - val[i], (uint32_t)(key[rep] - key[j]));
                wide_t right = wide_mul(val[rep] - val[j], (uint32_t)(key[j] - key[i]));
                greater = wide_greater(left, right);
            }
            if (!greater) {
                break;
            }
            top--;
        }
        stack[top++] = rep;
    }
    return top;
}

/* Tiers of the envelope test, by the largest relative coordinate or pixel
 * offset M. Narrow (1), M < 2^14: values < 2^28 + 2^30 < 2^31, so a value
 * difference fits int32 and its product with a key difference (< 2^15)
 * fits int64 from one 32x32 multiply. Mid (2), M < 2^19: values < 2^38 +
 * 2^40 < 2^41, key differences < 2^20, products < 2^61 in int64. Wide
 * (0), M < 2^29: 96-bit products (wide_mul). */
static uint32_t envelope(const vor__euclid_t *e, const int32_t *key, const int64_t *val,
                         uint32_t m, uint32_t *stack)
{
    if (e->narrow == 1) {
        return envelope_impl(key, val, m, stack, 1);
    }
    if (e->narrow == 2) {
        return envelope_impl(key, val, m, stack, 2);
    }
    return envelope_impl(key, val, m, stack, 0);
}

/* Does the crossing t* of lines i and j (key_i < key_j) satisfy
 * t* <= bound (le) or t* >= bound (ge)? t* = (val_j - val_i) / (2 (key_j -
 * key_i)); the denominator is positive, and 2 bound (key_j - key_i) <
 * 2^60 for 0 <= bound < 2^29. */
static int64_t crossing_scaled(int32_t dkey, int32_t bound)
{
    return 2 * vor__mul_i32(dkey, bound);
}

/* ------------------------------------------------------------- sites */

static int32_t rel_x(const vor__euclid_t *e, uint32_t id)
{
    return (int32_t)((int64_t)e->points[id].x - e->origin_x);
}

static int32_t rel_y(const vor__euclid_t *e, uint32_t id)
{
    return (int32_t)((int64_t)e->points[id].y - e->origin_y);
}

static int64_t square(int32_t x)
{
    return vor__mul_i32(x, x);
}

/* The line of site id along the vertical edge at pixel offset u_edge:
 * key b, value (a - u_edge)^2 + b^2. */
static int64_t vertical_val(const vor__euclid_t *e, uint32_t id, int32_t u_edge)
{
    return square(rel_x(e, id) - u_edge) + square(rel_y(e, id));
}

static int32_t frame_u(const vor__euclid_t *e)
{
    return (int32_t)(vor__offset(e->width - 1u, e->step_x));
}

/* Envelope of a vertical frame edge over every site (by_y order). */
static uint32_t vertical_envelope(vor__euclid_t *e, int32_t u_edge, uint32_t *out)
{
    for (uint32_t p = 0; p < e->n; p++) {
        uint32_t id = e->by_y[p];
        e->key[p] = rel_y(e, id);
        e->val[p] = vertical_val(e, id, u_edge);
    }
    uint32_t count = envelope(e, e->key, e->val, e->n, e->stack);
    for (uint32_t t = 0; t < count; t++) {
        out[t] = e->stack[t];
    }
    return count;
}

void vor__euclid_prepare(vor__euclid_t *e)
{
    sort_ids(e->by_x, e->n, e->points, 0);
    sort_ids(e->by_y, e->n, e->points, 1);
    for (uint32_t p = 0; p < e->n; p++) {
        e->sorted_x[p] = rel_x(e, e->by_x[p]);
        e->sorted_y[p] = rel_y(e, e->by_x[p]);
    }
    for (uint32_t k = 0; k < e->n; k++) {
        e->mark[k] = 0;
    }
    int64_t reach = vor__offset(e->width - 1u, e->step_x);
    int64_t tall = vor__offset(e->height - 1u, e->step_y);
    int64_t most = reach > tall ? reach : tall;
    for (uint32_t k = 0; k < e->n; k++) {
        int64_t a = rel_x(e, k), b = rel_y(e, k);
        a = a < 0 ? -a : a;
        b = b < 0 ? -b : b;
        most = a > most ? a : most;
        most = b > most ? b : most;
    }
    e->narrow = most < NARROW ? 1 : most < MID ? 2 : 0;
    e->left_count = vertical_envelope(e, 0, e->left);
    e->right_count = vertical_envelope(e, frame_u(e), e->right);
    e->band_valid = 0;
    e->inside_next = 0;
}

/* Marks the lines of a horizontal or vertical envelope whose pieces meet
 * [lo, hi], and every site tied with them (same key and value: equal
 * lines, whose closed cells all touch the edge). order maps positions to
 * sites; keyf/valf give a position's line. */
typedef struct edge_lines {
    const vor__euclid_t *e;
    const uint32_t *order;
    int vertical;  /* 0: key a, value a^2 + (v - b)^2; 1: key b, value (a - u)^2 + b^2 */
    int32_t fixed; /* v (horizontal edge) or u (vertical edge) */
} edge_lines_t;

static int32_t edge_key(const edge_lines_t *l, uint32_t pos)
{
    return l->vertical ? rel_y(l->e, l->order[pos]) : l->e->sorted_x[pos];
}

static int64_t edge_val(const edge_lines_t *l, uint32_t pos)
{
    return l->vertical ? vertical_val(l->e, l->order[pos], l->fixed)
                       : l->e->val[pos]; /* mark_horizontal's values */
}

static void mark_pieces(vor__euclid_t *e, const edge_lines_t *l, const uint32_t *hull,
                        uint32_t count, int32_t lo, int32_t hi, uint8_t flags)
{
    for (uint32_t t = 0; t < count; t++) {
        uint32_t pos = hull[t];
        int32_t key = edge_key(l, pos);
        int64_t val = edge_val(l, pos);
        if (t > 0u) { /* the piece starts at crossing(t-1, t): must be <= hi */
            uint32_t prev = hull[t - 1u];
            int32_t dkey = key - edge_key(l, prev);
            if (val - edge_val(l, prev) > crossing_scaled(dkey, hi)) {
                continue;
            }
        }
        if (t + 1u < count) { /* it ends at crossing(t, t+1): must be >= lo */
            uint32_t next = hull[t + 1u];
            int32_t dkey = edge_key(l, next) - key;
            if (edge_val(l, next) - val < crossing_scaled(dkey, lo)) {
                continue;
            }
        }
        /* the equal lines sit next to pos in the order (same key) */
        uint32_t first = pos;
        while (first > 0u && edge_key(l, first - 1u) == key) {
            first--;
        }
        for (uint32_t q = first; q < e->n && edge_key(l, q) == key; q++) {
            if (edge_val(l, q) == val) {
                e->mark[l->order[q]] |= flags;
            }
        }
    }
}

/* Envelope of the horizontal edge at row offset v, marked over [0, U]
 * with flags (bit 0: this band, bit 1: the next band). The keys are the
 * sites' relative x in by_x order (sorted_x), kept from prepare. */
static void mark_horizontal(vor__euclid_t *e, int32_t v, uint8_t flags)
{
    const int32_t *ax = e->sorted_x, *by = e->sorted_y;
    for (uint32_t p = 0; p < e->n; p++) {
        e->val[p] = square(ax[p]) + square(by[p] - v);
    }
    uint32_t count = envelope(e, ax, e->val, e->n, e->stack);
    edge_lines_t l = {e, e->by_x, 0, v};
    mark_pieces(e, &l, e->stack, count, 0, frame_u(e), flags);
}

/* Candidates of the band of rows [first, last]. Its rectangle reaches
 * down to the next band's first row (when there is one), so that its
 * bottom edge is the next band's top edge: that envelope is computed once
 * and marks both bands (bit 1 of a mark carries over to the next band). */
static void select_band(vor__euclid_t *e, uint32_t first, uint32_t last)
{
    int32_t v0 = (int32_t)(vor__offset(first, e->step_y));
    uint32_t bottom_row = (last + 1u < e->height) ? last + 1u : last;
    int32_t v1 = (int32_t)(vor__offset(bottom_row, e->step_y));
    int32_t u1 = frame_u(e);
    if (first == 0u) {
        mark_horizontal(e, v0, 1u);
    }
    if (v1 != v0) {
        mark_horizontal(e, v1, 3u);
    }
    edge_lines_t left = {e, e->by_y, 1, 0};
    mark_pieces(e, &left, e->left, e->left_count, v0, v1, 1u);
    edge_lines_t right = {e, e->by_y, 1, u1};
    mark_pieces(e, &right, e->right, e->right_count, v0, v1, 1u);
    /* sites inside the band's rectangle; bands come in increasing order,
     * so sites above the next band's top (v1) are never needed again */
    uint32_t p = e->inside_next;
    while (p < e->n && rel_y(e, e->by_y[p]) < v0) {
        p++;
    }
    uint32_t next = p;
    while (p < e->n && rel_y(e, e->by_y[p]) <= v1) {
        uint32_t id = e->by_y[p];
        int32_t a = rel_x(e, id);
        if (a >= 0 && a <= u1) {
            e->mark[id] |= 1u;
        }
        next += rel_y(e, id) < v1 ? 1u : 0u;
        p++;
    }
    e->inside_next = next;
    /* gather in (x, id) order, clearing the marks for the next band */
    uint32_t m = 0;
    for (uint32_t q = 0; q < e->n; q++) {
        uint32_t id = e->by_x[q];
        uint8_t flags = e->mark[id];
        e->mark[id] = (uint8_t)(flags >> 1);
        if ((flags & 1u) != 0u) {
            e->cand[m] = id;
            e->key[m] = e->sorted_x[q];
            m++;
        }
    }
    e->cand_count = m;
    e->band_first = first;
    e->band_last = last;
    e->band_valid = 1;
}

/* ---------------------------------------------------------------- rows */

static uint32_t emit(vor__run_t *runs, uint32_t count, uint32_t end, uint32_t site)
{
    if (count > 0u && runs[count - 1u].site == site) {
        runs[count - 1u].end = end;
        return count;
    }
    runs[count].end = end;
    runs[count].site = site;
    return count + 1u;
}

uint32_t vor__euclid_row(vor__euclid_t *e, uint32_t j, vor__run_t *runs)
{
    if (!e->band_valid || j > e->band_last) {
        uint32_t last = j + (VOR__CULL_ROWS - 1u);
        if (last >= e->height || last < j) {
            last = e->height - 1u;
        }
        select_band(e, j, last);
    }
    const int32_t v = (int32_t)(vor__offset(j, e->step_y));
    const uint32_t m = e->cand_count;
    const int32_t *key = e->key;
    int64_t *val = e->val;
    for (uint32_t q = 0; q < m; q++) {
        val[q] = square(key[q]) + square(rel_y(e, e->cand[q]) - v);
    }
    const uint32_t *hull = e->stack;
    const uint32_t hull_count = envelope(e, key, val, m, e->stack);

    /* walk the pixels: k is the envelope line of the current pixel */
    const uint32_t width = e->width;
    const int32_t step = e->step_x;
    uint32_t count = 0, k = 0, i = 0;
    while (i < width) {
        const int32_t u = (int32_t)(vor__offset(i, step));
        /* settle: g_k(u) - g_{k+1}(u); the values g_k(u), g_{k+1}(u), ...
         * fall to the lowest and then rise (crossings do not decrease) */
        int64_t d = 0;
        while (k + 1u < hull_count) {
            uint32_t c = hull[k], n = hull[k + 1u];
            d = (val[c] - val[n]) + 2 * vor__mul_i32(key[n] - key[c], u);
            if (d <= 0) {
                break;
            }
            k++;
        }
        if (k + 1u < hull_count && d == 0) {
            /* u is a crossing: every line equal here is nearest, the
             * smallest id wins; after u the last of them is lowest */
            uint32_t best = e->cand[hull[k]];
            uint32_t last = k + 1u;
            for (;;) {
                uint32_t id = e->cand[hull[last]];
                best = id < best ? id : best;
                if (last + 1u >= hull_count) {
                    break;
                }
                uint32_t c = hull[last], n = hull[last + 1u];
                if ((val[c] - val[n]) + 2 * vor__mul_i32(key[n] - key[c], u) != 0) {
                    break;
                }
                last++;
            }
            k = last;
            count = emit(runs, count, i + 1u, best);
            i++;
            continue;
        }
        const uint32_t site = e->cand[hull[k]];
        if (k + 1u >= hull_count) {
            count = emit(runs, count, width, site);
            break;
        }
        /* d < 0; it grows by 2 (key_next - key_k) step per pixel
         * (< 2^60 when width >= 2, < 2^62 otherwise: no overflow) */
        const int64_t grow = 2 * vor__mul_i32(key[hull[k + 1u]] - key[hull[k]], step);
#if HARDWARE_DIVIDE
        if (d >= -(int64_t)0xFFFFFFFF && grow <= (int64_t)0xFFFFFFFF) {
            /* 0 < -d < 2^32 and 0 < grow < 2^32 (always so in the narrow
             * tier): the first pixel t >= 1 steps on with d + t grow >= 0
             * is t = (-d - 1) / grow + 1, one 32-bit hardware division */
            uint32_t t = (uint32_t)(-d - 1) / (uint32_t)grow + 1u;
            i = (t < width - i) ? i + t : width;
            count = emit(runs, count, i, site);
            continue;
        }
#endif
        do {
            i++;
            d += grow;
        } while (i < width && d < 0);
        count = emit(runs, count, i, site);
    }
    return count;
}
