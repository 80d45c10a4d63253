/*
 * ej3_model.c - Ejercicio obligatorio 3's arithmetic, in double
 * precision on the float-rounded arguments its harness passes: a
 * case's arguments, a ray's scene (the course's scene 3 from the
 * course module), and computar_intensidad's colour as the statement's
 * formulas give it and as each modelled mistake (the course's
 * rayo_course_mistake) gives it.
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/course/course_scene.h"
#include "ej3.h"
#include "harness_math.h"

/* ---- arithmetic in double on float-rounded inputs (harness_math.h) ---- */

void ej3_sub(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

void ej3_value_args(const value_case *v, double *a, double *b, double *c,
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

/* Scene index as written (in double): the course's from its module. */
void ej3_scene_of(unsigned index, scene *s)
{
    const rayo_course_data *data = rayo_course_data_of(RAYO_COURSE_EJ3);
    size_t i;
    *s = ej3_scenes[index];
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
void ej3_ray_scene(const ray_case *rc, scene *s, double *d)
{
    size_t i;
    ej3_scene_of(rc->scene, s);
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



/* Whether sphere j blocks the ray from p along l before limit. */
int ej3_blocks(const sphere *s, const double *p, const double *l,
               double limit)
{
    double oc[3], beta, delta, root;
    ej3_sub(s->c, p, oc);
    beta = dot(oc, l);
    delta = beta * beta - dot(oc, oc) + s->r * s->r;
    if (delta < 0)
        return 0;
    root = beta - sqrt(delta) > 0 ? beta - sqrt(delta) : beta + sqrt(delta);
    return root > 0 && root < limit;
}

shading ej3_shade(const ray_case *rc, int m)
{
    scene s;
    double d[3], o[3] = {0, 0, 0}, best = INFINITY, p[3], n[3], c[3];
    double ka, kd;
    shading out;
    size_t i, j;
    memset(&out, 0, sizeof out);
    out.sphere = out.occluder = (size_t)-1;
    ej3_ray_scene(rc, &s, d);
    for (i = 0; i < s.spheres; i++) {
        double t = sphere_t(s.s[i].c, s.s[i].r, o, d, m == RAYO_MISTAKE_FAR_ROOT);
        if (t == INFINITY)
            continue;
        if (m == RAYO_MISTAKE_FIRST_SPHERE ? out.sphere == (size_t)-1
                                : m == RAYO_MISTAKE_LAST_SPHERE || t < best) {
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
               (m == RAYO_MISTAKE_UNNORMALISED_NORMAL ? 1 : s.s[i].r);
    }
    ka = m == RAYO_MISTAKE_KA_KD_SWAPPED ? s.s[i].kd : s.s[i].ka;
    kd = m == RAYO_MISTAKE_KA_KD_SWAPPED ? s.s[i].ka : s.s[i].kd;
    for (j = 0; j < 3; j++)
        c[j] = m == RAYO_MISTAKE_NO_AMBIENT || m == RAYO_MISTAKE_AMBIENT_NOT_ABSORBED
                   ? 0
                   : s.ambient[j] * ka;
    for (j = 0; j < s.lights; j++) {
        const light *lamp = &s.l[j];
        double l[3], shadow_l[3], limit = INFINITY, ln;
        size_t k;
        int shadowed = 0;
        if (lamp->point && m == RAYO_MISTAKE_POINT_AS_DIRECTIONAL) {
            unit(lamp->v, l);
        } else if (lamp->point) {
            ej3_sub(lamp->v, p, l);
            limit = sqrt(dot(l, l));
            if (m != RAYO_MISTAKE_UNNORMALISED_LIGHT)
                unit(l, l);
        } else {
            memcpy(l, lamp->v, sizeof l);
        }
        if (m == RAYO_MISTAKE_LIGHT_REVERSED)
            for (k = 0; k < 3; k++)
                l[k] = -l[k];
        unit(l, shadow_l);
        if (m == EJ3_BEYOND_LIGHT || m == RAYO_MISTAKE_POINT_AS_DIRECTIONAL)
            limit = INFINITY;
        ln = dot(l, n);
        if (ln <= 0 && m != RAYO_MISTAKE_NO_LN_TEST)
            continue;
        if (m == RAYO_MISTAKE_SELF_SHADOW)
            continue;
        for (k = 0; k < s.spheres && m != RAYO_MISTAKE_NO_SHADOWS && !shadowed; k++)
            if (k != i && ej3_blocks(&s.s[k], p, shadow_l, limit)) {
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
        if (m == RAYO_MISTAKE_AMBIENT_NOT_ABSORBED)
            out.c[j] += s.ambient[j] * ka;
    }
    return out;
}

/* Channels above 1 print as 255, so they compare as 1. */
int ej3_same_colour(const double *got, const double *want)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        double g = got[k] > 1 ? 1 : got[k], w = want[k] > 1 ? 1 : want[k];
        if (fabs(g - w) > 2e-3)
            return 0;
    }
    return 1;
}

