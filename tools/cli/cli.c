/* SPDX-License-Identifier: MIT */
/* cli.c - input, parsing, errors and output shared by the subcommands. */
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

/* The tool is one short-lived process: the --scale setting, the quoted
 * reason of the last bad field and the pending temporary output are
 * process-wide, which keeps every command's code free of them. */
static char field_reason[200];
static char pending_output[4096];

static const char *display_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}

/* atexit: an error exit must not leave a half-written temporary file. */
static void remove_pending_output(void)
{
    if (pending_output[0] != '\0') {
        remove(pending_output);
        pending_output[0] = '\0';
    }
}

void cli_error(const char *message)
{
    fprintf(stderr, "error: %s\n", message);
    exit(2);
}

void cli_line_error(const cli_input_t *in, const char *reason)
{
    fprintf(stderr, "error: %s:%lu: %s\n", display_name(in->name), in->line_number, reason);
    exit(2);
}

static void path_error(const char *path, int error)
{
    fprintf(stderr, "error: %s: %s\n", display_name(path), strerror(error));
    exit(2);
}

const char *cli_error_text(int err)
{
    switch (err) {
    case VOR_ERR_ARG: return "VOR_ERR_ARG: invalid argument (a NULL pointer or a value out of range)";
    case VOR_ERR_NOMEM: return "VOR_ERR_NOMEM: the arena is smaller than VOR_ARENA_BYTES";
    case VOR_ERR_ALIGN: return "VOR_ERR_ALIGN: the arena is not VOR_ARENA_ALIGN-aligned";
    case VOR_ERR_FULL: return "VOR_ERR_FULL: the diagram holds max_sites sites already";
    case VOR_ERR_DUPLICATE: return "VOR_ERR_DUPLICATE: the point is a site already";
    case VOR_ERR_INVALID: return "VOR_ERR_INVALID: vor_validate found a broken invariant";
    case VOR_ERR_EMPTY: return "VOR_ERR_EMPTY: a query on a diagram without sites";
    case VOR_ERR_BUFFER: return "VOR_ERR_BUFFER: the caller's buffer is too small";
    case VOR_ERR_CONFIG: return "VOR_ERR_CONFIG: library and tool were compiled with different vor_config.h";
    case VOR_ERR_STOPPED: return "VOR_ERR_STOPPED: the raster's flush asked to stop";
    case VOR_ERR_CONSTRAINED: return "VOR_ERR_CONSTRAINED: a constrained edge ends at the site";
    case VOR_ERR_OUTSIDE: return "VOR_ERR_OUTSIDE: the point is outside the convex hull of the sites";
    case VOR_ERR_POLYGON: return "VOR_ERR_POLYGON: the room is not a simple polygon";
    default: return "unknown error code";
    }
}

void cli_library_error(const char *call, int err)
{
    fprintf(stderr, "error: %s: %s\n", call, cli_error_text(err));
    exit(2);
}

void cli_usage_error(const char *command, const char *usage, const char *problem, const char *argument)
{
    if (argument != NULL) {
        fprintf(stderr, "error: vor %s: %s '%s'\n", command, problem, argument);
    } else {
        fprintf(stderr, "error: vor %s: %s\n", command, problem);
    }
    fprintf(stderr, "%s\nrun 'vor %s --help' for the formats and an example\n", usage, command);
    exit(2);
}

void cli_arguments_begin(cli_arguments_t *a, int argc, char **argv, const char *command, const char *usage,
                         const cli_option_t *options, size_t option_count)
{
    a->argc = argc;
    a->argv = argv;
    a->next = 0;
    a->command = command;
    a->usage = usage;
    a->options = options;
    a->option_count = option_count;
}

