/* SPDX-License-Identifier: MIT */
/*
 * examples/field - a sensor field on the microcontroller (`make field`):
 * 50 temperature sensors, their natural-neighbour (Sibson) interpolant
 * rendered exactly as a 320 x 240 RGB565 frame in 16-row bands
 * (vor_field_raster), as a display driver would take it.
 *
 * The sensors sit on pixel centres (multiples of 4 in a 320 x 240 frame
 * whose pixel (i, j) is the point (i, j)); eight of them near the frame's
 * corners and edge midpoints, so that most of the frame is inside their
 * convex hull. Each reads a smooth integer temperature in centi-degrees
 * (a warm spot and a cool one). The colour of a pixel is that of a
 * 256-entry ramp, blue to red, computed here; outside the hull it is grey.
 *
 * Every pixel is checked on the target, without the library:
 * (a) a second frame, of the values a x + b y + c, equals a x + b y + c
 *     exactly at every pixel inside the hull (Sibson's interpolant
 *     reproduces linear functions), and the outside value elsewhere;
 * (b) the pixels outside are exactly those outside the convex hull found
 *     by brute force here (every pair of sensors, exact orientations);
 * (c) at each sensor's pixel the value is its reading;
 * (d) every value inside lies between the smallest and largest reading;
 * (e) each RGB565 pixel is the ramp colour of the VALUE frame's pixel by
 *     the documented index, floor(256 (v - low) / (high - low + 1)).
 * For (e) each RGB565 band, in its flush, renders the VALUE frame of the
 * same rows (vor_field_raster over those rows, into a second band), so no
 * full frame is ever held.
 *
 * The RGB565 frame streams to build/field.rgb565, the values to
 * build/field.values (int32, little-endian, row-major) and the sensors to
 * build/field.sensors (text) through semihosting; `make field` turns the
 * first into build/field.png, and tools/check_field.py checks a sample of
 * the values against an exact brute force with Python's fractions.
 *
 * FIELD_STEP=4 (make test's build, example-field-quick) renders the same
 * field at every 4th pixel: an 80 x 60 frame, the same checks, written
 * to build/field-quick.*. The last line is "N passed, N failed".
 */
#include <stdbool.h>

#include "example_io.h"
#include "port.h"
#include "vor.h"
#include "vor_raster.h"

#define SENSORS 50u
#define WORLD_W 320 /* the full frame's pixel centres: x 0 .. 319, y 0 .. 239 */
#define WORLD_H 240
#ifndef FIELD_STEP
#define FIELD_STEP 1 /* pixel spacing: 1 the full frame, 4 make test's */
#endif
#if FIELD_STEP == 1
#define FIELD_OUT "build/field"
#else
#define FIELD_OUT "build/field-quick"
#endif
#define FRAME_W ((uint32_t)(WORLD_W / FIELD_STEP))
#define FRAME_H ((uint32_t)(WORLD_H / FIELD_STEP))
#define BAND_ROWS 16u
/* Natural neighbours the scratch holds: a pixel here has at most 9 (the
 * run prints the most); a pixel with more would stop the render with
 * VOR_ERR_NOMEM, which the checks report. */
#define NEIGHBOURS 16u
#define OUTSIDE INT32_MIN       /* VALUE of a pixel outside the hull */
#define OUTSIDE565 0x4208u      /* RGB565 of a pixel outside the hull: grey */
/* The linear field of check (a): a x + b y + c, within int32 over the frame. */
#define LINEAR_A 3000017
#define LINEAR_B (-2000003)
#define LINEAR_C 123457

static vor_point_t sensor[SENSORS];
static int32_t reading[SENSORS];
static int32_t linear[SENSORS];
static uint32_t first_of[SENSORS];
static uint8_t arena[VOR_ARENA_BYTES(SENSORS)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static vor_t diagram;

static uint16_t ramp[256];
static int32_t low, high; /* the smallest and largest reading */

static uint16_t colour_band[BAND_ROWS * FRAME_W];
static int32_t value_band[BAND_ROWS * FRAME_W];
static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(NEIGHBOURS)];
static uint8_t value_scratch[VOR_SIBSON_SCRATCH_BYTES(NEIGHBOURS)];

