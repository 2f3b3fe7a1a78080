/* SPDX-License-Identifier: MIT */
/* A test program whose one check fails: the run must end with status 1 and
 * the line "0 passed, 1 failed" (tools/run-tests.sh, suite "harness"). */
#include "test.h"

int main(void)
{
    vor_port_init();
    CHECK(1 + 1 == 3, "deliberate failure");
    test_summary();
    return test_failures() == 0 ? 0 : 1;
}
