/*
 * t_geometry.c - planes, triangles and the scene's storage, against values
 * worked out by hand (the working is in the comments), and every
 * validation error of the scene's adds.
 *
 * The hierarchy is tested against brute force in t_bvh.c; here scenes
 * are small and mostly unprepared, so the answers come from the shapes'
 * own arithmetic.
 */
#include <math.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

static rayo_ray ray_make(double ox, double oy, double oz, double dx,
                         double dy, double dz)
{
    rayo_ray r;
    r.origin = rayo_vec3_make(ox, oy, oz);
    r.direction = rayo_vec3_normalize(rayo_vec3_make(dx, dy, dz));
    return r;
}

static void test_plane(void)
{
    const double s = sqrt(0.5);
    rayo_plane p;
    rayo_ray r;
    rayo_vec3 n;
    p.point = rayo_vec3_make(0, 0, 5);
    p.normal = rayo_vec3_make(0, 0, 1);
    r = ray_make(0, 0, 0, 0, 0, 1);
    is_double(rayo_plane_intersect(&p, &r, 0, INFINITY), 5.0, 0,
              "plane z=5, ray along z: t = 5");
    n = rayo_plane_facing_normal(&p, &r);
    ok(n.x == 0 && n.y == 0 && n.z == -1,
       "plane normal turned to face the ray");
    r = ray_make(0, 0, 10, 0, 0, -1);
    n = rayo_plane_facing_normal(&p, &r);
    ok(n.z == 1, "from the other side the normal is kept");
    is_double(rayo_plane_intersect(&p, &r, 0, INFINITY), 5.0, 0,
              "from z=10 looking back: t = 5");
    r = ray_make(0, 0, 0, 0, 0, -1);
    ok(rayo_plane_intersect(&p, &r, 0, INFINITY) == INFINITY,
       "plane behind the origin: miss");
    r = ray_make(0, 0, 0, 1, 0, 0);
    ok(rayo_plane_intersect(&p, &r, 0, INFINITY) == INFINITY,
       "ray parallel to the plane: miss");
    r = ray_make(0, 0, 5, 1, 0, 0);
    ok(rayo_plane_intersect(&p, &r, 0, INFINITY) == INFINITY,
       "ray lying in the plane: miss");
    /* Plane y + z = 5: (P0 - o).n = 5/sqrt2, d.n = (0.6 + 0.8)/sqrt2,
     * t = 5 / 1.4. */
    p.normal = rayo_vec3_make(0, s, s);
    r = ray_make(0, 0, 0, 0, 0.6, 0.8);
    is_double(rayo_plane_intersect(&p, &r, 0, INFINITY), 5.0 / 1.4, 1e-14,
              "tilted plane y+z=5: t = 5/1.4");
    ok(rayo_plane_intersect(&p, &r, 0, 3.0) == INFINITY,
       "crossing beyond t_max: miss");
    ok(rayo_plane_intersect(&p, &r, 4.0, INFINITY) == INFINITY,
       "crossing before t_min: miss");
}

