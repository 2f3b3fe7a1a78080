/* SPDX-License-Identifier: MIT */
/*
 * bucket_grid.c - the coarse grid that gives a query without a hint a
 * nearby site to start from, so that a cold nearest-site query takes O(1)
 * expected steps on uniform sites instead of a walk across the diagram.
 *
 * The grid covers the sites' bounding box with square buckets, as many as
 * fit in VOR_BUCKETS(max_sites) entries (one per VOR_SITES_PER_BUCKET
 * sites, 4 by default: about that many sites a bucket when the diagram is
 * full, so a walk from its site to the nearest site of a point in the
 * bucket takes a step or two). Each bucket
 * holds one site in it, or, when it has none, a site of the nearest
 * non-empty bucket before it in row order (after it, for leading empty
 * buckets): any site is a correct start, a near one is a fast start.
 *
 * A coordinate's bucket is floor(offset * scale / 2^32), where offset is
 * its distance from the grid's origin and scale = 2^32 / (bucket side):
 * one 32x32->64 multiply, no division (Cortex-M0 has no divider). The
 * rebuild picks the largest scale whose grid fits, by bisection.
 */
#include "bucket_grid.h"
#include "mesh.h"
#include "multiword.h"

/* The bucket column (or row) of an offset from the origin. */
static uint32_t line_of(uint32_t offset, uint32_t scale)
{
    return (uint32_t)(vor__mul_u32(offset, scale) >> 32);
}

/* The column (or row) of coordinate c: clamped to the grid, so a point
 * outside the box starts from the border bucket nearest to it. */
static uint32_t bucket_line(int32_t c, int32_t origin, uint32_t scale, uint32_t count)
{
    if (c <= origin) {
        return 0;
    }
    /* c > origin: the difference is below 2^32 in unsigned arithmetic */
    uint32_t line = line_of((uint32_t)c - (uint32_t)origin, scale);
    return (line < count) ? line : (count - 1u);
}

static uint32_t bucket_of(const vor_t *d, int32_t x, int32_t y)
{
    return (bucket_line(y, d->bucket_origin.y, d->bucket_scale, d->bucket_rows) *
               d->bucket_columns) +
           bucket_line(x, d->bucket_origin.x, d->bucket_scale, d->bucket_columns);
}

/* How far a site lies from its bucket's centre, as a fraction of the
 * bucket's side (times 2^32, the larger of the two axes): the low word of
 * offset * scale is the position inside the bucket. */
static uint32_t off_centre(const vor_t *d, const vor_point_t *p)
{
    uint32_t fx = (uint32_t)vor__mul_u32((uint32_t)p->x - (uint32_t)d->bucket_origin.x,
                                         d->bucket_scale);
    uint32_t fy = (uint32_t)vor__mul_u32((uint32_t)p->y - (uint32_t)d->bucket_origin.y,
                                         d->bucket_scale);
    uint32_t dx = (fx >= 0x80000000u) ? (fx - 0x80000000u) : (0x80000000u - fx);
    uint32_t dy = (fy >= 0x80000000u) ? (fy - 0x80000000u) : (0x80000000u - fy);
    return (dx > dy) ? dx : dy;
}

/* Buckets of the grid of this scale over a box of the given extent. */
static uint64_t grid_size(uint32_t width, uint32_t height, uint32_t scale)
{
    return vor__mul_u32(line_of(width, scale) + 1u, line_of(height, scale) + 1u);
}

