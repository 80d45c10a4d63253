/*
 * tone_scene.c - what an image differs from one of the course's scenes
 * in, when no single mistake explains it: the background, a sphere
 * added, missing, moved or partly drawn, the ambient term, the light's
 * intensity, values below the ambient term.
 *
 * The scene's map (course_map.c: the sphere each pixel shows, each
 * light's L.N and shadow) is read region by region, away from every
 * outline (its core), so a picture drawn a pixel or two apart (the
 * course's z = 321.5) counts the same: the background's most common
 * value, each sphere's pixels that show it, the unlit pixels' most
 * common value (the ambient term), the lit ones' (v - ambient) / (L.N)
 * (II).  Where none of that fits, it says where the differences lie
 * (which sphere, which part of the background).  Not a fit of a scene
 * to a picture: the course's scene, read against the image, and only
 * for EJ2 (gray) and EJ3 (colour) at 640x480.
 */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "../course/course_impl.h"
#include "tone_impl.h"

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
/* Fewest pixels a finding about a sphere or a constant stands on. */
#define FEW 20
/* A pixel of a sphere tells a missing sphere only where the scene's
   value is this far (levels) from black and from the background. */
#define CLEAR 16
/* Pixels below the ambient term are named when they are at least this
   share of the lit, the shadowed or the unlit pixels (not noise) ... */
#define BELOW_SHARE 0.5
/* ... and darker than the ambient term by this many levels more than
   the comparison's own (a level or two of noise is not a finding). */
#define DARK_MARGIN 2

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static rayo_course_map maps[RAYO_COURSE_EXERCISES];

void tone_scene_release_cache(void)
{
    size_t i;
    pthread_mutex_lock(&lock);
    for (i = 0; i < RAYO_COURSE_EXERCISES; i++)
        rayo_course_map_free(&maps[i]);
    pthread_mutex_unlock(&lock);
}

/* The exercise's map, made once and kept (made under the lock: two
   threads never make it twice). */
static rayo_status map_of(rayo_course_exercise e, const rayo_course_map **map,
                          rayo_error *err)
{
    rayo_status s = RAYO_OK;
    pthread_mutex_lock(&lock);
    if (maps[e].ball == NULL)
        s = rayo_course_map_make(e, &maps[e], err);
    pthread_mutex_unlock(&lock);
    *map = s == RAYO_OK ? &maps[e] : NULL;
    return s;
}

typedef struct scene_work {
    const tone_image *ref, *image;
    const rayo_course_map *map;
    const rayo_course_data *data;
    rayo_compare_report *r;
    unsigned n, levels;
    int bg[3];
    int gone[32]; /* a sphere found missing */
} scene_work;

static int near_value(const unsigned char *v, const int *to, unsigned n,
                      unsigned levels)
{
    unsigned c;
    for (c = 0; c < n; c++) {
        int d = (int)v[c] - to[c];
        if (d > (int)levels || -d > (int)levels)
            return 0;
    }
    return 1;
}

static int is_bg(const scene_work *w, const unsigned char *v)
{
    return near_value(v, w->bg, w->n, w->levels);
}

static rayo_compare_finding *add_finding(rayo_compare_report *r,
                                         rayo_compare_finding_kind kind)
{
    rayo_compare_finding *f;
    if (r->tone.findings >= RAYO_COMPARE_FINDINGS)
        return NULL;
    f = &r->tone.finding[r->tone.findings++];
    memset(f, 0, sizeof *f);
    f->kind = kind;
    f->ball = -1;
    return f;
}

static void ball_at(const scene_work *w, int b, rayo_compare_finding *f)
{
    f->ball = b;
    rayo_course_ball_pixel(w->map, &w->data->balls[b], &f->x, &f->y);
}

/* The most common value of each channel over the core of the
   background, and whether it is most of it. */
