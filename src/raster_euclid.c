/* SPDX-License-Identifier: MIT */
/*
 * raster_euclid.c - the Euclidean family of the raster, vor_raster_euclid:
 * the fast exact path for Euclidean point sites, the brute-force search it
 * falls back on (VOR_RASTER_BRUTE, or a frame beyond its bit budget), and
 * the distance pixels, on the raster core (raster.h). It links none of the
 * other metrics.
 *
 * Along a row v (world y relative to the first pixel), the squared
 * distance from pixel u to site (a, b) (coordinates relative to the first
 * pixel centre) is (u - a)^2 + (v - b)^2. Dropping u^2, which every site
 * shares, leaves a line in u:
 *
 *     g(u) = a^2 + (v - b)^2 - 2 a u,
 *
 * so the nearest site along the row is the lower envelope of one line per
 * site. A row is rendered by the discrete envelope (row_envelope): the
 * lines, in slope order, go through a stack whose entries own runs of
 * pixels; a new line pops the entries it beats at their first pixel, and
 * one division gives the first pixel where it beats the entry below. The
 * stack is then the row's runs: no separate walk over the pixels.
 *
 * Which sites can win in a band of rows? A closed Voronoi cell that meets
 * the band's rectangle R of pixel centres either holds its site inside R,
 * or crosses the boundary of R; the cells crossing an edge of R are the
 * (continuous, exact) envelope of that edge, with ties kept. So the
 * candidates of a band are: the sites inside R, plus the envelopes of R's
 * top and bottom edges and pieces of the envelopes of the whole frame's
 * left and right edges (computed once). R reaches down to the next band's
 * first row, so the bottom edge of one band is the top edge of the next:
 * each band envelopes one new edge, and that from few sites (select_band):
 * the candidates found so far, plus the sites below the edge within the
 * largest distance to a site on the last row rendered, plus the rows in
 * between. Per frame: two sorts and two vertical envelopes, O(n log n);
 * per band, O(n) for the marks and O(candidates) for the edge; per row,
 * O(candidates) for the envelope and nothing per pixel.
 *
 * Bit budget (fits): every relative coordinate a, b lies in
 * (-2^29, 2^29) and every pixel offset u, v in [0, 2^29). Then |v - b| <
 * 2^30, values a^2 + (v - b)^2 < 2^58 + 2^60 < 2^61, |2 a u| < 2^59, and
 * the difference of two lines at a pixel, a difference of two squared
 * distances below 2^61, fits int64. The row envelope needs nothing wider;
 * the edge envelopes compare products of value and slope differences,
 * in tiers (envelope below), 96 bits at most.
 */
#include "raster.h"

#include "multiword.h"

#define BUDGET ((int64_t)536870912) /* 2^29 */

/* A 32-bit division instruction (Cortex-M3/M4, RV32IM, 64-bit hosts).
 * Without one (Cortex-M0) the compiler would call a library routine, so
 * quotients come from a shift-and-subtract loop instead. 64-bit hosts
 * also divide 64-bit numbers in one instruction. */
#if defined(__ARM_FEATURE_IDIV) || defined(__riscv_div) || defined(__x86_64__) ||              \
    defined(__aarch64__)
#define HARDWARE_DIVIDE 1
#else
#define HARDWARE_DIVIDE 0
#endif
#if defined(__x86_64__) || defined(__aarch64__)
#define HARDWARE_DIVIDE64 1
#else
#define HARDWARE_DIVIDE64 0
#endif
#define NARROW ((int64_t)16384) /* 2^14 */
#define MID ((int64_t)524288) /* 2^19 */

/* Rows per culling band. */
#define CULL_ROWS 16u

/* The family's state: the frame and sites of the request, and the fast
 * path's arrays, which live in the work memory after the rows (n entries
 * per array). */
typedef struct euclid {
    const vor_raster_frame_t *frame;
    /* frame's: rel_x, rel_y read them in per-site loops */
    int32_t origin_x;
    int32_t origin_y;
    const vor_point_t *points;
    uint32_t n;
    int fast;             /* the fast path; else the brute-force search */
    uint32_t *by_x;       /* site ids sorted by (x, id) */
    uint32_t *by_y;       /* site ids sorted by (y, id) */
    int32_t *sorted_x;    /* relative x of by_x[p] */
    int32_t *sorted_y;    /* relative y of by_x[p] */
    uint8_t *mark;        /* per site: candidate flags of this band and the next */
    uint32_t *cand;       /* the band's list: sites in (x, id) order (also scratch) */
    int64_t *val;         /* the list's lines, packed (also scratch: edge values) */
    int32_t *key;         /* scratch: edge envelope keys */
    uint32_t *stack;      /* scratch: edge envelope stack */
    uint32_t *left;       /* envelope of the left frame edge (positions in by_y) */
    uint32_t *right;      /* and of the right edge */
    uint32_t left_count;
    uint32_t right_count;
    uint32_t left_next;
    uint32_t right_next; /* first pieces that may meet the next band */
    uint32_t cand_count;
    /* rows of the current culling band */
    uint32_t band_first;
    uint32_t band_last;
    uint32_t inside_next;           /* by_y position: first site not yet below the band */
    uint32_t quotient_bits;         /* 2^quotient_bits >= width */
    uint32_t reach_row;             /* the last row of the previous band ... */
    uint64_t reach_most;            /* ... and its largest squared distance to a site */
    int band_valid;
    int narrow;          /* tier: 1 narrow (< 2^14), 2 mid (< 2^19), 0 wide */
} euclid_t;

/* True when the fast path's bit budget holds: every site within 2^29 of
 * the first pixel centre, (width - 1) * step_x and (height - 1) * step_y
 * below 2^29. */
