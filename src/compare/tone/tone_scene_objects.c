/*
 * tone_scene_objects.c - the objects of a student's image against the
 * course's scene: each sphere whose pixels show the background (missing,
 * or partly drawn), the regions of the background that are not its
 * value (an object added), and a missing sphere found elsewhere
 * (moved), or a sphere drawn another size (tone_scene_size.c), which
 * explains the ring added around it or the background inside it.
 * Part of tone_scene.c's reading, split off for its size; the
 * constants of the model are read there.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_scene.h"

/* Objects smaller than this (pixels), or filling less than half their
   box (specks of noise joined), are not named as added; nor is one
   that covers more than a quarter of the background. */
#define ADDED_MIN 100
/* More stray regions than this on the background: not objects. */
#define ADDED_MAX 4
/* A sphere whose pixels show the background at least this share of
   them is missing; from PARTLY_SHARE on it is partly drawn. */
#define MISSING_SHARE 0.75
#define PARTLY_SHARE 0.2
/* A missing sphere is moved when an object of about its size (its
   whole disc, within this factor: the frame may cut it, perspective
   stretch it) is where the scene shows background. */
#define MOVED_SIZE 3
/* A pixel of a sphere tells a missing sphere only where the scene's
   value is this far (levels) from black and from the background. */
#define CLEAR 16


/* A stray region of the background: its pixels, box and centroid. */
typedef struct region {
    uint64_t pixels;
    int32_t box[4];
    double sx, sy;
} region;

/* The 4-connected regions of stray pixels (1 in mark), the largest
   ADDED_MAX + 1 of at least ADDED_MIN pixels into out (largest first);
   their number returned (ADDED_MAX + 1: too many to be objects). */
static rayo_status find_regions(unsigned char *mark, uint32_t width,
                                uint32_t height, uint64_t background,
                                region *out, size_t *found, rayo_error *err)
{
    size_t pixels = (size_t)width * height, p, n = 0;
    uint32_t *stack = malloc(pixels * sizeof *stack);
    if (stack == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for the scene's "
                              "regions");
    for (p = 0; p < pixels; p++) {
        region g;
        size_t top = 0, k;
        if (mark[p] != 1)
            continue;
        memset(&g, 0, sizeof g);
        g.box[0] = g.box[1] = INT32_MAX;
        g.box[2] = g.box[3] = -1;
        mark[p] = 2;
        stack[top++] = (uint32_t)p;
        while (top > 0) {
            uint32_t q = stack[--top];
            int32_t x = (int32_t)(q % width), y = (int32_t)(q / width);
            g.pixels++;
            g.sx += x;
            g.sy += y;
            if (x < g.box[0])
                g.box[0] = x;
            if (y < g.box[1])
                g.box[1] = y;
            if (x > g.box[2])
                g.box[2] = x;
            if (y > g.box[3])
                g.box[3] = y;
            if (x > 0 && mark[q - 1] == 1)
                mark[q - 1] = 2, stack[top++] = q - 1;
            if (x + 1 < (int32_t)width && mark[q + 1] == 1)
                mark[q + 1] = 2, stack[top++] = q + 1;
            if (y > 0 && mark[q - width] == 1)
                mark[q - width] = 2, stack[top++] = q - width;
            if (y + 1 < (int32_t)height && mark[q + width] == 1)
                mark[q + width] = 2, stack[top++] = q + width;
        }
        if (g.pixels < ADDED_MIN ||
            2 * g.pixels < (uint64_t)(g.box[2] - g.box[0] + 1) *
                               (uint64_t)(g.box[3] - g.box[1] + 1))
            continue;
        /* kept in order, largest first */
        for (k = n < ADDED_MAX + 1 ? n : ADDED_MAX; k > 0; k--) {
            if (out[k - 1].pixels >= g.pixels)
                break;
            if (k < ADDED_MAX + 1)
                out[k] = out[k - 1];
        }
        if (k < ADDED_MAX + 1)
            out[k] = g;
        if (n < ADDED_MAX + 1)
            n++;
        if (4 * g.pixels > background)
            n = ADDED_MAX + 1; /* not an object: the picture is off */
    }
    free(stack);
    *found = n;
    return RAYO_OK;
}

/* The radius in the statement's units of a sphere at ball's centre
   drawn ratio times as large: the picture's size is the tangent of the
   angle the sphere spans, asin(r / D) at distance D. */
static double statement_radius(const rayo_course_ball *ball, double ratio)
{
    double d = sqrt(ball->center[0] * ball->center[0] +
                    ball->center[1] * ball->center[1] +
                    ball->center[2] * ball->center[2]);
    return d * sin(atan(ratio * tan(asin(ball->radius / d))));
}

/* A sphere whose centre is hidden, drawn shift (px) away: where it is
   in the picture (value), its disc's box, and its centre in the
   statement's units at the statement's depth (expected); pixels 0. */
static void hidden_moved(const scene_work *w, int b, const double *shift,
                         rayo_compare_finding *f)
{
    const rayo_course_ball *ball = &w->data->balls[b];
    double r = w->map->focal * ball->radius / ball->center[2];
    f->value[0] = f->x + shift[0];
    f->value[1] = f->y + shift[1];
    f->value[2] = r;
    f->box[0] = (int32_t)lround(f->value[0] - r);
    f->box[1] = (int32_t)lround(f->value[1] - r);
    f->box[2] = (int32_t)lround(f->value[0] + r);
    f->box[3] = (int32_t)lround(f->value[1] + r);
    f->expected[0] = (f->value[0] - w->map->width / 2.0) * ball->center[2] /
                     w->map->focal;
    f->expected[1] = (w->map->height / 2.0 - f->value[1]) *
                     ball->center[2] / w->map->focal;
    f->expected[2] = ball->center[2];
}

