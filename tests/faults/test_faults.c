/* SPDX-License-Identifier: MIT */
/*
 * test_faults.c - the topology survives wrong arithmetic (seed 003 section
 * 3, fig. 6; seed 000 section 5).
 *
 * Built with VOR_FAULT_INJECTION: the diagram's perturbed predicates return
 * the wrong sign with probability p. For p in {0.01, 0.1, 0.5} and 10,000
 * sites, building (incrementally and by divide and conquer, and
 * inserting one by one), then removing and moving sites, removing every
 * site, and removing a site with a star beyond removal's arrays, must
 * finish and leave a mesh
 * whose topological invariants all hold: counts from Euler's formula,
 * valid distinct vertices, symmetric neighbours, every site present with
 * one fan of triangles. Only the geometric checks (orientation, Delaunay)
 * may fail. The host runs this under AddressSanitizer too, so an
 * out-of-bounds access would also fail it.
 *
 * Constraints (vor_cdt.h) on a diagram under the same lies, one case
 * per rate: inserting sites (some in the middle of constraints),
 * constraining and unconstraining, marking the domain, walking every
 * iterator, removing and moving sites, with roomy limits and with tight
 * ones (tables and cuts that overflow), then constraining again after a
 * rebuild, must finish, return only the documented errors, and leave
 * the diagram's topology whole and every vertex the iterators report one
 * of the diagram's sites or crossings. The constrained mesh's own
 * predicates stay exact (attached before the faults start), no two sites
 * share a point and the rebuild is exact: the constrained code does not
 * survive lies of its own or a lying triangulation copied into it.
 *
 * Weighted sites (vor_power.h) under the same lies, one case per rate:
 * random sites with random weights, a grid with small random weights,
 * sites at a few points with different (and equal) weights, sites on one
 * line and collinear runs, each built (vor_power_build) and inserted one
 * by one (vor_power_insert), then removed, moved and queried
 * (vor_power_remove, vor_power_move, vor_power_nearest) at random. Every
 * call must return a documented result,
 * the mesh pass vor_power_validate's topological checks, and every id be
 * exactly one of a vertex, a hidden site (listed once by the hidden
 * iterator, no other) or a build's duplicate; with the rate back to 0 a
 * fresh build of each scene must validate whole.
 *
 * Natural-neighbour interpolation (vor_sibson, vor_laplace,
 * vor_interpolate, vor_interpolate_laplace) on diagrams built under the
 * same lies, one case per rate: random sites, a lattice (cocircular
 * sites) and a line, queried at random points, sites and hull edges with
 * good and bad hints. Every call returns a documented result and leaves
 * the arena, the diagram and the values byte-identical; each failing
 * path changes nothing else either: every scratch size below the need,
 * at every alignment, is VOR_ERR_NOMEM with only the count written and
 * the scratch untouched, a bad hint VOR_ERR_ARG and a point far outside
 * VOR_ERR_OUTSIDE with the output untouched; and the call with exactly
 * the scratch needed, after those failures, gives the first answer.
 */
#include "test.h"
#include "vor.h"
#include "vor_cdt.h"
#include "vor_power.h"

#ifndef VOR_FAULT_INJECTION
#error "build with -DVOR_FAULT_INJECTION"
#endif

#define SITES 10000u

static vor_point_t points[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(8)));

static const char *const check_names[] = {"counts",      "vertices", "neighbours",
                                          "sites",       "buckets",  "orientation",
                                          "delaunay",    "true output"};

static void check_topology(const vor_t *d, const char *what, uint32_t rate_percent,
                           uint32_t expected_sites)
{
    vor_violation_t v = {VOR_CHECK_COUNTS, 0, 0};
    int err = vor_validate(d, &v);
    bool topology_ok = err == VOR_OK || v.check >= VOR_CHECK_ORIENTATION;
    CHECK(topology_ok, "%s, p = %u%%: %s check failed at triangle %u, site %u", what,
          rate_percent, check_names[v.check], v.triangle, v.site);
    CHECK(d->vertex_count == expected_sites, "%s, p = %u%%: %u of %u sites in the mesh", what,
          rate_percent, d->vertex_count, expected_sites);
    test_printf("%s, p = %u%%: topology %s, geometry %s\n", what, rate_percent,
                topology_ok ? "consistent" : "BROKEN",
                err == VOR_OK ? "exact" : check_names[v.check]);
}

/* The constraints' run: sites, the constraints' calls in a random mix,
 * a rebuild; checks every call's result and the iterators' output. */
#define CDT_SITES 300u
#define CDT_CROSSINGS 60u
#define CDT_EDGES 500u
#define CDT_CUT (2u * (CDT_SITES + CDT_CROSSINGS) + 2u)

/* Sites on a grid, none twice: the lying diagram can miss a duplicate
 * (it tells one only at the triangle its walk ends in), and the
 * constrained mesh, whose predicates stay exact, is not given one. */
#define HALF 40
#define GRID (2u * HALF + 1u)
static bool taken[GRID * GRID];
static bool alive[CDT_SITES];
static vor_point_t at[CDT_SITES];

static uint32_t grid_index(vor_point_t p)
{
    return ((uint32_t)(p.x + HALF) * GRID) + (uint32_t)(p.y + HALF);
}

/* Mostly a site in the diagram, else an id that is none. */
static uint32_t some_site(test_rng_t *rng)
{
    uint32_t id = test_rng_u32(rng) % CDT_SITES;
    for (unsigned tries = 0; (tries < 8u) && !alive[id]; tries++) {
        id = test_rng_u32(rng) % CDT_SITES;
    }
    return id;
}

static uint8_t cdt_memory[VOR_CDT_BYTES(CDT_SITES, CDT_EDGES, CDT_CROSSINGS, CDT_CUT)]
    __attribute__((aligned(8)));
