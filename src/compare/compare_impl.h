/*
 * compare_impl.h - the pieces the mask comparison (src/compare/mask/) is
 * built from, shared by the files of src/compare and by no one else:
 * masks of packed bits, a candidate mistake undone (transform), the
 * reference's outline and each pixel's distance from it (outline, near,
 * farthest, band), a black region's shape, and the measuring pass.
 * docs/architecture.md lists the files of each group.
 */
#ifndef RAYO_COMPARE_IMPL_H
#define RAYO_COMPARE_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/compare.h"

typedef struct cmp_mask {
    uint32_t width, height;
    size_t stride;
    const unsigned char *bits;
} cmp_mask;

/* Bytes of a packed row of this width. */
static inline size_t cmp_row_bytes(uint32_t width)
{
    return ((size_t)width + 7) / 8;
}

static inline const unsigned char *cmp_mask_row(const cmp_mask *m,
                                                uint32_t y)
{
    return m->bits + (size_t)y * m->stride;
}

/* RAYO_ERR_INVALID unless the tolerance is finite and >= 0 and the
   levels at most 255 (compare.c). */
rayo_status cmp_options_check(const rayo_compare_options *options,
                              rayo_error *err);

/* The two masks of a comparison, converted from any layout when they
 * are not bilevel already (then borrowed, not copied). */
typedef struct cmp_pair {
    rayo_image owned_ref, owned_image;
    cmp_mask ref, image;
} cmp_pair;

rayo_status cmp_pair_make(cmp_pair *pair, const rayo_image *reference,
                          const rayo_image *image, rayo_error *err);
void cmp_pair_free(cmp_pair *pair);

/* Number of set bits in n bytes. */
uint64_t cmp_popcount(const unsigned char *bytes, size_t n);

/* Number of set bits in v (the classic SWAR reduction). */
static inline unsigned cmp_popcount64(uint64_t v)
{
    v = v - ((v >> 1) & 0x5555555555555555ull);
    v = (v & 0x3333333333333333ull) + ((v >> 2) & 0x3333333333333333ull);
    v = (v + (v >> 4)) & 0x0F0F0F0F0F0F0F0Full;
    return (unsigned)((v * 0x0101010101010101ull) >> 56);
}

/* Clears the bits past width in the last byte of a packed row. */
void cmp_clear_padding(unsigned char *row, uint32_t width);

/* ---- mask/transform.c ---- */

typedef enum cmp_transform_kind {
    CMP_IDENTITY,   /* same frame, or centred on the reference's */
    CMP_INVERT,
    CMP_FLIP_V,
    CMP_FLIP_H,
    CMP_FLIP_BOTH,
    CMP_TRANSPOSE,
    CMP_SHIFT,      /* the image is the reference moved by (dx, dy) */
    CMP_SCALE       /* the image is the reference scaled by s about the
                       optical centre */
} cmp_transform_kind;

typedef struct cmp_transform {
    cmp_transform_kind kind;
    int32_t dx, dy;
    double scale;
    uint32_t step; /* CMP_SCALE search: sample every step-th pixel only */
    const int32_t *columns; /* CMP_SCALE, step 1: the image column of each
                               reference column (-1: outside), or NULL */
    const cmp_mask *transposed; /* CMP_TRANSPOSE: the image transposed
                                   (cmp_mask_transpose), or NULL: read a
                                   column a row, pixel by pixel */
} cmp_transform;

/* out = m transposed (out->width = m->height), its bits in *bits (to
 * free); eight by eight blocks, so the image is read row by row instead
 * of a column (a cache miss a pixel) for each row. */
rayo_status cmp_mask_transpose(const cmp_mask *m, cmp_mask *out,
                               unsigned char **bits, rayo_error *err);

/* The column map of a CMP_SCALE transform (columns has room for
 * ref_width entries). */
void cmp_transform_columns(const cmp_transform *t, uint32_t ref_width,
                           uint32_t image_width, int32_t *columns);

/*
 * The image's row y undone by t, in the reference's frame (width
 * ref_width): out gets the bits, known the pixels that map inside the
 * image (1 = known).  Returns 1 when every pixel of the row is known
 * (known is then left alone, or used as scratch), -1 when none is (out
 * and known then need not be read), else 0.  Padding bits are zero in
 * both.
 */
int cmp_transform_row(const cmp_transform *t, const cmp_mask *image,
                      uint32_t ref_width, uint32_t ref_height, uint32_t y,
                      unsigned char *out, unsigned char *known);

/* ---- mask/outline.c ---- */

typedef struct cmp_outline cmp_outline;

rayo_status cmp_outline_create(cmp_outline **outline, const cmp_mask *ref,
                               rayo_error *err);
void cmp_outline_free(cmp_outline *outline);

/* Starts again from row y (rows must then be asked in increasing order). */
void cmp_outline_rewind(cmp_outline *outline, uint32_t y);

/* Another reader of the same outline, with cursors of its own, for a
 * thread working on other rows; free it before the outline. */
rayo_status cmp_outline_fork(const cmp_outline *base, cmp_outline **fork,
                             rayo_error *err);

/* 1 when the reference has both colours (so distances are finite). */
int cmp_outline_has_edges(const cmp_outline *outline);

/*
 * For the pixels x of row y set in diff (a packed row): d2[x] = squared
 * distance from (x, y) to the nearest reference pixel of colour `colour`
 * (0 white, 1 black), or INT64_MAX if there is none.  Other entries of d2
 * (room for the reference's width) may be written too.
 */
void cmp_outline_mismatch_distances(cmp_outline *outline, uint32_t y,
                                    int colour, const unsigned char *diff,
                                    int64_t *d2);

/* The same for every pixel of row y (d2 has room for the width). */
void cmp_outline_row_distances(cmp_outline *outline, uint32_t y, int colour,
                               int64_t *d2);

