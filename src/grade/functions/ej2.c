/*
 * ej2.c - the functions table of Ejercicio obligatorio 2 (gray, float[3]
 * vectors): the statement's eight functions, the cases that reveal what
 * the course's scene hides (vector values; rays to spheres that are
 * hit, missed, or hit only behind the origin; scenes made to reveal one
 * shading mistake each, after the course's scene 2 from the course
 * module), the records its harness (harness/ej2.c) is given, the
 * expected values in double precision on the float-rounded arguments,
 * and the judging that names the modelled mistake a wrong result
 * agrees with.  The engine (engine.c) probes, builds, runs and calls
 * judge.
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../course/course_impl.h"
#include "harness.h"
#include "harness_sources.h"
#include "table.h"
#include "harness_math.h"

#define IA 5.0
#define II 255.0
#define MAX_SPHERES 6
#define SAID_PER_FUNCTION 2 /* wrong cases quoted; the others counted */

enum {
    F_PRODUCTO,
    F_NORMA,
    F_NORMALIZAR,
    F_RESTA,
    F_INTERPOLAR,
    F_DISTANCIA,
    F_NORMAL,
    F_INTENSIDAD,
    F_COUNT
};

static const functions_function functions[F_COUNT] = {
    {"producto_interno",
     "float producto_interno(const float a[3], const float b[3])"},
    {"norma",
     "float norma(const float a[3])"},
    {"normalizar",
     "void normalizar(float a[3])"},
    {"resta",
     "void resta(float r[3], const float a[3], const float b[3])"},
    {"interpolar_recta",
     "void interpolar_recta(float p[3], const float o[3], const float d[3], "
     "float t)"},
    {"distancia_esfera",
     "float distancia_esfera(const float c[3], float r, const float o[3], "
     "const float d[3])"},
    {"normal_esfera",
     "void normal_esfera(float normal[3], const float c[3], float r, "
     "const float p[3])"},
    {"computar_intensidad",
     "int computar_intensidad(const float cs[][3], const float rs[], "
     "size_t n_esferas, const float luz[3], const float o[3], "
     "const float d[3])"},
};

/* The arguments of one call: a, b, c are vectors, s a scalar, by
   function: producto_interno(a, b); norma(a); normalizar(a);
   resta(r, a, b); interpolar_recta(p, a, b, s);
   distancia_esfera(a, s, b, c); normal_esfera(n, a, s, b). */
typedef struct vector_case {
    unsigned function;
    double a[3], b[3], c[3], s;
    const char *miss; /* distancia_esfera: how the ray misses, or NULL */
} vector_case;

static const vector_case vector_cases[] = {
    {F_PRODUCTO, {1, 2, 3}, {4, 5, 6}, {0, 0, 0}, 0, NULL},
    {F_PRODUCTO, {0.5, -1.5, 2}, {3, 0.25, -4}, {0, 0, 0}, 0, NULL},
    {F_PRODUCTO, {0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}, {0, 0, 0}, 0, NULL},
    {F_NORMA, {3, 4, 12}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_NORMA, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_NORMA, {-0.6, 0, -0.8}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_NORMALIZAR, {3, 4, 12}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_NORMALIZAR, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_NORMALIZAR, {0, -2, 0}, {0, 0, 0}, {0, 0, 0}, 0, NULL},
    {F_RESTA, {1, 2, 3}, {4, 6, 8}, {0, 0, 0}, 0, NULL},
    {F_RESTA, {0.5, -1, 2}, {-0.25, 0.5, 0.75}, {0, 0, 0}, 0, NULL},
    {F_INTERPOLAR, {1, 2, 3}, {0.5, -1, 2}, {0, 0, 0}, 2, NULL},
    {F_INTERPOLAR, {0, 0, 0}, {0.6, 0, 0.8}, {0, 0, 0}, 1.5, NULL},
    /* distancia_esfera: c, o, d and r */
    {F_DISTANCIA, {0, 0, 2}, {0, 0, 0}, {0, 0, 1}, 0.8, NULL},
    {F_DISTANCIA, {0.5, 0.75, 1.9}, {0, 0, 0}, {0.1, 0.2, 1}, 0.8, NULL},
    {F_DISTANCIA, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}, 2, NULL},
    {F_DISTANCIA, {1, 1, 5}, {1, 1, 0}, {0, 0, 1}, 1, NULL},
    {F_DISTANCIA, {0, 0, 3}, {0, 0, 0}, {1, 0, 0}, 1, "misses the sphere"},
    {F_DISTANCIA, {0, 0, -3}, {0, 0, 0}, {0, 0, 1}, 1,
     "meets the sphere only behind its origin (t < 0)"},
    /* normal_esfera: c, p and r */
    {F_NORMAL, {1, 2, 3}, {1, 2, 5}, {0, 0, 0}, 2, NULL},
    {F_NORMAL, {0.5, 0.75, 1.9}, {0.98, 0.75, 1.26}, {0, 0, 0}, 0.8, NULL},
};
#define VECTOR_CASES (sizeof vector_cases / sizeof vector_cases[0])