static uint32_t made_a[CDT_EDGES];
static uint32_t made_b[CDT_EDGES];

/* A vertex a CDT iterator may name: a site in d, or a crossing vertex. */
static bool cdt_vertex(const vor_t *d, uint32_t v)
{
    uint32_t s[4];
    return (v < d->site_count) || (vor_cdt_crossing(d, v, s) == VOR_OK);
}

/* Every iterator walked, bounded by the triangle slots; returns whether
 * each reported a vertex of d only and ended in time (the domain's
 * iterator refuses when no domain is marked since the last change). */
static bool cdt_iterators_sane(vor_t *d)
{
    uint32_t slots = 2u * (CDT_SITES + CDT_CROSSINGS);
    bool sane = true;
    for (unsigned inside = 0; inside < 2u; inside++) {
        vor_cdt_triangle_iter_t it;
        uint32_t ids[3];
        uint32_t n = 0;
        int begun = inside ? vor_cdt_inside_begin(&it, d) : vor_cdt_triangles_begin(&it, d);
        sane = sane && ((begun == VOR_OK) || (inside && (begun == VOR_ERR_ARG)));
        while ((n <= slots) && vor_cdt_triangles_next(&it, ids)) {
            sane = sane && cdt_vertex(d, ids[0]) && cdt_vertex(d, ids[1]) && cdt_vertex(d, ids[2]);
            n++;
        }
        sane = sane && (n <= slots);
    }
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    uint32_t n = 0;
    int begun = vor_cdt_edges_begin(&e, d);
    sane = sane && (begun == VOR_OK);
    while ((n <= CDT_EDGES) && vor_cdt_edges_next(&e, &a, &b)) {
        sane = sane && (a < b) && cdt_vertex(d, a) && cdt_vertex(d, b);
        n++;
    }
    return sane && (n <= CDT_EDGES);
}

static void cdt_under_faults(uint32_t rate, uint32_t rate_percent, unsigned k, bool tight,
                             test_rng_t *rng)
{
    vor_t d;
    vor_cdt_limits_t limits = {CDT_EDGES, CDT_CROSSINGS, CDT_CUT};
    if (tight) { /* the tables and the cuts overflow often */
        limits.edges = 120u;
        limits.crossings = 20u;
        limits.cut = 6u;
    }
    const char *what = tight ? "constraints, tight limits" : "constraints";
    CHECK(vor_init(&d, arena, sizeof arena, CDT_SITES) == VOR_OK, "init");
    /* attached before the faults are switched on, the constrained mesh
     * keeps exact predicates (the attach copies the rate): only the
     * diagram's lie */
    CHECK(vor_cdt_attach(&d, cdt_memory, sizeof cdt_memory, &limits) == VOR_OK, "cdt attach");
    d.fault_rate = rate;
    d.fault_state = 0x6A09E667F3BCC909ull + k;
    uint32_t live = 0;
    uint32_t made = 0;
    uint32_t refused = 0;
    bool results_ok = true;
    for (uint32_t i = 0; i < GRID * GRID; i++) {
        taken[i] = false;
    }
    for (uint32_t i = 0; i < CDT_SITES; i++) {
        alive[i] = false;
    }
    for (uint32_t step = 0; step < 250u; step++) {
        uint32_t a = some_site(rng);
        uint32_t b = some_site(rng);
        uint32_t choice = test_rng_u32(rng) % 16u;
        /* a free grid point, or the middle of a constraint made */
        vor_point_t p = {test_rng_range(rng, -HALF, HALF), test_rng_range(rng, -HALF, HALF)};
        if ((choice < 2u) && (made > 0u)) {
            uint32_t c = test_rng_u32(rng) % made;
            p.x = (at[made_a[c]].x + at[made_b[c]].x) / 2;
            p.y = (at[made_a[c]].y + at[made_b[c]].y) / 2;
        }
        bool free = !taken[grid_index(p)];
        int err;
        if (((choice < 5u) || (live < 8u)) && free) {
            uint32_t id = 0;
            err = vor_insert(&d, p, &id);
            if (err == VOR_OK) {
                live++;
                alive[id] = true;
                at[id] = p;
                taken[grid_index(p)] = true;
            }
            results_ok = results_ok && ((err == VOR_OK) || (err == VOR_ERR_FULL) ||
                                        (err == VOR_ERR_NOMEM));
        } else if ((choice >= 5u) && (choice < 10u)) {
            err = vor_constrain(&d, a, b);
            if ((err == VOR_OK) && (made < CDT_EDGES)) {
                made_a[made] = a;
                made_b[made] = b;
                made++;
            }
            refused += (err == VOR_ERR_NOMEM) ? 1u : 0u;
            results_ok = results_ok && ((err == VOR_OK) || (err == VOR_ERR_ARG) ||
                                        (err == VOR_ERR_NOMEM));
        } else if ((choice == 10u) || (choice == 11u)) {
            if (made > 0u) { /* one made before, or part of it */
                uint32_t c = test_rng_u32(rng) % made;
                a = made_a[c];
                b = (choice == 10u) ? made_b[c] : b;
            }
            err = vor_unconstrain(&d, a, b);
            results_ok = results_ok && ((err == VOR_OK) || (err == VOR_ERR_ARG));
        } else if (choice == 12u) {
            err = vor_remove(&d, a);
            if (err == VOR_OK) {
                live--;
                alive[a] = false;
                taken[grid_index(at[a])] = false;
            }
            results_ok = results_ok && ((err == VOR_OK) || (err == VOR_ERR_ARG) ||
                                        (err == VOR_ERR_CONSTRAINED));
        } else if ((choice == 13u) && free) {
            err = vor_move(&d, a, p, NULL);
            if (err == VOR_OK) {
                taken[grid_index(at[a])] = false;
                at[a] = p;
                taken[grid_index(p)] = true;
            }
            results_ok = results_ok && ((err == VOR_OK) || (err == VOR_ERR_ARG) ||
                                        (err == VOR_ERR_CONSTRAINED) || (err == VOR_ERR_NOMEM));
        } else if (choice == 14u) {
            results_ok = results_ok && (vor_cdt_domain(&d) == VOR_OK);
        } else if (choice == 15u) {
            results_ok = results_ok && cdt_iterators_sane(&d);
        } else {
            /* the point was taken: no site goes there */
        }
    }
    CHECK(results_ok, "%s, p = %u%%: a call returned an undocumented result", what, rate_percent);
    test_printf("%s, p = %u%%: %u sites, %u constraints made, %u refused for room\n", what,
                rate_percent, live, made, refused);
    check_topology(&d, what, rate_percent, live);
    CHECK(vor_cdt_domain(&d) == VOR_OK && cdt_iterators_sane(&d),
          "%s, p = %u%%: an iterator named no vertex, or did not end", what, rate_percent);
    /* a rebuild starts the constraints again from the diagram's
     * triangulation, which must then be exact: the constrained mesh's
     * walks take a copied triangulation as it is */
    static vor_point_t rebuilt[CDT_SITES];
    for (uint32_t i = 0; i < CDT_SITES; i++) { /* distinct: 37 is prime to GRID^2 */
        uint32_t cell = (i * 37u) % (GRID * GRID);
        rebuilt[i].x = (int32_t)(cell % GRID) - HALF;
        rebuilt[i].y = (int32_t)(cell / GRID) - HALF;
    }
    d.fault_rate = 0;
    CHECK(vor_build(&d, rebuilt, CDT_SITES, NULL, NULL) == VOR_OK, "build with constraints");
    d.fault_rate = rate;
    uint32_t made_again = 0;
    for (uint32_t i = 0; i < 100u; i++) {
        int err = vor_constrain(&d, test_rng_u32(rng) % CDT_SITES, test_rng_u32(rng) % CDT_SITES);
        made_again += (err == VOR_OK) ? 1u : 0u;
        CHECK((err == VOR_OK) || (err == VOR_ERR_ARG) || (err == VOR_ERR_NOMEM),
              "constrain after the build: %d", err);
    }
    CHECK(vor_cdt_domain(&d) == VOR_OK && cdt_iterators_sane(&d),
          "%s, p = %u%%: after the build, an iterator named no vertex, or did not end", what,
          rate_percent);
    test_printf("%s, p = %u%%: after a build, %u constraints made\n", what, rate_percent,
                made_again);
    check_topology(&d, "constraints after a build", rate_percent, CDT_SITES);
}

