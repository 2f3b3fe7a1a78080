/* SPDX-License-Identifier: MIT */
/*
 * interpolate.c - the harness of `make prove` for vor_sibson, vor_laplace,
 * vor_interpolate and vor_interpolate_laplace: on each small concrete
 * diagram of far_sites.h (five sites, four of them cocircular; three
 * collinear; one), points strictly inside the hull (the cocircular
 * square's centre, where the triangulation is not unique, and off it), on
 * a hull edge, at a site and outside, with the scratch
 * VOR_SIBSON_SCRATCH_BYTES gives (aligned and not) and one too small;
 * then any hint, any scratch size below the smallest answer's, and each
 * pointer the header allows to be NULL, NULL in turn. Every argument is
 * concrete but those, so that EVA follows each walk and sum exactly.
 *
 * WORK IN PROGRESS: not in prove.sh's default list. Run alone
 * (tools/prove/prove.sh interpolate), EVA had not finished after 25
 * minutes: the states of the boundary walk (src/interpolate.c,
 * walk_boundary) keep growing, and the any-hint call makes vor_nearest's
 * walk imprecise (out-of-bounds read alarms in src/queries.c's walk that
 * queries.c's harness avoids with -eva-widening-delay 12). To do: the
 * queries harness's options, the any-hint call in a harness of its own.
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
    /* any hint, any small scratch, and each NULL the header lists */
    r |= vor_sibson(d, queries[0], any_u32(), scratch, SCRATCH_BYTES, &c);
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
    return far_sites_each(0u, true, N - 1u, natural); /* the far site left out: small sums */
}
