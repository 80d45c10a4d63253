/*
 * tone_diagnose.c - the verdict of a tone comparison and, for an
 * inconsistent image, the one mistake that explains it.
 *
 * As for masks (diagnose.c), each candidate is undone on the image and
 * the images compared again; a candidate is named when nothing
 * unexplained is left, or at most a twentieth of it.  The candidates:
 * the course's typical mistakes, when the reference shows one of the
 * course's scenes (the image is compared with rayo's render of that
 * scene with the mistake: course.h); channels in another order; flips;
 * inversion; a whole-pixel shift; a scale about the centre (the focal
 * distance or the field of view); a constant offset, everywhere or on
 * the objects only (a missing ambient term); values wrapped past 255.
 * Among those that fit, the fewest unexplained pixels win, then the
 * first tried; the rounds are in try_all.  Consistent needs nothing
 * unexplained and the differences at most RAYO_COMPARE_BAND_SHARE of
 * the pixels where they could be explained (tone_band): a reference busy
 * everywhere explains anything.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../course/course_impl.h"
#include "../compare_impl.h"
#include "tone_impl.h"

#define CLOSE_REDUCTION 20
#define SHIFT_RANGE 3

typedef struct choice {
    int found;
    uint64_t unexplained, differing;
    tone_xform t;
    int mistake; /* >= 0: a course mistake instead of t */
} choice;

/* Caps a candidate's pass at what could still make it fit (consider). */
static void cap(tone_xform *t, const rayo_compare_report *r)
{
    t->capped = 1;
    t->max_unexplained = r->tone.unexplained / CLOSE_REDUCTION;
    t->max_differing = r->tone.differing / 2;
}

static void consider(choice *ch, const rayo_compare_report *r,
                     const tone_counts *k, const tone_xform *t, int mistake)
{
    /* A candidate must read at least an eighth of the picture from the
       image (a scale up to about 2.8 does), not bring in black. */
    if (k->stopped || 8 * k->placed < r->pixels)
        return;
    if ((k->unexplained != 0 &&
         k->unexplained * CLOSE_REDUCTION > r->tone.unexplained) ||
        2 * k->differing > r->tone.differing)
        return;
    if (ch->found && (k->unexplained > ch->unexplained ||
                      (k->unexplained == ch->unexplained &&
                       k->differing >= ch->differing)))
        return;
    ch->found = 1;
    ch->unexplained = k->unexplained;
    ch->differing = k->differing;
    if (t != NULL)
        ch->t = *t;
    ch->mistake = mistake;
}

/* A choice that leaves no pixel differing: nothing can beat it. */
static int unbeatable(const choice *ch)
{
    return ch->found && ch->unexplained == 0 && ch->differing == 0;
}

/* cap, and also stop a pass once it cannot beat the choice so far:
   more unexplained pixels than it, or, when it leaves none, as many
   differing (consider would turn the candidate down then). */
static void cap_to_beat(tone_xform *t, const rayo_compare_report *r,
                        const choice *ch)
{
    cap(t, r);
    if (!ch->found)
        return;
    if (ch->unexplained < t->max_unexplained)
        t->max_unexplained = ch->unexplained;
    if (ch->unexplained == 0 && ch->differing > 0 &&
        ch->differing - 1 < t->max_differing)
        t->max_differing = ch->differing - 1;
}

