/*
 * ej3.c - the functions table of Ejercicio obligatorio 3 (colour,
 * structs, dynamic memory): the statement's five types and fifteen
 * functions, their cases (values, constructors and destructors,
 * arreglo_agregar with allocation made to fail, computar_intensidad on
 * the course's scene 3 from the course module and on scenes made to
 * reveal one mistake each), the records its harness (harness/ej3.c) is
 * given, and their judging.  Types are probed first: a function is
 * called only when its signature and every type it uses are the
 * statement's.  Expected values are computed in double precision on
 * the float-rounded arguments; a wrong colour is compared with what
 * each modelled mistake gives, and the one that agrees is named.
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ej3.h"
#include "rayo/lang.h"
#include "harness_math.h"
#include "harness_sources.h"

/* Marks a message for xgettext where it is data; looked up where used. */
#define N_(text) text

/* ---- the statement's functions ---- */


const functions_function ej3_functions[F_COUNT] = {
    {"vector_producto_interno",
     "float vector_producto_interno(vector_t a, vector_t b)"},
    {"vector_norma",
     "float vector_norma(vector_t a)"},
    {"vector_resta",
     "vector_t vector_resta(vector_t a, vector_t b)"},
    {"vector_interpolar_recta",
     "vector_t vector_interpolar_recta(vector_t o, vector_t d, float t)"},
    {"vector_normalizar",
     "vector_t vector_normalizar(vector_t a)"},
    {"color_sumar",
     "color_t color_sumar(color_t c, color_t m, float p)"},
    {"color_absorber",
     "color_t color_absorber(color_t b, color_t c)"},
    {"color_imprimir",
     "void color_imprimir(color_t c)"},
    {"esfera_crear",
     "esfera_t *esfera_crear(vector_t centro, float radio, color_t color, "
     "float ka, float kd)"},
    {"esfera_destruir",
     "void esfera_destruir(esfera_t *esfera)"},
    {"luz_crear",
     "luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)"},
    {"luz_destruir",
     "void luz_destruir(luz_t *luz)"},
    {"esfera_distancia",
     "float esfera_distancia(const esfera_t *esfera, vector_t o, "
     "vector_t d, vector_t *punto, vector_t *normal)"},
    {"arreglo_agregar",
     "bool arreglo_agregar(arreglo_t *a, void *e)"},
    {"computar_intensidad",
     "color_t computar_intensidad(const arreglo_t *esferas, "
     "const arreglo_t *luces, color_t ambiente, vector_t o, vector_t d)"},
};

/* The types each function uses: TB() of each. */
const unsigned ej3_function_types[F_COUNT] = {
    TB(T_VECTOR), /* vector_producto_interno */
    TB(T_VECTOR), /* vector_norma */
    TB(T_VECTOR), /* vector_resta */
    TB(T_VECTOR), /* vector_interpolar_recta */
    TB(T_VECTOR), /* vector_normalizar */
    TB(T_COLOR), /* color_sumar */
    TB(T_COLOR), /* color_absorber */
    TB(T_COLOR), /* color_imprimir */
    TB(T_VECTOR) | TB(T_COLOR) | TB(T_ESFERA), /* esfera_crear */
    TB(T_ESFERA), /* esfera_destruir */
    TB(T_VECTOR) | TB(T_COLOR) | TB(T_LUZ), /* luz_crear */
    TB(T_LUZ), /* luz_destruir */
    TB(T_VECTOR) | TB(T_ESFERA), /* esfera_distancia */
    TB(T_ARREGLO), /* arreglo_agregar */
    TB(T_VECTOR) | TB(T_COLOR) | TB(T_ARREGLO), /* computar_intensidad */
};

/* ---- vector and colour cases ---- */


