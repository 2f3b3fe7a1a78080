/* SPDX-License-Identifier: MIT */
/*
 * examples/room - a navigation mesh of a flat, built on the
 * microcontroller from a constrained Delaunay triangulation (vor_cdt.h).
 *
 * The floor plan is in millimetres: the flat's outline (an L of 92 m^2),
 * thin inner walls that stop at the door jambs, and a pillar in the living
 * room. The sites are the walls' corners and one point sampled in each
 * square metre of floor; every wall is a constraint (vor_constrain), and
 * vor_cdt_domain marks the floor by the even-odd rule: a triangle is
 * inside when the fewest walls crossed to reach it from outside are odd
 * in number. Every room borders the outline, so its triangles are one
 * wall in; the pillar's are two, a hole. The inside triangles, joined
 * across the edges that are no wall, are the navigation mesh; a
 * breadth-first search on it finds a way from the bathroom to the
 * bedroom.
 *
 * Every result is checked against the floor plan, without the mesh:
 * - the constrained edges are the walls split at the corners on them;
 * - the triangle count is Euler's for a floor with one hole, and twice
 *   the area, summed exactly over the triangles, is the shoelace formula's
 *   for the outline less the pillar;
 * - no triangle edge crosses a wall, and every edge on the floor's
 *   boundary is one;
 * - of a grid of points, those the even-odd ray test puts on the floor
 *   lie in an inside triangle, the others in none;
 * - the way, through the midpoints of the edges it crosses, touches no
 *   wall and passes each of the three doors an odd number of times.
 * The last line is "N passed, N failed" (make test's suite `room` runs it
 * on the host and on every emulated target). Memory is static, sized at
 * compile time (VOR_ARENA_BYTES, VOR_CDT_BYTES).
 *
 * It writes the sites to build/room.sites and the walls to
 * build/room.walls, which the host tool draws:
 *     make PORT=cortex-m3 run-example-room
 *     build/host/vor draw --constraints build/room.walls --domain \
 *         build/room.sites -o build/room.svg
 */
#include <stdbool.h>

#include "example_io.h"
#include "port.h"
#include "vor.h"
#include "vor_cdt.h"

typedef struct segment {
    vor_point_t a, b;
} segment_t;

#define COUNT(array) (sizeof(array) / sizeof((array)[0]))

/* The flat's outline, counterclockwise: the living room on the left with
 * the bathroom in its top left corner, the kitchen on the right, the bedroom
 * above the kitchen. */
static const vor_point_t outline[] = {{0, 0},       {12000, 0},   {12000, 5000},
                                      {8000, 5000}, {8000, 9000}, {0, 9000}};
/* A pillar in the living room, turned 45 degrees: a hole in the floor. */
static const vor_point_t pillar[] = {{2500, 2300}, {2800, 2600}, {2500, 2900}, {2200, 2600}};
#define HOLES 1
/* The inner walls, thin; each ends at a door jamb or at another wall. */
static const segment_t inner_walls[] = {
    {{5000, 0}, {5000, 3800}},    /* living room | kitchen, below their door */
    {{5000, 4700}, {5000, 9000}}, /* living room | kitchen and bedroom */
    {{5000, 5000}, {6000, 5000}}, /* kitchen | bedroom, left of their door */
    {{6900, 5000}, {8000, 5000}}, /* and right of it */
    {{0, 6500}, {2500, 6500}},    /* living room | bathroom */
    {{2500, 6500}, {2500, 7300}}, /* bathroom | living room, below their door */
    {{2500, 8100}, {2500, 9000}}, /* and above it */
};
/* The doors: the openings between the jambs. */
static const segment_t doors[] = {
    {{5000, 3800}, {5000, 4700}}, /* living room - kitchen */
    {{6000, 5000}, {6900, 5000}}, /* kitchen - bedroom */
    {{2500, 7300}, {2500, 8100}}, /* bathroom - living room */
};
/* The way asked for: from the bathroom to the bedroom. */
static const vor_point_t start = {1201, 7802}, goal = {6501, 7502};

