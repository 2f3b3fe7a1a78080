/*
 * examples/voronoi - the main job (`make demo`): a Voronoi diagram of 2,000
 * sites built on the microcontroller itself, in a static arena.
 *
 * Copy from here: reserve the arena with VOR_ARENA_BYTES at compile time,
 * vor_init, vor_build, then query. Nothing is allocated; a too-small arena
 * is caught by the static assertion below rather than at run time.
 */
#include "example_io.h"
#include "port.h"
#include "vor.h"

#define SITES 2000u

static vor_point_t sites[SITES];
static uint32_t first_of[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
typedef char arena_is_big_enough[(sizeof arena >= VOR_ARENA_BYTES(SITES)) ? 1 : -1];

static uint32_t random_state = 2463534242u;

/* Sites in millimetres on a 100 m x 100 m floor: integers already. */
static int32_t coordinate(void)
{
    return (int32_t)(example_random(&random_state) % 100000u) - 50000;
}


int main(void)
{
    vor_port_init();
    for (uint32_t i = 0; i < SITES; i++) {
        sites[i].x = coordinate();
        sites[i].y = coordinate();
    }
    example_print("vor: Voronoi diagram of 2000 sites on this microcontroller\n\n");

    vor_t diagram;
    int err = vor_init(&diagram, arena, sizeof arena, SITES);
    uint64_t start = vor_port_counter();
    if (err == VOR_OK) {
        err = vor_build(&diagram, sites, SITES, NULL, first_of);
    }
    uint64_t spent = vor_port_counter() - start;
    if (err != VOR_OK) {
        example_print("build failed\n");
        return 1;
    }
    example_print("build:     ");
    example_print_uint(diagram.vertex_count);
    example_print(" sites (");
    example_print_uint(SITES - diagram.vertex_count);
    example_print(" duplicates) in ");
    example_print_uint(spent);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print(", ");
    example_print_uint(spent / SITES);
    example_print(" per site\n");

    vor_violation_t violation;
    err = vor_validate(&diagram, &violation);
    example_print("validate:  ");
    example_print(err == VOR_OK ? "every invariant holds (topology, orientation, Delaunay)\n"
                        : "FAILED\n");

    vor_memory_t memory;
    vor_memory(&diagram, &memory);
    example_print("memory:    ");
    example_print_uint(memory.used_bytes);
    example_print(" bytes in use of a ");
    example_print_uint(memory.arena_bytes);
    example_print("-byte static arena, ");
    example_print_uint(memory.bytes_per_site_x100 / 100u);
    example_print(".");
    example_print_uint(memory.bytes_per_site_x100 % 100u / 10u);
    example_print_uint(memory.bytes_per_site_x100 % 10u);
    example_print(" bytes per site, ");
    example_print_uint(memory.triangles);
    example_print(" triangles\n");

    /* a robot crossing the floor: each answer is the hint for the next */
    uint32_t hint = VOR_NO_HINT, wrong = 0;
    example_print("nearest:   ");
    start = vor_port_counter();
    for (int32_t step = 0; step <= 4; step++) {
        int32_t x = -40000 + step * 20000, y = 12345 - step * 7000;
        uint32_t site;
        err = vor_nearest(&diagram, x, y, hint, &site);
        wrong += (err != VOR_OK || site != example_brute_nearest(sites, SITES, first_of, x, y)) ? 1u : 0u;
        hint = site;
        example_print("(");
        example_print_int(x);
        example_print(", ");
        example_print_int(y);
        example_print(") -> site ");
        example_print_uint(site);
        example_print(step < 4 ? "; " : "\n");
    }
    example_print("           all five checked against a brute-force search: ");
    example_print(wrong == 0 ? "agree\n" : "DISAGREE\n");
    return (err == VOR_OK && wrong == 0) ? 0 : 1;
}
