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

/* The L-shaped hall, counterclockwise, and its robots. */
#define ROOM_ROBOTS 32u
#define ROOM_STEPS 30u
#define ROOM_VERTICES 6u
static const vor_point_t room[ROOM_VERTICES] = {
    {0, 0}, {WIDTH, 0}, {WIDTH, HEIGHT / 2}, {WIDTH / 2, HEIGHT / 2}, {WIDTH / 2, HEIGHT}, {0, HEIGHT}};
static uint8_t room_arena[VOR_ARENA_BYTES(ROOM_ROBOTS)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t clip_scratch[VOR_CLIP_SCRATCH_BYTES(ROOM_VERTICES, ROOM_ROBOTS)];
static uint8_t sums[VOR_CLIP_CENTROID_SCRATCH_BYTES(ROOM_VERTICES, ROOM_ROBOTS)];
static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(ROOM_VERTICES, ROOM_ROBOTS)];

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

/* Is p in the closed L (a winding number over its edges)? */
static bool in_room(vor_point_t p)
{
    int winding = 0;
    for (uint32_t k = 0; k < ROOM_VERTICES; k++) {
        vor_point_t a = room[k], b = room[(k + 1u) % ROOM_VERTICES];
        int64_t o = ((int64_t)b.x - a.x) * ((int64_t)p.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)p.x - a.x);
        bool within = (p.x >= (a.x < b.x ? a.x : b.x)) && (p.x <= (a.x < b.x ? b.x : a.x)) &&
                      (p.y >= (a.y < b.y ? a.y : b.y)) && (p.y <= (a.y < b.y ? b.y : a.y));
        if (o == 0 && within) {
            return true;
        }
        if (a.y <= p.y && b.y > p.y && o > 0) {
            winding++;
        } else if (b.y <= p.y && a.y > p.y && o < 0) {
            winding--;
        } else {
            /* no crossing */
        }
    }
    return winding != 0;
}

/* Where robot i goes: the centroid of its clipped cell if it is in the
 * L, else its largest piece's if that is, else where it is. */
static int room_goal(const vor_t *d, uint32_t i, vor_point_t *to, vor_centroid_t *whole)
{
    vor_clip_t clip;
    int err = vor_clip_begin(&clip, d, i, room, ROOM_VERTICES, clip_scratch, sizeof clip_scratch);
    if (err == VOR_OK) {
        err = vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, whole);
    }
    *to = robot[i];
    if (err != VOR_OK || whole->area == 0u) {
        return err;
    }
    if (in_room(whole->point)) {
        *to = whole->point;
        return VOR_OK;
    }
    vor_centroid_t best = {{0, 0}, 0, 0};
    for (uint32_t k = 0; k < clip.pieces; k++) {
        vor_centroid_t c;
        err = vor_clip_centroid(&clip, k, sums, sizeof sums, &c);
        if (err != VOR_OK) {
            return err;
        }
        best = (c.area > best.area) ? c : best;
    }
    if (in_room(best.point)) {
        *to = best.point;
    }
    return VOR_OK;
}

/* Mean squared distance from the COST_SPACING samples inside the L to
 * their nearest robot. */
static uint64_t room_cost(const vor_t *d)
{
    uint64_t sum = 0, samples = 0;
    uint32_t hint = VOR_NO_HINT;
    for (int32_t y = COST_SPACING / 2; y < HEIGHT; y += COST_SPACING) {
        for (int32_t x = COST_SPACING / 2; x < WIDTH; x += COST_SPACING) {
            uint32_t site;
            if (!in_room((vor_point_t){x, y})) {
                continue;
            }
            if (vor_nearest(d, (vor_point_t){x, y}, hint, &site) != VOR_OK) {
                return UINT64_MAX;
            }
            int64_t dx = (int64_t)robot[site].x - x, dy = (int64_t)robot[site].y - y;
            sum += (uint64_t)(dx * dx + dy * dy);
            samples++;
            hint = site;
        }
    }
    return sum / samples;
}

