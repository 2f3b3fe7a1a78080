/* SPDX-License-Identifier: MIT */
/* example_io.c - see example_io.h. */
#include "example_io.h"

#include "port.h"

void example_print(const char *text)
{
    size_t n = 0;
    while (text[n] != '\0') {
        n++;
    }
    vor_port_write(text, n);
}

void example_print_uint(uint64_t value)
{
    char buf[24];
    size_t n = sizeof buf;
    do {
        buf[--n] = (char)('0' + (int)(value % 10u));
        value /= 10u;
    } while (value != 0u);
    vor_port_write(buf + n, sizeof buf - n);
}

void example_print_int(int64_t value)
{
    if (value < 0) {
        example_print("-");
        example_print_uint(0u - (uint64_t)value);
    } else {
        example_print_uint((uint64_t)value);
    }
}

uint32_t example_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

uint32_t example_brute_nearest(const vor_point_t *sites, uint32_t n, const uint32_t *first_of,
                               int32_t x, int32_t y)
{
    uint32_t best = 0;
    uint64_t best_d = UINT64_MAX;
    for (uint32_t i = 0; i < n; i++) {
        int64_t dx = (int64_t)sites[i].x - x, dy = (int64_t)sites[i].y - y;
        uint64_t d = (uint64_t)(dx * dx + dy * dy);
        if ((first_of == NULL || first_of[i] == i) && d < best_d) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

/* ---- text files for the host (build/NAME.cells, build/field.sensors) */

#define DUMP_VERTICES 64u /* far above any cell of random sites (about 6) */

static vor_point_t cell_vertices[DUMP_VERTICES];

static void file_flush(example_file_t *f)
{
    if (f->handle >= 0 && f->used > 0) {
        (void)vor_port_file_write(f->handle, f->buffer, f->used);
    }
    f->used = 0;
}

void example_file_open(example_file_t *f, const char *path)
{
    f->handle = vor_port_file_open(path);
    f->used = 0;
}

void example_file_text(example_file_t *f, const char *text)
{
    for (; *text != '\0'; text++) {
        if (f->used == sizeof f->buffer) {
            file_flush(f);
        }
        f->buffer[f->used++] = *text;
    }
}

void example_file_int(example_file_t *f, int32_t value)
{
    char digits[13];
    uint32_t n = sizeof digits, magnitude = value < 0 ? 0u - (uint32_t)value : (uint32_t)value;
    digits[--n] = '\0';
    do {
        digits[--n] = (char)('0' + (int)(magnitude % 10u));
        magnitude /= 10u;
    } while (magnitude != 0u);
    if (value < 0) {
        digits[--n] = '-';
    }
    example_file_text(f, " ");
    example_file_text(f, digits + n);
}

void example_file_close(example_file_t *f)
{
    file_flush(f);
    if (f->handle >= 0) {
        (void)vor_port_file_close(f->handle);
    }
    f->handle = -1;
}

int32_t example_dump_cells(const char *path, const vor_t *diagram, const vor_point_t *sites,
                           uint32_t n, const vor_box_t *box)
{
    static example_file_t dump;
    example_file_open(&dump, path);
    example_file_text(&dump, "box");
    example_file_int(&dump, box->x0), example_file_int(&dump, box->y0);
    example_file_int(&dump, box->x1), example_file_int(&dump, box->y1);
    for (uint32_t i = 0; i < n; i++) {
        example_file_text(&dump, "\ns");
        example_file_int(&dump, sites[i].x), example_file_int(&dump, sites[i].y);
    }
    vor_cell_iter_t cells;
    vor_cells_begin(&cells, diagram, box);
    uint32_t site, count;
    int32_t written = 0;
    int more;
    while ((more = vor_cells_next(&cells, &site, cell_vertices, DUMP_VERTICES, &count)) == 1) {
        example_file_text(&dump, "\nc");
        example_file_int(&dump, (int32_t)site), example_file_int(&dump, (int32_t)count);
        for (uint32_t k = 0; k < count; k++) {
            example_file_int(&dump, cell_vertices[k].x), example_file_int(&dump, cell_vertices[k].y);
        }
        written++;
    }
    example_file_text(&dump, "\n");
    example_file_close(&dump);
    return more == 0 ? written : -1;
}

/* The examples' checks (firmware state, not the library's). */
static uint32_t checks_passed;
static uint32_t checks_failed;

void example_check(bool ok, const char *what)
{
    if (ok) {
        checks_passed++;
    } else {
        checks_failed++;
        example_print("FAIL ");
        example_print(what);
        example_print("\n");
    }
}

int example_print_tally(void)
{
    example_print_uint(checks_passed);
    example_print(" passed, ");
    example_print_uint(checks_failed);
    example_print(" failed\n");
    return (checks_failed == 0u) ? 0 : 1;
}