static void find_background(scene_work *w)
{
    uint64_t hist[3][256], total = 0, same = 0;
    size_t p, pixels = (size_t)w->map->width * w->map->height;
    unsigned c, v;
    memset(hist, 0, sizeof hist);
    for (p = 0; p < pixels; p++)
        if (w->map->core[p] && w->map->ball[p] < 0) {
            total++;
            for (c = 0; c < w->n; c++)
                hist[c][w->image->v[p * w->n + c]]++;
        }
    for (c = 0; c < w->n; c++) {
        uint64_t most = 0;
        w->bg[c] = 0;
        for (v = 0; v < 256; v++)
            if (hist[c][v] > most) {
                most = hist[c][v];
                w->bg[c] = (int)v;
            }
    }
    for (p = 0; p < pixels; p++)
        if (w->map->core[p] && w->map->ball[p] < 0 &&
            is_bg(w, w->image->v + p * w->n))
            same++;
    if (2 * same > total) {
        int black = 1;
        for (c = 0; c < w->n; c++)
            if (w->bg[c] > (int)w->levels)
                black = 0;
        if (!black) {
            rayo_compare_finding *f = add_finding(w->r,
                                                  RAYO_FINDING_BACKGROUND);
            if (f != NULL) {
                for (c = 0; c < w->n; c++)
                    f->value[c] = w->bg[c];
                f->pixels = same;
                f->total = total;
            }
        }
    } else {
        w->bg[0] = w->bg[1] = w->bg[2] = 0; /* no background to speak of */
    }
}

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

/* Each sphere's pixels that show the background (where the scene's do
   not), and the objects where the scene shows only background; a
   sphere missing with an object of its size elsewhere is moved. */
static rayo_status find_objects(scene_work *w, rayo_error *err)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p, i, found = 0;
    size_t balls = w->data->ball_count;
    uint64_t area[32], eligible[32], shows_bg[32], background = 0;
    int black[3] = {0, 0, 0};
    region regions[ADDED_MAX + 1];
    int used[ADDED_MAX + 1];
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
        f = add_finding(w->r, !w->gone[i]   ? RAYO_FINDING_PARTLY
                              : best < found ? RAYO_FINDING_MOVED
                                             : RAYO_FINDING_MISSING);
        if (f == NULL)
            break;
        ball_at(w, (int)i, f);
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
        if (used[i] || (f = add_finding(w->r, RAYO_FINDING_ADDED)) == NULL)
            continue;
        f->x = regions[i].sx / (double)regions[i].pixels;
        f->y = regions[i].sy / (double)regions[i].pixels;
        memcpy(f->box, regions[i].box, sizeof f->box);
        f->pixels = regions[i].pixels;
    }
    return RAYO_OK;
}

/* Whether pixel p is on a sphere still drawn, away from its outline. */
static int on_sphere(const scene_work *w, size_t p)
{
    int b = w->map->ball[p];
    return w->map->core[p] && b >= 0 && !w->gone[b];
}

/* 1 when no light reaches p (L.N <= 0 or shadowed, for every light). */
static int unlit(const scene_work *w, size_t p)
{
    size_t l;
    for (l = 0; l < w->map->lamp_count; l++)
        if (w->map->light[p * w->map->lamp_count + l] > 0)
            return 0;
    return 1;
}

/* The model's ambient value of channel c on sphere b: the byte of
   Ia ka M (EJ3) or IA (EJ2), in float as the student's program. */
static int ambient_byte(const scene_work *w, int b, unsigned c)
{
    const rayo_course_ball *ball = &w->data->balls[b];
    float a = (float)w->data->ambient[c], ka = (float)ball->ka;
    float m = (float)ball->color[c], v;
    if (w->map->exercise == RAYO_COURSE_EJ2)
        return (int)a;
    v = a * ka;
    v = v * m;
    return (int)(255 * v);
}

/* The unlit pixels' most common value: the ambient term (EJ2: of every
   sphere; EJ3: per channel, of the spheres whose ka M is 1 there). */
