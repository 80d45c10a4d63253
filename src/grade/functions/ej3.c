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

#include "../../course/course_impl.h"
#include "harness.h"
#include "harness_sources.h"
#include "table.h"
#include "harness_math.h"

#define SAID_PER_FUNCTION 2 /* wrong cases quoted; the others counted */
#define MAX_SPHERES 25
#define MAX_LIGHTS 4

/* ---- the statement's types ---- */

enum { T_VECTOR, T_COLOR, T_ESFERA, T_LUZ, T_ARREGLO, T_COUNT };

static const char *const type_names[T_COUNT] = {
    "vector_t", "color_t", "esfera_t", "luz_t", "arreglo_t"};

static const char *const type_texts[T_COUNT] = {
    "typedef struct { float x, y, z; } vector_t;",
    "typedef struct { float r, g, b; } color_t;",
    "typedef struct { vector_t centro; float radio; color_t color; "
    "float ka, kd; } esfera_t;",
    "typedef struct { vector_t posicion; color_t color; bool es_puntual; } "
    "luz_t;",
    "typedef struct { void **v; size_t n; } arreglo_t;"};

/* Each type's members: name and type as _Generic spells it. */
typedef struct member {
    const char *name, *type;
} member;

static const member members[T_COUNT][5] = {
    {{"x", "float"}, {"y", "float"}, {"z", "float"}},
    {{"r", "float"}, {"g", "float"}, {"b", "float"}},
    {{"centro", "vector_t"},
     {"radio", "float"},
     {"color", "color_t"},
     {"ka", "float"},
     {"kd", "float"}},
    {{"posicion", "vector_t"}, {"color", "color_t"}, {"es_puntual", "_Bool"}},
    {{"v", "void **"}, {"n", "size_t"}}};

/* The harness's (and the probe's mirror) definitions. */
static const char mirror_types[] =
    "struct rayo_vector_t { float x, y, z; };\n"
    "struct rayo_color_t { float r, g, b; };\n"
    "struct rayo_esfera_t { struct rayo_vector_t centro; float radio;\n"
    "    struct rayo_color_t color; float ka, kd; };\n"
    "struct rayo_luz_t { struct rayo_vector_t posicion;\n"
    "    struct rayo_color_t color; _Bool es_puntual; };\n"
    "struct rayo_arreglo_t { void **v; size_t n; };\n";

/* ---- the statement's functions ---- */

enum {
    F_PRODUCTO,
    F_NORMA,
    F_RESTA,
    F_INTERPOLAR,
    F_NORMALIZAR,
    F_SUMAR,
    F_ABSORBER,
    F_IMPRIMIR,
    F_ESFERA_CREAR,
    F_ESFERA_DESTRUIR,
    F_LUZ_CREAR,
    F_LUZ_DESTRUIR,
    F_DISTANCIA,
    F_AGREGAR,
    F_INTENSIDAD,
    F_COUNT
};

#define TB(t) (1u << (t))

