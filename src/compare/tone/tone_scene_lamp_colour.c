/*
 * tone_scene_lamp_colour.c - the colour Ii a point light of the colour
 * scene (EJ3) seems to have in a student's image, and a light left out.
 * Each of scene 3's point lights is the only one of its colour, so on
 * the pixels of a sphere whose M and kd let that channel through and
 * that the statement's light reaches (the map's L.N and shadows), what
 * is left of the value once Ia ka and the other lights are taken off is
 * Ii kd (L.N): with the light's place held, Ii is the least-squares fit
 * of that.  It is named only when it explains those pixels much better
 * than the statement's Ii; a light whose Ii comes out about 0 is left
 * out.  The pixels are chosen by the statement's map, not by the image,
 * so a light left out still has them.  Not for a light placed elsewhere
 * (tone_scene_lamps.c), which this does not fit.
 */
#include <math.h>

#include "tone_scene.h"

/* Fewest pixels a fit stands on; a pixel is read where the statement's
   light adds this many levels more than the comparison's own, on
   spheres with kd at least COLOUR_KD. */
#define COLOUR_MIN 500
#define COLOUR_LIT 3
#define COLOUR_KD 0.1
/* The fit's error (levels, RMS) at most this, the statement's at least
   COLOUR_BETTER times it and COLOUR_OFF levels, and Ii this far from
   the statement's (a share of it); below COLOUR_GONE of it, the light
   is left out. */
#define COLOUR_RMS 3.0
#define COLOUR_BETTER 4.0
#define COLOUR_OFF 8.0
#define COLOUR_SHARE 0.1
#define COLOUR_GONE 0.05

/* Pixel p on channel c for lamp `lamp`: its light's share g = kd (L.N)
   in the statement, and y, what is left of the value once the rest of
   the model is taken off; 0 when p is not read. */
static int colour_term(const scene_work *w, size_t p, size_t lamp,
                       unsigned c, double *g, double *y)
{
    const rayo_course_map *m = w->map;
    const rayo_course_lamp *lamps = w->data->lamps;
    const rayo_course_ball *ball = tone_scene_unclamped(w, p, c);
    int b = m->ball[p];
    double v = w->image->v[p * w->n + c], rest;
    float f;
    if (ball == NULL)
        return 0;
    f = m->light[p * m->lamp_count + lamp];
    if (ball->color[c] != 1 || ball->kd < COLOUR_KD || f <= 0)
        return 0;
    *g = ball->kd * f;
    if (255 * *g * lamps[lamp].color[c] <= w->levels + COLOUR_LIT)
        return 0;
    rest = tone_scene_rest(w, p, b, c, lamp);
    *y = (v + 0.5) / 255 - rest;
    return 1;
}

/* Lamp `lamp` on channel c: 1 when its colour is named. */
static int lamp_colour(scene_work *w, size_t lamp, unsigned c)
{
    const rayo_course_lamp *stated = &w->data->lamps[lamp];
    size_t pixels = (size_t)w->map->width * w->map->height, p;
    double gg = 0, gy = 0, g, y, ii, fit = 0, off = 0;
    uint64_t total = 0, close = 0;
    unsigned k;
    for (p = 0; p < pixels; p++)
        if (colour_term(w, p, lamp, c, &g, &y)) {
            gg += g * g;
            gy += g * y;
            total++;
        }
    if (total < COLOUR_MIN || gg <= 0)
        return 0;
    ii = gy / gg;
    for (p = 0; p < pixels; p++) {
        double e, s;
        if (!colour_term(w, p, lamp, c, &g, &y))
            continue;
        e = 255 * (y - ii * g);
        s = 255 * (y - stated->color[c] * g);
        fit += e * e;
        off += s * s;
        close += fabs(e) <= w->levels + 1;
    }
    fit = sqrt(fit / (double)total);
    off = sqrt(off / (double)total);
    if (fit > COLOUR_RMS || off < COLOUR_BETTER * fit || off < COLOUR_OFF ||
        fabs(ii - stated->color[c]) < COLOUR_SHARE * stated->color[c])
        return 0;
    {
        int gone = ii < COLOUR_GONE * stated->color[c];
        rayo_compare_finding *f = tone_scene_add(
            w->r, gone ? RAYO_FINDING_LAMP_MISSING : RAYO_FINDING_LAMP_COLOUR);
        if (f == NULL)
            return 0;
        for (k = 0; k < 3; k++) {
            f->value[k] = stated->color[k];
            f->expected[k] = stated->color[k];
        }
        f->value[c] = gone ? 0 : ii;
        f->box[0] = (int32_t)lamp;
        f->pixels = close;
        f->total = total;
    }
    return 1;
}

int tone_scene_lamp_colours(scene_work *w)
{
    size_t l, named = 0;
    if (!tone_scene_lamps_readable(w))
        return 0;
    for (l = 0; l < w->data->lamp_count; l++) {
        unsigned only = 0;
        if (tone_scene_lamp_channel(w, l, &only))
            named += (size_t)lamp_colour(w, l, only);
    }
    return named > 0;
}