static void find_ambient(scene_work *w)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p;
    uint64_t hist[3][256], total[3] = {0, 0, 0}, most[3] = {0, 0, 0};
    int mode[3] = {0, 0, 0}, off = 0;
    unsigned c, v;
    memset(hist, 0, sizeof hist);
    for (p = 0; p < pixels; p++) {
        const rayo_course_ball *ball;
        if (!on_sphere(w, p) || !unlit(w, p))
            continue;
        ball = &w->data->balls[m->ball[p]];
        for (c = 0; c < w->n; c++)
            if (m->exercise == RAYO_COURSE_EJ2 ||
                (ball->ka == 1 && ball->color[c] == 1)) {
                hist[c][w->image->v[p * w->n + c]]++;
                total[c]++;
            }
    }
    for (c = 0; c < w->n; c++) {
        int expected;
        for (v = 0; v < 256; v++)
            if (hist[c][v] > most[c]) {
                most[c] = hist[c][v];
                mode[c] = (int)v;
            }
        if (total[c] < FEW || 2 * most[c] <= total[c])
            return; /* no one value: not a constant */
        expected = m->exercise == RAYO_COURSE_EJ2
                       ? (int)w->data->ambient[c]
                       : (int)(255 * (float)w->data->ambient[c]);
        if (mode[c] - expected > (int)w->levels ||
            expected - mode[c] > (int)w->levels)
            off = 1;
    }
    if (off) {
        rayo_compare_finding *f = add_finding(w->r, RAYO_FINDING_AMBIENT);
        if (f == NULL)
            return;
        for (c = 0; c < w->n; c++) {
            f->expected[c] = w->data->ambient[c];
            /* EJ3: the byte is the integer part of 255 Ia */
            f->value[c] = m->exercise == RAYO_COURSE_EJ2
                              ? mode[c]
                              : (mode[c] + 0.5) / 255.0;
            f->pixels += most[c];
            f->total += total[c];
        }
    }
}

/* EJ2's light intensity: the median of (v - IA) / (L.N) over lit pixels
   the clamp does not reach, named when most agree on a value off the
   statement's II. */
static void find_light(scene_work *w)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p;
    uint64_t hist[1024], total = 0, seen = 0, close = 0;
    double ia = w->data->ambient[0], ii = w->data->lamps[0].color[0];
    size_t k, median = 0;
    size_t i;
    memset(hist, 0, sizeof hist);
    for (i = 0; i < w->r->tone.findings; i++)
        if (w->r->tone.finding[i].kind == RAYO_FINDING_AMBIENT)
            ia = w->r->tone.finding[i].value[0];
    for (p = 0; p < pixels; p++) {
        float f = m->light[p];
        double v = w->image->v[p];
        if (!on_sphere(w, p) || f < 0.2f || v >= 255 || v <= ia)
            continue;
        k = (size_t)((v + 0.5 - ia) / f + 0.5);
        hist[k < 1023 ? k : 1023]++;
        total++;
    }
    if (total < FEW)
        return;
    for (k = 0; k < 1024; k++) {
        seen += hist[k];
        if (2 * seen >= total) {
            median = k;
            break;
        }
    }
    for (k = median * 95 / 100; k <= median * 105 / 100 && k < 1024; k++)
        close += hist[k];
    if (2 * close <= total ||
        (median >= ii * 0.97 && median <= ii * 1.03))
        return;
    {
        rayo_compare_finding *f = add_finding(w->r, RAYO_FINDING_LIGHT);
        if (f != NULL) {
            f->value[0] = (double)median;
            f->expected[0] = ii;
            f->pixels = close;
            f->total = total;
        }
    }
}

/* Pixels of the spheres darker than their ambient term, which the model
   never gives, named when they are a good share of the lit, the
   shadowed (by another sphere) or the unlit pixels, not specks of
   noise; the sphere with most of them, and how many are shadowed. */
static void find_below(scene_work *w)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p, l;
    uint64_t per_ball[32], count = 0, most = 0;
    uint64_t below[3] = {0, 0, 0}, of[3] = {0, 0, 0}; /* lit, cast, unlit */
    int b, best = -1, k, shared = 0;
    unsigned c;
    memset(per_ball, 0, sizeof per_ball);
    for (p = 0; p < pixels; p++) {
        int dark = 0, lit = 0, cast = 0;
        if (!on_sphere(w, p))
            continue;
        b = m->ball[p];
        for (c = 0; c < w->n; c++) {
            int a = ambient_byte(w, b, c);
            if (w->image->v[p * w->n + c] + (int)w->levels + DARK_MARGIN <
                a)
                dark = 1;
        }
        for (l = 0; l < m->lamp_count; l++) {
            float f = m->light[p * m->lamp_count + l];
            lit |= f > 0;
            cast |= f < 0;
        }
        k = lit ? 0 : cast ? 1 : 2;
        of[k]++;
        if (!dark)
            continue;
        below[k]++;
        per_ball[b]++;
        count++;
    }
    for (k = 0; k < 3; k++)
        if (below[k] >= FEW && (double)below[k] >= BELOW_SHARE * (double)of[k])
            shared = 1;
    if (!shared)
        return;
    for (b = 0; b < (int)w->data->ball_count; b++)
        if (per_ball[b] > most) {
            most = per_ball[b];
            best = b;
        }
    {
        rayo_compare_finding *f = add_finding(w->r,
                                              RAYO_FINDING_BELOW_AMBIENT);
        if (f == NULL)
            return;
        ball_at(w, best, f);
        f->pixels = count;
        f->total = most;
        f->shadowed = below[1];
        for (c = 0; c < w->n; c++)
            f->expected[c] = w->data->ambient[c];
    }
}

