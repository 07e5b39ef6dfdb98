/* Boxes, turned boxes, discs and polygons: reading, checking, inside tests and the
 * lattice that fills them (shape.h). */
#include "shape.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lattice_box.h"

/* Relative tolerance (in spacings) of edges: a lattice point this close to an edge is
 * on it. */
#define SHAPE_TOL 1e-6

static const double pi = 3.14159265358979323846;

static int given(const fsi_case *c, const char *section, const char *key)
{
    const char *o = fsi_case_origin(c, section, key);
    return o && strcmp(o, "default") != 0;
}

static void read_vector(const fsi_case *c, const char *section, const char *key, double *out)
{
    if (fsi_case_get_vector(c, section, key, out) != 0)
        for (int d = 0; d < FSI_DIM; d++)
            out[d] = 0.0;
}

/* Numbers separated by blanks, commas or semicolons, taken in pairs. */
static void read_points(fsi_shape *s, const char *text)
{
    int n = 0;
    const char *p = text ? text : "";
    for (;;) {
        p += strspn(p, " \t,;");
        if (!*p)
            break;
        char *end;
        const double v = strtod(p, &end);
        if (end == p || !isfinite(v)) {
            int len = (int)strcspn(p, " \t,;");
            snprintf(s->points_problem, sizeof s->points_problem, "'%.*s' is not a number",
                     len > 40 ? 40 : len, p);
            s->n_points = 0;
            return;
        }
        if (n == 2 * FSI_SHAPE_MAX_POINTS) {
            snprintf(s->points_problem, sizeof s->points_problem, "more than %d corners",
                     FSI_SHAPE_MAX_POINTS);
            s->n_points = 0;
            return;
        }
        s->points[n++] = v;
        p = end;
    }
    if (n % 2) {
        snprintf(s->points_problem, sizeof s->points_problem,
                 "%d numbers, not pairs x,y", n);
        n = 0;
    }
    s->n_points = n / 2;
}

/* Local coordinates of x in a turned box's frame, relative to its centre. */
static void box_local(const fsi_shape *s, const double *x, double *q)
{
    for (int d = 0; d < FSI_DIM; d++)
        q[d] = x[d] - s->centre[d];
    const double u = q[0], v = q[1];
    q[0] = s->cos_a * u + s->sin_a * v;
    q[1] = -s->sin_a * u + s->cos_a * v;
}

static void box_turn(const fsi_shape *s, double *x)
{
    const double u = x[0] - s->centre[0], v = x[1] - s->centre[1];
    x[0] = s->centre[0] + s->cos_a * u - s->sin_a * v;
    x[1] = s->centre[1] + s->sin_a * u + s->cos_a * v;
}

static void bounds(fsi_shape *s)
{
    for (int d = 0; d < FSI_DIM; d++) {
        s->lo[d] = INFINITY;
        s->hi[d] = -INFINITY;
    }
    if (s->kind == FSI_SHAPE_BOX) {
        for (int corner = 0; corner < (1 << FSI_DIM); corner++) {
            double x[FSI_DIM];
            for (int d = 0; d < FSI_DIM; d++)
                x[d] = (corner >> d) & 1 ? s->max[d] : s->min[d];
            if (s->angle != 0.0)
                box_turn(s, x);
            for (int d = 0; d < FSI_DIM; d++) {
                s->lo[d] = fmin(s->lo[d], x[d]);
                s->hi[d] = fmax(s->hi[d], x[d]);
            }
        }
    } else if (s->kind == FSI_SHAPE_DISC) {
        for (int d = 0; d < FSI_DIM; d++) {
            s->lo[d] = s->centre[d] - s->radius;
            s->hi[d] = s->centre[d] + s->radius;
        }
    } else {
        for (int d = 0; d < FSI_DIM; d++)
            s->lo[d] = s->hi[d] = 0.0;
        for (int i = 0; i < s->n_points; i++)
            for (int d = 0; d < 2; d++) {
                const double v = s->points[2 * i + d];
                s->lo[d] = i ? fmin(s->lo[d], v) : v;
                s->hi[d] = i ? fmax(s->hi[d], v) : v;
            }
    }
}

