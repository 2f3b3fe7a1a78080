/* SPDX-License-Identifier: MIT */
/*
 * examples/coverage - multi-robot coverage control (Lloyd's algorithm) on
 * the microcontroller: 64 robots start in a 20 m x 20 m corner of a 60 m x 40 m
 * arena; every step each robot's Voronoi cell is clipped to the arena, its
 * exact centroid computed (vor_cell_centroid), and the robot moved there
 * (vor_move). The robots spread out until each sits at the centroid of
 * its own cell: a centroidal Voronoi tessellation, which minimises the
 * coverage cost, the mean squared distance from a point of the arena to
 * its nearest robot.
 *
 * Prints, per step, the coverage cost (over a 1 m grid of sample points,
 * exact integer distances) and the instructions the step took on this
 * target (centroids and moves; the cost is not counted). At the end it
 * checks eight cells against a brute-force search: every sample point of
 * a 250 mm grid goes to its nearest robot by exhaustive search, and each
 * cell's sample mean must lie within a sample spacing of the exact
 * centroid. It writes the final cells to build/coverage.cells, which
 * `make coverage` turns into build/coverage.svg with `vor draw --cells`.
 * The last line is "N passed, N failed" (make test runs it on Cortex-M3).
 */
#include "example_io.h"
#include "port.h"
#include "vor.h"

#define ROBOTS 64u
#define STEPS 40u
#define WIDTH 60000  /* mm */
#define HEIGHT 40000 /* mm */
#define COST_SPACING 1000  /* mm between the cost's sample points */
#define CHECK_SPACING 250  /* mm between the brute-force check's samples */

static const vor_box_t arena_box = {0, 0, WIDTH, HEIGHT};
static uint8_t arena[VOR_ARENA_BYTES(ROBOTS)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(ROBOTS))];
static vor_point_t robot[ROBOTS];
static vor_point_t goal[ROBOTS];

/* Mean squared distance (mm^2) from the sample points (cell centres of a
 * COST_SPACING grid over the arena) to their nearest robot. Each query is
 * hinted with the previous answer: neighbouring samples are near. */
static uint64_t coverage_cost(const vor_t *d)
{
    uint64_t sum = 0, samples = 0;
    uint32_t hint = VOR_NO_HINT;
    for (int32_t y = COST_SPACING / 2; y < HEIGHT; y += COST_SPACING) {
        for (int32_t x = COST_SPACING / 2; x < WIDTH; x += COST_SPACING) {
            uint32_t site;
            if (vor_nearest(d, (vor_point_t){x, y}, hint, &site) != VOR_OK) {
                return UINT64_MAX;
            }
            int64_t dx = (int64_t)robot[site].x - x, dy = (int64_t)robot[site].y - y;
            sum += (uint64_t)(dx * dx + dy * dy); /* below 2^33 each */
            samples++;
            hint = site;
        }
    }
    return sum / samples;
}

/* One Lloyd step: every centroid from the current diagram first, then
 * every move. Returns 0, or the first library error. */
static int lloyd_step(vor_t *d)
{
    for (uint32_t i = 0; i < ROBOTS; i++) {
        vor_centroid_t c;
        int err = vor_cell_centroid(d, i, &arena_box, scratch, sizeof scratch, &c);
        if (err != VOR_OK) {
            return err;
        }
        goal[i] = c.point;
    }
    for (uint32_t i = 0; i < ROBOTS; i++) {
        uint32_t other;
        int err = vor_move(d, i, goal[i], &other);
        if (err == VOR_OK) {
            robot[i] = goal[i];
        } else if (err != VOR_ERR_DUPLICATE) { /* two goals met: stay */
            return err;
        }
    }
    return 0;
}