/* ---- mask/near.c ---- */

/* Tolerances the near test takes (its cost grows as their square). */
#define CMP_NEAR_MAX_TOLERANCE 8.0
#define CMP_NEAR_MAX_RADIUS 8

typedef struct cmp_near cmp_near;

rayo_status cmp_near_create(cmp_near **near, const cmp_mask *ref,
                            double tolerance, rayo_error *err);
void cmp_near_free(cmp_near *near);

/* How many bits of diff (a packed row y of the reference's frame) have
 * no reference pixel of colour `colour` within the tolerance. */
uint64_t cmp_near_count_far(cmp_near *near, uint32_t y, int colour,
                            const unsigned char *diff);

/* ---- mask/band.c ---- */

/* *band = the reference pixels within the tolerance of a pixel of the
 * other colour (0 when the reference has one colour).  Rewinds the
 * outline. */
rayo_status cmp_outline_band(const cmp_mask *ref, cmp_outline *outline,
                             double tolerance, uint64_t *band,
                             rayo_error *err);

/* Whether differences fill more than RAYO_COMPARE_BAND_SHARE of the
 * band (masks and tones alike). */
static inline int cmp_crowded(uint64_t differences, uint64_t band)
{
    return (double)differences > RAYO_COMPARE_BAND_SHARE * (double)band;
}

/* The mismatches expected between masks of these black counts whose
 * black pixels were placed independently at random. */
double cmp_chance_mismatches(uint64_t pixels, uint64_t reference_black,
                             uint64_t image_black);

/* The most mismatches that still agree with the reference better than
 * chance, not by luck: CMP_CHANCE_SHARE of the chance count C (Cohen's
 * kappa at least 1/2).  An image of independent random pixels gets
 * under it with a probability below exp(-C/8) (Chernoff's lower tail),
 * 1e-8 from C = 150; noise against a 64x48 checkerboard (C = 1536)
 * below exp(-192). */
#define CMP_CHANCE_SHARE 0.5
double cmp_chance_limit(uint64_t pixels, uint64_t reference_black,
                        uint64_t image_black);

/* A mask report whose mismatches, all within the tolerance, still do
 * not make it consistent: more than the band's share, or more than
 * cmp_chance_limit (report's band, mismatches and black counts
 * filled). */
int cmp_mask_crowded(const rayo_compare_report *report);

/* ---- mask/farthest.c ---- */

typedef struct cmp_farthest cmp_farthest;

/* For rows y0..y1-1 (y0 < y1), reading distances through outline. */
rayo_status cmp_farthest_create(cmp_farthest **farthest,
                                cmp_outline *outline, uint32_t width,
                                uint32_t y0, uint32_t y1, rayo_error *err);
void cmp_farthest_free(cmp_farthest *farthest);

/* The sampled rows, i < cmp_farthest_samples, in increasing order; each
 * must be given to cmp_farthest_sample, in that order, with its
 * mismatches (black only in the reference, black only in the image; NULL
 * for none), before any cmp_farthest_row, and the outline rewound to y0
 * in between. */
uint32_t cmp_farthest_samples(const cmp_farthest *farthest);
uint32_t cmp_farthest_sample_row(const cmp_farthest *farthest, uint32_t i);
void cmp_farthest_sample(cmp_farthest *farthest, uint32_t i,
                         const unsigned char *reference_only,
                         const unsigned char *image_only);

/* The mismatches of row y (rows in increasing order) whose reference
 * colour is reference_colour. */
void cmp_farthest_row(cmp_farthest *farthest, uint32_t y,
                      int reference_colour, const unsigned char *diff);

/* The largest squared distance of a mismatch given, -1 for none. */
int64_t cmp_farthest_best(const cmp_farthest *farthest);

/* ---- mask/shape.c ---- */

typedef struct cmp_shape {
    uint64_t black;
    double cx, cy;            /* centroid, centred coordinates, y down */
    double sxx, syy, sxy;     /* central second moments (per pixel) */
    int touches_border;
} cmp_shape;

void cmp_shape_measure(const cmp_mask *mask, cmp_shape *shape);

/* Mean distance (pixels) of the mask's outline from its best-fitting
 * ellipse; HUGE_VAL when no ellipse around black fits.  Costs a few
 * passes over the mask, so it is asked for only when needed.  A mean
 * past limit is not finished: some value past limit is returned. */
double cmp_shape_ellipse_error(const cmp_mask *mask, double limit);

/* ---- mask/measure.c ---- */

typedef struct cmp_counts {
    uint64_t known;           /* pixels the transform could place */
    uint64_t reference_only, image_only, both, either;
    uint64_t beyond;          /* mismatches farther than the tolerance */
    double max_distance;      /* -1 when distances were not asked for */
} cmp_counts;

/*
 * Compares ref with image undone by t.  With outline NULL only the
 * counts are made (no distances, beyond = 0).  With exact 0, only
 * `beyond` is needed, not max_distance (left at 0): small tolerances
 * are then checked by looking around each mismatch, which is faster.
 */
rayo_status cmp_measure(const cmp_mask *ref, const cmp_mask *image,
                        const cmp_transform *t, cmp_outline *outline,
                        int exact, double tolerance, cmp_counts *counts,
                        rayo_error *err);

/* ---- mask/diagnose.c ---- */

/*
 * Fills report's verdict and diagnosis, given its measurements (filled by
 * compare.c) and the shapes.
 */
rayo_status cmp_diagnose(const cmp_mask *ref, const cmp_mask *image,
                         cmp_outline *outline, const cmp_shape *ref_shape,
                         const cmp_shape *image_shape,
                         rayo_compare_report *report, rayo_error *err);

#endif
