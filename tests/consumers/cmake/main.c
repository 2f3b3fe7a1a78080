/* SPDX-License-Identifier: MIT */
/*
 * main.c - a program that uses vor the way a CMake user does (through
 * vor::vor from add_subdirectory or find_package) and checks that it got
 * a working library: nearest sites against brute force, and the
 * configuration the build passed on. Ends with "N passed, N failed".
 */
#include "vor.h"

#include "test.h"

enum { SITE_COUNT = 300, QUERY_COUNT = 2000, SPAN = 1 << 20 };

static vor_point_t points[SITE_COUNT];
static uint32_t duplicate_of[SITE_COUNT];
static uint32_t arena[VOR_ARENA_BYTES(SITE_COUNT) / sizeof(uint32_t) + 1];

static uint64_t distance_squared(vor_point_t site, int32_t x, int32_t y)
{
    int64_t dx = (int64_t)site.x - x;
    int64_t dy = (int64_t)site.y - y;
    return (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
}

int main(void)
{
    test_rng_t rng;
    vor_t diagram;
    uint32_t i;

    vor_port_init();
    /* The build's option reached this program: vor.h sees the value the
     * consumer's CMakeLists.txt asked the package for. */
    CHECK(VOR_INDEX_BITS == CONSUMER_EXPECTED_INDEX_BITS, "VOR_INDEX_BITS %d, expected %d",
          VOR_INDEX_BITS, CONSUMER_EXPECTED_INDEX_BITS);

    test_rng_seed(&rng, 12);
    for (i = 0; i < SITE_COUNT; i++) {
        points[i].x = test_rng_range(&rng, -SPAN, SPAN);
        points[i].y = test_rng_range(&rng, -SPAN, SPAN);
    }
    CHECK(vor_init(&diagram, arena, sizeof arena, SITE_COUNT) == VOR_OK, "vor_init");
    CHECK(vor_build(&diagram, points, SITE_COUNT, NULL, duplicate_of) == VOR_OK, "vor_build");

    /* A library compiled with other options than this program would lay
     * out vor_t and the arena differently, and these answers would not
     * match the brute-force ones. */
    for (i = 0; i < QUERY_COUNT; i++) {
        int32_t x = test_rng_range(&rng, -SPAN - SPAN / 4, SPAN + SPAN / 4);
        int32_t y = test_rng_range(&rng, -SPAN - SPAN / 4, SPAN + SPAN / 4);
        uint32_t site = VOR_NO_HINT;
        uint32_t best = 0;
        uint32_t j;
        for (j = 1; j < SITE_COUNT; j++) {
            if (distance_squared(points[j], x, y) < distance_squared(points[best], x, y)) {
                best = j;
            }
        }
        CHECK(vor_nearest(&diagram, (vor_point_t){x, y}, VOR_NO_HINT, &site) == VOR_OK && site < SITE_COUNT &&
                  distance_squared(points[site], x, y) == distance_squared(points[best], x, y),
              "query (%d, %d): site %u, brute force %u", (int)x, (int)y, (unsigned)site,
              (unsigned)best);
    }
    test_summary();
    vor_port_exit(test_failures() == 0 ? 0 : 1);
}
