/*
 * ej2.h - what the files of Ejercicio obligatorio 2's functions table
 * share: its functions by number, its cases and scenes and their
 * arguments (ej2.c), and the judging with the model of
 * computar_intensidad and its mistakes (ej2_judge.c).  Private to
 * src/grade/functions.
 */
#ifndef RAYO_GRADE_FUNCTIONS_EJ2_H
#define RAYO_GRADE_FUNCTIONS_EJ2_H

#include <stddef.h>

#include "harness.h"
#include "table.h"

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

/* The arguments of one call: a, b, c are vectors, s a scalar, by
   function: producto_interno(a, b); norma(a); normalizar(a);
   resta(r, a, b); interpolar_recta(p, a, b, s);
   distancia_esfera(a, s, b, c); normal_esfera(n, a, s, b). */
typedef struct vector_case {
    unsigned function;
    double a[3], b[3], c[3], s;
    const char *miss; /* distancia_esfera: how the ray misses, or NULL */
} vector_case;

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

typedef struct ray_case {
    unsigned scene;
    double d[3]; /* normalised here */
} ray_case;

/* ej2.c: the tables and the float arguments of a case. */
extern const functions_function ej2_functions[F_COUNT];
extern const vector_case ej2_vector_cases[];
extern const size_t ej2_vector_case_count;
extern const scene ej2_scenes[];
extern const ray_case ej2_ray_cases[];
extern const size_t ej2_ray_case_count;
void ej2_case_args(const vector_case *v, double *a, double *b, double *c,
                   double *s);
const scene *ej2_scene_of(unsigned index, scene *whole);
void ej2_ray_args(const ray_case *rc, double *d, double *light,
                  double c[][3], double *r);
void ej2_describe_vector_case(unsigned k, char *out, size_t room);
void ej2_describe_ray_case(unsigned k, rayo_lang lang, char *out,
                           size_t room);

/* ej2_judge.c: judges function f from the log. */
rayo_status ej2_judge(grade_context *ctx, unsigned i, const char *log,
                      const int *usable, rayo_error *err);

#endif
