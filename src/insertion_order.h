/* SPDX-License-Identifier: MIT */
/*
 * insertion_order.h - orders of site ids, private to the library: the
 * grid sort and Z-order both builders start from (inline here), the id
 * sort and vor_build's insertion plan (insertion_order.c).
 */
#ifndef VOR_INSERTION_ORDER_H
#define VOR_INSERTION_ORDER_H

#include <stdbool.h>

#include "multiword.h"
#include "vor.h"

/* vor_build's plan (insertion_order.c): for the n sites already copied
 * into d->sites, writes plan[2i] = the i-th site to insert and plan[2i+1]
 * = the site its search starts from (VOR__NONE: the previous one); the
 * duplicates come last, with their first occurrence. Returns
 * the number of distinct sites. Writes duplicate_of[] if not NULL. Uses
 * scratch[0 .. 6n + 2) for n >= 8; scratch and plan must not overlap. */
uint32_t vor__plan(const vor_t *d, uint32_t n, enum vor_order order,
                   vor_index_t *scratch, vor_index_t *plan, uint32_t *duplicate_of);

/* The square a builder's grid lies over: side 2^shift, the least power of
 * two above the bounding box's longer span, from corner (x0, y0): the
 * box's low corner, or, if `centred`, the box centred in the square, so
 * that the square's midlines halve the box. The divide-and-conquer
 * quadtree centres it: a forked build's two halves are the rows below and
 * above the midline, and anchored at the low corner a box of span 2^32 / 3
 * had three quarters of its rows below it (75/25 halves). The plan, which
 * splits nothing in two, keeps the corner its counts were measured with.
 * The corner may lie below INT32_MIN, so it is an int64; every site's
 * offset from it is at most 2^shift - 1 < 2^32. */
typedef struct {
    int64_t x0;
    int64_t y0;
    unsigned shift;
} vor__grid_square_t;

static inline void vor__grid_square(const vor_t *d, bool centred, vor__grid_square_t *square)
{
    uint64_t span_x = (uint64_t)((int64_t)d->high.x - d->low.x);
    uint64_t span_y = (uint64_t)((int64_t)d->high.y - d->low.y);
    uint64_t span = (span_y > span_x) ? span_y : span_x;
    square->shift = 0;
    while (vor__shr_u64(span, square->shift) != 0u) {
        square->shift++;
    }
    uint64_t last = vor__shl_u64(1u, square->shift) - 1u; /* the largest offset */
    square->x0 = (int64_t)d->low.x - (centred ? (int64_t)((last - span_x) >> 1) : 0);
    square->y0 = (int64_t)d->low.y - (centred ? (int64_t)((last - span_y) >> 1) : 0);
}

/* The column (row) of coordinate c in a 2^k x 2^k grid over a square of
 * side 2^shift from corner: floor((c - corner) 2^k / 2^shift), for corner
 * <= c and c - corner < 2^shift (k <= 12, shift <= 32). c - corner < 2^32,
 * so this is one 32-bit shift, by shift - k or, in a square smaller than
 * the grid, left by k - shift: no 64-bit shift, which is a runtime call on
 * some targets. */
static inline uint32_t vor__grid_cell(int32_t c, int64_t corner, unsigned k, unsigned shift)
{
    uint32_t offset = (uint32_t)c - (uint32_t)corner; /* c - corner, in [0, 2^32) */
    if (shift < k) {
        return offset << (k - shift); /* < 2^k */
    }
    return ((shift - k) < 32u) ? offset >> (shift - k) : 0u;
}

/* Spreads the low 16 bits of x to the even bit positions. */
static inline uint32_t vor__spread_bits(uint32_t x_in)
{
    uint32_t x = x_in;
    x &= 0xFFFFu;
    x = (x | (x << 8)) & 0x00FF00FFu;
    x = (x | (x << 4)) & 0x0F0F0F0Fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
}

