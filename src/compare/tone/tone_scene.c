/*
 * tone_scene.c - what an image differs from one of the course's scenes
 * in, when no single mistake explains it: the background, a sphere
 * added, missing, moved, partly drawn or drawn another size, the
 * ambient term, the light's intensity or direction (EJ3: a point
 * light's colour or absence, tone_scene_lamp_colour.c, its place,
 * tone_scene_lamps.c, the directional light's direction), values below
 * the ambient term.
 *
 * Not a fit of a scene to a picture: the course's scene, read against
 * the image, and only for the exercises the student model covers (the
 * registry says), at their size.  How the scene's map is read is said
 * after the includes.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "tone_scene.h"

/*
 * The scene's map (course_map.c: the sphere each pixel shows, each
 * light's L.N and shadow) is read region by region, away from every
 * outline (its core), so a picture drawn a pixel or two apart (the
 * course's z = 321.5) counts the same: the background's most common
 * value, each sphere's pixels that show it, the unlit pixels' most
 * common value (the ambient term), the lit ones' (v - ambient) / (L.N)
 * (II).  Where none of that fits, it says where the differences lie
 * (which sphere, which part of the background).
 */

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

rayo_compare_finding *tone_scene_add(rayo_compare_report *r,
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

void tone_scene_ball_at(const scene_work *w, int b, rayo_compare_finding *f)
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
            rayo_compare_finding *f = tone_scene_add(w->r,
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
   Ia ka M (colour) or IA (gray), in float as the student's program. */
static int ambient_byte(const scene_work *w, int b, unsigned c)
{
    const rayo_course_ball *ball = &w->data->balls[b];
    float a = (float)w->data->ambient[c], ka = (float)ball->ka;
    float m = (float)ball->color[c], v;
    if (w->gray)
        return (int)a;
    v = a * ka;
    v = v * m;
    return (int)(255 * v);
}

/* The unlit pixels' most common value: the ambient term (gray: of every
   sphere; colour: per channel, of the spheres whose ka M is 1 there). */
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
            if (w->gray ||
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
        expected = w->gray
                       ? (int)w->data->ambient[c]
                       : (int)(255 * (float)w->data->ambient[c]);
        if (mode[c] - expected > (int)w->levels ||
            expected - mode[c] > (int)w->levels)
            off = 1;
    }
    if (off) {
        rayo_compare_finding *f = tone_scene_add(w->r, RAYO_FINDING_AMBIENT);
        if (f == NULL)
            return;
        for (c = 0; c < w->n; c++) {
            f->expected[c] = w->data->ambient[c];
            /* colour: the byte is the integer part of 255 Ia */
            f->value[c] = w->gray
                              ? mode[c]
                              : (mode[c] + 0.5) / 255.0;
            f->pixels += most[c];
            f->total += total[c];
        }
    }
}

/* The gray model's light intensity: the median of (v - IA) / (L.N)
   over lit pixels the clamp does not reach, named when most agree on a
   value off the statement's II. */
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
        rayo_compare_finding *f = tone_scene_add(w->r, RAYO_FINDING_LIGHT);
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
    uint64_t per_ball[SCENE_BALLS], count = 0, most = 0;
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
        rayo_compare_finding *f = tone_scene_add(w->r,
                                              RAYO_FINDING_BELOW_AMBIENT);
        if (f == NULL)
            return;
        tone_scene_ball_at(w, best, f);
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
    uint64_t differ[SCENE_BALLS + 1], total[SCENE_BALLS + 1];
    int32_t box[4] = {INT32_MAX, INT32_MAX, -1, -1};
    int shown[SCENE_BALLS + 1];
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
        if (most < FEW || (f = tone_scene_add(w->r, RAYO_FINDING_WHERE)) ==
                              NULL)
            break;
        shown[best] = 1;
        f->pixels = most;
        f->total = total[best];
        if (best > 0)
            tone_scene_ball_at(w, (int)best - 1, f);
        else
            memcpy(f->box, box, sizeof box);
    }
}

rayo_status tone_scene_find(const tone_image *ref, const tone_image *image,
                            int course, rayo_compare_report *r,
                            int *named, rayo_error *err)
{
    const rayo_course_info *info =
        rayo_course_info_of((rayo_course_exercise)course);
    scene_work w;
    rayo_status s;
    *named = 0;
    r->tone.findings = 0;
    if (info == NULL || !info->student_model)
        return RAYO_OK;
    if (ref->width != info->width || ref->height != info->height ||
        image->width != ref->width || image->height != ref->height ||
        ref->channels != image->channels ||
        ref->channels != (info->kind == RAYO_COURSE_GRAY ? 1u : 3u))
        return RAYO_OK;
    memset(&w, 0, sizeof w);
    w.ref = ref;
    w.image = image;
    w.r = r;
    w.n = ref->channels;
    w.levels = r->tone.levels;
    w.gray = tone_course_gray(course);
    w.data = rayo_course_data_of((rayo_course_exercise)course);
    if (w.data == NULL || w.data->ball_count > SCENE_BALLS)
        return RAYO_OK;
    if ((s = map_of((rayo_course_exercise)course, &w.map, err)) != RAYO_OK)
        return s;
    find_background(&w);
    if ((s = tone_scene_objects(&w, err)) != RAYO_OK)
        return s;
    find_ambient(&w);
    if (w.gray && !tone_scene_light_direction(&w))
        find_light(&w);
    if (!w.gray) {
        tone_scene_lamp_colours(&w);
        tone_scene_lamp_position(&w);
        tone_scene_sun_direction(&w);
    }
    find_below(&w);
    *named = r->tone.findings > 0;
    if (!*named)
        find_where(&w);
    return RAYO_OK;
}

/* Whether the findings are only the ambient term (and the background,
   which an ambient of the same value may colour), changed by the
   offset found on the objects: an IA of 20 for 5 is an offset of +15
   on every sphere, and the scene's words say which constant it is. */
static int ambient_is_offset(const rayo_compare_report *r,
                             const int *offset)
{
    unsigned i, c, ambient = 0;
    for (i = 0; i < r->tone.findings; i++) {
        const rayo_compare_finding *f = &r->tone.finding[i];
        if (f->kind == RAYO_FINDING_BACKGROUND)
            continue;
        if (f->kind != RAYO_FINDING_AMBIENT)
            return 0;
        for (c = 0; c < r->tone.channels; c++) {
            double seen = tone_course_gray(r->tone.course)
                              ? f->value[c] - f->expected[c]
                              : 255 * (f->value[c] - f->expected[c]);
            if (fabs(seen - offset[c]) > r->tone.levels + 1)
                return 0;
        }
        ambient = 1;
    }
    return ambient;
}

rayo_status tone_scene_diagnose(const tone_image *ref,
                                const tone_image *image, int found,
                                const int *offset, rayo_compare_report *r,
                                rayo_error *err)
{
    int named = 0;
    rayo_status s;
    if (r->tone.course < 0 || (found && offset == NULL))
        return RAYO_OK;
    s = tone_scene_find(ref, image, r->tone.course, r, &named, err);
    if (s != RAYO_OK)
        return s;
    if (offset != NULL && !(named && ambient_is_offset(r, offset))) {
        r->tone.findings = 0; /* the offset says it as well */
        return RAYO_OK;
    }
    if (named) {
        r->diagnosis = RAYO_DIAGNOSIS_SCENE;
        r->diagnosis_exact = 0;
    }
    return RAYO_OK;
}
