/* SPDX-License-Identifier: MIT */
/* main.c - runs every test group; the port's startup calls it. */
#include "test.h"

int main(void)
{
    vor_port_init();
    test_predicates();
    test_mesh();
    test_queries();
    test_raster();
    test_geometry();
    test_raster_metrics();
    test_true_output();
    test_api_safety();
    test_centroid();
    test_dynamic();
    test_motion();
    test_fork_join();
    test_summary();
    return test_failures() == 0 ? 0 : 1;
}
