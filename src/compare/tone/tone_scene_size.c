/*
 * tone_scene_size.c - the size each sphere of the course's scene is
 * drawn at, read from a student's image: from the sphere's centre, along
 * rays where the scene's outline meets the background and its picture
 * stands out from the image's background all along, how far the
 * image's object reaches against how far the scene's does.  A sphere
 * whose radius in the statement was typed otherwise then is named by
 * its size, not as an object added around it or as partly drawn.
 * A sphere whose centre another hides (or the frame cuts) is measured
 * the same way from where its centre would be, on the stretch of each
 * ray the scene shows it.  Part of tone_scene_objects.c's reading,
 * split off for its size; not a fit of circles to the picture.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_scene.h"

/* Rays from the centre tried, and the fewest that must see an outline
   against the background for a sphere to be measured. */
#define RAYS 72
#define RAYS_MIN 8
/* A radius off by more than this share, and by this many pixels, is a
   size of its own (the scene drawn a pixel apart is not). */
#define SIZE_SHARE 0.1
#define SIZE_PIXELS 3.0
/* The ratio of the image's reach to the scene's, ray by ray: its
   median at most half this from its nearer quartile for a size to be
   read. */
#define SIZE_SPREAD 0.1
/* More spheres than this share of those measured (and than 2) another
   size: the camera, not their radii. */
#define SIZE_MOST 0.25
/* A disc moved (on opposite rays, the median of half the difference
   of their reaches) by more than this share of its change in size is
   not read as a size (a picture shifted, or of another field). */
#define SIZE_MOVED 0.35

