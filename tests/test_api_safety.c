/* SPDX-License-Identifier: MIT */
/*
 * test_api_safety.c - every public call of vor.h, vor_power.h and
 * vor_raster.h with each bad argument (vor_field_raster's among them): a NULL pointer, a wrong
 * configuration fingerprint, a zeroed or closed iterator, an id that is
 * not a site (out of range, or a duplicate's), an inverted or empty box,
 * a too small or misaligned arena, a full diagram. Each call must
 * return its documented code, and the diagram, its arena and the output
 * buffers must be byte for byte as before (compared with copies taken
 * just before the call). Expected ids come from how the input was made
 * (which points are copies of which), never from the library.
 */
#include "test.h"
#include "vor.h"
#include "vor_power.h"
#include "vor_raster.h"

#define SAFE_SITES 32u
#define COPIES 5u /* the one-point diagram: five copies of one point */

static vor_point_t points[SAFE_SITES];
static uint8_t arena[VOR_ARENA_BYTES(SAFE_SITES)] __attribute__((aligned(8)));
static uint8_t saved_arena[sizeof arena];
static vor_t diagram, saved_diagram;

static void fill(void *to, size_t n, uint8_t value)
{
    uint8_t *t = to;
    for (size_t i = 0; i < n; i++) {
        t[i] = value;
    }
}

/* The diagram and its whole arena, before a call that must fail. */
static void snapshot(void)
{
    test_copy_bytes(&saved_diagram, &diagram, sizeof diagram);
    test_copy_bytes(saved_arena, arena, sizeof arena);
}

static bool unchanged(void)
{
    return test_same_bytes(&saved_diagram, &diagram, sizeof diagram) &&
           test_same_bytes(saved_arena, arena, sizeof arena);
}

/* SAFE_SITES distinct random points (distinct by construction: a grid
 * cell each, jittered inside it). */
static void make_points(test_rng_t *rng)
{
    for (uint32_t i = 0; i < SAFE_SITES; i++) {
        points[i].x = (int32_t)(i % 8u) * 1000 + test_rng_range(rng, 0, 999);
        points[i].y = (int32_t)(i / 8u) * 1000 + test_rng_range(rng, 0, 999);
    }
}

/* A fork/join hook that counts its calls and runs the work at once. */
static int safety_fork(void *context, void (*work)(void *arg), void *arg)
{
    (*(unsigned *)context)++;
    work(arg);
    return 0;
}

static void safety_join(void *context)
{
    (*(unsigned *)context)++;
}

static bool build_all(uint32_t max_sites)
{
    return vor_init(&diagram, arena, sizeof arena, max_sites) == VOR_OK &&
           vor_build(&diagram, points, SAFE_SITES < max_sites ? SAFE_SITES : max_sites, NULL,
                     NULL) == VOR_OK;
}

static void check_config(void)
{
    /* a fingerprint that differs in any bit is refused before anything */
    static vor_tracker_t tracker;
    fill(&diagram, sizeof diagram, 0xA5);
    fill(&tracker, sizeof tracker, 0x5A);
    snapshot();
    vor_tracker_t tracker_before;
    test_copy_bytes(&tracker_before, &tracker, sizeof tracker);
    unsigned bad = 0;
    for (unsigned bit = 0; bit < 32u; bit++) {
        uint32_t other = VOR_CONFIG_FINGERPRINT ^ (1u << bit);
        bad += vor_init_checked(&diagram, arena, sizeof arena, SAFE_SITES, other) ==
                       VOR_ERR_CONFIG && unchanged() ? 0u : 1u;
        bad += vor_tracker_begin_checked(&tracker, &diagram, other) == VOR_ERR_CONFIG &&
                       test_same_bytes(&tracker, &tracker_before, sizeof tracker)
                   ? 0u
                   : 1u;
    }
    CHECK(bad == 0, "%u mismatched fingerprints accepted or wrote", bad);
    CHECK(VOR_ERR_CONFIG < 0, "VOR_ERR_CONFIG is negative");
}

static void check_init(void)
{
    fill(&diagram, sizeof diagram, 0xA5);
    snapshot();
    CHECK(vor_init(NULL, arena, sizeof arena, 4) == VOR_ERR_ARG, "init: NULL diagram");
    CHECK(vor_init(&diagram, NULL, sizeof arena, 4) == VOR_ERR_ARG && unchanged(),
          "init: NULL arena");
    CHECK(vor_init(&diagram, arena, sizeof arena, 0) == VOR_ERR_ARG && unchanged(),
          "init: no sites");
    CHECK(vor_init(&diagram, arena, sizeof arena, VOR_MAX_SITES + 1u) == VOR_ERR_ARG &&
              unchanged(),
          "init: too many sites");
    CHECK(vor_init(&diagram, arena + 1, sizeof arena - 1u, 4) == VOR_ERR_ALIGN && unchanged(),
          "init: misaligned arena");
    CHECK(vor_init(&diagram, arena, VOR_ARENA_BYTES(SAFE_SITES) - 1u, SAFE_SITES) ==
                  VOR_ERR_NOMEM &&
              unchanged(),
          "init: arena one byte short");
}

/* Diagrams whose mesh has 0 or 1 vertices take no hint but a site of the
 * mesh or VOR_NO_HINT (issue 15: a duplicate's id was taken). */
static void check_small_hints(void)
{
    uint32_t out = 77, found = 77, list[4] = {77, 77, 77, 77};
    CHECK(vor_init(&diagram, arena, sizeof arena, SAFE_SITES) == VOR_OK, "init");
    snapshot();
    CHECK(vor_insert_near(&diagram, (vor_point_t){5, 5}, 0, &out) == VOR_ERR_ARG && unchanged() && out == 77,
          "empty diagram: hint 0 is not a site");
    CHECK(vor_nearest(&diagram, (vor_point_t){5, 5}, VOR_NO_HINT, &out) == VOR_ERR_EMPTY && out == 77,
          "empty diagram: nearest");
    CHECK(vor_insert_near(&diagram, (vor_point_t){5, 5}, VOR_NO_HINT, &out) == VOR_OK && out == 0u,
          "empty diagram: VOR_NO_HINT accepted");

    vor_point_t same[COPIES];
    uint32_t duplicate_of[COPIES];
    for (uint32_t i = 0; i < COPIES; i++) {
        same[i].x = -40;
        same[i].y = 1234;
    }
    CHECK(vor_build(&diagram, same, COPIES, NULL, duplicate_of) == VOR_OK, "five copies");
    snapshot();
    unsigned bad = 0;
    for (uint32_t hint = 1; hint < COPIES + 2u; hint++) { /* copies, then unused ids */
        out = found = 77;
        list[0] = 77;
        bad += vor_insert_near(&diagram, (vor_point_t){9, 9}, hint, &out) == VOR_ERR_ARG ? 0u : 1u;
        bad += vor_nearest(&diagram, (vor_point_t){9, 9}, hint, &out) == VOR_ERR_ARG ? 0u : 1u;
        bad += vor_nearest_k(&diagram, (vor_point_t){9, 9}, hint, 2, list, &found) == VOR_ERR_ARG ? 0u : 1u;
        bad += vor_locate(&diagram, (vor_point_t){9, 9}, hint, list) == VOR_ERR_ARG ? 0u : 1u;
        bad += vor_within(&diagram, (vor_point_t){9, 9}, 5, hint, list, 4, &found) == VOR_ERR_ARG ? 0u : 1u;
        bad += (out == 77 && found == 77 && list[0] == 77 && unchanged()) ? 0u : 1u;
    }
    CHECK(bad == 0, "one-vertex diagram: %u non-site hints accepted or wrote", bad);
    CHECK(vor_nearest(&diagram, (vor_point_t){9, 9}, 0, &out) == VOR_OK && out == 0u &&
              vor_nearest_k(&diagram, (vor_point_t){9, 9}, 0, 2, list, &found) == VOR_OK && found == 1u &&
              list[0] == 0u,
          "one-vertex diagram: its site as the hint");
    list[0] = 77;
    CHECK(vor_locate(&diagram, (vor_point_t){-40, 1234}, 0, list) == VOR_ERR_OUTSIDE && list[0] == 77 &&
              vor_within(&diagram, (vor_point_t){-40, 1234}, 0, 0, list, 4, &found) == VOR_OK && found == 1u &&
              list[0] == 0u && list[1] == 77 && unchanged(),
          "one-vertex diagram: no triangle; its site within 0");
    CHECK(vor_insert_near(&diagram, (vor_point_t){-40, 1234}, VOR_NO_HINT, &out) == VOR_ERR_DUPLICATE &&
              out == 0u && unchanged(),
          "one-vertex diagram: a copy again");
    CHECK(vor_insert_near(&diagram, (vor_point_t){9, 9}, 0, &out) == VOR_OK && out == COPIES &&
              vor_validate(&diagram, NULL) == VOR_OK,
          "one-vertex diagram: insert from its site");
}

