/*
 * tone_diagnose.c - the verdict of a tone comparison and, for an
 * inconsistent image, the one mistake that explains it.
 *
 * As for masks (mask/diagnose.c), each candidate is undone on the image and
 * the images compared again, and named when at most a twentieth of the
 * unexplained pixels is left.  The candidates here: channels in another
 * order, flips, inversion, a whole-pixel shift, a scale about the
 * centre, a constant offset (everywhere or on the objects), values
 * wrapped past 255; the course's mistakes are tone_mistakes.c's.  The
 * fewest unexplained pixels win (try_all).  Consistent needs nothing
 * unexplained and few differences where they could be (tone_band).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_choice.h"

#define SHIFT_RANGE 3

typedef tone_choice choice;

/* Caps a candidate's pass at what could still make it fit (consider). */
static void cap(tone_xform *t, const rayo_compare_report *r)
{
    t->capped = 1;
    t->max_unexplained = r->tone.unexplained / CLOSE_REDUCTION;
    t->max_differing = r->tone.differing / 2;
}

void tone_choice_consider(choice *ch, const rayo_compare_report *r,
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

int tone_choice_unbeatable(const choice *ch)
{
    return ch->found && ch->unexplained == 0 && ch->differing == 0;
}

/* cap, and also stop a pass once it cannot beat the choice so far:
   more unexplained pixels than it, or, when it leaves none, as many
   differing (consider would turn the candidate down then). */
void tone_choice_cap(tone_xform *t, const rayo_compare_report *r,
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
    if (tone_choice_unbeatable(ch))
        return;
    tone_choice_cap(&capped, r, ch);
    tone_measure(ref, image, &capped, r->tolerance, r->tone.levels, 0, &k);
    tone_choice_consider(ch, r, &k, t, -1);
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
    size_t i;
    rayo_status s = RAYO_OK;
    try_permutations(ch, ref, image, r);
    for (i = 0; i < sizeof plain / sizeof plain[0]; i++) {
        t.kind = plain[i];
        try_xform(ch, ref, image, r, &t);
    }
    /* (Each search only when its candidate could still win.) */
    if (tone_choice_unbeatable(ch))
        return RAYO_OK;
    t = best_shift(ref, image, r->tone.levels, &fewest);
    try_xform(ch, ref, image, r, &t);
    if (tone_choice_unbeatable(ch))
        return RAYO_OK;
    t = tone_identity();
    t.kind = TONE_SCALE;
    t.scale = tone_best_scale(ref, image, r->tone.levels, 0.25, 4.0,
                              &fewest, &squares);
    if (fabs(t.scale - 1) >= 0.004)
        try_xform(ch, ref, image, r, &t);
    if (exact(ch))
        return RAYO_OK;
    if ((s = tone_try_mistakes(ref, image, options, r, ch, err)) != RAYO_OK)
        return s;
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
            return tone_look_for_hidden(ref, image, options, r, err);
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
