/* SPDX-License-Identifier: MIT */
/* harness.c - formatter, counters and random numbers for the tests. */
#include "test.h"

static unsigned long passed_count;
static unsigned long failed_count;

unsigned long test_failures(void)
{
    return failed_count;
}

void test_summary(void)
{
    test_printf("%lu passed, %lu failed\n", passed_count, failed_count);
}

static void put_text(const char *s, size_t n)
{
    vor_port_write(s, n);
}

static size_t format_unsigned(char *buf, unsigned long long v, unsigned base)
{
    char tmp[24];
    size_t n = 0;
    do {
        unsigned digit = (unsigned)(v % base);
        tmp[n++] = (char)(digit < 10 ? '0' + digit : 'a' + digit - 10);
        v /= base;
    } while (v != 0);
    for (size_t i = 0; i < n; i++) {
        buf[i] = tmp[n - 1 - i];
    }
    return n;
}

static void test_vprintf(const char *f, va_list ap)
{
    char out[256];
    size_t n = 0;
    for (; *f != '\0'; f++) {
        if (n > sizeof out - 48) {
            put_text(out, n);
            n = 0;
        }
        if (*f != '%') {
            out[n++] = *f;
            continue;
        }
        f++;
        char pad = ' ';
        unsigned width = 0;
        if (*f == '0') {
            pad = '0';
            f++;
        }
        while (*f >= '0' && *f <= '9') {
            width = width * 10 + (unsigned)(*f++ - '0');
        }
        int longs = 0;
        bool size = false;
        while (*f == 'l') {
            longs++;
            f++;
        }
        if (*f == 'z') {
            size = true;
            f++;
        }
        char num[24];
        size_t len = 0;
        bool negative = false;
        switch (*f) {
        case 'd':
        case 'i': {
            long long v = (longs >= 2) ? va_arg(ap, long long)
                          : (longs == 1) ? va_arg(ap, long)
                                         : va_arg(ap, int);
            negative = v < 0;
            unsigned long long m = negative ? 0ull - (unsigned long long)v
                                            : (unsigned long long)v;
            len = format_unsigned(num, m, 10);
            break;
        }
        case 'u':
        case 'x': {
            unsigned long long v = size ? va_arg(ap, size_t)
                                   : (longs >= 2) ? va_arg(ap, unsigned long long)
                                   : (longs == 1) ? va_arg(ap, unsigned long)
                                                  : va_arg(ap, unsigned);
            len = format_unsigned(num, v, *f == 'x' ? 16u : 10u);
            break;
        }
        case 'c':
            num[len++] = (char)va_arg(ap, int);
            break;
        case 's': {
            const char *s = va_arg(ap, const char *);
            put_text(out, n);
            n = 0;
            size_t sl = 0;
            while (s[sl] != '\0') {
                sl++;
            }
            for (size_t w = sl; w < width; w++) {
                put_text(" ", 1);
            }
            put_text(s, sl);
            continue;
        }
        default:
            num[len++] = '%';
            break;
        }
        size_t total = len + (negative ? 1u : 0u);
        if (negative && pad == '0') {
            out[n++] = '-';
        }
        for (size_t w = total; w < width; w++) {
            out[n++] = pad;
        }
        if (negative && pad != '0') {
            out[n++] = '-';
        }
        for (size_t i = 0; i < len; i++) {
            out[n++] = num[i];
        }
    }
    put_text(out, n);
}

void test_printf(const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    test_vprintf(format, ap);
    va_end(ap);
}

bool test_check(bool ok, const char *file, int line, const char *format, ...)
{
    if (ok) {
        passed_count++;
        return true;
    }
    failed_count++;
    if (failed_count <= 50) {
        va_list ap;
        test_printf("FAIL %s:%d: ", file, line);
        va_start(ap, format);
        test_vprintf(format, ap);
        va_end(ap);
        test_printf("\n");
    }
    return false;
}

void test_rng_seed(test_rng_t *rng, uint64_t seed)
{
    rng->state = seed * 0x9E3779B97F4A7C15ull + 1u;
}

uint32_t test_rng_u32(test_rng_t *rng)
{
    uint64_t x = rng->state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    rng->state = x;
    return (uint32_t)(x >> 32);
}

int32_t test_rng_range(test_rng_t *rng, int32_t lo, int32_t hi)
{
    uint32_t span = (uint32_t)hi - (uint32_t)lo;
    uint32_t r = test_rng_u32(rng);
    if (span != UINT32_MAX) {
        r %= span + 1u;
    }
    return (int32_t)((uint32_t)lo + r);
}

bool test_same_bytes(const void *a, const void *b, size_t n)
{
    const uint8_t *x = a, *y = b;
    for (size_t i = 0; i < n; i++) {
        if (x[i] != y[i]) {
            return false;
        }
    }
    return true;
}

void test_copy_bytes(void *to, const void *from, size_t n)
{
    uint8_t *t = to;
    const uint8_t *f = from;
    for (size_t i = 0; i < n; i++) {
        t[i] = f[i];
    }
}

uint32_t test_predicate_calls(const vor_t *d)
{
    vor_stats_t s;
    if (vor_stats(d, &s) != VOR_OK) {
        return UINT32_MAX; /* a library without VOR_STATS: no count to compare */
    }
    uint32_t n = s.orient2d_perturbed + s.incircle_perturbed + s.closer_perturbed;
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        n += s.orient2d[t] + s.incircle[t] + s.closer[t];
    }
    return n;
}
