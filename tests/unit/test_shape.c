/* core/shape: turned boxes, discs (annuli) and polygons read from a case, their inside
 * tests, lattice counts and checks. Scratch file: $FSI_TEST_TMP/test_shape.ini. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "case_check.h"
#include "shape.h"
#include "unit_check.h"

static const double dx = 0.002;

static const char *const text =
    "[s.box]\nmin = 0, 0\nmax = 0.1, 0.04\n"
    "[s.turned]\nmin = 0, 0\nmax = 0.1, 0.04\nangle = 30\n"
    "[s.disc]\nshape = disc\ncentre = 0.2, 0.2\nradius = 0.05\n"
    "[s.inner]\nshape = disc\ncentre = 0.2, 0.2\nradius = 0.02\n"
    "[s.annulus]\nshape = disc\ncentre = 0.2, 0.2\nradius = 0.05\ninner_radius = 0.02\n"
    "[s.square]\nshape = polygon\npoints = 0,0 0.1,0 0.1,0.04 0,0.04\n"
    "[s.triangle]\nshape = polygon\npoints = 0,0 0.1,0 0,0.1\n"
    "[s.clockwise]\nshape = polygon\npoints = 0,0 0,0.1 0.1,0\n"
    "[s.touching]\nmin = 0.25, 0.15\nmax = 0.3, 0.25\n"
    "[s.into]\nmin = 0.24, 0.15\nmax = 0.3, 0.25\n"
    "[s.two]\nshape = polygon\npoints = 0,0 1,0\n"
    "[s.bowtie]\nshape = polygon\npoints = 0,0 1,1 1,0 0,1\n"
    "[s.flat]\nshape = disc\ncentre = 0, 0\nradius = 0\n"
    "[s.mixed]\nshape = disc\ncentre = 0, 0\nradius = 1\nmin = 0, 0\n";

static fsi_shape shape_of(const fsi_case *c, const char *name)
{
    fsi_shape s;
    fsi_shape_read(&s, c, name, dx);
    return s;
}

/* Problems fsi_shape_check reports for a section, the text in 'out'. */
static int problems(const fsi_case *c, const char *name, char *out, size_t size)
{
    FILE *f = tmpfile();
    fsi_case_checker k = {c, f, 0};
    fsi_shape s = shape_of(c, name);
    fsi_shape_check(&k, &s, name, dx);
    rewind(f);
    size_t n = fread(out, 1, size - 1, f);
    out[n] = '\0';
    fclose(f);
    return k.errors;
}