static void test_triangle(void)
{
    rayo_triangle tri;
    rayo_ray r;
    rayo_vec3 n;
    tri.a = rayo_vec3_make(0, 0, 5);
    tri.b = rayo_vec3_make(2, 0, 5);
    tri.c = rayo_vec3_make(0, 2, 5);
    r = ray_make(0.5, 0.5, 0, 0, 0, 1);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), 5.0, 1e-15,
              "triangle inside point: t = 5");
    r = ray_make(1.5, 1.5, 0, 0, 0, 1);
    ok(rayo_triangle_intersect(&tri, &r, 0, INFINITY) == INFINITY,
       "u + v = 1.5 > 1: miss");
    r = ray_make(1, 1, 0, 0, 0, 1);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), 5.0, 1e-15,
              "on the hypotenuse (u + v = 1): hit");
    r = ray_make(0, 0, 0, 0, 0, 1);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), 5.0, 1e-15,
              "through corner a: hit");
    r = ray_make(2, 0, 0, 0, 0, 1);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), 5.0, 1e-15,
              "through corner b: hit");
    r = ray_make(1, 0, 0, 0, 0, 1);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), 5.0, 1e-15,
              "on edge ab (v = 0): hit");
    r = ray_make(-1e-9, 0.5, 0, 0, 0, 1);
    ok(rayo_triangle_intersect(&tri, &r, 0, INFINITY) == INFINITY,
       "just outside edge ac: miss");
    r = ray_make(-1, 0.5, 5, 1, 0, 0);
    ok(rayo_triangle_intersect(&tri, &r, 0, INFINITY) == INFINITY,
       "ray in the triangle's plane: miss");
    r = ray_make(0.5, 0.5, 10, 0, 0, 1);
    ok(rayo_triangle_intersect(&tri, &r, 0, INFINITY) == INFINITY,
       "triangle behind the origin: miss");
    /* From the origin towards (0.5, 0.5, 5): t = |(0.5, 0.5, 5)|. */
    r = ray_make(0, 0, 0, 0.5, 0.5, 5);
    is_double(rayo_triangle_intersect(&tri, &r, 0, INFINITY), sqrt(25.5),
              1e-14, "slanted ray: t = sqrt(25.5)");
    ok(rayo_triangle_intersect(&tri, &r, 0, 5.0) == INFINITY,
       "hit beyond t_max: miss");
    n = rayo_triangle_normal(&tri);
    ok(n.x == 0 && n.y == 0 && n.z == 1, "normal (b-a)x(c-a) = +z");
    ok(rayo_triangle_is_valid(&tri), "a real triangle is valid");
    tri.c = rayo_vec3_make(4, 0, 5);
    ok(!rayo_triangle_is_valid(&tri), "collinear corners are not");
    tri.c = tri.a;
    ok(!rayo_triangle_is_valid(&tri), "a repeated corner is not");
    tri.a = rayo_vec3_make(0, 0, 1e-6);
    tri.b = rayo_vec3_make(1e-6, 0, 1e-6);
    tri.c = rayo_vec3_make(0, 1e-6, 1e-6);
    ok(rayo_triangle_is_valid(&tri), "a tiny triangle is valid (the "
                                     "test is relative)");
    tri.c.x = NAN;
    ok(!rayo_triangle_is_valid(&tri), "a NaN corner is not");
}

/* Runs one failing add and checks its status and a word of its message. */
static void expect_error(rayo_status got, rayo_status want,
                         const rayo_error *err, const char *word,
                         const char *name)
{
    is_int(got, want, "%s: status", name);
    ok(strstr(err->message, word) != NULL &&
           strchr(err->message, '\n') == NULL,
       "%s: one line naming '%s'", name, word);
    printf("# %s\n", err->message);
}