/* Weighted sites under lies: the scenes, built and inserted. */
#define POWER_N 1500u
static vor_point_t power_points[POWER_N];
static int64_t power_weights[POWER_N];
static uint32_t power_dup[POWER_N];
static bool power_listed[POWER_N];
static bool power_removed[POWER_N]; /* ids vor_power_remove freed */
static const char *const power_scenes[] = {"random", "grid", "one place", "one line",
                                           "collinear runs"};

/* Scene k: its sites and weights; returns their number. */
static uint32_t power_scene(unsigned k, test_rng_t *rng)
{
    uint32_t n = 0;
    if (k == 0u) { /* random, weights up to 2^32 (about the squared spacing) */
        for (n = 0; n < POWER_N; n++) {
            power_points[n].x = test_rng_range(rng, -1000000, 1000000);
            power_points[n].y = test_rng_range(rng, -1000000, 1000000);
            power_weights[n] = (int64_t)((((uint64_t)test_rng_u32(rng) << 32) | test_rng_u32(rng)) %
                                         ((uint64_t)1 << 32));
        }
    } else if (k == 1u) { /* a 30 x 30 grid, small weights (cocircular, coplanar lifts) */
        for (n = 0; n < 900u; n++) {
            power_points[n].x = (int32_t)(n % 30u) * 3;
            power_points[n].y = (int32_t)(n / 30u) * 3;
            power_weights[n] = test_rng_range(rng, 0, 30);
        }
    } else if (k == 2u) { /* 5 points, many weights each (equal ones: duplicates) */
        for (n = 0; n < 300u; n++) {
            int32_t at_point = test_rng_range(rng, 0, 4);
            power_points[n].x = (at_point % 3) * 7;
            power_points[n].y = (at_point / 3) * 5;
            power_weights[n] = test_rng_range(rng, -20, 40);
        }
    } else if (k == 3u) { /* one line (the one-dimensional case), a site off it last */
        for (n = 0; n < 400u; n++) {
            int32_t t = test_rng_range(rng, -500, 500);
            power_points[n].x = 2 * t;
            power_points[n].y = 3 * t;
            power_weights[n] = test_rng_range(rng, 0, 200);
        }
        power_points[n - 1u].x = 7;
        power_points[n - 1u].y = -4;
    } else { /* runs of 10 on random lines, small steps */
        for (n = 0; n < 600u; n++) {
            if (n % 10u == 0u) {
                power_points[n].x = test_rng_range(rng, -300, 300);
                power_points[n].y = test_rng_range(rng, -300, 300);
            } else {
                int32_t dx = (int32_t)((n / 10u) % 5u) - 2;
                int32_t dy = (int32_t)((n / 50u) % 3u) - 1;
                dx = ((dx == 0) && (dy == 0)) ? 1 : dx;
                power_points[n].x = power_points[n - 1u].x + dx * test_rng_range(rng, 1, 3);
                power_points[n].y = power_points[n - 1u].y + dy * test_rng_range(rng, 1, 3);
            }
            power_weights[n] = test_rng_range(rng, 0, 30);
        }
    }
    return n;
}

