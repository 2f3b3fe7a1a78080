/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/semihost_call.c - the ARM semihosting trap (bkpt 0xAB) for
 * port/common/semihost.c, shared by cortex-m0, cortex-m3 and cortex-m4f.
 */
#include "../common/semihost.h"

uint32_t vor__semihost_call(uint32_t op, const void *block)
{
    /* r0/r1 in, r0 out; the memory clobber makes the argument block
     * visible to the host and its results visible to us */
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = block;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void vor__semihost_no_exit(int status)
{
    (void)status;
    for (;;) { /* nowhere to return to */
        __asm__ volatile("wfi");
    }
}
