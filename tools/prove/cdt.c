/* SPDX-License-Identifier: MIT */
/*
 * cdt.c - the harness of `make prove` for the constraints (vor_cdt.h):
 * vor_cdt_attach, vor_constrain, vor_unconstrain, vor_cdt_crossing,
 * vor_cdt_domain and the triangle, inside and edge iterators, with
 * vor_insert, vor_remove, vor_move and vor_build keeping the constrained
 * triangulation up to date (and vor__incircle_h, below). The sites are
 * concrete (a square, its centre and three pairs of sites whose segments
 * cross the diagonal off any site, two of them at one point; then 12
 * sites with a spike), so that EVA follows each mesh exactly; every bad
 * argument the header lists is passed with any value that makes it one.
 */
#include "crossing.h"
#include "inputs.h"
#include "vor.h"
#include "vor_cdt.h"

/* 11 points: the square (0 to 3) and its centre (4), so that the
 * diagonal 0-2 is cut at a site; 5-6 and 7-8 cross the diagonal at (9, 9),
 * no site, where 5-6 makes a crossing vertex and 7-8 runs through it;
 * 9-10 crosses it at (11, 11), beyond that crossing vertex. */
#define SITES 11u
static const vor_point_t points[SITES] = {{0, 0},  {12, 0}, {12, 12}, {0, 12}, {6, 6},  {7, 11},
                                          {11, 7}, {10, 11}, {8, 7},   {10, 12}, {12, 10}};

/* 12 points where a constraint, 0-1, crosses every triangle of a vertex
 * hanging below it (2, at (0, -1): a spike in the cavity), and a second
 * one, 10-11, passes under that vertex. */
#define SPIKE 12u
static const vor_point_t spike[SPIKE] = {{-100, 0}, {100, 0}, {0, -1},    {0, -50},
                                         {-20, 5},  {0, 5},   {20, 5},    {-60, 30},
                                         {60, 30},  {0, 60},  {-70, -40}, {70, -40}};

/* room for the sites and the ones inserted later */
#define N 16u
#define EDGES 40u
#define CROSSINGS 4u
#define CUT ((2u * (N + CROSSINGS)) + 2u)
static uint32_t arena[(VOR_ARENA_BYTES(N) + 3u) / 4u];
static uint32_t walls[(VOR_CDT_BYTES(N, EDGES, CROSSINGS, CUT) + 3u) / 4u];

/* Any value from lo up. */
static uint32_t from(uint32_t lo)
{
    return Frama_C_unsigned_int_interval(lo, UINT32_MAX);
}

/* vor_cdt_attach's failures: each argument the header turns away, with
 * any value that makes it one (nothing is attached). */
static int bad_attach(vor_t *d)
{
    vor_cdt_limits_t limits = {EDGES, CROSSINGS, CUT};
    int r = 0;
    r |= vor_cdt_attach(NULL, walls, sizeof walls, &limits);
    r |= vor_cdt_attach(d, NULL, any_u32(), &limits);
    r |= vor_cdt_attach(d, walls, any_u32(), NULL);
    limits.edges = 0u;
    limits.crossings = any_u32();
    limits.cut = any_u32();
    r |= vor_cdt_attach(d, walls, sizeof walls, &limits);
    limits.edges = from(1u);
    limits.crossings = from(VOR_MAX_SITES - N + 1u);
    r |= vor_cdt_attach(d, walls, sizeof walls, &limits);
    limits.edges = from((3u * (N + CROSSINGS)) + 1u);
    limits.crossings = CROSSINGS;
    r |= vor_cdt_attach(d, walls, sizeof walls, &limits);
    limits.edges = EDGES;
    limits.cut = from(CUT + 1u);
    r |= vor_cdt_attach(d, walls, sizeof walls, &limits);
    limits.cut = CUT;
    /* misaligned, each way, of any size: at an absolute address, whose
     * alignment EVA knows (of a variable's address it knows none, and
     * would go on to attach memory one byte into walls); the call
     * returns before any access, which EVA would flag (no range of
     * absolute addresses is valid) */
    /*@ loop unroll 3; */
    for (uintptr_t k = 1; k < VOR_CDT_ALIGN; k++) {
        r |= vor_cdt_attach(d, (void *)(0x10000u + k), any_u32(), &limits);
    }
    /* too short, by any amount */
    r |= vor_cdt_attach(d, walls,
                        Frama_C_unsigned_int_interval(0u, VOR_CDT_BYTES(N, EDGES, CROSSINGS, CUT) - 1u),
                        &limits);
    return r;
}

