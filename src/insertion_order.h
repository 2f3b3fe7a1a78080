/* SPDX-License-Identifier: MIT */
/*
 * insertion_order.h - orders of site ids, private to the library: the
 * grid sort and Z-order both builders start from (inline here), the id
 * sort and vor_build's insertion plan (insertion_order.c).
 */
#ifndef VOR_INSERTION_ORDER_H
#define VOR_INSERTION_ORDER_H

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

/* The column (row) of coordinate c in a 2^k x 2^k grid over a square of
 * side 2^shift from low: floor((c - low) 2^k / 2^shift), for low <= c and
 * c - low < 2^shift (k <= 12, shift <= 32). c - low < 2^32, so this is one
 * 32-bit shift, by shift - k or, in a square smaller than the grid, left
 * by k - shift: no 64-bit shift, which is a runtime call on some targets. */
static inline uint32_t vor__grid_cell(int32_t c, int32_t low, unsigned k, unsigned shift)
{
    uint32_t offset = (uint32_t)((int64_t)c - low);
    if (shift < k) {
        return offset << (k - shift); /* < 2^k */
    }
    return (shift - k < 32u) ? offset >> (shift - k) : 0u;
}

/* Spreads the low 16 bits of x to the even bit positions. */
static inline uint32_t vor__spread_bits(uint32_t x)
{
    x &= 0xFFFFu;
    x = (x | (x << 8)) & 0x00FF00FFu;
    x = (x | (x << 4)) & 0x0F0F0F0Fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
}

/* The inverse: the even bits of x, packed. */
static inline uint32_t vor__compact_bits(uint32_t x)
{
    x &= 0x55555555u;
    x = (x | (x >> 1)) & 0x33333333u;
    x = (x | (x >> 2)) & 0x0F0F0F0Fu;
    x = (x | (x >> 4)) & 0x00FF00FFu;
    x = (x | (x >> 8)) & 0x0000FFFFu;
    return x;
}

/* The cell of site s in the 2^k x 2^k grid over the sites' bounding
 * square (corner d->low, side 2^shift), as a Z-order index: bit pairs
 * (row bit, column bit) from the top level down, so every quadtree square
 * is a run of indices and a square's four children come in the order
 * bottom-left, bottom-right, top-left, top-right. The column
 * (x - low.x) 2^k / 2^shift never decreases with x, so a lower column
 * means a smaller x (and the same for rows and y). k <= 12. */
static inline uint32_t vor__grid_z(const vor_t *d, uint32_t s, unsigned k, unsigned shift)
{
    uint32_t cx = vor__grid_cell(d->sites[s].x, d->low.x, k, shift);
    uint32_t cy = vor__grid_cell(d->sites[s].y, d->low.y, k, shift);
    return vor__spread_bits(cx) | (vor__spread_bits(cy) << 1);
}

/* A site's cell in that grid: the Z-order index of vor__grid_z (the
 * divide-and-conquer builder's quadtree), or by rows, (column << k) | row,
 * which serves vor_build's plan as well and spreads no bits. */
enum vor__cell_key { VOR__CELL_Z, VOR__CELL_ROWS };

static inline uint32_t vor__cell_of(const vor_t *d, uint32_t s, unsigned k, unsigned shift,
                                    enum vor__cell_key key)
{
    if (key == VOR__CELL_Z) {
        return vor__grid_z(d, s, k, shift);
    }
    return (vor__grid_cell(d->sites[s].x, d->low.x, k, shift) << k) |
           vor__grid_cell(d->sites[s].y, d->low.y, k, shift);
}

/* The grid sort both builders start from: a stable counting sort of sites
 * 0 .. n - 1 (n >= 1, their box in d->low, d->high) by their cell in the
 * 2^k x 2^k grid into ids[0, n). Returns the grid's shift (the bounding
 * square's side is 2^shift); start[c] is then where cell c's run begins,
 * for c <= 4^k (start[4^k] = n): start needs 4^k + 1 entries apart from
 * ids. Inline, with a constant key at each call, so that neither builder
 * pays for the other's cells: as fast as each one's own copy was. */
static inline unsigned vor__grid_sort(const vor_t *d, uint32_t n, unsigned k,
                                      enum vor__cell_key key, vor_index_t *start,
                                      vor_index_t *ids)
{
    uint64_t span = (uint64_t)((int64_t)d->high.x - d->low.x);
    uint64_t span_y = (uint64_t)((int64_t)d->high.y - d->low.y);
    span = (span_y > span) ? span_y : span;
    unsigned shift = 0;
    while (vor__shr_u64(span, shift) != 0u) {
        shift++;
    }
    uint32_t cells = 1u << (2u * k);
    for (uint32_t c = 0; c <= cells; c++) {
        start[c] = 0;
    }
    for (uint32_t s = 0; s < n; s++) {
        start[vor__cell_of(d, s, k, shift, key) + 1u]++;
    }
    for (uint32_t c = 0; c < cells; c++) {
        start[c + 1u] = (vor_index_t)(start[c + 1u] + start[c]);
    }
    for (uint32_t s = 0; s < n; s++) {
        uint32_t c = vor__cell_of(d, s, k, shift, key);
        ids[start[c]] = (vor_index_t)s;
        start[c]++;
    }
    for (uint32_t c = cells; c > 0u; c--) { /* undo the cursors' advance */
        start[c] = start[c - 1u];
    }
    start[0] = 0;
    return shift;
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
