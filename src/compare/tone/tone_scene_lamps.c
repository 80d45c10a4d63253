/*
 * tone_scene_lamps.c - where a point light of the colour scene (EJ3)
 * seems to be, read from the channel it lights in a student's image.
 * Each of scene 3's point lights is the only one of its colour, so on
 * the pixels of a sphere whose M and kd let that channel through, what
 * is left of the value (away from the clamp at 255, which noise may
 * pull a level or two below) once Ia ka and the other lights (the map's L.N
 * and shadows) are taken off is Ii kd (L.N), L towards the light.  With
 * d = |P - X| held, P.N = X.N + d (L.N) is linear in the light's place
 * P: the fit is that, refitted a few times from the statement's place.
 * It is named only when it explains those pixels much better than the
 * statement's light and is well away from it.  Not for the gray scene
 * (tone_scene_light.c), nor for a light's colour or a light left out
 * (tone_scene_lamp_colour.c, whose finding comes first), nor for the
 * directional light.
 */
#include <math.h>

#include "tone_scene.h"

/* Fewest pixels a fit stands on, and how many times it is refitted. */
#define LAMP_MIN 500
#define LAMP_ROUNDS 20
/* A pixel is read when the light adds this many levels more than the
   comparison's own to it, and on spheres with kd at least LAMP_KD. */
#define LAMP_LIT 3
#define LAMP_KD 0.1
/* The fit's error (levels, RMS) at most this, the statement's at least
   LAMP_BETTER times it and LAMP_OFF levels, and the two places this far
   apart (the statement's units). */
#define LAMP_RMS 3.0
#define LAMP_BETTER 4.0
#define LAMP_OFF 8.0
#define LAMP_APART 0.5

/* The light's term pixel p shows on channel c: (L.N) once the rest of
   the model is taken off; 0 when p is not read. */
static int lamp_term(const scene_work *w, size_t p, size_t lamp, unsigned c,
                     double *at, double *n, double *term)
{
    const rayo_course_map *m = w->map;
    const rayo_course_lamp *lamps = w->data->lamps;
    const rayo_course_ball *ball = tone_scene_unclamped(w, p, c);
    int b = m->ball[p];
    double v = w->image->v[p * w->n + c], rest;
    if (ball == NULL)
        return 0;
    if (ball->color[c] != 1 || ball->kd < LAMP_KD)
        return 0;
    rest = tone_scene_rest(w, p, b, c, lamp);
    *term = (v + 0.5) / 255 - rest;
    if (255 * *term <= w->levels + LAMP_LIT)
        return 0;
    *term /= ball->kd * lamps[lamp].color[c];
    return tone_scene_surface(w, b, (uint32_t)(p % m->width),
                              (uint32_t)(p / m->width), at, n);
}

/* One round: P from the pixels, with each pixel's distance to the
   light taken at the last P. */
static int refit(const scene_work *w, size_t lamp, unsigned c, double *pos)
{
    size_t pixels = (size_t)w->map->width * w->map->height, p;
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, y[3] = {0, 0, 0};
    double at[3], n[3], term;
    unsigned r, k;
    for (p = 0; p < pixels; p++) {
        double d = 0, xn = 0;
        if (!lamp_term(w, p, lamp, c, at, n, &term))
            continue;
        for (k = 0; k < 3; k++) {
            d += (pos[k] - at[k]) * (pos[k] - at[k]);
            xn += at[k] * n[k];
        }
        for (r = 0; r < 3; r++) {
            for (k = 0; k < 3; k++)
                a[r][k] += n[r] * n[k];
            y[r] += n[r] * (xn + sqrt(d) * term);
        }
    }
    return tone_scene_solve3(a, y, pos);
}