/* A scene for computar_intensidad. */
typedef struct scene {
    const char *what; /* "the course's scene 2", "2 spheres: ..." */
    size_t n;
    double c[MAX_SPHERES][3], r[MAX_SPHERES];
    double light[3]; /* normalised here */
} scene;

/* Scene 0 is the course's scene 2, filled from the course module
   (course_scenes.c, the one copy of its numbers) by scene_of. */
#define COURSE_SCENE 0

static const scene scenes[] = {
    {"the course's scene 2", 0, {{0, 0, 0}}, {0}, {0, 0, 0}},
    /* Reversed order: the far sphere first. */
    {"2 spheres, the far one first: (0, 0, 4) r 1, (0, -0.3, 2) r 0.5",
     2,
     {{0, 0, 4}, {0, -0.3, 2}},
     {1, 0.5},
     {1, 1, -1}},
    /* The same two in the other order. */
    {"2 spheres, the near one first: (0, -0.3, 2) r 0.5, (0, 0, 4) r 1",
     2,
     {{0, -0.3, 2}, {0, 0, 4}},
     {0.5, 1},
     {1, 1, -1}},
    /* A sphere between the point and the light. */
    {"a sphere (0, 0, 3) r 1 with a sphere (0, 2.5, 2) r 0.5 above it "
     "and the light straight up",
     2,
     {{0, 0, 3}, {0, 2.5, 2}},
     {1, 0.5},
     {0, 1, 0}},
    /* A sphere on the other side of the point, away from the light. */
    {"a sphere (0, 0, 3) r 1 with a sphere (0, -2.5, 2) r 0.5 below it "
     "and the light straight up",
     2,
     {{0, 0, 3}, {0, -2.5, 2}},
     {1, 0.5},
     {0, 1, 0}},
    /* The light behind the camera, straight at the point: L.N = 1. */
    {"a sphere (0, 0, 3) r 1 with the light towards the camera (0, 0, -1)",
     1,
     {{0, 0, 3}},
     {1},
     {0, 0, -1}},
};

typedef struct ray_case {
    unsigned scene;
    double d[3]; /* normalised here */
} ray_case;

/* The course's rays are pixel directions (vx, vy, 320) well away from
   every outline and shadow edge. */
static const ray_case ray_cases[] = {
    {0, {0, 0, 320}},
    {0, {230, -95, 320}},
    {0, {-100, 60, 320}},
    {0, {-150, -160, 320}},
    {0, {-110, 80, 320}},
    {1, {0.05, 0, 1}},
    {2, {0.05, 0, 1}},
    {3, {0, 0.3, 1}},
    {4, {0, 0.3, 1}},
    {3, {0, -0.3, 1}},
    {5, {0, 0, 1}},
};
#define RAY_CASES (sizeof ray_cases / sizeof ray_cases[0])

/* ---- arithmetic in double, on float-rounded inputs (harness_math.h) ---- */

/* The float arguments of a vector case. */
static void case_args(const vector_case *v, double *a, double *b, double *c,
                      double *s)
{
    vfl(v->a, a);
    vfl(v->b, b);
    vfl(v->c, c);
    if (v->function == F_DISTANCIA) {
        unit(v->c, c);
        vfl(c, c);
    }
    *s = fl(v->s);
}