/* Eight cells against a brute-force search of the sample points. */
static void check_centroids(const vor_t *d)
{
    static int64_t sum_x[ROBOTS], sum_y[ROBOTS], count[ROBOTS];
    for (int32_t y = CHECK_SPACING / 2; y < HEIGHT; y += CHECK_SPACING) {
        for (int32_t x = CHECK_SPACING / 2; x < WIDTH; x += CHECK_SPACING) {
            uint32_t i = example_brute_nearest(robot, ROBOTS, NULL, x, y);
            sum_x[i] += x;
            sum_y[i] += y;
            count[i]++;
        }
    }
    for (uint32_t i = 0; i < ROBOTS; i += ROBOTS / 8u) {
        vor_centroid_t c;
        int ok = vor_cell_centroid(d, i, &arena_box, scratch, sizeof scratch, &c) == VOR_OK &&
                 count[i] > 0;
        if (ok) {
            int64_t mean_x = sum_x[i] / count[i], mean_y = sum_y[i] / count[i];
            int64_t dx = mean_x - c.point.x, dy = mean_y - c.point.y;
            ok = dx <= CHECK_SPACING && dx >= -CHECK_SPACING && dy <= CHECK_SPACING &&
                 dy >= -CHECK_SPACING &&
                 /* the area: one sample per CHECK_SPACING^2, within a ring */
                 (int64_t)c.area >= (count[i] - 400) * CHECK_SPACING * CHECK_SPACING &&
                 (int64_t)c.area <= (count[i] + 400) * CHECK_SPACING * CHECK_SPACING;
        }
        example_check(ok, "a centroid or area disagrees with the brute-force samples");
    }
}

int main(void)
{
    vor_port_init();
    example_print("vor: Lloyd coverage control of 64 robots in a 60 m x 40 m arena\n\n");
    uint32_t state = 20261125u;
    vor_t d;
    int err = vor_init(&d, arena, sizeof arena, ROBOTS);
    for (uint32_t i = 0; i < ROBOTS && err == VOR_OK; i++) {
        /* all in the 20 m x 20 m corner at the start */
        robot[i].x = (int32_t)(example_random(&state) % 20000u);
        robot[i].y = (int32_t)(example_random(&state) % 20000u);
        uint32_t id;
        err = vor_insert(&d, robot[i], &id);
        if (err == VOR_ERR_DUPLICATE) { /* draw again */
            i--;
            err = VOR_OK;
        }
    }
    example_check(err == VOR_OK, "vor_init or vor_insert failed");
    if (err != VOR_OK) {
        return 1;
    }
    uint64_t first = coverage_cost(&d), cost = first, previous = first;
    example_print("step  0: cost ");
    example_print_uint(cost);
    example_print(" mm^2\n");
    int monotone = 1;
    for (uint32_t step = 1; step <= STEPS; step++) {
        uint64_t start = vor_port_counter();
        err = lloyd_step(&d);
        uint64_t spent = vor_port_counter() - start;
        example_check(err == 0, "a Lloyd step failed");
        if (err != 0) {
            break;
        }
        cost = coverage_cost(&d);
        /* Lloyd never raises the continuous cost; the sampled one may
         * wobble by a sampling error once the robots have settled */
        monotone &= cost <= previous + previous / 100u;
        previous = cost;
        example_print(step < 10u ? "step  " : "step ");
        example_print_uint(step);
        example_print(": cost ");
        example_print_uint(cost);
        example_print(" mm^2, ");
        example_print_uint(spent);
        example_print(" ");
        example_print(vor_port_counter_unit);
        example_print(" (");
        example_print_uint(spent / ROBOTS);
        example_print(" per robot)\n");
    }
    example_check(monotone, "the coverage cost rose");
    example_check(cost * 10u < first, "the coverage cost did not fall tenfold");
    vor_violation_t violation;
    example_check(vor_validate(&d, &violation) == VOR_OK, "vor_validate failed");
    check_centroids(&d);
    int32_t cells = example_dump_cells("build/coverage.cells", &d, robot, ROBOTS, &arena_box);
    example_check(cells == (int32_t)ROBOTS, "the cells could not be written");
    example_print("\ncells:   build/coverage.cells (make coverage draws build/coverage.svg)\n");
    return example_print_tally();
}