/* Nothing named: where the differences lie, on which spheres and on the
   background (its differing pixels' box), the most first. */
static void find_where(scene_work *w)
{
    const rayo_course_map *m = w->map;
    size_t pixels = (size_t)m->width * m->height, p, i;
    uint64_t differ[33], total[33];
    int32_t box[4] = {INT32_MAX, INT32_MAX, -1, -1};
    int shown[33];
    memset(differ, 0, sizeof differ);
    memset(total, 0, sizeof total);
    memset(shown, 0, sizeof shown);
    for (p = 0; p < pixels; p++) {
        int b = m->ball[p] + 1; /* 0: the background */
        const unsigned char *a = w->ref->v + p * w->n;
        const unsigned char *v = w->image->v + p * w->n;
        int same[3] = {a[0], w->n > 1 ? a[1] : 0, w->n > 1 ? a[2] : 0};
        if (!m->core[p])
            continue;
        total[b]++;
        if (near_value(v, same, w->n, w->levels))
            continue;
        differ[b]++;
        if (b == 0) {
            int32_t x = (int32_t)(p % m->width), y = (int32_t)(p / m->width);
            if (x < box[0])
                box[0] = x;
            if (y < box[1])
                box[1] = y;
            if (x > box[2])
                box[2] = x;
            if (y > box[3])
                box[3] = y;
        }
    }
    for (i = 0; i < 3; i++) {
        size_t b, best = 0;
        uint64_t most = 0;
        rayo_compare_finding *f;
        for (b = 0; b <= w->data->ball_count; b++)
            if (!shown[b] && differ[b] > most) {
                most = differ[b];
                best = b;
            }
        if (most < FEW || (f = add_finding(w->r, RAYO_FINDING_WHERE)) ==
                              NULL)
            break;
        shown[best] = 1;
        f->pixels = most;
        f->total = total[best];
        if (best > 0)
            ball_at(w, (int)best - 1, f);
        else
            memcpy(f->box, box, sizeof box);
    }
}

rayo_status tone_scene_find(const tone_image *ref, const tone_image *image,
                            int course, rayo_compare_report *r,
                            int *named, rayo_error *err)
{
    scene_work w;
    rayo_status s;
    *named = 0;
    r->tone.findings = 0;
    if (course != RAYO_COURSE_EJ2 && course != RAYO_COURSE_EJ3)
        return RAYO_OK;
    if (ref->width != RAYO_COURSE_WIDTH || ref->height != RAYO_COURSE_HEIGHT ||
        image->width != ref->width || image->height != ref->height ||
        ref->channels != image->channels ||
        ref->channels != (course == RAYO_COURSE_EJ2 ? 1u : 3u))
        return RAYO_OK;
    memset(&w, 0, sizeof w);
    w.ref = ref;
    w.image = image;
    w.r = r;
    w.n = ref->channels;
    w.levels = r->tone.levels;
    w.data = rayo_course_data_of((rayo_course_exercise)course);
    if (w.data == NULL || w.data->ball_count > 32)
        return RAYO_OK;
    if ((s = map_of((rayo_course_exercise)course, &w.map, err)) != RAYO_OK)
        return s;
    find_background(&w);
    if ((s = find_objects(&w, err)) != RAYO_OK)
        return s;
    find_ambient(&w);
    if (course == RAYO_COURSE_EJ2)
        find_light(&w);
    find_below(&w);
    *named = r->tone.findings > 0;
    if (!*named)
        find_where(&w);
    return RAYO_OK;
}