/* The inverse: the even bits of x, packed. */
static inline uint32_t vor__compact_bits(uint32_t x_in)
{
    uint32_t x = x_in;
    x &= 0x55555555u;
    x = (x | (x >> 1)) & 0x33333333u;
    x = (x | (x >> 2)) & 0x0F0F0F0Fu;
    x = (x | (x >> 4)) & 0x00FF00FFu;
    x = (x | (x >> 8)) & 0x0000FFFFu;
    return x;
}

/* The cell of site s in the 2^k x 2^k grid over `square`, as a Z-order
 * index: bit pairs (row bit, column bit) from the top level down, so every
 * quadtree square is a run of indices and a square's four children come
 * in the order bottom-left, bottom-right, top-left, top-right. The column
 * (x - x0) 2^k / 2^shift never decreases with x, so a lower column means
 * a smaller x (and the same for rows and y). k <= 12. */
static inline uint32_t vor__grid_z(const vor_t *d, uint32_t s, unsigned k,
                                   const vor__grid_square_t *square)
{
    uint32_t cx = vor__grid_cell(d->sites[s].x, square->x0, k, square->shift);
    uint32_t cy = vor__grid_cell(d->sites[s].y, square->y0, k, square->shift);
    return vor__spread_bits(cx) | (vor__spread_bits(cy) << 1);
}

/* A site's cell in that grid: the Z-order index of vor__grid_z (the
 * divide-and-conquer builder's quadtree), or by rows, (column << k) | row,
 * which serves vor_build's plan as well and spreads no bits. */
enum vor__cell_key { VOR__CELL_Z, VOR__CELL_ROWS };

static inline uint32_t vor__cell_of(const vor_t *d, uint32_t s, unsigned k,
                                    const vor__grid_square_t *square, enum vor__cell_key key)
{
    if (key == VOR__CELL_Z) {
        return vor__grid_z(d, s, k, square);
    }
    return (vor__grid_cell(d->sites[s].x, square->x0, k, square->shift) << k) |
           vor__grid_cell(d->sites[s].y, square->y0, k, square->shift);
}

/* The grid sort both builders start from: a stable counting sort of sites
 * 0 .. n - 1 (n >= 1) by their cell in the 2^k x 2^k grid over `square`
 * (vor__grid_square) into ids[0, n). start[c] is then where cell c's run
 * begins, for c <= 4^k (start[4^k] = n): start needs 4^k + 1 entries apart
 * from ids. Inline, with a constant key at each call, so that neither
 * builder pays for the other's cells: as fast as each one's own copy was. */
static inline void vor__grid_sort(const vor_t *d, uint32_t n, unsigned k,
                                  const vor__grid_square_t *square, enum vor__cell_key key,
                                  vor_index_t *start, vor_index_t *ids)
{
    uint32_t cells = 1u << (2u * k);
    for (uint32_t c = 0; c <= cells; c++) {
        start[c] = 0;
    }
    for (uint32_t s = 0; s < n; s++) {
        start[vor__cell_of(d, s, k, square, key) + 1u]++;
    }
    for (uint32_t c = 0; c < cells; c++) {
        start[c + 1u] = (vor_index_t)(start[c + 1u] + start[c]);
    }
    for (uint32_t s = 0; s < n; s++) {
        uint32_t c = vor__cell_of(d, s, k, square, key);
        ids[start[c]] = (vor_index_t)s;
        start[c]++;
    }
    for (uint32_t c = cells; c > 0u; c--) { /* undo the cursors' advance */
        start[c] = start[c - 1u];
    }
    start[0] = 0;
}

/* Introsort of ids[0..n) by a strict total order on site ids, ids breaking
 * ties: Z-order for the plan, lexicographic (x, y) for the divide-and-conquer
 * builder. O(n log n) worst case, in place, a stack of 34 ranges
 * (insertion_order.c). A key, not a function pointer, keeps the call graph
 * static (make size). */
enum vor__sort_key { VOR__SORT_Z, VOR__SORT_LEX };
void vor__sort_ids(const vor_point_t *sites, vor_index_t *ids, uint32_t n,
                   enum vor__sort_key key);

#endif