static uint32_t random_state = 20261128u;

/* ---- the sensors */

/* A temperature in centi-degrees at (x, y): 15 degrees, a warm spot
 * (+18) near (232, 72) and a cool one (-9) near (84, 168), both smooth. */
static int32_t temperature(int32_t x, int32_t y)
{
    int32_t d1 = (x - 232) * (x - 232) + (y - 72) * (y - 72);
    int32_t d2 = (x - 84) * (x - 84) + (y - 168) * (y - 168);
    return 1500 + 1800 * 4096 / (4096 + d1) - 900 * 6400 / (6400 + d2);
}

/* A multiple of 4 in [lo, lo + 4 * (span - 1)]. */
static int32_t grid(int32_t lo, uint32_t span)
{
    return lo + 4 * (int32_t)(example_random(&random_state) % span);
}

static void place_sensors(void)
{
    uint32_t n = 0;
    while (n < SENSORS) {
        vor_point_t p;
        if (n < 8u) { /* corners, then edge midpoints, 4 to 24 pixels in */
            static const int32_t side[8][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2},
                                               {1, 0}, {2, 1}, {1, 2}, {0, 1}};
            int32_t in_x = grid(4, 6), in_y = grid(4, 6);
            p.x = side[n][0] == 0 ? in_x : side[n][0] == 2 ? WORLD_W - 4 - in_x : grid(120, 20);
            p.y = side[n][1] == 0 ? in_y : side[n][1] == 2 ? WORLD_H - 4 - in_y : grid(88, 16);
        } else {
            p.x = grid(0, WORLD_W / 4);
            p.y = grid(0, WORLD_H / 4);
        }
        bool fresh = true;
        for (uint32_t k = 0; k < n; k++) {
            fresh = fresh && (sensor[k].x != p.x || sensor[k].y != p.y);
        }
        if (fresh) {
            sensor[n] = p;
            reading[n] = temperature(p.x, p.y);
            linear[n] = LINEAR_A * p.x + LINEAR_B * p.y + LINEAR_C;
            n++;
        }
    }
    low = reading[0];
    high = reading[0];
    for (uint32_t k = 1; k < SENSORS; k++) {
        low = reading[k] < low ? reading[k] : low;
        high = reading[k] > high ? reading[k] : high;
    }
}

/* ---- the checks' own geometry and colours, without the library */