static void test_validation(void)
{
    rayo_scene *s;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_material m;
    rayo_light l;
    unsigned id = 99;
    rayo_vec3 o = rayo_vec3_make(0, 0, 0), z = rayo_vec3_make(0, 0, 1);
    rayo_scene_create(&s, &err);
    expect_error(rayo_scene_add_sphere(s, o, 0.0, &err), RAYO_ERR_INVALID,
                 &err, "radius", "radius 0");
    expect_error(rayo_scene_add_sphere(s, o, -1.0, &err), RAYO_ERR_INVALID,
                 &err, "radius", "radius -1");
    expect_error(rayo_scene_add_sphere(s, o, NAN, &err), RAYO_ERR_INVALID,
                 &err, "radius", "radius NaN");
    expect_error(rayo_scene_add_sphere(s, rayo_vec3_make(INFINITY, 0, 0), 1,
                                       &err),
                 RAYO_ERR_INVALID, &err, "centre", "infinite centre");
    expect_error(rayo_scene_add_sphere_material(s, z, 1, 1, &err),
                 RAYO_ERR_INVALID, &err, "material 1", "unknown material");
    expect_error(rayo_scene_add_plane(s, o, o, 0, &err), RAYO_ERR_INVALID,
                 &err, "normal", "zero plane normal");
    expect_error(rayo_scene_add_plane(s, o, rayo_vec3_make(0, NAN, 1), 0,
                                      &err),
                 RAYO_ERR_INVALID, &err, "normal", "NaN plane normal");
    expect_error(rayo_scene_add_triangle(s, o, z, rayo_vec3_scale(z, 2), 0,
                                         &err),
                 RAYO_ERR_INVALID, &err, "degenerate", "collinear triangle");
    expect_error(rayo_scene_add_triangle(s, o, z, rayo_vec3_make(1, 0, 0), 3,
                                         &err),
                 RAYO_ERR_INVALID, &err, "material 3",
                 "triangle with unknown material");
    is_int(rayo_scene_object_count(s), 0, "no failed add left an object");

    m.color = rayo_vec3_make(1, 0.5, 0);
    m.ka = 0.1;
    m.kd = 0.9;
    m.ks = 0.5;
    m.shininess = 20;
    m.reflectivity = 0.25;
    m.color.y = 1.5;
    expect_error(rayo_scene_add_material(s, &m, &id, &err), RAYO_ERR_INVALID,
                 &err, "colour", "colour above 1");
    m.color.y = 0.5;
    m.ka = -1;
    expect_error(rayo_scene_add_material(s, &m, &id, &err), RAYO_ERR_INVALID,
                 &err, "ka", "negative ka");
    m.ka = 0.1;
    m.shininess = INFINITY;
    expect_error(rayo_scene_add_material(s, &m, &id, &err), RAYO_ERR_INVALID,
                 &err, "shininess", "infinite shininess");
    m.shininess = 20;
    m.reflectivity = 2;
    expect_error(rayo_scene_add_material(s, &m, &id, &err), RAYO_ERR_INVALID,
                 &err, "reflectivity", "reflectivity 2");
    m.reflectivity = 0.25;
    is_int(id, 99, "failed adds leave the id alone");
    is_int(rayo_scene_material_count(s), 1, "material 0 alone so far");
    is_int(rayo_scene_add_material(s, &m, &id, &err), RAYO_OK,
           "a valid material is accepted");
    is_int(id, 1, "the first material added is number 1");
    ok(rayo_scene_material(s, 1)->ks == 0.5 &&
           rayo_scene_material(s, 1)->reflectivity == 0.25,
       "material 1 reads back");
    ok(rayo_scene_material(s, 0)->color.x == 1 &&
           rayo_scene_material(s, 0)->ka == 1 &&
           rayo_scene_material(s, 0)->kd == 1 &&
           rayo_scene_material(s, 0)->ks == 0,
       "material 0 is white, ka = kd = 1, ks = 0");
    ok(rayo_scene_material(s, 2) == NULL, "material 2 does not exist");

    l.kind = RAYO_LIGHT_DIRECTIONAL;
    l.vector = o;
    l.color = rayo_vec3_make(1, 1, 1);
    expect_error(rayo_scene_add_light(s, &l, &err), RAYO_ERR_INVALID, &err,
                 "direction", "zero light direction");
    l.kind = (rayo_light_kind)7;
    expect_error(rayo_scene_add_light(s, &l, &err), RAYO_ERR_INVALID, &err,
                 "kind", "unknown light kind");
    l.kind = RAYO_LIGHT_POINT;
    l.color.z = -1;
    expect_error(rayo_scene_add_light(s, &l, &err), RAYO_ERR_INVALID, &err,
                 "colour", "negative light colour");
    l.color.z = 255;
    is_int(rayo_scene_add_light(s, &l, &err), RAYO_OK,
           "a point light at the origin is fine (intensity 255 too)");
    l.kind = RAYO_LIGHT_DIRECTIONAL;
    l.vector = rayo_vec3_make(3, 0, 4);
    is_int(rayo_scene_add_light(s, &l, &err), RAYO_OK,
           "directional light accepted");
    is_int(rayo_scene_light_count(s), 2, "two lights");
    ok(rayo_scene_light(s, 1)->vector.x == 0.6 &&
           rayo_scene_light(s, 1)->vector.z == 0.8,
       "directional light stored normalised: (0.6, 0, 0.8)");
    rayo_scene_free(s);
}