/* vor_power_validate's topological checks pass (exact ones too unless
 * lying), and the hidden sites agree three ways: vor_power_hidden of
 * every id, the hidden iterator (each once) and the counts; the
 * triangle iterator ends and names vertices only. dup: the build's
 * duplicate_of, or NULL after inserts (a duplicate gets no id). */
static void check_power(const vor_power_t *pd, const uint32_t *dup, const char *what,
                        const char *scene, uint32_t rate_percent, bool exact)
{
    vor_violation_t v = {VOR_CHECK_COUNTS, 0, 0};
    int err = vor_power_validate(pd, &v);
    bool topology_ok =
        (err == VOR_OK) || ((err == VOR_ERR_INVALID) && (v.check >= VOR_CHECK_ORIENTATION));
    CHECK(exact ? (err == VOR_OK) : topology_ok,
          "%s, %s, p = %u%%: %s check failed at triangle %u, site %u", what, scene, rate_percent,
          check_names[v.check], v.triangle, v.site);
    uint32_t n = pd->mesh.site_count;
    for (uint32_t i = 0; i < n; i++) {
        power_listed[i] = false;
    }
    vor_power_hidden_iter_t it;
    CHECK(vor_power_hidden_begin(&it, pd) == VOR_OK, "hidden begin");
    uint32_t listed = 0;
    uint32_t id = 0;
    bool list_ok = true;
    while ((listed <= n) && vor_power_hidden_next(&it, &id)) {
        list_ok = list_ok && (id < n) && !power_listed[id] && (vor_power_hidden(pd, id) == 1);
        if (id < n) {
            power_listed[id] = true;
        }
        listed++;
    }
    uint32_t vertices = 0;
    uint32_t hidden = 0;
    for (uint32_t i = 0; i < n; i++) {
        int h = vor_power_hidden(pd, i);
        vertices += (h == 0) ? 1u : 0u;
        hidden += (h == 1) ? 1u : 0u;
        list_ok = list_ok && ((h == 1) == power_listed[i]) &&
                  ((h == 0) || (h == 1) ||
                   ((h == VOR_ERR_ARG) && (((dup != NULL) && (dup[i] != i)) || power_removed[i])));
    }
    list_ok = list_ok && (listed == hidden) && (hidden == pd->hidden_count) &&
              (vertices == pd->mesh.vertex_count);
    CHECK(list_ok,
          "%s, %s, p = %u%%: hidden sites inconsistent: %u listed, %u hidden, count %u, "
          "%u vertices of %u",
          what, scene, rate_percent, listed, hidden, pd->hidden_count, vertices,
          pd->mesh.vertex_count);
    vor_triangle_iter_t t;
    uint32_t ids[3];
    uint32_t triangles = 0;
    bool triangles_ok = vor_power_triangles_begin(&t, pd) == VOR_OK;
    while ((triangles <= 2u * n) && vor_triangles_next(&t, ids)) {
        for (unsigned i = 0; i < 3u; i++) {
            triangles_ok = triangles_ok && (ids[i] < n) && (vor_power_hidden(pd, ids[i]) == 0);
        }
        triangles++;
    }
    CHECK(triangles_ok && (triangles <= 2u * n), "%s, %s, p = %u%%: the triangle iterator", what,
          scene, rate_percent);
    test_printf("%s, %s, p = %u%%: %u vertices, %u hidden, topology %s, geometry %s\n", what,
                scene, rate_percent, vertices, hidden, topology_ok ? "consistent" : "BROKEN",
                (err == VOR_OK) ? "exact" : check_names[v.check]);
}