/* (b - a) x (c - a); coordinates are below 2^9, so int32 holds it. */
static int32_t orientation(vor_point_t a, vor_point_t b, vor_point_t c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/* The hull's edges by brute force: the ordered pairs (a, b) of sensors
 * with no sensor to the right of a -> b. A point is outside the hull
 * exactly when it is to the right of one of them. */
static uint8_t hull_a[SENSORS * SENSORS], hull_b[SENSORS * SENSORS];
static uint32_t hull_edges;

static void find_hull(void)
{
    hull_edges = 0;
    for (uint32_t a = 0; a < SENSORS; a++) {
        for (uint32_t b = 0; b < SENSORS; b++) {
            bool edge = a != b;
            for (uint32_t c = 0; c < SENSORS && edge; c++) {
                edge = orientation(sensor[a], sensor[b], sensor[c]) >= 0;
            }
            if (edge) {
                hull_a[hull_edges] = (uint8_t)a;
                hull_b[hull_edges] = (uint8_t)b;
                hull_edges++;
            }
        }
    }
}

static bool inside_hull(int32_t x, int32_t y)
{
    vor_point_t q = {x, y};
    for (uint32_t e = 0; e < hull_edges; e++) {
        if (orientation(sensor[hull_a[e]], sensor[hull_b[e]], q) < 0) {
            return false;
        }
    }
    return true;
}

/* Blue, cyan, green, yellow, red: four stretches of 64 entries. */
static void make_ramp(void)
{
    static const uint8_t stop[5][3] = {{0, 0, 255}, {0, 255, 255}, {0, 255, 0},
                                       {255, 255, 0}, {255, 0, 0}};
    for (uint32_t t = 0; t < 256u; t++) {
        uint32_t s = t / 64u, f = t % 64u, rgb[3];
        for (uint32_t c = 0; c < 3u; c++) {
            rgb[c] = (stop[s][c] * (63u - f) + stop[s + 1u][c] * f) / 63u;
        }
        ramp[t] = (uint16_t)(((rgb[0] >> 3) << 11) | ((rgb[1] >> 2) << 5) | (rgb[2] >> 3));
    }
}

/* The documented index: floor(256 (v - low) / (high - low + 1)), clamped. */
static uint16_t ramp_colour(int32_t v)
{
    int64_t num = ((int64_t)v - low) * 256;
    int64_t index = num < 0 ? 0 : num / ((int64_t)high - low + 1);
    return ramp[index > 255 ? 255 : index];
}

/* ---- the rendering, with the checks in the flushes */

typedef struct field_run {
    int values_file, colours_file;
    const uint16_t *colours;  /* the RGB565 band being flushed */
    uint32_t first_row;       /* its first row */
    int value_err;            /* the first failed VALUE render */
    uint64_t value_spent;     /* counter ticks inside the VALUE renders */
    uint64_t flush_spent;     /* ... inside the RGB565 flush, all of it */
    uint64_t check_spent;     /* ... inside the VALUE flushes */
    uint32_t rows;            /* rows checked */
    uint32_t outside;         /* pixels outside the hull */
    uint32_t wrong_hull, wrong_range, wrong_colour, sensors_seen, wrong_sensor;
    int32_t seen_low, seen_high;
} field_run_t;

/* The VALUE band of the rows the RGB565 band holds: checks (b) to (e). */
static int check_values(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    field_run_t *s = user;
    uint64_t start = vor_port_counter();
    const int32_t *v = pixels;
    for (uint32_t r = 0; r < rows; r++) {
        uint32_t j = s->first_row + first_row + r;
        int32_t y = (int32_t)j * FIELD_STEP;
        const int32_t *row = v + r * FRAME_W;
        const uint16_t *colour = s->colours + (first_row + r) * FRAME_W;
        for (uint32_t i = 0; i < FRAME_W; i++) {
            if (!inside_hull((int32_t)i * FIELD_STEP, y)) {
                s->outside++;
                s->wrong_hull += row[i] != OUTSIDE ? 1u : 0u;
                s->wrong_colour += colour[i] != OUTSIDE565 ? 1u : 0u;
            } else {
                s->wrong_hull += row[i] == OUTSIDE ? 1u : 0u;
                s->wrong_range += row[i] < low || row[i] > high ? 1u : 0u;
                s->wrong_colour += colour[i] != ramp_colour(row[i]) ? 1u : 0u;
                s->seen_low = row[i] < s->seen_low ? row[i] : s->seen_low;
                s->seen_high = row[i] > s->seen_high ? row[i] : s->seen_high;
            }
        }
        for (uint32_t k = 0; k < SENSORS; k++) {
            if (sensor[k].y == y && sensor[k].x % FIELD_STEP == 0) {
                s->sensors_seen++;
                s->wrong_sensor += row[sensor[k].x / FIELD_STEP] != reading[k] ? 1u : 0u;
            }
        }
        s->rows++;
    }
    if (s->values_file >= 0) {
        (void)vor_port_file_write(s->values_file, pixels, rows * FRAME_W * sizeof(int32_t));
    }
    s->check_spent += vor_port_counter() - start;
    return 0;
}

/* A VALUE frame's output: 16-row bands of value_band to flush(user). */
static vor_field_output_t value_output(vor_raster_flush_t flush, void *user)
{
    vor_field_output_t out = {0};
    out.kind = VOR_FIELD_VALUE;
    out.band = value_band;
    out.band_bytes = sizeof value_band;
    out.band_rows = BAND_ROWS;
    out.flush = flush;
    out.user = user;
    out.outside = OUTSIDE;
    return out;
}

/* Each RGB565 band: the VALUE frame of its rows, rendered for the checks
 * (check_values), then the band to the host file. */
static int send_colours(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    field_run_t *s = user;
    uint64_t start = vor_port_counter();
    s->colours = pixels;
    s->first_row = first_row;
    vor_raster_frame_t these = {0, (int32_t)first_row * FIELD_STEP, FIELD_STEP, FIELD_STEP,
                                FRAME_W, rows};
    vor_field_output_t out = value_output(check_values, s);
    uint64_t checks = s->check_spent, value_start = vor_port_counter();
    int err = vor_field_raster(&diagram, reading, &these, &out, NULL, value_scratch,
                               sizeof value_scratch);
    s->value_spent += vor_port_counter() - value_start - (s->check_spent - checks);
    if (err != VOR_OK && s->value_err == VOR_OK) {
        s->value_err = err;
    }
    if (s->colours_file >= 0) {
        (void)vor_port_file_write(s->colours_file, pixels, rows * FRAME_W * sizeof(uint16_t));
    }
    s->flush_spent += vor_port_counter() - start;
    return 0;
}

static void print_per_pixel(uint64_t ticks)
{
    uint64_t tenths = ticks * 10u / (FRAME_W * FRAME_H);
    example_print_uint(tenths / 10u);
    example_print(".");
    example_print_uint(tenths % 10u);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print(" per pixel");
}

static void render_field(void)
{
    static field_run_t run;
    run.values_file = vor_port_file_open(FIELD_OUT ".values");
    run.colours_file = vor_port_file_open(FIELD_OUT ".rgb565");
    run.seen_low = INT32_MAX;
    run.seen_high = INT32_MIN;
    vor_raster_frame_t frame = {0, 0, FIELD_STEP, FIELD_STEP, FRAME_W, FRAME_H};
    uint32_t most = 0;
    vor_field_output_t out = {0};
    out.kind = VOR_FIELD_RGB565;
    out.band = colour_band;
    out.band_bytes = sizeof colour_band;
    out.band_rows = BAND_ROWS;
    out.flush = send_colours;
    out.user = &run;
    out.ramp565 = ramp;
    out.low = low;
    out.high = high;
    out.outside565 = OUTSIDE565;
    out.max_neighbours = &most;
    uint64_t start = vor_port_counter();
    int err = vor_field_raster(&diagram, reading, &frame, &out, NULL, scratch, sizeof scratch);
    uint64_t spent = vor_port_counter() - start - run.flush_spent;
    if (run.values_file >= 0) {
        (void)vor_port_file_close(run.values_file);
    }
    if (run.colours_file >= 0) {
        (void)vor_port_file_close(run.colours_file);
    }
    example_check(err == VOR_OK, "the RGB565 frame renders");
    example_check(run.value_err == VOR_OK, "every VALUE band renders");
    example_check(run.rows == FRAME_H, "every row is checked");
    example_check(run.wrong_hull == 0u, "(b) outside pixels are those outside the hull");
    example_check(run.sensors_seen == SENSORS && run.wrong_sensor == 0u,
                  "(c) each sensor's pixel has its reading");
    example_check(run.wrong_range == 0u, "(d) values lie between the readings' extremes");
    example_check(run.wrong_colour == 0u, "(e) RGB565 pixels are the ramp colours of the values");

    example_print("field:     ");
    example_print_uint(FRAME_W);
    example_print("x");
    example_print_uint(FRAME_H);
    example_print(" RGB565 frame in 16-row bands: ");
    print_per_pixel(spent);
    example_print(" (streaming and checks excluded);\n           VALUE frame of the same rows: ");
    print_per_pixel(run.value_spent);
    example_print("; at most ");
    example_print_uint(most);
    example_print(" natural neighbours a pixel\n           ");
    example_print_uint(run.outside);
    example_print(" pixels outside the hull; values ");
    example_print_int(run.seen_low);
    example_print(" .. ");
    example_print_int(run.seen_high);
    example_print(" in readings ");
    example_print_int(low);
    example_print(" .. ");
    example_print_int(high);
    example_print(run.colours_file >= 0 ? "; streamed to " FIELD_OUT ".rgb565 and .values\n"
                                        : "; no host file\n");
}

/* ---- check (a): the linear field, exact at every pixel */

typedef struct linear_run {
    uint32_t rows, wrong;
} linear_run_t;

static int check_linear(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    linear_run_t *s = user;
    const int32_t *v = pixels;
    for (uint32_t r = 0; r < rows; r++) {
        int32_t y = (int32_t)(first_row + r) * FIELD_STEP;
        for (uint32_t i = 0; i < FRAME_W; i++) {
            int32_t x = (int32_t)i * FIELD_STEP;
            int32_t want = inside_hull(x, y) ? LINEAR_A * x + LINEAR_B * y + LINEAR_C : OUTSIDE;
            s->wrong += v[r * FRAME_W + i] != want ? 1u : 0u;
        }
        s->rows++;
    }
    return 0;
}

static void render_linear(void)
{
    linear_run_t run = {0, 0};
    vor_raster_frame_t frame = {0, 0, FIELD_STEP, FIELD_STEP, FRAME_W, FRAME_H};
    vor_field_output_t out = value_output(check_linear, &run);
    int err = vor_field_raster(&diagram, linear, &frame, &out, NULL, scratch, sizeof scratch);
    example_check(err == VOR_OK && run.rows == FRAME_H,
                  "(a) the linear field's frame renders");
    example_check(run.wrong == 0u, "(a) the linear field is reproduced exactly");
    example_print("linear:    ");
    example_print_int(LINEAR_A);
    example_print(" x ");
    example_print_int(LINEAR_B);
    example_print(" y + ");
    example_print_int(LINEAR_C);
    example_print(": ");
    example_print(err == VOR_OK && run.wrong == 0u ? "exact at every pixel\n" : "WRONG\n");
}

/* ---- the sensors as text for the host: build/field.sensors */

static void write_sensors(void)
{
    static example_file_t out;
    example_file_open(&out, FIELD_OUT ".sensors");
    example_file_text(&out, "# examples/field: frame OX OY SX SY W H, the outside value, s X Y VALUE\nframe");
    example_file_int(&out, 0), example_file_int(&out, 0);
    example_file_int(&out, FIELD_STEP), example_file_int(&out, FIELD_STEP);
    example_file_int(&out, (int32_t)FRAME_W), example_file_int(&out, (int32_t)FRAME_H);
    example_file_text(&out, "\noutside");
    example_file_int(&out, OUTSIDE);
    for (uint32_t k = 0; k < SENSORS; k++) {
        example_file_text(&out, "\ns");
        example_file_int(&out, sensor[k].x), example_file_int(&out, sensor[k].y);
        example_file_int(&out, reading[k]);
    }
    example_file_text(&out, "\n");
    example_file_close(&out);
}

int main(void)
{
    vor_port_init();
    example_print("vor: a field of 50 sensors on this microcontroller\n\n");
    place_sensors();
    make_ramp();
    find_hull();
    int err = vor_init(&diagram, arena, sizeof arena, SENSORS);
    uint64_t start = vor_port_counter();
    if (err == VOR_OK) {
        err = vor_build(&diagram, sensor, SENSORS, NULL, first_of);
    }
    uint64_t spent = vor_port_counter() - start;
    example_check(err == VOR_OK && diagram.vertex_count == SENSORS, "the diagram builds");
    example_print("build:     ");
    example_print_uint(diagram.vertex_count);
    example_print(" sensors in ");
    example_print_uint(spent);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print("; readings ");
    example_print_int(low);
    example_print(" .. ");
    example_print_int(high);
    example_print(" centi-degrees\n");
    write_sensors();
    if (err == VOR_OK) {
        render_field();
        render_linear();
    }
    return example_print_tally();
}