static void check_insert_and_build(test_rng_t *rng)
{
    uint32_t out = 77;
    /* full: every point again is a duplicate with its own id, a new one FULL */
    for (uint32_t max_sites = 1; max_sites <= SAFE_SITES; max_sites += (max_sites < 4u) ? 1u : 9u) {
        CHECK(build_all(max_sites), "build %u", max_sites);
        snapshot();
        unsigned bad = 0;
        for (uint32_t i = 0; i < max_sites; i++) {
            out = 77;
            bad += (vor_insert(&diagram, points[i], &out) == VOR_ERR_DUPLICATE &&
                    out == i && unchanged())
                       ? 0u
                       : 1u;
            out = 77;
            bad += (vor_insert_near(&diagram, points[i], VOR_NO_HINT, &out) ==
                        VOR_ERR_DUPLICATE &&
                    out == i && unchanged())
                       ? 0u
                       : 1u;
        }
        out = 77;
        bad += (vor_insert(&diagram, (vor_point_t){-1, -1}, &out) == VOR_ERR_FULL && out == 77 && unchanged())
                   ? 0u
                   : 1u;
        CHECK(bad == 0, "full diagram of %u: %u wrong answers", max_sites, bad);
    }

    CHECK(vor_init(&diagram, arena, sizeof arena, SAFE_SITES) == VOR_OK, "init");
    /* a copy of site 3, so that id SAFE_SITES - 4 is a duplicate's */
    vor_point_t more[SAFE_SITES - 3u];
    uint32_t duplicate_of[SAFE_SITES - 3u];
    test_copy_bytes(more, points, sizeof more);
    more[SAFE_SITES - 4u] = points[3];
    CHECK(vor_build(&diagram, more, SAFE_SITES - 3u, NULL, duplicate_of) == VOR_OK &&
              duplicate_of[SAFE_SITES - 4u] == 3u,
          "build with a copy");
    snapshot();
    uint32_t bad_hints[] = {SAFE_SITES - 4u, SAFE_SITES - 3u, SAFE_SITES, 0xFFFFFFFEu};
    unsigned bad = 0;
    for (unsigned h = 0; h < sizeof bad_hints / sizeof bad_hints[0]; h++) {
        out = 77;
        bad += (vor_insert_near(&diagram, (vor_point_t){1, 2}, bad_hints[h], &out) == VOR_ERR_ARG && out == 77 &&
                unchanged())
                   ? 0u
                   : 1u;
    }
    CHECK(bad == 0, "insert_near: %u bad hints accepted", bad);
    CHECK(vor_insert(NULL, (vor_point_t){1, 2}, &out) == VOR_ERR_ARG &&
              vor_insert_near(NULL, (vor_point_t){1, 2}, 0, &out) == VOR_ERR_ARG && out == 77,
          "insert: NULL diagram");

    vor_build_options_t bad_order = {(enum vor_order)9, VOR_DC_QUADTREE, 0};
    uint32_t dup_out[SAFE_SITES + 1u];
    fill(dup_out, sizeof dup_out, 0xEE);
    uint32_t dup_before[SAFE_SITES + 1u];
    test_copy_bytes(dup_before, dup_out, sizeof dup_out);
    CHECK(vor_build(NULL, points, 3, NULL, dup_out) == VOR_ERR_ARG, "build: NULL diagram");
    CHECK(vor_build(&diagram, NULL, 3, NULL, dup_out) == VOR_ERR_ARG && unchanged(),
          "build: NULL points");
    CHECK(vor_build(&diagram, points, 3, &bad_order, dup_out) == VOR_ERR_ARG && unchanged(),
          "build: unknown order");
    CHECK(vor_build(&diagram, points, SAFE_SITES + 1u, NULL, dup_out) == VOR_ERR_FULL &&
              unchanged(),
          "build: more points than room");
    CHECK(vor_build_dc(NULL, points, 3, NULL, dup_out) == VOR_ERR_ARG,
          "build_dc: NULL diagram");
    CHECK(vor_build_dc(&diagram, NULL, 3, TEST_SPLIT(VOR_DC_XSPLIT), dup_out) == VOR_ERR_ARG && unchanged(),
          "build_dc: NULL points");
    CHECK(vor_build_dc(&diagram, points, 3, TEST_SPLIT(9), dup_out) == VOR_ERR_ARG &&
              unchanged(),
          "build_dc: unknown split");
    CHECK(vor_build_dc(&diagram, points, SAFE_SITES + 1u, NULL, dup_out) ==
                  VOR_ERR_FULL &&
              unchanged(),
          "build_dc: more points than room");
    unsigned calls = 0;
    vor_fork_join_t good = {safety_fork, safety_join, &calls};
    vor_fork_join_t no_fork = {NULL, safety_join, &calls};
    vor_fork_join_t no_join = {safety_fork, NULL, &calls};
    CHECK(vor_build_dc_forked(NULL, points, 3, NULL, dup_out, &good) == VOR_ERR_ARG,
          "build_dc_forked: NULL diagram");
    CHECK(vor_build_dc_forked(&diagram, NULL, 3, TEST_SPLIT(VOR_DC_XSPLIT), dup_out, &good) == VOR_ERR_ARG &&
              unchanged(),
          "build_dc_forked: NULL points");
    CHECK(vor_build_dc_forked(&diagram, points, 3, TEST_SPLIT(9), dup_out, &good) ==
                  VOR_ERR_ARG &&
              unchanged(),
          "build_dc_forked: unknown split");
    CHECK(vor_build_dc_forked(&diagram, points, 3, NULL, dup_out, &no_fork) ==
                  VOR_ERR_ARG &&
              unchanged(),
          "build_dc_forked: hook without fork");
    CHECK(vor_build_dc_forked(&diagram, points, 3, TEST_SPLIT(VOR_DC_XSPLIT), dup_out, &no_join) ==
                  VOR_ERR_ARG &&
              unchanged(),
          "build_dc_forked: hook without join");
    CHECK(vor_build_dc_forked(&diagram, points, SAFE_SITES + 1u, NULL, dup_out,
                              &good) == VOR_ERR_FULL &&
              unchanged(),
          "build_dc_forked: more points than room");
    CHECK(calls == 0u, "failed forked builds called the hook %u times", calls);
    CHECK(test_same_bytes(dup_out, dup_before, sizeof dup_out), "failed builds wrote duplicate_of");

    /* VOR_NO_HINT inserts land where vor_insert puts them */
    CHECK(vor_init(&diagram, arena, sizeof arena, SAFE_SITES) == VOR_OK, "init");
    bad = 0;
    for (uint32_t i = 0; i < SAFE_SITES; i++) {
        uint32_t hint = (test_rng_u32(rng) & 1u) ? VOR_NO_HINT : (i > 0u ? i - 1u : VOR_NO_HINT);
        bad += (vor_insert_near(&diagram, points[i], hint, &out) == VOR_OK &&
                out == i)
                   ? 0u
                   : 1u;
    }
    CHECK(bad == 0 && vor_validate(&diagram, NULL) == VOR_OK, "inserts with VOR_NO_HINT");
}

static void check_reads(void)
{
    CHECK(build_all(SAFE_SITES), "build");
    snapshot();
    vor_violation_t violation;
    fill(&violation, sizeof violation, 0x33);
    vor_violation_t violation_before = violation;
    CHECK(vor_validate(NULL, &violation) == VOR_ERR_ARG &&
              test_same_bytes(&violation, &violation_before, sizeof violation),
          "validate: NULL diagram");
    vor_memory_t memory;
    fill(&memory, sizeof memory, 0x33);
    vor_memory_t memory_before = memory;
    CHECK(vor_memory(NULL, &memory) == VOR_ERR_ARG &&
              vor_memory(&diagram, NULL) == VOR_ERR_ARG &&
              test_same_bytes(&memory, &memory_before, sizeof memory) && unchanged(),
          "memory: NULL");
    vor_stats_t counters;
    fill(&counters, sizeof counters, 0x34);
    vor_stats_t counters_before = counters;
    CHECK(vor_stats(NULL, &counters) == VOR_ERR_ARG && vor_stats(&diagram, NULL) == VOR_ERR_ARG &&
              test_same_bytes(&counters, &counters_before, sizeof counters) && unchanged(),
          "stats: NULL");
    CHECK(vor_stats(&diagram, &counters) == VOR_OK && test_predicate_calls(&diagram) > 0u &&
              unchanged(),
          "stats: the test build counts");

    /* the perturbed predicates: 0, never an answer, for a NULL array or a
     * repeated index (points by value leave the others nothing to refuse) */
    vor_point_t a = {0, 0}, b = {1, 0}, c = {0, 1};
    CHECK(vor_orient2d_sos(NULL, 0, 1, 2) == 0 &&
              vor_orient2d_sos(points, 0, 1, 1) == 0 &&
              vor_orient2d_sos(points, 2, 1, 2) == 0,
          "orient2d_sos: NULL sites, repeated index");
    CHECK(vor_incircle_sos(NULL, 0, 1, 2, 3) == 0 &&
              vor_incircle_sos(points, 0, 1, 2, 0) == 0 &&
              vor_incircle_sos(points, 0, 3, 2, 3) == 0,
          "incircle_sos: NULL sites, repeated index");
    CHECK(vor_closer_sos(NULL, 0, 1, 2) == 0 && vor_closer_sos(points, 1, 1, 2) == 0 &&
              vor_closer_sos(points, 0, 2, 2) == 0,
          "closer_sos: NULL sites, repeated index");
    static const int64_t weights[SAFE_SITES] = {0};
    CHECK(vor_power_test_sos(NULL, weights, 0, 1, 2, 3) == 0 &&
              vor_power_test_sos(points, NULL, 0, 1, 2, 3) == 0 &&
              vor_power_test_sos(points, weights, 0, 1, 2, 0) == 0 &&
              vor_power_test_sos(points, weights, 0, 3, 2, 3) == 0,
          "power_test_sos: NULL sites or weights, repeated index");

    vor_vertex_t vertex;
    fill(&vertex, sizeof vertex, 0x44);
    vor_vertex_t vertex_before = vertex;
    CHECK(vor_circumcentre(a, b, c, NULL) == VOR_ERR_ARG &&
              vor_voronoi_vertex(NULL, 0, 1, 2, &vertex) == VOR_ERR_ARG &&
              vor_voronoi_vertex(&diagram, 0, 1, 2, NULL) == VOR_ERR_ARG &&
              vor_voronoi_vertex(&diagram, 0, 1, SAFE_SITES, &vertex) == VOR_ERR_ARG &&
              vor_voronoi_vertex(&diagram, VOR_NO_HINT, 1, 2, &vertex) == VOR_ERR_ARG &&
              test_same_bytes(&vertex, &vertex_before, sizeof vertex) && unchanged(),
          "vertices: NULL, ids out of range");

    uint32_t out = 77, found = 77, list[3] = {77, 77, 77};
    CHECK(vor_nearest(NULL, (vor_point_t){0, 0}, VOR_NO_HINT, &out) == VOR_ERR_ARG &&
              vor_nearest(&diagram, (vor_point_t){0, 0}, VOR_NO_HINT, NULL) == VOR_ERR_ARG &&
              vor_nearest(&diagram, (vor_point_t){0, 0}, SAFE_SITES, &out) == VOR_ERR_ARG &&
              vor_nearest_k(NULL, (vor_point_t){0, 0}, VOR_NO_HINT, 3, list, &found) == VOR_ERR_ARG &&
              vor_nearest_k(&diagram, (vor_point_t){0, 0}, VOR_NO_HINT, 3, NULL, &found) == VOR_ERR_ARG &&
              vor_nearest_k(&diagram, (vor_point_t){0, 0}, VOR_NO_HINT, 3, list, NULL) == VOR_ERR_ARG &&
              vor_nearest_k(&diagram, (vor_point_t){0, 0}, SAFE_SITES + 7u, 3, list, &found) == VOR_ERR_ARG &&
              out == 77 && found == 77 && list[0] == 77 && list[2] == 77 && unchanged(),
          "nearest: NULL, bad hints");
    const uint32_t bad_hints[3] = {SAFE_SITES, SAFE_SITES + 7u, VOR_NO_HINT - 1u};
    unsigned refused = 0;
    for (unsigned k = 0; k < 3u; k++) {
        refused += vor_locate(&diagram, (vor_point_t){500, 500}, bad_hints[k], list) == VOR_ERR_ARG;
        refused += vor_within(&diagram, (vor_point_t){500, 500}, 1000000, bad_hints[k], list, 3, &found) ==
                   VOR_ERR_ARG;
    }
    CHECK(refused == 6u && vor_locate(NULL, (vor_point_t){0, 0}, VOR_NO_HINT, list) == VOR_ERR_ARG &&
              vor_locate(&diagram, (vor_point_t){0, 0}, VOR_NO_HINT, NULL) == VOR_ERR_ARG &&
              vor_locate(&diagram, (vor_point_t){-9, -9}, VOR_NO_HINT, list) == VOR_ERR_OUTSIDE &&
              vor_within(NULL, (vor_point_t){0, 0}, 9, VOR_NO_HINT, list, 3, &found) == VOR_ERR_ARG &&
              vor_within(&diagram, (vor_point_t){0, 0}, 9, VOR_NO_HINT, NULL, 3, &found) == VOR_ERR_ARG &&
              vor_within(&diagram, (vor_point_t){0, 0}, 9, VOR_NO_HINT, list, 3, NULL) == VOR_ERR_ARG &&
              found == 77 && list[0] == 77 && list[2] == 77 && unchanged(),
          "locate, within: NULL, bad hints, outside");
    /* too small a buffer: the count needed, nothing else written */
    CHECK(vor_within(&diagram, (vor_point_t){4000, 2000}, UINT64_MAX, VOR_NO_HINT, list, 3, &found) ==
                  VOR_ERR_BUFFER &&
              found == SAFE_SITES && list[0] == 77 && list[2] == 77 && unchanged(),
          "within: buffer too small");
    uint32_t triangles = 77;
    found = 77;
    CHECK(vor_triangles_count(NULL, &triangles) == VOR_ERR_ARG && vor_triangles_count(&diagram, NULL) == VOR_ERR_ARG &&
              vor_triangles_export(NULL, list, list, 1, &found) == VOR_ERR_ARG &&
              vor_triangles_export(&diagram, NULL, list, 1, &found) == VOR_ERR_ARG &&
              vor_triangles_export(&diagram, list, list, 1, NULL) == VOR_ERR_ARG && triangles == 77 &&
              found == 77 && list[0] == 77 && unchanged(),
          "count, export: NULL");
    CHECK(vor_triangles_count(&diagram, &triangles) == VOR_OK && triangles > 1u &&
              vor_triangles_export(&diagram, list, list + 1, 1, &found) == VOR_ERR_BUFFER &&
              found == triangles && list[0] == 77 && list[2] == 77 && unchanged(),
          "export: buffer too small");

    static vor_tracker_t zeroed;
    vor_tracker_t tracker;
    fill(&tracker, sizeof tracker, 0x66);
    vor_tracker_t tracker_before;
    test_copy_bytes(&tracker_before, &tracker, sizeof tracker);
    CHECK(vor_tracker_begin(NULL, &diagram) == VOR_ERR_ARG &&
              vor_tracker_begin(&tracker, NULL) == VOR_ERR_ARG &&
              test_same_bytes(&tracker, &tracker_before, sizeof tracker) &&
              vor_track(&zeroed, (vor_point_t){0, 0}, &out) == VOR_ERR_ARG &&
              vor_track(NULL, (vor_point_t){0, 0}, &out) == VOR_ERR_ARG && out == 77,
          "tracker: NULL, never begun");
    CHECK(vor_tracker_begin(&tracker, &diagram) == VOR_OK &&
              vor_track(&tracker, (vor_point_t){0, 0}, NULL) == VOR_ERR_ARG && unchanged(),
          "track: NULL result");
}

