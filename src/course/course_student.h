/*
 * course_student.h - the student's program of exercises 2 and 3 as the
 * statements (ejercicios-2-y-3.md) have it written, in float: its vector
 * functions, its ray-sphere distance, and its computar_intensidad for
 * each exercise, each with one mistake that can be switched on.
 *
 * Float as the statements' types are (float[3], vector_t, color_t), each
 * operation its own statement so that no compiler fuses a multiply and
 * an add (x86-64 builds of student code do not either): the model's
 * rounding is the rounding of a typical submission built there, so its
 * images resemble students' bit for bit where rounding decides
 * (SELF_SHADOW), not only in shape.
 */
#ifndef RAYO_COURSE_STUDENT_H
#define RAYO_COURSE_STUDENT_H

#include <float.h>
#include <math.h>

#include "course_impl.h"

/* The statements' INFINITO. */
#define RAYO_COURSE_INFINITO FLT_MAX

typedef struct course_fvec {
    float x, y, z;
} course_fvec;

/* A sphere and a light as the student's program holds them. */
typedef struct course_fball {
    course_fvec center, color;
    float radius, ka, kd;
} course_fball;

typedef struct course_flamp {
    int point;
    course_fvec vector, color;
} course_flamp;

/* At most as many as the course's scenes have. */
#define COURSE_MAX_BALLS 32
#define COURSE_MAX_LAMPS 4

typedef struct course_student {
    course_fball balls[COURSE_MAX_BALLS];
    size_t ball_count;
    course_flamp lamps[COURSE_MAX_LAMPS];
    size_t lamp_count;
    course_fvec ambient; /* EJ2: IA in .x */
    rayo_course_mistake mistake;
    /* The pixel loop's column (-1: none) and, for the row, the columns
       span_lo[b] .. span_hi[b] outside which sphere b's delta is
       negative for a ray from the eye (row_may_hit): there
       rayo_course_student_nearest skips it, as it would find no root. */
    int pixel;
    int span_lo[COURSE_MAX_BALLS], span_hi[COURSE_MAX_BALLS];
} course_student;

static inline course_fvec course_fvec_make(float x, float y, float z)
{
    course_fvec v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

/* a - b (resta, vector_resta) */
static inline course_fvec course_fsub(course_fvec a, course_fvec b)
{
    return course_fvec_make(a.x - b.x, a.y - b.y, a.z - b.z);
}

/* producto_interno: a.x*b.x + a.y*b.y + a.z*b.z, left to right. */
static inline float course_fdot(course_fvec a, course_fvec b)
{
    float xx = a.x * b.x;
    float yy = a.y * b.y;
    float zz = a.z * b.z;
    float sum = xx + yy;
    return sum + zz;
}

/* norma: sqrt of the dot product (math.h's sqrt, rounded to float). */
static inline float course_fnorm(course_fvec a)
{
    return (float)sqrt((double)course_fdot(a, a));
}

/* normalizar: each component divided by the norm. */
static inline course_fvec course_fnormalize(course_fvec a)
{
    float n = course_fnorm(a);
    return course_fvec_make(a.x / n, a.y / n, a.z / n);
}

/* interpolar_recta: o + t d, component by component. */
static inline course_fvec course_fpoint(course_fvec o, course_fvec d,
                                        float t)
{
    float x = t * d.x;
    float y = t * d.y;
    float z = t * d.z;
    return course_fvec_make(o.x + x, o.y + y, o.z + z);
}

/*
 * distancia_esfera / esfera_distancia as the assignment's note derives
 * it: beta = (C - O).d, delta = beta^2 - (C - O).(C - O) + R^2; no hit
 * when delta < 0; t = beta - sqrt(delta) when that is > 0, else
 * beta + sqrt(delta) when that is, else INFINITO.  The root is kept in a
 * float (float raiz = sqrt(delta)), so beta -+ raiz is float arithmetic.
 * far_root (FAR_ROOT) is the student who tries beta + sqrt(delta) first.
 */
static inline float course_fdistance(const course_fball *ball, course_fvec o,
                                     course_fvec d, int far_root)
{
    course_fvec l = course_fsub(ball->center, o);
    float beta = course_fdot(l, d);
    float bb = beta * beta;
    float ll = course_fdot(l, l);
    float rr = ball->radius * ball->radius;
    float delta = bb - ll;
    float root, near_t, far_t;
    delta = delta + rr;
    if (delta < 0)
        return RAYO_COURSE_INFINITO;
    root = (float)sqrt((double)delta);
    near_t = beta - root;
    far_t = beta + root;
    if (!far_root && near_t > 0)
        return near_t;
    if (far_t > 0)
        return far_t;
    if (near_t > 0)
        return near_t;
    return RAYO_COURSE_INFINITO;
}

/* The program's constants: the statement's numbers written as float,
   with one mistake (course_student.c). */
void rayo_course_student_init(course_student *s, const rayo_course_data *data,
                              rayo_course_mistake mistake);

/* Marks in maybe[] (RAYO_COURSE_WIDTH bytes) the pixels of the row at
   height vy whose ray may meet some sphere, and sets s->span_lo and
   span_hi (course_student.c says how). */
void rayo_course_student_row_may_hit(course_student *s, double vy, double vz,
                                     int half_w, unsigned char *maybe);

/* The sphere the ray o + t d shows (the nearest, or with FIRST_SPHERE
   the first of the array it meets), its t in *t; ball_count if none. */
size_t rayo_course_student_nearest(const course_student *s, course_fvec o,
                                   course_fvec d, float *t);

/* 1 when the shadow ray from p along l meets a sphere at t < limit
   (skipping the sphere `self` unless SELF_SHADOW). */
int rayo_course_student_shadowed(const course_student *s, course_fvec p,
                                 course_fvec l, float limit, size_t self);

/* EJ2's computar_intensidad, then what main prints (0..255). */
unsigned char rayo_course_student_gray(const course_student *s,
                                       course_fvec d);

/* EJ3's computar_intensidad, then color_imprimir's three bytes. */
void rayo_course_student_color(const course_student *s, course_fvec d,
                               unsigned char rgb[3]);

#endif
