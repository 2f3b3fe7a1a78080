/*
 * examples/robot_nearest - a robot driving through 500 beacons asks, at
 * every one of 100,000 steps, which beacon is nearest. Each answer is the
 * hint for the next query, so a query costs a few distance comparisons.
 *
 * Run it on the emulated Cortex-M3 with
 *     make PORT=cortex-m3 run-example-robot_nearest
 * (or on the host: make run-example-robot_nearest).
 *
 * Coordinates are millimetres on a 200 m x 200 m floor, int32 already: the
 * robot's position is integrated in Q16.16 millimetres and shifted down,
 * the "integer reduction" vor expects from its callers.
 */
#include "port.h"
#include "vor.h"

#define BEACONS 500u
#define STEPS 100000u

static vor_point_t beacons[BEACONS];
static uint8_t arena[VOR_ARENA_BYTES(BEACONS)] __attribute__((aligned(VOR_ARENA_ALIGN)));

static void print(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0') {
        n++;
    }
    vor_port_write(s, n);
}

static void print_uint(uint64_t v)
{
    char buf[24];
    size_t n = sizeof buf;
    do {
        buf[--n] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    vor_port_write(buf + n, sizeof buf - n);
}

static uint32_t random_state = 88675123u;
static uint32_t next_random(void)
{
    random_state ^= random_state << 13;
    random_state ^= random_state >> 17;
    random_state ^= random_state << 5;
    return random_state;
}

/* The nearest beacon by brute force (exact: differences below 2^31). */
static uint32_t brute_force(int32_t x, int32_t y)
{
    uint32_t best = 0;
    uint64_t best_d = UINT64_MAX;
    for (uint32_t i = 0; i < BEACONS; i++) {
        int64_t dx = (int64_t)beacons[i].x - x, dy = (int64_t)beacons[i].y - y;
        uint64_t d = (uint64_t)(dx * dx + dy * dy);
        if (d < best_d) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

int main(void)
{
    vor_port_init();
    for (uint32_t i = 0; i < BEACONS; i++) {
        beacons[i].x = (int32_t)(next_random() % 200000u) - 100000;
        beacons[i].y = (int32_t)(next_random() % 200000u) - 100000;
    }
    vor_t map;
    if (vor_init(&map, arena, sizeof arena, BEACONS) != VOR_OK ||
        vor_build(&map, beacons, BEACONS, NULL, NULL) != VOR_OK) {
        print("building the beacon map failed\n");
        return 1;
    }

    /* a robot on a wandering course: Q16.16 millimetres, 12 mm a step */
    int64_t x = 0, y = 0;
    int32_t heading_x = 12 << 16, heading_y = 0;
    uint32_t hint = VOR_NO_HINT, changes = 0, checked = 0, wrong = 0, answer = 0;
    uint64_t spent = 0;
    for (uint32_t step = 0; step < STEPS; step++) {
        /* turn a little, now and then, and bounce off the walls */
        if (step % 64u == 0u) {
            int32_t turn = (int32_t)(next_random() % 9u) - 4;
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

        uint64_t start = vor_port_counter();
        int err = vor_nearest(&map, px, py, hint, &answer);
        spent += vor_port_counter() - start;
        if (err != VOR_OK) {
            print("query failed\n");
            return 1;
        }
        changes += (answer != hint) ? 1u : 0u;
        hint = answer;
        if (step % 997u == 0u) { /* spot checks against brute force */
            checked++;
            wrong += (answer != brute_force(px, py)) ? 1u : 0u;
        }
    }
    print("robot: 500 beacons, 100000 steps, nearest beacon at every step\n");
    print("        nearest beacon changed ");
    print_uint(changes);
    print(" times; ");
    print_uint(checked);
    print(" spot checks against brute force: ");
    print(wrong == 0 ? "all agree\n" : "DISAGREE\n");
    print("        ");
    print_uint(spent / STEPS);
    print(" ");
    print(vor_port_counter_unit);
    print(" per query (the counter's own reads included)\n");
    return wrong == 0 ? 0 : 1;
}
