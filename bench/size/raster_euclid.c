/* SPDX-License-Identifier: MIT */
/* bench/size/raster_euclid.c - the discrete Voronoi diagram of Euclidean
 * point sites alone, no Delaunay mesh. */
#include "raster_common.h"

int main(void)
{
    return raster_render(vor_raster_euclid, VOR_METRIC_EUCLID) + (int)raster_sum;
}
