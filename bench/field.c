/* SPDX-License-Identifier: MIT */
/*
 * bench/field.c - cost of vor_field_raster per pixel, on any port.
 *
 * 50 uniform random sites (a fixed generator, the same on every target)
 * in the box [0, 2^16)^2, with random int32 values, and a 32 x 24 frame
 * over the middle of the box, [2^13, 7 2^13)^2, where nearly every pixel
 * is inside the convex hull; bands of 8 rows of VALUE pixels. Prints per
 * row
 *
 *   bench field-sibson PIXELS COST UNIT INSIDE NEIGHBOURS
 *   bench field-laplace PIXELS COST UNIT INSIDE NEIGHBOURS
 *   bench interpolate PIXELS COST UNIT INSIDE NEIGHBOURS
 *
 * where COST is the vor_port_counter() delta over the frame divided by
 * its pixels, with one decimal: instructions under QEMU -icount on
 * targets (one run: the count is repeatable), nanoseconds on the host
 * (best of 5 runs); INSIDE the pixels inside the hull, NEIGHBOURS the
 * largest count of natural neighbours. "interpolate" is vor_interpolate
 * at each pixel centre without a hint, for scale. "bench valid ok" ends a
 * good run (every call returned VOR_OK, the frame's pixels equal to
 * vor_interpolate's).
 */
#include "test.h"
#include "vor.h"
#include "vor_raster.h"

#define SITES 50u
#define HOST_RUNS 5u
#define WIDTH 32u
#define HEIGHT 24u
#define BAND_ROWS 8u

static vor_point_t points[SITES];
static int32_t values[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(16)];
static int32_t band[BAND_ROWS * WIDTH];
static int32_t frame_px[WIDTH * HEIGHT];
static vor_t diagram;
static const vor_raster_frame_t frame = {1 << 13, 1 << 13, 1 << 9, (3 << 13) / 12, WIDTH, HEIGHT};

static int keep_rows(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)user;
    const int32_t *px = pixels;
    for (uint32_t k = 0; k < rows * WIDTH; k++) {
        frame_px[(first_row * WIDTH) + k] = px[k];
    }
    return 0;
}

/* The counter delta over one frame, or 0 on an error. */
static uint64_t one_frame(int method, uint32_t *inside, uint32_t *most)
{
    vor_field_output_t out = {0};
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = BAND_ROWS;
    out.flush = keep_rows;
    out.outside = INT32_MIN;
    out.max_neighbours = most;
    vor_field_options_t options = {(method == 1) ? VOR_FIELD_LAPLACE : VOR_FIELD_SIBSON};
    bool ok = true;
    uint32_t count = 0;
    uint64_t start = vor_port_counter();
    if (method < 2) {
        ok = vor_field_raster(&diagram, values, &frame, &out, &options, scratch, sizeof scratch) ==
             VOR_OK;
    } else {
        *most = 0;
        for (uint32_t j = 0; j < HEIGHT; j++) {
            for (uint32_t i = 0; i < WIDTH; i++) {
                vor_point_t q = {frame.origin_x + (int32_t)i * frame.step_x,
                                 frame.origin_y + (int32_t)j * frame.step_y};
                vor_interpolation_t v;
                int err = vor_interpolate(&diagram, values, q, VOR_NO_HINT, scratch, sizeof scratch, &v);
                ok &= (err == VOR_OK) || (err == VOR_ERR_OUTSIDE);
                ok &= frame_px[(j * WIDTH) + i] == ((err == VOR_OK) ? v.value : INT32_MIN);
                count += (err == VOR_OK) ? 1u : 0u;
                *most = ((err == VOR_OK) && (v.neighbours > *most)) ? v.neighbours : *most;
            }
        }
    }
    uint64_t cost = vor_port_counter() - start;
    if (method < 2) {
        for (uint32_t k = 0; k < WIDTH * HEIGHT; k++) {
            count += (frame_px[k] != INT32_MIN) ? 1u : 0u;
        }
    }
    *inside = count;
    return ok ? cost : 0u;
}

static bool row(const char *name, int method)
{
    bool host = vor_port_counter_unit[0] == 'n';
    uint64_t best = 0;
    uint32_t inside = 0;
    uint32_t most = 0;
    for (unsigned run = 0; run < (host ? HOST_RUNS : 1u); run++) {
        uint64_t cost = one_frame(method, &inside, &most);
        if (cost == 0u) {
            return false;
        }
        best = (run == 0u || cost < best) ? cost : best;
    }
    uint32_t n = WIDTH * HEIGHT;
    uint64_t tenths = (best * 10u + n / 2u) / n;
    test_printf("bench %s %u %u.%u %s %u %u\n", name, n, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), vor_port_counter_unit, inside, most);
    return true;
}

int main(void)
{
    vor_port_init();
    test_rng_t rng;
    test_rng_seed(&rng, 2026u);
    for (uint32_t i = 0; i < SITES; i++) {
        points[i].x = (int32_t)(test_rng_u32(&rng) % 65536u);
        points[i].y = (int32_t)(test_rng_u32(&rng) % 65536u);
        values[i] = test_rng_range(&rng, -1000000, 1000000);
    }
    bool ok = vor_init(&diagram, arena, sizeof arena, SITES) == VOR_OK &&
              vor_build(&diagram, points, SITES, NULL, NULL) == VOR_OK;
    /* Sibson's frame last before the per-pixel check, which reads it */
    ok = ok && row("field-laplace", 1) && row("field-sibson", 0) && row("interpolate", 2);
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
