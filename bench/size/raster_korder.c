/* SPDX-License-Identifier: MIT */
/* bench/size/raster_korder.c - the K nearest sites of every pixel
 * (vor_raster_nearest, every metric reachable), in the k-set picture. */
#include "raster_common.h"

static uint16_t korder_band[SIZE_WIDTH * SIZE_ROWS];
static uint16_t korder_palette[SIZE_SITES];
static uint8_t korder_work[VOR_RASTER_NEAREST_WORK_BYTES(SIZE_SITES, SIZE_WIDTH, 4)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));

int main(void)
{
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        raster_points[i].x = size_x(i);
        raster_points[i].y = size_y(i);
        korder_palette[i] = (uint16_t)size_x(i);
    }
    vor_raster_frame_t frame = {size_x(0), size_y(0), 1, 1, SIZE_WIDTH, SIZE_ROWS};
    vor_raster_sites_t sites = {0};
    sites.metric = (enum vor_metric)size_x(5);
    sites.points = raster_points;
    sites.count = SIZE_SITES;
    vor_raster_output_t out = {0};
    out.kind = (enum vor_raster_kind)size_x(6);
    out.band = korder_band;
    out.band_bytes = sizeof korder_band;
    out.band_rows = SIZE_ROWS;
    out.flush = raster_flush;
    out.palette565 = korder_palette;
    return vor_raster_nearest(&frame, &sites, 4, &out, NULL, korder_work, sizeof korder_work) +
           (int)raster_sum;
}
