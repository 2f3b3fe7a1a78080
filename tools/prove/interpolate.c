/* SPDX-License-Identifier: MIT */
/*
 * interpolate.c - the harness of `make prove` for vor_sibson, vor_laplace,
 * vor_interpolate and vor_interpolate_laplace: on each concrete diagram
 * of far_sites.h (none, one site, three collinear, then all six points:
 * the cocircular four, the duplicate and the far site), six points: the
 * cocircular square's centre (strictly inside the hull, where the
 * triangulation is not unique), a point off it inside the square (both
 * walk the conflict region's boundary), one on a hull edge, one at a site,
 * one outside the square that the far site brings inside the hull (the
 * far site a natural neighbour: weights of 7 32-bit words), and one
 * outside both of those hulls (on the three collinear sites' segment);
 * each with the scratch VOR_SIBSON_SCRATCH_BYTES gives (aligned, and 1
 * and 3 bytes past a limb's alignment) and with 64 bytes, too small; the
 * values reach INT32_MIN and INT32_MAX. Then the square's centre from
 * each hint (each site's id, then any other value: inputs.h), with any
 * scratch size up to 64 bytes (below the smallest answer's) and with
 * each pointer the header allows to be NULL, NULL in turn. Every argument
 * is concrete but those, so that EVA keeps every state apart (prove.sh's
 * slevel) and follows each walk and sum exactly.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

/* The scratch at a fixed address (far_sites.h). */
#define SCRATCH_BYTES VOR_SIBSON_SCRATCH_BYTES(N)
#define scratch FIXED_SCRATCH

#define QUERIES 6u
static const vor_point_t queries[QUERIES] = {{5, 5}, {3, 6}, {5, 0}, {10, 10}, {-1, 20}, {15, 0}};
static const int32_t values[N] = {10, -20, 30, INT32_MIN, 99, INT32_MAX};

static int natural(const vor_t *d)
{
    vor_coordinates_t c;
    vor_interpolation_t v;
    int r = 0;
    /*@ loop unroll QUERIES; */
    for (unsigned i = 0; i < QUERIES; i++) {
        vor_point_t q = queries[i];
        r |= vor_sibson(d, q, VOR_NO_HINT, scratch, SCRATCH_BYTES, &c);
        r |= vor_laplace(d, q, VOR_NO_HINT, (unsigned char *)scratch + 1, SCRATCH_BYTES - 1u, &c);
        r |= vor_interpolate(d, values, q, VOR_NO_HINT, scratch, SCRATCH_BYTES, &v);
        r |= vor_interpolate_laplace(d, values, q, VOR_NO_HINT, (unsigned char *)scratch + 3,
                                     SCRATCH_BYTES - 3u, &v);
        r |= vor_sibson(d, q, VOR_NO_HINT, scratch, 64u, &c);
    }
    /* from each hint (unrolled: from an id anywhere the nearest-site
     * walk would start from every site at once), any small scratch, and
     * each NULL the header lists */
    /*@ loop unroll N + 1; */
    for (uint32_t h = 0; h <= N; h++) {
        r |= vor_sibson(d, queries[0], id_or_any(h, N), scratch, SCRATCH_BYTES, &c);
    }
    r |= vor_interpolate(d, values, queries[0], VOR_NO_HINT, scratch,
                         Frama_C_unsigned_int_interval(0u, 64u), &v);
    r |= vor_sibson(NULL, queries[0], VOR_NO_HINT, scratch, SCRATCH_BYTES, &c);
    r |= vor_sibson(d, queries[0], VOR_NO_HINT, NULL, SCRATCH_BYTES, &c);
    r |= vor_sibson(d, queries[0], VOR_NO_HINT, NULL, 0u, &c);
    r |= vor_sibson(d, queries[0], VOR_NO_HINT, scratch, SCRATCH_BYTES, NULL);
    r |= vor_interpolate(d, NULL, queries[0], VOR_NO_HINT, scratch, SCRATCH_BYTES, &v);
    r |= vor_interpolate(d, values, queries[0], VOR_NO_HINT, scratch, SCRATCH_BYTES, NULL);
    return r;
}

int main(void)
{
    return far_sites_each(0u, true, N, natural);
}
