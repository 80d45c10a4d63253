/*
 * hit_spans_impl.h - what the span fast path's two files share: the
 * plan of a frame, made once (hit_spans_plan.c), and the rows traced
 * from it (hit_spans.c, where the error bounds below are argued).
 * Private to src/render.
 */
#ifndef RAYO_HIT_SPANS_IMPL_H
#define RAYO_HIT_SPANS_IMPL_H

#include "hit_spans.h"

#include <float.h>

#include "rayo/sphere.h"

#define UNIT_ROUNDOFF (DBL_EPSILON / 2)
/* E and T (hit_spans.c), in units of UNIT_ROUNDOFF * (l.l + R^2). */
#define DELTA_ERROR 512.0
#define ESTIMATE_ERROR 512.0
/* Bound on the rounding of D and N, in units of u |l| |a|^i |b|^j. */
#define PEAK_ERROR 64.0
/* Where a row's hits go: its runs, while they suffice, else its bits. */
typedef struct row_target {
    unsigned char *bits;
    rayo_row_runs *runs; /* NULL when the row is in its bits */
} row_target;

typedef struct row_frame {
    const rayo_camera *camera;
    uint32_t row;
    int64_t width;
    double half_width;
    double a2, ab, b2; /* a.a, a.b, b.b */
    rayo_vec3 b;
    row_target *target;
} row_frame;

typedef struct sphere_row {
    const rayo_sphere *sphere;
    double length;         /* |l| */
    double p, q, k;        /* l.a, l.b, l.l - R^2 */
    double surely_hit;     /* E + T */
    double surely_missed;  /* -(E + 3T) */
    double hit_level;      /* k + surely_hit */
    double miss_level;     /* k + surely_missed */
} sphere_row;

/* A sphere's span on the row before, where rows are rendered in bands:
 * the first and last pixel hit, or first > last when that row had none
 * that tracking can start from. */
typedef struct span_hint {
    int64_t first, last;
} span_hint;

/* What a sphere's rows share, worked out once a frame. */
typedef enum sphere_kind {
    SPHERE_OUTSIDE, /* seen from outside: spans */
    SPHERE_AROUND,  /* the camera is inside: every pixel hits */
    SPHERE_NEAR,    /* the camera is within the error bounds of its
                       surface, or the bounds overflow: every pixel is
                       tested */
} sphere_kind;

typedef struct sphere_frame {
    sphere_kind kind;
    rayo_vec3 l;     /* C - O */
    sphere_row row;  /* all but q, which depends on the row */
} sphere_frame;

struct rayo_hit_spans {
    const rayo_camera *camera;
    double a2;         /* a.a */
    double half_width; /* floor(width / 2), as a double */
    double half_height;
    rayo_vec3 ahead;   /* forward * focal: b = ahead - y up */
    size_t count;
    sphere_frame *spheres;
};

/* The error bounds and levels of one sphere (plan_sphere's), and
 * whether spans apply to it. */
void hit_spans_plan_sphere(const rayo_camera *camera,
                           const rayo_sphere *sphere, sphere_frame *frame);

#endif
