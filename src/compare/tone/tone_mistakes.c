/*
 * tone_mistakes.c - the course's typical mistakes as candidates of the
 * tone diagnosis: when the reference is the right render of one of the
 * course's scenes (detected, or named by the options), the image is
 * compared with the student model's render of that scene with each
 * mistake that applies, and the one that explains it is named.  Also a
 * consistent image's hidden mistake, one the reference cannot see.
 *
 * Which exercise a picture can be, and whether a model covers it, the
 * course's registry says (rayo/course/course.h).  Renders come from
 * tone_cache.c when an earlier comparison made them.  Not the other
 * candidates (flips, shifts, offsets): tone_diagnose.c.
 */
#include <stdlib.h>
#include <string.h>

#include "rayo/course/course.h"
#include "rayo/course/course_scene.h"

#include "tone_choice.h"

typedef tone_choice choice;

/* The registry's entry of course when its student model covers it and
   the reference is a picture of its size; NULL otherwise. */
static const rayo_course_info *modelled(int course, const tone_image *ref)
{
    const rayo_course_info *info =
        course >= 0 ? rayo_course_info_of((rayo_course_exercise)course)
                    : NULL;
    if (info == NULL || !info->student_model || ref->width != info->width ||
        ref->height != info->height)
        return NULL;
    return info;
}

/* Rayo's render of the course's exercise with mistake m as a tone
   image of `channels`, its edges found for the report's tolerance and
   levels (edges 0: not needed). */
static rayo_status course_tone(rayo_course_exercise e, rayo_course_mistake m,
                               unsigned channels, int edges,
                               const rayo_compare_report *r, tone_image *t,
                               rayo_error *err)
{
    rayo_course_options o;
    rayo_image render;
    rayo_status s;
    int right = m == RAYO_MISTAKE_NONE;
    rayo_course_options_init(&o);
    o.mistake = m;
    memset(t, 0, sizeof *t);
    /* The right render, the one every comparison with the course's
       scene makes, from the cache (tone_cache.c); a mistake's too when
       the cache has all its rows. */
    if (!right) {
        const rayo_course_info *info = rayo_course_info_of(e);
        t->width = info->width;
        t->height = info->height;
        t->channels = channels;
        t->v = malloc((size_t)t->width * t->height * channels);
        if (t->v == NULL ||
            tone_cache_find_rows((int)e, (int)m, t) < t->height)
            tone_image_free(t);
    }
    if (right ? !tone_cache_find_course((int)e, channels, t) : t->v == NULL) {
        s = rayo_course_render(e, &o, &render, err);
        if (s != RAYO_OK)
            return s;
        s = tone_image_make(&render, channels, t, err);
        rayo_image_free(&render);
        if (s != RAYO_OK)
            return s;
        if (right)
            tone_cache_keep_course((int)e, t);
        else
            tone_cache_keep_rows((int)e, (int)m, t, t->height);
    }
    s = RAYO_OK;
    if (edges)
        s = right ? tone_image_find_edges_kept(t, r->tolerance,
                                               r->tone.levels, err)
                  : tone_image_find_edges(t, r->tolerance, r->tone.levels,
                                          err);
    if (s != RAYO_OK)
        tone_image_free(t);
    return s;
}

/* The course exercise the reference shows: the one whose render it is
   consistent with (the exercise whose pictures are of the reference's
   kind, gray or colour, when a model covers it and it has its size).
   keep (may be NULL) receives that render when one is found. */
static rayo_status detect_course(const tone_image *ref,
                                 const rayo_compare_report *r, int *course,
                                 tone_image *keep, rayo_error *err)
{
    rayo_course_kind kind =
        ref->channels == 1 && r->tone.reference_channels == 1
            ? RAYO_COURSE_GRAY
            : RAYO_COURSE_COLOUR;
    rayo_course_exercise e = rayo_course_of_kind(kind);
    tone_image t;
    tone_counts k;
    tone_xform id = tone_identity();
    rayo_status s;
    int radius = tone_radius(r->tolerance);
    int key = (int)r->tone.reference_channels;
    *course = -1;
    if (modelled((int)e, ref) == NULL)
        return RAYO_OK;
    if (kind == RAYO_COURSE_COLOUR && r->tone.reference_channels != 3)
        return RAYO_OK;
    /* Asked before about this very reference (tone_cache.c), when its
       render is not wanted. */
    if (keep == NULL &&
        tone_cache_find_detected(ref, radius, r->tone.levels, key, course))
        return RAYO_OK;
    s = course_tone(e, RAYO_MISTAKE_NONE, ref->channels, 1, r, &t, err);
    if (s != RAYO_OK)
        return s;
    id.capped = 1; /* one unexplained pixel settles it */
    id.max_unexplained = 0;
    id.max_differing = UINT64_MAX;
    tone_measure(&t, ref, &id, r->tolerance, r->tone.levels, 0, &k);
    if (!k.stopped && k.unexplained == 0)
        *course = (int)e;
    tone_cache_keep_detected(ref, radius, r->tone.levels, key, *course);
    if (keep != NULL && *course >= 0)
        *keep = t; /* the right render, for hidden_mistake */
    else
        tone_image_free(&t);
    return RAYO_OK;
}