/* Every iterator: begin with a NULL iterator, begin on a NULL diagram,
 * never begun (zeroed), NULL outputs, and after its end. */
static void check_iterators(void)
{
    CHECK(build_all(SAFE_SITES), "build");
    snapshot();
    uint32_t ids[3] = {77, 77, 77}, site = 77, count = 77;
    unsigned bad = 0;

    /* begin: VOR_ERR_ARG for a NULL iterator or diagram, a site not in
     * the mesh, a NULL or inverted box, the iterator then closed; next: 1
     * or 0, never an error, and 0 for NULL outputs, writing nothing */
    static vor_triangle_iter_t zero_triangles;
    vor_triangle_iter_t triangles;
    bad += vor_triangles_begin(NULL, &diagram) != VOR_ERR_ARG;
    bad += vor_triangles_next(&zero_triangles, ids) + vor_triangles_next(NULL, ids) != 0;
    bad += vor_triangles_begin(&triangles, NULL) != VOR_ERR_ARG;
    bad += vor_triangles_next(&triangles, ids) != 0;
    bad += vor_triangles_begin(&triangles, &diagram) != VOR_OK;
    bad += vor_triangles_next(&triangles, NULL) != 0;
    bad += (ids[0] != 77 || ids[2] != 77);
    while (vor_triangles_next(&triangles, ids)) {
    }
    bad += vor_triangles_next(&triangles, ids) != 0;
    CHECK(bad == 0 && unchanged(), "triangle iterator: %u wrong", bad);

    bad = 0;
    static vor_neighbour_iter_t zero_neighbours;
    vor_neighbour_iter_t neighbours;
    bad += vor_neighbours_begin(NULL, &diagram, 0) != VOR_ERR_ARG;
    bad += vor_neighbours_next(&zero_neighbours, &site) + vor_neighbours_next(NULL, &site) != 0;
    bad += vor_neighbours_begin(&neighbours, NULL, 0) != VOR_ERR_ARG;
    bad += vor_neighbours_next(&neighbours, &site) != 0;
    bad += vor_neighbours_begin(&neighbours, &diagram, SAFE_SITES) != VOR_ERR_ARG;
    bad += vor_neighbours_next(&neighbours, &site) != 0;
    bad += vor_neighbours_begin(&neighbours, &diagram, VOR_NO_HINT) != VOR_ERR_ARG;
    bad += vor_neighbours_next(&neighbours, &site) != 0;
    bad += vor_neighbours_begin(&neighbours, &diagram, 0) != VOR_OK;
    bad += vor_neighbours_next(&neighbours, NULL) != 0;
    bad += site != 77;
    while (vor_neighbours_next(&neighbours, &site)) {
    }
    bad += vor_neighbours_next(&neighbours, &site) != 0;
    CHECK(bad == 0 && unchanged(), "neighbour iterator: %u wrong", bad);

    bad = 0;
    static vor_edge_iter_t zero_edges;
    vor_edge_iter_t edges;
    vor_edge_t edge;
    fill(&edge, sizeof edge, 0x77);
    vor_edge_t edge_before = edge;
    bad += vor_edges_begin(NULL, &diagram) != VOR_ERR_ARG;
    bad += vor_edges_next(&zero_edges, &edge) + vor_edges_next(NULL, &edge) != 0;
    bad += vor_edges_begin(&edges, NULL) != VOR_ERR_ARG;
    bad += vor_edges_next(&edges, &edge) != 0;
    bad += vor_edges_begin(&edges, &diagram) != VOR_OK;
    bad += vor_edges_next(&edges, NULL) != 0;
    bad += !test_same_bytes(&edge, &edge_before, sizeof edge);
    while (vor_edges_next(&edges, &edge)) {
    }
    bad += vor_edges_next(&edges, &edge) != 0;
    CHECK(bad == 0 && unchanged(), "edge iterator: %u wrong", bad);

    bad = 0;
    site = 77;
    static vor_hull_iter_t zero_hull;
    vor_hull_iter_t hull;
    bad += vor_hull_begin(NULL, &diagram) != VOR_ERR_ARG;
    bad += vor_hull_next(&zero_hull, &site) + vor_hull_next(NULL, &site) != 0;
    bad += vor_hull_begin(&hull, NULL) != VOR_ERR_ARG;
    bad += vor_hull_next(&hull, &site) != 0;
    bad += vor_hull_begin(&hull, &diagram) != VOR_OK;
    bad += vor_hull_next(&hull, NULL) != 0;
    bad += site != 77;
    while (vor_hull_next(&hull, &site)) {
    }
    bad += vor_hull_next(&hull, &site) != 0;
    CHECK(bad == 0 && unchanged(), "hull iterator: %u wrong", bad);

    /* cells: a missing or inverted box is VOR_ERR_ARG at begin, and the
     * iterator is closed; bad outputs stop next with VOR_ERR_ARG kept */
    bad = 0;
    site = count = 77;
    vor_point_t poly[VOR_CELL_MAX_VERTICES(SAFE_SITES)];
    fill(poly, sizeof poly, 0x88);
    vor_point_t poly_before[VOR_CELL_MAX_VERTICES(SAFE_SITES)];
    test_copy_bytes(poly_before, poly, sizeof poly);
    uint32_t capacity = VOR_CELL_MAX_VERTICES(SAFE_SITES);
    static vor_cell_iter_t zero_cells;
    vor_cell_iter_t cells;
    vor_box_t box = {-10, -10, 9000, 5000};
    vor_box_t inverted_x = {10, 0, 9, 100}, inverted_y = {0, 10, 100, 9}, flat = {0, 7, 9000, 7};
    bad += vor_cells_begin(NULL, &diagram, &box) != VOR_ERR_ARG;
    bad += vor_cells_error(NULL) != VOR_ERR_ARG;
    bad += vor_cells_next(&zero_cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_error(&zero_cells) != VOR_OK;
    bad += vor_cells_next(NULL, &site, poly, capacity, &count) != 0;
    bad += vor_cells_begin(&cells, NULL, &box) != VOR_ERR_ARG;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += vor_cells_begin(&cells, &diagram, NULL) != VOR_ERR_ARG;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += vor_cells_begin(&cells, &diagram, &inverted_x) != VOR_ERR_ARG;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += vor_cells_begin(&cells, &diagram, &inverted_y) != VOR_ERR_ARG;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += vor_cells_begin(&cells, &diagram, &box) != VOR_OK;
    bad += vor_cells_error(&cells) != VOR_OK;
    bad += vor_cells_next(&cells, NULL, poly, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += vor_cells_next(&cells, &site, poly, capacity, NULL) != 0;
    bad += vor_cells_next(&cells, &site, NULL, capacity, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_ARG;
    bad += (site != 77 || count != 77 || !test_same_bytes(poly, poly_before, sizeof poly));
    CHECK(bad == 0 && unchanged(), "cell iterator, bad arguments: %u wrong", bad);

    /* a buffer too small for every cell: `while (next)` ends at once, with
     * VOR_ERR_BUFFER kept and the vertices needed in count, and resumes
     * at that cell with a large enough buffer (it spun forever when next
     * returned errors in its one channel) */
    bad = 0;
    unsigned rounds = 0;
    bad += vor_cells_begin(&cells, &diagram, &box) != VOR_OK;
    while (vor_cells_next(&cells, &site, poly, 2, &count) && rounds < 1000u) {
        rounds++;
    }
    bad += rounds != 0u;
    bad += vor_cells_error(&cells) != VOR_ERR_BUFFER || site != 0u || count <= 2u;
    uint32_t needed = count;
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 1 || site != 0u ||
           count != needed || vor_cells_error(&cells) != VOR_OK;
    while (vor_cells_next(&cells, &site, poly, capacity, &count) && rounds < 1000u) {
        rounds++;
    }
    bad += rounds != SAFE_SITES - 1u || vor_cells_error(&cells) != VOR_OK;
    CHECK(bad == 0 && unchanged(), "cell iterator, small buffer: %u wrong", bad);
    test_copy_bytes(poly, poly_before, sizeof poly);

    /* an empty (flat) box: every site's cell, each with no vertices */
    uint32_t listed = 0;
    bad = 0;
    vor_cells_begin(&cells, &diagram, &flat);
    while (vor_cells_next(&cells, &site, poly, capacity, &count) == 1) {
        bad += (site != listed++ || count != 0u);
    }
    bad += vor_cells_next(&cells, &site, poly, capacity, &count) != 0;
    CHECK(bad == 0 && listed == SAFE_SITES && unchanged(), "cells of a flat box: %u wrong", bad);

    bad = 0;
    count = 77;
    bad += vor_cell(NULL, 0, &box, poly, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, 0, NULL, poly, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, 0, &box, poly, capacity, NULL) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, 0, &box, NULL, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, 0, &inverted_x, poly, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, 0, &inverted_y, poly, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, SAFE_SITES, &box, poly, capacity, &count) != VOR_ERR_ARG;
    bad += vor_cell(&diagram, VOR_NO_HINT, &box, poly, capacity, &count) != VOR_ERR_ARG;
    bad += (count != 77 || !test_same_bytes(poly, poly_before, sizeof poly));
    CHECK(bad == 0 && unchanged(), "cell: %u bad arguments accepted or wrote", bad);

    /* cells clipped to a room: bad arguments and bad rooms leave the
     * scratch and outputs alone and close the iterator; next and the
     * centroid on a closed or zeroed iterator do nothing */
    {
        static const vor_point_t room[4] = {{-10, -10}, {9000, -10}, {9000, 5000}, {-10, 5000}};
        static const vor_point_t bowtie[4] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
        static uint8_t clip_scratch[VOR_CLIP_SCRATCH_BYTES(4, SAFE_SITES)];
        static uint8_t clip_before[sizeof clip_scratch];
        static vor_exact_point_t exact[VOR_CLIP_MAX_VERTICES(4, SAFE_SITES)];
        static vor_exact_point_t exact_before[VOR_CLIP_MAX_VERTICES(4, SAFE_SITES)];
        static vor_clip_t zero_clip;
        uint32_t clip_capacity = VOR_CLIP_MAX_VERTICES(4, SAFE_SITES);
        vor_clip_t clip;
        vor_centroid_t c, c_before;
        fill(clip_scratch, sizeof clip_scratch, 0x3C);
        test_copy_bytes(clip_before, clip_scratch, sizeof clip_scratch);
        fill(exact, sizeof exact, 0x77);
        test_copy_bytes(exact_before, exact, sizeof exact);
        fill(&c, sizeof c, 0x55);
        test_copy_bytes(&c_before, &c, sizeof c);
        bad = 0;
        count = 77;
        size_t n = sizeof clip_scratch;
        bad += vor_clip_begin(NULL, &diagram, 0, room, 4, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, NULL, 0, room, 4, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_next(&clip, exact, clip_capacity, &count) != 0;
        bad += vor_clip_error(&clip) != VOR_ERR_ARG;
        bad += vor_clip_centroid(&clip, VOR_CLIP_WHOLE, NULL, 0, &c) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, 0, NULL, 4, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, 0, room, 2, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, 0, room, 0xFFFFFFFFu, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, 0, room, 4, NULL, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, SAFE_SITES, room, 4, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, VOR_NO_HINT, room, 4, clip_scratch, n) != VOR_ERR_ARG;
        bad += vor_clip_begin(&clip, &diagram, 0, bowtie, 4, clip_scratch, n) != VOR_ERR_POLYGON;
        bad += vor_clip_error(&clip) != VOR_ERR_POLYGON;
        bad += vor_clip_next(&clip, exact, clip_capacity, &count) != 0;
        bad += vor_clip_begin(&clip, &diagram, 0, room, 4, clip_scratch, 16) != VOR_ERR_BUFFER;
        bad += vor_clip_next(&zero_clip, exact, clip_capacity, &count) != 0;
        bad += vor_clip_error(&zero_clip) != VOR_OK;
        bad += vor_clip_next(NULL, exact, clip_capacity, &count) != 0;
        bad += vor_clip_error(NULL) != VOR_ERR_ARG;
        bad += vor_clip_centroid(&zero_clip, VOR_CLIP_WHOLE, NULL, 0, &c) != VOR_ERR_ARG;
        bad += vor_clip_centroid(NULL, VOR_CLIP_WHOLE, NULL, 0, &c) != VOR_ERR_ARG;
        bad += (count != 77 || !test_same_bytes(exact, exact_before, sizeof exact) ||
                !test_same_bytes(clip_scratch, clip_before, sizeof clip_scratch) ||
                !test_same_bytes(&c, &c_before, sizeof c));
        CHECK(bad == 0 && unchanged(), "clip: %u bad arguments accepted or wrote", bad);

        /* a good room: bad outputs keep VOR_ERR_ARG, a short buffer
         * VOR_ERR_BUFFER with the count, and next resumes */
        bad = 0;
        bad += vor_clip_begin(&clip, &diagram, 0, room, 4, clip_scratch, n) != VOR_OK;
        bad += clip.pieces != 1u;
        bad += vor_clip_next(&clip, exact, clip_capacity, NULL) != 0;
        bad += vor_clip_error(&clip) != VOR_ERR_ARG;
        bad += vor_clip_next(&clip, NULL, clip_capacity, &count) != 0;
        bad += vor_clip_error(&clip) != VOR_ERR_ARG;
        bad += vor_clip_next(&clip, exact, 2, &count) != 0;
        bad += vor_clip_error(&clip) != VOR_ERR_BUFFER || count < 3u;
        bad += !test_same_bytes(exact, exact_before, sizeof exact);
        bad += vor_clip_centroid(&clip, 1, NULL, 0, &c) != VOR_ERR_ARG;
        bad += vor_clip_centroid(&clip, 0, NULL, 0, NULL) != VOR_ERR_ARG;
        bad += vor_clip_centroid(&clip, 0, NULL, 8, &c) != VOR_ERR_ARG;
        bad += !test_same_bytes(&c, &c_before, sizeof c);
        bad += vor_clip_next(&clip, exact, count, &count) != 1;
        bad += vor_clip_next(&clip, exact, clip_capacity, &count) != 0;
        bad += vor_clip_error(&clip) != VOR_OK;
        CHECK(bad == 0 && unchanged(), "clip: a good room: %u wrong", bad);

        /* order-K cells and the walk: bad arguments write neither the
         * scratch, the store nor the outputs */
        static uint8_t order_scratch[VOR_ORDER_SCRATCH_BYTES(4, SAFE_SITES, 2)];
        static uint8_t order_before[sizeof order_scratch];
        static uint32_t sets[VOR_ORDER_SETS_WORDS(VOR_ORDER_MAX_CELLS(SAFE_SITES, 2), 2)];
        static uint32_t sets_before[sizeof sets / sizeof sets[0]];
        static vor_order_iter_t zero_it;
        const uint32_t pair[2] = {0, 1}, twice[2] = {1, 1}, far[2] = {0, SAFE_SITES},
                       none[2] = {0, VOR_NO_HINT};
        uint32_t out_set[2] = {55, 56};
        uint32_t max_sets = (uint32_t)VOR_ORDER_MAX_CELLS(SAFE_SITES, 2);
        vor_order_iter_t it;
        vor_clip_t clip_before_copy;
        fill(order_scratch, sizeof order_scratch, 0x4B);
        test_copy_bytes(order_before, order_scratch, sizeof order_scratch);
        fill(sets, sizeof sets, 0x2D);
        test_copy_bytes(sets_before, sets, sizeof sets);
        size_t o = sizeof order_scratch;
        bad = 0;
        bad += vor_order_cell_begin(NULL, &diagram, pair, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, NULL, pair, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, NULL, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 0, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 0xFFFFFFFFu, room, 4, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, twice, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, far, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, none, 2, room, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 2, NULL, 4, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 2, room, 2, order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 2, room, 4, NULL, o) != VOR_ERR_ARG;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 2, bowtie, 4, order_scratch, o) !=
               VOR_ERR_POLYGON;
        bad += vor_order_cell_begin(&clip, &diagram, pair, 2, room, 4, order_scratch, 16) !=
               VOR_ERR_BUFFER;
        bad += clip.needed <= 16u;
        bad += vor_clip_next(&clip, exact, clip_capacity, &count) != 0;
        bad += vor_order_cells_begin(NULL, &diagram, 2, room, 4, sets, max_sets, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, NULL, 2, room, 4, sets, max_sets, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 0, room, 4, sets, max_sets, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, SAFE_SITES, room, 4, sets, max_sets,
                                     order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 2, NULL, 4, sets, max_sets, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 2, room, 0xFFFFFFFFu, sets, max_sets,
                                     order_scratch, o) != VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 2, room, 4, NULL, max_sets, order_scratch, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 2, room, 4, sets, max_sets, NULL, o) !=
               VOR_ERR_ARG;
        bad += vor_order_cells_begin(&it, &diagram, 2, bowtie, 4, sets, max_sets, order_scratch, o) !=
               VOR_ERR_POLYGON;
        bad += vor_order_cells_begin(&it, &diagram, 2, room, 4, sets, 0, order_scratch, o) !=
               VOR_ERR_BUFFER;
        test_copy_bytes(&clip_before_copy, &clip, sizeof clip);
        bad += vor_order_cells_next(&it, out_set, &clip) != 0;
        bad += vor_order_cells_error(&it) != VOR_ERR_BUFFER;
        bad += vor_order_cells_next(&zero_it, out_set, &clip) != 0;
        bad += vor_order_cells_error(&zero_it) != VOR_OK;
        bad += vor_order_cells_next(NULL, out_set, &clip) != 0;
        bad += vor_order_cells_error(NULL) != VOR_ERR_ARG;
        bad += (out_set[0] != 55u || !test_same_bytes(&clip, &clip_before_copy, sizeof clip));
        bad += (!test_same_bytes(order_scratch, order_before, sizeof order_scratch) ||
                !test_same_bytes(sets, sets_before, sizeof sets));
        /* a good walk: bad outputs keep VOR_ERR_ARG and write nothing */
        bad += vor_order_cells_begin(&it, &diagram, 2, room, 4, sets, max_sets, order_scratch, o) !=
               VOR_OK;
        bad += vor_order_cells_next(&it, NULL, &clip) != 0;
        bad += vor_order_cells_error(&it) != VOR_ERR_ARG;
        bad += vor_order_cells_next(&it, out_set, NULL) != 0;
        bad += vor_order_cells_error(&it) != VOR_ERR_ARG;
        bad += (out_set[0] != 55u || !test_same_bytes(&clip, &clip_before_copy, sizeof clip));
        bad += vor_order_cells_next(&it, out_set, &clip) != 1 || clip.pieces < 1u;
        CHECK(bad == 0 && unchanged(), "order cells: %u bad arguments accepted or wrote", bad);
    }

    /* the centroid: bad arguments write neither the output nor the
     * scratch; too small a scratch writes only the vertex count */
    static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(SAFE_SITES))];
    static uint8_t scratch_before[sizeof scratch];
    fill(scratch, sizeof scratch, 0x99);
    test_copy_bytes(scratch_before, scratch, sizeof scratch);
    vor_centroid_t centroid, centroid_before;
    fill(&centroid, sizeof centroid, 0x77);
    test_copy_bytes(&centroid_before, &centroid, sizeof centroid);
    size_t bytes = sizeof scratch;
    bad = 0;
    bad += vor_cell_centroid(NULL, 0, &box, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, 0, NULL, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, 0, &box, scratch, bytes, NULL) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, 0, &box, NULL, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, 0, &inverted_x, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, 0, &inverted_y, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, SAFE_SITES, &box, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += vor_cell_centroid(&diagram, VOR_NO_HINT, &box, scratch, bytes, &centroid) != VOR_ERR_ARG;
    bad += !test_same_bytes(&centroid, &centroid_before, sizeof centroid);
    bad += vor_cell_centroid(&diagram, 0, &box, scratch, 8, &centroid) != VOR_ERR_BUFFER;
    bad += (centroid.vertices < 3u || centroid.area != centroid_before.area ||
            centroid.point.x != centroid_before.point.x ||
            centroid.point.y != centroid_before.point.y);
    bad += !test_same_bytes(scratch, scratch_before, sizeof scratch);
    CHECK(bad == 0 && unchanged(), "cell centroid: %u bad arguments accepted or wrote", bad);

    /* natural-neighbour coordinates: bad arguments, a point outside, too
     * small a scratch write neither the output (but the count) nor the
     * scratch */
    static uint8_t natural_scratch[VOR_SIBSON_SCRATCH_BYTES(SAFE_SITES)];
    static uint8_t natural_before[sizeof natural_scratch];
    static int32_t values[SAFE_SITES];
    fill(natural_scratch, sizeof natural_scratch, 0x99);
    test_copy_bytes(natural_before, natural_scratch, sizeof natural_scratch);
    vor_coordinates_t coordinates, coordinates_before;
    vor_interpolation_t value, value_before;
    fill(&coordinates, sizeof coordinates, 0x77);
    fill(&value, sizeof value, 0x77);
    test_copy_bytes(&coordinates_before, &coordinates, sizeof coordinates);
    test_copy_bytes(&value_before, &value, sizeof value);
    size_t nb = sizeof natural_scratch;
    vor_point_t far = {INT32_MAX, INT32_MIN};
    vor_point_t q = diagram.sites[0];
    bad = 0;
    for (int laplace = 0; laplace < 2; laplace++) {
        int (*coords)(const vor_t *, vor_point_t, uint32_t, void *, size_t, vor_coordinates_t *) =
            laplace ? vor_laplace : vor_sibson;
        int (*interp)(const vor_t *, const int32_t *, vor_point_t, uint32_t, void *, size_t,
                      vor_interpolation_t *) = laplace ? vor_interpolate_laplace : vor_interpolate;
        bad += coords(NULL, q, VOR_NO_HINT, natural_scratch, nb, &coordinates) != VOR_ERR_ARG;
        bad += coords(&diagram, q, VOR_NO_HINT, natural_scratch, nb, NULL) != VOR_ERR_ARG;
        bad += coords(&diagram, q, VOR_NO_HINT, NULL, nb, &coordinates) != VOR_ERR_ARG;
        bad += coords(&diagram, q, SAFE_SITES, natural_scratch, nb, &coordinates) != VOR_ERR_ARG;
        bad += coords(&diagram, far, VOR_NO_HINT, natural_scratch, nb, &coordinates) != VOR_ERR_OUTSIDE;
        bad += interp(NULL, values, q, VOR_NO_HINT, natural_scratch, nb, &value) != VOR_ERR_ARG;
        bad += interp(&diagram, NULL, q, VOR_NO_HINT, natural_scratch, nb, &value) != VOR_ERR_ARG;
        bad += interp(&diagram, values, q, VOR_NO_HINT, natural_scratch, nb, NULL) != VOR_ERR_ARG;
        bad += interp(&diagram, values, q, VOR_NO_HINT, NULL, nb, &value) != VOR_ERR_ARG;
        bad += interp(&diagram, values, q, VOR_NO_HINT - 1u, natural_scratch, nb, &value) != VOR_ERR_ARG;
        bad += interp(&diagram, values, far, VOR_NO_HINT, natural_scratch, nb, &value) != VOR_ERR_OUTSIDE;
    }
    bad += !test_same_bytes(&coordinates, &coordinates_before, sizeof coordinates);
    bad += !test_same_bytes(&value, &value_before, sizeof value);
    bad += vor_sibson(&diagram, q, VOR_NO_HINT, natural_scratch, 8, &coordinates) != VOR_ERR_NOMEM;
    bad += (coordinates.count != 1u || coordinates.limbs != coordinates_before.limbs ||
            coordinates.sites != coordinates_before.sites);
    bad += !test_same_bytes(natural_scratch, natural_before, sizeof natural_scratch);
    CHECK(bad == 0 && unchanged(), "natural neighbours: %u bad arguments accepted or wrote", bad);
}

