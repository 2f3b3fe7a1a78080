/* SPDX-License-Identifier: MIT */
/* A test program that traps, like a failed VOR_ASSERT: the run must end
 * with a non-zero status (99 from the target ports' fault handlers). */
#include "test.h"

int main(void)
{
    vor_port_init();
    test_printf("trapping now\n");
    __builtin_trap();
}