static const functions_function functions[F_COUNT] = {
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
static const unsigned function_types[F_COUNT] = {
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

/* The prototype with bool spelled _Bool (the student may not include
   <stdbool.h> before a declaration of ours). */
static void put_prototype(harness_text *t, unsigned f, const char *suffix)
{
    const char *p = functions[f].prototype, *b;
    while ((b = strstr(p, "bool ")) != NULL &&
           (b == p || b[-1] == ' ' || b[-1] == '(')) {
        harness_append(t, "%.*s_Bool ", (int)(b - p), p);
        p = b + 5;
    }
    harness_append(t, "%s%s;\n", p, suffix);
}

/* ---- vector and colour cases ---- */

/* a, b vectors or colours; s a scalar.  vector_producto_interno(a, b),
   vector_norma(a), vector_resta(a, b), vector_interpolar_recta(a, b, s),
   vector_normalizar(a), color_sumar(a, b, s), color_absorber(a, b),
   color_imprimir(a), esfera_crear(a, s, b, ka, kd) with ka, kd in c,
   luz_crear(a, b, s != 0), esfera_distancia(sphere a r s, o b, d c). */
typedef struct value_case {
    unsigned function;
    double a[3], b[3], c[3], s;
} value_case;

static const value_case value_cases[] = {
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
#define VALUE_CASES (sizeof value_cases / sizeof value_cases[0])

/* ---- computar_intensidad's scenes ---- */

typedef struct sphere {
    double c[3], r, color[3], ka, kd;
} sphere;

typedef struct light {
    double v[3], color[3];
    int point;
} light;

typedef struct scene {
    const char *what;
    size_t spheres, lights;
    sphere s[MAX_SPHERES];
    light l[MAX_LIGHTS];
    double ambient[3];
} scene;

#define WHITE {1, 1, 1}

/* Scene 0 is the course's scene 3, filled from the course module
   (course_scenes.c, the one copy of its numbers) by scene_of. */
#define COURSE_SCENE 0

static const scene scenes[] = {
    {"the course's scene 3", 0, 0, {{{0, 0, 0}, 0, {0, 0, 0}, 0, 0}},
     {{{0, 0, 0}, {0, 0, 0}, 0}}, {0, 0, 0}},
    {"a red sphere (0, 0, 3) r 1 first in the array, a white one "
     "(0, 0, 1) r 0.2 second, a directional light towards the camera",
     2,
     1,
     {{{0, 0, 3}, 1, {1, 0, 0}, 1, 1}, {{0, 0, 1}, 0.2, WHITE, 1, 1}},
     {{{0, 0, -1}, {0.5, 0.5, 0.5}, 0}},
     {0.1, 0.1, 0.1}},
    {"a white sphere (0, 0, 1) r 0.2 first in the array, a red one "
     "(0, 0, 3) r 1 second, a directional light towards the camera",
     2,
     1,
     {{{0, 0, 1}, 0.2, WHITE, 1, 1}, {{0, 0, 3}, 1, {1, 0, 0}, 1, 1}},
     {{{0, 0, -1}, {0.5, 0.5, 0.5}, 0}},
     {0.1, 0.1, 0.1}},
    {"a sphere (0, 0, 3) r 1, a point light at (0, 0, 1) and a sphere "
     "(0, 0, -2) r 0.5 beyond the light",
     2,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}, {{0, 0, -2}, 0.5, WHITE, 1, 1}},
     {{{0, 0, 1}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
    {"a sphere (0, 0, 3) r 1, a point light at (0, 3, 2) and a sphere "
     "(0, 1.87, 2.13) r 0.3 between them",
     2,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}, {{0, 1.87, 2.13}, 0.3, WHITE, 1, 1}},
     {{{0, 3, 2}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
    {"a sphere (0, 0, 3) r 1 of colour (1, 0.5, 0.25), ka 0.5, kd 0.8, a "
     "light straight up and a point light below at (0, -5, 2)",
     1,
     2,
     {{{0, 0, 3}, 1, {1, 0.5, 0.25}, 0.5, 0.8}},
     {{{0, 1, 0}, {0.4, 0.4, 0.4}, 0}, {{0, -5, 2}, {0.6, 0.3, 0}, 1}},
     {0.1, 0.2, 0.3}},
    {"a sphere (0, 0, 3) r 1 and a point light at (0, 4, 0)",
     1,
     1,
     {{{0, 0, 3}, 1, WHITE, 1, 1}},
     {{{0, 4, 0}, {0.5, 0.5, 0.5}, 1}},
     {0.1, 0.1, 0.1}},
};

typedef struct ray_case {
    unsigned scene;
    double d[3]; /* normalised here */
} ray_case;

static const ray_case ray_cases[] = {
    {0, {0, -20, 320}},  {0, {-213, -64, 320}}, {0, {-40, -130, 320}},
    {0, {0, 60, 320}},   {0, {-160, -80, 320}}, {0, {250, 200, 320}},
    {1, {0, 0, 1}},      {2, {0, 0, 1}},        {3, {0, 0, 1}},
    {4, {0, 0.3, 1}},    {5, {0, 0.3, 1}},      {6, {0, 0, 1}},
};
#define RAY_CASES (sizeof ray_cases / sizeof ray_cases[0])

/* ---- arithmetic in double on float-rounded inputs (harness_math.h) ---- */

static void sub(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static void value_args(const value_case *v, double *a, double *b, double *c,
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

/* The near root when > 0, else the far one, else INFINITY; far: the far
   root only. */
static double sphere_t(const double *c, double r, const double *o,
                       const double *d, int far)
{
    double oc[3], beta, delta, s;
    sub(c, o, oc);
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

/* Scene index as written (in double): the course's from its module. */
static void scene_of(unsigned index, scene *s)
{
    const rayo_course_data *data = rayo_course_data_of(RAYO_COURSE_EJ3);
    size_t i;
    *s = scenes[index];
    if (index != COURSE_SCENE || data == NULL)
        return;
    s->spheres = data->ball_count < MAX_SPHERES ? data->ball_count
                                                : MAX_SPHERES;
    s->lights = data->lamp_count < MAX_LIGHTS ? data->lamp_count
                                              : MAX_LIGHTS;
    for (i = 0; i < s->spheres; i++) {
        const rayo_course_ball *b = &data->balls[i];
        memcpy(s->s[i].c, b->center, sizeof s->s[i].c);
        s->s[i].r = b->radius;
        memcpy(s->s[i].color, b->color, sizeof s->s[i].color);
        s->s[i].ka = b->ka;
        s->s[i].kd = b->kd;
    }
    for (i = 0; i < s->lights; i++) {
        memcpy(s->l[i].v, data->lamps[i].vector, sizeof s->l[i].v);
        memcpy(s->l[i].color, data->lamps[i].color, sizeof s->l[i].color);
        s->l[i].point = data->lamps[i].point != 0;
    }
    memcpy(s->ambient, data->ambient, sizeof s->ambient);
}

/* The scene of a ray case as the harness passes it: floats, directions
   normalised. */
static void ray_scene(const ray_case *rc, scene *s, double *d)
{
    size_t i;
    scene_of(rc->scene, s);
    for (i = 0; i < s->spheres; i++) {
        vfl(s->s[i].c, s->s[i].c);
        vfl(s->s[i].color, s->s[i].color);
        s->s[i].r = fl(s->s[i].r);
        s->s[i].ka = fl(s->s[i].ka);
        s->s[i].kd = fl(s->s[i].kd);
    }
    for (i = 0; i < s->lights; i++) {
        if (!s->l[i].point)
            unit(s->l[i].v, s->l[i].v);
        vfl(s->l[i].v, s->l[i].v);
        vfl(s->l[i].color, s->l[i].color);
    }
    vfl(s->ambient, s->ambient);
    unit(rc->d, d);
    vfl(d, d);
}

enum {
    M_NONE,
    M_FIRST_SPHERE,
    M_LAST_SPHERE,
    M_FAR_ROOT,
    M_NO_SHADOWS,
    M_BEYOND_LIGHT,
    M_NO_LN_TEST,
    M_LIGHT_REVERSED,
    M_NO_AMBIENT,
    M_AMBIENT_NOT_ABSORBED,
    M_KA_KD_SWAPPED,
    M_POINT_AS_DIRECTIONAL,
    M_UNNORMALISED_LIGHT,
    M_UNNORMALISED_NORMAL,
    M_SELF_SHADOW,
    M_COUNT
};

typedef struct shading {
    double c[3];
    size_t sphere, occluder; /* (size_t)-1: none */
} shading;

/* Whether sphere j blocks the ray from p along l before limit. */
static int blocks(const sphere *s, const double *p, const double *l,
                  double limit)
{
    double oc[3], beta, delta, root;
    sub(s->c, p, oc);
    beta = dot(oc, l);
    delta = beta * beta - dot(oc, oc) + s->r * s->r;
    if (delta < 0)
        return 0;
    root = beta - sqrt(delta) > 0 ? beta - sqrt(delta) : beta + sqrt(delta);
    return root > 0 && root < limit;
}

static shading shade(const ray_case *rc, int m)
{
    scene s;
    double d[3], o[3] = {0, 0, 0}, best = INFINITY, p[3], n[3], c[3];
    double ka, kd;
    shading out;
    size_t i, j;
    memset(&out, 0, sizeof out);
    out.sphere = out.occluder = (size_t)-1;
    ray_scene(rc, &s, d);
    for (i = 0; i < s.spheres; i++) {
        double t = sphere_t(s.s[i].c, s.s[i].r, o, d, m == M_FAR_ROOT);
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
    for (j = 0; j < 3; j++) {
        p[j] = best * d[j];
        n[j] = (p[j] - s.s[i].c[j]) /
               (m == M_UNNORMALISED_NORMAL ? 1 : s.s[i].r);
    }
    ka = m == M_KA_KD_SWAPPED ? s.s[i].kd : s.s[i].ka;
    kd = m == M_KA_KD_SWAPPED ? s.s[i].ka : s.s[i].kd;
    for (j = 0; j < 3; j++)
        c[j] = m == M_NO_AMBIENT || m == M_AMBIENT_NOT_ABSORBED
                   ? 0
                   : s.ambient[j] * ka;
    for (j = 0; j < s.lights; j++) {
        const light *lamp = &s.l[j];
        double l[3], shadow_l[3], limit = INFINITY, ln;
        size_t k;
        int shadowed = 0;
        if (lamp->point && m == M_POINT_AS_DIRECTIONAL) {
            unit(lamp->v, l);
        } else if (lamp->point) {
            sub(lamp->v, p, l);
            limit = sqrt(dot(l, l));
            if (m != M_UNNORMALISED_LIGHT)
                unit(l, l);
        } else {
            memcpy(l, lamp->v, sizeof l);
        }
        if (m == M_LIGHT_REVERSED)
            for (k = 0; k < 3; k++)
                l[k] = -l[k];
        unit(l, shadow_l);
        if (m == M_BEYOND_LIGHT || m == M_POINT_AS_DIRECTIONAL)
            limit = INFINITY;
        ln = dot(l, n);
        if (ln <= 0 && m != M_NO_LN_TEST)
            continue;
        if (m == M_SELF_SHADOW)
            continue;
        for (k = 0; k < s.spheres && m != M_NO_SHADOWS && !shadowed; k++)
            if (k != i && blocks(&s.s[k], p, shadow_l, limit)) {
                shadowed = 1;
                out.occluder = k;
            }
        if (shadowed)
            continue;
        for (k = 0; k < 3; k++)
            c[k] += lamp->color[k] * kd * ln;
    }
    for (j = 0; j < 3; j++) {
        out.c[j] = c[j] * s.s[i].color[j];
        if (m == M_AMBIENT_NOT_ABSORBED)
            out.c[j] += s.ambient[j] * ka;
    }
    return out;
}

/* Channels above 1 print as 255, so they compare as 1. */
static int same_colour(const double *got, const double *want)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        double g = got[k] > 1 ? 1 : got[k], w = want[k] > 1 ? 1 : want[k];
        if (fabs(g - w) > 2e-3)
            return 0;
    }
    return 1;
}

/* ---- the harness's records ---- */

static void put_numbers(harness_text *t, const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        harness_append(t, " %.9g", v[i]);
}

/* "c NAME K" and a, b, c and s (harness/ej3.c). */
static void write_value_case(harness_text *t, const value_case *v,
                             unsigned k)
{
    double a[3], b[3], c[3], s;
    value_args(v, a, b, c, &s);
    harness_append(t, "c %s %u", functions[v->function].name, k);
    put_numbers(t, a, 3);
    put_numbers(t, b, 3);
    put_numbers(t, c, 3);
    put_numbers(t, &s, 1);
    harness_append(t, "\n");
}

/* "c computar_intensidad K", the counts, each sphere, each light, the
   ambient colour, o and d. */
static void write_ray_case(harness_text *t, const ray_case *rc, unsigned k)
{
    static const double o[3] = {0, 0, 0};
    scene s;
    double d[3], point;
    size_t i;
    ray_scene(rc, &s, d);
    harness_append(t, "c computar_intensidad %u %zu %zu", k, s.spheres,
                   s.lights);
    for (i = 0; i < s.spheres; i++) {
        put_numbers(t, s.s[i].c, 3);
        put_numbers(t, &s.s[i].r, 1);
        put_numbers(t, s.s[i].color, 3);
        put_numbers(t, &s.s[i].ka, 1);
        put_numbers(t, &s.s[i].kd, 1);
    }
    for (i = 0; i < s.lights; i++) {
        point = s.l[i].point;
        put_numbers(t, s.l[i].v, 3);
        put_numbers(t, s.l[i].color, 3);
        put_numbers(t, &point, 1);
    }
    put_numbers(t, s.ambient, 3);
    put_numbers(t, o, 3);
    put_numbers(t, d, 3);
    harness_append(t, "\n");
}

/* The missing functions said first, then the value cases, the rays and
   arreglo_agregar, last (its harness code may end early). */
static void write_calls(harness_text *t, const int *usable)
{
    unsigned i, k;
    for (i = 0; i < F_COUNT; i++)
        if (usable[i])
            harness_append(t, "m %s\n", functions[i].name);
    for (k = 0; k < VALUE_CASES; k++)
        if (usable[value_cases[k].function])
            write_value_case(t, &value_cases[k], k);
    for (k = 0; k < RAY_CASES && usable[F_INTENSIDAD]; k++)
        write_ray_case(t, &ray_cases[k], k);
    if (usable[F_AGREGAR])
        harness_append(t, "c arreglo_agregar 0\n");
}

/* ---- what the student reads ---- */

static void describe_value_case(unsigned k, char *out, size_t room)
{
    const value_case *v = &value_cases[k];
    const char *name = functions[v->function].name;
    double a[3], b[3], c[3], s;
    char x[64], y[64], z[64];
    value_args(v, a, b, c, &s);
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
        snprintf(out, room, "esfera_distancia(a sphere at %s r %.7g, %s, "
                            "%s, &punto, &normal)",
                 x, s, y, z);
        break;
    default:
        snprintf(out, room, "%s(%s, %s)", name, x, y);
        break;
    }
}

static void describe_ray_case(unsigned k, char *out, size_t room)
{
    scene s;
    double d[3];
    char x[64];
    ray_scene(&ray_cases[k], &s, d);
    snprintf(out, room, "computar_intensidad on %s, along d = %s",
             scenes[ray_cases[k].scene].what, vec_text(d, x, sizeof x));
}

static void describe(const char *name, unsigned k, char *out, size_t room)
{
    if (strcmp(name, "computar_intensidad") == 0) {
        if (k < RAY_CASES)
            describe_ray_case(k, out, room);
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
    } else if (k < VALUE_CASES &&
               strcmp(name, functions[value_cases[k].function].name) == 0) {
        describe_value_case(k, out, room);
    }
}

/* The bytes color_imprimir must print for channel c (a float). */
static int channel_byte(double c)
{
    return c > 1 ? 255 : (int)floor(255 * c);
}

/* ---- judging ---- */

typedef struct judging {
    grade_context *ctx;
    rayo_grade_item *item;
    const char *log;
    unsigned wrong, unsaid, cases;
    unsigned limit; /* wrong cases given a line */
    /* Readings of an ambiguous statement seen, each accepted and named:
       a sphere beyond a point light casts a shadow; color_imprimir
       rounds 255 c. */
    int beyond_light, between_only, rounds;
} judging;

static rayo_status wrong_line(judging *j, rayo_error *err,
                              const char *format, ...) GRADE_PRINTF(3, 4);

/* A reason line for a wrong case, or only counted past the first few. */
static rayo_status wrong_line(judging *j, rayo_error *err,
                              const char *format, ...)
{
    char line[1024];
    va_list args;
    if (j->wrong++ >= j->limit) {
        j->unsaid++;
        j->item->result = RAYO_GRADE_FAIL;
        return RAYO_OK;
    }
    va_start(args, format);
    vsnprintf(line, sizeof line, format, args);
    va_end(args);
    return grade_fail(j->item, err, "%s", line);
}

/* What most likely makes function f return a NaN. */
static const char *nan_cause(unsigned f)
{
    switch (f) {
    case F_NORMA:
        return "the square root of a negative sum (a sum of squares is "
               "never negative: check the signs) or 0/0";
    case F_NORMALIZAR:
        return HARNESS_NAN_NORMAL;
    case F_DISTANCIA:
        return HARNESS_NAN_DISCRIMINANT;
    case F_INTENSIDAD:
        return HARNESS_NAN_SHADING;
    default:
        return HARNESS_NAN_ARITHMETIC;
    }
}

static rayo_status judge_value(judging *j, unsigned k, rayo_error *err)
{
    const value_case *v = &value_cases[k];
    const char *name = functions[v->function].name;
    double a[3], b[3], c[3], s, got[10], want[3], far;
    char call[512], g[64], w[64];
    int count;
    unsigned i;
    value_args(v, a, b, c, &s);
    describe_value_case(k, call, sizeof call);
    count = harness_result(j->log, name, k, got, 10);
    if (count < 0)
        return RAYO_ERR_CANCELLED; /* it ended before: said elsewhere */
    j->cases++;
    {
        int scalar = v->function == F_PRODUCTO || v->function == F_NORMA ||
                     v->function == F_DISTANCIA;
        char line[1024];
        if (v->function != F_IMPRIMIR && v->function != F_ESFERA_CREAR &&
            v->function != F_LUZ_CREAR && count >= 4 &&
            harness_not_finite(call, scalar ? got : got + 1, scalar ? 1 : 3,
                               nan_cause(v->function),
                               v->function == F_DISTANCIA
                                   ? "the statement's INFINITO is FLT_MAX, the "
                                     "largest "
                                     "float, not an infinity"
                                   : NULL,
                               line, sizeof line))
            return wrong_line(j, err, "%s", line);
        if (v->function == F_DISTANCIA && count >= 7 &&
            !is_infinito(got[0]) &&
            (harness_not_finite(call, got + 1, 3, HARNESS_NAN_ARITHMETIC,
                                NULL, line, sizeof line) ||
             harness_not_finite(call, got + 4, 3, HARNESS_NAN_NORMAL, NULL,
                                line, sizeof line)))
            return wrong_line(j, err, "%s (in *punto or *normal)", line);
    }
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA: {
        double x = v->function == F_NORMA ? sqrt(dot(a, a)) : dot(a, b);
        if (near_value(got[0], x))
            return RAYO_OK;
        if (got[0] == floor(x) && x != floor(x))
            return wrong_line(j, err, "%s returned %g; expected %.7g: the "
                                      "decimals are lost, is an int used "
                                      "inside the function?",
                              call, got[0], x);
        return wrong_line(j, err, "%s returned %.7g; expected %.7g", call,
                          got[0], x);
    }
    case F_RESTA:
        sub(a, b, want);
        if (near_vector(got + 1, want))
            return RAYO_OK;
        sub(b, a, c);
        return wrong_line(j, err, "%s returned %s; expected %s%s", call,
                          vec_text(got + 1, g, sizeof g),
                          vec_text(want, w, sizeof w),
                          near_vector(got + 1, c) ? ": that is b - a; the "
                                                    "result is a - b"
                                                  : "");
    case F_INTERPOLAR:
        for (i = 0; i < 3; i++)
            want[i] = a[i] + s * b[i];
        break;
    case F_NORMALIZAR:
        unit(a, want);
        break;
    case F_SUMAR:
        for (i = 0; i < 3; i++)
            want[i] = a[i] + s * b[i];
        break;
    case F_ABSORBER:
        for (i = 0; i < 3; i++)
            want[i] = a[i] * b[i];
        break;
    case F_IMPRIMIR:
        return RAYO_OK; /* judged from its output: judge_imprimir */
    case F_ESFERA_CREAR:
    case F_LUZ_CREAR:
        return RAYO_OK; /* judge_crear */
    default:
        far = sphere_t(a, s, b, c, 1);
        want[0] = sphere_t(a, s, b, c, 0);
        if (want[0] == INFINITY) {
            if (is_infinito(got[0]))
                return RAYO_OK;
            return wrong_line(j, err, "%s returned %.7g for a ray that %s; "
                                      "expected INFINITO (FLT_MAX)",
                              call, got[0],
                              a[2] < 0 ? "meets the sphere only behind "
                                         "its origin (t < 0)"
                                       : "misses the sphere");
        }
        if (is_infinito(got[0]))
            return wrong_line(j, err, "%s returned INFINITO for a ray that "
                                      "meets the sphere at t = %.7g",
                              call, want[0]);
        if (!near_value(got[0], want[0])) {
            if (far != want[0] && near_value(got[0], far))
                return wrong_line(j, err, "%s returned the far root %.7g "
                                          "for a ray that meets the sphere "
                                          "at t = %.7g first: "
                                          "beta - sqrt(delta) when it is "
                                          "> 0",
                                  call, got[0], want[0]);
            if (got[0] < 0)
                return wrong_line(j, err, "%s returned %.7g, a root behind "
                                          "the origin (t < 0), for a ray "
                                          "that starts inside the sphere; "
                                          "expected %.7g: when "
                                          "beta - sqrt(delta) <= 0 the "
                                          "answer is beta + sqrt(delta)",
                                  call, got[0], want[0]);
            return wrong_line(j, err, "%s returned %.7g; expected %.7g",
                              call, got[0], want[0]);
        }
        {
            double p[3], n[3], length = sqrt(dot(got + 4, got + 4));
            for (i = 0; i < 3; i++)
                p[i] = b[i] + want[0] * c[i];
            for (i = 0; i < 3; i++)
                n[i] = (p[i] - a[i]) / s;
            if (!near_vector(got + 1, p))
                return wrong_line(j, err, "%s: *punto is %s; expected the "
                                          "hit point o + t d = %s",
                                  call, vec_text(got + 1, g, sizeof g),
                                  vec_text(p, w, sizeof w));
            if (!near_vector(got + 4, n))
                return wrong_line(j, err, "%s: *normal is %s, of length "
                                          "%.7g; expected the unit normal "
                                          "(P - C) / r = %s",
                                  call, vec_text(got + 4, g, sizeof g),
                                  length, vec_text(n, w, sizeof w));
        }
        return RAYO_OK;
    }
    if (near_vector(got + 1, want))
        return RAYO_OK;
    return wrong_line(j, err, "%s returned %s; expected %s", call,
                      vec_text(got + 1, g, sizeof g),
                      vec_text(want, w, sizeof w));
}

/* color_imprimir: the text printed between the markers. */
static rayo_status judge_imprimir(judging *j, unsigned k, rayo_error *err)
{
    const value_case *v = &value_cases[k];
    double a[3], b[3], c[3], s, dummy;
    char call[256], key[64], shown[128], expect[32];
    const char *start, *end;
    int want[3], got[3], used = 0;
    unsigned i;
    value_args(v, a, b, c, &s);
    describe_value_case(k, call, sizeof call);
    if (harness_result(j->log, "color_imprimir", k, &dummy, 1) < 0)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    snprintf(key, sizeof key, "\nout color_imprimir %u\n", k);
    start = strstr(j->log, key);
    if (start == NULL)
        return RAYO_ERR_CANCELLED;
    start += strlen(key);
    end = strstr(start, "\nend color_imprimir ");
    if (end == NULL)
        end = start + strlen(start);
    harness_clean(start, (size_t)(end - start), shown, sizeof shown);
    for (i = 0; i < 3; i++)
        want[i] = channel_byte(a[i]);
    snprintf(expect, sizeof expect, "%d %d %d", want[0], want[1], want[2]);
    if (strstr(shown, "nan") != NULL || strstr(shown, "inf") != NULL ||
        strstr(shown, "-2147483648") != NULL)
        return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "nan and inf (printed by %%f) and "
                                  "-2147483648 (a NaN or a value past the "
                                  "int range through (int)) come from a "
                                  "result that is not a number: likely %s",
                          call, shown, expect, HARNESS_NAN_ARITHMETIC);
    if (sscanf(start, "%d %d %d%n", &got[0], &got[1], &got[2], &used) != 3 ||
        start + used > end || strspn(start + used, " \t\n") <
                                  (size_t)(end - start - used))
        return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "three integers R G B from 0 to 255",
                          call, shown, expect);
    if (got[0] == want[2] && got[1] == want[1] && got[2] == want[0] &&
        want[0] != want[2])
        return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "the channels are in the order B G R; "
                                  "a PPM pixel is R G B",
                          call, shown, expect);
    for (i = 0; i < 3; i++) {
        if (got[i] == want[i])
            continue;
        if (a[i] > 1 && got[i] == (int)floor(255 * a[i]) % 256)
            return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                      "255 x %.7g wrapped around 256; a "
                                      "component above 1 prints as 255",
                              call, shown, expect, a[i]);
        if (a[i] > 1)
            return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                      "a component above 1 prints as 255",
                              call, shown, expect);
        if (got[i] == (int)floor(255 * a[i] + 0.5)) {
            j->rounds = 1; /* a reading, accepted: judge() names it */
            continue;
        }
        if (got[i] == (int)floor(256 * a[i]))
            return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                      "scaled by 256; 0..1 scales to "
                                      "0..255",
                              call, shown, expect);
        return wrong_line(j, err, "%s printed \"%s\"; expected \"%s\"",
                          call, shown, expect);
    }
    return RAYO_OK;
}

