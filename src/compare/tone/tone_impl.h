/*
 * tone_impl.h - the pieces of the tone comparison (gray and colour
 * images compared by value), shared by src/compare/tone/ and the top of
 * src/compare (which chooses the tone or the mask comparison) only: the
 * images as 8-bit samples and their maps, a candidate mistake undone,
 * the measuring pass and what explains a difference, the diagnosis, the
 * difference picture, the report and the cache.  The mask comparison
 * (compare_impl.h) shares none of this but the report and its
 * vocabulary; docs/architecture.md lists the files of each group.
 */
#ifndef RAYO_TONE_IMPL_H
#define RAYO_TONE_IMPL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "rayo/compare.h"

/* An image as 8-bit samples, channels (1 or 3) a pixel, rows packed. */
typedef struct tone_image {
    uint32_t width, height;
    unsigned channels;
    unsigned char *v; /* owned */
    /* tone_image_find_edges: 1 where an edge lies within near_radius
       (levels near_levels); NULL until then.  Owned. */
    unsigned char *near;
    unsigned char *slope; /* the largest step of the shading (not an
                             edge) within near_radius; owned */
    unsigned char *lo, *hi; /* each channel's smallest and largest value
                               within near_radius, laid out as v; owned */
    int near_radius;
    unsigned near_levels;
} tone_image;

/* The radius of the edge maps for a tolerance: its whole part, at most
   64. */
static inline int tone_radius(double tolerance)
{
    return tolerance < 64 ? (int)floor(tolerance) : 64;
}

static inline const unsigned char *tone_pixel(const tone_image *t,
                                              uint32_t x, uint32_t y)
{
    return t->v + ((size_t)y * t->width + x) * t->channels;
}

/* 1 when the image is bilevel: BIT, or only black and white pixels. */
int tone_is_bilevel(const rayo_image *image);

/* 1 when the image has colour: RGB with some pixel not gray. */
int tone_has_colour(const rayo_image *image);

/* The image as 8-bit samples with `channels` channels (1: gray by
   luminance, 3: gray repeated). */
rayo_status tone_image_make(const rayo_image *image, unsigned channels,
                            tone_image *out, rayo_error *err);
void tone_image_free(tone_image *t);

/* Frees t's maps (near, slope, lo, hi), leaving its samples. */
void tone_image_drop_maps(tone_image *t);

/* Rows first..end-1 of image into out, made by tone_image_make from an
   image of the same size and format. */
void tone_image_convert_rows(const rayo_image *image, tone_image *out,
                             uint32_t first, uint32_t end);

/* Marks, once, the pixels of t within the tolerance of an edge (for
   levels), so tone_measure, used with t as the reference, needs not look
   around every differing pixel for one. */
rayo_status tone_image_find_edges(tone_image *t, double tolerance,
                                  unsigned levels, rayo_error *err);

/* The same, the maps taken from the process's cache (tone_cache.c) when
   an image of the very same samples had them made, and kept there
   otherwise: for the images compared against again and again (the
   reference, the course's render). */
rayo_status tone_image_find_edges_kept(tone_image *t, double tolerance,
                                       unsigned levels, rayo_error *err);

/* tone_cache.c: t's maps for radius and levels copied from the cache
   (1), or 0 when it has none for t's samples; t's samples and maps
   kept (copies).  The course's render of `course` with `channels` as a
   new tone image into t, its samples only (1), or 0; and kept.
   rayo_compare_release_cache (compare.h) frees every entry. */
int tone_cache_find_maps(tone_image *t, int radius, unsigned levels);
void tone_cache_keep_maps(const tone_image *t);
int tone_cache_find_course(int course, unsigned channels, tone_image *t);
void tone_cache_keep_course(int course, const tone_image *t);
/* The course scene (or -1) the image of t's samples was found to show,
   for radius, levels and key (the reference's own channels), as
   detect_course found it: 1 when known; and kept, with the image's
   entry only. */
int tone_cache_find_detected(const tone_image *t, int radius,
                             unsigned levels, int key, int *course);
void tone_cache_keep_detected(const tone_image *t, int radius,
                              unsigned levels, int key, int course);

