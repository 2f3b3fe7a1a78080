/* SPDX-License-Identifier: MIT */
/*
 * insertion_order.h - orders of site ids (insertion_order.c), private to
 * the library: the grid cells both builders sort sites into, the id sort,
 * and vor_build's insertion plan.
 */
#ifndef VOR_INSERTION_ORDER_H
#define VOR_INSERTION_ORDER_H

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

/* Introsort of ids[0..n) by a strict total order on site ids, ids breaking
 * ties: Z-order for the plan, lexicographic (x, y) for the divide-and-conquer
 * builder. O(n log n) worst case, in place, a stack of 34 ranges
 * (insertion_order.c). A key, not a function pointer, keeps the call graph
 * static (make size). */
enum vor__sort_key { VOR__SORT_Z, VOR__SORT_LEX };
void vor__sort_ids(const vor_point_t *sites, vor_index_t *ids, uint32_t n,
                   enum vor__sort_key key);

#endif