/* The ray's t to the sphere: the near root when > 0, else the far one,
   else INFINITY; far: the far root only. */
static double sphere_t(const double *c, double r, const double *o,
                       const double *d, int far)
{
    double oc[3], beta, delta, s;
    oc[0] = c[0] - o[0];
    oc[1] = c[1] - o[1];
    oc[2] = c[2] - o[2];
    beta = dot(oc, d);
    delta = beta * beta - dot(oc, oc) + r * r;
    if (delta < 0)
        return INFINITY;
    s = sqrt(delta);
    if (!far && beta - s > 0)
        return beta - s;
    if (beta + s > 0)
        return beta + s;
    return INFINITY;
}

/* Scene index as written (in double): the course's from its module.
   Returns whole. */
static const scene *scene_of(unsigned index, scene *whole)
{
    const rayo_course_data *data = rayo_course_data_of(RAYO_COURSE_EJ2);
    size_t i;
    *whole = scenes[index];
    if (index != COURSE_SCENE || data == NULL || data->lamp_count < 1)
        return whole;
    whole->n = data->ball_count < MAX_SPHERES ? data->ball_count
                                              : MAX_SPHERES;
    for (i = 0; i < whole->n; i++) {
        memcpy(whole->c[i], data->balls[i].center, sizeof whole->c[i]);
        whole->r[i] = data->balls[i].radius;
    }
    memcpy(whole->light, data->lamps[0].vector, sizeof whole->light);
    return whole;
}

/* The float arguments of a ray case. */
static void ray_args(const ray_case *rc, double *d, double *light,
                     double c[][3], double *r)
{
    scene whole;
    const scene *s = scene_of(rc->scene, &whole);
    size_t i;
    unit(rc->d, d);
    vfl(d, d);
    unit(s->light, light);
    vfl(light, light);
    for (i = 0; i < s->n; i++) {
        vfl(s->c[i], c[i]);
        r[i] = fl(s->r[i]);
    }
}

/* The mistakes of computar_intensidad that are modelled. */
enum {
    M_NONE,
    M_FIRST_SPHERE,
    M_LAST_SPHERE,
    M_FAR_ROOT,
    M_NO_SHADOWS,
    M_BEHIND_SHADOWS,
    M_NO_LN_TEST,
    M_LIGHT_REVERSED,
    M_NO_AMBIENT,
    M_NO_CLAMP,
    M_WRAPPED,
    M_UNNORMALISED_NORMAL,
    M_SELF_SHADOW,
    M_COUNT
};

/* What the model found, for the messages. */
typedef struct shading {
    double value;
    size_t sphere;   /* the sphere shaded, or (size_t)-1 */
    size_t occluder; /* the sphere that cast the shadow, or (size_t)-1 */
    double ln;
} shading;

static int occludes(const double *c, double r, const double *p,
                    const double *l, int behind_too)
{
    double oc[3], beta, delta;
    oc[0] = c[0] - p[0];
    oc[1] = c[1] - p[1];
    oc[2] = c[2] - p[2];
    beta = dot(oc, l);
    delta = beta * beta - dot(oc, oc) + r * r;
    if (delta < 0)
        return 0;
    return behind_too || beta + sqrt(delta) > 0;
}

