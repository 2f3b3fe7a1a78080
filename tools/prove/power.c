/* SPDX-License-Identifier: MIT */
/*
 * power.c - the harness of `make prove` for weighted sites (vor_power.h):
 * vor_power_init(_checked), vor_power_insert, vor_power_build,
 * vor_power_hidden, the hidden and triangle iterators and
 * vor_power_validate; vor_power_remove, vor_power_move and
 * vor_power_nearest with their bad arguments (power_dynamic.c runs them
 * on a concrete diagram, with options of its own: here the slevel that
 * keeps every insert's states apart split the nearest walk's into tens
 * of thousands, and a run had not ended after 20 minutes).
 * Every bad argument the header lists is passed with any value that
 * makes it one (sizes, counts, ids anywhere in their type,
 * pointers NULL); the diagrams are small and concrete, as in diagram.c,
 * so that EVA follows the mesh exactly, and one site is inserted with any
 * int64 weight at each of three places of a five-site diagram (inside,
 * at the inside vertex's point, on a hull edge), so that every outcome
 * of an insertion (a vertex, hidden, hiding a vertex, a duplicate) is
 * analysed for every weight.
 */
#include <__fc_builtin.h>

#include "vor.h"
#include "vor_power.h"

#include "inputs.h"

/* 10 weighted sites: the square 0 to 3 with equal weights (four lifted
 * points on one plane: the perturbation decides); 4 at 0's point and
 * weight (a duplicate); 5 at 0's point, heavier (0 becomes hidden); 6 in
 * the square, so light it is hidden at once; 7 in the square, and 8
 * beside it so heavy that 7, of degree three then, is merged away (the
 * 3-1 flip); 9 collinear with 0 and 1, beyond the square. */
#define N 10u
static const vor_point_t points[N] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0},
                                      {0, 0}, {5, 5},  {3, 4},   {4, 4},  {20, 0}};
static const int64_t weights[N] = {0, 0, 0, 0, 0, 40, -1000, 0, 60, 0};

/* 12 sites: five at one point while it is the only vertex (a
 * duplicate, a lighter one hidden, a heavier one that hides the first, a
 * duplicate of the hidden one), then on one line (the one-dimensional
 * case, kept exactly): 6 above the chain of its neighbours (hidden at
 * once), 7 below it (a vertex), 8 heavy enough to hide the point of the
 * first five on its way, 9 at 5's point and lighter (hidden); then a
 * site off the line, and one on the line of two vertices after that */
#define L 12u
static const vor_point_t line[L] = {{0, 0},   {0, 0},  {0, 0},  {0, 0},   {0, 0},  {12, 9},
                                    {4, 3},   {8, 6},  {-8, -6}, {12, 9}, {4, 20}, {16, 12}};
static const int64_t line_weights[L] = {0, 0, -5, 10, -5, 0, -60, 20, 400, -5, 0, 0};

/* 4 sites on a vertical line (2 above the chain, hidden at once; 3
 * below it); 5 sites whose first three (in a build's order) are on one
 * line, which the build swaps for the fifth, off it */
static const vor_point_t upright[4] = {{0, 0}, {0, 12}, {0, 4}, {0, 8}};
static const int64_t upright_weights[4] = {0, 0, -60, 20};
static const vor_point_t bend[5] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 5}};
static const int64_t bend_weights[5] = {0, 0, 0, 0, 0};

/* room for the sites and the inserts with any weight */
#define MAX (N + 6u)
static uint64_t arena[VOR_POWER_ARENA_BYTES(MAX) / 8u + 1u];

/* Everything the iterators read, and the hidden state of every id in
 * turn (concrete below ids, then any other), validated with and without
 * a report. The helpers return nothing and keep their results in
 * locals: EVA keeps every state apart (-eva-slevel), and a result kept
 * in main would split the rest of the analysis by it. */
static void read_all(const vor_power_t *pd, uint32_t ids)
{
    vor_triangle_iter_t it;
    vor_power_hidden_iter_t h;
    vor_violation_t violation;
    uint32_t tri[3];
    uint32_t site;
    (void)vor_power_triangles_begin(&it, pd);
    while (vor_triangles_next(&it, tri)) {
    }
    (void)vor_power_hidden_begin(&h, pd);
    while (vor_power_hidden_next(&h, &site)) {
    }
    (void)vor_power_hidden_begin(&h, pd);
    (void)vor_power_hidden_next(&h, NULL);
    /*@ loop unroll MAX + 1; */
    for (uint32_t i = 0; i <= ids; i++) {
        (void)vor_power_hidden(pd, id_or_any(i, ids));
    }
    (void)vor_power_validate(pd, &violation);
    (void)vor_power_validate(pd, NULL);
}

