/* SPDX-License-Identifier: MIT */
/*
 * port/template/port.c - starting point for running vor's tests, examples
 * and benchmarks on a new target. Copy port/template/ to port/<target>/,
 * fill in every "PORT:" marker, and point port.mk at the copies.
 *
 * The library itself (src/, include/) needs no port: it is pure
 * computation over caller memory. Only the programs that exercise it call
 * the functions below (declared in port/port.h).
 *
 * Shortcuts:
 *   - Any Cortex-M under a debugger or QEMU: copy port/cortex-m3/ (a
 *     port.mk and a link.ld); port/cortex-m/ and port/common/ supply the
 *     rest unchanged, including fault reports and the stack guard.
 *   - RISC-V in machine mode: start from port/riscv32/.
 * This file is the other case: a board with a UART and no debugger, with
 * the startup code written out so that every piece is visible. It is
 * written for a Cortex-M (vector table, SysTick/DWT); on another
 * architecture keep the function contracts and replace the machine parts.
 *
 * Bring-up order that finds problems one at a time:
 *   1. vor_port_write + a main() printing "hello": output works.
 *   2. vor_port_exit: `$(RUN) prog.elf; echo $?` shows 0, 1, 3 and 77 for
 *      main() returning those values.
 *   3. .data/.bss: a main() that checks an initialised and a zero static.
 *   4. a deliberate fault (load from an unmapped address) ends the run
 *      with a "fatal:" line and status 99, not a hang.
 *   5. vor_port_counter: time a loop of known length (see below).
 *   6. `make PORT=<target> tests run-tests`.
 */
#include "../port.h"

/* Status for a program stopped by a fault, as on every vor target. */
#define FAULT_STATUS 99

/* ---------------------------------------------------------------------
 * Startup. The reset handler must leave the machine able to run C:
 * stack pointer set (the Cortex-M hardware loads it from vector 0), .data
 * copied from flash, .bss zeroed, the FPU enabled if the code is compiled
 * for one. Then it runs main() and hands its return value to
 * vor_port_exit(): main is `int main(void)` and returning from it is how
 * a test program normally ends.
 * Check: a static initialised to 0x12345678 reads so in main(), a static
 * without initialiser reads 0.
 * ------------------------------------------------------------------- */

extern uint32_t __stack_top[];
extern const uint32_t __data_load[];
extern uint32_t __data_start[];
extern uint32_t __data_end[];
extern uint32_t __bss_start[];
extern uint32_t __bss_end[];

int main(void);
void Reset_Handler(void);
void Fault_Handler(void);

void Reset_Handler(void)
{
    const uint32_t *src = __data_load;
    uint32_t *dst;

    for (dst = __data_start; dst < __data_end; dst++) {
        *dst = *src++;
    }
    for (dst = __bss_start; dst < __bss_end; dst++) {
        *dst = 0u;
    }
    /* PORT: FPU on (CPACR) if ARCH_CFLAGS selects a hard-float ABI. */
    vor_port_exit(main());
}

/* Faults must end the run visibly, never hang: print one line starting
 * with "fatal:" and exit with FAULT_STATUS. (port/cortex-m/startup.c shows
 * how to recover the faulting pc and to survive a stack overflow.)
 * Check: main() doing `*(volatile uint32_t *)0xFFFFFFF0u;` (or any address
 * the chip leaves unmapped) exits 99 with that line. */
void Fault_Handler(void)
{
    static const char line[] = "fatal: fault\n";
    vor_port_write(line, sizeof line - 1u);
    vor_port_exit(FAULT_STATUS);
}

/* The vector table, placed first in flash by link.ld (section .vectors).
 * A struct keeps the stack address and the handlers apart, as ISO C does
 * not allow mixing object and function pointers in one array. */
struct vectors {
    uint32_t *initial_sp;
    void (*handler[15])(void);
};

#if defined(__GNUC__)
__attribute__((section(".vectors"), used))
#endif
const struct vectors vectors = {
    __stack_top,
    {
        Reset_Handler, Fault_Handler, Fault_Handler, Fault_Handler,
        Fault_Handler, Fault_Handler, 0, 0, 0, 0, Fault_Handler,
        Fault_Handler, 0, Fault_Handler, Fault_Handler,
    },
};

/* ---------------------------------------------------------------------
 * Output.
 * ------------------------------------------------------------------- */

/* PORT: send one byte, waiting while the transmitter is busy. */
static void uart_put(char c)
{
    (void)c;
}

