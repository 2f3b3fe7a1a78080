/* SPDX-License-Identifier: MIT */
/*
 * port/common/semihost.c - output, exit status and host files for every
 * target, through semihosting (ARM's operations, which RISC-V reuses). The
 * trap itself is the architecture's: vor__semihost_call in semihost.h.
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
 * On real hardware semihosting needs an attached debugger; without one the
 * trap faults. Replace this file for such a board.
 */
#include "../port.h"
#include "semihost.h"

#define SYS_OPEN 0x01u
#define SYS_CLOSE 0x02u
#define SYS_WRITE 0x05u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define OPEN_MODE_W 4u  /* "w"  */
#define OPEN_MODE_WB 5u /* "wb" */

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
    handle = vor__semihost_call(SYS_OPEN, block);
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
    return vor__semihost_call(SYS_WRITE, block) == 0u ? 0 : -1;
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
    (void)vor__semihost_call(SYS_EXIT_EXTENDED, block);
    vor__semihost_no_exit(status); /* not reached under semihosting */
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
    return vor__semihost_call(SYS_CLOSE, block) == 0u ? 0 : -1;
}
