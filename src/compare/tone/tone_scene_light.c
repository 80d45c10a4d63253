/*
 * tone_scene_light.c - where the gray scene's one light seems to come
 * from, read from the shading of a student's image: on the pixels of
 * the spheres that the light reaches (above IA, below the clamp at
 * 255), I = IA + II (L.N) is linear in L, so L is the least-squares fit
 * of (I - IA) / II against each pixel's normal (worked out here from
 * the scene's sphere and the pixel's ray).  It is named only when it
 * explains those pixels much better than the statement's light, and is
 * a direction (about a unit vector: a changed II is tone_scene.c's
 * finding, not this one).  The colour scene's directional light
 * (EJ3) the same way, once Ia ka and the point lights (the
 * statement's) are taken off each channel.  Not for the point lights
 * (tone_scene_lamps.c).
 */
#include <math.h>

#include "tone_scene.h"

/* Fewest lit pixels a fit stands on. */
#define FIT_MIN 500
/* The fit's error (levels, RMS) at most this, the statement's at least
   FIT_BETTER times it and FIT_OFF levels, the two directions this far
   apart (cosine), and the fitted L this near unit length. */
#define FIT_RMS 3.0
#define FIT_BETTER 4.0
#define FIT_OFF 8.0
#define FIT_COS 0.998
#define FIT_UNIT 0.1
/* The colour scene: spheres with kd at least this are read, where the
   directional light adds this many levels more than the comparison's
   own (noise of a level or two over a shadow is not lit). */
#define SUN_KD 0.1
#define SUN_LIT 3

int tone_scene_surface(const scene_work *w, int b, uint32_t i, uint32_t j,
                       double *at, double *n)
{
    const rayo_course_ball *ball = &w->data->balls[b];
    double d[3], len, dc = 0, cc = 0, disc, t;
    unsigned k;
    d[0] = (double)i - w->map->width / 2.0;
    d[1] = w->map->height / 2.0 - (double)j;
    d[2] = w->map->focal;
    len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (k = 0; k < 3; k++) {
        d[k] /= len;
        dc += d[k] * ball->center[k];
        cc += ball->center[k] * ball->center[k];
    }
    disc = dc * dc - (cc - ball->radius * ball->radius);
    if (disc < 0)
        return 0;
    t = dc - sqrt(disc);
    for (k = 0; k < 3; k++) {
        n[k] = (t * d[k] - ball->center[k]) / ball->radius;
        if (at != NULL)
            at[k] = t * d[k];
    }
    return 1;
}

int tone_scene_solve3(double a[3][3], const double *y, double *x)
{
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                 a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    unsigned c, r;
    if (fabs(det) < 1e-9)
        return 0;
    for (c = 0; c < 3; c++) {
        double m[3][3], d;
        for (r = 0; r < 3; r++) {
            m[r][0] = a[r][0];
            m[r][1] = a[r][1];
            m[r][2] = a[r][2];
            m[r][c] = y[r];
        }
        d = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        x[c] = d / det;
    }
    return 1;
}

/* The pixels the fit reads: on a sphere still drawn, lit in the image
   (a level or two above IA) and not clamped. */
static int fit_pixel(const scene_work *w, size_t p, double ia, double *n)
{
    const rayo_course_map *m = w->map;
    int b = m->ball[p];
    double v = w->image->v[p];
    if (!m->core[p] || b < 0 || w->gone[b] || v >= 255 ||
        v <= ia + w->levels + 1)
        return 0;
    return tone_scene_surface(w, b, (uint32_t)(p % m->width),
                              (uint32_t)(p / m->width), NULL, n);
}

/* The fitted L named when it fits (fit, stated: the sums of squares of
   the fit's and the statement's errors on total values, close of them
   within the levels and 1) much better than the statement's ls, is
   about unit length and away from ls; 1 when named. */
static int name_direction(scene_work *w, const double *l, const double *ls,
                          double fit, double stated, uint64_t total,
                          uint64_t close)
{
    double len, dot;
    rayo_compare_finding *f;
    unsigned c;
    fit = sqrt(fit / (double)total);
    stated = sqrt(stated / (double)total);
    len = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    dot = (l[0] * ls[0] + l[1] * ls[1] + l[2] * ls[2]) / len;
    if (fit > FIT_RMS || stated < FIT_BETTER * fit || stated < FIT_OFF ||
        fabs(len - 1) > FIT_UNIT || dot > FIT_COS)
        return 0;
    f = tone_scene_add(w->r, RAYO_FINDING_LIGHT_DIRECTION);
    if (f == NULL)
        return 0;
    for (c = 0; c < 3; c++) {
        f->value[c] = l[c] / len;
        if (fabs(f->value[c]) < 0.005)
            f->value[c] = 0; /* no -0.00 */
        f->expected[c] = ls[c];
    }
    f->pixels = close;
    f->total = total;
    return 1;
}

