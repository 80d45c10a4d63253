/*
 * harness_math.h - the arithmetic the functions criterion's expected
 * values are computed with (ej2*.c, ej3*.c): double
 * precision on arguments rounded to float as the student's call rounds
 * them, the tolerance a float result is held to, and a vector in a
 * reason line.  Private to src/grade.
 */
#ifndef RAYO_HARNESS_MATH_H
#define RAYO_HARNESS_MATH_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>

/* x as the student's float holds it.  Through a volatile float: gcc 12
   at -O2 vectorised two neighbouring (double)(float) conversions into
   plain divisions, dropping the rounding (clang kept it). */
static inline double fl(double x)
{
    volatile float f = (float)x;
    return f;
}

static inline void vfl(const double *in, double *out)
{
    out[0] = fl(in[0]);
    out[1] = fl(in[1]);
    out[2] = fl(in[2]);
}

static inline double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void unit(const double *in, double *out)
{
    double n = sqrt(dot(in, in));
    out[0] = in[0] / n;
    out[1] = in[1] / n;
    out[2] = in[2] / n;
}

/* The t at which the ray o + t d (d a unit vector) meets the sphere
   (c, r): the near root when > 0, else the far one, else INFINITY;
   far: the far root only. */
static inline double sphere_t(const double *c, double r, const double *o,
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

/* A float result within 1e-5 + 1e-4 relative of the expected value. */
static inline int near_value(double got, double want)
{
    return fabs(got - want) <= 1e-5 + 1e-4 * fabs(want);
}

static inline int near_vector(const double *got, const double *want)
{
    return near_value(got[0], want[0]) && near_value(got[1], want[1]) &&
           near_value(got[2], want[2]);
}

/* The statement's INFINITO, FLT_MAX, as a double read back. */
static inline int is_infinito(double v)
{
    return fabs(v / FLT_MAX - 1) < 1e-6;
}

/* "(x, y, z)" with 7 significant digits into out. */
static inline const char *vec_text(const double *v, char *out, size_t room)
{
    snprintf(out, room, "(%.7g, %.7g, %.7g)", v[0], v[1], v[2]);
    return out;
}

#endif