/* Rows of a mistake's render made at a time before it is checked. */
#define RENDER_BAND 16

/* Whether the render t of a mistake, rows 0..end-1 made so far, already
   differs from the image in too many pixels for consider to take it:
   *differing counts them, from row `from` on. */
static int ruled_out(const tone_image *t, const tone_image *image,
                     const rayo_compare_report *r, const choice *ch,
                     uint32_t from, uint32_t end, uint64_t *differing)
{
    size_t i = (size_t)from * t->width * t->channels;
    size_t stop = (size_t)end * t->width * t->channels;
    unsigned c, n = t->channels, levels = r->tone.levels;
    for (; i < stop; i += n) {
        unsigned worst = 0;
        for (c = 0; c < n; c++) {
            unsigned a = t->v[i + c], b = image->v[i + c];
            unsigned d = a > b ? a - b : b - a;
            if (d > worst)
                worst = d;
        }
        *differing += worst > levels;
    }
    return 2 * *differing > r->tone.differing ||
           (ch->found && ch->unexplained == 0 && *differing >= ch->differing);
}

/* The render of mistake m as a tone image into t, made a band of rows
   at a time and given up (*out 1, t freed) as soon as the pixels that
   differ from the image rule the mistake out: consider needs them
   halved whatever is explained, and fewer than those of a choice that
   leaves nothing unexplained.  The rows an earlier comparison made come
   from the cache (tone_cache.c), checked band by band all the same, and
   the rows made here go there. */
static rayo_status mistake_render(int course, int m, const tone_image *image,
                                  const rayo_compare_report *r,
                                  const choice *ch, tone_image *t, int *out,
                                  rayo_error *err)
{
    const rayo_course_info *info =
        rayo_course_info_of((rayo_course_exercise)course);
    rayo_course_options o;
    rayo_image render;
    rayo_status s = RAYO_OK;
    uint64_t differing = 0;
    uint32_t y = 0, end, known = 0, made = 0;
    int created = 0;
    rayo_course_options_init(&o);
    o.mistake = (rayo_course_mistake)m;
    memset(t, 0, sizeof *t);
    *out = 0;
    memset(&render, 0, sizeof render);
    if (image->width != info->width || image->height != info->height)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "compare: the course's render is %ux%u, the "
                              "image %ux%u",
                              info->width, info->height, image->width,
                              image->height);
    /* tone_image_make's image, its rows converted as they come */
    t->width = image->width;
    t->height = image->height;
    t->channels = image->channels;
    t->v = malloc((size_t)t->width * t->height * t->channels);
    if (t->v == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for a %ux%u image",
                              t->width, t->height);
    known = tone_cache_find_rows(course, m, t);
    made = known;
    for (; s == RAYO_OK && y < t->height && !*out; y = end) {
        end = y + RENDER_BAND < t->height ? y + RENDER_BAND : t->height;
        if (end > known) {
            uint32_t from = y > known ? y : known;
            /* The call from row 0 creates the image (course_impl.h):
               made first, with no rows, when rows come from the cache. */
            if (!created && from > 0)
                s = rayo_course_render_student_rows(
                    (rayo_course_exercise)course, &o, &render, 0, 0, err);
            created = 1;
            if (s == RAYO_OK)
                s = rayo_course_render_student_rows(
                    (rayo_course_exercise)course, &o, &render, from, end,
                    err);
            if (s != RAYO_OK)
                break;
            tone_image_convert_rows(&render, t, from, end);
            made = end;
        }
        *out = ruled_out(t, image, r, ch, y, end, &differing);
    }
    rayo_image_free(&render); /* zeroed when never created */
    if (s == RAYO_OK && made > known)
        tone_cache_keep_rows(course, m, t, made);
    if (s != RAYO_OK || *out)
        tone_image_free(t);
    return s;
}