static shading shade(const ray_case *rc, int m)
{
    scene whole;
    const scene *s = scene_of(rc->scene, &whole);
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    double o[3] = {0, 0, 0}, best = INFINITY, p[3], n[3], amb, value;
    shading out = {0, (size_t)-1, (size_t)-1, 0};
    size_t i;
    ray_args(rc, d, light, c, r);
    for (i = 0; i < s->n; i++) {
        double t = sphere_t(c[i], r[i], o, d, m == M_FAR_ROOT);
        if (t == INFINITY)
            continue;
        if (m == M_FIRST_SPHERE ? out.sphere == (size_t)-1
                                : m == M_LAST_SPHERE || t < best) {
            best = t;
            out.sphere = i;
        }
    }
    if (out.sphere == (size_t)-1)
        return out;
    i = out.sphere;
    p[0] = best * d[0];
    p[1] = best * d[1];
    p[2] = best * d[2];
    n[0] = (p[0] - c[i][0]) / (m == M_UNNORMALISED_NORMAL ? 1 : r[i]);
    n[1] = (p[1] - c[i][1]) / (m == M_UNNORMALISED_NORMAL ? 1 : r[i]);
    n[2] = (p[2] - c[i][2]) / (m == M_UNNORMALISED_NORMAL ? 1 : r[i]);
    if (m == M_LIGHT_REVERSED) {
        light[0] = -light[0];
        light[1] = -light[1];
        light[2] = -light[2];
    }
    out.ln = dot(light, n);
    amb = m == M_NO_AMBIENT ? 0 : IA;
    out.value = amb;
    if (out.ln <= 0 && m != M_NO_LN_TEST)
        return out;
    if (m == M_SELF_SHADOW)
        return out;
    for (i = 0; i < s->n && m != M_NO_SHADOWS; i++)
        if (i != out.sphere &&
            occludes(c[i], r[i], p, light, m == M_BEHIND_SHADOWS)) {
            out.occluder = i;
            return out;
        }
    value = trunc(amb + II * out.ln);
    if (m == M_WRAPPED)
        value = fmod(value, 256);
    else if (m != M_NO_CLAMP && value > 255)
        value = 255;
    out.value = value;
    return out;
}

/* ---- the harness's records ---- */

static void put_numbers(harness_text *t, const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        harness_append(t, " %.9g", v[i]);
}

/* "c NAME K" and a, b, c and s (harness/ej2.c). */
static void write_vector_case(harness_text *t, const vector_case *v,
                              unsigned k)
{
    double a[3], b[3], c[3], s;
    case_args(v, a, b, c, &s);
    harness_append(t, "c %s %u", functions[v->function].name, k);
    put_numbers(t, a, 3);
    put_numbers(t, b, 3);
    put_numbers(t, c, 3);
    put_numbers(t, &s, 1);
    harness_append(t, "\n");
}

/* "c computar_intensidad K", n, the centres, the radii, luz, o, d. */
static void write_ray_case(harness_text *t, const ray_case *rc, unsigned k)
{
    scene whole;
    const scene *s = scene_of(rc->scene, &whole);
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    static const double o[3] = {0, 0, 0};
    size_t i;
    ray_args(rc, d, light, c, r);
    harness_append(t, "c computar_intensidad %u %zu", k, s->n);
    for (i = 0; i < s->n; i++)
        put_numbers(t, c[i], 3);
    put_numbers(t, r, s->n);
    put_numbers(t, light, 3);
    put_numbers(t, o, 3);
    put_numbers(t, d, 3);
    harness_append(t, "\n");
}

static void write_calls(harness_text *t, const int *usable)
{
    unsigned i, k;
    for (i = 0; i < F_COUNT; i++)
        if (usable[i])
            harness_append(t, "m %s\n", functions[i].name);
    for (k = 0; k < VECTOR_CASES; k++)
        if (usable[vector_cases[k].function])
            write_vector_case(t, &vector_cases[k], k);
    for (k = 0; k < RAY_CASES && usable[F_INTENSIDAD]; k++)
        write_ray_case(t, &ray_cases[k], k);
}

/* ---- what the student reads ---- */

static void describe_vector_case(unsigned k, char *out, size_t room)
{
    const vector_case *v = &vector_cases[k];
    const char *name = functions[v->function].name;
    double a[3], b[3], c[3], s;
    char x[64], y[64], z[64];
    case_args(v, a, b, c, &s);
    switch (v->function) {
    case F_PRODUCTO:
        snprintf(out, room, "%s(%s, %s)", name, vec_text(a, x, sizeof x),
                 vec_text(b, y, sizeof y));
        break;
    case F_NORMA:
    case F_NORMALIZAR:
        snprintf(out, room, "%s(%s)", name, vec_text(a, x, sizeof x));
        break;
    case F_RESTA:
        snprintf(out, room, "resta(r, %s, %s)", vec_text(a, x, sizeof x),
                 vec_text(b, y, sizeof y));
        break;
    case F_INTERPOLAR:
        snprintf(out, room, "interpolar_recta(p, %s, %s, %.7g)",
                 vec_text(a, x, sizeof x), vec_text(b, y, sizeof y), s);
        break;
    case F_DISTANCIA:
        snprintf(out, room, "distancia_esfera(%s, %.7g, %s, %s)",
                 vec_text(a, x, sizeof x), s, vec_text(b, y, sizeof y),
                 vec_text(c, z, sizeof z));
        break;
    default:
        snprintf(out, room, "normal_esfera(n, %s, %.7g, %s)",
                 vec_text(a, x, sizeof x), s, vec_text(b, y, sizeof y));
        break;
    }
}

