/*
 * ej3_rays.c - judging Ejercicio obligatorio 3's computar_intensidad:
 * each wrong colour is compared with what every modelled mistake gives
 * (ej3_model.c), and the mistake that agrees with it, and best with
 * the other results, is named with the course's sentence
 * (rayo_course_mistake_text_lang).
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ej3.h"
#include "harness_math.h"

/* The course's mistakes of computar_intensidad that ej3_shade models,
   and the reading EJ3_BEYOND_LIGHT, in the order that breaks a tie
   between two that agree as well. */
static const int modelled[] = {
    RAYO_MISTAKE_FIRST_SPHERE,     RAYO_MISTAKE_LAST_SPHERE,
    RAYO_MISTAKE_FAR_ROOT,         RAYO_MISTAKE_NO_SHADOWS,
    EJ3_BEYOND_LIGHT,              RAYO_MISTAKE_NO_LN_TEST,
    RAYO_MISTAKE_LIGHT_REVERSED,   RAYO_MISTAKE_NO_AMBIENT,
    RAYO_MISTAKE_AMBIENT_NOT_ABSORBED, RAYO_MISTAKE_KA_KD_SWAPPED,
    RAYO_MISTAKE_POINT_AS_DIRECTIONAL, RAYO_MISTAKE_UNNORMALISED_LIGHT,
    RAYO_MISTAKE_UNNORMALISED_NORMAL,  RAYO_MISTAKE_SELF_SHADOW};
#define MODELLED (sizeof modelled / sizeof modelled[0])
#define NAN_SAID (EJ3_NO_MODEL + 1) /* the said bit of a NaN */

static void colour_text(const double *c, char *out, size_t room)
{
    snprintf(out, room, "(%.3g, %.3g, %.3g)", c[0], c[1], c[2]);
}

/* Sphere i's centre and colour, as two vectors "(x, y, z)". */
static void sphere_text(const ray_case *rc, size_t i, char *at,
                        char *colour, size_t room)
{
    scene whole;
    const sphere *s = &whole.s[i];
    ej3_scene_of(rc->scene, &whole);
    snprintf(at, room, "(%g, %g, %g)", s->c[0], s->c[1], s->c[2]);
    snprintf(colour, room, "(%g, %g, %g)", s->color[0], s->color[1],
             s->color[2]);
}

/* How many of the results each modelled mistake agrees with. */
static void mistake_scores(double got[][3], unsigned *score)
{
    unsigned c, i;
    for (i = 0; i < EJ3_NO_MODEL; i++)
        score[i] = 0;
    for (c = 0; c < ej3_ray_case_count; c++)
        for (i = 0; i < MODELLED; i++)
            score[modelled[i]] += ej3_same_colour(
                got[c], ej3_shade(&ej3_ray_cases[c], modelled[i]).c);
}

/* The mistake that gives got for this case (and not the right colour)
   and agrees with the most results overall; EJ3_NO_MODEL when none
   does. */
static int ray_mistake(const ray_case *rc, const double *got,
                       const unsigned *score)
{
    shading want = ej3_shade(rc, RAYO_MISTAKE_NONE);
    int best = EJ3_NO_MODEL;
    unsigned i;
    for (i = 0; i < MODELLED; i++) {
        int k = modelled[i];
        shading m = ej3_shade(rc, k);
        if (!ej3_same_colour(m.c, want.c) && ej3_same_colour(got, m.c) &&
            (best == EJ3_NO_MODEL || score[k] > score[best]))
            best = k;
    }
    return best;
}

/* The facts of one wrong colour, then the course's sentence for
   mistake k. */
