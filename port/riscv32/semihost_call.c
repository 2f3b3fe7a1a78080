/* SPDX-License-Identifier: MIT */
/*
 * port/riscv32/semihost_call.c - the RISC-V semihosting trap for
 * port/common/semihost.c: a0 = operation, a1 = argument block, and the
 * sequence
 *     slli x0, x0, 0x1f ; ebreak ; srai x0, x0, 7
 * in uncompressed (norvc) instructions that must not straddle a page,
 * hence the 16-byte alignment.
 */
#include "../common/semihost.h"
#include "riscv32.h"

/* An ordinary call, so the compiler already assumes it reads and writes
 * memory. */
__asm__(
    "  .pushsection .text.vor__semihost_call,\"ax\",@progbits\n"
    "  .balign 16\n"
    "  .globl vor__semihost_call\n"
    "  .type vor__semihost_call, @function\n"
    "vor__semihost_call:\n"
    "  .option push\n"
    "  .option norvc\n"
    "  slli x0, x0, 0x1f\n"
    "  ebreak\n"
    "  srai x0, x0, 7\n"
    "  .option pop\n"
    "  ret\n"
    "  .size vor__semihost_call, . - vor__semihost_call\n"
    "  .popsection\n");

void vor__semihost_no_exit(int status)
{
    vor__rv_test_exit(status);
}

void vor__rv_test_exit(int status)
{
    uint32_t code = (uint32_t)status & 0xFFFFu;
    VOR_RV_VIRT_TEST = code == 0u ? 0x5555u : (code << 16) | 0x3333u;
    for (;;) { /* not reached on QEMU virt */
        __asm__ volatile("wfi");
    }
}