static void describe_ray_case(unsigned k, char *out, size_t room)
{
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    char x[64], y[64];
    ray_args(&ray_cases[k], d, light, c, r);
    snprintf(out, room, "computar_intensidad on %s, luz = %s, along d = %s",
             scenes[ray_cases[k].scene].what, vec_text(light, x, sizeof x),
             vec_text(d, y, sizeof y));
}

static void describe(const char *name, unsigned k, char *out, size_t room)
{
    if (strcmp(name, "computar_intensidad") == 0) {
        if (k < RAY_CASES)
            describe_ray_case(k, out, room);
        return;
    }
    if (k < VECTOR_CASES &&
        strcmp(name, functions[vector_cases[k].function].name) == 0)
        describe_vector_case(k, out, room);
}

/* The expected value (scalar functions) or vector, and the answer of
   two mistakes to recognise: *alt a vector, *alt_value a number. */
static void expect_vector_case(const vector_case *v, double *want,
                               double *want_v)
{
    double a[3], b[3], c[3], s, n;
    size_t i;
    case_args(v, a, b, c, &s);
    *want = 0;
    want_v[0] = want_v[1] = want_v[2] = 0;
    switch (v->function) {
    case F_PRODUCTO:
        *want = dot(a, b);
        break;
    case F_NORMA:
        *want = sqrt(dot(a, a));
        break;
    case F_NORMALIZAR:
        unit(a, want_v);
        break;
    case F_RESTA:
        for (i = 0; i < 3; i++)
            want_v[i] = a[i] - b[i];
        break;
    case F_INTERPOLAR:
        for (i = 0; i < 3; i++)
            want_v[i] = a[i] + s * b[i];
        break;
    case F_DISTANCIA:
        *want = sphere_t(a, s, b, c, 0);
        break;
    default:
        n = s;
        for (i = 0; i < 3; i++)
            want_v[i] = (b[i] - a[i]) / n;
        break;
    }
}