/* vor_port_init: called first by main(). Bring up what the other functions
 * need: clocks, the UART, the counter. Must be safe to call twice.
 * Check: the "hello" of step 1 appears. */
void vor_port_init(void)
{
    static int started = 0;
    if (started) {
        return;
    }
    started = 1;
    /* PORT: clocks, UART pins and baud rate. */
    /* The counter: DWT CYCCNT counts core cycles on Cortex-M3/M4/M7
     * silicon (it reads 0 under QEMU: use SysTick there, see
     * port/cortex-m/systick.c). Enable trace, then the counter. */
    *(volatile uint32_t *)0xE000EDFCu |= 1u << 24; /* DEMCR.TRCENA */
    *(volatile uint32_t *)0xE0001004u = 0u;         /* DWT_CYCCNT */
    *(volatile uint32_t *)0xE0001000u |= 1u;        /* DWT_CTRL.CYCCNTENA */
}

/* vor_port_write: write exactly n bytes to the host's standard output, in
 * order, no translation (tests print '\n' line ends; add '\r' here if your
 * terminal needs it). Blocking is fine.
 * Check: a test's "N passed, N failed" line arrives intact. */
void vor_port_write(const char *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        uart_put(text[i]);
    }
}

/* vor_port_exit: end the program so that the shell running $(RUN) sees
 * exactly `status` (0 = all tests passed). Never returns. Without
 * semihosting, print a marker the RUN script can parse, then stop.
 * Check: step 2 above. */
void vor_port_exit(int status)
{
    static const char marker[] = "\nvor-exit: ";
    char digits[12];
    size_t n = 0;
    uint32_t v = status < 0 ? 0u - (uint32_t)status : (uint32_t)status;

    vor_port_write(marker, sizeof marker - 1u);
    if (status < 0) {
        uart_put('-');
    }
    do { /* at most 10 digits */
        digits[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    while (n > 0u) {
        uart_put(digits[--n]);
    }
    uart_put('\n');
    for (;;) { /* PORT: or reset, or bkpt for a debugger */
    }
}

/* ---------------------------------------------------------------------
 * Counter.
 * ------------------------------------------------------------------- */

/* What vor_port_counter counts, printed next to every benchmark figure:
 * "instructions" (QEMU -icount, minstret), "cycles" (DWT CYCCNT on
 * silicon), or "ns". */
const char vor_port_counter_unit[] = "cycles";

/* vor_port_counter: a 64-bit count that never goes backwards, in the unit
 * above. Extend a 32-bit hardware counter in software (count wraps in an
 * interrupt, or compare with the last value read) and read it race-free.
 * Check: around a loop of known length, e.g. on Thumb
 *     __asm__ volatile("1: subs %0, %0, #1\n bne 1b" : "+l"(n) :: "cc");
 * (2 instructions an iteration), the difference grows linearly with n at
 * the expected rate (instructions: exactly 2 per iteration, to the
 * counter's granularity) and two runs give the same figures. */
uint64_t vor_port_counter(void)
{
    static uint32_t last = 0u;
    static uint32_t high = 0u;
    uint32_t now = *(volatile uint32_t *)0xE0001004u; /* DWT_CYCCNT */

    /* Software extension: correct if called at least once per 2^32
     * cycles. Not interrupt-safe: the tests call it from one context. */
    if (now < last) {
        high++;
    }
    last = now;
    return ((uint64_t)high << 32) | now;
}

/* ---------------------------------------------------------------------
 * Host files: tests and tools stream images and tables out of the
 * firmware through these. Without a host link, return -1 from
 * vor_port_file_open; the programs then skip writing files.
 * Check (with a host link): open "out.bin", write 9 bytes, close; the
 * file on the host holds exactly those bytes; open of a path in a
 * missing directory returns -1.
 * ------------------------------------------------------------------- */

/* Create or truncate a binary file; return a handle >= 0, or -1. */
int vor_port_file_open(const char *path)
{
    (void)path;
    return -1; /* PORT: semihosting SYS_OPEN mode "wb", see
                  port/common/semihost.c */
}

/* Write all n bytes: 0 on success, -1 otherwise (n = 0 succeeds). */
int vor_port_file_write(int handle, const void *data, size_t n)
{
    (void)handle;
    (void)data;
    (void)n;
    return -1;
}

/* Close the file: 0 on success, -1 otherwise (bad handle included). */
int vor_port_file_close(int handle)
{
    (void)handle;
    return -1;
}
