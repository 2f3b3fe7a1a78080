/* SPDX-License-Identifier: MIT */
/*
 * tests/reference/vor_interpolate.c - vor's side of the interpolation
 * reference (tests/reference/compare_interpolate.py): every coordinate of
 * vor_sibson and vor_laplace and the exact values of vor_interpolate and
 * vor_interpolate_laplace, unreduced, for a comparison with CGAL
 * (cgal_interpolate.cpp) as exact rationals. Host tests only.
 *
 *   vor-interpolate SITES QUERIES
 *
 * SITES: "x y value" lines; QUERIES: "x y" lines. For each query four
 * lines, numbers in hexadecimal, most significant digit first:
 *   s X Y DEN ID:WEIGHT ...   vor_sibson: weight / DEN per neighbour
 *   l X Y DEN ID:WEIGHT ...   vor_laplace
 *   S X Y VALUE SIGN NUM DEN  vor_interpolate: value rounded, sign, |num|, den
 *   L X Y VALUE SIGN NUM DEN  vor_interpolate_laplace
 * or "X Y outside" (VOR_ERR_OUTSIDE), "X Y error E" (any other error).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "vor.h"

typedef int (*coordinates_fn)(const vor_t *, vor_point_t, uint32_t, void *, size_t,
                              vor_coordinates_t *);
typedef int (*interpolate_fn)(const vor_t *, const int32_t *, vor_point_t, uint32_t, void *,
                              size_t, vor_interpolation_t *);

static void *scratch;
static size_t scratch_bytes;

static void grow(uint32_t k)
{
    free(scratch);
    scratch_bytes = VOR_SIBSON_SCRATCH_BYTES(k);
    scratch = malloc(scratch_bytes);
    if (scratch == NULL) {
        fprintf(stderr, "vor-interpolate: out of memory\n");
        exit(1);
    }
}

static void hex(const uint32_t *a, uint32_t limbs)
{
    printf(" ");
    for (uint32_t i = limbs; i-- > 0;) {
        printf("%08x", (unsigned)a[i]);
    }
}

/* Prints the tail of a line for err, 1 if it was VOR_OK. */
static int status(int err)
{
    if (err == VOR_ERR_OUTSIDE) {
        printf(" outside\n");
    } else if (err != VOR_OK) {
        printf(" error %d\n", err);
    }
    return err == VOR_OK;
}

static void coordinates(char tag, coordinates_fn fn, const vor_t *d, vor_point_t q)
{
    vor_coordinates_t c;
    int err = fn(d, q, VOR_NO_HINT, scratch, scratch_bytes, &c);
    if (err == VOR_ERR_NOMEM) {
        grow(c.count);
        err = fn(d, q, VOR_NO_HINT, scratch, scratch_bytes, &c);
    }
    printf("%c %d %d", tag, (int)q.x, (int)q.y);
    if (status(err)) {
        hex(c.denominator, c.limbs);
        for (uint32_t i = 0; i < c.count; i++) {
            printf(" %u:", (unsigned)c.sites[i]);
            hex(c.weights + (size_t)i * c.limbs, c.limbs);
        }
        printf("\n");
    }
}

static void value(char tag, interpolate_fn fn, const vor_t *d, const int32_t *values, vor_point_t q)
{
    vor_interpolation_t v;
    int err = fn(d, values, q, VOR_NO_HINT, scratch, scratch_bytes, &v);
    if (err == VOR_ERR_NOMEM) {
        grow(v.neighbours);
        err = fn(d, values, q, VOR_NO_HINT, scratch, scratch_bytes, &v);
    }
    printf("%c %d %d", tag, (int)q.x, (int)q.y);
    if (status(err)) {
        printf(" %d %d", (int)v.value, (int)v.sign);
        hex(v.numerator, v.limbs);
        hex(v.denominator, v.limbs);
        printf("\n");
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: vor-interpolate SITES QUERIES\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "r");
    if (f == NULL) {
        perror(argv[1]);
        return 2;
    }
    size_t n = 0, capacity = 16;
    vor_point_t *sites = malloc(capacity * sizeof *sites);
    int32_t *values = malloc(capacity * sizeof *values);
    long x, y, w;
    while (sites != NULL && values != NULL && fscanf(f, "%ld %ld %ld", &x, &y, &w) == 3) {
        if (n == capacity) {
            capacity *= 2u;
            sites = realloc(sites, capacity * sizeof *sites);
            values = realloc(values, capacity * sizeof *values);
            if (sites == NULL || values == NULL) {
                break;
            }
        }
        sites[n].x = (int32_t)x;
        sites[n].y = (int32_t)y;
        values[n] = (int32_t)w;
        n++;
    }
    fclose(f);
    if (sites == NULL || values == NULL || n == 0u) {
        fprintf(stderr, "vor-interpolate: no sites, or out of memory\n");
        return 1;
    }
    vor_t d;
    void *arena = malloc(VOR_ARENA_BYTES(n));
    int err = (arena == NULL) ? VOR_ERR_NOMEM : vor_init(&d, arena, VOR_ARENA_BYTES(n), (uint32_t)n);
    if (err == VOR_OK) {
        err = vor_build(&d, sites, (uint32_t)n, NULL, NULL);
    }
    if (err != VOR_OK) {
        fprintf(stderr, "vor-interpolate: vor_init/vor_build: %d\n", err);
        return 1;
    }
    grow(8);
    f = fopen(argv[2], "r");
    if (f == NULL) {
        perror(argv[2]);
        return 2;
    }
    while (fscanf(f, "%ld %ld", &x, &y) == 2) {
        vor_point_t q = {(int32_t)x, (int32_t)y};
        coordinates('s', vor_sibson, &d, q);
        coordinates('l', vor_laplace, &d, q);
        value('S', vor_interpolate, &d, values, q);
        value('L', vor_interpolate_laplace, &d, values, q);
    }
    fclose(f);
    free(scratch);
    free(arena);
    free(sites);
    free(values);
    return 0;
}