static int never_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)first_row;
    (void)rows;
    (void)pixels;
    *(unsigned *)user += 1u;
    return 0;
}

/* vor_raster_nearest with K = 2, in the entry points' type. */
static int raster_nearest2(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                           const vor_raster_output_t *out, const vor_raster_options_t *options,
                           void *work, size_t work_bytes)
{
    return vor_raster_nearest(frame, sites, 2, out, options, work, work_bytes);
}

static void check_raster(void)
{
    static uint8_t work[VOR_RASTER_NEAREST_WORK_BYTES(SAFE_SITES, 8, 2)]
        __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
    uint8_t band[8 * 4], band_before[sizeof band];
    uint32_t areas[SAFE_SITES], areas_before[SAFE_SITES];
    fill(band, sizeof band, 0x99);
    fill(areas, sizeof areas, 0x99);
    test_copy_bytes(band_before, band, sizeof band);
    test_copy_bytes(areas_before, areas, sizeof areas);
    unsigned flushes = 0;
    vor_raster_frame_t frame = {0, 0, 100, 100, 8, 4};
    vor_raster_sites_t set = {VOR_METRIC_EUCLID, points, SAFE_SITES, NULL, NULL, NULL, 0, 0, 0, 0, NULL};
    vor_raster_output_t out = {VOR_RASTER_LABEL8, band, sizeof band, 4, never_flush, &flushes,
                               NULL, NULL, areas};
    vor_raster_frame_t empty = frame, inverted = frame;
    empty.width = 0;
    inverted.step_x = -100;
    vor_raster_output_t no_band = out, no_flush = out;
    no_band.band = NULL;
    no_flush.flush = NULL;
    vor_raster_sites_t no_points = set;
    no_points.points = NULL;
    vor_raster_sites_t l1 = set;
    l1.metric = VOR_METRIC_L1;
    vor_raster_sites_t weightless = set; /* power diagram without its weights */
    weightless.metric = VOR_METRIC_POWER;
    /* the three entry points; vor_raster_euclid also refuses another
     * metric, vor_raster_nearest a K of 0 or past its largest and the
     * k-set picture without a palette */
    int (*const entries[3])(const vor_raster_frame_t *, const vor_raster_sites_t *,
                            const vor_raster_output_t *, const vor_raster_options_t *, void *,
                            size_t) = {vor_raster, vor_raster_euclid, raster_nearest2};
    vor_raster_options_t bad_method = {(enum vor_raster_method)7, 0};
    vor_raster_output_t ksets = out;
    ksets.kind = VOR_RASTER_KSETS;
    for (unsigned e = 0; e < 3u; e++) {
        unsigned bad = 0;
        bad += entries[e](NULL, &set, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, NULL, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &set, NULL, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &set, &out, NULL, NULL, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &no_points, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &set, &no_band, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &set, &no_flush, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&empty, &set, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&inverted, &set, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &set, &out, &bad_method, work, sizeof work) != VOR_ERR_ARG;
        bad += entries[e](&frame, &weightless, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        if (e == 1u) {
            bad += vor_raster_euclid(&frame, &l1, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
        }
        if (e == 2u) {
            bad += vor_raster_nearest(&frame, &set, 0, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
            bad += vor_raster_nearest(&frame, &set, VOR_RASTER_MAX_NEAREST + 1u, &out, NULL, work,
                                      sizeof work) != VOR_ERR_ARG;
            bad += vor_raster_nearest(&frame, &set, 2, &ksets, NULL, work, sizeof work) != VOR_ERR_ARG;
        } else {
            bad += entries[e](&frame, &set, &ksets, NULL, work, sizeof work) != VOR_ERR_ARG;
        }
        bad += (flushes != 0u || !test_same_bytes(band, band_before, sizeof band) ||
                !test_same_bytes(areas, areas_before, sizeof areas));
        CHECK(bad == 0, "raster entry %u: %u bad arguments accepted or wrote", e, bad);
    }
    CHECK(vor_raster(&frame, &set, &out, NULL, work, sizeof work) == VOR_OK && flushes == 1u,
          "raster: the good call");
    CHECK(vor_raster_euclid(&frame, &set, &out, NULL, work, sizeof work) == VOR_OK && flushes == 2u,
          "raster_euclid: the good call");
    CHECK(vor_raster_nearest(&frame, &set, 2, &out, NULL, work, sizeof work) == VOR_OK &&
              flushes == 3u,
          "raster_nearest: the good call");
}

/* vor_field_raster: each bad argument refused before the first pixel,
 * with the diagram, the band, max_neighbours and the scratch as they
 * were and no flush; a never-initialised diagram is empty. */
static void check_field(void)
{
    CHECK(build_all(SAFE_SITES), "build");
    snapshot();
    static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(SAFE_SITES)];
    static uint8_t scratch_before[sizeof scratch];
    static int32_t values[SAFE_SITES];
    static vor_t zeroed;
    int32_t band[8 * 2], band_before[8 * 2];
    uint16_t ramp[256];
    fill(band, sizeof band, 0x99);
    fill(scratch, sizeof scratch, 0x98);
    fill(ramp, sizeof ramp, 0x11);
    test_copy_bytes(band_before, band, sizeof band);
    test_copy_bytes(scratch_before, scratch, sizeof scratch);
    unsigned flushes = 0;
    uint32_t most = 0x77u;
    vor_raster_frame_t frame = {0, 0, 1000, 1000, 8, 4};
    vor_field_output_t out = {VOR_FIELD_VALUE, band, sizeof band, 2, never_flush, &flushes, -1,
                              ramp, 0, 100, 0, &most};
    vor_raster_frame_t empty = frame, inverted = frame, past = frame;
    empty.height = 0;
    inverted.step_y = -1;
    past.origin_x = INT32_MAX - 6000; /* the last centre is INT32_MAX + 1000 */
    vor_field_output_t no_band = out, no_flush = out, no_rows = out, kind = out, no_ramp = out,
                       flat = out, small = out;
    no_band.band = NULL;
    no_flush.flush = NULL;
    no_rows.band_rows = 0;
    kind.kind = (enum vor_field_kind)9;
    no_ramp.kind = VOR_FIELD_RGB565;
    no_ramp.ramp565 = NULL;
    flat.kind = VOR_FIELD_RGB565;
    flat.high = flat.low - 1;
    small.band_bytes--;
    vor_field_options_t method = {(enum vor_field_method)9};
    size_t nb = sizeof scratch;
    unsigned bad = 0;
    bad += vor_field_raster(NULL, values, &frame, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, NULL, &frame, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, NULL, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, NULL, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &out, NULL, NULL, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &out, &method, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &empty, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &inverted, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &past, &out, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &no_band, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &no_flush, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &no_rows, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &kind, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &no_ramp, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &flat, NULL, scratch, nb) != VOR_ERR_ARG;
    bad += vor_field_raster(&diagram, values, &frame, &small, NULL, scratch, nb) != VOR_ERR_NOMEM;
    bad += vor_field_raster(&zeroed, values, &frame, &out, NULL, scratch, nb) != VOR_ERR_EMPTY;
    bad += (flushes != 0u || most != 0x77u || !test_same_bytes(band, band_before, sizeof band) ||
            !test_same_bytes(scratch, scratch_before, sizeof scratch));
    CHECK(bad == 0 && unchanged(), "field: %u bad arguments accepted or wrote", bad);
    CHECK(vor_field_raster(&diagram, values, &frame, &out, NULL, scratch, nb) == VOR_OK &&
              flushes == 2u && most >= 1u && unchanged(),
          "field: the good call (the diagram only read)");
}

/* A vor_t that vor_init never saw, zeroed as static storage is: no room,
 * no sites. Every call treats it as an empty, full diagram. */
static void check_zeroed_diagram(void)
{
    static vor_t zeroed;
    uint32_t out = 77, found = 77, list[2] = {77, 77}, ids[3], count = 77;
    vor_point_t poly[4];
    vor_box_t box = {0, 0, 10, 10};
    vor_vertex_t vertex;
    vor_memory_t memory;
    unsigned bad = 0;
    bad += vor_insert(&zeroed, (vor_point_t){1, 1}, &out) != VOR_ERR_FULL;
    bad += vor_insert_near(&zeroed, (vor_point_t){1, 1}, VOR_NO_HINT, &out) != VOR_ERR_FULL;
    bad += vor_build(&zeroed, points, 1, NULL, NULL) != VOR_ERR_FULL;
    bad += vor_build_dc(&zeroed, points, 1, NULL, NULL) != VOR_ERR_FULL;
    bad += vor_build_dc_forked(&zeroed, points, 1, TEST_SPLIT(VOR_DC_XSPLIT), NULL, NULL) != VOR_ERR_FULL;
    bad += vor_nearest(&zeroed, (vor_point_t){1, 1}, VOR_NO_HINT, &out) != VOR_ERR_EMPTY;
    bad += vor_nearest_k(&zeroed, (vor_point_t){1, 1}, VOR_NO_HINT, 2, list, &found) != VOR_ERR_EMPTY;
    bad += vor_locate(&zeroed, (vor_point_t){1, 1}, VOR_NO_HINT, ids) != VOR_ERR_EMPTY;
    bad += vor_within(&zeroed, (vor_point_t){1, 1}, 4, VOR_NO_HINT, list, 2, &found) != VOR_ERR_EMPTY;
    bad += vor_triangles_export(&zeroed, NULL, NULL, 0, &count) != VOR_OK || count != 0u;
    count = 77;
    bad += vor_cell(&zeroed, 0, &box, poly, 4, &count) != VOR_ERR_ARG;
    vor_centroid_t centroid;
    bad += vor_cell_centroid(&zeroed, 0, &box, NULL, 0, &centroid) != VOR_ERR_ARG;
    bad += vor_voronoi_vertex(&zeroed, 0, 1, 2, &vertex) != VOR_ERR_ARG;
    bad += vor_validate(&zeroed, NULL) != VOR_OK;
    bad += (vor_memory(&zeroed, &memory) != VOR_OK || memory.sites != 0u);
    bad += (out != 77 || found != 77 || list[0] != 77 || count != 77);
    vor_triangle_iter_t triangles;
    vor_triangles_begin(&triangles, &zeroed);
    bad += vor_triangles_next(&triangles, ids) != 0;
    vor_neighbour_iter_t neighbours;
    vor_neighbours_begin(&neighbours, &zeroed, 0);
    bad += vor_neighbours_next(&neighbours, &out) != 0;
    vor_edge_iter_t edges;
    vor_edge_t edge;
    vor_edges_begin(&edges, &zeroed);
    bad += vor_edges_next(&edges, &edge) != 0;
    vor_hull_iter_t hull;
    vor_hull_begin(&hull, &zeroed);
    bad += vor_hull_next(&hull, &out) != 0;
    vor_cell_iter_t cells;
    vor_cells_begin(&cells, &zeroed, &box);
    bad += vor_cells_next(&cells, &out, poly, 4, &count) != 0;
    vor_tracker_t tracker;
    bad += (vor_tracker_begin(&tracker, &zeroed) != VOR_OK ||
            vor_track(&tracker, (vor_point_t){0, 0}, &out) != VOR_ERR_EMPTY);
    CHECK(bad == 0 && out == 77, "a never-initialised diagram: %u wrong answers", bad);
}

/* The arguments each check tells apart one by one: every repeated index
 * of the perturbed predicates (each pair of positions, the others
 * distinct), each limit of a raster frame and output on its own, and the
 * calls whose NULL is allowed. Every refusal leaves everything as it was. */
static void check_each_argument(void)
{
    static const int64_t power_weights[SAFE_SITES] = {0, 1, 2, 3, 4, INT64_MIN, INT64_MAX, 7};
    CHECK(build_all(SAFE_SITES), "build");
    snapshot();
    unsigned bad = 0;
    for (uint32_t i = 0; i < 4u; i++) {
        for (uint32_t j = i + 1u; j < 4u; j++) {
            uint32_t id[4] = {4, 5, 6, 7}; /* distinct, then positions i and j equal */
            id[j] = id[i];
            bad += vor_incircle_sos(points, id[0], id[1], id[2], id[3]) != 0;
            bad += vor_power_test_sos(points, power_weights, id[0], id[1], id[2], id[3]) != 0;
            if (j < 3u) {
                bad += vor_orient2d_sos(points, id[0], id[1], id[2]) != 0;
                bad += vor_closer_sos(points, id[0], id[1], id[2]) != 0;
            }
        }
    }
    /* the same ids distinct: an answer, never 0 */
    bad += vor_incircle_sos(points, 4, 5, 6, 7) == 0 || vor_orient2d_sos(points, 4, 5, 6) == 0 ||
           vor_closer_sos(points, 4, 5, 6) == 0 ||
           vor_power_test_sos(points, power_weights, 4, 5, 6, 7) == 0;
    CHECK(bad == 0 && unchanged(), "perturbed predicates, repeated indices: %u wrong", bad);

    /* cells: vertices NULL with capacity 0 asks for the count only */
    vor_box_t box = {-10, -10, 9000, 5000};
    vor_point_t poly[VOR_CELL_MAX_VERTICES(SAFE_SITES)];
    uint32_t want = 0, site = 77, count = 77;
    vor_cell_iter_t cells;
    bad = vor_cell(&diagram, 0, &box, poly, VOR_CELL_MAX_VERTICES(SAFE_SITES), &want) != VOR_OK;
    bad += vor_cells_begin(&cells, &diagram, &box) != VOR_OK;
    bad += vor_cells_next(&cells, &site, NULL, 0, &count) != 0;
    bad += vor_cells_error(&cells) != VOR_ERR_BUFFER || site != 0u || count != want || want < 3u;
    CHECK(bad == 0 && unchanged(), "cells: the count alone: %u wrong", bad);

    /* one site duplicated with NULL for its id: the duplicate is still
     * told (a full diagram, and one of a single vertex) */
    CHECK(vor_insert(&diagram, points[3], NULL) == VOR_ERR_DUPLICATE && unchanged(),
          "full diagram: a duplicate, id not wanted");
    CHECK(vor_init(&diagram, arena, sizeof arena, SAFE_SITES) == VOR_OK &&
              vor_insert(&diagram, points[0], NULL) == VOR_OK,
          "one site");
    snapshot();
    CHECK(vor_insert(&diagram, points[0], NULL) == VOR_ERR_DUPLICATE && unchanged(),
          "one-vertex diagram: a duplicate, id not wanted");
    /* no points at all is a valid build: it empties the diagram */
    uint32_t nearest = 77;
    CHECK(vor_build(&diagram, NULL, 0, NULL, NULL) == VOR_OK &&
              vor_nearest(&diagram, points[0], VOR_NO_HINT, &nearest) == VOR_ERR_EMPTY &&
              nearest == 77u && vor_validate(&diagram, NULL) == VOR_OK,
          "vor_build of no points (NULL)");
    snapshot();

    /* raster: each limit alone (the frame, then the output's kind) */
    static uint8_t work[VOR_RASTER_WORK_BYTES(SAFE_SITES, 8)]
        __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
    uint8_t band[8 * 4 * 4], band_before[sizeof band];
    fill(band, sizeof band, 0x99);
    test_copy_bytes(band_before, band, sizeof band);
    unsigned flushes = 0;
    const vor_raster_frame_t good = {0, 0, 100, 100, 8, 4};
    vor_raster_frame_t frames[8];
    for (unsigned k = 0; k < 8u; k++) {
        frames[k] = good;
    }
    frames[0].height = 0;
    frames[1].step_y = 0;
    frames[2].width = 0x80000000u;
    frames[3].height = 0x80000000u;
    frames[4].origin_x = INT32_MAX - 699; /* last centre x = INT32_MAX + 1 */
    frames[5].origin_y = INT32_MAX - 299; /* last centre y = INT32_MAX + 1 */
    /* 2^27 columns of step 1 from INT32_MIN: the centres fit, the work
     * size would not */
    frames[6].origin_x = INT32_MIN;
    frames[6].step_x = 1;
    frames[6].width = 0x08000000u;
    frames[7].origin_x = INT32_MAX - 700; /* the widest frame that fits: valid */
    vor_raster_sites_t set = {VOR_METRIC_EUCLID, points, SAFE_SITES, NULL, NULL, NULL, 0, 0, 0, 0, NULL};
    vor_raster_output_t out = {VOR_RASTER_LABEL8, band, sizeof band, 4, never_flush, &flushes,
                               NULL, NULL, NULL};
    bad = 0;
    for (unsigned k = 0; k < 7u; k++) {
        bad += vor_raster(&frames[k], &set, &out, NULL, work, sizeof work) != VOR_ERR_ARG;
    }
    vor_raster_sites_t many = set; /* counts refused before any point is read */
    vor_raster_output_t kinds = out;
    kinds.kind = VOR_RASTER_LABEL16;
    many.count = 65537u;
    bad += vor_raster(&good, &many, &kinds, NULL, work, sizeof work) != VOR_ERR_ARG;
    kinds.kind = VOR_RASTER_RGB565;
    bad += vor_raster(&good, &set, &kinds, NULL, work, sizeof work) != VOR_ERR_ARG;
    kinds.kind = VOR_RASTER_RGB888;
    bad += vor_raster(&good, &set, &kinds, NULL, work, sizeof work) != VOR_ERR_ARG;
    kinds.kind = VOR_RASTER_LABEL32;
    many.count = 0x08000000u;
    bad += vor_raster(&good, &many, &kinds, NULL, work, sizeof work) != VOR_ERR_ARG;
    bad += (flushes != 0u || !test_same_bytes(band, band_before, sizeof band));
    CHECK(bad == 0 && unchanged(), "raster limits: %u bad arguments accepted or wrote", bad);
    CHECK(vor_raster(&frames[7], &set, &out, NULL, work, sizeof work) == VOR_OK && flushes == 1u,
          "raster: the frame ending at INT32_MAX");
}

/* ------------------------------------------------------------------ */
/* Weighted sites (vor_power.h)                                        */

#define POWER_N (SAFE_SITES - 3u) /* the scene's sites, a duplicate and a hidden twin among them */

static uint8_t power_arena[VOR_POWER_ARENA_BYTES(SAFE_SITES) + 8u]
    __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));