static int fits(const vor_raster_frame_t *frame, const vor_point_t *points, uint32_t n)
{
    if (vor__offset(frame->width - 1u, frame->step_x) >= BUDGET ||
        vor__offset(frame->height - 1u, frame->step_y) >= BUDGET) {
        return 0;
    }
    for (uint32_t k = 0; k < n; k++) {
        int64_t a = (int64_t)points[k].x - frame->origin_x;
        int64_t b = (int64_t)points[k].y - frame->origin_y;
        if (a <= -BUDGET || (a >= BUDGET) || (b <= -BUDGET) || (b >= BUDGET)) {
            return 0;
        }
    }
    return 1;
}

/* ------------------------------------------------------------- sites */

static int32_t rel_x(const euclid_t *e, uint32_t id)
{
    return (int32_t)((int64_t)e->points[id].x - e->origin_x);
}

static int32_t rel_y(const euclid_t *e, uint32_t id)
{
    return (int32_t)((int64_t)e->points[id].y - e->origin_y);
}

static int64_t square(int32_t x)
{
    return vor__mul_i32(x, x);
}

/* The offset of the last pixel of a row, U = (width - 1) step_x < 2^29. */
static int32_t frame_u(const euclid_t *e)
{
    return (int32_t)(vor__offset(e->frame->width - 1u, e->frame->step_x));
}

/* ---------------------------------------------------------------- sort */

/*
 * ids[0 .. n) = 0 .. n-1 sorted by (value[id], id), with tmp[n] as
 * scratch: insertion sort of blocks of 8, then a bottom-up merge sort
 * (no recursion). Both are stable and start from ids in increasing
 * order, so equal values keep id order. The merge keeps the two heads in
 * registers; each pass doubles the sorted runs, so there are at most
 * ceil(log2(n / 8)) passes; the insertion sort moves an id at most 7
 * places.
 */
#define SORT_BLOCK 8u
static void sort_ids(uint32_t *ids, uint32_t *tmp, const int32_t *value, uint32_t n)
{
    for (uint32_t k = 0; k < n; k++) {
        uint32_t block = k - (k % SORT_BLOCK);
        uint32_t p = k;
        int32_t v = value[k];
        while ((p > block) && (value[ids[p - 1u]] > v)) {
            ids[p] = ids[p - 1u];
            p--;
        }
        ids[p] = k;
    }
    uint32_t *from = ids;
    uint32_t *to = tmp;
    for (uint32_t width = SORT_BLOCK; width < n; width *= 2u) { /* n < 2^27: no overflow */
        for (uint32_t lo = 0; lo < n; lo += 2u * width) {
            const uint32_t mid = ((n - lo) > width) ? (lo + width) : n;
            const uint32_t hi = ((n - mid) > width) ? (mid + width) : n;
            uint32_t i = lo;
            uint32_t j = mid;
            uint32_t k = lo;
            if (j < hi) {
                uint32_t id_i = from[i];
                uint32_t id_j = from[j];
                int32_t v_i = value[id_i];
                int32_t v_j = value[id_j];
                for (;;) {
                    if (v_j < v_i) { /* equal values: the left run first */
                        to[k] = id_j;
                        k++;
                        if (++j == hi) {
                            break;
                        }
                        id_j = from[j];
                        v_j = value[id_j];
                    } else {
                        to[k] = id_i;
                        k++;
                        if (++i == mid) {
                            break;
                        }
                        id_i = from[i];
                        v_i = value[id_i];
                    }
                }
            }
            for (; i < mid; i++) {
                to[k] = from[i];
                k++;
            }
            for (; j < hi; j++) {
                to[k] = from[j];
                k++;
            }
        }
        uint32_t *t = from;
        from = to;
        to = t;
    }
    if (from != ids) {
        for (uint32_t k = 0; k < n; k++) {
            ids[k] = from[k];
        }
    }
}

/* ---------------------------------------------------- edge envelopes */

/*
 * Continuous lower envelope of the lines val[p] - 2 key[p] t, positions
 * 0 .. m-1, keys non-decreasing (the band edges, where every real point
 * of the edge counts, not only pixel centres). Of lines with equal keys
 * only the lowest is taken (the first of the lowest). A line is dropped
 * only when it lies strictly above the envelope everywhere: one that
 * meets it in a single point is kept, so that the cells touching the edge
 * there are found. The stack receives the positions of the kept lines;
 * their crossing points do not decrease. Keys fit in (-2^29, 2^29) (key
 * differences < 2^30), values in [0, 2^61).
 */
VOR__ALWAYS_INLINE uint32_t envelope_impl(const int32_t *key, const int64_t *val, uint32_t m,
                                     uint32_t *stack, int tier)
{
    uint32_t top = 0;
    uint32_t p = 0;
    while (p < m) {
        uint32_t rep = p;
        uint32_t q = p + 1u;
        while ((q < m) && (key[q] == key[p])) {
            if (val[q] < val[rep]) {
                rep = q;
            }
            q++;
        }
        p = q;
        /* pop j (between i and rep) while its crossing with i lies
         * strictly right of its crossing with rep: then j is never lowest */
        while (top >= 2u) {
            uint32_t i = stack[top - 2u];
            uint32_t j = stack[top - 1u];
            int greater;
            if (tier == 1) { /* value differences fit int32, key ones 2^15 */
                int64_t left = vor__mul_i32((int32_t)(val[j] - val[i]), key[rep] - key[j]);
                int64_t right = vor__mul_i32((int32_t)(val[rep] - val[j]), key[j] - key[i]);
                greater = (left > right) ? 1 : 0;
            } else if (tier == 2) { /* values < 2^41, key differences < 2^20 */
                int64_t left = vor__mul_i64_i32(val[j] - val[i], key[rep] - key[j]);
                int64_t right = vor__mul_i64_i32(val[rep] - val[j], key[j] - key[i]);
                greater = (left > right) ? 1 : 0;
            } else {
                vor__mw_i96_t left;
                vor__mw_i96_t right;
                vor__mw_i96_mul(&left, val[j] - val[i], (uint32_t)(key[rep] - key[j]));
                vor__mw_i96_mul(&right, val[rep] - val[j], (uint32_t)(key[j] - key[i]));
                greater = vor__mw_i96_greater(&left, &right);
            }
            if (!greater) {
                break;
            }
            top--;
        }
        stack[top] = rep;
        top++;
    }
    return top;
}