/* esfera_crear and luz_crear keep what they are given. */
static rayo_status judge_crear(judging *j, unsigned k, rayo_error *err)
{
    static const char *const sphere_fields[] = {
        "centro.x", "centro.y", "centro.z", "radio", "color.r",
        "color.g",  "color.b",  "ka",       "kd"};
    static const char *const light_fields[] = {
        "posicion.x", "posicion.y", "posicion.z", "color.r",
        "color.g",    "color.b",    "es_puntual"};
    const value_case *v = &value_cases[k];
    int is_sphere = v->function == F_ESFERA_CREAR;
    const char *name = functions[v->function].name;
    double a[3], b[3], c[3], s, got[9], given[9];
    char call[512], text[16];
    int count, fields = is_sphere ? 9 : 7;
    unsigned i;
    value_args(v, a, b, c, &s);
    describe_value_case(k, call, sizeof call);
    if (!harness_result_text(j->log, name, k, text, sizeof text))
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (strncmp(text, "null", 4) == 0)
        return wrong_line(j, err, "%s returned NULL", call);
    count = harness_result(j->log, name, k, got, fields);
    for (i = 0; i < 3; i++) {
        given[i] = a[i];
        given[i + (is_sphere ? 4 : 3)] = b[i];
    }
    if (is_sphere) {
        given[3] = s;
        given[7] = c[0];
        given[8] = c[1];
    } else {
        given[6] = s != 0;
    }
    for (i = 0; i < (unsigned)fields && (int)i < count; i++)
        if (!near_value(got[i], given[i]))
            return wrong_line(
                j, err, "%s returned a %s whose %s is %.7g, not the %.7g "
                        "it was given",
                call, is_sphere ? "sphere" : "light",
                is_sphere ? sphere_fields[i] : light_fields[i], got[i],
                given[i]);
    return RAYO_OK;
}