static void power_under_faults(uint32_t rate, uint32_t rate_percent, unsigned k, test_rng_t *rng)
{
    static vor_power_t pd;
    for (unsigned scene = 0; scene < 5u; scene++) {
        uint32_t n = power_scene(scene, rng);
        /* the batch build */
        CHECK(vor_power_init(&pd, arena, sizeof arena, POWER_N) == VOR_OK, "power init");
        pd.mesh.fault_rate = rate;
        pd.mesh.fault_state = 0xBB67AE8584CAA73Bull + (k * 5u) + scene;
        CHECK(vor_power_build(&pd, power_points, power_weights, n, power_dup) == VOR_OK,
              "power build");
        check_power(&pd, power_dup, "power build", power_scenes[scene], rate_percent, false);
        /* one by one */
        CHECK(vor_power_init(&pd, arena, sizeof arena, POWER_N) == VOR_OK, "power init");
        pd.mesh.fault_rate = rate;
        pd.mesh.fault_state = 0x3C6EF372FE94F82Bull + (k * 5u) + scene;
        bool results_ok = true;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t id = 0;
            int err = vor_power_insert(&pd, power_points[i], power_weights[i], &id);
            results_ok = results_ok &&
                         (((err == VOR_OK) && (id == pd.mesh.site_count - 1u)) ||
                          ((err == VOR_ERR_DUPLICATE) && (id < pd.mesh.site_count)));
        }
        CHECK(results_ok, "power inserts, %s, p = %u%%: an insert returned an undocumented result",
              power_scenes[scene], rate_percent);
        check_power(&pd, NULL, "power inserts", power_scenes[scene], rate_percent, false);
        /* removals (sites and ids that are none), moves to the scene's
         * points and weights, nearest sites: documented results only */
        for (uint32_t i = 0; i < POWER_N; i++) {
            power_removed[i] = false;
        }
        for (uint32_t op = 0; op < 3u * n; op++) {
            uint32_t count = pd.mesh.site_count;
            uint32_t id = test_rng_u32(rng) % (count + 1u);
            bool site = vor_power_hidden(&pd, id) >= 0;
            uint32_t pick = test_rng_u32(rng) % n;
            uint32_t out = 0;
            int err;
            if (op % 3u == 0u) {
                err = vor_power_remove(&pd, id);
                results_ok = results_ok && (err == (site ? VOR_OK : VOR_ERR_ARG));
                if (site) { /* id may be one past the ids handed out (and past the array) */
                    power_removed[id] = true;
                }
            } else if (op % 3u == 1u) {
                err = vor_power_move(&pd, id, power_points[pick], power_weights[pick], &out);
                results_ok = results_ok && (site ? ((err == VOR_OK) || ((err == VOR_ERR_DUPLICATE) &&
                                                                        (out != id) &&
                                                                        (vor_power_hidden(&pd, out) >= 0)))
                                                 : (err == VOR_ERR_ARG));
            } else {
                err = vor_power_nearest(&pd, power_points[pick], site ? id : VOR_NO_HINT, &out);
                results_ok = results_ok && (((err == VOR_OK) && (vor_power_hidden(&pd, out) >= 0)) ||
                                            ((err == VOR_ERR_EMPTY) && (pd.mesh.vertex_count == 0u)));
            }
        }
        CHECK(results_ok,
              "power remove, move, nearest, %s, p = %u%%: an undocumented result",
              power_scenes[scene], rate_percent);
        check_power(&pd, NULL, "power removals and moves", power_scenes[scene], rate_percent, false);
        for (uint32_t i = 0; i < POWER_N; i++) {
            power_removed[i] = false;
        }
        /* no lies: a fresh build is the exact regular triangulation */
        CHECK(vor_power_init(&pd, arena, sizeof arena, POWER_N) == VOR_OK, "power init");
        CHECK(vor_power_build(&pd, power_points, power_weights, n, power_dup) == VOR_OK,
              "power build");
        check_power(&pd, power_dup, "power build, no lies", power_scenes[scene], rate_percent,
                    true);
    }
}

/* The interpolation's run: a diagram of IP_N sites built under lies,
 * then the four calls at IP_QUERIES points per scene. */
#define IP_N 200u
#define IP_QUERIES 16u
#define IP_MOST_K 24u /* the scratch's neighbours; a query needing more is counted, not probed */
#define IP_GUARD 64u
static vor_point_t ip_points[IP_N];
static int32_t ip_values[IP_N];
static int32_t ip_values_before[IP_N];
static uint8_t ip_arena[VOR_ARENA_BYTES(IP_N)] __attribute__((aligned(8)));
static uint8_t ip_arena_before[sizeof ip_arena];
static uint8_t ip_scratch[VOR_SIBSON_SCRATCH_BYTES(IP_MOST_K) + IP_GUARD] __attribute__((aligned(8)));
static uint8_t ip_scratch_before[sizeof ip_scratch];
static uint32_t ip_answer[2][4096]; /* a call's answer, flattened: the first one and a later one */

/* The answer of call f (0, 1: vor_sibson, vor_laplace; 2, 3:
 * vor_interpolate, vor_interpolate_laplace) flattened into ip_answer[slot],
 * with its size; calls it with n bytes of scratch at ip_scratch + offset. */
static int ip_call(unsigned f, const vor_t *d, vor_point_t q, uint32_t hint, size_t offset,
                   size_t n, vor_coordinates_t *c, vor_interpolation_t *v)
{
    void *scratch = (n > 0u) ? (void *)(ip_scratch + offset) : NULL;
    switch (f) {
    case 0u:
        return vor_sibson(d, q, hint, scratch, n, c);
    case 1u:
        return vor_laplace(d, q, hint, scratch, n, c);
    case 2u:
        return vor_interpolate(d, ip_values, q, hint, scratch, n, v);
    default:
        return vor_interpolate_laplace(d, ip_values, q, hint, scratch, n, v);
    }
}

static size_t ip_flatten(unsigned f, unsigned slot, const vor_coordinates_t *c,
                         const vor_interpolation_t *v)
{
    uint32_t *a = ip_answer[slot];
    size_t n = 0;
    if (f < 2u) {
        a[n++] = c->count;
        a[n++] = c->limbs;
        for (uint32_t i = 0; (i < c->count) && (n < 4000u); i++) {
            a[n++] = c->sites[i];
            for (uint32_t w = 0; w < c->limbs; w++) {
                a[n++] = c->weights[(i * c->limbs) + w];
            }
        }
        for (uint32_t w = 0; (w < c->limbs) && (n < 4096u); w++) {
            a[n++] = c->denominator[w];
        }
    } else {
        a[n++] = (uint32_t)v->value;
        a[n++] = (uint32_t)v->sign;
        a[n++] = v->neighbours;
        a[n++] = v->limbs;
        for (uint32_t w = 0; (w < v->limbs) && (n < 4094u); w++) {
            a[n++] = v->numerator[w];
            a[n++] = v->denominator[w];
        }
    }
    return n;
}

/* A failing call of f: err expected, and nothing but the count (NOMEM)
 * written. Returns whether it held. */
