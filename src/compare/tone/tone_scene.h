/*
 * tone_scene.h - what the tone_scene*.c files share: the image being
 * read against the course's scene, whether the exercise's model is the
 * gray one, and the helpers that add a finding to the report.  Private
 * to those files.
 */
#ifndef RAYO_TONE_SCENE_H
#define RAYO_TONE_SCENE_H

#include "rayo/course/course.h"
#include "rayo/course/course_scene.h"

#include "tone_impl.h"

/* At most as many spheres as the course's scenes have. */
#define SCENE_BALLS 32
/* Fewest pixels a finding about a sphere or a constant stands on. */
#define FEW 20

typedef struct scene_work {
    const tone_image *ref, *image;
    const rayo_course_map *map;
    const rayo_course_data *data;
    rayo_compare_report *r;
    unsigned n, levels;
    int gray;               /* the gray model's levels (else colours in
                               [0, 1]): the exercise's light model */
    int bg[3];              /* the image's background (find_background) */
    int gone[SCENE_BALLS];  /* a sphere found missing */
} scene_work;

/* Every channel of v within levels of to. */
static inline int near_value(const unsigned char *v, const int *to,
                             unsigned n, unsigned levels)
{
    unsigned c;
    for (c = 0; c < n; c++) {
        int d = (int)v[c] - to[c];
        if (d > (int)levels || -d > (int)levels)
            return 0;
    }
    return 1;
}

static inline int is_bg(const scene_work *w, const unsigned char *v)
{
    return near_value(v, w->bg, w->n, w->levels);
}

/* Whether the course exercise's light model gives levels (the gray
   one) rather than colours in [0, 1]: the registry says. */
static inline int tone_course_gray(int course)
{
    const rayo_course_info *info =
        rayo_course_info_of((rayo_course_exercise)course);
    return info != NULL && info->shade == RAYO_SHADE_COURSE_GRAY;
}

/* The sphere pixel p shows, when its channel c is read by the colour
   model's fits: away from every outline, on a sphere still drawn, the
   value away from the clamp at 255 (noise may pull it a level or two
   below); NULL when not. */
static inline const rayo_course_ball *tone_scene_unclamped(
    const scene_work *w, size_t p, unsigned c)
{
    int b = w->map->ball[p];
    if (!w->map->core[p] || b < 0 || w->gone[b] ||
        w->image->v[p * w->n + c] + w->levels + 1 >= 255)
        return NULL;
    return &w->data->balls[b];
}

/* The colour model's value of channel c at pixel p (on sphere b) but
   for light `skip`: Ia ka and every other light's Ii kd (L.N), with the
   statement's Ii and the map's L.N and shadows. */
static inline double tone_scene_rest(const scene_work *w, size_t p, int b,
                                     unsigned c, size_t skip)
{
    const rayo_course_map *m = w->map;
    const rayo_course_ball *ball = &w->data->balls[b];
    double rest = w->data->ambient[c] * ball->ka;
    size_t l;
    for (l = 0; l < m->lamp_count; l++) {
        float f = m->light[p * m->lamp_count + l];
        if (l != skip && f > 0)
            rest += ball->kd * w->data->lamps[l].color[c] * f;
    }
    return rest;
}

/* A new finding of kind in r (NULL when r has no room left). */
rayo_compare_finding *tone_scene_add(rayo_compare_report *r,
                                     rayo_compare_finding_kind kind);

/* f is about sphere b: its index and where its centre appears. */
void tone_scene_ball_at(const scene_work *w, int b, rayo_compare_finding *f);

/* tone_scene_size.c: each sphere's radius (px) in the scene and as the
   image shows it (0, 0: not measured), and off[b] where they differ
   enough to be named: 1 another size, 2 a sphere whose centre is
   hidden drawn elsewhere (shift[b], px, how far). */
void tone_scene_sizes(const scene_work *w, double *scene, double *seen,
                      int *off, double (*shift)[2]);

/* tone_scene_outline.c: whether the outline points (i) the image shows
   of a sphere are the scene's (s) moved, the circle about the same
   size; shift, in px, how far. */
int tone_scene_outline_moved(const double *sx, const double *sy,
                             const double *ix, const double *iy, size_t n,
                             double *shift);

/* tone_scene_light.c: the point at (NULL: not wanted) and the normal n
   pixel (i, j) shows of sphere b (0 when its ray misses it), and the
   3x3 system a x = y (Cramer; 0 when singular). */
int tone_scene_surface(const scene_work *w, int b, uint32_t i, uint32_t j,
                       double *at, double *n);
int tone_scene_solve3(double a[3][3], const double *y, double *x);

/* tone_scene_lamps.c: the channel lamp l alone lights into *channel, 1
   when it is a point light of one channel (scene 3's red, green and
   blue), 0 otherwise; and whether the colour model's lights can be read
   at all (a colour image, no changed ambient found: else the rest of the
   model is not the statement's). */
int tone_scene_lamp_channel(const scene_work *w, size_t l, unsigned *channel);
int tone_scene_lamps_readable(const scene_work *w);

/* tone_scene_lamps.c (the colour model): a point light placed
   elsewhere, read from the channel it alone lights; 1 when named. */
int tone_scene_lamp_position(scene_work *w);

/* tone_scene_lamp_colour.c (the colour model): a point light of
   another colour, or left out, read from the channel it alone lights;
   1 when one is named. */
int tone_scene_lamp_colours(scene_work *w);

/* tone_scene_light.c (the gray model): the light's direction the shading fits,
   named when it explains the lit pixels much better than the
   statement's; 1 when named. */
int tone_scene_light_direction(scene_work *w);
/* The same for the colour model's directional light (EJ3), read on
   each channel once the point lights are taken off; not looked for
   when a point light or the ambient term was named. */
int tone_scene_sun_direction(scene_work *w);

/* tone_scene_objects.c: each sphere missing, moved or partly drawn,
   drawn another size, and the objects where the scene shows only
   background. */
rayo_status tone_scene_objects(scene_work *w, rayo_error *err);

#endif