/* Lloyd in the L, checked as in the box; its pieces dumped. */
static void room_coverage(void)
{
    static int64_t sum_x[ROOM_ROBOTS], sum_y[ROOM_ROBOTS], count[ROOM_ROBOTS];
    example_print("\nvor: Lloyd coverage control of 32 robots in an L-shaped hall\n\n");
    uint32_t state = 20261128u;
    vor_t d;
    int err = vor_init(&d, room_arena, sizeof room_arena, ROOM_ROBOTS);
    for (uint32_t i = 0; i < ROOM_ROBOTS && err == VOR_OK; i++) {
        /* all in the 20 m x 20 m lower left corner */
        robot[i].x = (int32_t)(example_random(&state) % 20000u);
        robot[i].y = (int32_t)(example_random(&state) % 20000u);
        uint32_t id;
        err = vor_insert(&d, robot[i], &id);
        if (err == VOR_ERR_DUPLICATE) {
            i--;
            err = VOR_OK;
        }
    }
    example_check(err == VOR_OK, "the hall: vor_init or vor_insert failed");
    if (err != VOR_OK) {
        return;
    }
    uint64_t first = room_cost(&d), cost = first;
    for (uint32_t step = 1; step <= ROOM_STEPS && err == VOR_OK; step++) {
        uint64_t start = vor_port_counter();
        vor_centroid_t whole;
        for (uint32_t i = 0; i < ROOM_ROBOTS && err == VOR_OK; i++) {
            err = room_goal(&d, i, &goal[i], &whole);
        }
        for (uint32_t i = 0; i < ROOM_ROBOTS && err == VOR_OK; i++) {
            uint32_t other;
            err = vor_move(&d, i, goal[i], &other);
            if (err == VOR_OK) {
                robot[i] = goal[i];
            } else if (err == VOR_ERR_DUPLICATE) {
                err = VOR_OK;
            } else {
                /* a library error: reported below */
            }
        }
        uint64_t spent = vor_port_counter() - start;
        cost = room_cost(&d);
        if (step == 1u || step % 10u == 0u) {
            example_print(step < 10u ? "step  " : "step ");
            example_print_uint(step);
            example_print(": cost ");
            example_print_uint(cost);
            example_print(" mm^2, ");
            example_print_uint(spent / ROOM_ROBOTS);
            example_print(" ");
            example_print(vor_port_counter_unit);
            example_print(" per robot\n");
        }
    }
    example_check(err == VOR_OK, "the hall: a Lloyd step failed");
    example_check(cost * 5u < first, "the hall: the coverage cost did not fall fivefold");
    for (uint32_t i = 0; i < ROOM_ROBOTS; i++) {
        example_check(in_room(robot[i]), "the hall: a robot left the L");
    }
    /* eight cells against the samples of the L nearest to each robot */
    for (int32_t y = CHECK_SPACING / 2; y < HEIGHT; y += CHECK_SPACING) {
        for (int32_t x = CHECK_SPACING / 2; x < WIDTH; x += CHECK_SPACING) {
            if (in_room((vor_point_t){x, y})) {
                uint32_t i = example_brute_nearest(robot, ROOM_ROBOTS, NULL, x, y);
                sum_x[i] += x;
                sum_y[i] += y;
                count[i]++;
            }
        }
    }
    for (uint32_t i = 0; i < ROOM_ROBOTS; i += ROOM_ROBOTS / 8u) {
        vor_clip_t clip;
        vor_centroid_t c;
        bool ok = vor_clip_begin(&clip, &d, i, room, ROOM_VERTICES, clip_scratch, sizeof clip_scratch) ==
                      VOR_OK &&
                  vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, &c) == VOR_OK &&
                  count[i] > 0;
        if (ok) {
            int64_t dx = sum_x[i] / count[i] - c.point.x, dy = sum_y[i] / count[i] - c.point.y;
            ok = dx <= CHECK_SPACING && dx >= -CHECK_SPACING && dy <= CHECK_SPACING &&
                 dy >= -CHECK_SPACING &&
                 (int64_t)c.area >= (count[i] - 400) * CHECK_SPACING * CHECK_SPACING &&
                 (int64_t)c.area <= (count[i] + 400) * CHECK_SPACING * CHECK_SPACING;
        }
        example_check(ok, "the hall: a centroid or area disagrees with the brute-force samples");
    }
    /* the pieces, for vor draw --cells */
    static example_file_t dump;
    example_file_open(&dump, "build/coverage-room.cells");
    example_file_text(&dump, "box");
    example_file_int(&dump, 0), example_file_int(&dump, 0);
    example_file_int(&dump, WIDTH), example_file_int(&dump, HEIGHT);
    for (uint32_t i = 0; i < ROOM_ROBOTS; i++) {
        example_file_text(&dump, "\ns");
        example_file_int(&dump, robot[i].x), example_file_int(&dump, robot[i].y);
    }
    uint32_t pieces = 0;
    for (uint32_t i = 0; i < ROOM_ROBOTS; i++) {
        vor_clip_t clip;
        uint32_t k;
        if (vor_clip_begin(&clip, &d, i, room, ROOM_VERTICES, clip_scratch, sizeof clip_scratch) != VOR_OK) {
            continue;
        }
        while (vor_clip_next(&clip, piece, VOR_CLIP_MAX_VERTICES(ROOM_VERTICES, ROOM_ROBOTS), &k)) {
            example_file_text(&dump, "\nc");
            example_file_int(&dump, (int32_t)i), example_file_int(&dump, (int32_t)k);
            for (uint32_t v = 0; v < k; v++) {
                example_file_int(&dump, piece[v].point.x), example_file_int(&dump, piece[v].point.y);
            }
            pieces++;
        }
    }
    example_file_text(&dump, "\n");
    example_file_close(&dump);
    example_check(pieces >= ROOM_ROBOTS, "the hall: the pieces could not be written");
    example_print("\ncells:   build/coverage-room.cells (make coverage draws build/coverage-room.svg)\n");
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
    room_coverage();
    return example_print_tally();
}
