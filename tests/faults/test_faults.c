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
 */
#include "test.h"
#include "vor.h"

#ifndef VOR_FAULT_INJECTION
#error "build with -DVOR_FAULT_INJECTION"
#endif

#define SITES 10000u

static vor_point_t points[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(8)));

static const char *const check_names[] = {"counts", "vertices", "neighbours", "sites",
                                          "orientation", "delaunay"};

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
    return test_finish();
}