#define WALLS (COUNT(outline) + COUNT(pillar) + COUNT(inner_walls))
#define WIDTH 12000 /* mm: the outline's bounding box */
#define DEPTH 9000
#define SAMPLE_SPACING 1000 /* mm: one sampled site in each such square */
#define MAX_SITES (2u * WALLS + (WIDTH / SAMPLE_SPACING) * (DEPTH / SAMPLE_SPACING))
#define MAX_TRIANGLES (2u * MAX_SITES)
/* A wall counts one constrained edge for each piece the corners on it
 * split it into: only T-junctions split these, so twice the walls is
 * ample. No two walls cross, so no crossing vertex; the cut is the bound
 * that always suffices. */
#define EDGE_LIMIT (2u * WALLS)
#define CUT_LIMIT (2u * MAX_SITES + 2u)
#define NONE UINT32_MAX

/* A point within 3 mm of (x, y) on no wall, door or pillar side: walls
 * and doors run along multiples of 100 mm and the pillar's sides along
 * x + y or x - y a multiple of 100, so a point with x odd and y = 2
 * (mod 4) is on none of them, nor at a corner's height. */
static vor_point_t off_the_walls(int32_t x, int32_t y)
{
    vor_point_t p = {x | 1, (y - (y % 4)) + 2};
    return p;
}

static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t cdt_memory[VOR_CDT_BYTES(MAX_SITES, EDGE_LIMIT, 0u, CUT_LIMIT)]
    __attribute__((aligned(VOR_CDT_ALIGN)));

static segment_t walls[WALLS];
static uint32_t wall_ends[WALLS][2]; /* their sites */
static vor_point_t sites[MAX_SITES];
static uint32_t site_count;
static uint32_t constrained[EDGE_LIMIT][2];
static uint32_t constrained_count;
static uint32_t mesh[MAX_TRIANGLES][3]; /* the inside triangles, counterclockwise */
static uint32_t across[MAX_TRIANGLES][3]; /* the one beyond side k (k, k + 1), if no wall */
static uint32_t mesh_count;
static uint32_t came_from[MAX_TRIANGLES]; /* the breadth-first search's tree */
static uint32_t queue[MAX_TRIANGLES];
static uint32_t way[MAX_TRIANGLES]; /* the triangles from start to goal */

/* ---- plain integer geometry, independent of the library */

/* Twice the signed area of triangle a b c: positive counterclockwise.
 * Coordinates here stay below 2^16, so the products fit. */