/*
 * Sphere (0,0,10) r 1 [object 0, material 1], floor y = -2 [object 1],
 * triangle at z = 20 [object 2], second sphere [object 3].
 */
static rayo_scene *small_scene(void)
{
    rayo_scene *s;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_material m = {{1, 0, 0}, 0.1, 0.9, 0, 0, 0};
    unsigned red;
    rayo_scene_create(&s, &err);
    rayo_scene_add_material(s, &m, &red, &err);
    rayo_scene_add_sphere_material(s, rayo_vec3_make(0, 0, 10), 1, red, &err);
    rayo_scene_add_plane(s, rayo_vec3_make(0, -2, 0),
                         rayo_vec3_make(0, 5, 0), 0, &err);
    rayo_scene_add_triangle(s, rayo_vec3_make(-5, -5, 20),
                            rayo_vec3_make(5, -5, 20),
                            rayo_vec3_make(0, 5, 20), 0, &err);
    rayo_scene_add_sphere(s, rayo_vec3_make(3, 0, 10), 0.5, &err);
    return s;
}

static void check_small_scene(rayo_scene *s, const char *how)
{
    rayo_hit h;
    rayo_ray r = ray_make(0, 0, 0, 0, 0, 1);
    ok(rayo_scene_intersect(s, &r, 0, INFINITY, &h) && h.object == 0 &&
           h.t == 9 && h.normal.z == -1 && h.material == 1 && h.point.z == 9,
       "%s: along z the red sphere at t = 9, normal -z", how);
    ok(rayo_scene_occluded(s, &r, 0, INFINITY, 0),
       "%s: skipping the sphere, the triangle still blocks", how);
    ok(!rayo_scene_occluded(s, &r, 0, 15, 0),
       "%s: ... but not before t = 15", how);
    ok(rayo_scene_occluded(s, &r, 0, 15, RAYO_NO_OBJECT),
       "%s: without the skip the sphere blocks", how);
    r = ray_make(0, 0, 10, 0, 0, 1);
    ok(rayo_scene_intersect(s, &r, 0, INFINITY, &h) && h.object == 0 &&
           h.t == 1 && h.normal.z == 1,
       "%s: from inside the sphere: its wall at t = 1, outward normal", how);
    /* Down at (0, -0.6, 0.8): floor y = -2 at t = 2 / 0.6; the sphere's
     * delta = 64 - 100 + 1 < 0. */
    r = ray_make(0, 0, 0, 0, -0.6, 0.8);
    ok(rayo_scene_intersect(s, &r, 0, INFINITY, &h) && h.object == 1 &&
           fabs(h.t - 2 / 0.6) < 1e-14 && h.normal.y == 1 &&
           h.material == 0,
       "%s: the floor at t = 10/3 with normal +y", how);
    r = ray_make(0, 0, 0, 0, 0.15, 1);
    ok(rayo_scene_intersect(s, &r, 0, INFINITY, &h) && h.object == 2 &&
           h.normal.z == -1,
       "%s: above the sphere, the triangle, normal facing the ray", how);
    r = ray_make(3, 0, 0, 0, 0, 1);
    ok(rayo_scene_intersect(s, &r, 0, INFINITY, &h) && h.object == 3 &&
           h.t == 9.5,
       "%s: the second sphere is object 3, t = 9.5", how);
    r = ray_make(0, 0, 0, 0, 1, 0);
    ok(!rayo_scene_intersect(s, &r, 0, INFINITY, &h) &&
           !rayo_scene_hit_any(s, &r, 0),
       "%s: straight up: nothing", how);
}