/* The student model's render of a course mistake (its tone image, of
   t's size and channels), as far as it was made: its rows 0..n-1 into
   t->v, n returned (0: none); and kept, rows 0..rows-1 of t. */
uint32_t tone_cache_find_rows(int course, int mistake, tone_image *t);
void tone_cache_keep_rows(int course, int mistake, const tone_image *t,
                          uint32_t rows);

/* tone_window.c: the extreme (max 1: largest, 0: smallest) of in over
   the window |dx|, |dy| <= radius around each pixel, into out (both
   width x height x channels, interleaved); one line of it, strided,
   with scratch prefix and suffix of n + 2 radius bytes each. */
rayo_status tone_window_map(const unsigned char *in, unsigned char *out,
                            uint32_t width, uint32_t height,
                            unsigned channels, int radius, int max,
                            rayo_error *err);
void tone_window_line(const unsigned char *in, size_t stride,
                      unsigned char *out, size_t out_stride, uint32_t n,
                      int radius, int max, unsigned char *prefix,
                      unsigned char *suffix);

/* A candidate mistake undone on the image, as it is read at a pixel of
   the reference's frame. */
typedef enum tone_kind {
    TONE_IDENTITY,   /* laid on the reference's frame, centres aligned */
    TONE_FLIP_V,
    TONE_FLIP_H,
    TONE_FLIP_BOTH,
    TONE_SHIFT,      /* the image is the reference moved by (dx, dy) */
    TONE_SCALE,      /* the image is the reference scaled by s about the
                        optical centre */
    TONE_PERMUTE,    /* the image's channel i is the reference's perm[i] */
    TONE_INVERT,     /* 255 - v */
    TONE_OFFSET,     /* the image is the reference + offset */
    TONE_OFFSET_ON_SHAPES, /* the same where the reference is not black */
    TONE_WRAPPED     /* values past 255 wrapped: where the reference is 255
                        and the image dark, the image really was 255 */
} tone_kind;

typedef struct tone_xform {
    tone_kind kind;
    int32_t dx, dy;
    double scale;
    unsigned char perm[3];
    int offset[3];
    uint32_t step;   /* sample every step-th row and column (>= 1) */
    /* capped: stop the pass (tone_counts.stopped) once more than
       max_unexplained pixels are unexplained or more than max_differing
       differ: a candidate that cannot win is not measured to the end. */
    int capped;
    uint64_t max_unexplained, max_differing;
    /* capped, classify -1 (the searches): stop once the sum of squares
       is past max_squares, or more than max_differing differ. */
    uint64_t max_squares;
} tone_xform;

/* A transform that changes nothing. */
tone_xform tone_identity(void);

/* The image's pixel for reference pixel (x, y), undone by t, into u;
   0 when it falls outside the image. */
int tone_undo(const tone_image *ref, const tone_image *image,
              const tone_xform *t, uint32_t x, uint32_t y, unsigned char *u);

/* Whether the reference takes u's values within the window of radius
   around (x, y), give or take the levels and its shading there; and
   whether an edge of the reference lies within radius of (x, y). */
int tone_explained(const tone_image *ref, uint32_t x, uint32_t y,
                   const unsigned char *u, int radius, unsigned levels);
int tone_near_edge(const tone_image *ref, uint32_t x, uint32_t y, int radius,
                   unsigned levels);

typedef struct tone_counts {
    uint64_t known;       /* pixels compared (outside the image: black) */
    uint64_t placed;      /* of those, the ones read inside the image */
    uint64_t differing, at_edges, in_shading, unexplained;
    uint64_t beyond[3];
    unsigned max_difference[3], max_edge_difference;
    double sum_squares[3];
    int32_t first_x, first_y;
    int stopped;          /* a cap of the transform was passed */
} tone_counts;

/*
 * Compares ref with image undone by t.  classify 1: sort the explained
 * differences into edges and shading; 0: count them all as in_shading;
 * -1: only count the differences, explaining none (unexplained stays
 * 0).  With sizes that differ, the image is laid on the reference's
 * frame centred.
 */