static rayo_status try_mistakes(choice *ch, const tone_image *image,
                                int course, const rayo_compare_report *r,
                                rayo_error *err)
{
    int m, out;
    for (m = RAYO_MISTAKE_NONE + 1; m < RAYO_MISTAKE_COUNT; m++) {
        tone_image t;
        tone_counts k;
        tone_xform id = tone_identity();
        rayo_status s;
        /* Nothing beats a candidate that leaves no pixel differing. */
        if (tone_choice_unbeatable(ch))
            break;
        if (!rayo_course_mistake_pictured((rayo_course_exercise)course,
                                          (rayo_course_mistake)m))
            continue;
        s = mistake_render(course, m, image, r, ch, &t, &out, err);
        if (s != RAYO_OK)
            return s;
        if (out)
            continue;
        s = tone_image_find_edges(&t, r->tolerance, r->tone.levels, err);
        if (s != RAYO_OK) {
            tone_image_free(&t);
            return s;
        }
        tone_choice_cap(&id, r, ch);
        tone_measure(&t, image, &id, r->tolerance, r->tone.levels, 0, &k);
        tone_image_free(&t);
        tone_choice_consider(ch, r, &k, NULL, m);
    }
    return RAYO_OK;
}

/* Pixels that differ at all between image and render. */
static uint64_t differing_at_all(const tone_image *render,
                                 const tone_image *image)
{
    tone_counts k;
    tone_xform id = tone_identity();
    tone_measure(render, image, &id, 0, 0, -1, &k);
    return k.differing;
}

/* The same against the course's render with mistake m. */
static rayo_status differing_from(const tone_image *image, int course,
                                  rayo_course_mistake m,
                                  const rayo_compare_report *r,
                                  uint64_t *count, rayo_error *err)
{
    tone_image t;
    rayo_status s = course_tone((rayo_course_exercise)course, m,
                                image->channels, 0, r, &t, err);
    if (s != RAYO_OK)
        return s;
    *count = differing_at_all(&t, image);
    tone_image_free(&t);
    return RAYO_OK;
}

/* A consistent image can still be a mistake the reference cannot see
   (values wrapped past 255 only at the limbs, say): when the render of a
   mistake agrees with the image twenty times better than the right
   render does, that mistake is named.  right_render: that render when
   detect_course made it already, else NULL. */
static rayo_status hidden_mistake(const tone_image *image, int course,
                                  const tone_image *right_render,
                                  rayo_compare_report *r, rayo_error *err)
{
    uint64_t right, best = UINT64_MAX, d;
    int m, found = -1;
    rayo_status s = RAYO_OK;
    if (right_render != NULL)
        right = differing_at_all(right_render, image);
    else
        s = differing_from(image, course, RAYO_MISTAKE_NONE, r, &right, err);
    if (s != RAYO_OK || right < CLOSE_REDUCTION)
        return s;
    for (m = RAYO_MISTAKE_NONE + 1; m < RAYO_MISTAKE_COUNT && best > 0;
         m++) {
        if (!rayo_course_mistake_pictured((rayo_course_exercise)course,
                                          (rayo_course_mistake)m))
            continue;
        if ((s = differing_from(image, course, (rayo_course_mistake)m, r, &d,
                                err)) != RAYO_OK)
            return s;
        if (d * CLOSE_REDUCTION <= right && d < best) {
            best = d;
            found = m;
        }
    }
    if (found < 0)
        return RAYO_OK;
    r->verdict = RAYO_VERDICT_INCONSISTENT;
    r->diagnosis = RAYO_DIAGNOSIS_MISTAKE;
    r->diagnosis_exact = 1;
    r->tone.course = course;
    r->tone.mistake = (rayo_course_mistake)found;
    return RAYO_OK;
}

/* A consistent image against the course's scene: the mistakes the
   reference cannot see (hidden_mistake), with the scene detected from
   the reference unless options name it. */
rayo_status tone_look_for_hidden(const tone_image *ref,
                                 const tone_image *image,
                                 const rayo_compare_options *options,
                                 rayo_compare_report *r, rayo_error *err)
{
    tone_image right;
    int course = options->course, detected = 0;
    rayo_status s = RAYO_OK;
    memset(&right, 0, sizeof right);
    if (course == RAYO_COMPARE_COURSE_AUTO) {
        s = detect_course(ref, r, &course, &right, err);
        detected = course >= 0;
    }
    if (s == RAYO_OK && modelled(course, ref) != NULL)
        s = hidden_mistake(image, course, detected ? &right : NULL, r, err);
    tone_image_free(&right);
    return s;
}

rayo_status tone_try_mistakes(const tone_image *ref, const tone_image *image,
                              const rayo_compare_options *options,
                              rayo_compare_report *r, choice *ch,
                              rayo_error *err)
{
    const rayo_course_info *info;
    int course = options->course;
    rayo_status s = RAYO_OK;
    if (course == RAYO_COMPARE_COURSE_AUTO)
        s = detect_course(ref, r, &course, NULL, err);
    if (s != RAYO_OK)
        return s;
    info = modelled(course, ref);
    /* A colour scene's renders are not compared with a gray pair. */
    if (info == NULL ||
        (info->kind == RAYO_COURSE_COLOUR && ref->channels == 1))
        return RAYO_OK;
    r->tone.course = course;
    return try_mistakes(ch, image, course, r, err);
}