/* Tiers of the edge envelope test, by the largest relative coordinate or
 * pixel offset M. Narrow (1), M < 2^14: values < 2^28 + 2^30 < 2^31, so a
 * value difference fits int32 and its product with a key difference (<
 * 2^15) fits int64 from one 32x32 multiply. Mid (2), M < 2^19: values <
 * 2^38 + 2^40 < 2^41, key differences < 2^20, products < 2^61 in int64.
 * Wide (0), M < 2^29: 96-bit products (vor__mw_i96_mul). */
static uint32_t envelope(const euclid_t *e, const int32_t *key, const int64_t *val,
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

/* 2 dkey bound, the scale at which a crossing (val_j - val_i) / (2 dkey)
 * is compared with a bound: < 2^60 for dkey < 2^30, 0 <= bound < 2^29. */
static int64_t crossing_scaled(int32_t dkey, int32_t bound)
{
    return 2 * vor__mul_i32(dkey, bound);
}

/* The lines of an edge envelope, by position: a horizontal edge (key a,
 * value a^2 + (v - b)^2, positions into the band's list: key[], val[],
 * sites by_x[cand[pos]]) or a vertical one at offset u (key b, value
 * (a - u)^2 + b^2, positions into by_y). */
typedef struct edge_lines {
    const euclid_t *e;
    int32_t u;     /* vertical edges: the edge's offset */
    uint32_t m;    /* positions 0 .. m-1 */
} edge_lines_t;

VOR__ALWAYS_INLINE uint32_t edge_site(const edge_lines_t *l, uint32_t pos, int vertical)
{
    return vertical ? l->e->by_y[pos] : l->e->by_x[l->e->cand[pos]];
}

VOR__ALWAYS_INLINE int32_t edge_key(const edge_lines_t *l, uint32_t pos, int vertical)
{
    return vertical ? rel_y(l->e, l->e->by_y[pos]) : l->e->key[pos];
}

VOR__ALWAYS_INLINE int64_t edge_val(const edge_lines_t *l, uint32_t pos, int vertical)
{
    if (vertical != 0) {
        uint32_t id = l->e->by_y[pos];
        return square(rel_x(l->e, id) - l->u) + square(rel_y(l->e, id));
    }
    return l->e->val[pos];
}

/*
 * Marks (with flags) the sites of the envelope lines hull[from .. count)
 * whose pieces meet [lo, hi], and every site tied with them (equal key
 * and value: equal lines, whose closed cells all touch the edge). The
 * pieces come in order along the edge, so the walk starts past those that
 * end before lo and stops at the first that starts after hi. Returns the
 * first piece not ending before lo: a later band, whose lo is larger, can
 * start there.
 */
VOR__ALWAYS_INLINE uint32_t mark_pieces_impl(euclid_t *e, const edge_lines_t *l,
                                        const uint32_t *hull, uint32_t from, uint32_t count,
                                        int32_t lo, int32_t hi, uint8_t flags, int vertical)
{
    uint32_t t = from;
    /* piece t ends at crossing(t, t+1) = (val_next - val) / (2 dkey) */
    while ((t + 1u) < count) {
        int32_t dkey = edge_key(l, hull[t + 1u], vertical) - edge_key(l, hull[t], vertical);
        if (edge_val(l, hull[t + 1u], vertical) - edge_val(l, hull[t], vertical) >=
            crossing_scaled(dkey, lo)) {
            break;
        }
        t++;
    }
    const uint32_t resume = t;
    for (; t < count; t++) {
        uint32_t pos = hull[t];
        int32_t key = edge_key(l, pos, vertical);
        int64_t val = edge_val(l, pos, vertical);
        if (t > resume) { /* the piece starts at crossing(t-1, t): must be <= hi */
            uint32_t prev = hull[t - 1u];
            int32_t dkey = key - edge_key(l, prev, vertical);
            if (val - edge_val(l, prev, vertical) > crossing_scaled(dkey, hi)) {
                break; /* and so do the later ones */
            }
        }
        /* the equal lines sit next to pos in the order (same key) */
        uint32_t first = pos;
        while ((first > 0u) && edge_key(l, first - 1u, vertical) == key) {
            first--;
        }
        for (uint32_t q = first; (q < l->m) && edge_key(l, q, vertical) == key; q++) {
            if (edge_val(l, q, vertical) == val) {
                e->mark[edge_site(l, q, vertical)] |= flags;
            }
        }
    }
    return resume;
}

/* The pieces of the frame's left or right edge envelope that meet the
 * band's rows [v0, v1]; *cursor carries the first live piece to the next
 * band. */
static void mark_vertical(euclid_t *e, const uint32_t *hull, uint32_t count, int32_t u,
                          int32_t v0, int32_t v1, uint32_t *cursor)
{
    edge_lines_t l = {e, u, e->n};
    *cursor = mark_pieces_impl(e, &l, hull, *cursor, count, v0, v1, 1u, 1);
}

/* Envelope of a vertical frame edge at offset u over every site (keys:
 * relative y in by_y order, in sorted_y while prepare runs). */
static uint32_t vertical_envelope(euclid_t *e, int32_t u, uint32_t *out)
{
    for (uint32_t p = 0; p < e->n; p++) {
        uint32_t id = e->by_y[p];
        e->val[p] = square(rel_x(e, id) - u) + square(e->sorted_y[p]);
    }
    uint32_t count = envelope(e, e->sorted_y, e->val, e->n, e->stack);
    for (uint32_t t = 0; t < count; t++) {
        out[t] = e->stack[t];
    }
    return count;
}

/* Envelope of the horizontal edge at row offset v over the band's list
 * cand[0 .. m) (by_x positions, in (x, id) order), marked over the whole
 * width [0, U] with flags. */
static void mark_horizontal(euclid_t *e, uint32_t m, int32_t v, uint8_t flags)
{
    for (uint32_t q = 0; q < m; q++) {
        uint32_t p = e->cand[q];
        int32_t a = e->sorted_x[p];
        e->key[q] = a;
        e->val[q] = square(a) + square(e->sorted_y[p] - v);
    }
    uint32_t count = envelope(e, e->key, e->val, m, e->stack);
    edge_lines_t l = {e, 0, m};
    (void)mark_pieces_impl(e, &l, e->stack, 0, count, 0, frame_u(e), flags, 0);
}

/* ------------------------------------------------------------- prepare */

/* Sorts the sites and envelopes the frame's left and right edges; e's
 * arrays carved, fits() true. */
static void fast_prepare(euclid_t *e)
{
    const uint32_t n = e->n;
    /* y order first: sorted_y holds the y of by_y until the x sort
     * (sorted_x the y of each site while sorting) */
    for (uint32_t k = 0; k < n; k++) {
        e->sorted_x[k] = rel_y(e, k);
    }
    sort_ids(e->by_y, e->cand, e->sorted_x, n);
    for (uint32_t p = 0; p < n; p++) {
        e->sorted_y[p] = e->sorted_x[e->by_y[p]];
    }

    int64_t reach = vor__offset(e->frame->width - 1u, e->frame->step_x);
    int64_t tall = vor__offset(e->frame->height - 1u, e->frame->step_y);
    int64_t most = (reach > tall) ? reach : tall;
    for (uint32_t k = 0; k < n; k++) {
        int64_t a = rel_x(e, k);
        int64_t b = rel_y(e, k);
        a = (a < 0) ? -a : a;
        b = (b < 0) ? -b : b;
        most = (a > most) ? a : most;
        most = (b > most) ? b : most;
    }
    e->narrow = most < NARROW ? 1 : most < MID ? 2 : 0;
    e->left_count = vertical_envelope(e, 0, e->left);
    e->right_count = vertical_envelope(e, frame_u(e), e->right);

    /* x order (key: the x of each site while sorting) */
    for (uint32_t k = 0; k < n; k++) {
        e->key[k] = rel_x(e, k);
    }
    sort_ids(e->by_x, e->cand, e->key, n);
    for (uint32_t p = 0; p < n; p++) {
        uint32_t id = e->by_x[p];
        e->sorted_x[p] = e->key[id];
        e->sorted_y[p] = rel_y(e, id);
        e->mark[p] = 0;
    }
    /* quotients of the row envelope stay below width: bits enough */
    uint32_t bits = 1;
    while ((bits < 31u) && ((uint32_t)1 << bits) < e->frame->width) {
        bits++;
    }
    e->quotient_bits = bits;
    e->band_valid = 0;
    e->inside_next = 0;
    e->left_next = 0;
    e->right_next = 0;
    e->reach_row = 0;
    e->reach_most = 0;
}

/* ---------------------------------------------------------------- rows */

/* floor(r / g) for g > 0 and r < g 2^bits: one hardware division when
 * both fit 32 bits, else restoring division, one quotient bit per step
 * (bits steps). (r >> b) >= g exactly when r >= g 2^b, and g 2^b <= r
 * never overflows. */
static uint32_t quotient32(uint32_t r_in, uint32_t g, uint32_t bits)
{
    uint32_t r = r_in;
#if HARDWARE_DIVIDE
    (void)bits;
    return r / g;
#else
    uint32_t q = 0;
    for (uint32_t b = bits; b-- > 0u;) {
        if ((r >> b) >= g) {
            r -= g << b;
            q |= (uint32_t)1 << b;
        }
    }
    return q;
#endif
}

static uint32_t quotient64(uint64_t r_in, uint64_t g, uint32_t bits)
{
    uint64_t r = r_in;
#if HARDWARE_DIVIDE64
    (void)bits;
    return (uint32_t)(r / g);
#else
    if (((r >> 32) == 0u) && (g >> 32) == 0u) {
        return quotient32((uint32_t)r, (uint32_t)g, bits);
    }
    uint32_t q = 0;
    for (uint32_t b = bits; b-- > 0u;) {
        if (vor__shr_u64(r, b) >= g) {
            r -= vor__shl_u64(g, b);
            q |= (uint32_t)1 << b;
        }
    }
    return q;
#endif
}

/* ---------------------------------------------------------- row lists */

/* A band's candidates are a list of lines in (a, site) order: cand[q] =
 * site and val[q] = the line's (a, b) packed. Mid and wide tiers: a and b
 * each biased by 2^29 into (0, 2^30), one int64 below 2^62. */
static int64_t pack_line(int32_t a, int32_t b)
{
    int32_t a_biased = a + (int32_t)BUDGET;
    int32_t b_biased = b + (int32_t)BUDGET;
    uint64_t lo = (uint32_t)a_biased;
    uint64_t hi = (uint32_t)b_biased;
    uint64_t packed = (hi << 32) | lo; /* < 2^62 */
    return (int64_t)packed;
}

VOR__ALWAYS_INLINE int32_t line_a(int64_t line)
{
    return (int32_t)(uint32_t)((uint64_t)line & 0xFFFFFFFFu) - (int32_t)BUDGET;
}

/* v - b, from v + 2^29 */
VOR__ALWAYS_INLINE int32_t line_dy(int64_t line, int32_t v_biased)
{
    return v_biased - (int32_t)(line >> 32);
}

/* Narrow tier: a and b biased by 2^14 into 15 bits each, and the site,
 * in one int64 below 2^59: one load gives all three. */
#define NARROW_BIAS 16384
static int64_t pack_narrow(int32_t a, int32_t b, uint32_t id)
{
    int32_t a_biased = a + NARROW_BIAS;
    int32_t b_biased = b + NARROW_BIAS;
    uint32_t lo = (uint32_t)a_biased | ((uint32_t)b_biased << 16);
    uint64_t packed = ((uint64_t)id << 32) | lo;
    return (int64_t)packed;
}

/* The fields of a narrow-tier line x (pack_narrow): its slope a, and
 * v - b from v + 2^14. */
VOR__ALWAYS_INLINE int32_t narrow_a(uint64_t x)
{
    uint32_t a_biased = (uint32_t)x & 0xFFFFu;
    return (int32_t)a_biased - NARROW_BIAS;
}

VOR__ALWAYS_INLINE int32_t narrow_dy(uint64_t x, int32_t v_biased)
{
    uint32_t b_biased = (uint32_t)x >> 16;
    return v_biased - (int32_t)b_biased;
}

/* Sets list line q. */
static void set_line(euclid_t *e, uint32_t q, uint32_t id, int32_t a, int32_t b)
{
    e->cand[q] = id;
    e->val[q] = (e->narrow == 1) ? pack_narrow(a, b, id) : pack_line(a, b);
}

/*
 * The discrete lower envelope of row offset v over the band's list (q <
 * cand_count, at least one line): which line is lowest at each pixel
 * centre, ties to the smallest site. Returns the count of stack
 * entries; entry t owns the pixels from runs[t].end (its first pixel, for
 * now) up to the next entry's first pixel, and runs[t].site is its list
 * position (cand[] maps it to the site).
 *
 * Line l beats line j at pixel i when g_l < g_j at u_i = i step, or they
 * are equal and l has the smaller index. For slope(l) >= slope(j) the
 * difference D(i) = g_j(u_i) - g_l(u_i) = val_j - val_l + 2 (a_l - a_j) u_i
 * does not decrease with i, so l beats j on a suffix of the pixels, and l
 * beats every earlier line (the lowest at each pixel being a minimum in a
 * total order) on a suffix too. Lines come in slope order, so a new line
 * l pops each top entry j it beats at j's first pixel (then on all of j's
 * pixels), and otherwise starts where it first beats j: the smallest t >=
 * 1 with D(s_j) + 2 (a_l - a_j) step t > -bias, bias 1 when l has the
 * smaller index. If that is past the last pixel (or the slopes are
 * equal), l is lowest nowhere and is dropped. Stack entries thus own
 * non-empty runs in order, at most min(lines, width) of them. The top
 * entry lives in registers; the stack in memory is runs[t] = (first
 * pixel, list position), and a popped-to entry's line is looked up again.
 * One function per tier: the narrow one in 32 bits, the other in 64.
 *
 * Bounds: narrow (every coordinate and offset below 2^14): values <
 * 2^28 + 2^30 < 2^31, D is a difference of squared distances below 2^31,
 * 2 (a_l - a_j) u_i < 2^16 2^14, everything in int32. Otherwise (below
 * 2^29): values < 2^61, |D| < 2^61, 2 (a_l - a_j) < 2^31 fits int32 and
 * its product with an offset is < 2^60, everything in int64. The quotient
 * is below width (2^quotient_bits).
 */
static uint32_t row_envelope_narrow(const euclid_t *e, int32_t v, vor__run_t *runs)
{
    const int64_t *line = e->val;
    const uint32_t m = e->cand_count;
    const uint32_t step = (uint32_t)e->frame->step_x;
    const uint32_t last_u = (uint32_t)frame_u(e);
    const uint32_t bits = e->quotient_bits;
    const int32_t vb = v + NARROW_BIAS;
    /* the top entry: slope, value, first pixel and its offset, site */
    uint64_t x = (uint64_t)line[0];
    int32_t top_a = narrow_a(x);
    int32_t top_dy = narrow_dy(x, vb);
    int32_t top_val = (top_a * top_a) + (top_dy * top_dy);
    uint32_t top_start = 0;
    uint32_t top_site = (uint32_t)(x >> 32);
    uint32_t top_u = 0;
    runs[0].end = 0;
    runs[0].site = 0;
    uint32_t top = 1; /* entries */
    for (uint32_t q = 1; q < m; q++) {
        x = (uint64_t)line[q];
        const int32_t a = narrow_a(x);
        const int32_t dy = narrow_dy(x, vb);
        const uint32_t id = (uint32_t)(x >> 32);
        const int32_t val = (a * a) + (dy * dy);
        uint32_t start;
        for (;;) {
            const int32_t da = a - top_a; /* >= 0: slope order */
            const int32_t d = (top_val - val) + (2 * da * (int32_t)top_u);
            if ((d > 0) || ((d == 0) && (id < top_site))) {
                goto pop; /* l beats the top on all of its pixels */
            }
            /* l wins from the first t >= 1 with d + 2 da step t > -bias */
            const uint32_t r = (uint32_t)-d - ((id < top_site) ? 1u : 0u);
            const uint32_t g = 2u * (uint32_t)da;
            if ((da == 0) || (r >= (g * (last_u - top_u)))) {
                goto dropped; /* l never beats the top within the row */
            }
            const uint32_t skip = quotient32(r, g * step, bits);
            start = top_start + skip + 1u;
            break;
        pop:
            top--;
            if (top == 0u) {
                start = 0; /* l starts at pixel 0 */
                break;
            }
            { /* the entry below becomes the top again */
                x = (uint64_t)line[runs[top - 1u].site];
                top_start = runs[top - 1u].end;
                top_u = top_start * step;
                top_a = narrow_a(x);
                top_site = (uint32_t)(x >> 32);
                top_dy = narrow_dy(x, vb);
                top_val = (top_a * top_a) + (top_dy * top_dy);
            }
        }
        runs[top].end = start;
        runs[top].site = q;
        top++;
        top_a = a;
        top_val = val;
        top_start = start;
        top_u = start * step;
        top_site = id;
    dropped:;
    }
    return top;
}

static uint32_t row_envelope_wide(const euclid_t *e, int32_t v, vor__run_t *runs)
{
    const uint32_t *site = e->cand;
    const int64_t *line = e->val;
    const uint32_t m = e->cand_count;
    const int32_t step = e->frame->step_x;
    const int32_t last_u = frame_u(e);
    const uint32_t bits = e->quotient_bits;
    const int32_t vb = v + (int32_t)BUDGET;
    /* the top entry: slope, value, first pixel and its offset, site */
    int32_t top_a = line_a(line[0]);
    int32_t top_dy = line_dy(line[0], vb);
    int64_t top_val = square(top_a) + square(top_dy);
    uint32_t top_start = 0;
    uint32_t top_site = site[0];
    int32_t top_u = 0;
    runs[0].end = 0;
    runs[0].site = 0;
    uint32_t top = 1; /* entries */
    for (uint32_t q = 1; q < m; q++) {
        const int64_t l = line[q];
        const int32_t a = line_a(l);
        const int32_t dy = line_dy(l, vb);
        const uint32_t id = site[q];
        const int64_t val = square(a) + square(dy);
        uint32_t start;
        for (;;) {
            const int32_t da = a - top_a; /* >= 0: slope order */
            const int32_t da2 = 2 * da;
            const int64_t d = (top_val - val) + vor__mul_i32(da2, top_u);
            if ((d > 0) || ((d == 0) && (id < top_site))) {
                goto pop; /* l beats the top on all of its pixels */
            }
            /* l wins from the first t >= 1 with d + 2 da step t > -bias */
            const uint64_t r = (uint64_t)-d - ((id < top_site) ? 1u : 0u);
            if ((da == 0) || (r >= (uint64_t)vor__mul_i32(da2, last_u - top_u))) {
                goto dropped; /* l never beats the top within the row */
            }
            const uint32_t skip = quotient64(r, (uint64_t)vor__mul_i32(da2, step), bits);
            start = top_start + skip + 1u;
            break;
        pop:
            top--;
            if (top == 0u) {
                start = 0; /* l starts at pixel 0 */
                break;
            }
            { /* the entry below becomes the top again */
                const uint32_t below = runs[top - 1u].site;
                const int64_t bl = line[below];
                top_start = runs[top - 1u].end;
                top_u = (int32_t)vor__offset(top_start, step);
                top_a = line_a(bl);
                top_site = site[below];
                const int32_t below_dy = line_dy(bl, vb);
                top_val = square(top_a) + square(below_dy);
            }
        }
        runs[top].end = start;
        runs[top].site = q;
        top++;
        top_a = a;
        top_val = val;
        top_start = start;
        top_u = (int32_t)vor__offset(start, step);
        top_site = id;
    dropped:;
    }
    return top;
}

static uint32_t row_envelope(const euclid_t *e, int32_t v, vor__run_t *runs)
{
    if (e->narrow == 1) {
        return row_envelope_narrow(e, v, runs);
    }
    return row_envelope_wide(e, v, runs);
}

/* --------------------------------------------------------------- bands */

/* The sites whose marks meet flags, in (x, id) order, as the list the
 * rows take (cand = site, val = pack_line(a, b)); returns their count. */
static uint32_t gather_lines(euclid_t *e, uint8_t flags)
{
    uint32_t m = 0;
    for (uint32_t p = 0; p < e->n; p++) {
        uint32_t id = e->by_x[p];
        if ((e->mark[id] & flags) != 0u) {
            set_line(e, m++, id, e->sorted_x[p], e->sorted_y[p]);
        }
    }
    return m;
}

/* The same sites as by_x positions (cand = position), for
 * mark_horizontal; returns their count. */
static uint32_t gather_positions(euclid_t *e, uint8_t flags)
{
    uint32_t m = 0;
    for (uint32_t p = 0; p < e->n; p++) {
        if ((e->mark[e->by_x[p]] & flags) != 0u) {
            e->cand[m] = p;
            m++;
        }
    }
    return m;
}

/* The last row of the band that starts at row first, and the row of its
 * rectangle's bottom edge: the next band's first row, if any. */
static uint32_t band_last_row(const euclid_t *e, uint32_t first)
{
    uint32_t last = first + (CULL_ROWS - 1u);
    return ((last >= e->frame->height) || (last < first)) ? (e->frame->height - 1u) : last;
}

static uint32_t band_bottom(const euclid_t *e, uint32_t first)
{
    uint32_t last = band_last_row(e, first);
    return ((last + 1u) < e->frame->height) ? (last + 1u) : last;
}

/* The largest squared distance from a pixel centre of row offset v to
 * its site, from the row's stack (first pixels, list positions): along a
 * run it is largest at one of the run's ends. */
static uint64_t farthest(const euclid_t *e, int32_t v, const vor__run_t *runs,
                         uint32_t count)
{
    uint64_t most = 0;
    for (uint32_t t = 0; t < count; t++) {
        uint32_t id = e->cand[runs[t].site];
        uint32_t end = ((t + 1u) < count) ? runs[t + 1u].end : e->frame->width;
        int32_t a = rel_x(e, id);
        int64_t dy2 = square(rel_y(e, id) - v);
        int64_t d1 = square((int32_t)vor__offset(runs[t].end, e->frame->step_x) - a) + dy2;
        int64_t d2 = square((int32_t)vor__offset(end - 1u, e->frame->step_x) - a) + dy2;
        uint64_t d = (uint64_t)((d1 > d2) ? d1 : d2);
        most = (d > most) ? d : most;
    }
    return most;
}

/*
 * Candidates of the band of rows [first, last] (the list the rows take).
 * Its rectangle R = [0, U] x [v0, v1] reaches down to the next band's first
 * row (when there is one). Marks: bit 0, a candidate of this band; bit 1,
 * of the next band (the bottom edge, which is the next band's top edge);
 * bit 2, a site tried for the bottom edge.
 *
 * The bottom edge from few sites: a site whose closed cell meets the
 * bottom edge at p either lies below the edge (b > v1), or is already a
 * candidate (inside R, or its cell crosses the top, left or right edge on
 * the way from its site to p: convexity). One below has b - v1 <= |p - s|
 * = dist(p, S) <= |p_i - s_i| + |p - p_i| for any pixel centre p_i of the
 * edge and any site s_i. Every p of the edge lies within step_x / 2 of
 * some p_i, and for s_i the site that won the pixel above p_i on the
 * previous band's last row (rendered just before) serves: with E the
 * largest |p_i - s_i|^2, b - v1 - ceil(step_x / 2) <= sqrt(E). The first
 * band has no row above; there s_i is the nearest of the candidates found
 * so far (their discrete envelope at the edge's row). The sites below are
 * taken in y order while that holds, and the edge's envelope is computed
 * over them and the candidates.
 */
static void select_band(euclid_t *e, uint32_t first, vor__run_t *runs)
{
    const uint32_t last = band_last_row(e, first);
    const int32_t v0 = (int32_t)(vor__offset(first, e->frame->step_y));
    const int32_t v1 = (int32_t)(vor__offset(band_bottom(e, first), e->frame->step_y));
    const int32_t u1 = frame_u(e);
    const uint32_t n = e->n;
    if (first == 0u) { /* the frame's top edge, over every site */
        for (uint32_t p = 0; p < n; p++) {
            e->cand[p] = p;
        }
        mark_horizontal(e, n, v0, 1u);
    }
    mark_vertical(e, e->left, e->left_count, 0, v0, v1, &e->left_next);
    mark_vertical(e, e->right, e->right_count, u1, v0, v1, &e->right_next);
    /* sites inside the band's rectangle; bands come in increasing order,
     * so sites above the next band's top (v1) are never needed again */
    uint32_t p = e->inside_next;
    while ((p < n) && rel_y(e, e->by_y[p]) < v0) {
        p++;
    }
    uint32_t next = p;
    while ((p < n) && rel_y(e, e->by_y[p]) <= v1) {
        uint32_t id = e->by_y[p];
        int32_t a = rel_x(e, id);
        if ((a >= 0) && (a <= u1)) {
            e->mark[id] |= 1u;
        }
        next += (rel_y(e, id) < v1) ? 1u : 0u;
        p++;
    }
    e->inside_next = next;

    uint32_t m;
    if (v1 == v0) { /* a last band of one row: no bottom edge */
        m = gather_positions(e, 1u);
    } else {
        /* E (see above) */
        uint64_t most;
        if ((first > 0u) && (e->reach_row + 1u) == first) {
            most = e->reach_most;
        } else {
            e->cand_count = gather_lines(e, 1u);
            uint32_t count = row_envelope(e, v1, runs);
            most = farthest(e, v1, runs, count);
        }
        /* the sites below the edge, in y order, while b - v1 - h <= sqrt(E)
         * (d below 2^30 when positive: its square fits) */
        const uint32_t half_step = ((uint32_t)e->frame->step_x + 1u) / 2u;
        const int64_t h = (int64_t)half_step;
        for (; p < n; p++) {
            uint32_t id = e->by_y[p];
            int64_t d = (int64_t)rel_y(e, id) - v1 - h;
            if ((d > 0) && vor__mul_u32((uint32_t)d, (uint32_t)d) > most) {
                break;
            }
            e->mark[id] |= 4u;
        }
        m = gather_positions(e, 5u);
        mark_horizontal(e, m, v1, 3u);
    }
    /* keep the candidates as the rows' list; clear the marks but the
     * next band's (every marked site is in cand) */
    uint32_t kept = 0;
    for (uint32_t q = 0; q < m; q++) {
        uint32_t pos = e->cand[q];
        uint32_t id = e->by_x[pos];
        uint8_t flags = e->mark[id];
        e->mark[id] = (uint8_t)((flags >> 1) & 1u);
        if ((flags & 1u) != 0u) {
            set_line(e, kept++, id, e->sorted_x[pos], e->sorted_y[pos]);
        }
    }
    e->cand_count = kept;
    e->band_first = first;
    e->band_last = last;
    e->band_valid = 1;
}

/* Runs of row j by the fast path. */
static uint32_t fast_row(euclid_t *e, uint32_t j, vor__run_t *runs)
{
    if (!e->band_valid || (j > e->band_last)) {
        select_band(e, j, runs);
    }
    const int32_t v = (int32_t)(vor__offset(j, e->frame->step_y));
    const uint32_t count = row_envelope(e, v, runs);
    if ((j == e->band_last) && (j + 1u) < e->frame->height) {
        /* this row's sites, at the next band's bottom edge */
        uint32_t bottom = band_bottom(e, j + 1u);
        e->reach_most = farthest(e, (int32_t)vor__offset(bottom, e->frame->step_y), runs, count);
        e->reach_row = j;
    }
    /* (first pixel, list position) to (end, site) */
    const uint32_t *site = e->cand;
    for (uint32_t t = 0; (t + 1u) < count; t++) {
        runs[t].end = runs[t + 1u].end;
        runs[t].site = site[runs[t].site];
    }
    runs[count - 1u].end = e->frame->width;
    runs[count - 1u].site = site[runs[count - 1u].site];
    return count;
}

/* ------------------------------------------------------------ distances */

/* floor(sqrt(x)) by the bit-by-bit method (no division). */
static uint32_t isqrt64(uint64_t x_in)
{
    uint64_t x = x_in;
    uint64_t root = 0;
    uint64_t bit = (uint64_t)1 << 62;
    while (bit > x) {
        bit >>= 2;
    }
    while (bit != 0u) { /* 32 steps at most: bit moves 2 places each */
        if (x >= (root + bit)) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root;
}

/* |q - s|^2 exactly, as *high (0 or 1) and the low 64 bits returned:
 * each square is below 2^64 for int32 coordinates, their sum below 2^65. */
static uint64_t squared_distance(int32_t qx, int32_t qy, const vor_point_t *s, uint32_t *high)
{
    uint64_t dx2 = vor__mul_u32(vor__mw_magnitude((int64_t)qx - s->x),
                                vor__mw_magnitude((int64_t)qx - s->x));
    uint64_t dy2 = vor__mul_u32(vor__mw_magnitude((int64_t)qy - s->y),
                                vor__mw_magnitude((int64_t)qy - s->y));
    uint64_t low = dx2 + dy2;
    *high = (low < dx2) ? 1u : 0u;
    return low;
}

/* floor(|q - s|), saturated at UINT32_MAX: from 2^64 on the root is
 * >= 2^32. */
static uint32_t euclid_distance(int32_t qx, int32_t qy, const vor_point_t *s)
{
    uint32_t high;
    uint64_t low = squared_distance(qx, qy, s, &high);
    return (high != 0u) ? 0xFFFFFFFFu : isqrt64(low);
}

/* ---------------------------------------------------------- brute force */

/* The nearest site to q by exact squared distances, ties to the smaller
 * index. */
static uint32_t brute_nearest(const euclid_t *e, int32_t qx, int32_t qy)
{
    uint32_t best = 0;
    uint32_t best_high;
    uint64_t best_low = squared_distance(qx, qy, &e->points[0], &best_high);
    for (uint32_t k = 1; k < e->n; k++) {
        uint32_t high;
        uint64_t low = squared_distance(qx, qy, &e->points[k], &high);
        if ((high < best_high) || ((high == best_high) && (low < best_low))) {
            best = k;
            best_high = high;
            best_low = low;
        }
    }
    return best;
}

static uint32_t brute_row(const euclid_t *e, uint32_t j, vor__run_t *runs)
{
    const int32_t origin_x = e->frame->origin_x;
    const int32_t step_x = e->frame->step_x;
    const uint32_t width = e->frame->width;
    int32_t qy = (int32_t)(e->frame->origin_y + vor__offset(j, e->frame->step_y));
    uint32_t count = 0;
    for (uint32_t i = 0; i < width; i++) {
        int32_t qx = (int32_t)(origin_x + vor__offset(i, step_x));
        count = vor__run_push(runs, count, i, brute_nearest(e, qx, qy));
    }
    return count;
}

/* -------------------------------------------------------------- family */

/* Carves the fast path's arrays from the work memory after the rows:
 * 8-byte arrays first, then 4-byte ones, then bytes, so that every array
 * is aligned (45 n bytes). */
static void carve(euclid_t *e, uint8_t *base)
{
    const size_t n = e->n;
    e->val = (int64_t *)(void *)base;
    uint32_t *words = (uint32_t *)(void *)(base + (n * sizeof(int64_t)));
    e->by_x = words;
    e->by_y = words + n;
    e->cand = words + (2u * n);
    e->key = (int32_t *)(void *)(words + (3u * n));
    e->stack = words + (4u * n);
    e->left = words + (5u * n);
    e->right = words + (6u * n);
    e->sorted_x = (int32_t *)(void *)(words + (7u * n));
    e->sorted_y = (int32_t *)(void *)(words + (8u * n));
    e->mark = (uint8_t *)(void *)(words + (9u * n));
}

/* Sets e up for the checked request r: the fast path when r asks for it
 * and its bit budget holds, else the brute force. */
static void prepare(euclid_t *e, const vor__raster_t *r)
{
    e->frame = r->frame;
    e->origin_x = r->frame->origin_x;
    e->origin_y = r->frame->origin_y;
    e->points = r->sites->points;
    e->n = r->sites->count;
    e->fast = !r->brute && fits(e->frame, e->points, e->n);
    if (e->fast != 0) {
        carve(e, r->rest);
        fast_prepare(e);
    }
}

/* The family's producers for the scan (vor__raster_row_fn,
 * vor__raster_distances_fn). */
static uint32_t row(void *state, uint32_t j, vor__run_t *runs)
{
    euclid_t *e = state;
    return e->fast ? fast_row(e, j, runs) : brute_row(e, j, runs);
}

/* floor(|q - s|) of each pixel's site, saturated at UINT32_MAX. */
static void distances(const void *state, uint32_t j, const vor__run_t *runs, uint32_t count,
                      uint32_t *px)
{
    const euclid_t *e = state;
    const int32_t origin_x = e->frame->origin_x;
    const int32_t step_x = e->frame->step_x;
    int32_t qy = (int32_t)(e->frame->origin_y + vor__offset(j, e->frame->step_y));
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        for (; i < runs[r].end; i++) {
            int32_t qx = (int32_t)(origin_x + vor__offset(i, step_x));
            px[i] = euclid_distance(qx, qy, &e->points[runs[r].site]);
        }
    }
}

int vor_raster_euclid(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                      const vor_raster_output_t *out, const vor_raster_options_t *options,
                      void *work, size_t work_bytes)
{
    vor__raster_t r;
    int status = vor__raster_check(&r, frame, sites, out, options, work, work_bytes);
    if (status != VOR_OK) {
        return status;
    }
    if (sites->metric != VOR_METRIC_EUCLID) {
        return VOR_ERR_ARG;
    }
    euclid_t e;
    prepare(&e, &r);
    return vor__raster_scan(&r, &e, row, distances);
}
