/* SPDX-License-Identifier: MIT */
/* cli.c - input, parsing, errors and output shared by the subcommands. */
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void cli_error(const char *message)
{
    fprintf(stderr, "error: %s\n", message);
    exit(2);
}

void cli_line_error(const cli_input_t *in, const char *reason)
{
    fprintf(stderr, "error: line %lu: %s\n", in->line_number, reason);
    exit(2);
}

void cli_open(cli_input_t *in, const char *path)
{
    in->name = path;
    in->line_number = 0;
    in->buffer = NULL;
    in->capacity = 0;
    if (strcmp(path, "-") == 0) {
        in->file = stdin;
        return;
    }
    in->file = fopen(path, "r");
    if (in->file == NULL) {
        fprintf(stderr, "error: %s: %s\n", path, strerror(errno));
        exit(2);
    }
}

void cli_close(cli_input_t *in)
{
    if (in->file != stdin) {
        fclose(in->file);
    }
    free(in->buffer);
    in->buffer = NULL;
}

static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

const char *cli_next_line(cli_input_t *in)
{
    for (;;) {
        size_t length = 0;
        int c;
        while ((c = fgetc(in->file)) != EOF && c != '\n') {
            if (length + 2 > in->capacity) {
                in->capacity = in->capacity ? 2 * in->capacity : 256;
                in->buffer = realloc(in->buffer, in->capacity);
                if (in->buffer == NULL) {
                    cli_error("out of memory");
                }
            }
            in->buffer[length++] = (char)c;
        }
        if (c == EOF && length == 0) {
            return NULL;
        }
        in->line_number++;
        if (in->buffer == NULL) {
            continue; /* an empty line before any content */
        }
        in->buffer[length] = '\0';
        const char *p = in->buffer;
        while (*p != '\0' && is_blank(*p)) {
            p++;
        }
        if (*p != '\0' && *p != '#') {
            return in->buffer;
        }
    }
}

bool cli_at_end(const char *cursor)
{
    while (*cursor != '\0' && is_blank(*cursor)) {
        cursor++;
    }
    return *cursor == '\0';
}

bool cli_int32_field(const char **cursor, int32_t *value, const char **why)
{
    const char *p = *cursor;
    while (*p != '\0' && is_blank(*p)) {
        p++;
    }
    if (*p == '\0') {
        *why = "missing coordinate";
        return false;
    }
    bool negative = (*p == '-');
    if (*p == '-' || *p == '+') {
        p++;
    }
    if (*p < '0' || *p > '9') {
        *why = "not a decimal integer";
        return false;
    }
    /* accumulate the magnitude, bounded so it cannot overflow */
    unsigned long long magnitude = 0;
    while (*p >= '0' && *p <= '9') {
        magnitude = magnitude * 10u + (unsigned)(*p - '0');
        if (magnitude > 2147483648ull) {
            *why = "out of int32 range";
            return false;
        }
        p++;
    }
    if (*p != '\0' && !is_blank(*p)) {
        *why = "not a decimal integer";
        return false;
    }
    if (magnitude > (negative ? 2147483648ull : 2147483647ull)) {
        *why = "out of int32 range";
        return false;
    }
    *value = negative ? (int32_t)(-(long long)magnitude) : (int32_t)magnitude;
    *cursor = p;
    return true;
}

void cli_append(cli_output_t *out, const char *format, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, format);
        size_t room = out->capacity - out->length;
        int n = vsnprintf(out->data ? out->data + out->length : NULL, room, format, ap);
        va_end(ap);
        if (n < 0) {
            cli_error("output formatting failed");
        }
        if ((size_t)n < room) {
            out->length += (size_t)n;
            return;
        }
        out->capacity = 2 * out->capacity + (size_t)n + 4096;
        out->data = realloc(out->data, out->capacity);
        if (out->data == NULL) {
            cli_error("out of memory");
        }
    }
}

void cli_flush(cli_output_t *out)
{
    if (out->length > 0 && fwrite(out->data, 1, out->length, stdout) != out->length) {
        cli_error("writing standard output failed");
    }
    fflush(stdout);
    free(out->data);
    out->data = NULL;
    out->length = out->capacity = 0;
}

vor_point_t *cli_read_sites(const char *path, uint32_t *count)
{
    cli_input_t in;
    cli_open(&in, path);
    vor_point_t *sites = NULL;
    size_t n = 0, capacity = 0;
    const char *line;
    while ((line = cli_next_line(&in)) != NULL) {
        vor_point_t p;
        const char *why;
        const char *cursor = line;
        if (!cli_int32_field(&cursor, &p.x, &why) || !cli_int32_field(&cursor, &p.y, &why)) {
            cli_line_error(&in, why);
        }
        if (!cli_at_end(cursor)) {
            cli_line_error(&in, "too many fields (expected x y)");
        }
        if (n == VOR_MAX_SITES) {
            cli_line_error(&in, "more sites than VOR_MAX_SITES");
        }
        if (n == capacity) {
            capacity = capacity ? 2 * capacity : 1024;
            sites = realloc(sites, capacity * sizeof *sites);
            if (sites == NULL) {
                cli_error("out of memory");
            }
        }
        sites[n++] = p;
    }
    cli_close(&in);
    *count = (uint32_t)n;
    return sites;
}

double cli_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}
