/* SPDX-License-Identifier: MIT */
/* bench/size/everything.c - every public function of vor.h, vor_cdt.h,
 * vor_power.h and vor_raster.h reachable: the whole library as one
 * firmware keeps it. */
#include "raster_common.h"
#include "vor_cdt.h"
#include "vor_power.h"

static vor_point_t cell[VOR_CELL_MAX_VERTICES(SIZE_SITES)];
static uint8_t centroid_scratch[VOR_CENTROID_SCRATCH_BYTES(16)];
static uint8_t natural_scratch[VOR_SIBSON_SCRATCH_BYTES(8)];
static int32_t site_values[SIZE_SITES];
static int32_t field_band[SIZE_WIDTH * 2u];
static uint16_t field_ramp[256];
static uint32_t ids[SIZE_SITES];
static uint8_t motion[VOR_MOTION_BYTES(SIZE_SITES)] __attribute__((aligned(VOR_MOTION_ALIGN)));
static uint8_t walls[VOR_CDT_BYTES(SIZE_SITES, 64, 16, 64)] __attribute__((aligned(VOR_CDT_ALIGN)));

SIZE_ARENA(size_arena);
static uint8_t power_arena[VOR_POWER_ARENA_BYTES(SIZE_SITES)]
    __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));
static int64_t power_weights[SIZE_SITES];
static uint32_t triangles_flat[3u * VOR_TRIANGLES_MAX(SIZE_SITES)];
static uint32_t halfedges[3u * VOR_TRIANGLES_MAX(SIZE_SITES)];
static uint32_t order_scratch[VOR_ORDER_SCRATCH_BYTES(SIZE_L_ROOM, SIZE_SITES, 2u) / 4u + 1u];
static uint32_t order_sets[VOR_ORDER_SETS_WORDS(VOR_ORDER_MAX_CELLS(SIZE_SITES, 2u), 2u)];
static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(SIZE_L_ROOM, SIZE_SITES)];