void fsi_shape_read(fsi_shape *s, const fsi_case *c, const char *section, double spacing)
{
    memset(s, 0, sizeof *s);
    s->kind = fsi_case_choice_is(c, section, "shape", "disc")      ? FSI_SHAPE_DISC
              : fsi_case_choice_is(c, section, "shape", "polygon") ? FSI_SHAPE_POLYGON
                                                                   : FSI_SHAPE_BOX;
    read_vector(c, section, "min", s->min);
    read_vector(c, section, "max", s->max);
    for (int d = 0; d < FSI_DIM; d++)
        s->count[d] = fsi_lattice_count(s->min[d], s->max[d], spacing);
    if (s->kind == FSI_SHAPE_BOX) {
        s->angle = fsi_case_get_real(c, section, "angle", 0.0) * pi / 180.0;
        s->cos_a = cos(s->angle);
        s->sin_a = sin(s->angle);
        for (int d = 0; d < FSI_DIM; d++)
            s->centre[d] = 0.5 * (s->min[d] + s->max[d]);
    } else if (s->kind == FSI_SHAPE_DISC) {
        read_vector(c, section, "centre", s->centre);
        s->radius = fmax(fsi_case_get_real(c, section, "radius", 0.0), 0.0);
        s->inner_radius = fsi_case_get_real(c, section, "inner_radius", 0.0);
    } else {
        read_points(s, fsi_case_get(c, section, "points"));
    }
    bounds(s);
    if (s->kind == FSI_SHAPE_BOX) {
        s->n_lattice = fsi_lattice_points(s->count);
        return;
    }
    /* Counted point by point, unless the bounding box alone holds more than any run
     * may (the solvers' checks refuse that count). */
    double candidates = 1.0;
    for (int d = 0; d < FSI_DIM; d++)
        candidates *= spacing > 0.0 ? (s->hi[d] - s->lo[d]) / spacing + 2.0 : 0.0;
    if (!(candidates < 4e9)) {
        s->n_lattice = candidates;
        return;
    }
    fsi_shape_walk w;
    double x[FSI_DIM];
    fsi_shape_walk_begin(&w, s, spacing);
    while (fsi_shape_walk_next(&w, x))
        s->n_lattice += 1.0;
}

double fsi_shape_points(const fsi_shape *s)
{
    return s->kind == FSI_SHAPE_BOX ? fsi_lattice_points(s->count) : s->n_lattice;
}

int fsi_shape_is_plain_box(const fsi_shape *s)
{
    return s->kind == FSI_SHAPE_BOX && s->angle == 0.0;
}

static double distance_to_segment(const double *x, const double *a, const double *b)
{
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double len2 = ex * ex + ey * ey;
    double t = len2 > 0.0 ? ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / len2 : 0.0;
    t = fmin(fmax(t, 0.0), 1.0);
    return hypot(x[0] - a[0] - t * ex, x[1] - a[1] - t * ey);
}