int main(void)
{
    const char *tmp = getenv("FSI_TEST_TMP") ? getenv("FSI_TEST_TMP") : ".";
    char path[512], msg[1024];
    mkdir(tmp, 0755);
    snprintf(path, sizeof path, "%s/test_shape.ini", tmp);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        return 1;
    }
    fsi_case *c = fsi_case_read(path, stderr);
    CHECK(c != NULL, "cannot read %s", path);
    if (!c)
        return unit_check_report("test_shape");

    /* A turned box holds exactly the unturned box's points, turned about its centre:
     * the same distances from the centre, each inside the turned shape. */
    fsi_shape box = shape_of(c, "s.box"), turned = shape_of(c, "s.turned");
    CHECK(fsi_shape_points(&box) == 1000.0 && fsi_shape_points(&turned) == 1000.0,
          "box %g, turned box %g points, want 50 x 20 = 1000", fsi_shape_points(&box),
          fsi_shape_points(&turned));
    fsi_shape_walk wb, wt;
    double xb[2], xt[2], worst = 0.0;
    int all_inside = 1, n = 0;
    fsi_shape_walk_begin(&wb, &box, dx);
    fsi_shape_walk_begin(&wt, &turned, dx);
    while (fsi_shape_walk_next(&wb, xb) && fsi_shape_walk_next(&wt, xt)) {
        n++;
        worst = fmax(worst, fabs(hypot(xb[0] - 0.05, xb[1] - 0.02) -
                                 hypot(xt[0] - 0.05, xt[1] - 0.02)));
        all_inside &= fsi_shape_contains(&turned, 1e-9, xt);
    }
    CHECK(n == 1000 && worst < 1e-15 && all_inside, "turned lattice: %d points, distance "
          "from the centre changed by up to %g, all inside %d", n, worst, all_inside);
    const double corner[2] = {0.0999, 0.0399};
    CHECK(fsi_shape_contains(&box, 0.0, corner) && !fsi_shape_contains(&turned, 0.0, corner),
          "the unturned corner lies in the box, not in the turned box");

    /* Disc: pi r^2 / dx^2 = 1963.5 points for r = 25 dx, within 1 % (the lattice's
     * error is of the order of the perimeter's square root in spacings, ~ 13). */
    fsi_shape disc = shape_of(c, "s.disc"), inner = shape_of(c, "s.inner"),
              annulus = shape_of(c, "s.annulus");
    const double area = 3.14159265358979 * 0.05 * 0.05 / (dx * dx);
    CHECK(fabs(fsi_shape_points(&disc) - area) < 0.01 * area, "disc %g points, pi r^2 / dx^2 "
          "= %g", fsi_shape_points(&disc), area);
    CHECK(fsi_shape_points(&annulus) == fsi_shape_points(&disc) - fsi_shape_points(&inner),
          "annulus %g = disc %g - inner disc %g", fsi_shape_points(&annulus),
          fsi_shape_points(&disc), fsi_shape_points(&inner));
    const double centre[2] = {0.2, 0.2}, out[2] = {0.2 + 0.0505, 0.2};
    CHECK(fsi_shape_contains(&disc, 0.0, centre) && !fsi_shape_contains(&annulus, 0.0, centre) &&
          !fsi_shape_contains(&disc, 0.0, out), "disc and annulus inside tests");
    const double up[2] = {0.0, 1.0};
    CHECK(fabs(fsi_shape_reach(&disc, up) - 0.25) < 1e-15, "disc reaches y = %g, want 0.25",
          fsi_shape_reach(&disc, up));

    /* Polygons: area by the shoelace formula, a rectangle holds the box's points, a
     * triangle about area / dx^2 in either orientation. */
    fsi_shape square = shape_of(c, "s.square"), tri = shape_of(c, "s.triangle"),
              cw = shape_of(c, "s.clockwise");
    CHECK(square.n_points == 4 && fabs(fsi_polygon_area(square.points, 4) - 0.004) < 1e-15,
          "square: %d corners, area %g", square.n_points, fsi_polygon_area(square.points, 4));
    CHECK(fabs(fsi_polygon_area(tri.points, 3) - 0.005) < 1e-15 &&
          fsi_polygon_area(cw.points, 3) == fsi_polygon_area(tri.points, 3),
          "triangle area %g, clockwise %g", fsi_polygon_area(tri.points, 3),
          fsi_polygon_area(cw.points, 3));
    CHECK(fsi_shape_points(&square) == 1000.0, "rectangle polygon %g points, want 1000",
          fsi_shape_points(&square));
    /* 50 x 50 / 2 = 1250 below the hypotenuse plus its 50 lattice points on it. */
    CHECK(fsi_shape_points(&tri) == 1275.0 && fsi_shape_points(&cw) == 1275.0,
          "triangle %g, clockwise %g points, want 1275", fsi_shape_points(&tri),
          fsi_shape_points(&cw));

    /* Overlap: a box touching the disc's edge does not overlap it, one reaching in does. */
    fsi_shape touching = shape_of(c, "s.touching"), into = shape_of(c, "s.into");
    CHECK(!fsi_shapes_overlap(&disc, &touching, dx) && fsi_shapes_overlap(&disc, &into, dx) &&
          !fsi_shapes_overlap(&annulus, &inner, dx) && fsi_shapes_overlap(&disc, &inner, dx),
          "overlaps: touching box, box reaching in, annulus around its hole, disc in disc");

    /* Checks: each names the section and the key. */
    CHECK(problems(c, "s.disc", msg, sizeof msg) == 0 &&
              problems(c, "s.turned", msg, sizeof msg) == 0 &&
              problems(c, "s.triangle", msg, sizeof msg) == 0, "a good shape refused: %s", msg);
    CHECK(problems(c, "s.two", msg, sizeof msg) == 1 &&
              strstr(msg, "[s.two] points: too few corners"), "two corners: %s", msg);
    CHECK(problems(c, "s.bowtie", msg, sizeof msg) == 1 &&
              strstr(msg, "[s.bowtie] points: edge 1 (corner 1 to 2) crosses edge 3"),
          "bowtie: %s", msg);
    CHECK(problems(c, "s.flat", msg, sizeof msg) == 1 &&
              strstr(msg, "[s.flat] radius: must be > 0"), "radius 0: %s", msg);
    CHECK(problems(c, "s.mixed", msg, sizeof msg) == 1 &&
              strstr(msg, "[s.mixed] min: only shape = box takes min"), "disc with min: %s", msg);
    CHECK(strstr(msg, "test_shape.ini:") != NULL, "no file and line in: %s", msg);
    fsi_case_free(c);
    return unit_check_report("test_shape");
}