static rayo_status say_ray(judging *j, unsigned c, const double *got,
                           int k, rayo_error *err)
{
    const ray_case *rc = &ej3_ray_cases[c];
    shading want = ej3_shade(rc, RAYO_MISTAKE_NONE), m;
    const char *why;
    char call[512], g[64], w[64], x[64], xc[64], y[64], yc[64];
    ej3_describe_ray_case(c, rayo_error_lang(err), call, sizeof call);
    colour_text(got, g, sizeof g);
    colour_text(want.c, w, sizeof w);
    if (k >= EJ3_BEYOND_LIGHT)
        return ej3_wrong_line(j, err, "%s returned %s; expected %s", call, g,
                              w);
    m = ej3_shade(rc, k);
    why = rayo_course_mistake_text_lang(RAYO_COURSE_EJ3,
                                        (rayo_course_mistake)k,
                                        rayo_error_lang(err));
    if (k == RAYO_MISTAKE_FIRST_SPHERE || k == RAYO_MISTAKE_LAST_SPHERE) {
        sphere_text(rc, m.sphere, x, xc, sizeof x);
        sphere_text(rc, want.sphere, y, yc, sizeof y);
        return ej3_wrong_line(j, err, "%s returned %s, the colour of the "
                                      "sphere at %s of colour %s; expected "
                                      "%s, the colour of the nearest one, "
                                      "at %s of colour %s: %s",
                              call, g, x, xc, w, y, yc, why);
    }
    if (k == RAYO_MISTAKE_FAR_ROOT) {
        sphere_text(rc, want.sphere, x, xc, sizeof x);
        return ej3_wrong_line(j, err, "%s returned %s, the colour at the far "
                                      "side of the sphere at %s of colour "
                                      "%s; expected %s: %s",
                              call, g, x, xc, w, why);
    }
    if (k == RAYO_MISTAKE_NO_SHADOWS) {
        sphere_text(rc, want.occluder, x, xc, sizeof x);
        return ej3_wrong_line(j, err, "%s returned %s; expected %s, as the "
                                      "sphere at %s of colour %s lies "
                                      "between the point and a light: %s",
                              call, g, w, x, xc, why);
    }
    return ej3_wrong_line(j, err, "%s returned %s; expected %s: %s", call, g,
                          w, why);
}

rayo_status ej3_judge_rays(judging *j, rayo_error *err)
{
    double got[ej3_ray_case_count][3];
    char call[512], line[1024];
    unsigned c, said = 0, score[EJ3_NO_MODEL];
    rayo_status status = RAYO_OK;
    for (c = 0; c < ej3_ray_case_count; c++) {
        double v[4];
        if (harness_result(j->log, "computar_intensidad", c, v, 4) != 4)
            return RAYO_ERR_CANCELLED;
        memcpy(got[c], v + 1, sizeof got[c]);
    }
    mistake_scores(got, score);
    for (c = 0; c < ej3_ray_case_count && status == RAYO_OK; c++) {
        const ray_case *rc = &ej3_ray_cases[c];
        int mistake;
        j->cases++;
        if (harness_not_finite("", got[c], 3, "", NULL, line, sizeof line)) {
            if (said & (1u << NAN_SAID)) {
                j->wrong++;
                j->unsaid++;
                continue;
            }
            said |= 1u << (NAN_SAID);
            ej3_describe_ray_case(c, rayo_error_lang(err), call, sizeof call);
            harness_not_finite(call, got[c], 3, HARNESS_NAN_SHADING, NULL,
                               line, sizeof line);
            status = ej3_wrong_line(j, err, "%s", line);
            continue;
        }
        if (ej3_same_colour(got[c], ej3_shade(rc, RAYO_MISTAKE_NONE).c)) {
            if (!ej3_same_colour(ej3_shade(rc, RAYO_MISTAKE_NONE).c,
                             ej3_shade(rc, EJ3_BEYOND_LIGHT).c))
                j->between_only = 1; /* the other reading, named too */
            continue;
        }
        if (ej3_same_colour(got[c], ej3_shade(rc, EJ3_BEYOND_LIGHT).c)) {
            j->beyond_light = 1; /* a reading,
                accepted: ej3_judge() names it */
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