/* The calls on d without constraint memory, and with NULL arguments. */
static int bad_calls(vor_t *d)
{
    vor_cdt_triangle_iter_t it;
    vor_cdt_edge_iter_t et;
    uint32_t ids[4], a, b;
    int r = 0;
    r |= vor_constrain(d, 0u, 1u) | vor_unconstrain(d, 0u, 1u) | vor_cdt_domain(d);
    r |= vor_cdt_crossing(d, N, ids);
    r |= vor_cdt_triangles_begin(&it, d);
    r |= vor_cdt_triangles_next(&it, ids);
    r |= vor_cdt_inside_begin(&it, d);
    r |= vor_cdt_edges_begin(&et, d);
    r |= vor_cdt_edges_next(&et, &a, &b);
    r |= vor_constrain(NULL, 0u, 1u) | vor_unconstrain(NULL, 0u, 1u) | vor_cdt_domain(NULL);
    r |= vor_cdt_crossing(NULL, N, ids);
    r |= vor_cdt_triangles_begin(NULL, d) | vor_cdt_triangles_begin(&it, NULL);
    r |= vor_cdt_inside_begin(NULL, d) | vor_cdt_inside_begin(&it, NULL);
    r |= vor_cdt_triangles_next(NULL, ids);
    r |= vor_cdt_edges_begin(NULL, d) | vor_cdt_edges_begin(&et, NULL);
    r |= vor_cdt_edges_next(NULL, &a, &b);
    return r;
}

/* Everything the iterators and vor_cdt_crossing read, every id of the
 * latter in turn (concrete below max_sites + CROSSINGS, then any other),
 * each NULL the header lists in turn. */
static int read_all(vor_t *d)
{
    vor_cdt_triangle_iter_t it;
    vor_cdt_edge_iter_t et;
    uint32_t ids[4], a, b;
    int r = 0;
    r |= vor_cdt_triangles_begin(&it, d);
    while (vor_cdt_triangles_next(&it, ids)) {
    }
    r |= vor_cdt_triangles_begin(&it, d);
    r |= vor_cdt_triangles_next(&it, NULL);
    r |= vor_cdt_inside_begin(&it, d); /* a domain marked since the last change or not */
    while (vor_cdt_triangles_next(&it, ids)) {
    }
    r |= vor_cdt_edges_begin(&et, d);
    while (vor_cdt_edges_next(&et, &a, &b)) {
    }
    r |= vor_cdt_edges_begin(&et, d);
    r |= vor_cdt_edges_next(&et, NULL, &b) | vor_cdt_edges_next(&et, &a, NULL);
    r |= vor_cdt_crossing(d, Frama_C_unsigned_int_interval(0u, N - 1u), ids);
    /*@ loop unroll CROSSINGS; */
    for (uint32_t x = N; x < N + CROSSINGS; x++) {
        r |= vor_cdt_crossing(d, x, ids);
    }
    r |= vor_cdt_crossing(d, from(N + CROSSINGS), ids);
    r |= vor_cdt_crossing(d, N, NULL);
    return r;
}

/* vor__incircle_h (crossing.h), the exact incircle test without the
 * perturbation, which only the tests call (the library's are all
 * perturbed): the crossing vertex at (9, 9) against the circle through
 * three corners of the square. */
static int exact_incircle(void)
{
    vor__hpoint_t h[4];
    (void)vor__hpoint_crossing(&h[3], points[0], points[2], points[5], points[6]);
    vor__hpoint_site(&h[0], points[1]);
    vor__hpoint_site(&h[1], points[2]);
    vor__hpoint_site(&h[2], points[3]);
    return vor__incircle_h(&h[0], &h[1], &h[2], &h[3]);
}