int cli_next_argument(cli_arguments_t *a)
{
    static const cli_option_t scale_option = {"--scale", 1};
    for (;;) {
        if (a->next == a->argc) {
            return CLI_END;
        }
        char *text = a->argv[a->next++];
        if (text[0] != '-' || text[1] == '\0') {
            a->values[0] = text;
            return CLI_POSITIONAL;
        }
        /* "--name=values": only long options take the '=' form */
        char *equals = (text[1] == '-') ? strchr(text, '=') : NULL;
        size_t name_length = equals != NULL ? (size_t)(equals - text) : strlen(text);
        const cli_option_t *option = NULL;
        int index = -1;
        for (size_t k = 0; k < a->option_count && option == NULL; k++) {
            if (strlen(a->options[k].name) == name_length && strncmp(a->options[k].name, text, name_length) == 0) {
                option = &a->options[k];
                index = (int)k;
            }
        }
        if (option == NULL && name_length == strlen(scale_option.name) &&
            strncmp(scale_option.name, text, name_length) == 0) {
            option = &scale_option;
        }
        if (option == NULL) {
            cli_usage_error(a->command, a->usage, "unknown option", text);
        }
        if (equals != NULL) {
            if (option->values == 0u) {
                cli_usage_error(a->command, a->usage, "this option takes no value", text);
            }
            /* several values: comma-separated (the last keeps any more commas) */
            unsigned commas = 0;
            for (const char *c = equals + 1; *c != '\0'; c++) {
                commas += (*c == ',');
            }
            if (commas + 1u < option->values) {
                char problem[80];
                snprintf(problem, sizeof problem, "expected %u comma-separated values in", option->values);
                cli_usage_error(a->command, a->usage, problem, text);
            }
            char *value = equals + 1;
            for (unsigned v = 0; v < option->values; v++) {
                a->values[v] = value;
                if (v + 1u < option->values) {
                    value = strchr(value, ',');
                    *value++ = '\0';
                }
            }
        } else {
            if (a->argc - a->next < (int)option->values) {
                cli_usage_error(a->command, a->usage, "missing value after", text);
            }
            for (unsigned v = 0; v < option->values; v++) {
                a->values[v] = a->argv[a->next++];
            }
        }
        if (option != &scale_option) {
            return index;
        }
        cli_set_scale(a->values[0]);
    }
}

FILE *cli_create_output(const char *path)
{
    struct stat status;
    if (stat(path, &status) == 0 && S_ISDIR(status.st_mode)) {
        path_error(path, EISDIR);
    }
    if (strlen(path) + 8 > sizeof pending_output) {
        path_error(path, ENAMETOOLONG);
    }
    snprintf(pending_output, sizeof pending_output, "%s.XXXXXX", path);
    static bool cleanup_registered = false;
    if (!cleanup_registered) {
        atexit(remove_pending_output);
        cleanup_registered = true;
    }
    int fd = mkstemp(pending_output);
    if (fd < 0) {
        int error = errno;
        pending_output[0] = '\0';
        path_error(path, error);
    }
    /* mkstemp makes the file private; a plain output file gets the umask */
    mode_t mask = umask(0);
    umask(mask);
    FILE *file = (fchmod(fd, 0666 & ~mask) == 0) ? fdopen(fd, "wb") : NULL;
    if (file == NULL) {
        path_error(path, errno);
    }
    return file;
}

void cli_commit_output(FILE *file, const char *path)
{
    bool written = !ferror(file);
    int error = errno;
    if (fclose(file) != 0 && written) {
        written = false;
        error = errno;
    }
    if (!written) {
        path_error(path, error);
    }
    if (rename(pending_output, path) != 0) {
        path_error(path, errno);
    }
    pending_output[0] = '\0';
}

