/* SPDX-License-Identifier: MIT */
/*
 * examples/robot_nearest - a robot driving through 500 beacons asks, at
 * every one of 100,000 steps, which beacon is nearest. A vor_tracker_t
 * keeps the current beacon's Voronoi cell as a few bisector tests, so
 * while the robot stays in the cell a query is a handful of multiplies.
 * For comparison, every step is also asked of vor_nearest with the last
 * answer as the hint (the stateless way, a short walk through the mesh).
 *
 * Run it on the emulated Cortex-M3 with
 *     make PORT=cortex-m3 run-example-robot_nearest
 * (or on the host: make run-example-robot_nearest).
 *
 * Coordinates are millimetres on a 200 m x 200 m floor, int32 already: the
 * robot's position is integrated in Q16.16 millimetres and shifted down,
 * the "integer reduction" vor expects from its callers.
 */
#include "example_io.h"
#include "port.h"
#include "vor.h"

#define BEACONS 500u
#define STEPS 100000u

static vor_point_t beacons[BEACONS];
static uint8_t arena[VOR_ARENA_BYTES(BEACONS)] __attribute__((aligned(VOR_ARENA_ALIGN)));

static uint32_t random_state = 88675123u;

int main(void)
{
    vor_port_init();
    for (uint32_t i = 0; i < BEACONS; i++) {
        beacons[i].x = (int32_t)(example_random(&random_state) % 200000u) - 100000;
        beacons[i].y = (int32_t)(example_random(&random_state) % 200000u) - 100000;
    }
    vor_t map;
    vor_tracker_t tracker;
    if (vor_init(&map, arena, sizeof arena, BEACONS) != VOR_OK ||
        vor_build(&map, beacons, BEACONS, NULL, NULL) != VOR_OK ||
        vor_tracker_begin(&tracker, &map) != VOR_OK) {
        example_print("building the beacon map failed\n");
        return 1;
    }

    /* a robot on a wandering course: Q16.16 millimetres, 12 mm a step */
    int64_t x = 0, y = 0;
    int32_t heading_x = 12 << 16, heading_y = 0;
    uint32_t hint = VOR_NO_HINT, changes = 0, checked = 0, wrong = 0, answer = 0, hinted = 0;
    uint64_t spent = 0, spent_hinted = 0;
    for (uint32_t step = 0; step < STEPS; step++) {
        /* turn a little, now and then, and bounce off the walls */
        if (step % 64u == 0u) {
            int32_t turn = (int32_t)(example_random(&random_state) % 9u) - 4;
            int32_t hx = heading_x - (heading_y >> 6) * turn;
            heading_y += (heading_x >> 6) * turn;
            heading_x = hx;
        }
        if ((x >> 16) > 95000 || (x >> 16) < -95000) {
            heading_x = -heading_x;
        }
        if ((y >> 16) > 95000 || (y >> 16) < -95000) {
            heading_y = -heading_y;
        }
        x += heading_x;
        y += heading_y;
        int32_t px = (int32_t)(x >> 16), py = (int32_t)(y >> 16);
        vor_point_t robot = {px, py};

        uint64_t start = vor_port_counter();
        int err = vor_track(&tracker, robot, &answer);
        spent += vor_port_counter() - start;
        start = vor_port_counter();
        err |= vor_nearest(&map, robot, hint, &hinted);
        spent_hinted += vor_port_counter() - start;
        if (err != VOR_OK || hinted != answer) {
            example_print("query failed\n");
            return 1;
        }
        changes += (answer != hint) ? 1u : 0u;
        hint = answer;
        if (step % 997u == 0u) { /* spot checks against brute force */
            checked++;
            wrong += (answer != example_brute_nearest(beacons, BEACONS, NULL, px, py)) ? 1u : 0u;
        }
    }
    /* what the two counter reads around a query cost by themselves */
    uint64_t idle = 0;
    for (uint32_t i = 0; i < STEPS; i++) {
        uint64_t start = vor_port_counter();
        idle += vor_port_counter() - start;
    }
    example_print("robot: 500 beacons, 100000 steps, nearest beacon at every step\n");
    example_print("        nearest beacon changed ");
    example_print_uint(changes);
    example_print(" times; ");
    example_print_uint(checked);
    example_print(" spot checks against brute force: ");
    example_print(wrong == 0 ? "all agree\n" : "DISAGREE\n");
    example_print("        vor_track: ");
    example_print_uint((spent - idle) / STEPS);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print(" per query; vor_nearest with the last answer as hint: ");
    example_print_uint((spent_hinted - idle) / STEPS);
    example_print(" (both agree at every step)\n        the counter's own reads, ");
    example_print_uint(idle / STEPS);
    example_print(" a query, are taken off both\n");
    return wrong == 0 ? 0 : 1;
}