/* Signed distance to the polygon's edges: < 0 inside (even-odd rule), > 0 outside. */
static double polygon_distance(const fsi_shape *s, const double *x)
{
    int inside = 0;
    double dist = INFINITY;
    for (int i = 0, j = s->n_points - 1; i < s->n_points; j = i++) {
        const double *a = &s->points[2 * j], *b = &s->points[2 * i];
        if ((a[1] > x[1]) != (b[1] > x[1]) &&
            x[0] < a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            inside = !inside;
        dist = fmin(dist, distance_to_segment(x, a, b));
    }
    return inside ? -dist : dist;
}

int fsi_shape_contains(const fsi_shape *s, double tol, const double *x)
{
    switch (s->kind) {
    case FSI_SHAPE_BOX: {
        if (s->angle == 0.0)
            return fsi_box_contains(s->min, s->max, tol, x);
        double q[FSI_DIM];
        box_local(s, x, q);
        for (int d = 0; d < FSI_DIM; d++)
            if (fabs(q[d]) > 0.5 * (s->max[d] - s->min[d]) + tol)
                return 0;
        return 1;
    }
    case FSI_SHAPE_DISC: {
        double r2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            r2 += (x[d] - s->centre[d]) * (x[d] - s->centre[d]);
        const double r = sqrt(r2);
        return r <= s->radius + tol && (s->inner_radius <= 0.0 || r >= s->inner_radius - tol);
    }
    case FSI_SHAPE_POLYGON:
        return s->n_points >= 3 && polygon_distance(s, x) <= tol;
    }
    return 0;
}

double fsi_shape_reach(const fsi_shape *s, const double *u)
{
    double best = -INFINITY;
    if (s->kind == FSI_SHAPE_DISC) {
        best = s->radius;
        for (int d = 0; d < FSI_DIM; d++)
            best += s->centre[d] * u[d];
    } else if (s->kind == FSI_SHAPE_POLYGON) {
        for (int i = 0; i < s->n_points; i++)
            best = fmax(best, s->points[2 * i] * u[0] + s->points[2 * i + 1] * u[1]);
    } else {
        for (int corner = 0; corner < (1 << FSI_DIM); corner++) {
            double x[FSI_DIM], dot = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                x[d] = (corner >> d) & 1 ? s->max[d] : s->min[d];
            if (s->angle != 0.0)
                box_turn(s, x);
            for (int d = 0; d < FSI_DIM; d++)
                dot += x[d] * u[d];
            best = fmax(best, dot);
        }
    }
    return best;
}

void fsi_shape_walk_begin(fsi_shape_walk *w, const fsi_shape *s, double spacing)
{
    memset(w, 0, sizeof *w);
    w->s = s;
    w->dx = spacing;
    if (s->kind == FSI_SHAPE_BOX) {
        w->n = (long)fsi_lattice_points(s->count);
        return;
    }
    if (!(spacing > 0.0))
        return;
    w->n = 1;
    for (int d = 0; d < FSI_DIM; d++) {
        w->first[d] = (long)floor(s->lo[d] / spacing - 0.5);
        w->span[d] = (long)ceil(s->hi[d] / spacing - 0.5) - w->first[d] + 1;
        w->n *= w->span[d] > 0 ? w->span[d] : 0;
    }
}

int fsi_shape_walk_next(fsi_shape_walk *w, double *x)
{
    const fsi_shape *s = w->s;
    if (s->kind == FSI_SHAPE_BOX) {
        if (w->j >= w->n)
            return 0;
        fsi_lattice_point(s->min, s->count, w->dx, w->j++, x);
        if (s->angle != 0.0)
            box_turn(s, x);
        return 1;
    }
    while (w->j < w->n) {
        long j = w->j++;
        for (int d = 0; d < FSI_DIM; d++) {
            x[d] = ((double)(w->first[d] + j % w->span[d]) + 0.5) * w->dx;
            j /= w->span[d];
        }
        if (fsi_shape_contains(s, SHAPE_TOL * w->dx, x))
            return 1;
    }
    return 0;
}

/* 1 when a lattice point of a lies inside b by more than the tolerance. */
static int point_inside(const fsi_shape *a, const fsi_shape *b, double spacing)
{
    fsi_shape_walk w;
    double x[FSI_DIM];
    fsi_shape_walk_begin(&w, a, spacing);
    while (fsi_shape_walk_next(&w, x))
        if (fsi_shape_contains(b, -SHAPE_TOL * spacing, x))
            return 1;
    return 0;
}

int fsi_shapes_overlap(const fsi_shape *a, const fsi_shape *b, double spacing)
{
    if (fsi_shape_is_plain_box(a) && fsi_shape_is_plain_box(b))
        return fsi_boxes_overlap(a->min, a->max, b->min, b->max) > SHAPE_TOL * spacing;
    if (fsi_boxes_overlap(a->lo, a->hi, b->lo, b->hi) <= 0.0)
        return 0;
    return point_inside(a, b, spacing) || point_inside(b, a, spacing);
}

double fsi_polygon_area(const double *points, int n_points)
{
    double twice = 0.0;
    for (int i = 0, j = n_points - 1; i < n_points; j = i++)
        twice += points[2 * j] * points[2 * i + 1] - points[2 * i] * points[2 * j + 1];
    return 0.5 * fabs(twice);
}

/* Twice the signed area of the triangle a, b, c. */
static double orientation(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int on_segment(const double *a, const double *b, const double *p)
{
    return fmin(a[0], b[0]) <= p[0] && p[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= p[1] &&
           p[1] <= fmax(a[1], b[1]);
}

/* 1 when segments p-q and a-b share a point (touching counts). */
static int segments_meet(const double *p, const double *q, const double *a, const double *b)
{
    const double o1 = orientation(p, q, a), o2 = orientation(p, q, b);
    const double o3 = orientation(a, b, p), o4 = orientation(a, b, q);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return 1;
    return (o1 == 0 && on_segment(p, q, a)) || (o2 == 0 && on_segment(p, q, b)) ||
           (o3 == 0 && on_segment(a, b, p)) || (o4 == 0 && on_segment(a, b, q));
}

/* The first two edges (i, j) that cross or touch other than at their shared corner;
 * 0 when the polygon is simple. */
static int crossing_edges(const fsi_shape *s, int *ei, int *ej)
{
    const int n = s->n_points;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            if (j == i + 1 || (i == 0 && j == n - 1))
                continue;       /* neighbours share a corner */
            if (segments_meet(&s->points[2 * i], &s->points[2 * ((i + 1) % n)],
                              &s->points[2 * j], &s->points[2 * ((j + 1) % n)])) {
                *ei = i;
                *ej = j;
                return 1;
            }
        }
    return 0;
}

/* Keys that belong to another shape than the section's. */
static void check_foreign_keys(fsi_case_checker *k, const fsi_shape *s, const char *section)
{
    static const char *const shape_word[] = {"box", "disc", "polygon"};
    const struct {
        const char *key;
        fsi_shape_kind owner;
    } keys[] = {{"min", FSI_SHAPE_BOX},    {"max", FSI_SHAPE_BOX},
                {"angle", FSI_SHAPE_BOX},  {"centre", FSI_SHAPE_DISC},
                {"radius", FSI_SHAPE_DISC}, {"inner_radius", FSI_SHAPE_DISC},
                {"points", FSI_SHAPE_POLYGON}};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (keys[i].owner != s->kind && given(k->c, section, keys[i].key))
            fsi_case_problem(k, section, keys[i].key, "only shape = %s takes %s (this section "
                             "has shape = %s)", shape_word[keys[i].owner], keys[i].key,
                             shape_word[s->kind]);
}

static void check_polygon(fsi_case_checker *k, const fsi_shape *s, const char *section,
                          double spacing)
{
    if (s->points_problem[0]) {
        fsi_case_problem(k, section, "points", "%s: give the corners as x1,y1 x2,y2 x3,y3 ...",
                         s->points_problem);
        return;
    }
    if (s->n_points < 3) {
        fsi_case_problem(k, section, "points", "%s: a polygon needs at least 3 corners "
                         "(x1,y1 x2,y2 x3,y3 ...)", s->n_points ? "too few corners" :
                         "required with shape = polygon");
        return;
    }
    for (int i = 0; i < s->n_points; i++) {
        const int j = (i + 1) % s->n_points;
        if (s->points[2 * i] == s->points[2 * j] && s->points[2 * i + 1] == s->points[2 * j + 1]) {
            fsi_case_problem(k, section, "points", "corners %d and %d are the same point "
                             "(%g, %g)", i + 1, j + 1, s->points[2 * i], s->points[2 * i + 1]);
            return;
        }
    }
    int ei, ej;
    if (crossing_edges(s, &ei, &ej)) {
        fsi_case_problem(k, section, "points", "edge %d (corner %d to %d) crosses edge %d "
                         "(corner %d to %d): the polygon must be simple", ei + 1, ei + 1,
                         (ei + 1) % s->n_points + 1, ej + 1, ej + 1,
                         (ej + 1) % s->n_points + 1);
        return;
    }
    if (!(fsi_polygon_area(s->points, s->n_points) > SHAPE_TOL * spacing * spacing))
        fsi_case_problem(k, section, "points", "the polygon has no area");
}

int fsi_shape_check(fsi_case_checker *k, const fsi_shape *s, const char *section,
                    double spacing)
{
    const int before = k->errors;
    check_foreign_keys(k, s, section);
    if (s->kind == FSI_SHAPE_BOX) {
        for (int i = 0; i < 2; i++) {
            const char *key = i ? "max" : "min";
            if (!given(k->c, section, key))
                fsi_case_problem(k, section, key, "required key missing (shape = box)");
        }
        if (FSI_DIM != 2 && s->angle != 0.0)
            fsi_case_problem(k, section, "angle", "turned boxes are 2D only; this build is "
                             "%dD", FSI_DIM);
        return k->errors - before;
    }
    if (FSI_DIM != 2) {
        fsi_case_problem(k, section, "shape", "discs and polygons are 2D only; this build is "
                         "%dD", FSI_DIM);
        return k->errors - before;
    }
    if (s->kind == FSI_SHAPE_DISC) {
        if (!given(k->c, section, "centre"))
            fsi_case_problem(k, section, "centre", "required with shape = disc");
        if (!(s->radius > 0.0))
            fsi_case_problem(k, section, "radius", "must be > 0 with shape = disc (it is "
                             "%g m)", fsi_case_get_real(k->c, section, "radius", 0.0));
        else if (s->inner_radius >= s->radius)
            fsi_case_problem(k, section, "inner_radius", "%g m is not below radius = %g m: "
                             "the annulus would be empty", s->inner_radius, s->radius);
    } else {
        check_polygon(k, s, section, spacing);
    }
    if (k->errors == before && !(s->n_lattice >= 1.0))
        fsi_case_problem(k, section, "shape", "holds no lattice point (the points (i + 1/2) "
                         "spacing, spacing %g m): make it larger", spacing);
    return k->errors - before;
}
