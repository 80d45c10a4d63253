/*
 * ej3_rays.c - judging Ejercicio obligatorio 3's computar_intensidad:
 * each wrong colour is compared with what every modelled mistake gives
 * (ej3_model.c), and the mistake that agrees with it, and best with
 * the other results, is named in the statement's terms.
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

static void colour_text(const double *c, char *out, size_t room)
{
    snprintf(out, room, "(%.3g, %.3g, %.3g)", c[0], c[1], c[2]);
}

static void sphere_text(const ray_case *rc, size_t i, char *out,
                        size_t room)
{
    scene whole;
    const sphere *s = &whole.s[i];
    ej3_scene_of(rc->scene, &whole);
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
    for (c = 0; c < ej3_ray_case_count; c++)
        for (k = M_NONE + 1; k < M_COUNT; k++)
            score[k] += ej3_same_colour(got[c], ej3_shade(&ej3_ray_cases[c],
                                                          k).c);
}

/* The mistake that gives got for this case (and not the right colour)
   and agrees with the most results overall; M_COUNT when none does. */
static int ray_mistake(const ray_case *rc, const double *got,
                       const unsigned *score)
{
    shading want = ej3_shade(rc, M_NONE);
    int k, best = M_COUNT;
    for (k = M_NONE + 1; k < M_COUNT; k++) {
        shading m = ej3_shade(rc, k);
        if (!ej3_same_colour(m.c, want.c) && ej3_same_colour(got, m.c) &&
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
    const ray_case *rc = &ej3_ray_cases[c];
    shading want = ej3_shade(rc, M_NONE), m;
    char call[512], g[64], w[64], x[128], y[128];
    ej3_describe_ray_case(c, call, sizeof call);
    colour_text(got, g, sizeof g);
    colour_text(want.c, w, sizeof w);
    if (k == M_COUNT)
        return ej3_wrong_line(j, err, "%s returned %s; expected %s", call, g,
                              w);
    m = ej3_shade(rc, k);
    if (k == M_FIRST_SPHERE || k == M_LAST_SPHERE) {
        sphere_text(rc, m.sphere, x, sizeof x);
        sphere_text(rc, want.sphere, y, sizeof y);
        return ej3_wrong_line(j, err, "%s returned %s, the colour of %s, the "
                                  "%s sphere in the array the ray hits, not "
                                  "the nearest (%s, %s): keep the smallest "
                                  "t",
                          call, g, x, k == M_FIRST_SPHERE ? "first" : "last",
                          y, w);
    }
    if (k == M_FAR_ROOT) {
        sphere_text(rc, want.sphere, x, sizeof x);
        return ej3_wrong_line(j, err, "%s returned %s, the colour at the far "
                                  "side of %s; expected %s: the ray meets "
                                  "it first at t = beta - sqrt(delta)",
                          call, g, x, w);
    }
    if (k == M_NO_SHADOWS || k == M_BEYOND_LIGHT) {
        sphere_text(rc, k == M_NO_SHADOWS ? want.occluder : m.occluder, x,
                    sizeof x);
        return ej3_wrong_line(j, err, "%s returned %s; expected %s: %s %s",
                          call, g, w, x, mistake_texts[k]);
    }
    return ej3_wrong_line(j, err, "%s returned %s; expected %s: %s", call, g,
                          w,
                      mistake_texts[k]);
}

rayo_status ej3_judge_rays(judging *j, rayo_error *err)
{
    double got[ej3_ray_case_count][3];
    char call[512], line[1024];
    unsigned c, said = 0, score[M_COUNT];
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
            if (said & (1u << (M_COUNT + 1))) {
                j->wrong++;
                j->unsaid++;
                continue;
            }
            said |= 1u << (M_COUNT + 1);
            ej3_describe_ray_case(c, call, sizeof call);
            harness_not_finite(call, got[c], 3, HARNESS_NAN_SHADING, NULL,
                               line, sizeof line);
            status = ej3_wrong_line(j, err, "%s", line);
            continue;
        }
        if (ej3_same_colour(got[c], ej3_shade(rc, M_NONE).c)) {
            if (!ej3_same_colour(ej3_shade(rc, M_NONE).c,
                             ej3_shade(rc, M_BEYOND_LIGHT).c))
                j->between_only = 1; /* the other reading, named too */
            continue;
        }
        if (ej3_same_colour(got[c], ej3_shade(rc, M_BEYOND_LIGHT).c)) {
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