/* vor_power_init_checked with every argument anywhere, the arena no
 * shorter than it is said to be: any size up to its own; any max_sites,
 * in two parts (up to MAX, which the arena holds, and beyond, which it
 * cannot: EVA would not tie the weights' end, arena + 8 max_sites, to
 * the size test otherwise); misaligned memory at each alignment, at an
 * absolute address (see cdt.c), which the call turns away before any
 * access; and every size too short. */
static void bad_init(void)
{
    vor_power_t e;
    e.mesh.revision = any_u32(); /* a caller's object: anything (vor_init reads it) */
    (void)vor_power_init_checked(Frama_C_nondet_ptr(&e, NULL), Frama_C_nondet_ptr(arena, NULL),
                                 Frama_C_unsigned_int_interval(0u, sizeof arena),
                                 Frama_C_unsigned_int_interval(0u, MAX), any_u32());
    (void)vor_power_init_checked(Frama_C_nondet_ptr(&e, NULL), Frama_C_nondet_ptr(arena, NULL),
                                 Frama_C_unsigned_int_interval(0u, sizeof arena),
                                 Frama_C_unsigned_int_interval(MAX + 1u, UINT32_MAX), any_u32());
    /*@ loop unroll 7; */
    for (uintptr_t k = 1; k < VOR_POWER_ARENA_ALIGN; k++) {
        (void)vor_power_init(&e, (void *)(0x10000u + k), any_u32(), any_u32());
    }
    (void)vor_power_init(&e, arena,
                         Frama_C_unsigned_int_interval(0u, VOR_POWER_ARENA_BYTES(MAX) - 1u), MAX);
}

/* The calls with NULL arguments, bad counts and a failed begin. */
static void bad_calls(vor_power_t *pd)
{
    vor_triangle_iter_t it;
    vor_power_hidden_iter_t h;
    vor_violation_t violation;
    uint32_t site;
    uint32_t ids[3];
    uint32_t dup[N];
    (void)vor_power_insert(NULL, any_point(), any_weight(), &site);
    (void)vor_power_build(NULL, points, weights, any_u32(), dup);
    (void)vor_power_build(pd, NULL, weights, Frama_C_unsigned_int_interval(1u, UINT32_MAX), dup);
    (void)vor_power_build(pd, points, NULL, Frama_C_unsigned_int_interval(1u, UINT32_MAX), dup);
    (void)vor_power_build(pd, points, weights, Frama_C_unsigned_int_interval(MAX + 1u, UINT32_MAX),
                          dup);
    (void)vor_power_hidden(NULL, any_u32());
    (void)vor_power_hidden_begin(NULL, pd);
    (void)vor_power_hidden_begin(&h, NULL);
    (void)vor_power_hidden_next(&h, &site); /* after the failed begin */
    (void)vor_power_hidden_next(NULL, &site);
    (void)vor_power_triangles_begin(NULL, pd);
    (void)vor_power_triangles_begin(&it, NULL);
    (void)vor_triangles_next(&it, ids);
    (void)vor_power_validate(NULL, &violation);
    (void)vor_power_remove(NULL, any_u32());
    (void)vor_power_remove(pd, any_u32()); /* pd empty: no id is a site */
    (void)vor_power_move(NULL, any_u32(), any_point(), any_weight(), &site);
    (void)vor_power_move(pd, any_u32(), any_point(), any_weight(), &site);
    (void)vor_power_nearest(NULL, any_point(), any_u32(), &site);
    (void)vor_power_nearest(pd, any_point(), any_u32(), NULL);
    (void)vor_power_nearest(pd, any_point(), any_u32(), &site); /* empty */
}

/* One site with any weight at p, in a diagram of five sites (the square
 * and 7 inside it) built afresh in its own arena: whatever the weight,
 * the insert and every read after it; the arena cleared after, so that
 * the outcomes end in one state. (Five sites, not points[]: EVA follows
 * each outcome's flips on its own.) */