void tone_measure(const tone_image *ref, const tone_image *image,
                  const tone_xform *t, double tolerance, unsigned levels,
                  int classify, tone_counts *counts);

/* What one pixel of the reference's frame is: the image is outside it,
   agrees, differs explained or unexplained (tone_measure's rules);
   *difference the largest channel difference. */
enum {
    TONE_PIXEL_UNKNOWN,
    TONE_PIXEL_SAME,
    TONE_PIXEL_EXPLAINED,
    TONE_PIXEL_UNEXPLAINED
};
int tone_classify_pixel(const tone_image *ref, const tone_image *image,
                        uint32_t x, uint32_t y, double tolerance,
                        unsigned levels, unsigned *difference);

/* Sets report->verdict and report->diagnosis, given the measurements in
   report (tone.c) and the identity counts. */
rayo_status tone_diagnose(const tone_image *ref, const tone_image *image,
                          const rayo_compare_options *options,
                          rayo_compare_report *report, rayo_error *err);

/* The pixels of the reference where a difference could be explained at
   all: near an edge, or where some channel's value varies within the
   tolerance (its maps made by tone_image_find_edges); elsewhere the
   reference is flat and a differing pixel never is explained. */
uint64_t tone_band(const tone_image *ref);

/* The scale s (image = reference scaled by s about the optical centre)
   between lo and hi that leaves the smallest sum of squared differences
   (searched on a sampled grid, then finer); *left the differing pixels
   at s and *squares that sum, over every pixel. */
double tone_best_scale(const tone_image *ref, const tone_image *image,
                       unsigned levels, double lo, double hi,
                       uint64_t *left, double *squares);

/* The tone comparison (called by rayo_compare_images). */
rayo_status tone_compare(const rayo_image *reference, const rayo_image *image,
                         const rayo_compare_options *options,
                         rayo_compare_report *report, rayo_error *err);

/* The tone difference picture (called by rayo_compare_write_diff). */
rayo_status tone_write_diff(const rayo_image *reference,
                            const rayo_image *image,
                            const rayo_compare_options *options,
                            rayo_output *out, rayo_error *err);

/* tone_scene.c: what image differs from the course's scene `course`
   (EJ2 or EJ3) in, into r->tone.finding: *named 1 when something is
   named (a background, a sphere, a constant), else the findings say
   only where the differences lie (RAYO_FINDING_WHERE).  The scene's map
   is kept until tone_scene_release_cache (rayo_compare_release_cache). */
rayo_status tone_scene_find(const tone_image *ref, const tone_image *image,
                            int course, rayo_compare_report *r, int *named,
                            rayo_error *err);
void tone_scene_release_cache(void);

/* The diagnosis against the course's scene, after tone_diagnose's
   candidates: found, whether one was chosen (r has its diagnosis);
   offset, its offsets when it is an offset on the objects, else NULL.
   With nothing found, or such an offset that the ambient term explains,
   the findings make the diagnosis RAYO_DIAGNOSIS_SCENE; with nothing
   found and nothing named, UNKNOWN keeps the findings that say where
   the differences lie. */
rayo_status tone_scene_diagnose(const tone_image *ref,
                                const tone_image *image, int found,
                                const int *offset, rayo_compare_report *r,
                                rayo_error *err);

/* tone_scene_text.c: the findings as sentences joined by "; ", and as
   the JSON member "findings". */
struct cmp_sink;
void tone_put_findings(const rayo_compare_report *r, struct cmp_sink *s);
void tone_put_findings_json(const rayo_compare_report *r,
                            struct cmp_sink *s);

/* tone_format.c: the tone parts of report_format.c's forms. */
struct cmp_sink;
void tone_format_text(const rayo_compare_report *r, struct cmp_sink *s);
void tone_format_json(const rayo_compare_report *r, struct cmp_sink *s);
void tone_put_diagnosis(const rayo_compare_report *r, struct cmp_sink *s);

/* report_format.c: the notes on samples beyond a raster, appended at
   *length (snprintf semantics). */
void cmp_put_surplus(char *buffer, size_t size, size_t *length,
                     const rayo_compare_report *r);

#endif