static bool ip_fails(unsigned f, const vor_t *d, vor_point_t q, uint32_t hint, size_t offset,
                     size_t n, int expected, uint32_t k)
{
    vor_coordinates_t c, c_before;
    vor_interpolation_t v, v_before;
    for (size_t i = 0; i < sizeof c; i++) {
        ((uint8_t *)&c)[i] = (uint8_t)(0x5Au + i);
    }
    for (size_t i = 0; i < sizeof v; i++) {
        ((uint8_t *)&v)[i] = (uint8_t)(0xA5u + i);
    }
    test_copy_bytes(&c_before, &c, sizeof c);
    test_copy_bytes(&v_before, &v, sizeof v);
    int err = ip_call(f, d, q, hint, offset, n, &c, &v);
    if (expected == VOR_ERR_NOMEM) {
        c_before.count = k;
        v_before.neighbours = k;
    }
    bool same = (f < 2u) ? test_same_bytes(&c, &c_before, sizeof c) : test_same_bytes(&v, &v_before, sizeof v);
    return (err == expected) && same && test_same_bytes(ip_scratch, ip_scratch_before, sizeof ip_scratch);
}

static uint32_t ip_scene(unsigned scene, test_rng_t *rng)
{
    for (uint32_t i = 0; i < IP_N; i++) {
        if (scene == 0u) { /* random, some repeated */
            ip_points[i].x = test_rng_range(rng, -1000, 1000);
            ip_points[i].y = test_rng_range(rng, -1000, 1000);
        } else if (scene == 1u) { /* a lattice: cocircular sites everywhere */
            ip_points[i].x = (int32_t)(i % 14u) * 5;
            ip_points[i].y = (int32_t)(i / 14u) * 5;
        } else { /* one line */
            ip_points[i].x = (int32_t)i * 6 - 600;
            ip_points[i].y = (int32_t)i * 4 + 7;
        }
        ip_values[i] = (int32_t)test_rng_u32(rng);
    }
    return IP_N;
}

static void interpolate_under_faults(uint32_t rate, uint32_t rate_percent, unsigned k, test_rng_t *rng)
{
    static const char *const scenes[] = {"random", "lattice", "line"};
    static const char *const calls[] = {"vor_sibson", "vor_laplace", "vor_interpolate",
                                        "vor_interpolate_laplace"};
    for (unsigned scene = 0; scene < 3u; scene++) {
        uint32_t n = ip_scene(scene, rng);
        vor_t d;
        CHECK(vor_init(&d, ip_arena, sizeof ip_arena, IP_N) == VOR_OK, "interpolate init");
        d.fault_rate = rate;
        d.fault_state = 0x9E3779B97F4A7C15ull ^ (k * 5u + scene);
        CHECK(vor_build(&d, ip_points, n, NULL, NULL) == VOR_OK, "interpolate build");
        vor_t d_before = d;
        test_copy_bytes(ip_arena_before, ip_arena, sizeof ip_arena);
        test_copy_bytes(ip_values_before, ip_values, sizeof ip_values);
        uint32_t answered = 0, outside = 0, too_many = 0, bad = 0;
        for (uint32_t i = 0; i < IP_QUERIES; i++) {
            vor_point_t a = ip_points[test_rng_u32(rng) % n];
            vor_point_t b = ip_points[test_rng_u32(rng) % n];
            vor_point_t q = {test_rng_range(rng, -1100, 1100), test_rng_range(rng, -1100, 1100)};
            if (i % 4u == 1u) {
                q = a; /* at a site */
            } else if (i % 4u == 2u) {
                q.x = (a.x + b.x) / 2; /* between two sites: on hull edges of the line */
                q.y = (a.y + b.y) / 2;
            } else if ((i % 4u == 3u) && (scene == 1u)) {
                q.x = test_rng_range(rng, 0, 65); /* inside the lattice */
                q.y = test_rng_range(rng, 0, 70);
            } else if (i % 4u == 3u) {
                q.x = a.x + 3; /* on the line between two sites (or past its end) */
                q.y = a.y + 2;
            }
            uint32_t hint = ((i % 3u) == 0u) ? VOR_NO_HINT : (test_rng_u32(rng) % n);
            for (unsigned f = 0; f < 4u; f++) {
                vor_coordinates_t c;
                vor_interpolation_t v;
                for (size_t j = 0; j < sizeof ip_scratch; j++) {
                    ip_scratch[j] = (uint8_t)(j * 7u + i);
                }
                test_copy_bytes(ip_scratch_before, ip_scratch, sizeof ip_scratch);
                /* no scratch: the need, or the answer needing none */
                int err = ip_call(f, &d, q, hint, 0, 0, &c, &v);
                bool ok = (err == VOR_OK) || (err == VOR_ERR_OUTSIDE) || (err == VOR_ERR_NOMEM);
                if (err == VOR_ERR_OUTSIDE) {
                    outside++;
                    ok = ok && ip_fails(f, &d, q, hint, 0, sizeof ip_scratch - IP_GUARD, VOR_ERR_OUTSIDE, 0);
                }
                uint32_t need_k = (f < 2u) ? c.count : v.neighbours;
                if ((err == VOR_ERR_NOMEM) && (need_k > IP_MOST_K)) {
                    too_many++;
                } else if (err == VOR_ERR_NOMEM) {
                    /* the first answer, with all the scratch */
                    ok = ok && (ip_call(f, &d, q, hint, 0, sizeof ip_scratch - IP_GUARD, &c, &v) == VOR_OK);
                    size_t words = ok ? ip_flatten(f, 0, &c, &v) : 0u;
                    for (size_t j = 0; j < sizeof ip_scratch; j++) {
                        ip_scratch[j] = (uint8_t)(j * 11u + i);
                    }
                    test_copy_bytes(ip_scratch_before, ip_scratch, sizeof ip_scratch);
                    /* the need at this alignment: the macro less the 8
                     * bytes it keeps for alignment, plus the skip */
                    size_t offset = test_rng_u32(rng) % 8u;
                    size_t need = VOR_SIBSON_SCRATCH_BYTES(need_k) - 8u + ((8u - offset) % 8u);
                    size_t sizes[14] = {0, 1, 8, need / 2u, need - 1u - (test_rng_u32(rng) % need), 0};
                    sizes[5] = (need_k > 1u) ? VOR_SIBSON_SCRATCH_BYTES(need_k - 1u) - 8u : 0u;
                    for (unsigned s = 6; s < 14u; s++) { /* the last 8 sizes below the need */
                        sizes[s] = need - (s - 5u);
                    }
                    for (unsigned s = 0; s < 14u; s++) {
                        ok = ok && ip_fails(f, &d, q, hint, offset, sizes[s], VOR_ERR_NOMEM, need_k);
                    }
                    /* a bad hint: nothing written (a point outside: above) */
                    ok = ok && ip_fails(f, &d, q, n + 1u, offset, need, VOR_ERR_ARG, 0);
                    /* exactly the need, after the failures: the same answer */
                    ok = ok && (ip_call(f, &d, q, hint, offset, need, &c, &v) == VOR_OK) &&
                         (ip_flatten(f, 1, &c, &v) == words) &&
                         test_same_bytes(ip_answer[0], ip_answer[1], words * sizeof(uint32_t)) &&
                         test_same_bytes(ip_scratch + offset + need, ip_scratch_before + offset + need,
                                         sizeof ip_scratch - offset - need);
                    answered++;
                } else if (err == VOR_OK) {
                    ok = false; /* every answer needs scratch: at a site, one neighbour */
                }
                ok = ok && test_same_bytes(ip_arena, ip_arena_before, sizeof ip_arena) &&
                     test_same_bytes(&d, &d_before, sizeof d) &&
                     test_same_bytes(ip_values, ip_values_before, sizeof ip_values);
                bad += ok ? 0u : 1u;
                CHECK(ok, "%s, %s scene, p = %u%%: query %u (%d, %d) hint %u: %d", calls[f], scenes[scene],
                      rate_percent, i, q.x, q.y, hint, err);
            }
        }
        test_printf("interpolation on the %s scene built at p = %u%%: %u answers, %u outside, %u needing "
                    "more than %u neighbours, %u bad\n",
                    scenes[scene], rate_percent, answered, outside, too_many, IP_MOST_K, bad);
        CHECK(answered >= 4u * (IP_QUERIES / 4u), "%s scene, p = %u%%: only %u answers", scenes[scene], rate_percent,
              answered);
    }
}

