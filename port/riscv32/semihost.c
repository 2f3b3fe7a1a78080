/*
 * port/riscv32/semihost.c - output, exit status and host files through
 * RISC-V semihosting: a0 = operation, a1 = argument block, and the trap
 * sequence
 *     slli x0, x0, 0x1f ; ebreak ; srai x0, x0, 7
 * in uncompressed (norvc) instructions that must not straddle a page,
 * hence the 16-byte alignment. Operations and blocks are ARM's.
 *
 * Under QEMU run with -semihosting-config enable=on,target=native:
 *   - SYS_OPEN ":tt" mode "w" gives the console handle; SYS_WRITE to it
 *     reaches QEMU's stdout (SYS_WRITE0 would reach its stderr).
 *   - SYS_EXIT_EXTENDED with {ADP_Stopped_ApplicationExit, code} makes
 *     QEMU exit with exactly `code`.
 *   - SYS_OPEN of a relative path opens it relative to QEMU's working
 *     directory.
 */
#include "../port.h"

#include "riscv32.h"

#define SYS_OPEN 0x01u
#define SYS_CLOSE 0x02u
#define SYS_WRITE 0x05u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define OPEN_MODE_W 4u  /* "w"  */
#define OPEN_MODE_WB 5u /* "wb" */

/* uint32_t vor__rv_semihost(uint32_t op, const void *arg): an ordinary
 * call, so the compiler already assumes it reads and writes memory. */
uint32_t vor__rv_semihost(uint32_t op, const void *arg);
__asm__(
    "  .pushsection .text.vor__rv_semihost,\"ax\",@progbits\n"
    "  .balign 16\n"
    "  .globl vor__rv_semihost\n"
    "  .type vor__rv_semihost, @function\n"
    "vor__rv_semihost:\n"
    "  .option push\n"
    "  .option norvc\n"
    "  slli x0, x0, 0x1f\n"
    "  ebreak\n"
    "  srai x0, x0, 7\n"
    "  .option pop\n"
    "  ret\n"
    "  .size vor__rv_semihost, . - vor__rv_semihost\n"
    "  .popsection\n");

static size_t string_length(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0') { /* bounded by the caller's terminating NUL */
        n++;
    }
    return n;
}

/* SYS_OPEN: {name, mode, strlen(name)}; returns a handle or -1. */
static int semihost_open(const char *path, uint32_t mode)
{
    uint32_t block[3];
    uint32_t handle;
    block[0] = (uint32_t)(uintptr_t)path;
    block[1] = mode;
    block[2] = (uint32_t)string_length(path);
    handle = vor__rv_semihost(SYS_OPEN, block);
    if (handle > 0x7FFFFFFFu) {
        return -1;
    }
    return (int)handle;
}

/* SYS_WRITE: {handle, data, n}; returns the number of bytes NOT written. */
static int semihost_write(int handle, const void *data, size_t n)
{
    uint32_t block[3];
    block[0] = (uint32_t)handle;
    block[1] = (uint32_t)(uintptr_t)data;
    block[2] = (uint32_t)n;
    return vor__rv_semihost(SYS_WRITE, block) == 0u ? 0 : -1;
}

/* The console handle, opened on first use so that output works even
 * before vor_port_init() (e.g. from the trap handler). -1: not yet open. */
static int console = -1;

void vor_port_write(const char *text, size_t n)
{
    if (n == 0u) {
        return;
    }
    if (console < 0) {
        console = semihost_open(":tt", OPEN_MODE_W);
        if (console < 0) {
            return;
        }
    }
    (void)semihost_write(console, text, n);
}

void vor_port_exit(int status)
{
    uint32_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    (void)vor__rv_semihost(SYS_EXIT_EXTENDED, block);
    vor__rv_test_exit(status); /* not reached under semihosting */
}

void vor__rv_test_exit(int status)
{
    uint32_t code = (uint32_t)status & 0xFFFFu;
    VOR_RV_VIRT_TEST = code == 0u ? 0x5555u : (code << 16) | 0x3333u;
    for (;;) { /* not reached on QEMU virt */
        __asm__ volatile("wfi");
    }
}

int vor_port_file_open(const char *path)
{
    return semihost_open(path, OPEN_MODE_WB);
}

int vor_port_file_write(int handle, const void *data, size_t n)
{
    if (handle < 0) {
        return -1;
    }
    if (n == 0u) {
        return 0;
    }
    return semihost_write(handle, data, n);
}

int vor_port_file_close(int handle)
{
    uint32_t block[1];
    if (handle < 0) {
        return -1;
    }
    block[0] = (uint32_t)handle;
    return vor__rv_semihost(SYS_CLOSE, block) == 0u ? 0 : -1;
}