void cli_open(cli_input_t *in, const char *path)
{
    in->name = path;
    in->line_number = 0;
    in->buffer = NULL;
    in->capacity = 0;
    in->header_allowed = true;
    if (strcmp(path, "-") == 0) {
        in->file = stdin;
        return;
    }
    in->file = fopen(path, "r");
    if (in->file == NULL) {
        path_error(path, errno);
    }
    /* fopen opens a directory for reading on Linux; reading it fails later */
    struct stat status;
    if (fstat(fileno(in->file), &status) == 0 && S_ISDIR(status.st_mode)) {
        path_error(path, EISDIR);
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

/* A header: a CSV line every field of which starts with a letter or '"'.
 * Every record of every input format (points, weighted sites, predicates,
 * operations, dumps) holds a number among its fields, so a header cannot
 * be a record: a first line such as "i,0,0" is read, never dropped. */
static bool is_header(const char *line)
{
    if (strchr(line, ',') == NULL) {
        return false;
    }
    for (const char *field = line;;) {
        while (is_blank(*field)) {
            field++;
        }
        char c = *field;
        if (c != '"' && !(c >= 'a' && c <= 'z') && !(c >= 'A' && c <= 'Z')) {
            return false;
        }
        field = strchr(field, ',');
        if (field == NULL) {
            return true;
        }
        field++;
    }
}

/* A CSV line: checks that every comma-separated field is one non-empty
 * token, then turns the commas into blanks for the field parsers. */
static void split_csv(cli_input_t *in, char *line)
{
    unsigned field = 1;
    char *start = line;
    for (char *p = line;; p++) {
        if (*p != ',' && *p != '\0') {
            continue;
        }
        char *first = start, *last = p;
        while (first < last && is_blank(*first)) {
            first++;
        }
        while (last > first && is_blank(last[-1])) {
            last--;
        }
        char reason[120];
        if (first == last) {
            snprintf(reason, sizeof reason, "CSV field %u is empty", field);
            cli_line_error(in, reason);
        }
        for (char *q = first; q < last; q++) {
            if (is_blank(*q)) {
                snprintf(reason, sizeof reason,
                         "CSV field %u holds a blank (separate fields by commas or by blanks, not both)", field);
                cli_line_error(in, reason);
            }
        }
        if (*p == '\0') {
            return;
        }
        *p = ' ';
        start = p + 1;
        field++;
    }
}

const char *cli_next_line(cli_input_t *in)
{
    for (;;) {
        size_t length = 0;
        int c;
        while ((c = fgetc(in->file)) != EOF && c != '\n') {
            if (c == '\0') {
                /* a NUL would end the line early and drop its site silently */
                char reason[120];
                in->line_number++;
                snprintf(reason, sizeof reason, "NUL byte at column %zu (a binary file?)", length + 1);
                cli_line_error(in, reason);
            }
            if (length + 2 > in->capacity) {
                in->capacity = in->capacity ? 2 * in->capacity : 256;
                in->buffer = realloc(in->buffer, in->capacity);
                if (in->buffer == NULL) {
                    cli_error("out of memory");
                }
            }
            in->buffer[length++] = (char)c;
        }
        if (c == EOF && ferror(in->file)) {
            path_error(in->name, errno);
        }
        if (c == EOF && length == 0) {
            return NULL;
        }
        in->line_number++;
        if (in->buffer == NULL) {
            continue; /* an empty line before any content */
        }
        in->buffer[length] = '\0';
        /* a UTF-8 byte-order mark, as spreadsheets write it, opens no field */
        if (in->line_number == 1u && length >= 3u && memcmp(in->buffer, "\xEF\xBB\xBF", 3) == 0) {
            memmove(in->buffer, in->buffer + 3, length - 2u);
        }
        const char *p = in->buffer;
        while (*p != '\0' && is_blank(*p)) {
            p++;
        }
        if (*p == '\0' || *p == '#') {
            continue;
        }
        bool header = in->header_allowed && is_header(p);
        in->header_allowed = false;
        if (header) {
            continue;
        }
        if (strchr(p, ',') != NULL) {
            split_csv(in, in->buffer);
        }
        return in->buffer;
    }
}

bool cli_at_end(const char *cursor)
{
    while (*cursor != '\0' && is_blank(*cursor)) {
        cursor++;
    }
    return *cursor == '\0';
}

/* The field at p (up to a blank or the end), quoted in field_reason after
 * the problem. */
static const char *quote_field(const char *problem, const char *p)
{
    int length = 0;
    while (p[length] != '\0' && !is_blank(p[length]) && length < 60) {
        length++;
    }
    snprintf(field_reason, sizeof field_reason, "%s: '%.*s'", problem, length, p);
    return field_reason;
}

/* A decimal integer field of magnitude at most `most` (negative: most + 1),
 * named `range` in the error; the int32 and int64 fields below. `missing`
 * is the error for no field, `decimal` the one for a decimal number. */
static bool integer_field(const char **cursor, unsigned long long most, const char *range,
                          const char *missing, const char *decimal, bool *negative_out,
                          unsigned long long *magnitude_out, const char **why)
{
    const char *p = *cursor;
    while (*p != '\0' && is_blank(*p)) {
        p++;
    }
    if (*p == '\0') {
        *why = missing;
        return false;
    }
    const char *field = p;
    bool negative = (*p == '-');
    if (*p == '-' || *p == '+') {
        p++;
    }
    if (*p < '0' || *p > '9') {
        *why = quote_field("not a decimal integer", field);
        return false;
    }
    /* accumulate the magnitude, bounded so it cannot overflow */
    unsigned long long magnitude = 0;
    while (*p >= '0' && *p <= '9') {
        unsigned digit = (unsigned)(*p - '0');
        if (magnitude > (most + 1u - digit) / 10u) {
            *why = quote_field(range, field);
            return false;
        }
        magnitude = magnitude * 10u + digit;
        p++;
    }
    if (*p != '\0' && !is_blank(*p)) {
        *why = quote_field(*p == '.' || *p == 'e' || *p == 'E' ? decimal : "not a decimal integer",
                           field);
        return false;
    }
    if (magnitude > (negative ? most + 1u : most)) {
        *why = quote_field(range, field);
        return false;
    }
    *negative_out = negative;
    *magnitude_out = magnitude;
    *cursor = p;
    return true;
}

bool cli_int32_field(const char **cursor, int32_t *value, const char **why)
{
    bool negative;
    unsigned long long magnitude;
    if (!integer_field(cursor, 2147483647ull, "out of int32 range", "missing coordinate",
                       "not a decimal integer (use --scale S for decimal coordinates)", &negative,
                       &magnitude, why)) {
        return false;
    }
    *value = negative ? (int32_t)(-(long long)magnitude) : (int32_t)magnitude;
    return true;
}

/* An exact decimal: (-1)^negative * digits * 10^exponent, digits[0] the
 * most significant, no leading or trailing zeros (count 0: the value 0). */
#define DECIMAL_DIGITS 100
typedef struct {
    bool negative;
    unsigned count;
    uint8_t digits[DECIMAL_DIGITS];
    long exponent;
} decimal_t;

/* Parses [+-]D[.D][(e|E)[+-]D] (digits on at least one side of the point)
 * up to a blank or the end; returns the end, or NULL with *why set. */
static const char *parse_decimal(const char *p, decimal_t *d, const char **why)
{
    const char *field = p;
    d->negative = (*p == '-');
    d->count = 0;
    d->exponent = 0;
    if (*p == '-' || *p == '+') {
        p++;
    }
    bool point = false, any_digit = false;
    long pending_zeros = 0; /* zeros after the last nonzero digit */
    for (;; p++) {
        if (*p == '.' && !point) {
            point = true;
            continue;
        }
        if (*p < '0' || *p > '9') {
            break;
        }
        any_digit = true;
        d->exponent -= point;
        if (*p == '0') {
            pending_zeros += (d->count > 0); /* leading zeros carry nothing */
            continue;
        }
        if ((long)d->count + pending_zeros + 1 > DECIMAL_DIGITS) {
            *why = quote_field("more than 100 significant digits", field);
            return NULL;
        }
        for (; pending_zeros > 0; pending_zeros--) {
            d->digits[d->count++] = 0;
        }
        d->digits[d->count++] = (uint8_t)(*p - '0');
    }
    d->exponent += pending_zeros;
    if (!any_digit) {
        *why = quote_field("not a decimal number", field);
        return NULL;
    }
    if (*p == 'e' || *p == 'E') {
        p++;
        bool exponent_negative = (*p == '-');
        if (*p == '-' || *p == '+') {
            p++;
        }
        if (*p < '0' || *p > '9') {
            *why = quote_field("not a decimal number", field);
            return NULL;
        }
        long e = 0;
        for (; *p >= '0' && *p <= '9'; p++) {
            /* saturates: beyond 10^100000 no nonzero value fits int32 */
            e = (e < 100000) ? e * 10 + (*p - '0') : e;
        }
        d->exponent += exponent_negative ? -e : e;
    }
    if (*p != '\0' && !is_blank(*p)) {
        *why = quote_field("not a decimal number", field);
        return NULL;
    }
    return p;
}

static decimal_t scale;
static bool scaled = false;

void cli_set_scale(const char *text)
{
    const char *why;
    const char *end = parse_decimal(text, &scale, &why);
    if (end == NULL || !cli_at_end(end) || scale.negative || scale.count == 0) {
        fprintf(stderr, "error: --scale: expected a positive decimal number such as 1000 or 0.5, got '%s'\n",
                text);
        exit(2);
    }
    scaled = true;
}

/* A decimal field times scale^factors (1: a coordinate, 2: a squared
 * length), rounded to the nearest integer, ties away from zero, computed
 * exactly on digit strings; its magnitude at most `most` (negative:
 * most + 1), else *why names `range`. */
static bool scaled_field(const char **cursor, unsigned factors, unsigned long long most,
                         const char *range, const char *missing, bool *negative_out,
                         unsigned long long *magnitude_out, const char **why)
{
    const char *p = *cursor;
    while (*p != '\0' && is_blank(*p)) {
        p++;
    }
    if (*p == '\0') {
        *why = missing;
        return false;
    }
    const char *field = p;
    decimal_t v;
    const char *end = parse_decimal(p, &v, why);
    if (end == NULL) {
        return false;
    }
    /* the exact product of the digit strings, least significant first */
    uint8_t product[3 * DECIMAL_DIGITS + 1], next[3 * DECIMAL_DIGITS + 1];
    unsigned length = v.count;
    long exponent = v.exponent;
    memset(product, 0, sizeof product);
    for (unsigned i = 0; i < v.count; i++) {
        product[i] = v.digits[v.count - 1u - i];
    }
    for (unsigned f = 0; f < factors; f++) {
        memset(next, 0, sizeof next);
        for (unsigned i = 0; i < length; i++) {
            unsigned carry = 0;
            unsigned a = product[i];
            for (unsigned j = 0; j < scale.count; j++) {
                unsigned t = next[i + j] + a * scale.digits[scale.count - 1u - j] + carry;
                next[i + j] = (uint8_t)(t % 10u);
                carry = t / 10u;
            }
            for (unsigned k = i + scale.count; carry != 0; k++) {
                unsigned t = next[k] + carry;
                next[k] = (uint8_t)(t % 10u);
                carry = t / 10u;
            }
        }
        memcpy(product, next, sizeof product);
        length += scale.count;
        exponent += scale.exponent;
    }
    /* value = product * 10^exponent; ties away from zero need only the first
     * digit after the point: 5 or more rounds the magnitude up. The checks
     * come before each step, so the magnitude never overflows. */
    const unsigned long long limit = v.negative ? most + 1u : most;
    unsigned long long magnitude = 0;
    for (long i = (long)length - 1; i >= 0; i--) {
        if (i + exponent < 0) {
            break;
        }
        if (magnitude > (limit - product[i]) / 10u) {
            *why = quote_field(range, field);
            return false;
        }
        magnitude = magnitude * 10u + product[i];
    }
    for (long k = 0; k < exponent && magnitude != 0; k++) {
        if (magnitude > limit / 10u) {
            *why = quote_field(range, field);
            return false;
        }
        magnitude *= 10u;
    }
    long first_fraction = -1 - exponent;
    if (first_fraction >= 0 && first_fraction < (long)length && product[first_fraction] >= 5u) {
        if (magnitude == limit) {
            *why = quote_field(range, field);
            return false;
        }
        magnitude++;
    }
    *negative_out = v.negative;
    *magnitude_out = magnitude;
    *cursor = end;
    return true;
}

bool cli_coordinate_field(const char **cursor, int32_t *value, const char **why)
{
    if (!scaled) {
        return cli_int32_field(cursor, value, why);
    }
    bool negative;
    unsigned long long magnitude;
    if (!scaled_field(cursor, 1, 2147483647ull, "out of int32 range after --scale",
                      "missing coordinate", &negative, &magnitude, why)) {
        return false;
    }
    *value = negative ? (int32_t)(-(long long)magnitude) : (int32_t)magnitude;
    return true;
}

bool cli_squared_field(const char **cursor, int64_t *value, const char **why)
{
    bool negative;
    unsigned long long magnitude;
    if (!scaled) {
        if (!integer_field(cursor, 9223372036854775807ull, "out of int64 range", "missing weight",
                           "not a decimal integer (use --scale S for decimal weights)", &negative,
                           &magnitude, why)) {
            return false;
        }
        *value = negative ? (int64_t)(0u - magnitude) : (int64_t)magnitude;
        return true;
    }
    if (!scaled_field(cursor, 2, 9223372036854775807ull, "out of int64 range after --scale",
                      "missing weight", &negative, &magnitude, why)) {
        return false;
    }
    *value = negative ? (int64_t)(0u - magnitude) : (int64_t)magnitude;
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
    /* stdout is buffered: a full disk may show only at the flush */
    if ((out->length > 0 && fwrite(out->data, 1, out->length, stdout) != out->length) ||
        fflush(stdout) != 0) {
        fprintf(stderr, "error: <stdout>: %s\n", strerror(errno));
        exit(2);
    }
    free(out->data);
    out->data = NULL;
    out->length = out->capacity = 0;
}

uint32_t cli_read_points(const char *path, const char *third, cli_field_parser_t *parse, size_t size,
                         vor_point_t **points, void **fields)
{
    char expected[100];
    if (parse != NULL) {
        snprintf(expected, sizeof expected, "x y %s or x,y,%s", third, third);
    } else {
        snprintf(expected, sizeof expected, "x y or x,y");
    }
    cli_input_t in;
    cli_open(&in, path);
    size_t n = 0, capacity = 0;
    unsigned char *values = NULL;
    *points = NULL;
    for (const char *line; (line = cli_next_line(&in)) != NULL;) {
        vor_point_t p;
        union {
            int32_t i32;
            int64_t i64;
        } field; /* room for any field, aligned for it */
        const char *why = NULL;
        const char *cursor = line;
        char reason[300];
        if (!cli_coordinate_field(&cursor, &p.x, &why) || !cli_coordinate_field(&cursor, &p.y, &why) ||
            ((parse != NULL) && !parse(&cursor, &field, &why))) {
            snprintf(reason, sizeof reason, "%s (expected %s)", why, expected);
            cli_line_error(&in, reason);
        }
        if (!cli_at_end(cursor)) {
            snprintf(reason, sizeof reason, "too many fields (expected %s)", expected);
            cli_line_error(&in, reason);
        }
        if (n == VOR_MAX_SITES) {
            cli_line_error(&in, "more sites than VOR_MAX_SITES");
        }
        if (n == capacity) {
            capacity = (capacity != 0u) ? 2u * capacity : 1024u;
            *points = realloc(*points, capacity * sizeof **points);
            if (parse != NULL) {
                values = realloc(values, capacity * size);
            }
            if ((*points == NULL) || ((parse != NULL) && (values == NULL))) {
                cli_error("out of memory");
            }
        }
        (*points)[n] = p;
        if (parse != NULL) {
            memcpy(values + n * size, &field, size);
        }
        n++;
    }
    cli_close(&in);
    if (fields != NULL) {
        *fields = values;
    }
    return (uint32_t)n;
}

vor_point_t *cli_read_sites(const char *path, uint32_t *count)
{
    vor_point_t *sites;
    *count = cli_read_points(path, NULL, NULL, 0, &sites, NULL);
    return sites;
}

uint32_t cli_site_colour(uint32_t site)
{
    uint32_t c = (uint32_t)(site * 2654435761u) & 0x1FFFFFu;
    return ((128u + (c & 127u)) << 16) | ((128u + ((c >> 7) & 127u)) << 8) | (128u + (c >> 14));
}

double cli_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int compare_triangles(const void *a, const void *b)
{
    const uint32_t *x = a, *y = b;
    for (int i = 0; i < 3; i++) {
        if (x[i] != y[i]) {
            return (x[i] < y[i]) ? -1 : 1;
        }
    }
    return 0;
}

size_t cli_append_triangle_iter(vor_triangle_iter_t *it, size_t most, cli_output_t *out)
{
    uint32_t (*triangles)[3] = malloc((most + 1u) * sizeof *triangles);
    if (triangles == NULL) {
        cli_error("out of memory");
    }
    size_t count = 0;
    uint32_t ids[3];
    while ((count < most) && vor_triangles_next(it, ids)) {
        unsigned first = (ids[1] < ids[0]) ? 1u : 0u;
        first = (ids[2] < ids[first]) ? 2u : first;
        for (unsigned k = 0; k < 3u; k++) {
            triangles[count][k] = ids[(first + k) % 3u];
        }
        count++;
    }
    qsort(triangles, count, sizeof *triangles, compare_triangles);
    for (size_t t = 0; t < count; t++) {
        cli_append(out, "t %u %u %u\n", triangles[t][0], triangles[t][1], triangles[t][2]);
    }
    free(triangles);
    return count;
}

size_t cli_append_triangles(const vor_t *d, cli_output_t *out)
{
    vor_memory_t memory;
    vor_memory(d, &memory);
    vor_triangle_iter_t it;
    vor_triangles_begin(&it, d);
    return cli_append_triangle_iter(&it, memory.triangles, out);
}

void *cli_diagram(vor_t *d, uint32_t max_sites)
{
    uint32_t capacity = (max_sites < 1u) ? 1u : max_sites;
    void *arena = malloc(VOR_ARENA_BYTES(capacity));
    if (arena == NULL) {
        cli_error("out of memory");
    }
    int err = vor_init(d, arena, VOR_ARENA_BYTES(capacity), capacity);
    if (err != VOR_OK) {
        cli_library_error("vor_init", err);
    }
    return arena;
}

void *cli_query_diagram(vor_t *d, const vor_point_t *sites, uint32_t n, const char *sites_path,
                        const char *queries_path, const char *no_sites, vor_point_t **queries,
                        uint32_t *query_count)
{
    *queries = cli_read_sites(queries_path, query_count);
    if (n == 0u && *query_count > 0u) {
        fprintf(stderr, "error: %s: %s\n", sites_path, no_sites);
        exit(2);
    }
    void *arena = cli_diagram(d, n);
    int err = vor_build(d, sites, n, NULL, NULL);
    if (err != VOR_OK) {
        cli_library_error("vor_build", err);
    }
    return arena;
}

void cli_append_wide(cli_output_t *out, cli_wide_t v)
{
    __extension__ typedef unsigned __int128 unsigned_wide_t;
    char digits[48];
    size_t n = 0;
    unsigned_wide_t m = (v < 0) ? (unsigned_wide_t)(-(v + 1)) + 1u : (unsigned_wide_t)v;
    do {
        digits[n++] = (char)('0' + (int)(m % 10u));
        m /= 10u;
    } while (m != 0u);
    if (v < 0) {
        cli_append(out, "-");
    }
    while (n > 0u) {
        cli_append(out, "%c", digits[--n]);
    }
}
