/*
 * near.c - which mismatches lie within the tolerance of the reference's
 * outline, counted a row at a time with whole words of bits.
 *
 * A mismatch within the tolerance t belongs to the other colour's set
 * dilated by the disk of radius t; the dilation is separable by rows
 * (below).  The same test as computing every mismatch's exact distance
 * and comparing it with t, at a few word operations per 64 pixels.  Only
 * for small tolerances (CMP_NEAR_MAX_TOLERANCE): the cost grows with the
 * square of t; measure.c computes exact distances beyond that.  Not a
 * general morphology library: one disk, counts only.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

/*
 * A mismatch on a reference pixel of one colour is within the tolerance
 * t when some reference pixel of the other colour lies within t of it.
 * For each row offset dy (|dy| <= t) the rows y - dy and y + dy are ORed
 * and then widened sideways by the largest dx with dx^2 + dy^2 <= t^2.
 * So the count of far mismatches does not depend on how many mismatches
 * there are, where a distance transform per mismatch would.
 */

struct cmp_near {
    const cmp_mask *ref;
    uint32_t radius;                      /* floor(t) */
    int32_t reach[CMP_NEAR_MAX_RADIUS + 1]; /* largest dx for |dy|, -1:
                                               none */
    size_t words;                         /* 64-bit words of a row */
    uint64_t last;                        /* the frame's bits of the
                                             last word */
    uint64_t *acc, *tmp, *diff;
    uint64_t *ring;                       /* the rows y - radius ..
                                             y + radius as words, row j
                                             in slot j % slots */
    int64_t ring_row[2 * CMP_NEAR_MAX_RADIUS + 1];
    uint32_t slots;
};

rayo_status cmp_near_create(cmp_near **near, const cmp_mask *ref,
                            double tolerance, rayo_error *err)
{
    double t2 = tolerance * tolerance;
    size_t words = ((size_t)ref->width + 63) / 64;
    cmp_near *n;
    int32_t dy, dx;
    *near = NULL;
    if (!(tolerance >= 0 && tolerance <= CMP_NEAR_MAX_TOLERANCE))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "compare: tolerance %g; the near test takes "
                              "0 to %g pixels",
                              tolerance, CMP_NEAR_MAX_TOLERANCE);
    n = calloc(1, sizeof *n);
    if (n == NULL ||
        words > SIZE_MAX / (3 + 2 * CMP_NEAR_MAX_RADIUS + 1) /
                    sizeof *n->acc ||
        (n->acc = malloc((3 + 2 * CMP_NEAR_MAX_RADIUS + 1) * words *
                         sizeof *n->acc)) == NULL) {
        free(n);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for rows of %u pixels",
                              ref->width);
    }
    n->ref = ref;
    n->words = words;
    n->tmp = n->acc + words;
    n->diff = n->tmp + words;
    n->ring = n->diff + words;
    n->last = ref->width % 64 ? ~(uint64_t)0 << (64 - ref->width % 64)
                              : ~(uint64_t)0;
    n->radius = (uint32_t)floor(tolerance);
    n->slots = 2 * n->radius + 1;
    for (dy = 0; dy < (int32_t)n->slots; dy++)
        n->ring_row[dy] = -1;
    for (dy = 0; dy <= (int32_t)n->radius; dy++) {
        n->reach[dy] = -1; /* as comparing the exact distance with t */
        for (dx = 0; (double)(dx * dx + dy * dy) <= t2; dx++)
            n->reach[dy] = dx;
    }
    *near = n;
    return RAYO_OK;
}

void cmp_near_free(cmp_near *near)
{
    if (near == NULL)
        return;
    free(near->acc);
    free(near);
}

/* Row bytes as big-endian words (pixel 0 in bit 63); the bytes past
 * the row's are zero. */
static void load_words(const unsigned char *row, uint32_t width,
                       uint64_t *out, size_t words)
{
    size_t n = cmp_row_bytes(width), i, k;
    for (i = 0; i + 1 < words; i++) {
        const unsigned char *p = row + 8 * i;
        out[i] = (uint64_t)p[0] << 56 | (uint64_t)p[1] << 48 |
                 (uint64_t)p[2] << 40 | (uint64_t)p[3] << 32 |
                 (uint64_t)p[4] << 24 | (uint64_t)p[5] << 16 |
                 (uint64_t)p[6] << 8 | (uint64_t)p[7];
    }
    out[i] = 0;
    for (k = 0; k < 8; k++)
        out[i] = out[i] << 8 | (i * 8 + k < n ? row[i * 8 + k] : 0u);
}

/* The reference's row j as words, loaded once while it is in reach. */
static const uint64_t *row_words(cmp_near *n, uint32_t j)
{
    uint32_t slot = j % n->slots;
    uint64_t *words = n->ring + (size_t)slot * n->words;
    if (n->ring_row[slot] != (int64_t)j) {
        load_words(cmp_mask_row(n->ref, j), n->ref->width, words, n->words);
        words[n->words - 1] &= n->last; /* padding may be set */
        n->ring_row[slot] = j;
    }
    return words;
}

/* ORs row j of the reference's colour `colour` into out. */
static void or_row(cmp_near *n, uint32_t j, int colour, uint64_t *out)
{
    const uint64_t *words = row_words(n, j);
    size_t i;
    if (colour) {
        for (i = 0; i < n->words; i++)
            out[i] |= words[i];
        return;
    }
    for (i = 0; i < n->words; i++)
        out[i] |= ~words[i];
    out[n->words - 1] &= n->last;
}

/* acc |= src widened by k pixels each way (k < 64). */
static void widen_into(uint64_t *acc, const uint64_t *src, size_t words,
                       int32_t k)
{
    size_t i;
    int32_t d;
    for (i = 0; i < words; i++) {
        uint64_t v = src[i];
        for (d = 1; d <= k; d++) {
            v |= src[i] >> d | src[i] << d;
            if (i > 0)
                v |= src[i - 1] << (64 - d);
            if (i + 1 < words)
                v |= src[i + 1] >> (64 - d);
        }
        acc[i] |= v;
    }
}

uint64_t cmp_near_count_far(cmp_near *n, uint32_t y, int colour,
                            const unsigned char *diff)
{
    uint64_t far = 0;
    uint32_t dy;
    size_t i;
    memset(n->acc, 0, n->words * sizeof *n->acc);
    for (dy = 0; dy <= n->radius; dy++) {
        if (n->reach[dy] < 0)
            continue;
        memset(n->tmp, 0, n->words * sizeof *n->tmp);
        if (y >= dy)
            or_row(n, y - dy, colour, n->tmp);
        if (dy > 0 && (uint64_t)y + dy < n->ref->height)
            or_row(n, y + dy, colour, n->tmp);
        widen_into(n->acc, n->tmp, n->words, n->reach[dy]);
    }
    load_words(diff, n->ref->width, n->diff, n->words);
    for (i = 0; i < n->words; i++) {
        uint64_t v = n->diff[i] & ~n->acc[i];
        if (v != 0) /* bits are bits in any byte order */
            far += cmp_popcount((const unsigned char *)&v, sizeof v);
    }
    return far;
}