static uint8_t saved_power_arena[sizeof power_arena];
static vor_power_t power, saved_power;
static vor_point_t power_points[POWER_N];
static int64_t power_weights[POWER_N];

static void power_snapshot(void)
{
    test_copy_bytes(&saved_power, &power, sizeof power);
    test_copy_bytes(saved_power_arena, power_arena, sizeof power_arena);
}

static bool power_unchanged(void)
{
    return test_same_bytes(&saved_power, &power, sizeof power) &&
           test_same_bytes(saved_power_arena, power_arena, sizeof power_arena);
}

/* The power calls' set-up: the scene built in power (duplicate_of into
 * dup, or NULL), then the snapshot power_unchanged compares with; returns
 * whether it built. The scene: the jittered grid, weight 0, but site 10
 * heavy enough to hide every site off the hull (a radius of 10^4 over a
 * grid of 8000 by 4000), site POWER_N - 2 at site 5's point 1000 lighter
 * (hidden: farther everywhere), site POWER_N - 1 a copy of site 3 (a
 * duplicate). */
static bool power_scene(uint32_t *dup)
{
    for (uint32_t i = 0; i < POWER_N; i++) {
        power_points[i] = points[i];
        power_weights[i] = 0;
    }
    power_weights[10] = 100000000;
    power_points[POWER_N - 2u] = points[5];
    power_weights[POWER_N - 2u] = -1000;
    power_points[POWER_N - 1u] = points[3];
    bool built = vor_power_init(&power, power_arena, sizeof power_arena, SAFE_SITES) == VOR_OK &&
                 vor_power_build(&power, power_points, power_weights, POWER_N, dup) == VOR_OK;
    power_snapshot();
    return built;
}

