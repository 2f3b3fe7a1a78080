/* SPDX-License-Identifier: MIT */
/*
 * locate.c - the harness of `make prove` for the queries robots ask:
 * vor_locate, vor_within, vor_triangles_count and vor_triangles_export,
 * over the small concrete diagrams of far_sites.h (an empty one, three
 * collinear sites, then all of them): every query point anywhere in
 * int32, every hint anywhere in uint32 (each site's id in turn, then any
 * other value), every r2 anywhere in uint64, any capacity up to beyond
 * the sites (and any capacity with NULL output), every pointer NULL or
 * not.
 */
#include "far_sites.h"
#include "inputs.h"

static uint64_t any_u64(void)
{
    return (uint64_t)Frama_C_unsigned_long_long_interval(0u, UINT64_MAX);
}

static int queries(const vor_t *d)
{
    uint32_t ids[3];
    uint32_t list[N + 1u];
    uint32_t count;
    int r = 0;

    /* set: EVA cannot relate vor_within's count to the entries its walk
     * wrote before the sort reads them (the tests check each one) */
    /*@ loop unroll N + 1; */
    for (uint32_t i = 0; i <= N; i++) {
        list[i] = any_u32();
    }

    r |= vor_locate(Frama_C_nondet_ptr((void *)d, NULL), any_point(), any_u32(), NULL);
    /* (a capacity above 0: with NULL ids, refused before any walk, which
     * from a hint anywhere could not tell a duplicate's id from a site's) */
    r |= vor_within(Frama_C_nondet_ptr((void *)d, NULL), any_point(), any_u64(), any_u32(), NULL,
                    Frama_C_unsigned_int_interval(1u, UINT32_MAX), &count);
    r |= vor_within(d, any_point(), any_u64(), any_u32(), list, 1u, NULL);
    /* from each hint */
    /*@ loop unroll N + 1; */
    for (uint32_t h = 0; h <= N; h++) {
        r |= vor_locate(d, any_point(), id_or_any(h, N), ids);
    }
    /* from each hint, any capacity the list holds (below the sites:
     * the counting walk first; NULL ids with capacity 0: the count
     * alone), and one holding every site */
    /*@ loop unroll N + 1; */
    for (uint32_t h = 0; h <= N; h++) {
        r |= vor_within(d, any_point(), any_u64(), id_or_any(h, N), Frama_C_nondet_ptr(list, NULL),
                        Frama_C_unsigned_int_interval(0u, N + 1u), &count);
        r |= vor_within(d, any_point(), any_u64(), id_or_any(h, N), list, N + 1u, &count);
    }
    return r;
}

static int export(const vor_t *d)
{
    uint32_t triangles[3u * VOR_TRIANGLES_MAX(N)];
    uint32_t halfedges[3u * VOR_TRIANGLES_MAX(N)];
    uint32_t count;
    int r = 0;

    r |= vor_triangles_count(Frama_C_nondet_ptr((void *)d, NULL), Frama_C_nondet_ptr(&count, NULL));
    r |= vor_triangles_export(Frama_C_nondet_ptr((void *)d, NULL), NULL, halfedges, any_u32(),
                              Frama_C_nondet_ptr(&count, NULL));
    /* each capacity in turn, up to the bound */
    /*@ loop unroll VOR_TRIANGLES_MAX(N) + 1; */
    for (uint32_t c = 0; c <= VOR_TRIANGLES_MAX(N); c++) {
        r |= vor_triangles_export(d, triangles, Frama_C_nondet_ptr(halfedges, NULL), c, &count);
    }
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;

    if (far_sites_init(&d) != VOR_OK) {
        return 1;
    }
    r |= queries(&d);
    r |= export(&d);
    /* each build checked: only its success goes on (-eva-split-return),
     * so that the next build starts from one diagram, not a merge of it
     * with the empty one */
    if (vor_build(&d, collinear, 3u, NULL, NULL) != VOR_OK) {
        return 1;
    }
    r |= queries(&d);
    r |= export(&d);
    if (vor_build(&d, points, N, NULL, NULL) != VOR_OK) {
        return 1;
    }
    r |= queries(&d);
    r |= export(&d);
    return r;
}