static void insert_any(vor_point_t p)
{
    static uint64_t other[sizeof arena / 8u];
    vor_power_t pd;
    uint32_t id;
    pd.mesh.revision = any_u32();
    if (vor_power_init(&pd, other, sizeof other, MAX) == VOR_OK) {
        (void)vor_power_build(&pd, points, weights, 4u, NULL);
        (void)vor_power_insert(&pd, points[7], weights[7], &id);
        (void)vor_power_insert(&pd, p, any_weight(), &id);
        read_all(&pd, 6u);
    }
    /*@ loop unroll 1024; */ /* more than its words: about 200 */
    for (size_t i = 0; i < sizeof other / 8u; i++) {
        other[i] = 0u;
    }
}

/* A new site with any point and weight (a duplicate or not) when the
 * diagram is full. */
static void insert_full(void)
{
    static uint64_t room[VOR_POWER_ARENA_BYTES(3) / 8u + 1u];
    vor_power_t tiny;
    uint32_t id;
    tiny.mesh.revision = any_u32();
    if (vor_power_init(&tiny, room, sizeof room, 3u) != VOR_OK) {
        return;
    }
    /*@ loop unroll 3; */
    for (uint32_t s = 0; s < 3u; s++) {
        (void)vor_power_insert(&tiny, points[s + 5u], weights[s + 5u], &id);
    }
    (void)vor_power_insert(&tiny, any_point(), any_weight(), &id);
    (void)vor_power_insert(&tiny, any_point(), any_weight(), NULL);
    read_all(&tiny, 3u);
}

int main(void)
{
    vor_power_t pd;
    uint32_t dup[MAX];
    uint32_t id;

    bad_init();
    pd.mesh.revision = any_u32();
    if (vor_power_init(&pd, arena, sizeof arena, MAX) != VOR_OK) {
        return 1;
    }
    bad_calls(&pd);
    read_all(&pd, 0u);
    /* the inserts one by one, each read after (every other one without
     * an id back) */
    /*@ loop unroll N; */
    for (uint32_t s = 0; s < N; s++) {
        (void)vor_power_insert(&pd, points[s], weights[s], ((s % 2u) == 0u) ? &id : NULL);
        read_all(&pd, s + 1u);
    }
    /* a duplicate of a hidden site, of a vertex */
    (void)vor_power_insert(&pd, points[6], weights[6], &id);
    (void)vor_power_insert(&pd, points[5], weights[5], &id);

    /* the builds of points[0 .. n) for every n, duplicate_of given or not
     * in turn; no points at all */
    (void)vor_power_build(&pd, NULL, NULL, 0u, NULL);
    read_all(&pd, 0u);
    /*@ loop unroll N + 1; */
    for (uint32_t n = 0; n <= N; n++) {
        (void)vor_power_build(&pd, points, weights, n, ((n % 2u) == 0u) ? dup : NULL);
        read_all(&pd, n);
    }

    /* the one-dimensional case, inserted into the empty diagram, and built */
    (void)vor_power_build(&pd, points, weights, 0u, dup);
    /*@ loop unroll L; */
    for (uint32_t s = 0; s < L; s++) {
        (void)vor_power_insert(&pd, line[s], line_weights[s], &id);
        read_all(&pd, s + 1u);
    }
    (void)vor_power_build(&pd, line, line_weights, L, dup);
    read_all(&pd, L);
    (void)vor_power_build(&pd, line, line_weights, 6u, dup);
    read_all(&pd, 6u);
    (void)vor_power_build(&pd, upright, upright_weights, 0u, dup);
    /*@ loop unroll 4; */
    for (uint32_t s = 0; s < 4u; s++) {
        (void)vor_power_insert(&pd, upright[s], upright_weights[s], &id);
    }
    read_all(&pd, 4u);
    (void)vor_power_build(&pd, upright, upright_weights, 4u, dup);
    read_all(&pd, 4u);
    (void)vor_power_build(&pd, bend, bend_weights, 5u, dup);
    read_all(&pd, 5u);

    /* one site with any weight: inside the square, at the inside
     * vertex's point, on a hull edge */
    {
        vor_point_t inside = {7, 2};
        vor_point_t on_edge = {10, 5};
        insert_any(inside);
        insert_any(points[7]);
        insert_any(on_edge);
    }
    insert_full();
    return 0;
}
