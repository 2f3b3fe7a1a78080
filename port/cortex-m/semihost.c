/*
 * port/cortex-m/semihost.c - output, exit status and host files for every
 * Cortex-M target, through ARM semihosting (bkpt 0xAB, r0 = operation,
 * r1 = argument block). Shared by cortex-m0, cortex-m3 and cortex-m4f.
 *
 * Under QEMU run with -semihosting-config enable=on,target=native:
 *   - SYS_OPEN ":tt" mode "w" gives the console handle; SYS_WRITE to it
 *     reaches QEMU's stdout. (SYS_WRITE0 reaches QEMU's stderr instead, so
 *     it is not used.)
 *   - SYS_EXIT_EXTENDED with {ADP_Stopped_ApplicationExit, code} makes
 *     QEMU exit with exactly `code` (plain SYS_EXIT reports only 0 or 1).
 *   - SYS_OPEN of a relative path opens it relative to QEMU's working
 *     directory.
 *
 * On real hardware semihosting needs an attached debugger; without one
 * bkpt 0xAB escalates to HardFault. Replace this file for such a board.
 */
#include "../port.h"

#define SYS_OPEN 0x01u
#define SYS_CLOSE 0x02u
#define SYS_WRITE 0x05u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define OPEN_MODE_W 4u  /* "w"  */
#define OPEN_MODE_WB 5u /* "wb" */

/* One semihosting call. r0/r1 in, r0 out; the memory clobber makes the
 * argument block visible to the host and its results visible to us. */
static uint32_t semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

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
    handle = semihost(SYS_OPEN, block);
    if (handle == 0xFFFFFFFFu || handle > 0x7FFFFFFFu) {
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
    return semihost(SYS_WRITE, block) == 0u ? 0 : -1;
}

/* The console handle, opened on first use so that output works even
 * before vor_port_init() (e.g. from a fault handler). -1: not yet open. */
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
    (void)semihost(SYS_EXIT_EXTENDED, block);
    for (;;) { /* not reached under semihosting: nowhere to return to */
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
    return semihost(SYS_CLOSE, block) == 0u ? 0 : -1;
}
