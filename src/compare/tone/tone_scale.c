/*
 * tone_scale.c - the scale about the optical centre that brings the
 * image closest to the reference (another focal distance or field of
 * view), searched on a sampled grid and then finer, each pass stopped
 * once it is past the best so far.
 *
 * The smallest sum of squared differences wins; the search is the
 * diagnosis's (tone_diagnose.c), which decides whether the scale found
 * explains the image.  Not an optimiser: two rounds of fixed candidates.
 */
#include <math.h>
#include <stdint.h>

#include "tone_impl.h"

static double squares_of(const tone_counts *k)
{
    return k->sum_squares[0] + k->sum_squares[1] + k->sum_squares[2];
}

/* The sum of squares of a pass at scale t->scale, or UINT64_MAX when
   it is sure to be more than limit (the pass stopped there). */
static uint64_t scale_squares(const tone_image *ref, const tone_image *image,
                              tone_xform *t, unsigned levels, uint64_t limit)
{
    tone_counts k;
    t->capped = limit != UINT64_MAX;
    t->max_squares = limit;
    t->max_differing = UINT64_MAX;
    tone_measure(ref, image, t, 0, levels, -1, &k);
    if (k.stopped)
        return UINT64_MAX;
    return (uint64_t)squares_of(&k);
}

/*
 * The candidates of a round are tried from the middle of the range out
 * (i = mid, mid - 1, mid + 1, ...), where the good ones are likely, and
 * each pass stops once its sum of squares is past the best so far: the
 * scale chosen is still the first of the round's order i = 0, 1, ...
 * with the smallest sum (ties go to the smaller i), that of trying them
 * all in order to the end.  A later round keeps an earlier round's best
 * on a tie.
 */
static void scale_round(const tone_image *ref, const tone_image *image,
                        unsigned levels, tone_xform *t, uint32_t count,
                        double lo, double hi, double ratio, int geometric,
                        double *best, uint64_t *fewest)
{
    uint32_t mid = count / 2, d, side, i, found = UINT32_MAX;
    for (d = 0; d <= mid || mid + d < count; d++)
        for (side = 0; side < 2; side++) {
            uint64_t sq;
            /* mid, then mid - 1, mid + 1, mid - 2, mid + 2, ... */
            if ((d == 0 && side) || (side == 0 && d > mid) ||
                (side && mid + d >= count))
                continue;
            i = side ? mid + d : mid - d;
            t->scale = geometric ? lo * pow(ratio, i)
                                 : lo + (hi - lo) * i / (count - 1);
            sq = scale_squares(ref, image, t, levels, *fewest);
            if (sq < *fewest || (sq == *fewest && found != UINT32_MAX &&
                                 i < found)) {
                *fewest = sq;
                *best = t->scale;
                found = i;
            }
        }
}

double tone_best_scale(const tone_image *ref, const tone_image *image,
                       unsigned levels, double lo, double hi,
                       uint64_t *left, double *squares)
{
    double pixels = (double)ref->width * ref->height, best = 1, ratio;
    uint64_t fewest = UINT64_MAX;
    uint32_t step = (uint32_t)ceil(sqrt(pixels / 65536.0));
    tone_xform t = tone_identity();
    tone_counts k;
    const uint32_t scan = 41, fine = 21;
    t.kind = TONE_SCALE;
    t.step = step > 0 ? step : 1;
    ratio = pow(hi / lo, 1.0 / (scan - 1));
    scale_round(ref, image, levels, &t, scan, lo, hi, ratio, 1, &best,
                &fewest);
    lo = best / ratio;
    hi = best * ratio;
    scale_round(ref, image, levels, &t, fine, lo, hi, ratio, 0, &best,
                &fewest);
    t = tone_identity();
    t.kind = TONE_SCALE;
    t.scale = best;
    tone_measure(ref, image, &t, 0, levels, -1, &k);
    *left = k.differing;
    *squares = squares_of(&k);
    return best;
}