static void test_scene_queries(void)
{
    rayo_scene *s = small_scene();
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    is_int(rayo_scene_object_count(s), 4, "four objects");
    is_int(rayo_scene_sphere_count(s), 2, "two of them spheres");
    is_int(rayo_scene_object_kind(s, 1), RAYO_OBJECT_PLANE, "object 1 is "
                                                            "the plane");
    is_int(rayo_scene_object_kind(s, 2), RAYO_OBJECT_TRIANGLE,
           "object 2 the triangle");
    ok(rayo_scene_sphere(s, 1)->radius == 0.5, "sphere 1 is object 3");
    ok(!rayo_scene_is_prepared(s), "not prepared yet");
    check_small_scene(s, "brute force");
    is_int(rayo_scene_prepare(s, &err), RAYO_OK, "prepare");
    ok(rayo_scene_is_prepared(s), "prepared");
    check_small_scene(s, "prepared");
    rayo_scene_add_sphere(s, rayo_vec3_make(0, 0, 5), 0.25, &err);
    ok(!rayo_scene_is_prepared(s), "an add undoes the preparation");
    rayo_scene_free(s);
    /* No assertion can see a free; a crash here breaks the plan. */
    rayo_scene_free(NULL);
}

static void test_ambient_background(void)
{
    rayo_scene *s;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_vec3 v;
    rayo_scene_create(&s, &err);
    v = rayo_scene_ambient(s);
    ok(v.x == 0 && v.y == 0 && v.z == 0, "ambient starts at 0");
    rayo_scene_set_ambient(s, rayo_vec3_make(0.05, 0.05, 0.05));
    rayo_scene_set_background(s, rayo_vec3_make(0.1, 0.2, 0.3));
    ok(rayo_scene_ambient(s).y == 0.05, "ambient reads back");
    ok(rayo_scene_background(s).z == 0.3, "background reads back");
    rayo_scene_free(s);
}

/* The watertightness test's numbers: the library's seeded generator. */
static rayo_lcg wt_lcg;

static double wt_uniform(double lo, double hi)
{
    return lo + (hi - lo) * rayo_lcg_next(&wt_lcg);
}

#define WT_N 9 /* vertices a side of the mesh */
#define WT_TRIANGLES (2 * (WT_N - 1) * (WT_N - 1))

/* 1 when some triangle of the mesh meets the ray at distance, within
 * 1e-9 of it (another part of the mesh in front does not count). */
static int wt_meets_at(const rayo_triangle *mesh, const rayo_ray *r,
                       double distance)
{
    int k;
    for (k = 0; k < WT_TRIANGLES; k++)
        if (fabs(rayo_triangle_intersect(&mesh[k], r, 0, INFINITY) -
                 distance) <= 1e-9 * distance)
            return 1;
    return 0;
}

static int wt_has_corner(const rayo_triangle *tri, rayo_vec3 p)
{
    const rayo_vec3 *c[3];
    int k;
    c[0] = &tri->a;
    c[1] = &tri->b;
    c[2] = &tri->c;
    for (k = 0; k < 3; k++)
        if (c[k]->x == p.x && c[k]->y == p.y && c[k]->z == p.z)
            return 1;
    return 0;
}

/*
 * 1 when the triangles around the target (those with both corners p and
 * q; with p == q, those with the corner p) all face the ray the same way.
 * Where they do not, the target is on the mesh's silhouette as the ray
 * sees it, and a ray that rounding sets just beside it rightly misses.
 */
static int wt_faces_one_way(const rayo_triangle *mesh, rayo_vec3 p,
                            rayo_vec3 q, rayo_vec3 d)
{
    int k, front = 0, back = 0;
    for (k = 0; k < WT_TRIANGLES; k++)
        if (wt_has_corner(&mesh[k], p) && wt_has_corner(&mesh[k], q)) {
            double f = rayo_vec3_dot(
                rayo_vec3_cross(rayo_vec3_sub(mesh[k].b, mesh[k].a),
                                rayo_vec3_sub(mesh[k].c, mesh[k].a)),
                d);
            front += f < 0;
            back += f > 0;
        }
    return (front == 0) != (back == 0);
}

