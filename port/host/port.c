/* SPDX-License-Identifier: MIT */
/*
 * port/host/port.c - vor's port interface on a hosted POSIX system: the
 * tests, examples and benchmarks run as ordinary programs.
 *
 * Output goes to stdout and is flushed on every write, so a crash loses
 * nothing already printed. The counter is CLOCK_MONOTONIC in nanoseconds
 * (wall time, so not repeatable run to run: benchmarks on targets count
 * instructions instead).
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#endif

#include "../port.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* Open files; handles are indices into this table. */
#define VOR_PORT_HOST_FILES 16

static FILE *files[VOR_PORT_HOST_FILES];

const char vor_port_counter_unit[] = "ns";

void vor_port_init(void)
{
    /* Nothing to start: CLOCK_MONOTONIC always runs. */
}

void vor_port_write(const char *text, size_t n)
{
    if (n == 0u) {
        return;
    }
    (void)fwrite(text, 1u, n, stdout);
    (void)fflush(stdout);
}

void vor_port_exit(int status)
{
    (void)fflush(stdout);
    exit(status);
}

uint64_t vor_port_counter(void)
{
    struct timespec now;
    if (clock_gettime(CLOCK_MONOTONIC, &now) != 0) {
        return 0u;
    }
    return (uint64_t)now.tv_sec * 1000000000u + (uint64_t)now.tv_nsec;
}

int vor_port_file_open(const char *path)
{
    int handle;
    for (handle = 0; handle < VOR_PORT_HOST_FILES; handle++) {
        if (files[handle] == NULL) {
            files[handle] = fopen(path, "wb");
            return files[handle] != NULL ? handle : -1;
        }
    }
    return -1;
}

static FILE *file_of(int handle)
{
    if (handle < 0 || handle >= VOR_PORT_HOST_FILES) {
        return NULL;
    }
    return files[handle];
}

int vor_port_file_write(int handle, const void *data, size_t n)
{
    FILE *f = file_of(handle);
    if (f == NULL) {
        return -1;
    }
    if (n == 0u) {
        return 0;
    }
    return fwrite(data, 1u, n, f) == n ? 0 : -1;
}

int vor_port_file_close(int handle)
{
    FILE *f = file_of(handle);
    if (f == NULL) {
        return -1;
    }
    files[handle] = NULL;
    return fclose(f) == 0 ? 0 : -1;
}
