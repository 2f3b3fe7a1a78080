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

/* Where the formatter's text goes: the port's output, or a name buffer. */
typedef struct {
    char *buf; /* NULL: the port's output */
    size_t size, len;
} sink_t;

static void put_text(sink_t *to, const char *s, size_t n)
{
    if (to->buf == NULL) {
        vor_port_write(s, n);
        return;
    }
    for (size_t i = 0; i < n && to->len + 1u < to->size; i++) {
        to->buf[to->len++] = s[i];
    }
    to->buf[to->len] = '\0';
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

static void format_to(sink_t *to, const char *f, va_list ap)
{
    char out[256];
    size_t n = 0;
    for (; *f != '\0'; f++) {
        if (n > sizeof out - 48) {
            put_text(to, out, n);
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
            put_text(to, out, n);
            n = 0;
            size_t sl = 0;
            while (s[sl] != '\0') {
                sl++;
            }
            for (size_t w = sl; w < width; w++) {
                put_text(to, " ", 1);
            }
            put_text(to, s, sl);
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
    put_text(to, out, n);
}

static void test_vprintf(const char *f, va_list ap)
{
    sink_t port = {NULL, 0, 0};
    format_to(&port, f, ap);
}

void test_printf(const char *f, ...)
{
    va_list ap;
    va_start(ap, f);
    test_vprintf(f, ap);
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
#ifdef TEST_STOP_AT_FAILURE
    /* The mutation runs (tools/mutants.py): the first failed check kills
     * the mutant, so the rest of the run would tell nothing more. */
    test_printf("stopped at the first failure\n");
    vor_port_exit(1);
#else
    return false;
#endif
}

test_rng_t *test_rng_seed(test_rng_t *rng, uint64_t seed)
{
    rng->state = seed * 0x9E3779B97F4A7C15ull + 1u;
    return rng;
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

/* ---- named cases and the filter (test.h) ---- */

static const char *only = ""; /* comma-separated patterns; "" selects all */
static unsigned mode;
static const char *group;
static char case_name[96];
static unsigned long case_checks, case_failures; /* the counters at the case's start */
static unsigned long cases_passed, cases_failed, cases_listed;
static uint32_t patterns_used; /* bit i: pattern i selected a case */

void test_select(const char *patterns, unsigned flags)
{
    only = patterns;
    mode = flags;
}

void test_group(const char *name, void (*run)(void))
{
    group = name;
    run();
    group = NULL;
}

/* The length of the pattern at p (up to the next ',' or the end). */
static size_t pattern_length(const char *p)
{
    size_t n = 0;
    while (p[n] != '\0' && p[n] != ',') {
        n++;
    }
    return n;
}

/* Does the pattern p[0..n) name this case, or a group or a prefix of it
 * that ends at a '/'? */
static bool selects(const char *p, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++) {
        if (name[i] != p[i]) {
            return false;
        }
    }
    return n > 0u && (name[n] == '\0' || name[n] == '/');
}

static bool selected(const char *name)
{
    if (*only == '\0') {
        return true;
    }
    bool any = false;
    unsigned index = 0;
    for (const char *p = only;; p++, index++) {
        size_t n = pattern_length(p);
        if (selects(p, n, name)) {
            any = true;
            patterns_used |= index < 32u ? UINT32_C(1) << index : 0u;
        }
        p += n;
        if (*p == '\0') {
            return any;
        }
    }
}

bool test_case_begin(const char *f, ...)
{
    sink_t name = {case_name, sizeof case_name, 0};
    case_name[0] = '\0';
    if (group != NULL) {
        size_t n = 0;
        while (group[n] != '\0') {
            n++;
        }
        put_text(&name, group, n);
        put_text(&name, "/", 1);
    }
    va_list ap;
    va_start(ap, f);
    format_to(&name, f, ap);
    va_end(ap);
    if (!selected(case_name)) {
        return false;
    }
    if (mode & TEST_LIST) {
        test_printf("%s\n", case_name);
        cases_listed++;
        return false;
    }
    if (mode & TEST_VERBOSE) { /* first, so that a trap shows where it was */
        test_printf("case %s\n", case_name);
    }
    case_checks = passed_count + failed_count;
    case_failures = failed_count;
    return true;
}

bool test_case_end(void)
{
    unsigned long checks = passed_count + failed_count - case_checks;
    unsigned long failures = failed_count - case_failures;
    if (checks == 0u) { /* a case that cannot fail is a defect */
        failed_count++;
        cases_failed++;
        test_printf("FAIL case %s ran no check\n", case_name);
    } else if (failures != 0u) {
        cases_failed++;
        test_printf("FAIL case %s: %lu of %lu checks failed\n", case_name, failures, checks);
    } else {
        cases_passed++;
        if (mode & TEST_VERBOSE) {
            test_printf("ok   %s: %lu checks\n", case_name, checks);
        }
    }
    return false;
}

int test_finish(void)
{
    if (cases_passed + cases_failed + cases_listed == 0u) {
        failed_count++;
        test_printf("no case matches ONLY=%s\n", only);
    } else if (*only != '\0') {
        unsigned index = 0;
        for (const char *p = only;; p++, index++) {
            size_t n = pattern_length(p);
            if (index < 32u && (patterns_used & (UINT32_C(1) << index)) == 0u) {
                char pattern[64];
                sink_t copy = {pattern, sizeof pattern, 0};
                put_text(&copy, p, n);
                test_printf("note: ONLY pattern '%s' matches no case here\n", pattern);
            }
            p += n;
            if (*p == '\0') {
                break;
            }
        }
    }
    if (mode & TEST_LIST) {
        test_printf("%lu cases\n", cases_listed);
        return cases_listed != 0u ? 0 : 1;
    }
    test_printf("cases: %lu passed, %lu failed\n", cases_passed, cases_failed);
    test_summary();
    return failed_count == 0u ? 0 : 1;
}