int main(void)
{
    vor_port_init();
    test_select(TEST_ONLY, TEST_MODE);
    static const uint32_t percents[] = {1, 10, 50};
    test_rng_t rng;
    test_rng_seed(&rng, 2026);
    for (uint32_t i = 0; i < SITES; i++) {
        points[i].x = test_rng_range(&rng, -1000000, 1000000);
        points[i].y = test_rng_range(&rng, -1000000, 1000000);
    }
    for (unsigned k = 0; k < 3u; k++) {
        /* one case per rate; the loop body is the case */
        if (!test_case_begin("faults/rate_%u", percents[k])) {
            continue;
        }
        test_rng_seed(&rng, 2027u + k); /* the same removals and moves when run alone */
        uint32_t rate = (uint32_t)(((uint64_t)percents[k] << 32) / 100u);
        vor_t d;
        static uint32_t dup[SITES];
        /* batch build */
        CHECK(vor_init(&d, arena, sizeof arena, SITES) == VOR_OK, "init");
        d.fault_rate = rate;
        d.fault_state = 0x9E3779B97F4A7C15ull + k;
        CHECK(vor_build(&d, points, SITES, NULL, dup) == VOR_OK, "build");
        uint32_t distinct = 0;
        for (uint32_t i = 0; i < SITES; i++) {
            distinct += (dup[i] == i) ? 1u : 0u;
        }
        check_topology(&d, "build of 10000 sites", percents[k], distinct);
        /* the divide-and-conquer builds: guards C1-C5, T1, T2 */
        for (unsigned split = VOR_DC_QUADTREE; split <= VOR_DC_XSPLIT; split++) {
            CHECK(vor_init(&d, arena, sizeof arena, SITES) == VOR_OK, "init");
            d.fault_rate = rate;
            d.fault_state = 0x2545F4914F6CDD1Dull + k * 3u + 2u - split;
            CHECK(vor_build_dc(&d, points, SITES, TEST_SPLIT(split), dup) == VOR_OK,
                  "d&c build");
            check_topology(&d, split == VOR_DC_XSPLIT ? "d&c build of 10000 sites"
                                                      : "d&c quadtree build of 10000 sites",
                           percents[k], distinct);
            /* degenerate input: a grid (collinear and cocircular sites) */
            static vor_point_t grid[2500];
            for (uint32_t i = 0; i < 2500u; i++) {
                grid[i].x = (int32_t)(i % 50u) * 7;
                grid[i].y = (int32_t)(i / 50u) * 7;
            }
            CHECK(vor_init(&d, arena, sizeof arena, SITES) == VOR_OK, "init");
            d.fault_rate = rate;
            d.fault_state = 0x9E3779B97F4A7C15ull ^ (k * 7u + 2u - split);
            CHECK(vor_build_dc(&d, grid, 2500, TEST_SPLIT(split), NULL) == VOR_OK,
                  "d&c grid build");
            check_topology(&d, "d&c build of a 50x50 grid", percents[k], 2500);
        }
        /* one by one: the dynamic path, with its duplicate search */
        CHECK(vor_init(&d, arena, sizeof arena, SITES) == VOR_OK, "init");
        d.fault_rate = rate;
        d.fault_state = 0x5851F42D4C957F2Dull + k;
        uint32_t inserted = 0;
        for (uint32_t i = 0; i < 3000u; i++) {
            int err = vor_insert(&d, (vor_point_t){points[i].x / 1000, points[i].y / 1000}, NULL);
            inserted += (err == VOR_OK) ? 1u : 0u;
            CHECK(err == VOR_OK || err == VOR_ERR_DUPLICATE, "insert %u: %d", i, err);
        }
        check_topology(&d, "3000 inserts (many degenerate)", percents[k], inserted);
        /* removals and moves on that mesh: the ear guard and the local
         * check must keep it a triangulation whatever the signs */
        uint32_t live = inserted;
        for (uint32_t i = 0; i < 1000u; i++) {
            int err = vor_remove(&d, test_rng_u32(&rng) % d.site_count);
            live -= (err == VOR_OK) ? 1u : 0u;
            CHECK(err == VOR_OK || err == VOR_ERR_ARG, "remove %u: %d", i, err);
        }
        check_topology(&d, "1000 removals", percents[k], live);
        /* with the motion cache: boxes sized from exact magnitudes, moves
         * inside them skip the (lying) predicates */
        static uint8_t motion[VOR_MOTION_BYTES(SITES)] __attribute__((aligned(4)));
        CHECK(vor_motion_attach(&d, motion, sizeof motion) == VOR_OK, "attach");
        for (uint32_t i = 0; i < 2000u; i++) {
            uint32_t site = test_rng_u32(&rng) % d.site_count;
            vor_point_t to = {test_rng_range(&rng, -1000, 1000), test_rng_range(&rng, -1000, 1000)};
            if (i % 2u == 0u && site < d.site_count) { /* a small step */
                to.x = d.sites[site].x + test_rng_range(&rng, -3, 3);
                to.y = d.sites[site].y + test_rng_range(&rng, -3, 3);
            }
            int err = vor_move(&d, site, to, NULL);
            CHECK(err == VOR_OK || err == VOR_ERR_ARG || err == VOR_ERR_DUPLICATE, "move %u: %d",
                  i, err);
        }
        check_topology(&d, "2000 moves", percents[k], live);
        for (uint32_t i = 0; i < 4000u; i++) { /* tiny steps: many inside their boxes */
            uint32_t site = test_rng_u32(&rng) % d.site_count;
            vor_point_t step = d.sites[site];
            step.x += test_rng_range(&rng, -1, 1);
            step.y += test_rng_range(&rng, -1, 1);
            int err = vor_move(&d, site, step, NULL);
            CHECK(err == VOR_OK || err == VOR_ERR_ARG || err == VOR_ERR_DUPLICATE, "move %u: %d",
                  i, err);
        }
        check_topology(&d, "4000 tiny moves with the motion cache", percents[k], live);
        /* every site removed: stars of every size, hull sites, and the
         * small meshes at the end */
        for (uint32_t id = 0; id < d.site_count; id++) {
            bool removed = vor_remove(&d, id) == VOR_OK;
            live -= removed ? 1u : 0u;
            if (removed && (live == 100u || live == 3u)) {
                check_topology(&d, live == 100u ? "removals down to 100" : "removals down to 3",
                               percents[k], live);
            }
        }
        check_topology(&d, "removals down to none", percents[k], live);
        /* a star beyond removal's arrays: a site inside 32 cocircular
         * sites (lattice points of x^2 + y^2 = 5525^2) */
        uint32_t found = 0, ring = 0;
        int32_t y = 5525;
        for (int32_t x = 0; x < 5525; x++) {
            while ((int64_t)y * y > 5525 * 5525 - (int64_t)x * x) {
                y--;
            }
            if ((int64_t)y * y == 5525 * 5525 - (int64_t)x * x && found++ % 6u == 0u) {
                ring += (vor_insert(&d, (vor_point_t){x, y}, NULL) == VOR_OK) ? 1u : 0u;
                ring += (vor_insert(&d, (vor_point_t){-y, x}, NULL) == VOR_OK) ? 1u : 0u;
                ring += (vor_insert(&d, (vor_point_t){-x, -y}, NULL) == VOR_OK) ? 1u : 0u;
                ring += (vor_insert(&d, (vor_point_t){y, -x}, NULL) == VOR_OK) ? 1u : 0u;
            }
        }
        uint32_t centre = 0;
        CHECK(vor_insert(&d, (vor_point_t){0, 0}, &centre) == VOR_OK && vor_remove(&d, centre) == VOR_OK,
              "ring centre");
        check_topology(&d, "a ring's centre removed", percents[k], ring);
        test_case_end();
    }
    for (unsigned k = 0; k < 3u; k++) {
        if (!test_case_begin("faults/cdt/rate_%u", percents[k])) {
            continue;
        }
        test_rng_seed(&rng, 3031u + k);
        uint32_t rate = (uint32_t)(((uint64_t)percents[k] << 32) / 100u);
        cdt_under_faults(rate, percents[k], k, false, &rng);
        cdt_under_faults(rate, percents[k], k, true, &rng);
        test_case_end();
    }
    for (unsigned k = 0; k < 3u; k++) {
        if (!test_case_begin("faults/power/rate_%u", percents[k])) {
            continue;
        }
        test_rng_seed(&rng, 4041u + k);
        uint32_t rate = (uint32_t)(((uint64_t)percents[k] << 32) / 100u);
        power_under_faults(rate, percents[k], k, &rng);
        test_case_end();
    }
    for (unsigned k = 0; k < 3u; k++) {
        if (!test_case_begin("faults/interpolate/rate_%u", percents[k])) {
            continue;
        }
        test_rng_seed(&rng, 5051u + k);
        uint32_t rate = (uint32_t)(((uint64_t)percents[k] << 32) / 100u);
        interpolate_under_faults(rate, percents[k], k, &rng);
        test_case_end();
    }
    return test_finish();
}
