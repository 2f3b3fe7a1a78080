/* SPDX-License-Identifier: MIT */
/*
 * examples/voronoi - the main job (`make demo`): a Voronoi diagram of 2,000
 * sites built on the microcontroller itself, in a static arena.
 *
 * Copy from here: reserve the arena with VOR_ARENA_BYTES at compile time,
 * vor_init, vor_build, then query. Nothing is allocated; a too-small arena
 * is caught by the static assertion below rather than at run time.
 *
 * For the host it streams a raster frame (build/demo.rgb565) and its cells
 * clipped to the floor, as text (build/demo.cells, for `vor draw --cells`),
 * through semihosting files.
 */
#include "example_io.h"
#include "port.h"
#include "vor.h"
#include "vor_raster.h"

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


/* ---- the frame: 320x240 RGB565 in 16-row bands, streamed to the host */

#define FRAME_W 320u
#define FRAME_H 240u
#define BAND_ROWS 16u
#define FRAME_SITES 256u

static uint16_t band[BAND_ROWS * FRAME_W];
static uint16_t colours[FRAME_SITES];
static uint8_t raster_work[VOR_RASTER_WORK_BYTES(FRAME_SITES, FRAME_W)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));

typedef struct stream {
    int file;
    uint32_t checked, wrong;
    uint64_t spent; /* counter ticks inside send_band */
} stream_t;

/* Each band goes to the host file; a few pixels per band are checked
 * against a brute-force search of the same sites. */
static int send_band(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    stream_t *s = user;
    const uint16_t *px = pixels;
    uint64_t start = vor_port_counter();
    for (uint32_t r = 0; r < rows; r++) {
        uint32_t i = (first_row + r) * 37u % FRAME_W, j = first_row + r;
        uint32_t want = example_brute_nearest(sites, FRAME_SITES, NULL, -49844 + (int32_t)i * 312,
                                              -49792 + (int32_t)j * 416);
        s->wrong += px[r * FRAME_W + i] != colours[want] ? 1u : 0u;
        s->checked++;
    }
    if (s->file >= 0) {
        (void)vor_port_file_write(s->file, pixels, rows * FRAME_W * sizeof(uint16_t));
    }
    s->spent += vor_port_counter() - start;
    return 0;
}

static int render_frame(void)
{
    for (uint32_t k = 0; k < FRAME_SITES; k++) { /* light RGB565 colours */
        uint32_t h = (k + 1u) * 2654435761u;
        colours[k] = (uint16_t)(((0x10u | (h >> 28)) << 11) | ((0x20u | ((h >> 22) & 0x1Fu)) << 5) |
                                (0x10u | ((h >> 17) & 0x0Fu)));
    }
    /* the 100 m floor over 320x240 pixels: 312 mm by 416 mm each */
    vor_raster_frame_t frame = {-49844, -49792, 312, 416, FRAME_W, FRAME_H};
    vor_raster_sites_t set = {.metric = VOR_METRIC_EUCLID, .points = sites, .count = FRAME_SITES};
    stream_t stream = {vor_port_file_open("build/demo.rgb565"), 0, 0, 0};
    vor_raster_output_t out = {VOR_RASTER_RGB565, band, sizeof band, BAND_ROWS, send_band,
                               &stream, colours, NULL, NULL};
    uint64_t start = vor_port_counter();
    int err = vor_raster(&frame, &set, &out, NULL, raster_work, sizeof raster_work);
    uint64_t spent = vor_port_counter() - start - stream.spent;
    if (stream.file >= 0) {
        (void)vor_port_file_close(stream.file);
    }
    example_print("raster:    320x240 RGB565 frame of the first 256 sites in 16-row bands: ");
    example_print_uint(spent * 10u / (FRAME_W * FRAME_H) / 10u);
    example_print(".");
    example_print_uint(spent * 10u / (FRAME_W * FRAME_H) % 10u);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print(" per pixel (streaming and checks excluded), ");
    example_print_uint(sizeof band + sizeof raster_work);
    example_print(" bytes of RAM\n           ");
    example_print_uint(stream.checked);
    example_print(" pixels checked against a brute-force search: ");
    example_print(err == VOR_OK && stream.wrong == 0 ? "agree" : "DISAGREE");
    example_print(stream.file >= 0 ? "; streamed to build/demo.rgb565\n" : "; no host file\n");
    return err == VOR_OK && stream.wrong == 0 ? 0 : 1;
}

/* ---- the diagram as text, streamed to the host for `vor draw --cells` */

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
        err = vor_nearest(&diagram, (vor_point_t){x, y}, hint, &site);
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
    int raster_status = render_frame();
    const vor_box_t floor = {-50000, -50000, 50000, 50000};
    int32_t cells = example_dump_cells("build/demo.cells", &diagram, sites, SITES, &floor);
    example_print("cells:     ");
    if (cells >= 0) {
        example_print_uint((uint64_t)cells);
        example_print(" cells clipped to the floor, streamed to build/demo.cells\n");
    } else {
        example_print("FAILED\n");
    }
    return (err == VOR_OK && wrong == 0 && raster_status == 0 && cells >= 0) ? 0 : 1;
}