int main(void)
{
    vor_t d;
    vor_violation_t violation;
    vor_cdt_limits_t limits = {EDGES, CROSSINGS, 0u};
    uint32_t id;
    int r = 0;

    d.revision = any_u32();
    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    r |= bad_calls(&d);
    r |= bad_attach(&d);
    /* attached to the empty diagram, with a cut of no triangle: the sites
     * go in one by one; only edges there are can be constrained */
    if (vor_cdt_attach(&d, walls, sizeof walls, &limits) != VOR_OK) {
        return 1;
    }
    r |= read_all(&d);
    /*@ loop unroll SITES; */
    for (uint32_t s = 0; s < SITES; s++) {
        r |= vor_insert(&d, points[s], &id);
    }
    r |= vor_constrain(&d, 0u, 2u); /* cuts triangles: too long */
    r |= vor_constrain(&d, 0u, 1u); /* a hull edge */
    /* attached again (the Delaunay triangulation copied): 3 edges, no
     * crossing; a split, a crossing, a site moved onto an edge overflow */
    limits.edges = 3u;
    limits.crossings = 0u;
    limits.cut = (2u * N) + 2u; /* the most without crossings */
    if (vor_cdt_attach(&d, walls, sizeof walls, &limits) != VOR_OK) {
        return 1;
    }
    r |= vor_constrain(&d, 0u, 2u); /* 0-4, 4-2 */
    r |= vor_constrain(&d, 1u, 0u);
    r |= vor_constrain(&d, 5u, 6u);
    vor_point_t on_diagonal = {3, 3};
    r |= vor_insert(&d, on_diagonal, &id);
    r |= vor_move(&d, 3u, on_diagonal, &id);
    /* the limits the rest needs */
    limits.edges = EDGES;
    limits.crossings = CROSSINGS;
    limits.cut = CUT;
    if (vor_cdt_attach(&d, walls, sizeof walls, &limits) != VOR_OK) {
        return 1;
    }
    r |= vor_constrain(&d, 0u, 2u);
    r |= vor_constrain(&d, 5u, 6u);  /* a crossing vertex at (9, 9) */
    r |= vor_constrain(&d, 7u, 8u);  /* through it */
    r |= vor_constrain(&d, 9u, 10u); /* one at (11, 11), beside it */
    r |= vor_constrain(&d, 0u, 1u);
    r |= vor_constrain(&d, 1u, 0u);  /* again: two constraints on 0-1 */
    r |= vor_constrain(&d, 3u, 3u);
    r |= vor_constrain(&d, 3u, from(SITES));
    r |= read_all(&d);
    r |= vor_cdt_domain(&d);
    r |= read_all(&d);
    /* sites: on a constrained edge (it splits), at a crossing vertex (it
     * takes its place), on a constrained hull edge and beyond it on its
     * line */
    vor_point_t at_crossing = {11, 11};
    vor_point_t on_hull = {6, 0};
    vor_point_t beyond = {14, 0};
    r |= vor_insert(&d, on_diagonal, &id);
    r |= vor_insert(&d, at_crossing, &id);
    r |= vor_insert(&d, on_hull, &id);
    r |= vor_insert(&d, beyond, &id);
    r |= vor_cdt_domain(&d);
    r |= read_all(&d);
    /* a constraint's end stays; a free site goes, moves, and comes back */
    vor_point_t aside = {1, 13};
    r |= vor_remove(&d, 4u);
    r |= vor_move(&d, 4u, aside, &id);
    r |= vor_move(&d, 3u, points[4], &id); /* onto a site */
    r |= vor_move(&d, 3u, aside, &id);
    r |= vor_remove(&d, 3u);
    r |= vor_constrain(&d, 3u, 0u);        /* a free id */
    r |= vor_insert(&d, points[3], &id);
    r |= vor_validate(&d, &violation);
    /* constraints off: pieces not constrained, a site to itself, no site;
     * then 5-6 (its crossing vertex stays, on 0-2 and 7-8), 7-8 (now it
     * goes), 0-1 twice, and a third time when no constraint is left */
    r |= vor_unconstrain(&d, 5u, 7u);
    r |= vor_unconstrain(&d, 3u, 3u);
    r |= vor_unconstrain(&d, from(SITES + 4u), 0u);
    r |= vor_unconstrain(&d, 5u, 6u);
    r |= read_all(&d);
    r |= vor_unconstrain(&d, 8u, 7u);
    r |= vor_unconstrain(&d, 0u, 1u);
    r |= vor_unconstrain(&d, 0u, 1u);
    r |= vor_unconstrain(&d, 0u, 1u);
    r |= vor_validate(&d, &violation);
    r |= read_all(&d);
    /* a build starts the constrained triangulation again */
    r |= vor_build(&d, points, SITES, NULL, NULL);
    r |= vor_constrain(&d, 5u, 6u);
    r |= read_all(&d);
    r |= vor_build(&d, spike, SPIKE, NULL, NULL);
    r |= vor_constrain(&d, 0u, 1u);
    r |= vor_constrain(&d, 10u, 11u);
    r |= read_all(&d);
    r |= exact_incircle();
    return r;
}