int main(void)
{
    vor_t d;
    uint32_t site = 0, count = 0, found = 0;
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    vor_build_options_t options = {(enum vor_order)size_x(6), (enum vor_dc_split)size_x(7), 0};
    acc |= vor_build(&d, raster_points, SIZE_SITES / 2u, &options, ids);
    acc |= vor_build_dc(&d, raster_points, SIZE_SITES / 2u, &options, ids);
    acc |= vor_build_dc_forked(&d, raster_points, SIZE_SITES / 2u, &options,
                               ids, NULL);
    acc |= vor_insert(&d, (vor_point_t){size_x(1), size_y(1)}, &site);
    acc |= vor_insert_near(&d, (vor_point_t){size_x(2), size_y(2)}, site, &site);
    acc |= vor_motion_attach(&d, motion, sizeof motion);
    acc |= vor_move(&d, site, (vor_point_t){size_x(8), size_y(8)}, &site);
    acc |= vor_remove(&d, site);
    acc |= vor_nearest(&d, (vor_point_t){size_x(3), size_y(3)}, VOR_NO_HINT, &site);
    acc |= vor_nearest_k(&d, (vor_point_t){size_x(3), size_y(3)}, site, 4, ids, &found);
    acc |= vor_locate(&d, (vor_point_t){size_x(9), size_y(9)}, site, ids);
    acc |= vor_within(&d, (vor_point_t){size_x(9), size_y(9)}, (uint64_t)size_x(10), site, ids,
                      SIZE_SITES, &found);
    acc |= vor_triangles_count(&d, &found);
    acc |= vor_triangles_export(&d, triangles_flat, halfedges, found, &count);
    vor_tracker_t tracker;
    vor_tracker_begin(&tracker, &d);
    acc |= vor_track(&tracker, (vor_point_t){size_x(4), size_y(4)}, &site);
    vor_violation_t violation;
    acc |= vor_validate(&d, &violation);
    vor_memory_t memory;
    acc |= vor_memory(&d, &memory);
    vor_triangle_iter_t triangles;
    vor_triangles_begin(&triangles, &d);
    while (vor_triangles_next(&triangles, ids) > 0) {
        acc++;
    }
    vor_neighbour_iter_t neighbours;
    vor_neighbours_begin(&neighbours, &d, site);
    while (vor_neighbours_next(&neighbours, &site) > 0) {
        acc++;
    }
    vor_hull_iter_t hull;
    vor_hull_begin(&hull, &d);
    while (vor_hull_next(&hull, &site) > 0) {
        acc++;
    }
    vor_edge_iter_t edges;
    vor_edge_t edge;
    vor_edges_begin(&edges, &d);
    while (vor_edges_next(&edges, &edge) > 0) {
        acc++;
    }
    vor_box_t box = {size_x(2), size_y(2), size_x(3), size_y(3)};
    acc |= vor_cell(&d, site, &box, cell, VOR_CELL_MAX_VERTICES(SIZE_SITES), &count);
    vor_centroid_t centroid;
    acc |= vor_cell_centroid(&d, site, &box, centroid_scratch, sizeof centroid_scratch, &centroid);
    vor_point_t room[SIZE_L_ROOM];
    size_l_room(room);
    vor_clip_t clip;
    acc |= vor_clip_begin(&clip, &d, site, room, SIZE_L_ROOM, order_scratch,
                          sizeof order_scratch);
    while (vor_clip_next(&clip, piece, VOR_CLIP_MAX_VERTICES(SIZE_L_ROOM, SIZE_SITES), &count) >
           0) {
        acc += (int)count;
    }
    acc |= vor_clip_error(&clip);
    acc |= vor_clip_centroid(&clip, VOR_CLIP_WHOLE, centroid_scratch, sizeof centroid_scratch,
                             &centroid);
    acc |= vor_order_cell_begin(&clip, &d, ids, 2u, room, SIZE_L_ROOM, order_scratch,
                                sizeof order_scratch);
    vor_order_iter_t order;
    acc |= vor_order_cells_begin(&order, &d, 2u, room, SIZE_L_ROOM, order_sets,
                                 (uint32_t)VOR_ORDER_MAX_CELLS(SIZE_SITES, 2u), order_scratch,
                                 sizeof order_scratch);
    while (vor_order_cells_next(&order, ids, &clip) > 0) {
        acc++;
    }
    acc |= vor_order_cells_error(&order);
    vor_coordinates_t natural;
    vor_interpolation_t value;
    vor_point_t q = {size_x(5), size_y(5)};
    acc |= vor_sibson(&d, q, VOR_NO_HINT, natural_scratch, sizeof natural_scratch, &natural);
    acc |= vor_laplace(&d, q, VOR_NO_HINT, natural_scratch, sizeof natural_scratch, &natural);
    acc |= vor_interpolate(&d, site_values, q, VOR_NO_HINT, natural_scratch, sizeof natural_scratch, &value);
    acc |= vor_interpolate_laplace(&d, site_values, q, VOR_NO_HINT, natural_scratch,
                                   sizeof natural_scratch, &value);
    acc += value.value;
    vor_raster_frame_t field_frame = {size_x(9), size_y(9), 1, 1, SIZE_WIDTH, 4};
    vor_field_output_t field_out = {0};
    field_out.kind = (enum vor_field_kind)size_x(8);
    field_out.band = field_band;
    field_out.band_bytes = sizeof field_band;
    field_out.band_rows = 2;
    field_out.flush = raster_flush;
    field_out.ramp565 = field_ramp;
    field_out.high = 255;
    vor_field_options_t field_options = {(enum vor_field_method)size_x(8)};
    acc |= vor_field_raster(&d, site_values, &field_frame, &field_out, &field_options,
                            natural_scratch, sizeof natural_scratch);
    vor_vertex_t centre;
    acc |= vor_circumcentre(raster_points[0], raster_points[1], raster_points[2], &centre);
    acc |= vor_voronoi_vertex(&d, 0, 1, 2, &centre);
    acc += vor_orient2d(raster_points[0], raster_points[1], raster_points[2]);
    acc += vor_incircle(raster_points[0], raster_points[1], raster_points[2], raster_points[3]);
    acc += vor_closer(raster_points[0], raster_points[1], raster_points[2]);
    acc += vor_orient2d_sos(raster_points, 0, 1, 2);
    acc += vor_incircle_sos(raster_points, 0, 1, 2, 3);
    acc += vor_closer_sos(raster_points, 0, 1, 2);
    static const int64_t weights[4] = {0, 1, 2, 3};
    acc += vor_power_test(raster_points[0], weights[0], raster_points[1], weights[1],
                          raster_points[2], weights[2], raster_points[3], weights[3]);
    acc += vor_power_test_sos(raster_points, weights, 0, 1, 2, 3);
    acc += vor_power_closer(raster_points[0], raster_points[1], weights[1], raster_points[2],
                            weights[2]);
    vor_cdt_limits_t limits = {64, 16, 64};
    acc |= vor_cdt_attach(&d, walls, sizeof walls, &limits);
    acc |= vor_constrain(&d, 0, site);
    acc |= vor_cdt_domain(&d);
    vor_cdt_triangle_iter_t cdt_triangles;
    (void)vor_cdt_inside_begin(&cdt_triangles, &d);
    while (vor_cdt_triangles_next(&cdt_triangles, ids) > 0) {
        acc++;
    }
    vor_cdt_edge_iter_t cdt_edges;
    vor_cdt_edges_begin(&cdt_edges, &d);
    while (vor_cdt_edges_next(&cdt_edges, &site, &count) > 0) {
        acc++;
    }
    uint32_t crossing[4];
    acc |= vor_cdt_crossing(&d, SIZE_SITES, crossing);
    acc |= vor_unconstrain(&d, 0, site);
    vor_power_t pd;
    acc |= vor_power_init(&pd, power_arena, sizeof power_arena, SIZE_SITES);
    acc |= vor_power_build(&pd, raster_points, power_weights, SIZE_SITES / 2u, ids);
    acc |= vor_power_insert(&pd, (vor_point_t){size_x(9), size_y(9)}, size_x(10), &site);
    acc |= vor_power_hidden(&pd, site);
    vor_power_hidden_iter_t hidden;
    vor_power_hidden_begin(&hidden, &pd);
    while (vor_power_hidden_next(&hidden, &site) > 0) {
        acc++;
    }
    (void)vor_power_triangles_begin(&triangles, &pd);
    while (vor_triangles_next(&triangles, ids) > 0) {
        acc++;
    }
    acc |= vor_power_validate(&pd, &violation);
    vor_raster_sites_t korder_sites = {0};
    korder_sites.metric = (enum vor_metric)size_x(11);
    korder_sites.points = raster_points;
    korder_sites.count = SIZE_SITES;
    vor_raster_output_t korder_out = {0};
    korder_out.kind = (enum vor_raster_kind)size_x(12);
    korder_out.band = raster_band;
    korder_out.band_bytes = sizeof raster_band;
    korder_out.band_rows = 1;
    korder_out.flush = raster_flush;
    acc |= vor_raster_nearest(&field_frame, &korder_sites, (uint32_t)size_x(13), &korder_out, NULL,
                              raster_work, sizeof raster_work);
    return acc + raster_render(vor_raster, (enum vor_metric)size_x(5)) + (int)raster_sum;
}