const value_case ej3_value_cases[] = {
    {F_PRODUCTO, {1, 2, 3}, {4, 5, 6}, {0, 0, 0}, 0},
    {F_PRODUCTO, {0.5, -1.5, 2}, {3, 0.25, -4}, {0, 0, 0}, 0},
    {F_NORMA, {3, 4, 12}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_NORMA, {-0.6, 0, -0.8}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_RESTA, {1, 2, 3}, {4, 6, 8}, {0, 0, 0}, 0},
    {F_RESTA, {0.5, -1, 2}, {-0.25, 0.5, 0.75}, {0, 0, 0}, 0},
    {F_INTERPOLAR, {1, 2, 3}, {0.5, -1, 2}, {0, 0, 0}, 2},
    {F_INTERPOLAR, {0, 0, 0}, {0.6, 0, 0.8}, {0, 0, 0}, 1.5},
    {F_NORMALIZAR, {3, 4, 12}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_NORMALIZAR, {0, -2, 0}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_SUMAR, {0.1, 0.2, 0.3}, {0.5, 0.25, 1}, {0, 0, 0}, 0.5},
    {F_SUMAR, {0, 0, 0}, {0.05, 0.05, 0.05}, {0, 0, 0}, 0.8},
    {F_ABSORBER, {0.5, 0.8, 1}, {1, 0.5, 0.25}, {0, 0, 0}, 0},
    /* color_imprimir: above 1, just below 1, and the truncation of
       255 c (0.5 -> 127, 0.25 -> 63, 0.1 -> 25). */
    {F_IMPRIMIR, {1.5, 2, 1.0001}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_IMPRIMIR, {0.999, 0.5, 0}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_IMPRIMIR, {0.9999, 0.25, 0.1}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_IMPRIMIR, {1, 0.75, 0.001}, {0, 0, 0}, {0, 0, 0}, 0},
    {F_ESFERA_CREAR, {0.5, -0.6, 3}, {1, 0.5, 0.25}, {0.3, 0.8, 0}, 0.3},
    {F_LUZ_CREAR, {-2, 10, 2.5}, {0.9, 0, 0.1}, {0, 0, 0}, 1},
    {F_LUZ_CREAR, {0, 1, 0}, {0.2, 0.3, 0.4}, {0, 0, 0}, 0},
    /* esfera_distancia: centre a, radius s, origin b, direction c */
    {F_DISTANCIA, {0, 0, 2}, {0, 0, 0}, {0, 0, 1}, 0.8},
    {F_DISTANCIA, {0.5, 0.75, 1.9}, {0, 0, 0}, {0.1, 0.2, 1}, 0.8},
    {F_DISTANCIA, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}, 2},
    {F_DISTANCIA, {1, 1, 5}, {1, 1, 0}, {0, 0, 1}, 1},
    {F_DISTANCIA, {0, 0, 3}, {0, 0, 0}, {1, 0, 0}, 1},
    {F_DISTANCIA, {0, 0, -3}, {0, 0, 0}, {0, 0, 1}, 1},
};
const size_t ej3_value_case_count =
    sizeof ej3_value_cases / sizeof ej3_value_cases[0];

/* ---- computar_intensidad's scenes ---- */




#define WHITE {1, 1, 1}

/* Scene 0 (COURSE_SCENE) is the course's scene 3, filled from the
   course module (course_scenes.c, the one copy of its numbers) by
   ej3_scene_of. */