/* One wrong vector case: the reason line. */
static rayo_status say_vector(rayo_grade_item *item, const vector_case *v,
                              const char *call, double got,
                              const double *got_v, rayo_error *err)
{
    double a[3], b[3], c[3], s, want, want_v[3], alt[3], far;
    char g[64], w[64];
    size_t i;
    case_args(v, a, b, c, &s);
    expect_vector_case(v, &want, want_v);
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA:
        if (got == floor(want) && want != floor(want))
            return grade_fail(item, err, "%s returned %g; expected %.7g: "
                                         "the decimals are lost, is an int "
                                         "used inside the function?",
                              call, got, want);
        if (v->function == F_NORMA && near_value(got, want * want))
            return grade_fail(item, err, "%s returned %.7g, the square of "
                                         "the norm; expected %.7g: is the "
                                         "square root missing?",
                              call, got, want);
        return grade_fail(item, err, "%s returned %.7g; expected %.7g", call,
                          got, want);
    case F_DISTANCIA:
        far = sphere_t(a, s, b, c, 1);
        if (want == INFINITY && is_infinito(got))
            return RAYO_OK;
        if (want == INFINITY)
            return grade_fail(item, err, "%s returned %.7g for a ray that "
                                         "%s; expected INFINITO (FLT_MAX)",
                              call, got, v->miss);
        if (is_infinito(got))
            return grade_fail(item, err, "%s returned INFINITO for a ray "
                                         "that meets the sphere at t = %.7g",
                              call, want);
        if (far != want && near_value(got, far))
            return grade_fail(item, err, "%s returned the far root %.7g "
                                         "for a ray that meets the sphere at "
                                         "t = %.7g first: beta - sqrt(delta) "
                                         "when it is > 0",
                              call, got, want);
        if (got < 0)
            return grade_fail(item, err, "%s returned %.7g, a root behind "
                                         "the origin (t < 0), for a ray that "
                                         "starts inside the sphere; expected "
                                         "%.7g: when beta - sqrt(delta) <= 0 "
                                         "the answer is beta + sqrt(delta)",
                              call, got, want);
        return grade_fail(item, err, "%s returned %.7g; expected %.7g%s",
                          call, got, want,
                          dot(b, b) > 0 ? " (the ray starts at o, not at "
                                          "the origin of coordinates)"
                                        : "");
    default:
        break;
    }
    vec_text(got_v, g, sizeof g);
    vec_text(want_v, w, sizeof w);
    for (i = 0; i < 3; i++)
        alt[i] = b[i] - a[i];
    if (v->function == F_RESTA && near_vector(got_v, alt))
        return grade_fail(item, err, "%s gave %s, which is b - a; expected "
                                     "%s: r = a - b",
                          call, g, w);
    if (v->function == F_NORMALIZAR && near_vector(got_v, a))
        return grade_fail(item, err, "%s left a unchanged %s; expected %s: "
                                     "normalizar divides the array it is "
                                     "given by its norm",
                          call, g, w);
    if (v->function == F_NORMAL) {
        double length = sqrt(dot(got_v, got_v));
        for (i = 0; i < 3; i++)
            alt[i] = want_v[i] * s;
        if (near_vector(got_v, alt))
            return grade_fail(item, err, "%s gave %s, of length %.7g; "
                                         "expected the unit normal %s: "
                                         "N = (P - C) / r",
                              call, g, length, w);
        for (i = 0; i < 3; i++)
            alt[i] = -want_v[i];
        if (near_vector(got_v, alt))
            return grade_fail(item, err, "%s gave %s, pointing into the "
                                         "sphere; expected %s: "
                                         "N = (P - C) / r",
                              call, g, w);
    }
    return grade_fail(item, err, "%s gave %s; expected %s", call, g, w);
}

static int vector_case_right(const vector_case *v, const double *got)
{
    double want, want_v[3];
    expect_vector_case(v, &want, want_v);
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA:
        return near_value(got[0], want);
    case F_DISTANCIA:
        return want == INFINITY ? is_infinito(got[0])
                                : near_value(got[0], want);
    default:
        return near_vector(got + 1, want_v);
    }
}

static const char *sphere_text(const ray_case *rc, size_t i, char *out,
                               size_t room)
{
    scene whole;
    const scene *s = scene_of(rc->scene, &whole);
    snprintf(out, room, "the sphere at (%g, %g, %g)", s->c[i][0],
             s->c[i][1], s->c[i][2]);
    return out;
}

/* One wrong computar_intensidad: the mistake that agrees, named. */
/* How well each modelled mistake agrees with the results: 2 for each
   case within 1, 3 when exact. */
static void mistake_scores(const double *got, unsigned *score)
{
    unsigned c;
    int k;
    for (k = 0; k < M_COUNT; k++)
        score[k] = 0;
    for (c = 0; c < RAY_CASES; c++)
        for (k = M_NONE + 1; k < M_COUNT; k++) {
            double m = shade(&ray_cases[c], k).value;
            if (fabs(got[c] - m) <= 1)
                score[k] += 2 + (fabs(got[c] - m) < 0.5);
        }
}

/* The mistake that gives got for this case (and not the right value)
   and agrees best with the results overall; M_COUNT when none does. */
static int ray_mistake(const ray_case *rc, double got,
                       const unsigned *score)
{
    double want = shade(rc, M_NONE).value;
    int k, best = M_COUNT;
    for (k = M_NONE + 1; k < M_COUNT; k++) {
        double m = shade(rc, k).value;
        if (fabs(m - want) > 1 && fabs(got - m) <= 1 &&
            (best == M_COUNT || score[k] > score[best]))
            best = k;
    }
    return best;
}

