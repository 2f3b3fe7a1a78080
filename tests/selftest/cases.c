/* SPDX-License-Identifier: MIT */
/* Named cases under a filter: the selected case whose check fails and the
 * one that checks nothing must fail by name, the one left out must not
 * run, and the run must end with status 1 (tools/run-tests.sh, suite
 * "harness"). */
#include "test.h"

static void group(void)
{
    TEST_CASE("passes") CHECK(1 + 1 == 2, "arithmetic");
    TEST_CASE("fails") CHECK(1 + 1 == 3, "deliberate failure");
    TEST_CASE("empty") test_printf("a case that checks nothing\n");
    TEST_CASE("left_out") CHECK(1 + 1 == 3, "a case the filter leaves out");
}

int main(void)
{
    vor_port_init();
    test_select("selftest/passes,selftest/fails,selftest/empty", 0u);
    test_group("selftest", group);
    return test_finish();
}
