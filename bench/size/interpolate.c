/* SPDX-License-Identifier: MIT */
/* bench/size/interpolate.c - build_nearest's calls (vor_build, vor_nearest)
 * plus natural-neighbour interpolation of site values, Sibson's and
 * Laplace's: vor_interpolate and vor_interpolate_laplace, as a firmware
 * that maps a field from scattered sensors does. */
#include "common.h"

static vor_point_t points[SIZE_SITES];
static int32_t values[SIZE_SITES];
static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(16)];

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t site = 0;
    size_points(points);
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        values[i] = size_x(i) - size_y(i);
    }
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    acc |= vor_nearest(&d, (vor_point_t){size_x(0), size_y(1)}, VOR_NO_HINT, &site);
    vor_point_t q = {size_x(2), size_y(2)};
    vor_interpolation_t sibson, laplace;
    acc |= vor_interpolate(&d, values, q, site, scratch, sizeof scratch, &sibson);
    acc |= vor_interpolate_laplace(&d, values, q, site, scratch, sizeof scratch, &laplace);
    return acc + sibson.value + laplace.value;
}
