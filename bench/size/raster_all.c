/* SPDX-License-Identifier: MIT */
/* bench/size/raster_all.c - the raster with every metric reachable (the
 * metric comes from input the compiler cannot see). */
#include "raster_common.h"

int main(void)
{
    return raster_render(vor_raster, (enum vor_metric)size_x(5)) + (int)raster_sum;
}