static rayo_status say_ray(rayo_grade_item *item, const ray_case *rc,
                           const char *call, double got, int k,
                           rayo_error *err)
{
    shading want = shade(rc, M_NONE), m;
    char x[96], y[96];
    if (k < M_COUNT) {
        m = shade(rc, k);
        switch (k) {
        case M_FIRST_SPHERE:
        case M_LAST_SPHERE:
            return grade_fail(item, err, "%s returned %g, the intensity of "
                                         "%s, the %s sphere in the array the "
                                         "ray hits, not the nearest (%s, "
                                         "%g): keep the smallest t",
                              call, got,
                              sphere_text(rc, m.sphere, x, sizeof x),
                              k == M_FIRST_SPHERE ? "first" : "last",
                              sphere_text(rc, want.sphere, y, sizeof y),
                              want.value);
        case M_FAR_ROOT:
            return grade_fail(item, err, "%s returned %g, the intensity at "
                                         "the far side of %s; expected %g: "
                                         "the ray meets it first at t = "
                                         "beta - sqrt(delta)",
                              call, got,
                              sphere_text(rc, want.sphere, x, sizeof x),
                              want.value);
        case M_NO_SHADOWS:
            return grade_fail(item, err, "%s returned %g; expected %g: %s "
                                         "lies between the point and the "
                                         "light, so only the ambient IA "
                                         "counts",
                              call, got, want.value,
                              sphere_text(rc, want.occluder, x, sizeof x));
        case M_BEHIND_SHADOWS:
            return grade_fail(item, err, "%s returned %g; expected %g: %s "
                                         "is on the other side of the point, "
                                         "away from the light, and casts no "
                                         "shadow: only a sphere hit at t > 0 "
                                         "from P towards L does",
                              call, got, want.value,
                              sphere_text(rc, m.occluder, x, sizeof x));
        case M_NO_LN_TEST:
            return grade_fail(item, err, "%s returned %g; expected %g: here "
                                         "L.N = %.3g < 0, the point faces "
                                         "away from the light and gets only "
                                         "the ambient IA",
                              call, got, want.value, want.ln);
        case M_LIGHT_REVERSED:
            return grade_fail(item, err, "%s returned %g; expected %g: as "
                                         "if the light came from -luz; luz "
                                         "is the direction towards the "
                                         "light (L.N = %.3g here)",
                              call, got, want.value, want.ln);
        case M_NO_AMBIENT:
            return grade_fail(item, err, "%s returned %g; expected %g: the "
                                         "ambient IA = 5 is missing "
                                         "(I = IA + II (L.N))",
                              call, got, want.value);
        case M_WRAPPED:
            return grade_fail(item, err, "%s returned %g, which is %g "
                                         "wrapped around 256; expected 255: "
                                         "values above 255 return 255",
                              call, got, shade(rc, M_NO_CLAMP).value);
        case M_NO_CLAMP:
            return grade_fail(item, err, "%s returned %g; expected 255: "
                                         "IA + II (L.N) = %g here, and "
                                         "values above 255 return 255",
                              call, got, shade(rc, M_NO_CLAMP).value);
        case M_UNNORMALISED_NORMAL:
            return grade_fail(item, err, "%s returned %g; expected %g: as "
                                         "if the normal were P - C, not "
                                         "divided by the radius",
                              call, got, want.value);
        default:
            return grade_fail(item, err, "%s returned %g; expected %g: a "
                                         "shadow where no other sphere "
                                         "blocks the light; does the shadow "
                                         "test skip the sphere the point is "
                                         "on?",
                              call, got, want.value);
        }
    }
    return grade_fail(item, err, "%s returned %g; expected %g", call, got,
                      want.value);
}

/* ---- judging ---- */

/* What most likely makes function i return a NaN. */
static const char *nan_cause(unsigned i)
{
    switch (i) {
    case F_NORMA:
        return "the square root of a negative sum (a sum of squares is "
               "never negative: check the signs) or 0/0";
    case F_NORMALIZAR:
    case F_NORMAL:
        return HARNESS_NAN_NORMAL;
    case F_DISTANCIA:
        return HARNESS_NAN_DISCRIMINANT;
    default:
        return HARNESS_NAN_ARITHMETIC;
    }
}

