/*
 * band.c - the outline's neighbourhood: how many reference pixels lie
 * within the tolerance of a pixel of the other colour.
 *
 * Every mismatch within the tolerance lies in this band, and a picture
 * drawn a pixel or two apart changes only a part of it.  The consistency
 * rule (diagnose.c, docs/compare.md) compares the mismatches with this
 * count, and with what chance would give (cmp_chance_limit), so that an
 * image whose mismatches are near an outline only because the reference
 * is all outline (a checkerboard against its inverse, noise) is not
 * called consistent.  Counted with near.c's dilations for small
 * tolerances and outline.c's exact distances beyond.
 */
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

/*
 * A picture drawn a pixel or two apart (another focal distance, float
 * instead of double, off-by-one outlines): an outline moved by d <= t
 * pixels turns d of the 2t pixels across the band, at most half where it
 * is straight, a little more on the outside of a curve
 * (RAYO_COMPARE_BAND_SHARE).  The band is counted in a pass over the
 * reference, made only when every mismatch is within the tolerance.
 *
 * Where the reference is noise or a checkerboard, the band is the whole
 * frame, and any unrelated image mismatches about half of it: the share
 * alone is then a coin toss, and so is "fewer than chance", which an
 * unrelated image meets half the time.  So a consistent image must agree
 * with the reference clearly better than chance: at most half the
 * mismatches of an image with as many black pixels placed at random
 * (cmp_chance_limit; docs/compare.md has the bound on the luck left).
 */

/* Pixels of row (bits of one colour, padding clear) within the
 * tolerance of the other colour, from its exact distances. */
static uint64_t near_by_distance(cmp_outline *outline, uint32_t y,
                                 int colour, const unsigned char *row,
                                 uint32_t width, double tolerance,
                                 int64_t *d2)
{
    uint64_t near = 0;
    uint32_t x;
    double tol2 = tolerance * tolerance;
    cmp_outline_mismatch_distances(outline, y, !colour, row, d2);
    for (x = 0; x < width; x++)
        if (rayo_bit_get(row, x) && !((double)d2[x] > tol2))
            near++;
    return near;
}

rayo_status cmp_outline_band(const cmp_mask *ref, cmp_outline *outline,
                             double tolerance, uint64_t *band,
                             rayo_error *err)
{
    size_t n = cmp_row_bytes(ref->width), k;
    unsigned char *rows = malloc(2 * n);
    int64_t *d2 = NULL;
    cmp_near *near = NULL;
    rayo_status s = RAYO_OK;
    uint32_t y;
    *band = 0;
    if (!cmp_outline_has_edges(outline)) {
        free(rows);
        return RAYO_OK; /* no outline: nothing is near one */
    }
    if (rows == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for rows of %u pixels",
                              ref->width);
    if (tolerance <= CMP_NEAR_MAX_TOLERANCE)
        s = cmp_near_create(&near, ref, tolerance, err);
    else if ((d2 = malloc((size_t)ref->width * sizeof *d2)) == NULL)
        s = rayo_error_set(err, RAYO_ERR_NOMEM,
                           "compare: out of memory for rows of %u pixels",
                           ref->width);
    if (s == RAYO_OK && near == NULL)
        cmp_outline_rewind(outline, 0);
    for (y = 0; s == RAYO_OK && y < ref->height; y++) {
        unsigned char *black = rows, *white = rows + n;
        const unsigned char *r = cmp_mask_row(ref, y);
        for (k = 0; k < n; k++) {
            black[k] = r[k];
            white[k] = (unsigned char)~r[k];
        }
        cmp_clear_padding(black, ref->width);
        cmp_clear_padding(white, ref->width);
        if (near != NULL) {
            *band += cmp_popcount(black, n) - cmp_near_count_far(near, y, 0,
                                                                 black);
            *band += cmp_popcount(white, n) - cmp_near_count_far(near, y, 1,
                                                                 white);
        } else {
            *band += near_by_distance(outline, y, 1, black, ref->width,
                                      tolerance, d2);
            *band += near_by_distance(outline, y, 0, white, ref->width,
                                      tolerance, d2);
        }
    }
    cmp_near_free(near);
    free(d2);
    free(rows);
    return s;
}

double cmp_chance_mismatches(uint64_t pixels, uint64_t reference_black,
                             uint64_t image_black)
{
    double n = (double)pixels, r = (double)reference_black;
    double i = (double)image_black;
    return n > 0 ? (r * (n - i) + i * (n - r)) / n : 0;
}

double cmp_chance_limit(uint64_t pixels, uint64_t reference_black,
                        uint64_t image_black)
{
    return CMP_CHANCE_SHARE *
           cmp_chance_mismatches(pixels, reference_black, image_black);
}

int cmp_mask_crowded(const rayo_compare_report *r)
{
    return cmp_crowded(r->mismatches, r->band) ||
           (double)r->mismatches >
               cmp_chance_limit(r->pixels, r->reference_black,
                                r->image_black);
}