static rayo_status judge_agregar(judging *j, rayo_error *err)
{
    double r[8];
    int count = harness_result(j->log, "arreglo_agregar", 0, r, 8);
    if (count < 8)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (r[6] == 0)
        return wrong_line(j, err, "arreglo_agregar wrote past the end of "
                                  "a->v: after three additions to an empty "
                                  "array its last realloc asked for %g "
                                  "bytes, and a pointer was written beyond "
                                  "them; ask for (a->n + 1) * sizeof(void *) "
                                  "before writing a->v[a->n]",
                          r[7]);
    if (r[0] == 0 || r[1] == 0 || r[2] == 0)
        return wrong_line(j, err, "arreglo_agregar returned false while "
                                  "adding three elements to an empty "
                                  "array {NULL, 0}; it returns true when "
                                  "it adds");
    if (r[3] != 3)
        return wrong_line(j, err, "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->n is %g; expected 3",
                          r[3]);
    if (r[4] == 0)
        return wrong_line(j, err, "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->v is NULL");
    if (r[5] == 0)
        return wrong_line(j, err, "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->v does not hold the "
                                  "three elements in the order added");
    /* tries, returned, n before, n after, v NULL, v same, same contents */
    count = harness_result(j->log, "arreglo_agregar", 1, r, 7);
    if (count < 7)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (r[0] == 0)
        return wrong_line(j, err, "arreglo_agregar added %g elements "
                                  "without asking for memory: a->v must "
                                  "grow (with realloc) as elements are "
                                  "added",
                          r[3]);
    if (r[4] != 0)
        return wrong_line(j, err, "arreglo_agregar lost the array when "
                                  "realloc failed: a->v became NULL; keep "
                                  "realloc's result in a temporary and "
                                  "assign it only when it is not NULL");
    if (r[1] != 0)
        return wrong_line(j, err, "arreglo_agregar returned true when "
                                  "realloc failed; on failure it returns "
                                  "false");
    if (r[2] != r[3])
        return wrong_line(j, err, "arreglo_agregar changed a->n from %g to "
                                  "%g when realloc failed; on failure the "
                                  "array is left exactly as it was",
                          r[2], r[3]);
    if (r[5] == 0 || r[6] == 0)
        return wrong_line(j, err, "arreglo_agregar changed a->v or its "
                                  "elements when realloc failed; on "
                                  "failure the array is left exactly as it "
                                  "was");
    return RAYO_OK;
}