static void try_xform(choice *ch, const tone_image *ref,
                      const tone_image *image, const rayo_compare_report *r,
                      const tone_xform *t)
{
    tone_counts k;
    tone_xform capped = *t;
    if (unbeatable(ch))
        return;
    cap_to_beat(&capped, r, ch);
    tone_measure(ref, image, &capped, r->tolerance, r->tone.levels, 0, &k);
    consider(ch, r, &k, t, -1);
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
        t->width = RAYO_COURSE_WIDTH;
        t->height = RAYO_COURSE_HEIGHT;
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
   consistent with (only for 640x480, gray for EJ2 and colour for EJ3).
   keep (may be NULL) receives that render when one is found. */
static rayo_status detect_course(const tone_image *ref,
                                 const rayo_compare_report *r, int *course,
                                 tone_image *keep, rayo_error *err)
{
    rayo_course_exercise e =
        ref->channels == 1 && r->tone.reference_channels == 1
            ? RAYO_COURSE_EJ2
            : RAYO_COURSE_EJ3;
    tone_image t;
    tone_counts k;
    tone_xform id = tone_identity();
    rayo_status s;
    int radius = tone_radius(r->tolerance);
    int key = (int)r->tone.reference_channels;
    *course = -1;
    if (ref->width != 640 || ref->height != 480)
        return RAYO_OK;
    if (e == RAYO_COURSE_EJ3 && r->tone.reference_channels != 3)
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
    if (image->width != RAYO_COURSE_WIDTH ||
        image->height != RAYO_COURSE_HEIGHT)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "compare: the course's render is %ux%u, the "
                              "image %ux%u",
                              RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT,
                              image->width, image->height);
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
        if (unbeatable(ch))
            break;
        if (!rayo_course_mistake_applies((rayo_course_exercise)course,
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
        cap_to_beat(&id, r, ch);
        tone_measure(&t, image, &id, r->tolerance, r->tone.levels, 0, &k);
        tone_image_free(&t);
        consider(ch, r, &k, NULL, m);
    }
    return RAYO_OK;
}

static void try_permutations(choice *ch, const tone_image *ref,
                             const tone_image *image,
                             const rayo_compare_report *r)
{
    static const unsigned char perms[5][3] = {
        {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    tone_xform t = tone_identity();
    size_t i;
    if (ref->channels != 3)
        return;
    t.kind = TONE_PERMUTE;
    for (i = 0; i < 5; i++) {
        memcpy(t.perm, perms[i], 3);
        try_xform(ch, ref, image, r, &t);
    }
}

/* The whole-pixel shift, |dx|, |dy| <= SHIFT_RANGE, that leaves the
   fewest differing pixels (on a sampled grid); of those the first in
   the order dy, then dx, from -SHIFT_RANGE up.  The shifts are tried
   nearest first (rings |dx|, |dy| <= 1, 2, 3), where the fit is likely,
   and a pass stops once it differs in more pixels than the best so far:
   the same shift as trying all to the end in that order. */
static tone_xform best_shift(const tone_image *ref, const tone_image *image,
                             unsigned levels, uint64_t *fewest)
{
    double pixels = (double)ref->width * ref->height;
    tone_xform t = tone_identity(), best = tone_identity();
    tone_counts k;
    int dx, dy, ring, order, best_order = 0;
    t.kind = TONE_SHIFT;
    t.step = (uint32_t)ceil(sqrt(pixels / 262144.0));
    if (t.step < 1)
        t.step = 1;
    *fewest = UINT64_MAX;
    for (ring = 1; ring <= SHIFT_RANGE; ring++)
        for (dy = -ring; dy <= ring; dy++)
            for (dx = -ring; dx <= ring; dx++) {
                if (dx != ring && dx != -ring && dy != ring && dy != -ring)
                    continue; /* an inner ring's */
                order = (dy + SHIFT_RANGE) * (2 * SHIFT_RANGE + 1) +
                        (dx + SHIFT_RANGE);
                t.dx = dx;
                t.dy = dy;
                t.capped = *fewest != UINT64_MAX;
                t.max_differing = *fewest;
                tone_measure(ref, image, &t, 0, levels, -1, &k);
                if (k.stopped)
                    continue;
                if (k.differing < *fewest ||
                    (k.differing == *fewest && order < best_order)) {
                    *fewest = k.differing;
                    best = t;
                    best_order = order;
                }
            }
    best.step = 1;
    best.capped = 0;
    best.max_differing = 0;
    return best;
}

/* The most common difference (image - reference) of differing pixels,
   per channel, leaving out image values that may have been clamped. */
static void common_offset(const tone_image *ref, const tone_image *image,
                          unsigned levels, int *offset)
{
    uint64_t hist[3][511];
    uint32_t x, y;
    unsigned c, n = ref->channels;
    int v;
    memset(hist, 0, sizeof hist);
    for (y = 0; y < ref->height; y++)
        for (x = 0; x < ref->width; x++) {
            const unsigned char *a = tone_pixel(ref, x, y);
            const unsigned char *b = tone_pixel(image, x, y);
            for (c = 0; c < n; c++) {
                int d = (int)b[c] - (int)a[c];
                /* values at 0 or 255 may have been clamped there */
                if (b[c] != 0 && b[c] != 255 &&
                    (d > (int)levels || -d > (int)levels))
                    hist[c][d + 255]++;
            }
        }
    for (c = 0; c < n; c++) {
        uint64_t most = 0;
        offset[c] = 0;
        for (v = 0; v < 511; v++)
            if (hist[c][v] > most) {
                most = hist[c][v];
                offset[c] = v - 255;
            }
    }
}

static int all_black(const tone_image *image)
{
    size_t i, n = (size_t)image->width * image->height * image->channels;
    for (i = 0; i < n; i++)
        if (image->v[i] != 0)
            return 0;
    return 1;
}

static rayo_compare_diagnosis diagnosis_of(tone_kind kind)
{
    switch (kind) {
    case TONE_FLIP_V:
        return RAYO_DIAGNOSIS_FLIPPED_VERTICALLY;
    case TONE_FLIP_H:
        return RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY;
    case TONE_FLIP_BOTH:
        return RAYO_DIAGNOSIS_ROTATED_180;
    case TONE_SHIFT:
        return RAYO_DIAGNOSIS_SHIFTED;
    case TONE_SCALE:
        return RAYO_DIAGNOSIS_SCALED;
    case TONE_PERMUTE:
        return RAYO_DIAGNOSIS_CHANNELS_SWAPPED;
    case TONE_INVERT:
        return RAYO_DIAGNOSIS_INVERTED;
    case TONE_OFFSET:
    case TONE_OFFSET_ON_SHAPES:
        return RAYO_DIAGNOSIS_OFFSET;
    case TONE_WRAPPED:
        return RAYO_DIAGNOSIS_WRAPPED;
    default:
        return RAYO_DIAGNOSIS_UNKNOWN;
    }
}

static void name_choice(const choice *ch, rayo_compare_report *r)
{
    r->diagnosis_exact = ch->unexplained == 0;
    if (ch->mistake >= 0) {
        r->diagnosis = RAYO_DIAGNOSIS_MISTAKE;
        r->tone.mistake = (rayo_course_mistake)ch->mistake;
        return;
    }
    r->diagnosis = diagnosis_of(ch->t.kind);
    r->shift_x = ch->t.dx;
    r->shift_y = ch->t.dy;
    r->scale_found = ch->t.scale;
    memcpy(r->tone.order, ch->t.perm, 3);
    memcpy(r->tone.offset, ch->t.offset, sizeof r->tone.offset);
    r->tone.offset_on_shapes = ch->t.kind == TONE_OFFSET_ON_SHAPES;
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
        if (!rayo_course_mistake_applies((rayo_course_exercise)course,
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
static rayo_status look_for_hidden(const tone_image *ref,
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
    if (s == RAYO_OK && course >= 0 && course < RAYO_COURSE_EXERCISES &&
        course != RAYO_COURSE_EJ1 && ref->width == 640 && ref->height == 480)
        s = hidden_mistake(image, course, detected ? &right : NULL, r, err);
    tone_image_free(&right);
    return s;
}

/* Every difference explained: consistent, unless a whole-pixel shift
   of the image removes most of them (then it is a mistake). */
static void judge_close(const tone_image *ref, const tone_image *image,
                        rayo_compare_report *r)
{
    uint64_t fewest;
    tone_xform t = best_shift(ref, image, r->tone.levels, &fewest);
    tone_counts k;
    r->verdict = RAYO_VERDICT_CONSISTENT;
    if (t.dx > 1 || t.dx < -1 || t.dy > 1 || t.dy < -1)
        return; /* far shifts are rounding's look-alikes only when tiny */
    tone_measure(ref, image, &t, 0, r->tone.levels, -1, &k);
    if (2 * k.differing > r->tone.differing)
        return;
    r->verdict = RAYO_VERDICT_INCONSISTENT;
    r->diagnosis = RAYO_DIAGNOSIS_SHIFTED;
    r->diagnosis_exact = 1;
    r->shift_x = t.dx;
    r->shift_y = t.dy;
}

/* A candidate that leaves nothing unexplained ends the search. */
static int exact(const choice *ch)
{
    return ch->found && ch->unexplained == 0;
}

/* Three rounds, each only when the ones before found nothing exact:
   what the picture shows wrongly (channels, flips, inversion, shift,
   scale), cheap to undo; the course's mistakes, a render each, which
   name the line of code; then constant offsets and wrapped values,
   which the course's mistakes explain better when they can (no
   ambient is an offset on the objects). */
static rayo_status try_all(const tone_image *ref, const tone_image *image,
                           const rayo_compare_options *options,
                           rayo_compare_report *r, choice *ch,
                           rayo_error *err)
{
    static const tone_kind plain[] = {TONE_FLIP_V, TONE_FLIP_H,
                                      TONE_FLIP_BOTH, TONE_INVERT};
    tone_xform t = tone_identity();
    uint64_t fewest;
    double squares;
    int course = options->course;
    size_t i;
    rayo_status s = RAYO_OK;
    try_permutations(ch, ref, image, r);
    for (i = 0; i < sizeof plain / sizeof plain[0]; i++) {
        t.kind = plain[i];
        try_xform(ch, ref, image, r, &t);
    }
    /* (Each search only when its candidate could still win.) */
    if (unbeatable(ch))
        return RAYO_OK;
    t = best_shift(ref, image, r->tone.levels, &fewest);
    try_xform(ch, ref, image, r, &t);
    if (unbeatable(ch))
        return RAYO_OK;
    t = tone_identity();
    t.kind = TONE_SCALE;
    t.scale = tone_best_scale(ref, image, r->tone.levels, 0.25, 4.0,
                              &fewest, &squares);
    if (fabs(t.scale - 1) >= 0.004)
        try_xform(ch, ref, image, r, &t);
    if (exact(ch))
        return RAYO_OK;
    if (course == RAYO_COMPARE_COURSE_AUTO)
        s = detect_course(ref, r, &course, NULL, err);
    if (s != RAYO_OK)
        return s;
    /* EJ3's colour renders are not compared with a gray pair. */
    if (course >= 0 && course < RAYO_COURSE_EXERCISES &&
        course != RAYO_COURSE_EJ1 && ref->width == 640 &&
        ref->height == 480 &&
        !(course == RAYO_COURSE_EJ3 && ref->channels == 1)) {
        r->tone.course = course;
        if ((s = try_mistakes(ch, image, course, r, err)) != RAYO_OK)
            return s;
    }
    if (exact(ch))
        return RAYO_OK;
    /* On the objects first: on a black background both fit, and the
       objects-only one says more (a missing ambient term). */
    t = tone_identity();
    common_offset(ref, image, r->tone.levels, t.offset);
    t.kind = TONE_OFFSET_ON_SHAPES;
    try_xform(ch, ref, image, r, &t);
    t.kind = TONE_OFFSET;
    try_xform(ch, ref, image, r, &t);
    t = tone_identity();
    t.kind = TONE_WRAPPED;
    try_xform(ch, ref, image, r, &t);
    return RAYO_OK;
}

rayo_status tone_diagnose(const tone_image *ref, const tone_image *image,
                          const rayo_compare_options *options,
                          rayo_compare_report *r, rayo_error *err)
{
    choice ch;
    rayo_status s;
    r->diagnosis = RAYO_DIAGNOSIS_NONE;
    r->scale_found = 1;
    if (ref->width != image->width || ref->height != image->height) {
        r->verdict = RAYO_VERDICT_INCONSISTENT;
        r->diagnosis = RAYO_DIAGNOSIS_DIFFERENT_SIZE;
        return RAYO_OK;
    }
    if (r->tone.differing == 0) {
        r->verdict = RAYO_VERDICT_IDENTICAL;
        return RAYO_OK;
    }
    if (r->tone.unexplained == 0) {
        judge_close(ref, image, r);
        if (r->verdict != RAYO_VERDICT_CONSISTENT)
            return RAYO_OK;
        r->band = tone_band(ref);
        if (!cmp_crowded(r->tone.differing, r->band))
            return look_for_hidden(ref, image, options, r, err);
        r->crowded = 1;
    }
    r->verdict = RAYO_VERDICT_INCONSISTENT;
    if (all_black(image)) {
        r->diagnosis = RAYO_DIAGNOSIS_EMPTY;
        return RAYO_OK;
    }
    memset(&ch, 0, sizeof ch);
    ch.mistake = -1;
    s = try_all(ref, image, options, r, &ch, err);
    if (s != RAYO_OK)
        return s;
    if (ch.found)
        name_choice(&ch, r);
    else
        r->diagnosis = RAYO_DIAGNOSIS_UNKNOWN;
    /* against the course's scene when nothing, or only an offset on
       the objects, was found (tone_scene.c) */
    return tone_scene_diagnose(
        ref, image, ch.found,
        ch.found && ch.mistake < 0 && ch.t.kind == TONE_OFFSET_ON_SHAPES
            ? ch.t.offset
            : NULL,
        r, err);
}