/* vor_power_init: each documented error alone, nothing written; the good
 * call writes only *pd, never the arena. */
static void check_power_init(void)
{
    fill(&power, sizeof power, 0xA5);
    fill(power_arena, sizeof power_arena, 0x5A);
    power_snapshot();
    size_t need = VOR_POWER_ARENA_BYTES(SAFE_SITES);
    unsigned bad = 0;
    bad += vor_power_init(NULL, power_arena, need, 4) != VOR_ERR_ARG;
    bad += vor_power_init(&power, NULL, need, 4) != VOR_ERR_ARG;
    bad += vor_power_init(&power, power_arena, need, 0) != VOR_ERR_ARG;
    bad += vor_power_init(&power, power_arena, sizeof power_arena, VOR_MAX_SITES + 1u) != VOR_ERR_ARG;
    bad += vor_power_init(&power, power_arena, sizeof power_arena, 0xFFFFFFFFu) != VOR_ERR_ARG;
    for (unsigned off = 1; off < VOR_POWER_ARENA_ALIGN; off++) { /* 4 too: the weights are int64 */
        bad += vor_power_init(&power, power_arena + off, need, SAFE_SITES) != VOR_ERR_ALIGN;
    }
    bad += vor_power_init(&power, power_arena, need - 1u, SAFE_SITES) != VOR_ERR_NOMEM;
    bad += vor_power_init(&power, power_arena, VOR_ARENA_BYTES(SAFE_SITES), SAFE_SITES) != VOR_ERR_NOMEM;
    bad += vor_power_init(&power, power_arena, VOR_POWER_ARENA_BYTES(1) - 1u, 1) != VOR_ERR_NOMEM;
    bad += vor_power_init(&power, power_arena, 0, 1) != VOR_ERR_NOMEM;
    for (unsigned bit = 0; bit < 32u; bit++) {
        bad += vor_power_init_checked(&power, power_arena, need, SAFE_SITES,
                                      VOR_CONFIG_FINGERPRINT ^ (1u << bit)) != VOR_ERR_CONFIG;
    }
    /* the fingerprint first: a bad one with every other argument bad too */
    bad += vor_power_init_checked(NULL, NULL, 0, 0, VOR_CONFIG_FINGERPRINT ^ 1u) != VOR_ERR_CONFIG;
    CHECK(bad == 0 && power_unchanged(), "power_init: %u bad arguments accepted or wrote", bad);
    CHECK(vor_power_init(&power, power_arena, need, SAFE_SITES) == VOR_OK &&
              test_same_bytes(saved_power_arena, power_arena, sizeof power_arena),
          "power_init: the exact size, the arena untouched");
    vor_power_hidden_iter_t one_site_hidden;
    uint32_t hidden_id = 77;
    CHECK(vor_power_init(&power, power_arena, VOR_POWER_ARENA_BYTES(1), 1) == VOR_OK &&
              vor_power_insert(&power, (vor_point_t){1, 2}, 3, NULL) == VOR_OK &&
              vor_power_validate(&power, NULL) == VOR_OK &&
              vor_power_hidden_begin(&one_site_hidden, &power) == VOR_OK &&
              vor_power_hidden_next(&one_site_hidden, &hidden_id) == 0 && hidden_id == 77,
          "power_init: one site in the smallest arena");
}

