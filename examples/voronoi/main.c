/*
 * examples/voronoi - the main job (`make demo`): a Voronoi diagram of 2,000
 * sites built on the microcontroller itself, in a static arena.
 *
 * Copy from here: reserve the arena with VOR_ARENA_BYTES at compile time,
 * vor_init, vor_build, then query. Nothing is allocated; a too-small arena
 * is caught by the static assertion below rather than at run time.
 */
#include "port.h"
#include "vor.h"

#define SITES 2000u

static vor_point_t sites[SITES];
static uint32_t first_of[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
typedef char arena_is_big_enough[(sizeof arena >= VOR_ARENA_BYTES(SITES)) ? 1 : -1];

/* Output without a C library. */
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

static void print_int(int32_t v)
{
    if (v < 0) {
        print("-");
        print_uint((uint64_t)(-(int64_t)v));
    } else {
        print_uint((uint64_t)v);
    }
}

/* A deterministic generator (xorshift32): the same sites on every run. */
static uint32_t random_state = 2463534242u;
static uint32_t next_random(void)
{
    random_state ^= random_state << 13;
    random_state ^= random_state >> 17;
    random_state ^= random_state << 5;
    return random_state;
}

/* Sites in millimetres on a 100 m x 100 m floor: integers already. */
static int32_t coordinate(void)
{
    return (int32_t)(next_random() % 100000u) - 50000;
}

static uint32_t brute_force_nearest(int32_t x, int32_t y)
{
    uint32_t best = 0;
    uint64_t best_d = UINT64_MAX;
    for (uint32_t i = 0; i < SITES; i++) {
        int64_t dx = (int64_t)sites[i].x - x, dy = (int64_t)sites[i].y - y;
        uint64_t d = (uint64_t)(dx * dx + dy * dy);
        if (first_of[i] == i && d < best_d) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

int main(void)
{
    vor_port_init();
    for (uint32_t i = 0; i < SITES; i++) {
        sites[i].x = coordinate();
        sites[i].y = coordinate();
    }
    print("vor: Voronoi diagram of 2000 sites on this microcontroller\n\n");

    vor_t diagram;
    int err = vor_init(&diagram, arena, sizeof arena, SITES);
    uint64_t start = vor_port_counter();
    if (err == VOR_OK) {
        err = vor_build(&diagram, sites, SITES, NULL, first_of);
    }
    uint64_t spent = vor_port_counter() - start;
    if (err != VOR_OK) {
        print("build failed\n");
        return 1;
    }
    print("build:     ");
    print_uint(diagram.vertex_count);
    print(" sites (");
    print_uint(SITES - diagram.vertex_count);
    print(" duplicates) in ");
    print_uint(spent);
    print(" ");
    print(vor_port_counter_unit);
    print(", ");
    print_uint(spent / SITES);
    print(" per site\n");

    vor_violation_t violation;
    err = vor_validate(&diagram, &violation);
    print("validate:  ");
    print(err == VOR_OK ? "every invariant holds (topology, orientation, Delaunay)\n"
                        : "FAILED\n");

    vor_memory_t memory;
    vor_memory(&diagram, &memory);
    print("memory:    ");
    print_uint(memory.used_bytes);
    print(" bytes in use of a ");
    print_uint(memory.arena_bytes);
    print("-byte static arena, ");
    print_uint(memory.bytes_per_site_x100 / 100u);
    print(".");
    print_uint(memory.bytes_per_site_x100 % 100u / 10u);
    print_uint(memory.bytes_per_site_x100 % 10u);
    print(" bytes per site, ");
    print_uint(memory.triangles);
    print(" triangles\n");

    /* a robot crossing the floor: each answer is the hint for the next */
    uint32_t hint = VOR_NO_HINT, wrong = 0;
    print("nearest:   ");
    start = vor_port_counter();
    for (int32_t step = 0; step <= 4; step++) {
        int32_t x = -40000 + step * 20000, y = 12345 - step * 7000;
        uint32_t site;
        err = vor_nearest(&diagram, x, y, hint, &site);
        wrong += (err != VOR_OK || site != brute_force_nearest(x, y)) ? 1u : 0u;
        hint = site;
        print("(");
        print_int(x);
        print(", ");
        print_int(y);
        print(") -> site ");
        print_uint(site);
        print(step < 4 ? "; " : "\n");
    }
    print("           all five checked against a brute-force search: ");
    print(wrong == 0 ? "agree\n" : "DISAGREE\n");
    return (err == VOR_OK && wrong == 0) ? 0 : 1;
}