const scene ej3_scenes[] = {
    {N_("the course's scene 3"), 0, 0, {{{0, 0, 0}, 0, {0, 0, 0}, 0, 0}},
     {{{0, 0, 0}, {0, 0, 0}, 0}}, {0, 0, 0}},
    {N_("a red sphere (0, 0, 3) r 1 first in the array, a white one "
     "(0, 0, 1) r 0.2 second, a directional light towards the camera"),
     2,
     1,
     {{{0, 0, 3}, 1, {1, 0, 0}, 1, 1}, {{0, 0, 1}, 0.2, WHITE, 1, 1}},
     {{{0, 0, -1}, {0.5, 0.5, 0.5}, 0}},
     {0.1, 0.1, 0.1}},
    {N_("a white sphere (0, 0, 1) r 0.2 first in the array, a red one "
     "(0, 0, 3) r 1 second, a directional light towards the camera"),
     2,
     1,
     {{{0, 0, 1}, 0.2, WHITE, 1, 1}, {{0, 0, 3}, 1, {1, 0, 0}, 1, 1}},
     {{{0, 0, -1}, {0.5, 0.5, 0.5}, 0}},
     {0.1, 0.1, 0.1}},
    {N_("a sphere (0, 0, 3) r 1, a point light at (0, 0, 1) and a sphere "
     "(0, 0, -2) r 0.5 beyond the light"),
     2,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}, {{0, 0, -2}, 0.5, WHITE, 1, 1}},
     {{{0, 0, 1}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
    {N_("a sphere (0, 0, 3) r 1, a point light at (0, 3, 2) and a sphere "
     "(0, 1.87, 2.13) r 0.3 between them"),
     2,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}, {{0, 1.87, 2.13}, 0.3, WHITE, 1, 1}},
     {{{0, 3, 2}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
    {N_("a sphere (0, 0, 3) r 1 of colour (1, 0.5, 0.25), ka 0.5, kd 0.8, a "
     "light straight up and a point light below at (0, -5, 2)"),
     1,
     2,
     {{{0, 0, 3}, 1, {1, 0.5, 0.25}, 0.5, 0.8}},
     {{{0, 1, 0}, {0.4, 0.4, 0.4}, 0}, {{0, -5, 2}, {0.6, 0.3, 0}, 1}},
     {0.1, 0.2, 0.3}},
    {N_("a sphere (0, 0, 3) r 1 and a point light at (0, 4, 0)"),
     1,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}},
     {{{0, 4, 0}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
};


const ray_case ej3_ray_cases[] = {
    {0, {0, -20, 320}},  {0, {-213, -64, 320}}, {0, {-40, -130, 320}},
    {0, {0, 60, 320}},   {0, {-160, -80, 320}}, {0, {250, 200, 320}},
    {1, {0, 0, 1}},      {2, {0, 0, 1}},        {3, {0, 0, 1}},
    {4, {0, 0.3, 1}},    {5, {0, 0.3, 1}},      {6, {0, 0, 1}},
};
const size_t ej3_ray_case_count =
    sizeof ej3_ray_cases / sizeof ej3_ray_cases[0];

/* ---- the harness's records ---- */

/* "c NAME K" and a, b, c and s (harness/ej3.c). */
static void write_value_case(harness_text *t, const value_case *v,
                             unsigned k)
{
    double a[3], b[3], c[3], s;
    ej3_value_args(v, a, b, c, &s);
    harness_vector_record(t, ej3_functions[v->function].name, k, a, b, c, s);
}

/* "c computar_intensidad K", the counts, each sphere, each light, the
   ambient colour, o and d. */
static void write_ray_case(harness_text *t, const ray_case *rc, unsigned k)
{
    static const double o[3] = {0, 0, 0};
    scene s;
    double d[3], point;
    size_t i;
    ej3_ray_scene(rc, &s, d);
    harness_append(t, "c computar_intensidad %u %zu %zu", k, s.spheres,
                   s.lights);
    for (i = 0; i < s.spheres; i++) {
        harness_numbers(t, s.s[i].c, 3);
        harness_numbers(t, &s.s[i].r, 1);
        harness_numbers(t, s.s[i].color, 3);
        harness_numbers(t, &s.s[i].ka, 1);
        harness_numbers(t, &s.s[i].kd, 1);
    }
    for (i = 0; i < s.lights; i++) {
        point = s.l[i].point;
        harness_numbers(t, s.l[i].v, 3);
        harness_numbers(t, s.l[i].color, 3);
        harness_numbers(t, &point, 1);
    }
    harness_numbers(t, s.ambient, 3);
    harness_numbers(t, o, 3);
    harness_numbers(t, d, 3);
    harness_append(t, "\n");
}

/* The value cases, then the rays, then arreglo_agregar, last (its
   harness code may end early). */
static void write_calls(harness_text *t, const int *usable)
{
    unsigned k;
    for (k = 0; k < ej3_value_case_count; k++)
        if (usable[ej3_value_cases[k].function])
            write_value_case(t, &ej3_value_cases[k], k);
    for (k = 0; k < ej3_ray_case_count && usable[F_INTENSIDAD]; k++)
        write_ray_case(t, &ej3_ray_cases[k], k);
    if (usable[F_AGREGAR])
        harness_append(t, "c arreglo_agregar 0\n");
}

/* ---- what the student reads ---- */

void ej3_describe_value_case(unsigned k, rayo_lang lang, char *out,
                             size_t room)
{
    const value_case *v = &ej3_value_cases[k];
    const char *name = ej3_functions[v->function].name;
    double a[3], b[3], c[3], s;
    char x[64], y[64], z[64];
    ej3_value_args(v, a, b, c, &s);
    vec_text(a, x, sizeof x);
    vec_text(b, y, sizeof y);
    vec_text(c, z, sizeof z);
    switch (v->function) {
    case F_NORMA:
    case F_NORMALIZAR:
    case F_IMPRIMIR:
        snprintf(out, room, "%s(%s)", name, x);
        break;
    case F_INTERPOLAR:
    case F_SUMAR:
        snprintf(out, room, "%s(%s, %s, %.7g)", name, x, y, s);
        break;
    case F_ESFERA_CREAR:
        snprintf(out, room, "esfera_crear(%s, %.7g, %s, %.7g, %.7g)", x, s,
                 y, c[0], c[1]);
        break;
    case F_LUZ_CREAR:
        snprintf(out, room, "luz_crear(%s, %s, %s)", x, y,
                 s != 0 ? "true" : "false");
        break;
    case F_DISTANCIA:
        snprintf(out, room,
                 rayo_gettext(lang, "esfera_distancia(a sphere at %s r %.7g, "
                                    "%s, %s, &punto, &normal)"),
                 x, s, y, z);
        break;
    default:
        snprintf(out, room, "%s(%s, %s)", name, x, y);
        break;
    }
}

void ej3_describe_ray_case(unsigned k, rayo_lang lang, char *out,
                           size_t room)
{
    scene s;
    double d[3];
    char x[64];
    ej3_ray_scene(&ej3_ray_cases[k], &s, d);
    snprintf(out, room,
             rayo_gettext(lang, "computar_intensidad on %s, along d = %s"),
             rayo_gettext(lang, ej3_scenes[ej3_ray_cases[k].scene].what),
             vec_text(d, x, sizeof x));
}

static void describe(const char *name, unsigned k, rayo_lang lang,
                     char *out, size_t room)
{
    if (strcmp(name, "computar_intensidad") == 0) {
        if (k < ej3_ray_case_count)
            ej3_describe_ray_case(k, lang, out, room);
    } else if (strcmp(name, "arreglo_agregar") == 0) {
        snprintf(out, room, k == 0 ? "arreglo_agregar on an empty array "
                                     "{NULL, 0}, three times"
                                   : "arreglo_agregar with malloc and "
                                     "realloc made to fail, on an array "
                                     "of 3");
    } else if (strcmp(name, "esfera_destruir") == 0 ||
               strcmp(name, "luz_destruir") == 0) {
        snprintf(out, room, "%s on what %s returned", name,
                 name[0] == 'e' ? "esfera_crear" : "luz_crear");
    } else if (k < ej3_value_case_count &&
               strcmp(name,
                      ej3_functions[ej3_value_cases[k].function].name) == 0) {
        ej3_describe_value_case(k, lang, out, room);
    }
}

/* The link words, shared with the Makefile's HARNESS_LINK_ej3. */
static const char *const wrap_words[] = {
#include "ej3_link.def"
};

/* What valgrind's frames in these functions mean. */
static const functions_owner owners[] = {
    {"esfera_crear", 0, "spheres made by esfera_crear are never destroyed: "
                        "call esfera_destruir on each before freeing the "
                        "array"},
    {"luz_crear", 0, "lights made by luz_crear are never destroyed: call "
                     "luz_destruir on each before freeing the array"},
    {"arreglo_agregar", 0, "the arrays' v is never freed: free each array's "
                           "v after destroying its elements"},
    {"arreglo_agregar", 1, "a write past the end of v: grow it to n + 1 "
                           "elements before writing v[n]"}};

const functions_exercise functions_ej3 = {
    .functions = ej3_functions,
    .count = F_COUNT,
    .harness = harness_ej3_c,
    .harness_size = &harness_ej3_c_size,
    .link = wrap_words,
    .link_count = sizeof wrap_words / sizeof wrap_words[0],
    .probe = ej3_probe,
    .write_calls = write_calls,
    .judge = ej3_judge,
    .describe = describe,
    .owners = owners,
    .owner_count = sizeof owners / sizeof owners[0]};