/* Judges function i: 0 when the log ends before its calls are done. */
static rayo_status judge(grade_context *ctx, unsigned i, const char *log,
                         const int *usable, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char call[512], line[1024];
    unsigned k, cases = 0, wrong = 0, unsaid = 0, said = 0;
    rayo_status status = RAYO_OK;
    (void)usable;
    if (harness_missing(log, functions[i].name))
        return grade_fail(item, err, "%s: not defined; the statement asks "
                                     "for %s",
                          functions[i].name, functions[i].prototype);
    for (k = 0; k < VECTOR_CASES && i != F_INTENSIDAD; k++) {
        double got[4];
        if (vector_cases[k].function != i)
            continue;
        if (harness_result(log, functions[i].name, k, got, 4) != 4)
            return RAYO_OK; /* it ended inside or before: said elsewhere */
        cases++;
        if (vector_case_right(&vector_cases[k], got))
            continue;
        if (wrong++ >= SAID_PER_FUNCTION) {
            unsaid++;
            continue;
        }
        describe_vector_case(k, call, sizeof call);
        if (harness_not_finite(call, i == F_PRODUCTO || i == F_NORMA ||
                                             i == F_DISTANCIA
                                         ? got
                                         : got + 1,
                               i == F_PRODUCTO || i == F_NORMA ||
                                       i == F_DISTANCIA
                                   ? 1
                                   : 3,
                               nan_cause(i),
                               i == F_DISTANCIA
                                   ? "the statement's INFINITO is FLT_MAX, the "
                                     "largest "
                                     "float, not an infinity"
                                   : NULL,
                               line, sizeof line))
            status = grade_fail(item, err, "%s", line);
        else
            status = say_vector(item, &vector_cases[k], call, got[0],
                                got + 1, err);
        if (status != RAYO_OK)
            return status;
    }
    if (i == F_INTENSIDAD) {
        double got[RAY_CASES];
        unsigned score[M_COUNT];
        int mistake;
        for (k = 0; k < RAY_CASES; k++)
            if (harness_result(log, functions[i].name, k, &got[k], 1) != 1)
                return RAYO_OK; /* it ended inside or before */
        mistake_scores(got, score);
        for (k = 0; k < RAY_CASES; k++) {
            const ray_case *rc = &ray_cases[k];
            cases++;
            if (fabs(got[k] - shade(rc, M_NONE).value) <= 1)
                continue;
            wrong++;
            /* One line per mistake recognised; the same one again
               counted. */
            mistake = got[k] == HARNESS_INT_MIN ? M_COUNT + 1
                                                : ray_mistake(rc, got[k],
                                                              score);
            if (said & (1u << mistake) || wrong > SAID_PER_FUNCTION + 2) {
                unsaid++;
                continue;
            }
            said |= 1u << mistake;
            describe_ray_case(k, call, sizeof call);
            if (mistake == M_COUNT + 1)
                status = grade_fail(item, err, "%s returned -2147483648, "
                                               "what a NaN (not a number) "
                                               "or a value past the int "
                                               "range becomes through "
                                               "(int): likely %s",
                                    call, HARNESS_NAN_SHADING);
            else
                status = say_ray(item, rc, call, got[k], mistake, err);
            if (status != RAYO_OK)
                return status;
        }
    }
    if (wrong == 0)
        status = grade_say(item, err, "%s: right on %u known inputs",
                           functions[i].name, cases);
    else if (unsaid > 0)
        status = grade_fail(item, err, "%s: wrong on %u more of its %u "
                                       "known inputs",
                            functions[i].name, unsaid, cases);
    return status;
}

static const char *const probe_before = "#include <stddef.h>\n";

const functions_exercise functions_ej2 = {
    functions, F_COUNT, harness_ej2_c, &harness_ej2_c_size, NULL, 0,
    probe_before, 0, NULL, write_calls, judge, describe, NULL, 0};