static void colour_text(const double *c, char *out, size_t room)
{
    snprintf(out, room, "(%.3g, %.3g, %.3g)", c[0], c[1], c[2]);
}

static void sphere_text(const ray_case *rc, size_t i, char *out,
                        size_t room)
{
    scene whole;
    const sphere *s = &whole.s[i];
    scene_of(rc->scene, &whole);
    snprintf(out, room, "the sphere at (%g, %g, %g) of colour (%g, %g, %g)",
             s->c[0], s->c[1], s->c[2], s->color[0], s->color[1],
             s->color[2]);
}

/* How many of the results each modelled mistake agrees with. */
static void mistake_scores(double got[][3], unsigned *score)
{
    unsigned c;
    int k;
    for (k = 0; k < M_COUNT; k++)
        score[k] = 0;
    for (c = 0; c < RAY_CASES; c++)
        for (k = M_NONE + 1; k < M_COUNT; k++)
            score[k] += same_colour(got[c], shade(&ray_cases[c], k).c);
}

/* The mistake that gives got for this case (and not the right colour)
   and agrees with the most results overall; M_COUNT when none does. */
static int ray_mistake(const ray_case *rc, const double *got,
                       const unsigned *score)
{
    shading want = shade(rc, M_NONE);
    int k, best = M_COUNT;
    for (k = M_NONE + 1; k < M_COUNT; k++) {
        shading m = shade(rc, k);
        if (!same_colour(m.c, want.c) && same_colour(got, m.c) &&
            (best == M_COUNT || score[k] > score[best]))
            best = k;
    }
    return best;
}

