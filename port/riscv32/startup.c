/* SPDX-License-Identifier: MIT */
/*
 * port/riscv32/startup.c - reset entry and trap handler for RV32 in machine
 * mode on QEMU's virt board (-bios none: the hart starts at 0x80000000,
 * where link.ld puts _start).
 *
 * _start sets gp and sp, points mtvec at the trap entry and calls
 * vor__rv_reset, which copies .data from its load image, zeroes .bss,
 * fills the unused stack with VOR_PORT_STACK_PAINT so the stack high-water
 * mark can be measured (scan up from __stack_bottom for the first other
 * word), makes the page below the stack inaccessible with a locked PMP
 * entry (a stack overflow then traps instead of silently overwriting
 * memory), calls vor_port_init() and main(), and passes main's return
 * value to vor_port_exit().
 *
 * Every trap (exception or interrupt: none is enabled) prints one line
 *     fatal: trap mcause=0x00000005 (load access fault) mepc=0x80000136
 *            mtval=0xfffffff0 sp=0x80410f80
 * (on one line) and exits with status 99.
 *
 * Symbols the linker script must define (see link.ld):
 *   __global_pointer$             gp, for linker relaxation
 *   __stack_top, __stack_bottom   initial sp (16-byte aligned) and stack end
 *   __stack_guard, __stack_guard_size   the PMP guard below the stack, a
 *                                 power of two >= 8 bytes, aligned to it
 *   __data_load                   load address of .data
 *   __data_start, __data_end      run address range of .data
 *   __bss_start, __bss_end        range of .bss
 * and the section .text.vor__rv_start must come first, at the reset address.
 */
#include "../port.h"
#include "../common/fault_line.h"

#include "riscv32.h"

/* Word written over the unused stack at reset. */
#define VOR_PORT_STACK_PAINT 0x5AA55AA5u

extern uint32_t __stack_top[];
extern uint32_t __stack_bottom[];
extern uint32_t __stack_guard[];
extern const char __stack_guard_size[];
extern const uint32_t __data_load[];
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];

int main(void);

void vor__rv_reset(void) VOR_PORT_NORETURN VOR_PORT_USED;
void vor__rv_trap(uint32_t sp) VOR_PORT_NORETURN VOR_PORT_USED;

/*
 * Reset entry and trap entry. gp is loaded with relaxation off (it is what
 * relaxation is relative to). The trap entry must be 4-byte aligned (mtvec
 * direct mode); it passes the faulting sp to vor__rv_trap and gives it a
 * fresh stack, since the old one may be what overflowed.
 */
__asm__(
    "  .pushsection .text.vor__rv_start,\"ax\",@progbits\n"
    "  .globl _start\n"
    "  .type _start, @function\n"
    "_start:\n"
    "  .option push\n"
    "  .option norelax\n"
    "  la gp, __global_pointer$\n"
    "  .option pop\n"
    "  la sp, __stack_top\n"
    "  la t0, vor__rv_trap_entry\n"
    "  .insn i 0x73, 1, x0, t0, 0x305\n" /* csrw mtvec, t0 */
    "  call vor__rv_reset\n"
    "  .size _start, . - _start\n"
    "  .balign 4\n"
    "  .globl vor__rv_trap_entry\n"
    "  .type vor__rv_trap_entry, @function\n"
    "vor__rv_trap_entry:\n"
    "  mv a0, sp\n"
    "  la sp, __stack_top\n"
    "  call vor__rv_trap\n"
    "  .size vor__rv_trap_entry, . - vor__rv_trap_entry\n"
    "  .popsection\n");


static const char *cause_name(uint32_t mcause)
{
    if ((mcause & 0x80000000u) != 0u) {
        return "interrupt";
    }
    switch (mcause) {
    case 0u: return "instruction address misaligned";
    case 1u: return "instruction access fault";
    case 2u: return "illegal instruction";
    case 3u: return "breakpoint";
    case 4u: return "load address misaligned";
    case 5u: return "load access fault";
    case 6u: return "store address misaligned";
    case 7u: return "store access fault";
    case 8u: case 9u: case 11u: return "environment call";
    default: return "exception";
    }
}

/* Report a trap and exit 99. A second trap while reporting the first (say,
 * semihosting is off and the ebreak itself traps) exits through the SiFive
 * test device instead. */
void vor__rv_trap(uint32_t sp)
{
    static volatile int reporting = 0;
    char line[160];
    size_t n = 0;
    uint32_t mcause;
    uint32_t mepc;
    uint32_t mtval;

    if (reporting) {
        vor__rv_test_exit(VOR_PORT_FAULT_STATUS);
    }
    reporting = 1;
    VOR_RV_CSR_READ(VOR_RV_CSR_MCAUSE, mcause);
    VOR_RV_CSR_READ(VOR_RV_CSR_MEPC, mepc);
    VOR_RV_CSR_READ(VOR_RV_CSR_MTVAL, mtval);
    n = vor__line_hex(line, n, sizeof line, "fatal: trap mcause=0x", mcause);
    n = vor__line_text(line, n, sizeof line, " (");
    n = vor__line_text(line, n, sizeof line, cause_name(mcause));
    n = vor__line_hex(line, n, sizeof line, ") mepc=0x", mepc);
    n = vor__line_hex(line, n, sizeof line, " mtval=0x", mtval);
    n = vor__line_hex(line, n, sizeof line, " sp=0x", sp);
    if (sp < (uint32_t)(uintptr_t)__stack_bottom
        || sp > (uint32_t)(uintptr_t)__stack_top) {
        n = vor__line_text(line, n, sizeof line, " outside the stack (overflow)");
    }
    line[n++] = '\n';
    vor_port_write(line, n);
    vor_port_exit(VOR_PORT_FAULT_STATUS);
}

/* PMP entry 0, locked so that it binds machine mode too: NAPOT region
 * __stack_guard of __stack_guard_size bytes, no access. Machine-mode
 * accesses that match no entry stay allowed. */
static void guard_stack(void)
{
    uint32_t base = (uint32_t)(uintptr_t)__stack_guard;
    uint32_t size = (uint32_t)(uintptr_t)__stack_guard_size;
    uint32_t addr = (base | ((size >> 1) - 1u)) >> 2;
    uint32_t cfg = 0x80u | 0x18u; /* L | A = NAPOT, R = W = X = 0 */
    VOR_RV_CSR_WRITE(VOR_RV_CSR_PMPADDR0, addr);
    VOR_RV_CSR_WRITE(VOR_RV_CSR_PMPCFG0, cfg);
}

void vor__rv_reset(void)
{
    const uint32_t *src;
    uint32_t *dst;
    volatile uint32_t *paint;
    uint32_t *sp;

    /* Copy .data from its load image; the bounds come from the linker. */
    src = __data_load;
    for (dst = __data_start; dst < __data_end; dst++) {
        *dst = *src++;
    }
    for (dst = __bss_start; dst < __bss_end; dst++) {
        *dst = 0u;
    }

    /* Paint the stack below the current frame; volatile keeps the compiler
     * from turning the loop into a memset call that would run on the very
     * memory being painted. */
    __asm__ volatile("mv %0, sp" : "=r"(sp));
    for (paint = __stack_bottom; paint < (volatile uint32_t *)sp; paint++) {
        *paint = VOR_PORT_STACK_PAINT;
    }

    guard_stack();
    /* main() calls vor_port_init() first too; calling it here as well
     * (it is idempotent) means the counter runs even if a program forgets. */
    vor_port_init();
    vor_port_exit(main());
}
