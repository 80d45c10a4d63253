/*
 * ej3.h - what the files of Ejercicio obligatorio 3's functions table
 * share: its functions and types by number, its cases and scenes
 * (ej3.c), the model of computar_intensidad and its mistakes
 * (ej3_model.c), the judging (ej3_judge.c, ej3_rays.c) and the probes of
 * the statement's types and signatures (ej3_probe.c).  Private to
 * src/grade/functions.
 */
#ifndef RAYO_GRADE_FUNCTIONS_EJ3_H
#define RAYO_GRADE_FUNCTIONS_EJ3_H

#include <stddef.h>

#include "rayo/course/course.h"
#include "harness.h"
#include "table.h"

#define SAID_PER_FUNCTION 2 /* wrong cases quoted; the others counted */
#define MAX_SPHERES 25
#define MAX_LIGHTS 4

enum { T_VECTOR, T_COLOR, T_ESFERA, T_LUZ, T_ARREGLO, T_COUNT };

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

/* a, b vectors or colours; s a scalar.  vector_producto_interno(a, b),
   vector_norma(a), vector_resta(a, b), vector_interpolar_recta(a, b, s),
   vector_normalizar(a), color_sumar(a, b, s), color_absorber(a, b),
   color_imprimir(a), esfera_crear(a, s, b, ka, kd) with ka, kd in c,
   luz_crear(a, b, s != 0), esfera_distancia(sphere a r s, o b, d c). */
typedef struct value_case {
    unsigned function;
    double a[3], b[3], c[3], s;
} value_case;

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

#define COURSE_SCENE 0 /* ej3_scenes[0]: filled from the course module */

typedef struct ray_case {
    unsigned scene;
    double d[3]; /* normalised here */
} ray_case;

/* ej3_shade's m: one of the course's mistakes (rayo_course_mistake),
   or the reading of the statement in which a sphere beyond a point
   light casts a shadow, which is accepted and named (not a mistake). */
#define EJ3_BEYOND_LIGHT RAYO_MISTAKE_COUNT
#define EJ3_NO_MODEL (RAYO_MISTAKE_COUNT + 1) /* none agrees */

typedef struct shading {
    double c[3];
    size_t sphere, occluder; /* (size_t)-1: none */
} shading;

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

/* ej3.c: the tables. */
extern const functions_function ej3_functions[F_COUNT];
extern const unsigned ej3_function_types[F_COUNT]; /* TB() of its types */
extern const value_case ej3_value_cases[];
extern const size_t ej3_value_case_count;
extern const scene ej3_scenes[]; /* 0: the course's scene 3 */
extern const ray_case ej3_ray_cases[];
extern const size_t ej3_ray_case_count;
void ej3_describe_value_case(unsigned k, rayo_lang lang, char *out,
                             size_t room);
void ej3_describe_ray_case(unsigned k, rayo_lang lang, char *out,
                           size_t room);

/* ej3_model.c: arithmetic in double on float-rounded inputs. */
void ej3_sub(const double *a, const double *b, double *out);
void ej3_value_args(const value_case *v, double *a, double *b, double *c,
                    double *s);
void ej3_scene_of(unsigned index, scene *s);
void ej3_ray_scene(const ray_case *rc, scene *s, double *d);
int ej3_blocks(const sphere *s, const double *p, const double *l,
               double limit);
shading ej3_shade(const ray_case *rc, int m);
int ej3_same_colour(const double *got, const double *want);

/* ej3_judge.c and ej3_rays.c; ej3_wrong_line's format is a catalog
   message (an xgettext keyword), looked up in err's language. */
rayo_status ej3_wrong_line(judging *j, rayo_error *err, const char *format,
                           ...) GRADE_PRINTF(3, 4);
rayo_status ej3_judge_rays(judging *j, rayo_error *err);
rayo_status ej3_judge(grade_context *ctx, unsigned f, const char *log,
                      const int *usable, rayo_error *err);

/* ej3_probe.c: the types, then the signatures; findings said. */
rayo_status ej3_probe(grade_context *ctx, int *usable, rayo_error *err);

#endif