int tone_scene_light_direction(scene_work *w)
{
    const rayo_course_map *m = w->map;
    const double *ls = w->data->lamps[0].vector;
    size_t pixels = (size_t)m->width * m->height, p, i;
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, y[3] = {0, 0, 0};
    double l[3], n[3], ia = w->data->ambient[0];
    double ii = w->data->lamps[0].color[0], fit = 0, stated = 0;
    uint64_t total = 0, close = 0;
    unsigned r, c;
    if (!w->gray || w->data->lamp_count != 1 ||
        w->data->lamps[0].point)
        return 0;
    for (i = 0; i < w->r->tone.findings; i++)
        if (w->r->tone.finding[i].kind == RAYO_FINDING_AMBIENT)
            ia = w->r->tone.finding[i].value[0];
    for (p = 0; p < pixels; p++) {
        double v;
        if (!fit_pixel(w, p, ia, n))
            continue;
        v = (w->image->v[p] + 0.5 - ia) / ii; /* (int) cut the level */
        for (r = 0; r < 3; r++) {
            for (c = 0; c < 3; c++)
                a[r][c] += n[r] * n[c];
            y[r] += n[r] * v;
        }
        total++;
    }
    if (total < FIT_MIN || !tone_scene_solve3(a, y, l))
        return 0;
    for (p = 0; p < pixels; p++) {
        double v, e, s;
        float lit;
        if (!fit_pixel(w, p, ia, n))
            continue;
        v = w->image->v[p] + 0.5 - ia;
        e = v - ii * (l[0] * n[0] + l[1] * n[1] + l[2] * n[2]);
        lit = m->light[p];
        s = v - (lit > 0 ? ii * lit : 0);
        fit += e * e;
        stated += s * s;
        close += fabs(e) <= w->levels + 1;
    }
    return name_direction(w, l, ls, fit, stated, total, close);
}

/* The colour scene (EJ3): pixel p's channel c, once Ia ka and the
   point lights (the map's L.N and shadows, the statement's Ii) are
   taken off, over kd Ii of the directional light `sun`: its L.N; 0
   when p is not read (not lit by it in the image, or clamped). */
static int sun_pixel(const scene_work *w, size_t p, size_t sun, unsigned c,
                     double *n, double *term, double *scale)
{
    const rayo_course_map *m = w->map;
    const rayo_course_ball *ball = tone_scene_unclamped(w, p, c);
    int b = m->ball[p];
    double v = w->image->v[p * w->n + c], rest;
    if (ball == NULL)
        return 0;
    if (ball->color[c] != 1 || ball->kd < SUN_KD ||
        w->data->lamps[sun].color[c] <= 0)
        return 0;
    rest = tone_scene_rest(w, p, b, c, sun);
    *scale = 255 * ball->kd * w->data->lamps[sun].color[c];
    *term = 255 * ((v + 0.5) / 255 - rest);
    if (*term <= w->levels + 1 + SUN_LIT)
        return 0;
    *term /= *scale;
    return tone_scene_surface(w, b, (uint32_t)(p % m->width),
                              (uint32_t)(p / m->width), NULL, n);
}

int tone_scene_sun_direction(scene_work *w)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p, i, sun = 0, suns = 0;
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, y[3] = {0, 0, 0};
    double l[3], n[3], fit = 0, stated = 0, term, scale;
    const double *ls;
    uint64_t total = 0, close = 0;
    unsigned r, c, k;
    if (w->gray || w->n != 3)
        return 0;
    for (i = 0; i < w->r->tone.findings; i++)
        if (w->r->tone.finding[i].kind == RAYO_FINDING_AMBIENT ||
            w->r->tone.finding[i].kind == RAYO_FINDING_LAMP_POSITION ||
            w->r->tone.finding[i].kind == RAYO_FINDING_LAMP_COLOUR ||
            w->r->tone.finding[i].kind == RAYO_FINDING_LAMP_MISSING)
            return 0; /* the rest of the model is not the statement's */
    for (i = 0; i < w->data->lamp_count; i++)
        if (!w->data->lamps[i].point) {
            sun = i;
            suns++;
        }
    if (suns != 1)
        return 0;
    ls = w->data->lamps[sun].vector;
    for (p = 0; p < pixels; p++)
        for (c = 0; c < 3; c++) {
            if (!sun_pixel(w, p, sun, c, n, &term, &scale))
                continue;
            for (r = 0; r < 3; r++) {
                for (k = 0; k < 3; k++)
                    a[r][k] += n[r] * n[k];
                y[r] += n[r] * term;
            }
            total++;
        }
    if (total < FIT_MIN || !tone_scene_solve3(a, y, l))
        return 0;
    for (p = 0; p < pixels; p++)
        for (c = 0; c < 3; c++) {
            double e, s;
            float lit;
            if (!sun_pixel(w, p, sun, c, n, &term, &scale))
                continue;
            e = scale * (term - (l[0] * n[0] + l[1] * n[1] + l[2] * n[2]));
            lit = m->light[p * m->lamp_count + sun];
            s = scale * (term - (lit > 0 ? lit : 0));
            fit += e * e;
            stated += s * s;
            close += fabs(e) <= w->levels + 1;
        }
    return name_direction(w, l, ls, fit, stated, total, close);
}