/* Each sphere's pixels that show the background (where the scene's do
   not), and the objects where the scene shows only background; a
   sphere missing with an object of its size elsewhere is moved. */
rayo_status tone_scene_objects(scene_work *w, rayo_error *err)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p, i, found = 0;
    size_t balls = w->data->ball_count;
    uint64_t area[SCENE_BALLS], eligible[SCENE_BALLS], shows_bg[SCENE_BALLS], background = 0;
    int black[3] = {0, 0, 0};
    region regions[ADDED_MAX + 1];
    int used[ADDED_MAX + 1], off[SCENE_BALLS];
    double scene_r[SCENE_BALLS], seen_r[SCENE_BALLS], shift[SCENE_BALLS][2];
    unsigned char *mark;
    rayo_status s;
    memset(area, 0, sizeof area);
    memset(eligible, 0, sizeof eligible);
    memset(shows_bg, 0, sizeof shows_bg);
    memset(used, 0, sizeof used);
    mark = calloc(pixels, 1);
    if (mark == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for the scene's "
                              "regions");
    for (p = 0; p < pixels; p++) {
        int b = m->ball[p];
        const unsigned char *v = w->image->v + p * w->n;
        if (!m->core[p])
            continue;
        if (b < 0) {
            mark[p] = !is_bg(w, v);
            background++;
            continue;
        }
        /* where the scene's value is near black or the background, the
           background in the image says nothing */
        if (near_value(w->ref->v + p * w->n, w->bg, w->n, CLEAR) ||
            near_value(w->ref->v + p * w->n, black, w->n, CLEAR))
            continue;
        eligible[b]++;
        shows_bg[b] += is_bg(w, v);
    }
    s = find_regions(mark, m->width, m->height, background, regions, &found,
                     err);
    free(mark);
    if (s != RAYO_OK)
        return s;
    if (found > ADDED_MAX)
        found = 0; /* a background of noise, not objects */
    tone_scene_sizes(w, scene_r, seen_r, off, shift);
    for (i = 0; i < balls; i++) {
        /* its whole disc, hidden parts too: the size it has moved */
        const rayo_course_ball *ball = &w->data->balls[i];
        double r = m->focal * ball->radius / ball->center[2];
        area[i] = (uint64_t)(3.14159 * r * r);
    }
    for (i = 0; i < balls; i++) {
        rayo_compare_finding *f;
        double share;
        size_t k, best = found;
        if (off[i] == 2) {
            /* its centre hidden: placed from the outline that shows */
            f = tone_scene_add(w->r, RAYO_FINDING_MOVED);
            if (f == NULL)
                break;
            tone_scene_ball_at(w, (int)i, f);
            hidden_moved(w, (int)i, shift[i], f);
            w->gone[i] = 1;
            for (k = 0; k < found; k++)
                if (regions[k].box[0] <= f->box[2] + 2 &&
                    regions[k].box[2] >= f->box[0] - 2 &&
                    regions[k].box[1] <= f->box[3] + 2 &&
                    regions[k].box[3] >= f->box[1] - 2)
                    used[k] = 1;
            continue;
        }
        if (off[i]) {
            f = tone_scene_add(w->r, RAYO_FINDING_SIZE);
            if (f == NULL)
                break;
            tone_scene_ball_at(w, (int)i, f);
            f->value[0] = seen_r[i];
            f->expected[0] = scene_r[i];
            f->value[1] = statement_radius(&w->data->balls[i],
                                           seen_r[i] / scene_r[i]);
            /* its shading is not the scene's: left out of the rest */
            w->gone[i] = 1;
            /* the ring it adds is itself, not another object */
            for (k = 0; k < found; k++)
                if (regions[k].box[0] <= f->x + 1.2 * seen_r[i] &&
                    regions[k].box[2] >= f->x - 1.2 * seen_r[i] &&
                    regions[k].box[1] <= f->y + 1.2 * seen_r[i] &&
                    regions[k].box[3] >= f->y - 1.2 * seen_r[i])
                    used[k] = 1;
            continue;
        }
        if (eligible[i] < FEW)
            continue;
        share = (double)shows_bg[i] / (double)eligible[i];
        if (share < PARTLY_SHARE)
            continue;
        w->gone[i] = share >= MISSING_SHARE;
        for (k = 0; w->gone[i] && k < found; k++)
            if (!used[k] && MOVED_SIZE * regions[k].pixels >= area[i] &&
                regions[k].pixels <= MOVED_SIZE * area[i] &&
                (best == found || regions[k].pixels > regions[best].pixels))
                best = k;
        f = tone_scene_add(w->r, !w->gone[i]   ? RAYO_FINDING_PARTLY
                              : best < found ? RAYO_FINDING_MOVED
                                             : RAYO_FINDING_MISSING);
        if (f == NULL)
            break;
        tone_scene_ball_at(w, (int)i, f);
        f->pixels = shows_bg[i];
        f->total = eligible[i];
        if (best < found) {
            used[best] = 1;
            memcpy(f->box, regions[best].box, sizeof f->box);
            f->value[0] = regions[best].sx / (double)regions[best].pixels;
            f->value[1] = regions[best].sy / (double)regions[best].pixels;
        }
    }
    for (i = 0; i < found; i++) {
        rayo_compare_finding *f;
        if (used[i] || (f = tone_scene_add(w->r, RAYO_FINDING_ADDED)) == NULL)
            continue;
        f->x = regions[i].sx / (double)regions[i].pixels;
        f->y = regions[i].sy / (double)regions[i].pixels;
        memcpy(f->box, regions[i].box, sizeof f->box);
        f->pixels = regions[i].pixels;
    }
    return RAYO_OK;
}
