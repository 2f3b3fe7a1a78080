/* SPDX-License-Identifier: MIT */
/* main.c - runs every test group; the port's startup calls it. */
#include "test.h"

int main(void)
{
    vor_port_init();
    test_select(TEST_ONLY, TEST_MODE);
    test_group("predicates", test_predicates);
    test_group("mesh", test_mesh);
    test_group("queries", test_queries);
    test_group("raster", test_raster);
    test_group("geometry", test_geometry);
    test_group("raster_metrics", test_raster_metrics);
    test_group("korder", test_korder);
    test_group("true_output", test_true_output);
    test_group("api_safety", test_api_safety);
    test_group("centroid", test_centroid);
    test_group("interpolate", test_interpolate);
    test_group("field", test_field);
    test_group("dynamic", test_dynamic);
    test_group("motion", test_motion);
    test_group("fork_join", test_fork_join);
    test_group("cdt", test_cdt);
    test_group("power", test_power);
    test_group("locate", test_locate);
    test_group("clip", test_clip);
    test_group("order", test_order);
    return test_finish();
}
