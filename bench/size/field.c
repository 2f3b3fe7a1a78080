/* SPDX-License-Identifier: MIT */
/* bench/size/field.c - build_nearest's calls (vor_build, vor_nearest)
 * plus a field frame of the Sibson interpolant, vor_field_raster, as a
 * firmware that draws a sensor field on a display without a GPU does. */
#include "common.h"

#include "vor_raster.h"

#define WIDTH 32u
#define BAND_ROWS 8u

static vor_point_t points[SIZE_SITES];
static int32_t values[SIZE_SITES];
static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(16)];
static uint16_t band[BAND_ROWS * WIDTH];
static uint16_t ramp[256];

SIZE_ARENA(size_arena);

static int show(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)first_row;
    *(uint32_t *)user += rows + ((const uint16_t *)pixels)[0];
    return 0;
}

int main(void)
{
    vor_t d;
    uint32_t shown = 0;
    size_points(points);
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        values[i] = size_x(i) - size_y(i);
    }
    for (uint32_t i = 0; i < 256u; i++) {
        ramp[i] = (uint16_t)(i * 257u);
    }
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    vor_raster_frame_t frame = {size_x(0), size_y(0), 1, 1, WIDTH, 24u};
    vor_field_output_t out = {0};
    out.kind = VOR_FIELD_RGB565;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = BAND_ROWS;
    out.flush = show;
    out.user = &shown;
    out.ramp565 = ramp;
    out.low = -1000;
    out.high = 1000;
    acc |= vor_field_raster(&d, values, &frame, &out, NULL, scratch, sizeof scratch);
    return acc + (int)shown;
}