static const char *const mistake_texts[M_COUNT] = {
    "",
    "",
    "",
    "",
    "lies between the point and the light, which then does not count",
    "lies beyond the point light, not between the point and the light, "
    "and casts no shadow: only a sphere hit at t < |posicion - P| does",
    "a light with L.N < 0 adds nothing: the diffuse term counts only when "
    "L.N > 0",
    "as if each L pointed away from its light: L is the direction from P "
    "towards the light (normalise(posicion - P) for a point light)",
    "the ambient Ia ka is missing",
    "Ia ka was added after the product with the sphere's colour: "
    "C = (Ia ka + sum of the lights) (x) M",
    "ka and kd are swapped: Ia ka is the ambient term, kd multiplies the "
    "lights",
    "a point light's posicion was used as a direction: its L is "
    "normalise(posicion - P)",
    "posicion - P was not normalised",
    "as if the normal were P - C, not divided by the radius",
    "a shadow where no other sphere blocks the light: does the shadow "
    "test skip the sphere the point is on?"};

static rayo_status say_ray(judging *j, unsigned c, const double *got,
                           int k, rayo_error *err)
{
    const ray_case *rc = &ray_cases[c];
    shading want = shade(rc, M_NONE), m;
    char call[512], g[64], w[64], x[128], y[128];
    describe_ray_case(c, call, sizeof call);
    colour_text(got, g, sizeof g);
    colour_text(want.c, w, sizeof w);
    if (k == M_COUNT)
        return wrong_line(j, err, "%s returned %s; expected %s", call, g, w);
    m = shade(rc, k);
    if (k == M_FIRST_SPHERE || k == M_LAST_SPHERE) {
        sphere_text(rc, m.sphere, x, sizeof x);
        sphere_text(rc, want.sphere, y, sizeof y);
        return wrong_line(j, err, "%s returned %s, the colour of %s, the "
                                  "%s sphere in the array the ray hits, not "
                                  "the nearest (%s, %s): keep the smallest "
                                  "t",
                          call, g, x, k == M_FIRST_SPHERE ? "first" : "last",
                          y, w);
    }
    if (k == M_FAR_ROOT) {
        sphere_text(rc, want.sphere, x, sizeof x);
        return wrong_line(j, err, "%s returned %s, the colour at the far "
                                  "side of %s; expected %s: the ray meets "
                                  "it first at t = beta - sqrt(delta)",
                          call, g, x, w);
    }
    if (k == M_NO_SHADOWS || k == M_BEYOND_LIGHT) {
        sphere_text(rc, k == M_NO_SHADOWS ? want.occluder : m.occluder, x,
                    sizeof x);
        return wrong_line(j, err, "%s returned %s; expected %s: %s %s",
                          call, g, w, x, mistake_texts[k]);
    }
    return wrong_line(j, err, "%s returned %s; expected %s: %s", call, g, w,
                      mistake_texts[k]);
}

static rayo_status judge_rays(judging *j, rayo_error *err)
{
    double got[RAY_CASES][3];
    char call[512], line[1024];
    unsigned c, said = 0, score[M_COUNT];
    rayo_status status = RAYO_OK;
    for (c = 0; c < RAY_CASES; c++) {
        double v[4];
        if (harness_result(j->log, "computar_intensidad", c, v, 4) != 4)
            return RAYO_ERR_CANCELLED;
        memcpy(got[c], v + 1, sizeof got[c]);
    }
    mistake_scores(got, score);
    for (c = 0; c < RAY_CASES && status == RAYO_OK; c++) {
        const ray_case *rc = &ray_cases[c];
        int mistake;
        j->cases++;
        if (harness_not_finite("", got[c], 3, "", NULL, line, sizeof line)) {
            if (said & (1u << (M_COUNT + 1))) {
                j->wrong++;
                j->unsaid++;
                continue;
            }
            said |= 1u << (M_COUNT + 1);
            describe_ray_case(c, call, sizeof call);
            harness_not_finite(call, got[c], 3, HARNESS_NAN_SHADING, NULL,
                               line, sizeof line);
            status = wrong_line(j, err, "%s", line);
            continue;
        }
        if (same_colour(got[c], shade(rc, M_NONE).c)) {
            if (!same_colour(shade(rc, M_NONE).c,
                             shade(rc, M_BEYOND_LIGHT).c))
                j->between_only = 1; /* the other reading, named too */
            continue;
        }
        if (same_colour(got[c], shade(rc, M_BEYOND_LIGHT).c)) {
            j->beyond_light = 1; /* a reading, accepted: judge() names it */
            continue;
        }
        mistake = ray_mistake(rc, got[c], score);
        /* One line per mistake recognised; the same one again counted. */
        if (said & (1u << mistake)) {
            j->wrong++;
            j->unsaid++;
            continue;
        }
        said |= 1u << mistake;
        status = say_ray(j, c, got[c], mistake, err);
    }
    return status;
}

/* Judges function f; RAYO_ERR_CANCELLED inside: the run ended before
   its calls were done (said by harness_judge_ending). */