/* L.N at `at` for a light at pos (0 where it faces away). */
static double facing(const double *pos, const double *at, const double *n)
{
    double l[3], len = 0, dot = 0;
    unsigned k;
    for (k = 0; k < 3; k++) {
        l[k] = pos[k] - at[k];
        len += l[k] * l[k];
    }
    len = sqrt(len);
    for (k = 0; k < 3; k++)
        dot += l[k] * n[k] / len;
    return dot > 0 ? dot : 0;
}

/* Lamp `lamp` on channel c: 1 when its place is named. */
static int lamp_place(scene_work *w, size_t lamp, unsigned c)
{
    const rayo_course_lamp *stated = &w->data->lamps[lamp];
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p;
    double pos[3], at[3], n[3], term, fit = 0, off = 0, apart = 0;
    uint64_t total = 0, close = 0;
    unsigned k, round;
    for (k = 0; k < 3; k++)
        pos[k] = stated->vector[k];
    for (round = 0; round < LAMP_ROUNDS; round++)
        if (!refit(w, lamp, c, pos))
            return 0;
    for (p = 0; p < pixels; p++) {
        const rayo_course_ball *ball;
        double scale, e, s;
        float f;
        if (!lamp_term(w, p, lamp, c, at, n, &term))
            continue;
        ball = &w->data->balls[m->ball[p]];
        scale = 255 * ball->kd * stated->color[c];
        f = m->light[p * m->lamp_count + lamp];
        e = scale * (term - facing(pos, at, n));
        s = scale * (term - (f > 0 ? f : 0));
        fit += e * e;
        off += s * s;
        close += fabs(e) <= w->levels + 1;
        total++;
    }
    if (total < LAMP_MIN)
        return 0;
    fit = sqrt(fit / (double)total);
    off = sqrt(off / (double)total);
    for (k = 0; k < 3; k++)
        apart += (pos[k] - stated->vector[k]) * (pos[k] - stated->vector[k]);
    if (fit > LAMP_RMS || off < LAMP_BETTER * fit || off < LAMP_OFF ||
        sqrt(apart) < LAMP_APART)
        return 0;
    {
        rayo_compare_finding *f = tone_scene_add(w->r,
                                              RAYO_FINDING_LAMP_POSITION);
        if (f == NULL)
            return 0;
        for (k = 0; k < 3; k++) {
            f->value[k] = fabs(pos[k]) < 0.05 ? 0 : pos[k]; /* no -0.0 */
            f->expected[k] = stated->vector[k];
        }
        f->box[0] = (int32_t)lamp;
        f->pixels = close;
        f->total = total;
    }
    return 1;
}

int tone_scene_lamp_channel(const scene_work *w, size_t l, unsigned *channel)
{
    const rayo_course_lamp *lamp = &w->data->lamps[l];
    unsigned c, lit = 0;
    if (!lamp->point)
        return 0;
    for (c = 0; c < 3; c++)
        if (lamp->color[c] > 0) {
            lit++;
            *channel = c;
        }
    return lit == 1;
}

int tone_scene_lamps_readable(const scene_work *w)
{
    size_t i;
    if (w->gray || w->n != 3)
        return 0;
    for (i = 0; i < w->r->tone.findings; i++)
        if (w->r->tone.finding[i].kind == RAYO_FINDING_AMBIENT)
            return 0;
    return 1;
}

int tone_scene_lamp_position(scene_work *w)
{
    size_t l, named = 0, i;
    if (!tone_scene_lamps_readable(w))
        return 0;
    for (l = 0; l < w->data->lamp_count; l++) {
        unsigned only = 0;
        int explained = 0;
        for (i = 0; i < w->r->tone.findings; i++)
            if ((w->r->tone.finding[i].kind == RAYO_FINDING_LAMP_COLOUR ||
                 w->r->tone.finding[i].kind == RAYO_FINDING_LAMP_MISSING) &&
                w->r->tone.finding[i].box[0] == (int32_t)l)
                explained = 1; /* its colour explains it */
        if (!explained && tone_scene_lamp_channel(w, l, &only))
            named += (size_t)lamp_place(w, l, only);
    }
    return named > 0;
}