/* Insert and build: NULLs, duplicates (with and without an id wanted),
 * a full object; every failure leaves the object and the arena as they
 * were and writes no id and no duplicate_of. */
static void check_power_insert_and_build(void)
{
    uint32_t dup[POWER_N];
    uint32_t out = 77;
    CHECK(power_scene(dup) && dup[POWER_N - 1u] == 3u && dup[POWER_N - 2u] == POWER_N - 2u && dup[0] == 0u,
          "power: the scene");
    unsigned bad = 0;
    bad += vor_power_insert(NULL, (vor_point_t){1, 2}, 0, &out) != VOR_ERR_ARG;
    bad += out != 77;
    for (uint32_t i = 0; i < POWER_N; i++) {
        uint32_t want = (i == POWER_N - 1u) ? 3u : i;
        out = 77;
        bad += vor_power_insert(&power, power_points[i], power_weights[i], &out) != VOR_ERR_DUPLICATE;
        bad += out != want;
        bad += vor_power_insert(&power, power_points[i], power_weights[i], NULL) != VOR_ERR_DUPLICATE;
    }
    CHECK(bad == 0 && power_unchanged(), "power_insert: %u wrong answers to NULL or duplicates", bad);

    uint32_t dup_out[SAFE_SITES + 1u], dup_before[SAFE_SITES + 1u];
    fill(dup_out, sizeof dup_out, 0xEE);
    test_copy_bytes(dup_before, dup_out, sizeof dup_out);
    static vor_point_t many[SAFE_SITES + 1u];
    static int64_t many_w[SAFE_SITES + 1u];
    bad = 0;
    bad += vor_power_build(NULL, power_points, power_weights, 3, dup_out) != VOR_ERR_ARG;
    bad += vor_power_build(&power, NULL, power_weights, 3, dup_out) != VOR_ERR_ARG;
    bad += vor_power_build(&power, power_points, NULL, 3, dup_out) != VOR_ERR_ARG;
    bad += vor_power_build(&power, NULL, NULL, SAFE_SITES + 1u, dup_out) != VOR_ERR_ARG;
    bad += vor_power_build(&power, many, many_w, SAFE_SITES + 1u, dup_out) != VOR_ERR_FULL;
    bad += vor_power_build(&power, many, many_w, 0xFFFFFFFFu, dup_out) != VOR_ERR_FULL;
    bad += !test_same_bytes(dup_out, dup_before, sizeof dup_out);
    CHECK(bad == 0 && power_unchanged(), "power_build: %u bad arguments accepted or wrote", bad);

    /* full: a new site FULL, id not written; a duplicate still told */
    for (uint32_t max_sites = 1; max_sites <= POWER_N; max_sites += (max_sites < 4u) ? 1u : 8u) {
        uint32_t n = max_sites;
        CHECK(vor_power_init(&power, power_arena, sizeof power_arena, max_sites) == VOR_OK &&
                  vor_power_build(&power, power_points, power_weights, n, NULL) == VOR_OK,
              "power: build %u", n);
        power_snapshot();
        bad = 0;
        out = 77;
        bad += vor_power_insert(&power, (vor_point_t){-1, -1}, 5, &out) != VOR_ERR_FULL;
        bad += vor_power_insert(&power, power_points[0], power_weights[0] + 1, &out) != VOR_ERR_FULL;
        bad += out != 77;
        bad += vor_power_insert(&power, power_points[n - 1u], power_weights[n - 1u], &out) != VOR_ERR_DUPLICATE;
        bad += out != n - 1u;
        bad += vor_power_insert(&power, power_points[n - 1u], power_weights[n - 1u], NULL) != VOR_ERR_DUPLICATE;
        CHECK(bad == 0 && power_unchanged(), "power: full at %u: %u wrong answers", n, bad);
    }
    /* a build of no points (NULL) empties it */
    CHECK(vor_power_build(&power, NULL, NULL, 0, NULL) == VOR_OK &&
              vor_power_hidden(&power, 0) == VOR_ERR_ARG && vor_power_validate(&power, NULL) == VOR_OK,
          "power_build of no points (NULL)");
}

/* The reads: vor_power_hidden of every id, the iterators with NULLs,
 * zeroed and after their end, vor_power_validate; none writes. */
