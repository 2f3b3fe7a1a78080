/*
 * bucket_grid.c - the coarse grid that gives a query without a hint a
 * nearby site to start from, so that a cold nearest-site query takes O(1)
 * expected steps on uniform sites instead of a walk across the diagram.
 *
 * The grid covers the sites' bounding box with square buckets of side
 * 2^shift, the smallest power of two for which the buckets fit in
 * VOR_BUCKETS(max_sites) entries (one per 16 sites: about 16 sites a
 * bucket when the diagram is full, so a walk from any of them to the
 * nearest site of a point in the bucket takes a few steps). Each bucket
 * holds one site in it, or, when it has none, a site of the nearest
 * non-empty bucket before it in row order (after it, for leading empty
 * buckets): any site is a correct start, a near one is a fast start.
 * Powers of two make the bucket of a point two shifts, with no division.
 */
#include "mesh.h"

/* x >> shift for shifts up to 32 (a 32-bit shift by 32 is undefined in C) */
static uint32_t shift_right(uint32_t x, uint32_t shift)
{
    return (shift >= 32u) ? 0u : x >> shift;
}

/* The column (or row) of coordinate c: clamped to the grid, so a point
 * outside the box starts from the border bucket nearest to it. */
static uint32_t bucket_line(int32_t c, int32_t origin, uint32_t shift, uint32_t count)
{
    if (c <= origin) {
        return 0;
    }
    /* c > origin: the difference is below 2^32 in unsigned arithmetic */
    uint32_t line = shift_right((uint32_t)c - (uint32_t)origin, shift);
    return (line < count) ? line : count - 1u;
}

static uint32_t bucket_of(const vor_t *d, int32_t x, int32_t y)
{
    return bucket_line(y, d->bucket_origin.y, d->bucket_shift, d->bucket_rows) *
               d->bucket_columns +
           bucket_line(x, d->bucket_origin.x, d->bucket_shift, d->bucket_columns);
}

void vor__grid_rebuild(vor_t *d)
{
    uint32_t capacity = (uint32_t)VOR_BUCKETS(d->max_sites);
    uint32_t width = (uint32_t)d->high.x - (uint32_t)d->low.x; /* < 2^32 */
    uint32_t height = (uint32_t)d->high.y - (uint32_t)d->low.y;
    /* the smallest shift whose grid fits; shift 32 is a single bucket, and
     * the count only shrinks as the shift grows, so the loop finds one */
    uint32_t shift = 0, columns = 1, rows = 1;
    for (; shift <= 32u; shift++) {
        uint32_t last_column = shift_right(width, shift), last_row = shift_right(height, shift);
        if (last_column < capacity && last_row < capacity && /* no overflow below */
            vor__mul_u32(last_column + 1u, last_row + 1u) <= (uint64_t)capacity) {
            columns = last_column + 1u;
            rows = last_row + 1u;
            break;
        }
    }
    d->bucket_origin.x = d->low.x;
    d->bucket_origin.y = d->low.y;
    d->bucket_shift = shift;
    d->bucket_columns = columns;
    d->bucket_rows = rows;
    d->bucket_rebuild_at = 2u * d->vertex_count;

    uint32_t count = columns * rows;
    vor_index_t *bucket = d->buckets;
    for (uint32_t b = 0; b < count; b++) {
        bucket[b] = VOR__NONE;
    }
    for (uint32_t s = 0; s < d->site_count; s++) {
        if (!vor__slot_empty(&d->triangles[s])) { /* in the mesh, not a duplicate */
            uint32_t b = bucket_of(d, d->sites[s].x, d->sites[s].y);
            bucket[b] = (bucket[b] == VOR__NONE) ? (vor_index_t)s : bucket[b];
        }
    }
    /* empty buckets borrow from the last filled one before them, the
     * leading ones from the first filled one */
    vor_index_t last = VOR__NONE;
    for (uint32_t b = 0; b < count; b++) {
        bucket[b] = (bucket[b] == VOR__NONE) ? last : bucket[b];
        last = bucket[b];
    }
    for (uint32_t b = count; b-- > 0u;) {
        last = (bucket[b] == VOR__NONE) ? last : bucket[b];
        bucket[b] = last;
    }
}

void vor__grid_add(vor_t *d, uint32_t site)
{
    if (d->vertex_count >= d->bucket_rebuild_at) {
        /* redrawn as the site count doubles: O(1) amortized per site, and
         * the grid follows the bounding box as it grows */
        vor__grid_rebuild(d);
        return;
    }
    /* a bucket whose site lies elsewhere (borrowed) takes the new site */
    uint32_t b = bucket_of(d, d->sites[site].x, d->sites[site].y);
    vor_index_t held = d->buckets[b];
    if (bucket_of(d, d->sites[held].x, d->sites[held].y) != b) {
        d->buckets[b] = (vor_index_t)site;
    }
}

uint32_t vor__grid_start(const vor_t *d, int32_t x, int32_t y)
{
    return d->buckets[bucket_of(d, x, y)];
}