static int pixel_at(const rayo_course_map *m, double x, double y, size_t *p)
{
    long i = lround(x), j = lround(y);
    if (i < 0 || j < 0 || i >= (long)m->width || j >= (long)m->height)
        return 0;
    *p = (size_t)j * m->width + (size_t)i;
    return 1;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One sphere: the median radius (px) the scene gives it, over the rays
   where the scene's outline meets the background, and that times the
   median ratio of the image's reach to the scene's on each; 0 when too
   few such rays or when the ratios do not agree. */
static void measure(const scene_work *w, int b, double *scene, double *seen,
                    int *moved, double *shift)
{
    const rayo_course_map *m = w->map;
    const rayo_course_ball *ball = &w->data->balls[b];
    double cx, cy, ms[RAYS], is[RAYS], qs[RAYS], ss[RAYS / 2];
    double rm_at[RAYS], is_at[RAYS], far;
    size_t p, n = 0, k, pairs = 0;
    int hidden;
    *scene = *seen = 0;
    *moved = 0;
    rayo_course_ball_pixel(m, ball, &cx, &cy);
    /* hidden: the stretch of each ray the sphere shows is looked for as
       far as twice its radius in the picture, and a little more */
    hidden = !pixel_at(m, cx, cy, &p) || m->ball[p] != b;
    far = 2 * m->focal * ball->radius / ball->center[2] + 10;
    if (!hidden && is_bg(w, w->image->v + p * w->n))
        return;
    for (k = 0; k < RAYS; k++) {
        double a = 6.283185307179586 * (double)k / RAYS;
        double dx = cos(a), dy = sin(a), t, rm = 0, cap, from = 0;
        int inside = 1;
        rm_at[k] = -1;
        if (hidden) {
            /* the stretch [from, its last pixel] the sphere shows */
            from = -1;
            for (t = 1; t < far; t += 1)
                if (pixel_at(m, cx + t * dx, cy + t * dy, &p) &&
                    m->ball[p] == b) {
                    if (from < 0)
                        from = t;
                    rm = t - 0.5;
                }
            /* and the image must show an object where the stretch
               begins: a sphere gone from there (moved, or smaller than
               what hides it) is not measured */
            if (from < 0 || !pixel_at(m, cx + from * dx, cy + from * dy, &p) ||
                is_bg(w, w->image->v + p * w->n))
                continue;
        } else {
            for (t = 1; inside; t += 1)
                inside = pixel_at(m, cx + t * dx, cy + t * dy, &p) &&
                         m->ball[p] == b;
            rm = t - 1.5;
        }
        /* the scene's outline there must meet the background */
        if (!pixel_at(m, cx + (rm + 3) * dx, cy + (rm + 3) * dy, &p) ||
            m->ball[p] >= 0)
            continue;
        /* and the scene's sphere must stand out from the image's
           background all along the ray (not an unlit side at IA over
           a background at IA) */
        for (t = from; t < rm - 1; t += 1)
            if (pixel_at(m, cx + t * dx, cy + t * dy, &p) &&
                is_bg(w, w->ref->v + p * w->n))
                break;
        if (t < rm - 1)
            continue;
        cap = 3 * rm + 10;
        for (t = from > 1 ? from : 1; t < cap; t += 1) {
            size_t q;
            if (!pixel_at(m, cx + t * dx, cy + t * dy, &p) ||
                !pixel_at(m, cx + (t + 1) * dx, cy + (t + 1) * dy, &q)) {
                t = cap;
                break;
            }
            if (is_bg(w, w->image->v + p * w->n) &&
                is_bg(w, w->image->v + q * w->n))
                break;
        }
        if (t >= cap)
            continue; /* the frame or something beyond: no outline */
        rm_at[k] = ms[n] = rm;
        is_at[k] = is[n] = t - 0.5;
        qs[n] = is[n] / rm;
        n++;
    }
    if (n < RAYS_MIN)
        return;
    if (hidden) {
        /* its outline's circle moved, not grown: a place, not a size */
        double sx[RAYS], sy[RAYS], ix[RAYS], iy[RAYS];
        size_t q = 0;
        for (k = 0; k < RAYS; k++)
            if (rm_at[k] > 0) {
                double a = 6.283185307179586 * (double)k / RAYS;
                sx[q] = rm_at[k] * cos(a);
                sy[q] = rm_at[k] * sin(a);
                ix[q] = is_at[k] * cos(a);
                iy[q] = is_at[k] * sin(a);
                q++;
            }
        if (tone_scene_outline_moved(sx, sy, ix, iy, q, shift)) {
            *moved = 1;
            return;
        }
    }
    /* opposite rays: a disc moved by s reaches s.u farther on one and
       s.u nearer on the other */
    for (k = 0; k < RAYS / 2; k++)
        if (rm_at[k] > 0 && rm_at[k + RAYS / 2] > 0)
            ss[pairs++] = fabs((is_at[k] - rm_at[k]) -
                               (is_at[k + RAYS / 2] - rm_at[k + RAYS / 2])) /
                          2;
    qsort(qs, n, sizeof qs[0], cmp_double);
    qsort(ms, n, sizeof ms[0], cmp_double);
    qsort(ss, pairs, sizeof ss[0], cmp_double);
    /* a disc drawn another size reaches the same share farther on
       every ray; one moved or stretched, more on some than on others.
       A smaller one may show what the scene's hid, farther on some
       rays only: the closer side of the median tells */
    if (2 * fmin(qs[n / 2] - qs[n / 4], qs[3 * n / 4] - qs[n / 2]) >
        SIZE_SPREAD)
        return;
    *scene = ms[n / 2];
    *seen = ms[n / 2] * qs[n / 2];
    /* and the disc must have grown or shrunk more than it moved; seen
       on one side only (its neighbours hide the other), the ratios
       must agree twice as closely */
    if (pairs < RAYS_MIN / 2
            ? 2 * (qs[3 * n / 4] - qs[n / 4]) > SIZE_SPREAD
            : ss[pairs / 2] > SIZE_MOVED * fabs(*seen - *scene))
        *scene = *seen = 0;
}

void tone_scene_sizes(const scene_work *w, double *scene, double *seen,
                      int *off, double (*shift)[2])
{
    size_t i, balls = w->data->ball_count, measured = 0, odd = 0;
    size_t shifted = 0;
    int moved[SCENE_BALLS];
    for (i = 0; i < balls; i++) {
        measure(w, (int)i, &scene[i], &seen[i], &moved[i], shift[i]);
        off[i] = 0;
        if (scene[i] <= 0)
            continue;
        measured++;
        if (fabs(seen[i] - scene[i]) > SIZE_SHARE * scene[i] &&
            fabs(seen[i] - scene[i]) >= SIZE_PIXELS) {
            off[i] = 1;
            odd++;
        }
    }
    /* many spheres another size: the camera (the focal distance), not
       their radii */
    if (odd > 2 && (double)odd > SIZE_MOST * (double)measured)
        memset(off, 0, balls * sizeof *off);
    for (i = 0; i < balls; i++)
        shifted += (size_t)moved[i];
    /* and many hidden ones moved: the camera too */
    if (shifted > 1)
        return;
    for (i = 0; i < balls; i++)
        if (moved[i])
            off[i] = 2;
}
