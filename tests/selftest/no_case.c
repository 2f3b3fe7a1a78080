/* SPDX-License-Identifier: MIT */
/* A filter that selects no case: the run must fail (status 1, "no case
 * matches"), never pass with no check (tools/run-tests.sh, suite
 * "harness"). */
#include "test.h"

static void group(void)
{
    TEST_CASE("passes") CHECK(1 + 1 == 2, "arithmetic");
}

int main(void)
{
    vor_port_init();
    test_select("selftest/missing", 0u);
    test_group("selftest", group);
    return test_finish();
}
