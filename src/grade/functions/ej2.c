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

#include "rayo/course/course_scene.h"
#include "ej2.h"
#include "rayo/lang.h"
#include "harness_math.h"
#include "harness_sources.h"

/* Marks a message for xgettext where it is data; looked up where used. */
#define N_(text) text



const functions_function ej2_functions[F_COUNT] = {
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


const vector_case ej2_vector_cases[] = {
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
const size_t ej2_vector_case_count =
    sizeof ej2_vector_cases / sizeof ej2_vector_cases[0];



const scene ej2_scenes[] = {
    {N_("the course's scene 2"), 0, {{0, 0, 0}}, {0}, {0, 0, 0}},
    /* Reversed order: the far sphere first. */
    {N_("2 spheres, the far one first: (0, 0, 4) r 1, (0, -0.3, 2) r 0.5"),
     2,
     {{0, 0, 4}, {0, -0.3, 2}},
     {1, 0.5},
     {1, 1, -1}},
    /* The same two in the other order. */
    {N_("2 spheres, the near one first: (0, -0.3, 2) r 0.5, (0, 0, 4) r 1"),
     2,
     {{0, -0.3, 2}, {0, 0, 4}},
     {0.5, 1},
     {1, 1, -1}},
    /* A sphere between the point and the light. */
    {N_("a sphere (0, 0, 3) r 1 with a sphere (0, 2.5, 2) r 0.5 above it "
     "and the light straight up"),
     2,
     {{0, 0, 3}, {0, 2.5, 2}},
     {1, 0.5},
     {0, 1, 0}},
    /* A sphere on the other side of the point, away from the light. */
    {N_("a sphere (0, 0, 3) r 1 with a sphere (0, -2.5, 2) r 0.5 below it "
     "and the light straight up"),
     2,
     {{0, 0, 3}, {0, -2.5, 2}},
     {1, 0.5},
     {0, 1, 0}},
    /* The light behind the camera, straight at the point: L.N = 1. */
    {N_("a sphere (0, 0, 3) r 1 with the light towards the camera (0, 0, -1)"),
     1,
     {{0, 0, 3}},
     {1},
     {0, 0, -1}},
};


/* The course's rays are pixel directions (vx, vy, 320) well away from
   every outline and shadow edge. */
const ray_case ej2_ray_cases[] = {
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
const size_t ej2_ray_case_count =
    sizeof ej2_ray_cases / sizeof ej2_ray_cases[0];

/* ---- arithmetic in double, on float-rounded inputs (harness_math.h) ---- */

/* The float arguments of a vector case. */
void ej2_case_args(const vector_case *v, double *a, double *b, double *c,
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


/* Scene index as written (in double): the course's from its module.
   Returns whole. */
const scene *ej2_scene_of(unsigned index, scene *whole)
{
    const rayo_course_data *data = rayo_course_data_of(RAYO_COURSE_EJ2);
    size_t i;
    *whole = ej2_scenes[index];
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
void ej2_ray_args(const ray_case *rc, double *d, double *light,
                  double c[][3], double *r)
{
    scene whole;
    const scene *s = ej2_scene_of(rc->scene, &whole);
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


/* ---- the harness's records ---- */

/* "c NAME K" and a, b, c and s (harness/ej2.c). */
static void write_vector_case(harness_text *t, const vector_case *v,
                              unsigned k)
{
    double a[3], b[3], c[3], s;
    ej2_case_args(v, a, b, c, &s);
    harness_vector_record(t, ej2_functions[v->function].name, k, a, b, c, s);
}

/* "c computar_intensidad K", n, the centres, the radii, luz, o, d. */
static void write_ray_case(harness_text *t, const ray_case *rc, unsigned k)
{
    scene whole;
    const scene *s = ej2_scene_of(rc->scene, &whole);
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    static const double o[3] = {0, 0, 0};
    size_t i;
    ej2_ray_args(rc, d, light, c, r);
    harness_append(t, "c computar_intensidad %u %zu", k, s->n);
    for (i = 0; i < s->n; i++)
        harness_numbers(t, c[i], 3);
    harness_numbers(t, r, s->n);
    harness_numbers(t, light, 3);
    harness_numbers(t, o, 3);
    harness_numbers(t, d, 3);
    harness_append(t, "\n");
}

static void write_calls(harness_text *t, const int *usable)
{
    unsigned k;
    for (k = 0; k < ej2_vector_case_count; k++)
        if (usable[ej2_vector_cases[k].function])
            write_vector_case(t, &ej2_vector_cases[k], k);
    for (k = 0; k < ej2_ray_case_count && usable[F_INTENSIDAD]; k++)
        write_ray_case(t, &ej2_ray_cases[k], k);
}

/* ---- what the student reads ---- */

void ej2_describe_vector_case(unsigned k, char *out, size_t room)
{
    const vector_case *v = &ej2_vector_cases[k];
    const char *name = ej2_functions[v->function].name;
    double a[3], b[3], c[3], s;
    char x[64], y[64], z[64];
    ej2_case_args(v, a, b, c, &s);
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

void ej2_describe_ray_case(unsigned k, rayo_lang lang, char *out,
                           size_t room)
{
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    char x[64], y[64];
    ej2_ray_args(&ej2_ray_cases[k], d, light, c, r);
    snprintf(out, room,
             rayo_gettext(lang,
                          "computar_intensidad on %s, luz = %s, along d = %s"),
             rayo_gettext(lang, ej2_scenes[ej2_ray_cases[k].scene].what),
             vec_text(light, x, sizeof x), vec_text(d, y, sizeof y));
}

static void describe(const char *name, unsigned k, rayo_lang lang,
                     char *out, size_t room)
{
    if (strcmp(name, "computar_intensidad") == 0) {
        if (k < ej2_ray_case_count)
            ej2_describe_ray_case(k, lang, out, room);
        return;
    }
    if (k < ej2_vector_case_count &&
        strcmp(name, ej2_functions[ej2_vector_cases[k].function].name) == 0)
        ej2_describe_vector_case(k, out, room);
}

const functions_exercise functions_ej2 = {
    .functions = ej2_functions,
    .count = F_COUNT,
    .harness = harness_ej2_c,
    .harness_size = &harness_ej2_c_size,
    .probe_before = "#include <stddef.h>\n",
    .write_calls = write_calls,
    .judge = ej2_judge,
    .describe = describe};