/*
 * Watertightness: a bumpy mesh of WT_N x WT_N vertices, each cell cut
 * into two triangles, and rays from scattered origins at points of its
 * inner edges (drawn along the edge, so within rounding of it) and at
 * its inner vertices.  Every ray must meet the mesh where it was aimed
 * (some triangle's hit within 1e-9 of the target's distance), not slip
 * through.  (Where the bumps fold, a ray may meet the mesh in front of
 * its target too, which does not count either way; and a target on the
 * mesh's silhouette as seen from the ray's origin is left out.)  The Moller-Trumbore test this
 * replaced let 8.8% of these edge rays and 5.9% of the corner rays
 * through.
 */
static void test_watertight(void)
{
    rayo_vec3 v[WT_N][WT_N];
    rayo_triangle mesh[WT_TRIANGLES];
    long rays[2] = {0, 0}, gaps[2] = {0, 0}, silhouette = 0;
    int i, j, n, m = 0;
    rayo_lcg_seed(&wt_lcg, 2013);
    for (i = 0; i < WT_N; i++)
        for (j = 0; j < WT_N; j++) {
            /* One draw a statement: the same mesh whatever order a
             * compiler evaluates arguments in. */
            double x = i - 4.0 + wt_uniform(-0.3, 0.3);
            double y = j - 4.0 + wt_uniform(-0.3, 0.3);
            double z = 10.0 + sin(0.7 * i) * cos(0.5 * j) +
                       wt_uniform(-0.2, 0.2);
            v[i][j] = rayo_vec3_make(x, y, z);
        }
    for (i = 0; i + 1 < WT_N; i++)
        for (j = 0; j + 1 < WT_N; j++) {
            mesh[m].a = v[i][j];
            mesh[m].b = v[i + 1][j];
            mesh[m++].c = v[i + 1][j + 1];
            mesh[m].a = v[i][j];
            mesh[m].b = v[i + 1][j + 1];
            mesh[m++].c = v[i][j + 1];
        }
    for (n = 0; n < 40000; n++) {
        int corner = n % 8 == 0, kind = n % 3;
        rayo_vec3 target, from, to;
        rayo_ray r;
        double ox, oy, oz, distance;
        i = 1 + (int)wt_uniform(0, WT_N - 2);
        j = 1 + (int)wt_uniform(0, WT_N - 2);
        if (corner) {
            target = from = to = v[i][j];
        } else {
            /* An inner edge from v[i][j]: the diagonal down-left, or the
             * edge to the left or below, each between two triangles. */
            from = v[i][j];
            to = kind == 0 ? v[i - 1][j - 1] : kind == 1 ? v[i - 1][j]
                                                          : v[i][j - 1];
            target = rayo_vec3_add(
                from,
                rayo_vec3_scale(rayo_vec3_sub(to, from), wt_uniform(0, 1)));
        }
        ox = wt_uniform(-3, 3);
        oy = wt_uniform(-3, 3);
        oz = wt_uniform(-2, 2);
        r.origin = rayo_vec3_make(ox, oy, oz);
        distance = rayo_vec3_length(rayo_vec3_sub(target, r.origin));
        r.direction = rayo_vec3_normalize(rayo_vec3_sub(target, r.origin));
        if (!wt_faces_one_way(mesh, from, to, r.direction)) {
            silhouette++;
            continue;
        }
        rays[corner]++;
        gaps[corner] += !wt_meets_at(mesh, &r, distance);
    }
    is_int(gaps[0], 0, "watertight: %ld rays at shared edges all meet them",
           rays[0]);
    is_int(gaps[1], 0, "watertight: %ld rays at shared corners all meet them",
           rays[1]);
    ok(silhouette < 2000, "watertight: %ld rays left out at the silhouette",
       silhouette);
}

int main(void)
{
    test_plane();
    test_triangle();
    test_watertight();
    test_validation();
    test_scene_queries();
    test_ambient_background();
    return tap_done();
}