static int64_t cross(vor_point_t a, vor_point_t b, vor_point_t c)
{
    return ((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) -
           ((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

static int sign(int64_t v)
{
    return (v > 0) - (v < 0);
}

static bool same_point(vor_point_t a, vor_point_t b)
{
    return a.x == b.x && a.y == b.y;
}

static vor_point_t twice(vor_point_t p)
{
    vor_point_t q = {2 * p.x, 2 * p.y};
    return q;
}

static segment_t twice_segment(segment_t s)
{
    segment_t t = {twice(s.a), twice(s.b)};
    return t;
}

/* Whether p lies on the closed segment s. */
static bool on_segment(vor_point_t p, segment_t s)
{
    return cross(s.a, s.b, p) == 0 && (p.x - s.a.x) * (int64_t)(p.x - s.b.x) <= 0 &&
           (p.y - s.a.y) * (int64_t)(p.y - s.b.y) <= 0;
}

/* Whether the closed segments p-q and s meet. */
static bool segments_meet(vor_point_t p, vor_point_t q, segment_t s)
{
    int o1 = sign(cross(p, q, s.a)), o2 = sign(cross(p, q, s.b));
    if (o1 == 0 && o2 == 0) { /* on one line: do they overlap? */
        segment_t pq = {p, q};
        return on_segment(s.a, pq) || on_segment(s.b, pq) || on_segment(p, s);
    }
    return o1 * o2 <= 0 && sign(cross(s.a, s.b, p)) * sign(cross(s.a, s.b, q)) <= 0;
}

/* Whether the open segments p-q and s cross at one point inside both. */
static bool segments_cross(vor_point_t p, vor_point_t q, segment_t s)
{
    return sign(cross(p, q, s.a)) * sign(cross(p, q, s.b)) < 0 &&
           sign(cross(s.a, s.b, p)) * sign(cross(s.a, s.b, q)) < 0;
}

/* Twice a polygon's area, by the shoelace formula. */
static int64_t shoelace(const vor_point_t *polygon, uint32_t n)
{
    int64_t sum = 0;
    for (uint32_t i = 0; i < n; i++) {
        vor_point_t a = polygon[i], b = polygon[(i + 1u) % n];
        sum += (int64_t)a.x * b.y - (int64_t)b.x * a.y;
    }
    return sum;
}

/* Whether a ray from p towards +x crosses the polygon's boundary an odd
 * number of times; p is on no side and at no vertex's height. */
static bool odd_crossings(vor_point_t p, const vor_point_t *polygon, uint32_t n)
{
    bool odd = false;
    for (uint32_t i = 0; i < n; i++) {
        vor_point_t a = polygon[i], b = polygon[(i + 1u) % n];
        if ((a.y > p.y) != (b.y > p.y)) {
            /* the side passes p's height right of p when p is on the
             * side's left going up, or on its right going down */
            odd ^= (cross(a, b, p) > 0) == (b.y > a.y);
        }
    }
    return odd;
}

/* Whether p is on the floor: inside the outline and not in the pillar. */
static bool on_floor(vor_point_t p)
{
    return odd_crossings(p, outline, COUNT(outline)) != odd_crossings(p, pillar, COUNT(pillar));
}

/* ---- the floor plan as sites and constraints */

static void gather_walls(void)
{
    uint32_t w = 0;
    for (uint32_t i = 0; i < COUNT(outline); i++, w++) {
        walls[w].a = outline[i];
        walls[w].b = outline[(i + 1u) % COUNT(outline)];
    }
    for (uint32_t i = 0; i < COUNT(pillar); i++, w++) {
        walls[w].a = pillar[i];
        walls[w].b = pillar[(i + 1u) % COUNT(pillar)];
    }
    for (uint32_t i = 0; i < COUNT(inner_walls); i++, w++) {
        walls[w] = inner_walls[i];
    }
}

/* The site at p, added if there is none. */
static uint32_t corner_site(vor_point_t p)
{
    for (uint32_t i = 0; i < site_count; i++) {
        if (same_point(sites[i], p)) {
            return i;
        }
    }
    sites[site_count] = p;
    return site_count++;
}

/* The walls' corners, then a point in each square metre of floor, at a
 * random place in its middle. */
static uint32_t gather_sites(void)
{
    for (uint32_t w = 0; w < WALLS; w++) {
        wall_ends[w][0] = corner_site(walls[w].a);
        wall_ends[w][1] = corner_site(walls[w].b);
    }
    uint32_t corners = site_count, state = 20261127u;
    for (int32_t y = 0; y < DEPTH; y += SAMPLE_SPACING) {
        for (int32_t x = 0; x < WIDTH; x += SAMPLE_SPACING) {
            int32_t dx = 200 + (int32_t)(example_random(&state) % 600u);
            int32_t dy = 200 + (int32_t)(example_random(&state) % 600u);
            vor_point_t p = off_the_walls(x + dx, y + dy);
            if (on_floor(p)) {
                sites[site_count++] = p;
            }
        }
    }
    return corners;
}

/* ---- the navigation mesh */

static bool is_constrained(uint32_t a, uint32_t b)
{
    for (uint32_t i = 0; i < constrained_count; i++) {
        if ((constrained[i][0] == a && constrained[i][1] == b) ||
            (constrained[i][0] == b && constrained[i][1] == a)) {
            return true;
        }
    }
    return false;
}

/* Copies the inside triangles and the constrained edges out of d. */
static bool read_mesh(const vor_t *d)
{
    vor_cdt_triangle_iter_t triangles;
    uint32_t ids[3];
    bool ok = vor_cdt_inside_begin(&triangles, d) == VOR_OK;
    while (ok && vor_cdt_triangles_next(&triangles, ids) != 0) {
        /* every vertex is a site: no wall crosses another */
        ok = mesh_count < MAX_TRIANGLES && ids[0] < site_count && ids[1] < site_count &&
             ids[2] < site_count;
        for (uint32_t k = 0; ok && k < 3u; k++) {
            mesh[mesh_count][k] = ids[k];
        }
        mesh_count += ok ? 1u : 0u;
    }
    vor_cdt_edge_iter_t edges;
    uint32_t a, b;
    ok = ok && vor_cdt_edges_begin(&edges, d) == VOR_OK;
    while (ok && vor_cdt_edges_next(&edges, &a, &b) != 0) {
        ok = constrained_count < EDGE_LIMIT;
        if (ok) {
            constrained[constrained_count][0] = a;
            constrained[constrained_count][1] = b;
            constrained_count++;
        }
    }
    return ok;
}

/* Links each inside triangle to those beyond its sides that are no wall.
 * Returns the number of sides with no inside triangle beyond them that
 * are no wall either: a hole in the floor's boundary, none if the domain
 * is right. */
static uint32_t link_mesh(void)
{
    uint32_t open = 0;
    for (uint32_t t = 0; t < mesh_count; t++) {
        for (uint32_t k = 0; k < 3u; k++) {
            uint32_t a = mesh[t][k], b = mesh[t][(k + 1u) % 3u];
            across[t][k] = NONE;
            if (is_constrained(a, b)) {
                continue;
            }
            for (uint32_t u = 0; u < mesh_count; u++) {
                for (uint32_t j = 0; j < 3u; j++) {
                    if (mesh[u][j] == b && mesh[u][(j + 1u) % 3u] == a) {
                        across[t][k] = u;
                    }
                }
            }
            open += across[t][k] == NONE ? 1u : 0u;
        }
    }
    return open;
}

/* The inside triangle holding p (on its boundary or inside), or NONE. */
static uint32_t locate(vor_point_t p)
{
    for (uint32_t t = 0; t < mesh_count; t++) {
        vor_point_t a = sites[mesh[t][0]], b = sites[mesh[t][1]], c = sites[mesh[t][2]];
        if (cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0) {
            return t;
        }
    }
    return NONE;
}

/* The fewest triangles from triangle `from` to `to` across sides that
 * are no wall, in way[]; returns their number, 0 when there is no way. */
static uint32_t find_way(uint32_t from, uint32_t to)
{
    for (uint32_t t = 0; t < mesh_count; t++) {
        came_from[t] = NONE;
    }
    uint32_t head = 0, tail = 0;
    came_from[from] = from;
    queue[tail++] = from;
    while (head < tail && came_from[to] == NONE) {
        uint32_t t = queue[head++];
        for (uint32_t k = 0; k < 3u; k++) {
            uint32_t u = across[t][k];
            if (u != NONE && came_from[u] == NONE) {
                came_from[u] = t;
                queue[tail++] = u;
            }
        }
    }
    if (came_from[to] == NONE) {
        return 0;
    }
    uint32_t n = 0;
    for (uint32_t t = to; t != from; t = came_from[t]) {
        n++;
    }
    uint32_t i = n + 1u;
    for (uint32_t t = to; i > 0u; t = came_from[t]) {
        way[--i] = t;
    }
    return n + 1u;
}

/* The midpoint of the side triangles t and u share, in doubled
 * coordinates (exact). */
static vor_point_t portal(uint32_t t, uint32_t u)
{
    for (uint32_t k = 0; k < 3u; k++) {
        if (across[t][k] == u) {
            vor_point_t a = sites[mesh[t][k]], b = sites[mesh[t][(k + 1u) % 3u]];
            vor_point_t m = {a.x + b.x, a.y + b.y};
            return m;
        }
    }
    return twice(sites[mesh[t][0]]); /* not reached: u is beyond a side of t */
}

/* Whether the step p -> q passes the door: p and q on different sides of
 * its line (a point on the line counts with the right-hand side, so a
 * step that ends on it and the next that leaves it count once), crossing
 * it between the jambs. */
static bool passes(vor_point_t p, vor_point_t q, segment_t door)
{
    if ((cross(door.a, door.b, p) > 0) == (cross(door.a, door.b, q) > 0)) {
        return false;
    }
    return sign(cross(p, q, door.a)) * sign(cross(p, q, door.b)) < 0;
}

static uint64_t square_root(uint64_t v)
{
    uint64_t root = 0;
    for (uint64_t bit = (uint64_t)1 << 62; bit != 0u; bit >>= 2) {
        if (v >= root + bit) {
            v -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
    }
    return root;
}

/* Walks the way start -> portals -> goal in doubled coordinates: checks
 * that no step meets a wall and that each door is passed an odd number of
 * times. Returns the way's length in mm (each step rounded down). */
static uint64_t walk_way(uint32_t steps)
{
    uint32_t passes_of[COUNT(doors)] = {0};
    uint64_t length = 0;
    bool clear = true;
    vor_point_t p = twice(start);
    for (uint32_t i = 0; i < steps; i++) {
        vor_point_t q = i + 1u < steps ? portal(way[i], way[i + 1u]) : twice(goal);
        for (uint32_t w = 0; w < WALLS; w++) {
            clear &= !segments_meet(p, q, twice_segment(walls[w]));
        }
        for (uint32_t door = 0; door < COUNT(doors); door++) {
            passes_of[door] += passes(p, q, twice_segment(doors[door])) ? 1u : 0u;
        }
        int64_t dx = (int64_t)q.x - p.x, dy = (int64_t)q.y - p.y;
        length += square_root((uint64_t)(dx * dx + dy * dy)) / 2u;
        p = q;
    }
    example_check(clear, "the way meets a wall");
    for (uint32_t door = 0; door < COUNT(doors); door++) {
        example_check(passes_of[door] % 2u == 1u, "the way does not pass a door");
    }
    return length;
}

/* ---- the checks against the floor plan */

static void check_walls(void)
{
    uint32_t pieces = 0;
    for (uint32_t w = 0; w < WALLS; w++) {
        for (uint32_t i = 0; i < site_count; i++) {
            pieces += on_segment(sites[i], walls[w]) ? 1u : 0u;
        }
        pieces--; /* n sites on a wall, n - 1 pieces */
    }
    bool on_walls = true;
    for (uint32_t e = 0; e < constrained_count; e++) {
        bool found = false;
        for (uint32_t w = 0; w < WALLS; w++) {
            found |= on_segment(sites[constrained[e][0]], walls[w]) &&
                     on_segment(sites[constrained[e][1]], walls[w]);
        }
        on_walls &= found;
    }
    example_check(constrained_count == pieces, "the constrained edges are not the walls' pieces");
    example_check(on_walls, "a constrained edge is on no wall");
}

/* Euler: a triangulated floor with v vertices, b of them on its boundary
 * and h holes, has 2 v - b - 2 + 2 h triangles. */
static uint32_t expected_triangles(void)
{
    uint32_t boundary = 0;
    for (uint32_t i = 0; i < site_count; i++) {
        bool on = false;
        for (uint32_t w = 0; w < COUNT(outline) + COUNT(pillar); w++) {
            on |= on_segment(sites[i], walls[w]);
        }
        boundary += on ? 1u : 0u;
    }
    return 2u * site_count - boundary - 2u + 2u * HOLES;
}

static int64_t mesh_twice_area(void)
{
    int64_t sum = 0;
    for (uint32_t t = 0; t < mesh_count; t++) {
        sum += cross(sites[mesh[t][0]], sites[mesh[t][1]], sites[mesh[t][2]]);
    }
    return sum;
}

static bool edges_clear_of_walls(void)
{
    for (uint32_t t = 0; t < mesh_count; t++) {
        for (uint32_t k = 0; k < 3u; k++) {
            vor_point_t a = sites[mesh[t][k]], b = sites[mesh[t][(k + 1u) % 3u]];
            for (uint32_t w = 0; w < WALLS; w++) {
                if (segments_cross(a, b, walls[w])) {
                    return false;
                }
            }
        }
    }
    return true;
}

#define GRID_X 250 /* mm between the located points */
#define GRID_Y 200

/* Locates a grid of points over the outline's box and a margin; returns
 * how many the even-odd test puts on the floor. */
static uint32_t check_locations(uint32_t *points)
{
    uint32_t floor = 0, disagree = 0;
    *points = 0;
    for (int32_t y = -GRID_Y; y <= DEPTH + GRID_Y; y += GRID_Y) {
        for (int32_t x = -GRID_X; x <= WIDTH + GRID_X; x += GRID_X) {
            vor_point_t p = off_the_walls(x, y);
            bool inside = on_floor(p);
            floor += inside ? 1u : 0u;
            disagree += inside != (locate(p) != NONE) ? 1u : 0u;
            (*points)++;
        }
    }
    example_check(disagree == 0u, "a point's triangle disagrees with the even-odd test");
    return floor;
}

/* ---- output */

typedef struct text_file {
    int handle;
    uint32_t used;
    char buffer[256]; /* semihosting calls are slow: one per buffer */
} text_file_t;

static void file_flush(text_file_t *f)
{
    if (f->handle >= 0 && f->used > 0u) {
        (void)vor_port_file_write(f->handle, f->buffer, f->used);
    }
    f->used = 0;
}

static void file_text(text_file_t *f, const char *text)
{
    for (; *text != '\0'; text++) {
        if (f->used == sizeof f->buffer) {
            file_flush(f);
        }
        f->buffer[f->used++] = *text;
    }
}

/* Coordinates and ids here are below 10^5 and not negative. */
static void file_uint(text_file_t *f, uint32_t value)
{
    char digits[11];
    uint32_t n = sizeof digits;
    digits[--n] = '\0';
    do {
        digits[--n] = (char)('0' + (int)(value % 10u));
        value /= 10u;
    } while (value != 0u);
    file_text(f, digits + n);
}

static void file_close(text_file_t *f)
{
    file_flush(f);
    if (f->handle >= 0) {
        (void)vor_port_file_close(f->handle);
    }
}

/* The sites and the walls as `vor draw --constraints` reads them. */
static void write_floor_plan(void)
{
    static text_file_t f;
    f.handle = vor_port_file_open("build/room.sites");
    f.used = 0;
    for (uint32_t i = 0; i < site_count; i++) {
        file_uint(&f, (uint32_t)sites[i].x);
        file_text(&f, " ");
        file_uint(&f, (uint32_t)sites[i].y);
        file_text(&f, "\n");
    }
    file_close(&f);
    f.handle = vor_port_file_open("build/room.walls");
    f.used = 0;
    for (uint32_t w = 0; w < WALLS; w++) {
        file_uint(&f, wall_ends[w][0]);
        file_text(&f, " ");
        file_uint(&f, wall_ends[w][1]);
        file_text(&f, "\n");
    }
    file_close(&f);
}

static void print_point(vor_point_t p)
{
    example_print("(");
    example_print_int(p.x);
    example_print(", ");
    example_print_int(p.y);
    example_print(")");
}

int main(void)
{
    vor_port_init();
    example_print("vor: the navigation mesh of a flat, from its walls as constraints\n\n");
    gather_walls();
    uint32_t corners = gather_sites();

    vor_t d;
    uint64_t started = vor_port_counter();
    int err = vor_init(&d, arena, sizeof arena, MAX_SITES);
    err = err != VOR_OK ? err : vor_build(&d, sites, site_count, NULL, NULL);
    uint64_t built = vor_port_counter();
    vor_cdt_limits_t limits = {EDGE_LIMIT, 0u, CUT_LIMIT};
    err = err != VOR_OK ? err : vor_cdt_attach(&d, cdt_memory, sizeof cdt_memory, &limits);
    for (uint32_t w = 0; w < WALLS && err == VOR_OK; w++) {
        err = vor_constrain(&d, wall_ends[w][0], wall_ends[w][1]);
    }
    uint64_t walled = vor_port_counter();
    err = err != VOR_OK ? err : vor_cdt_domain(&d);
    uint64_t marked = vor_port_counter();
    example_check(err == VOR_OK, "building the constrained triangulation failed");
    bool mesh_read = (err == VOR_OK) && read_mesh(&d);
    example_check(mesh_read, "reading the mesh failed");
    if ((err != VOR_OK) || !mesh_read) {
        example_print("error ");
        example_print_int(err);
        example_print("\n");
        return example_print_tally();
    }
    uint32_t all_triangles = 0, ids[3];
    vor_cdt_triangle_iter_t every;
    vor_cdt_triangles_begin(&every, &d);
    while (vor_cdt_triangles_next(&every, ids) != 0) {
        all_triangles++;
    }

    check_walls();
    uint32_t expected = expected_triangles();
    example_check(mesh_count == expected, "the inside triangles are not as many as Euler's count");
    int64_t area = mesh_twice_area();
    int64_t plan_area = shoelace(outline, COUNT(outline)) - shoelace(pillar, COUNT(pillar));
    example_check(area == plan_area, "the inside triangles' area is not the floor plan's");
    example_check(edges_clear_of_walls(), "a triangle edge crosses a wall");
    uint32_t open = link_mesh();
    example_check(open == 0u, "a side of the floor's boundary is no wall");
    uint32_t points;
    uint32_t floor_points = check_locations(&points);

    uint32_t from = locate(start), to = locate(goal);
    uint32_t steps = (from != NONE && to != NONE) ? find_way(from, to) : 0u;
    example_check(steps != 0u, "no way from the bathroom to the bedroom");
    uint64_t length = steps != 0u ? walk_way(steps) : 0u;
    write_floor_plan();

    example_print("sites:      ");
    example_print_uint(site_count);
    example_print(" (");
    example_print_uint(corners);
    example_print(" wall corners, ");
    example_print_uint(site_count - corners);
    example_print(" sampled on the floor)\nwalls:      ");
    example_print_uint(WALLS);
    example_print(" constraints, ");
    example_print_uint(constrained_count);
    example_print(" constrained edges (split where a wall meets another)\ntriangles:  ");
    example_print_uint(mesh_count);
    example_print(" on the floor of ");
    example_print_uint(all_triangles);
    example_print("; Euler's count for a floor with one hole: ");
    example_print_uint(expected);
    example_print("\narea:       twice ");
    example_print_int(area);
    example_print(" mm^2 summed over the triangles; the shoelace formula: twice ");
    example_print_int(plan_area);
    example_print("\nlocated:    ");
    example_print_uint(points);
    example_print(" grid points, ");
    example_print_uint(floor_points);
    example_print(" of them on the floor by the even-odd test, each in a floor triangle,\n");
    example_print("            the others in none; ");
    example_print_uint(open);
    example_print(" sides of the floor's boundary not a wall\nway:        ");
    print_point(start);
    example_print(" in the bathroom to ");
    print_point(goal);
    example_print(" in the bedroom: ");
    example_print_uint(steps);
    example_print(" triangles, ");
    example_print_uint(length);
    example_print(" mm through the midpoints of the sides crossed\n");
    example_print("cost:       build ");
    example_print_uint(built - started);
    example_print(", walls ");
    example_print_uint(walled - built);
    example_print(", domain ");
    example_print_uint(marked - walled);
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print("\nmemory:     static, ");
    example_print_uint(sizeof arena);
    example_print(" bytes for the diagram, ");
    example_print_uint(sizeof cdt_memory);
    example_print(" for the constraints\n");
    example_print("files:      build/room.sites, build/room.walls (vor draw --constraints)\n");
    return example_print_tally();
}
