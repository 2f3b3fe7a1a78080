/* SPDX-License-Identifier: MIT */
/*
 * motion.h - the motion cache of small moves (motion.c), private to the
 * library: the entry layout, the epoch every change of the triangles
 * bumps, and vor_move's fast test, inline so that they cost no call (and
 * so that code which only inserts links nothing of motion.c).
 */
#ifndef VOR_MOTION_H
#define VOR_MOTION_H

#include <stdbool.h>

#include "vor.h"

/* One site's entry. With a box: the anchor (centre of the box) in x, y
 * and the stamp (epoch << 8 | level << 5 | (e + 1)), the box being
 * |x - ax|, |y - ay| <= 2^e. Without one (stamp's low five bits 0): y is
 * 1 once the site has moved slowly since the cache was attached and x
 * counts the slow moves it still makes before its box is sized again.
 * The level (0 to 5) is the backoff of a site whose boxes went unused
 * (motion.c, "The backoff"). */
struct vor__motion_entry {
    int32_t x;
    int32_t y;
    uint32_t stamp;
};

/* the size macro in vor.h must match the layout */
typedef char vor__motion_size_check[(sizeof(struct vor__motion_entry) == VOR_MOTION_ENTRY_BYTES)
                                        ? 1
                                        : -1];

/* the stamp's e + 1, 0 for no box */
#define VOR__BOX_MASK 0x1Fu
#define VOR__EPOCH_MASK 0xFFFFFFu

/* Every change of the triangles calls this: stamps of older epochs are
 * void from now on. After 2^24 changes the epoch comes round again and
 * an old stamp would look current, so at the wrap every stamp is cleared
 * (once in 2^24 changes: O(1) amortised). */
static inline void vor__topology_changed(vor_t *d)
{
    d->motion_epoch = (d->motion_epoch + 1u) & VOR__EPOCH_MASK;
    if (d->motion_epoch == 0u) {
        d->motion_epoch = 1u;
        for (uint32_t i = 0; (d->motion != NULL) && (i < d->max_sites); i++) {
            d->motion[i].x = 0;
            d->motion[i].y = 0; /* the backoff starts again */
            d->motion[i].stamp = 0;
        }
    }
}

/* Is (x, y) inside the box of `site` (a site in the mesh), stamped in the
 * current epoch? Then by invariant J (motion.c) moving it there changes
 * no triangle and meets no other site. The box lies within int32
 * (motion.c), so the offsets below, taken mod 2^32, cannot wrap into it. */
static inline bool vor__motion_fast(const vor_t *d, uint32_t site, int32_t x, int32_t y)
{
    if (d->motion == NULL) {
        return false;
    }
    const struct vor__motion_entry *e = &d->motion[site];
    uint32_t stamp = e->stamp;
    uint32_t size = stamp & VOR__BOX_MASK;
    if (((stamp >> 8) != d->motion_epoch) || (size == 0u)) {
        return false;
    }
    uint32_t r = 1u << (size - 1u); /* e <= 30: 2r fits */
    return (((uint32_t)x - (uint32_t)e->x + r) <= (2u * r)) &&
           ((uint32_t)y - (uint32_t)e->y + r) <= (2u * r);
}

/* After a slow move of p from `from`, begun in `epoch`, that kept the
 * triangles or changed them (p at its new place, the mesh final): restores invariant J for
 * p's predicates and, when the backoff allows and a box can hold another
 * such step, gives p a new box (motion.c). Only with a cache attached:
 * through the pointer vor_motion_attach stores, so that vor_move links
 * none of motion.c unless the firmware attaches a cache. from by pointer:
 * a structure passed by value is a memcpy call on Cortex-M0 at -Og. */
static inline void vor__motion_update(vor_t *d, uint32_t p, const vor_point_t *from,
                                      uint32_t epoch)
{
    if (d->motion_update != NULL) {
        d->motion_update(d, p, from, epoch);
    }
}

#endif