static rayo_status judge(grade_context *ctx, unsigned f, const char *log,
                         const int *usable, rayo_error *err)
{
    judging j;
    unsigned k;
    rayo_status status = RAYO_OK;
    j.ctx = ctx;
    j.item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    j.log = log;
    j.wrong = j.unsaid = j.cases = 0;
    j.beyond_light = j.between_only = j.rounds = 0;
    j.limit = f == F_INTENSIDAD ? SAID_PER_FUNCTION + 2 : SAID_PER_FUNCTION;
    if (harness_missing(log, functions[f].name))
        return grade_fail(j.item, err, "%s: not defined; the statement asks "
                                       "for %s",
                          functions[f].name, functions[f].prototype);
    if (f == F_ESFERA_DESTRUIR || f == F_LUZ_DESTRUIR) {
        unsigned maker = f == F_ESFERA_DESTRUIR ? F_ESFERA_CREAR
                                                : F_LUZ_CREAR;
        if (!usable[maker] || harness_missing(log, functions[maker].name))
            return grade_say(j.item, err, "%s: not called (it needs what "
                                          "%s returns)",
                             functions[f].name, functions[maker].name);
        for (k = 0; k < VALUE_CASES; k++)
            if (value_cases[k].function == maker &&
                harness_result_text(log, functions[f].name, k, (char[4]){0},
                                    4))
                break;
        if (k == VALUE_CASES)
            return RAYO_OK;
        return grade_say(j.item, err, "%s: called on what %s returned "
                                      "(valgrind checks what it frees)",
                         functions[f].name, functions[maker].name);
    }
    if (f == F_AGREGAR)
        status = judge_agregar(&j, err);
    else if (f == F_INTENSIDAD)
        status = judge_rays(&j, err);
    for (k = 0; k < VALUE_CASES && status == RAYO_OK; k++) {
        if (value_cases[k].function != f)
            continue;
        if (f == F_IMPRIMIR)
            status = judge_imprimir(&j, k, err);
        else if (f == F_ESFERA_CREAR || f == F_LUZ_CREAR)
            status = judge_crear(&j, k, err);
        else
            status = judge_value(&j, k, err);
    }
    if (status == RAYO_ERR_CANCELLED)
        return RAYO_OK;
    if (status == RAYO_OK && j.wrong == 0)
        status = grade_say(j.item, err, "%s: right on %u known input%s",
                           functions[f].name, j.cases,
                           j.cases == 1 ? "" : "s");
    else if (status == RAYO_OK && j.unsaid > 0)
        status = grade_fail(j.item, err, "%s: wrong on %u more of its %u "
                                         "known inputs",
                            functions[f].name, j.unsaid, j.cases);
    if (status == RAYO_OK && j.beyond_light)
        status = grade_say(j.item, err, "computar_intensidad: a sphere "
                                        "beyond a point light casts a "
                                        "shadow: the statement's rule (an "
                                        "object in the light's direction "
                                        "casts a shadow) read to the "
                                        "letter, accepted; the other "
                                        "reading, a shadow only from a "
                                        "sphere between the point and the "
                                        "light, is accepted too, and the "
                                        "course's scenes look the same "
                                        "either way");
    if (status == RAYO_OK && j.between_only && !j.beyond_light)
        status = grade_say(j.item, err, "computar_intensidad: only a sphere "
                                        "between the point and a point "
                                        "light casts a shadow, not one "
                                        "beyond the light: one of the "
                                        "statement's two readings, "
                                        "accepted; the other, to the "
                                        "letter (an object in the light's "
                                        "direction casts a shadow), is "
                                        "accepted too, and the course's "
                                        "scenes look the same either way");
    if (status == RAYO_OK && j.rounds)
        status = grade_say(j.item, err, "color_imprimir: rounds 255 c to "
                                        "the nearest integer (0.999 prints "
                                        "255) instead of taking its integer "
                                        "part (254): a reading of the "
                                        "statement's 'scale 0..1 to the "
                                        "integers 0..255', accepted");
    return status;
}

/* ---- probing the types and the signatures ---- */

enum { TYPE_MISSING, TYPE_OK, TYPE_WRONG };

/* The probe text after the #include for type t. */
static void type_probe(harness_text *t, unsigned type)
{
    const char *name = type_names[type];
    unsigned i;
    harness_append(t, "\n%stypedef %s rayo_probe_type;\n", mirror_types,
                   name);
    for (i = 0; i < 5 && members[type][i].name != NULL; i++)
        harness_append(t, "typedef char rayo_check_%s_%s[_Generic(((%s *)0)"
                          "->%s, %s: 1, default: -1)];\n",
                       name, members[type][i].name, name,
                       members[type][i].name, members[type][i].type);
    harness_append(t, "typedef char rayo_layout_%s[sizeof(%s) == "
                      "sizeof(struct rayo_%s)",
                   name, name, name);
    for (i = 0; i < 5 && members[type][i].name != NULL; i++)
        harness_append(t, " && offsetof(%s, %s) == offsetof(struct rayo_%s, "
                          "%s)",
                       name, members[type][i].name, name,
                       members[type][i].name);
    harness_append(t, " ? 1 : -1];\n");
}

/* Probes the types in source i: state[t] for each. */
static rayo_status probe_types(grade_context *ctx, size_t i, int *state,
                               char reasons[][HARNESS_REASON],
                               rayo_error *err)
{
    unsigned t;
    rayo_status status = RAYO_OK;
    for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
        harness_text text = {NULL, 0, 0, 0};
        char reason[HARNESS_REASON];
        int ok;
        if ((t == T_ESFERA || t == T_LUZ) &&
            (state[T_VECTOR] != TYPE_OK || state[T_COLOR] != TYPE_OK)) {
            state[t] = TYPE_MISSING;
            snprintf(reasons[t], HARNESS_REASON, "it uses vector_t and "
                                                 "color_t");
            continue;
        }
        type_probe(&text, t);
        if (text.failed) {
            free(text.data);
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        }
        status = harness_probe(ctx, i, "#include <stddef.h>\n", text.data,
                               &ok, reason, sizeof reason, err);
        free(text.data);
        if (status != RAYO_OK)
            break;
        if (ok) {
            state[t] = TYPE_OK;
        } else {
            /* gcc: unknown type name; clang: also "must use 'struct'
               tag" for a struct of that name without its typedef. */
            state[t] = strstr(reason, "unknown type name") != NULL ||
                               strstr(reason, "undeclared") != NULL ||
                               strstr(reason, "must use 'struct'") != NULL
                           ? TYPE_MISSING
                           : TYPE_WRONG;
            memcpy(reasons[t], reason, sizeof reason);
        }
    }
    return status;
}

static rayo_status say_type(rayo_grade_item *item, unsigned t, int state,
                            const char *reason, rayo_error *err)
{
    const char *p = strstr(reason, "rayo_check_");
    char member_name[32] = "";
    if (state == TYPE_MISSING)
        return grade_fail(item, err, "%s: not defined as the statement's "
                                     "type (the compiler says: %s); the "
                                     "statement gives %s (a struct declared "
                                     "without the typedef is struct NAME, "
                                     "not %s)",
                          type_names[t], reason, type_texts[t],
                          type_names[t]);
    if (p != NULL &&
        sscanf(p + strlen("rayo_check_") + strlen(type_names[t]) + 1,
               "%31[a-z_]", member_name) == 1)
        return grade_fail(item, err, "%s: its member %s is not of the "
                                     "statement's type; the statement gives "
                                     "%s",
                          type_names[t], member_name, type_texts[t]);
    if (strstr(reason, "rayo_layout_") != NULL)
        return grade_fail(item, err, "%s: its members are not the "
                                     "statement's, in its order; the "
                                     "statement gives %s",
                          type_names[t], type_texts[t]);
    return grade_fail(item, err, "%s: differs from the statement's %s (the "
                                 "compiler says: %s)",
                      type_names[t], type_texts[t], reason);
}