static void check_power_reads(void)
{
    CHECK(power_scene(NULL), "power: the scene");
    unsigned bad = 0;
    uint32_t hidden = 0;
    bad += vor_power_hidden(NULL, 0) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, POWER_N - 1u) != VOR_ERR_ARG; /* a duplicate's */
    bad += vor_power_hidden(&power, POWER_N) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, SAFE_SITES) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, VOR_NO_HINT) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, 0xFFFFFFFFu) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, POWER_N - 2u) != 1;           /* the lighter twin */
    bad += vor_power_hidden(&power, 10) != 0;                     /* the heavy site */
    for (uint32_t i = 0; i + 1u < POWER_N; i++) {
        int h = vor_power_hidden(&power, i);
        bad += (h != 0) && (h != 1);
        hidden |= (h == 1 && i != POWER_N - 2u) ? 1u : 0u;
    }
    CHECK(bad == 0 && hidden != 0u && power_unchanged(), "power_hidden: %u wrong answers", bad);

    bad = 0;
    uint32_t site = 77, listed = 0;
    static vor_power_hidden_iter_t zero_hidden;
    vor_power_hidden_iter_t it;
    bad += vor_power_hidden_begin(NULL, &power) != VOR_ERR_ARG;
    bad += vor_power_hidden_next(&zero_hidden, &site) + vor_power_hidden_next(NULL, &site) != 0;
    bad += vor_power_hidden_begin(&it, NULL) != VOR_ERR_ARG;
    bad += vor_power_hidden_next(&it, &site) != 0;
    bad += vor_power_hidden_begin(&it, &power) != VOR_OK;
    bad += vor_power_hidden_next(&it, NULL) != 0;
    bad += site != 77;
    bad += vor_power_hidden_begin(&it, &power) != VOR_OK;
    while (vor_power_hidden_next(&it, &site) && listed <= POWER_N) {
        listed++;
        bad += vor_power_hidden(&power, site) != 1;
    }
    bad += vor_power_hidden_next(&it, &site) != 0;
    uint32_t count = 0;
    for (uint32_t i = 0; i < POWER_N; i++) {
        count += vor_power_hidden(&power, i) == 1 ? 1u : 0u;
    }
    bad += listed != count;
    CHECK(bad == 0 && power_unchanged(), "power hidden iterator: %u wrong, %u listed of %u", bad, listed,
          count);

    bad = 0;
    uint32_t ids[3] = {77, 77, 77}, triangles = 0;
    vor_triangle_iter_t ti;
    bad += vor_power_triangles_begin(NULL, &power) != VOR_ERR_ARG;
    bad += vor_power_triangles_begin(&ti, NULL) != VOR_ERR_ARG;
    bad += vor_triangles_next(&ti, ids) != 0;
    bad += vor_power_triangles_begin(&ti, &power) != VOR_OK;
    bad += vor_triangles_next(&ti, NULL) != 0;
    bad += (ids[0] != 77 || ids[2] != 77);
    bad += vor_power_triangles_begin(&ti, &power) != VOR_OK;
    while (vor_triangles_next(&ti, ids) && triangles <= 2u * POWER_N) {
        triangles++;
        for (unsigned k = 0; k < 3u; k++) {
            bad += vor_power_hidden(&power, ids[k]) != 0;
        }
    }
    bad += triangles == 0u;
    bad += vor_triangles_next(&ti, ids) != 0;
    CHECK(bad == 0 && power_unchanged(), "power triangle iterator: %u wrong", bad);

    vor_violation_t violation;
    fill(&violation, sizeof violation, 0x33);
    vor_violation_t violation_before = violation;
    CHECK(vor_power_validate(NULL, &violation) == VOR_ERR_ARG &&
              test_same_bytes(&violation, &violation_before, sizeof violation) &&
              vor_power_validate(&power, NULL) == VOR_OK &&
              vor_power_validate(&power, &violation) == VOR_OK && power_unchanged(),
          "power_validate: NULL, or a good object refused");

    /* the cells: every id and bad arguments; an error writes nothing, a
     * hidden site's cell is empty, a cell fits VOR_CELL_MAX_VERTICES */
    static vor_point_t poly[VOR_CELL_MAX_VERTICES(POWER_N)];
    static uint8_t centroid_scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(POWER_N))];
    const vor_box_t box = {-2000000000, -2000000000, 2000000000, 2000000000};
    const vor_box_t inverted = {0, 1, 0, 0};
    const uint32_t cap = VOR_CELL_MAX_VERTICES(POWER_N);
    bad = 0;
    uint32_t m = 77;
    vor_centroid_t c = {{77, 77}, 77, 77};
    bad += vor_power_cell(NULL, 0, &box, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, 0, NULL, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, 0, &inverted, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, 0, &box, NULL, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, 0, &box, poly, cap, NULL) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, POWER_N - 1u, &box, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, POWER_N, &box, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell(&power, 0xFFFFFFFFu, &box, poly, cap, &m) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(NULL, 0, &box, centroid_scratch, sizeof centroid_scratch, &c) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, 0, NULL, centroid_scratch, sizeof centroid_scratch, &c) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, 0, &inverted, centroid_scratch, sizeof centroid_scratch, &c) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, 0, &box, NULL, 1, &c) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, 0, &box, centroid_scratch, sizeof centroid_scratch, NULL) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, POWER_N - 1u, &box, centroid_scratch, sizeof centroid_scratch, &c) != VOR_ERR_ARG;
    bad += vor_power_cell_centroid(&power, 0xFFFFFFFFu, &box, centroid_scratch, sizeof centroid_scratch, &c) != VOR_ERR_ARG;
    bad += (m != 77 || c.area != 77 || c.vertices != 77 || c.point.x != 77);
    for (uint32_t i = 0; i + 1u < POWER_N; i++) {
        int h = vor_power_hidden(&power, i);
        bad += vor_power_cell(&power, i, &box, poly, cap, &m) != VOR_OK;
        bad += (h == 1) ? (m != 0u) : (m < 3u);
        bad += vor_power_cell_centroid(&power, i, &box, centroid_scratch, sizeof centroid_scratch, &c) != VOR_OK;
        bad += c.vertices != m;
    }
    CHECK(bad == 0 && power_unchanged(), "power cells: %u wrong answers", bad);
}

/* Remove, move and nearest: NULLs, ids that are no site (unused, a
 * duplicate's, removed, huge), a move onto another site (with and
 * without *existing), bad hints; every failure leaves the object and the
 * arena as they were and writes no id. Then the good calls. */
static void check_power_dynamic(void)
{
    CHECK(power_scene(NULL), "power: the scene");
    unsigned bad = 0;
    uint32_t out = 77;
    const uint32_t no_site[5] = {POWER_N - 1u, POWER_N, SAFE_SITES, VOR_NO_HINT - 1u, VOR_NO_HINT};
    vor_point_t q = {1, 2};
    bad += vor_power_remove(NULL, 0) != VOR_ERR_ARG;
    bad += vor_power_move(NULL, 0, q, 0, &out) != VOR_ERR_ARG;
    bad += vor_power_nearest(NULL, q, VOR_NO_HINT, &out) != VOR_ERR_ARG;
    bad += vor_power_nearest(&power, q, VOR_NO_HINT, NULL) != VOR_ERR_ARG;
    for (unsigned k = 0; k < 5u; k++) {
        bad += vor_power_remove(&power, no_site[k]) != VOR_ERR_ARG;
        bad += vor_power_move(&power, no_site[k], q, 0, &out) != VOR_ERR_ARG;
        bad += (no_site[k] != VOR_NO_HINT) &&
               (vor_power_nearest(&power, q, no_site[k], &out) != VOR_ERR_ARG);
    }
    /* onto another site (point and weight): refused with its id */
    bad += vor_power_move(&power, 0, power_points[1], power_weights[1], NULL) != VOR_ERR_DUPLICATE;
    bad += out != 77;
    bad += vor_power_move(&power, 0, power_points[3], power_weights[3], &out) != VOR_ERR_DUPLICATE;
    bad += out != 3u;
    bad += vor_power_move(&power, POWER_N - 2u, power_points[10], power_weights[10], &out) !=
           VOR_ERR_DUPLICATE; /* the hidden site onto the heavy one */
    bad += out != 10u;
    /* onto itself: nothing changes */
    bad += vor_power_move(&power, 4, power_points[4], power_weights[4], &out) != VOR_OK;
    CHECK(bad == 0 && out == 10u && power_unchanged(),
          "power remove, move, nearest: %u wrong answers, or a failure wrote", bad);

    /* the good calls: every site removed, the ids freed, then moved ones */
    bad = 0;
    bad += vor_power_nearest(&power, power_points[10], POWER_N - 2u, &out) != VOR_OK;
    bad += out != 10u; /* the heavy site, from a hidden hint */
    bad += vor_power_remove(&power, POWER_N - 2u) != VOR_OK;
    bad += vor_power_remove(&power, POWER_N - 2u) != VOR_ERR_ARG;
    bad += vor_power_hidden(&power, POWER_N - 2u) != VOR_ERR_ARG;
    bad += vor_power_nearest(&power, q, POWER_N - 2u, &out) != VOR_ERR_ARG;
    bad += vor_power_move(&power, 10, (vor_point_t){-5, -5}, 7, &out) != VOR_OK;
    bad += vor_power_hidden(&power, 10) != 0;
    bad += vor_power_validate(&power, NULL) != VOR_OK;
    for (uint32_t i = 0; i + 2u < POWER_N; i++) {
        bad += vor_power_remove(&power, i) != VOR_OK;
        bad += vor_power_validate(&power, NULL) != VOR_OK;
    }
    bad += vor_power_nearest(&power, q, VOR_NO_HINT, &out) != VOR_ERR_EMPTY;
    out = 77;
    bad += vor_power_insert(&power, q, 0, &out) != VOR_OK;
    bad += out != POWER_N - 3u; /* the most recently freed id */
    CHECK(bad == 0, "power remove, move, nearest: %u wrong answers to good calls", bad);
}

/* A vor_power_t vor_power_init never saw, zeroed as static storage is:
 * empty and full, every call refused or empty, nothing written. */
static void check_power_zeroed(void)
{
    static vor_power_t zeroed;
    static const vor_power_t zero;
    uint32_t out = 77, ids[3] = {77, 77, 77};
    uint32_t dup[2] = {77, 77};
    unsigned bad = 0;
    bad += vor_power_insert(&zeroed, (vor_point_t){1, 1}, 0, &out) != VOR_ERR_FULL;
    bad += vor_power_insert(&zeroed, (vor_point_t){1, 1}, 0, NULL) != VOR_ERR_FULL;
    bad += vor_power_build(&zeroed, points, power_weights, 1, dup) != VOR_ERR_FULL;
    bad += vor_power_hidden(&zeroed, 0) != VOR_ERR_ARG;
    bad += vor_power_hidden(&zeroed, 1) != VOR_ERR_ARG;
    bad += vor_power_validate(&zeroed, NULL) != VOR_OK;
    bad += vor_power_remove(&zeroed, 0) != VOR_ERR_ARG;
    bad += vor_power_move(&zeroed, 0, (vor_point_t){1, 1}, 0, &out) != VOR_ERR_ARG;
    bad += vor_power_nearest(&zeroed, (vor_point_t){1, 1}, VOR_NO_HINT, &out) != VOR_ERR_EMPTY;
    bad += vor_power_nearest(&zeroed, (vor_point_t){1, 1}, 0, &out) != VOR_ERR_EMPTY;
    vor_power_hidden_iter_t it;
    bad += vor_power_hidden_begin(&it, &zeroed) != VOR_OK;
    bad += vor_power_hidden_next(&it, &out) != 0;
    vor_triangle_iter_t ti;
    bad += vor_power_triangles_begin(&ti, &zeroed) != VOR_OK;
    bad += vor_triangles_next(&ti, ids) != 0;
    bad += (out != 77 || ids[0] != 77 || dup[0] != 77);
    vor_point_t poly[4];
    uint32_t m = 77;
    const vor_box_t box = {0, 0, 10, 10};
    bad += vor_power_cell(&zeroed, 0, &box, poly, 4, &m) != VOR_ERR_ARG;
    bad += m != 77;
    CHECK(bad == 0 && test_same_bytes(&zeroed, &zero, sizeof zero),
          "a never-initialised power object: %u wrong answers, or written", bad);
}

void test_api_safety(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 0x5AFE);
    make_points(&rng);
    TEST_CASE("config") check_config();
    TEST_CASE("init") check_init();
    TEST_CASE("small_hints") check_small_hints();
    TEST_CASE("insert_and_build") check_insert_and_build(test_rng_seed(&rng, 0x5AFE1));
    TEST_CASE("reads") check_reads();
    TEST_CASE("iterators") check_iterators();
    TEST_CASE("raster") check_raster();
    TEST_CASE("field") check_field();
    TEST_CASE("zeroed_diagram") check_zeroed_diagram();
    TEST_CASE("each_argument") check_each_argument();
    TEST_CASE("power/init") check_power_init();
    TEST_CASE("power/insert_and_build") check_power_insert_and_build();
    TEST_CASE("power/reads") check_power_reads();
    TEST_CASE("power/dynamic") check_power_dynamic();
    TEST_CASE("power/zeroed") check_power_zeroed();
}
