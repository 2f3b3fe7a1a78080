/* SPDX-License-Identifier: MIT */
/*
 * main.c - the configuration contract test (tests/config/mismatch.c): an
 * application compiled with other vor_config.h options than its library
 * gets VOR_ERR_CONFIG from vor_init and vor_tracker_begin, with nothing
 * written; with the same options everything works.
 */
#include "test.h"

void config_same(const char *name);
void config_tracker_edges(const char *name);
void config_index_bits(const char *name);
void config_sites_per_bucket(const char *name);
void config_stats(const char *name);

int main(void)
{
    vor_port_init();
    test_select(TEST_ONLY, TEST_MODE);
    TEST_CASE("config/same") config_same("same options as the library");
    TEST_CASE("config/tracker_edges") config_tracker_edges("VOR_TRACKER_EDGES 12 against 24");
    TEST_CASE("config/index_bits") config_index_bits("VOR_INDEX_BITS other than the library's");
    TEST_CASE("config/sites_per_bucket") {
        config_sites_per_bucket("VOR_SITES_PER_BUCKET 16 against 4");
    }
    TEST_CASE("config/stats") config_stats("VOR_STATS 1 against 0");
    return test_finish();
}