void vor__grid_rebuild(vor_t *d)
{
    uint32_t capacity = (uint32_t)VOR_BUCKETS(d->max_sites);
    uint32_t width = (uint32_t)d->high.x - (uint32_t)d->low.x; /* < 2^32 */
    uint32_t height = (uint32_t)d->high.y - (uint32_t)d->low.y;
    /* the largest scale whose grid fits: scale 0 is one bucket, and the
     * count grows with the scale; 32 halvings of [0, 2^32) */
    uint32_t fits = 0;
    uint32_t step = 0x80000000u;
    for (; step != 0u; step >>= 1) {
        if (grid_size(width, height, fits | step) <= capacity) {
            fits |= step;
        }
    }
    uint32_t columns = line_of(width, fits) + 1u;
    uint32_t rows = line_of(height, fits) + 1u;
    d->bucket_origin.x = d->low.x;
    d->bucket_origin.y = d->low.y;
    d->bucket_scale = fits;
    d->bucket_columns = columns;
    d->bucket_rows = rows;
    d->bucket_rebuild_at = 2u * d->vertex_count;

    uint32_t count = columns * rows;
    vor_index_t *bucket = d->buckets;
    for (uint32_t b = 0; b < count; b++) {
        bucket[b] = VOR__NONE;
    }
    /* each bucket keeps its site nearest to its centre: walks from there
     * are shortest on average */
    for (uint32_t s = 0; s < d->site_count; s++) {
        if (!vor__slot_empty(&d->triangles[s])) { /* in the mesh, not a duplicate */
            const vor_point_t *p = &d->sites[s];
            uint32_t b = bucket_of(d, p->x, p->y);
#if VOR_INDEX_BITS == 32
            /* ids take 21 bits (VOR_MAX_SITES < 2^21): while the grid is
             * filled, the 11 bits above hold the site's distance from the
             * centre (off_centre < 2^31, in steps of 2^20), so that the
             * comparison reads no coordinates from elsewhere in the arena:
             * on a cached host those reads were most of the rebuild. An
             * empty bucket, VOR__NONE, is above every packed entry. */
            vor_index_t packed = ((off_centre(d, p) >> 20) << 21) | s;
            bucket[b] = (packed < bucket[b]) ? packed : bucket[b];
#else
            if (bucket[b] == VOR__NONE ||
                off_centre(d, p) < off_centre(d, &d->sites[bucket[b]])) {
                bucket[b] = (vor_index_t)s;
            }
#endif
        }
    }
#if VOR_INDEX_BITS == 32
    for (uint32_t b = 0; b < count; b++) {
        bucket[b] = (bucket[b] == VOR__NONE) ? VOR__NONE : (bucket[b] & 0x1FFFFFu);
    }
#endif
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
    uint32_t held_at = bucket_of(d, d->sites[held].x, d->sites[held].y);
    if (held_at != b) {
        d->buckets[b] = (vor_index_t)site;
        /* the borrowed run is cut in two: the part away from the held
         * site's bucket joins the new site's run (vor__grid_forget needs
         * each site's entries in one run through its own bucket) */
        uint32_t count = d->bucket_columns * d->bucket_rows;
        if (held_at < b) {
            for (uint32_t k = b + 1u; (k < count) && (d->buckets[k] == held); k++) {
                d->buckets[k] = (vor_index_t)site;
            }
        } else {
            for (uint32_t k = b; (k > 0u) && (d->buckets[k - 1u] == held); k--) {
                d->buckets[k - 1u] = (vor_index_t)site;
            }
        }
    }
}

void vor__grid_forget(vor_t *d, uint32_t site, uint32_t fallback)
{
    /* the entries naming the site: one run of equal entries through its
     * own bucket (vor__grid_rebuild fills runs so, vor__grid_add keeps
     * them so). The run joins the run before it (after it, at the grid's
     * start), whose own bucket then still lies in the merged run. */
    uint32_t count = d->bucket_columns * d->bucket_rows;
    vor_index_t *bucket = d->buckets;
    uint32_t low = bucket_of(d, d->sites[site].x, d->sites[site].y);
    uint32_t high = low;
    if (bucket[low] != site) {
        return; /* the site shares its bucket and is not its entry */
    }
    while ((low > 0u) && (bucket[low - 1u] == site)) {
        low--;
    }
    while (((high + 1u) < count) && (bucket[high + 1u] == site)) {
        high++;
    }
    vor_index_t heir = (low > 0u)           ? bucket[low - 1u]
                       : ((high + 1u) < count) ? bucket[high + 1u]
                                             : (vor_index_t)fallback;
    for (uint32_t k = low; k <= high; k++) {
        bucket[k] = heir;
    }
}

uint32_t vor__grid_start(const vor_t *d, int32_t x, int32_t y)
{
    return d->buckets[bucket_of(d, x, y)];
}

void vor__grid_move(vor_t *d, uint32_t site, vor_point_t from, uint32_t fallback)
{
    vor_point_t to = d->sites[site];
    if (bucket_of(d, from.x, from.y) == bucket_of(d, to.x, to.y)) {
        return; /* the same bucket: every run keeps its own bucket */
    }
    d->sites[site] = from; /* its runs are found from its old bucket */
    vor__grid_forget(d, site, fallback);
    d->sites[site] = to;
    vor__grid_add(d, site);
}