/* Probes the prototypes of the functions in which[] in source i. */
static rayo_status probe_functions(grade_context *ctx, size_t i,
                                   const unsigned *which, size_t count,
                                   int *ok, char *reason, rayo_error *err)
{
    harness_text t = {NULL, 0, 0, 0};
    char *messages = NULL, type[200];
    size_t k;
    rayo_status status;
    harness_append(&t, "\n");
    for (k = 0; k < count; k++)
        put_prototype(&t, which[k], "");
    if (t.failed) {
        free(t.data);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    status = harness_probe_full(ctx, i, "#include <stddef.h>\n", t.data,
                                ok, reason, HARNESS_REASON, &messages, err);
    /* Our declaration comes second, so the compiler's "have" is ours;
       the student's type is in its note, when it gives one. */
    if (status == RAYO_OK && !*ok && count == 1) {
        char said[HARNESS_REASON];
        harness_previous_type(messages, functions[which[0]].name, type,
                              sizeof type);
        if (strstr(reason, "; have ") != NULL)
            *strstr(reason, "; have ") = '\0';
        memcpy(said, reason, sizeof said);
        if (type[0] != '\0')
            snprintf(reason, HARNESS_REASON, "the file has %s", type);
        else {
            harness_shorten(said, 300);
            snprintf(reason, HARNESS_REASON, "the compiler says: %s", said);
        }
    }
    free(messages);
    free(t.data);
    return status;
}

typedef struct probing {
    int type_state[T_COUNT];
    char type_reasons[T_COUNT][HARNESS_REASON];
    int usable[F_COUNT];
    char reasons[F_COUNT][HARNESS_REASON]; /* "" when usable */
} probing;

static rayo_status probe_all(grade_context *ctx, probing *p,
                             rayo_error *err)
{
    int state[T_COUNT];
    char reasons[T_COUNT][HARNESS_REASON];
    unsigned f, t, which[F_COUNT];
    size_t i, n;
    int ok;
    rayo_status status = RAYO_OK;
    memset(p, 0, sizeof *p);
    for (i = 0; i < ctx->source_count && status == RAYO_OK; i++) {
        status = probe_types(ctx, i, state, reasons, err);
        for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
            if (state[t] == TYPE_WRONG ||
                (state[t] == TYPE_OK && p->type_state[t] == TYPE_MISSING) ||
                (i == 0 && state[t] == TYPE_MISSING)) {
                if (p->type_state[t] != TYPE_WRONG) {
                    p->type_state[t] = state[t];
                    memcpy(p->type_reasons[t], reasons[t],
                           sizeof reasons[t]);
                }
            }
        }
    }
    for (f = 0; f < F_COUNT; f++) {
        p->usable[f] = 1;
        for (t = 0; t < T_COUNT; t++)
            if ((function_types[f] & TB(t)) &&
                p->type_state[t] != TYPE_OK)
                p->usable[f] = 0;
    }
    /* The signatures, in the sources where their types are visible:
       one probe for all, one each when that fails. */
    for (i = 0; i < ctx->source_count && status == RAYO_OK; i++) {
        status = probe_types(ctx, i, state, reasons, err);
        n = 0;
        for (f = 0; f < F_COUNT && status == RAYO_OK; f++) {
            int visible = p->usable[f];
            for (t = 0; t < T_COUNT; t++)
                if ((function_types[f] & TB(t)) && state[t] != TYPE_OK)
                    visible = 0;
            if (visible)
                which[n++] = f;
        }
        if (status != RAYO_OK || n == 0)
            continue;
        status = probe_functions(ctx, i, which, n, &ok, p->reasons[0], err);
        p->reasons[0][0] = '\0';
        for (f = 0; f < n && status == RAYO_OK && !ok; f++) {
            int one;
            status = probe_functions(ctx, i, &which[f], 1, &one,
                                     p->reasons[which[f]], err);
            if (status == RAYO_OK && !one)
                p->usable[which[f]] = 0;
            else if (status == RAYO_OK)
                p->reasons[which[f]][0] = '\0';
        }
    }
    return status;
}

/* The report of the probes: types first, then the functions not called
   because of a type, then each wrong signature. */
static rayo_status say_probes(rayo_grade_item *item, const probing *p,
                              rayo_error *err)
{
    harness_text list = {NULL, 0, 0, 0};
    unsigned t, f, bad_types = 0;
    rayo_status status = RAYO_OK;
    for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
        if (p->type_state[t] == TYPE_OK)
            continue;
        bad_types |= TB(t);
        if ((t == T_ESFERA || t == T_LUZ) &&
            (p->type_state[T_VECTOR] != TYPE_OK ||
             p->type_state[T_COLOR] != TYPE_OK))
            continue; /* not checkable; said with vector_t or color_t */
        status = say_type(item, t, p->type_state[t], p->type_reasons[t],
                          err);
    }
    for (f = 0; f < F_COUNT; f++)
        if (function_types[f] & bad_types)
            harness_append(&list, "%s%s", list.length > 0 ? ", " : "",
                           functions[f].name);
    if (list.failed)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    else if (status == RAYO_OK && list.length > 0)
        status = grade_fail(item, err, "not called, as they use a type that "
                                       "is not the statement's: %s",
                            list.data);
    free(list.data);
    for (f = 0; f < F_COUNT && status == RAYO_OK; f++)
        if (!p->usable[f] && !(function_types[f] & bad_types))
            status = grade_fail(item, err, "%s: the signature differs from "
                                           "the statement's %s (%s); not "
                                           "called",
                                functions[f].name, functions[f].prototype,
                                p->reasons[f]);
    return status;
}

/* The exercise's own probe: types, then signatures; its findings
   said, the functions to call in usable. */
static rayo_status probe(grade_context *ctx, int *usable, rayo_error *err)
{
    probing *p = malloc(sizeof *p);
    unsigned f;
    rayo_status status;
    if (p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    status = probe_all(ctx, p, err);
    for (f = 0; f < F_COUNT; f++)
        usable[f] = p->usable[f];
    if (status == RAYO_OK)
        status = say_probes(&ctx->report->items[RAYO_GRADE_FUNCTIONS], p,
                            err);
    free(p);
    return status;
}

static const char *const wrap_words[] = {
    "-Wl,--wrap=malloc", "-Wl,--wrap=calloc", "-Wl,--wrap=realloc"};

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
    functions, F_COUNT, harness_ej3_c, &harness_ej3_c_size, wrap_words,
    sizeof wrap_words / sizeof wrap_words[0], "", 0, probe, write_calls,
    judge, describe, owners, sizeof owners / sizeof owners[0]};
