/*
 * compare.h - comparing a rendered image with a reference, and saying
 * what is wrong when they disagree.
 *
 * Bilevel images are compared as black/white masks, laid on the
 * reference's frame with their optical centres aligned; gray and colour
 * images by value (a tone comparison).  The report gives measurements, a
 * verdict (identical, consistent, inconsistent) and, for an inconsistent
 * image, the one mistake that explains it when one fits.  Memory is a few
 * bits a pixel: no full-size distance map.  Not an image-similarity metric
 * for photographs (no PSNR, no SSIM).
 */
#ifndef RAYO_COMPARE_H
#define RAYO_COMPARE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/course.h"
#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/lang_id.h"
#include "rayo/output.h"
#include "rayo/reader.h"
#include "rayo/status.h"

/*
 * Both images become black/white masks (image_convert.h: gray and colour
 * are black below half their maximum) when either is bilevel.  The image
 * is laid on the reference's frame: pixel (i, j) of each is the point
 * x = i - floor(w/2), y = j - floor(h/2) of its own grid (camera.h), so
 * images of different sizes are aligned at their optical centres and the
 * part of the image outside the reference's frame is ignored.
 *
 * What is measured (rayo_compare_report): the mismatched pixels; the IoU
 * (intersection over union) of the black regions; for every mismatch its
 * distance from the reference's outline, which is the Euclidean distance
 * in pixels to the nearest reference pixel of the other colour (a
 * mismatch just outside the reference's sphere is 1 away); the offset
 * between the centroids of the black shapes (x to the right, y down, in
 * pixels) and their scale (the square root of the ratio of their areas).
 *
 * The verdict:
 *   identical     the masks agree everywhere (and the sizes are equal);
 *   consistent    same size, every mismatch within `tolerance` pixels of
 *                 the reference's outline, and no whole-pixel shift of the
 *                 image explains the mismatches (a one-row shift keeps
 *                 every mismatch on the outline but is still a mistake);
 *   inconsistent  anything else.
 * An inconsistent image gets a diagnosis when one fits: each candidate
 * mistake (a flip, inverted colours, a transposition, a shift, a scale
 * about the optical centre) is undone on the image, and the candidate is
 * named only when the result becomes consistent with the reference, or
 * nearly so (at most a twentieth of the far mismatches left).  Otherwise
 * the black shape itself is examined: empty, not ellipse-like ("not a
 * sphere"), or a sphere somewhere else or of another size.
 *
 * Masks are packed bits and distances come from per-column lists of the
 * reference's colour changes.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_compare_verdict {
    RAYO_VERDICT_IDENTICAL,
    RAYO_VERDICT_CONSISTENT,
    RAYO_VERDICT_INCONSISTENT
} rayo_compare_verdict;

typedef enum rayo_compare_diagnosis {
    RAYO_DIAGNOSIS_NONE,            /* identical or consistent */
    RAYO_DIAGNOSIS_FLIPPED_VERTICALLY,   /* rows upside down */
    RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY, /* columns right to left */
    RAYO_DIAGNOSIS_ROTATED_180,     /* flipped both ways */
    RAYO_DIAGNOSIS_INVERTED,        /* 0 and 1 swapped */
    RAYO_DIAGNOSIS_TRANSPOSED,      /* rows written as columns */
    RAYO_DIAGNOSIS_SHIFTED,         /* moved by (shift_x, shift_y) */
    RAYO_DIAGNOSIS_SCALED,          /* scaled by `scale_found` about the
                                       optical centre: field of view or
                                       focal distance */
    RAYO_DIAGNOSIS_DIFFERENT_SIZE,  /* width or height differ */
    RAYO_DIAGNOSIS_EMPTY,           /* the image has no black pixel */
    RAYO_DIAGNOSIS_NOT_A_SPHERE,    /* black region not ellipse-like */
    RAYO_DIAGNOSIS_OTHER_SPHERE,    /* a sphere, but placed or sized
                                       differently */
    RAYO_DIAGNOSIS_UNKNOWN,         /* nothing fits */
    /* Tone compares only: */
    RAYO_DIAGNOSIS_CHANNELS_SWAPPED, /* RGB in another order: tone.order */
    RAYO_DIAGNOSIS_OFFSET,          /* values off by a constant:
                                       tone.offset */
    RAYO_DIAGNOSIS_WRAPPED,         /* values past the maximum wrapped
                                       around 256 */
    RAYO_DIAGNOSIS_MISTAKE,         /* the render of one of the course's
                                       typical mistakes: tone.mistake */
    RAYO_DIAGNOSIS_OUT_OF_RANGE,    /* the image's file holds samples
                                       outside 0..maxval (clamped to
                                       compare: rayo_compare_note_clamped) */
    RAYO_DIAGNOSIS_SCENE            /* the reference is one of the
                                       course's scenes and the image
                                       differs from it as tone.finding
                                       says (a background, a sphere added
                                       or missing, a constant) */
} rayo_compare_diagnosis;

/* The most of the band (rayo_compare_report.band) the differences of a
   consistent image may fill.  An outline drawn d <= tolerance pixels
   apart changes d of the 2 x tolerance pixels across the band, at most
   half where it is straight; a disc of radius r grown by the tolerance t
   fills 1/2 + t / 4r of it, 3/4 when r = t (docs/compare.md,
   "Consistent"). */
#define RAYO_COMPARE_BAND_SHARE 0.75

/* What a picture holds, whatever its file's format: only black and
   white pixels (bilevel), gray values, or colour (an RGB pixel whose
   channels differ).  The course's EJ1 is bilevel, EJ2 gray, EJ3
   colour. */
typedef enum rayo_picture_kind {
    RAYO_PICTURE_UNKNOWN,
    RAYO_PICTURE_BILEVEL,
    RAYO_PICTURE_GRAY,
    RAYO_PICTURE_COLOUR
} rayo_picture_kind;

/* How a comparison was made. */
typedef enum rayo_compare_kind {
    RAYO_COMPARE_MASK, /* both bilevel: black/white masks */
    RAYO_COMPARE_TONE  /* either gray or colour: values */
} rayo_compare_kind;

/* rayo_compare_options.course: try the mistakes of the course exercise
   whose render the reference agrees with, or of none. */
#define RAYO_COMPARE_COURSE_AUTO (-1)
#define RAYO_COMPARE_COURSE_NONE (-2)

typedef struct rayo_compare_options {
    double tolerance; /* pixels; default 2 */
    unsigned levels;  /* tone: levels (of 255) a value may be off and
                         still agree; default 1 */
    int course;       /* tone: a rayo_course_exercise whose mistakes the
                         diagnosis tries, or RAYO_COMPARE_COURSE_AUTO
                         (default) or RAYO_COMPARE_COURSE_NONE */
    int lossy;        /* the image was saved lossily (JPEG): values are
                         compared within RAYO_COMPARE_LOSSY_LEVELS at
                         least, and against a bilevel reference the image
                         is taken as black where darker than half;
                         default 0 */
    rayo_lang lang;   /* the language of the report's text (never of its
                         JSON); default RAYO_LANG_EN */
} rayo_compare_options;

/* The levels a lossy image's values are compared within, at least: a
 * JPEG of quality 90 of the course's scene 3 is within them away from
 * the outlines. */
#define RAYO_COMPARE_LOSSY_LEVELS 32u

RAYO_API void rayo_compare_options_init(rayo_compare_options *options);

/* One channel of a tone comparison, in levels of 255. */
typedef struct rayo_compare_channel {
    uint64_t beyond;          /* pixels off by more than the levels */
    unsigned max_difference;
    double rmse;
    double psnr;              /* dB, peak 255; INFINITY when rmse is 0 */
} rayo_compare_channel;

/* What an image differs from one of the course's scenes in
   (RAYO_DIAGNOSIS_SCENE, or where the differences lie for
   RAYO_DIAGNOSIS_UNKNOWN): docs/compare.md, "Against the course's
   scene". */
typedef enum rayo_compare_finding_kind {
    RAYO_FINDING_BACKGROUND, /* value: the background; expected: 0 */
    RAYO_FINDING_ADDED,      /* an object where the scene has background:
                                x, y its centre, box, pixels */
    RAYO_FINDING_MISSING,    /* ball shows the background: x, y where */
    RAYO_FINDING_MOVED,      /* ball missing at x, y and an object of its
                                size in box, centred at value[0],
                                value[1] */
    RAYO_FINDING_PARTLY,     /* ball shows the background in part:
                                pixels of total */
    RAYO_FINDING_AMBIENT,    /* value: the ambient (levels for EJ2, 0..1
                                for EJ3); expected: the statement's */
    RAYO_FINDING_LIGHT,      /* value: the light's intensity II (EJ2) */
    RAYO_FINDING_BELOW_AMBIENT, /* pixels of the spheres darker than the
                                ambient term; ball: where most (total)
                                are, shadowed: how many in a cast
                                shadow */
    RAYO_FINDING_WHERE,      /* nothing fits: pixels of total differ on
                                ball (-1: the background, box) */
    RAYO_FINDING_SIZE,       /* ball drawn another size: value[0] its
                                radius seen (px), expected[0] the
                                scene's (px), value[1] the radius in
                                the statement's units it fits */
    RAYO_FINDING_LIGHT_DIRECTION, /* EJ2: value the direction the
                                shading fits (unit), expected the
                                statement's; pixels of total fitted */
    RAYO_FINDING_LAMP_POSITION, /* EJ3: box[0] the point light (0 first),
                                value the place its channel fits,
                                expected the statement's; pixels of
                                total fitted */
    RAYO_FINDING_LAMP_COLOUR, /* EJ3: box[0] the point light, value the
                                colour Ii its channel fits at its place,
                                expected the statement's; pixels of
                                total fitted */
    RAYO_FINDING_LAMP_MISSING /* EJ3: box[0] the point light, left out
                                (its Ii fits about 0): as LAMP_COLOUR */
} rayo_compare_finding_kind;

#define RAYO_COMPARE_FINDINGS 6

typedef struct rayo_compare_finding {
    rayo_compare_finding_kind kind;
    int ball;                 /* the scene's sphere (0 first), or -1 */
    double x, y;              /* pixels: column, row */
    int32_t box[4];           /* x0, y0, x1, y1 (inclusive) */
    double value[3], expected[3];
    uint64_t pixels, total, shadowed;
} rayo_compare_finding;

/*
 * What a tone comparison measured.  Both images are taken as 8-bit (16-
 * bit and other maxvals scaled to 255), gray when neither has colour
 * (an RGB image whose channels are all equal is gray), else RGB.  A
 * pixel differs when a channel is off by more than `levels`.  A
 * differing pixel is explained when, in every channel, the reference
 * takes the image's value (within the levels) somewhere within
 * `tolerance` pixels: the same picture with its outlines, shadow edges
 * or shading a pixel or two away.  Explained pixels are at an edge when
 * an outline or shadow edge of the reference (a step between two
 * neighbours larger than the levels and than twice the steps beside it)
 * lies within the tolerance, else in shading.
 */
typedef struct rayo_compare_tone {
    unsigned channels;        /* 1 gray, 3 RGB: what was compared */
    unsigned reference_channels, image_channels; /* as read (1 or 3) */
    unsigned levels;
    rayo_compare_channel channel[3];
    uint64_t differing;       /* pixels with a channel beyond levels */
    uint64_t at_edges, in_shading, unexplained; /* their sum: differing */
    unsigned max_edge_difference; /* the largest among at_edges */
    int32_t first_x, first_y; /* the first unexplained pixel, -1 none */
    double scale_fit;         /* the image scaled by this about the centre
                                 lays best on the reference (1: no scale
                                 does better than none) */
    uint64_t differing_scaled; /* differing pixels left at scale_fit */
    int course;               /* the course exercise whose mistakes were
                                 tried, or -1 */
    rayo_course_mistake mistake;  /* RAYO_DIAGNOSIS_MISTAKE */
    unsigned char order[3];   /* CHANNELS_SWAPPED: the image's channel i
                                 shows the reference's order[i] */
    int offset[3];            /* OFFSET: image - reference, per channel */
    int offset_on_shapes;     /* OFFSET only where the reference is not
                                 black (the objects, not the background) */
    unsigned findings;        /* SCENE, UNKNOWN: finding[0..findings-1] */
    rayo_compare_finding finding[RAYO_COMPARE_FINDINGS];
} rayo_compare_tone;

typedef struct rayo_compare_report {
    rayo_compare_kind kind;
    /* Pixels each file held beyond the raster its header promises (a
       481st row; the reader's trailing samples over the file's samples a
       pixel, a part of a pixel counting as one); left 0 by
       rayo_compare_images, set by a caller that read the files, and
       printed by the formatters as a note. */
    uint64_t reference_surplus, image_surplus;
    /* Samples of the image's file outside 0..maxval, clamped by a reader
       asked to (rayo_compare_note_clamped), and where the first were. */
    uint64_t image_clamped_high, image_clamped_low;
    uint64_t image_first_high_line, image_first_low_line;
    long image_largest, image_smallest;
    /* How the image's file departs from what the course hands in (set
       by rayo_compare_note_clamped from the read report, printed as
       notes): a BMP's bits a pixel (other than the course's 24), rows
       stored top down, rows without their padding; and, set by the
       caller, the levels a lossy JPEG was compared within (0: not). */
    int image_bmp;            /* the image's file is a BMP */
    unsigned image_bmp_bits;
    int image_bmp_top_down, image_bmp_unpadded;
    unsigned image_lossy_levels;
    rayo_compare_tone tone;   /* RAYO_COMPARE_TONE; zero for masks */
    uint32_t reference_width, reference_height;
    uint32_t image_width, image_height;
    double tolerance;

    /* Over the reference's frame. */
    uint64_t pixels;          /* reference width x height */
    uint64_t mismatches;      /* reference_only + image_only */
    uint64_t reference_only;  /* black in the reference, white in image */
    uint64_t image_only;      /* black in the image, white in reference */
    double mismatch_percent;  /* 100 mismatches / pixels */
    double iou;               /* |both black| / |either black|; 1 when
                                 neither has black */
    double max_distance;      /* of a mismatch from the outline; 0 with no
                                 mismatch; -1 when the reference is one
                                 colour (it has no outline) */
    uint64_t beyond_tolerance; /* mismatches farther than tolerance */
    /* Where a picture drawn a pixel or two apart may differ: masks, the
       reference pixels within the tolerance of a pixel of the other
       colour; tones, the pixels near an edge or where the reference's
       values vary within the tolerance.  Counted only when nothing is
       beyond the tolerance (else 0).  crowded: the differences are more
       than RAYO_COMPARE_BAND_SHARE of it or (masks) more than half of
       those between black pixels placed at random, so the image is
       inconsistent however near the outlines they lie (a checkerboard
       against its inverse, noise against a checkerboard). */
    uint64_t band;
    int crowded;

    /* The black shapes, each in its own frame. */
    uint64_t reference_black, image_black;
    int shapes_measured;      /* both have black pixels: offset and scale
                                 below are meaningful */
    double offset_x, offset_y; /* image centroid - reference centroid */
    double scale;             /* sqrt(image_black / reference_black) */

    rayo_compare_verdict verdict;
    rayo_compare_diagnosis diagnosis;
    int diagnosis_exact;      /* undoing the mistake gives a consistent
                                 image (0: it only comes close) */
    int32_t shift_x, shift_y; /* RAYO_DIAGNOSIS_SHIFTED: the image is the
                                 reference moved this far (right, down) */
    double scale_found;       /* RAYO_DIAGNOSIS_SCALED; for consistent
                                 masks, the course's focal factor (about
                                 1.0048, or its inverse) when scaling by
                                 it halves the mismatches, else 1 */

    /* What each picture is (rayo_compare_note_kinds; both
       RAYO_PICTURE_UNKNOWN, 0, when not set, and then nothing is said):
       when the kinds differ the text report notes it, naming the
       course's exercise the reference is and the one the image's kind
       belongs to. */
    rayo_picture_kind reference_picture, image_picture;
    int reference_is_course;  /* the reference is the course's image of
                                 reference_course */
    rayo_course_exercise reference_course;

    /* The language rayo_compare_format_text and
       rayo_compare_format_diagnosis write in (the options'). */
    rayo_lang lang;
} rayo_compare_report;

/*
 * Compares image with reference (any layouts).  Fails only for memory
 * (RAYO_ERR_NOMEM) or an invalid image (RAYO_ERR_INVALID); disagreement
 * is the report's business.
 */
RAYO_API rayo_status rayo_compare_images(const rayo_image *reference,
                                          const rayo_image *image,
                                          const rayo_compare_options *options,
                                          rayo_compare_report *report,
                                          rayo_error *err);

/*
 * Writes the difference picture to out as an 8-bit PNG of the
 * reference's size, streamed row by row, with the image laid on the
 * reference's frame as for the report.  options may be NULL (the
 * defaults); their tolerance and levels matter for tone comparisons.
 * Masks (both bilevel): black and white where the masks agree,
 * RAYO_DIFF_REFERENCE_ONLY_RGB (red) where only the reference is black,
 * RAYO_DIFF_IMAGE_ONLY_RGB (blue) where only the image is black.
 * Tones: the reference dimmed to a third, in gray, and over it each
 * pixel off by more than the levels in RAYO_DIFF_EXPLAINED_RGB (amber:
 * the reference takes its value within the tolerance) or
 * RAYO_DIFF_UNEXPLAINED_RGB (red), stronger as the difference grows (full
 * at 64 levels).  The caller commits or aborts out.
 */
#define RAYO_DIFF_REFERENCE_ONLY_RGB 0xE0, 0x10, 0x10 /* red */
#define RAYO_DIFF_IMAGE_ONLY_RGB 0x10, 0x60, 0xF0     /* blue */
#define RAYO_DIFF_EXPLAINED_RGB 0xFF, 0xB0, 0x00      /* amber */
#define RAYO_DIFF_UNEXPLAINED_RGB 0xFF, 0x20, 0x20    /* red */
RAYO_API rayo_status rayo_compare_write_diff(
    const rayo_image *reference, const rayo_image *image,
    const rayo_compare_options *options, rayo_output *out, rayo_error *err);

/*
 * Gray and colour comparisons keep, for the process's next ones, the
 * reference's maps, the course scene's render and the renders of the
 * course's mistakes (about 20 MB at most; thread-safe): comparing many
 * images with one reference then makes those once.  This frees all of
 * it (call it when no comparison is running); the next comparison makes
 * again what it needs.  Reports never depend on what was kept.
 */
RAYO_API void rayo_compare_release_cache(void);

/* "identical", "consistent", "inconsistent". */
RAYO_API const char *rayo_compare_verdict_name(rayo_compare_verdict verdict);

/* A short machine name: "flipped-vertically", "shifted", "none", ... */
RAYO_API const char *rayo_compare_diagnosis_name(
    rayo_compare_diagnosis diagnosis);

/*
 * The report as text for a person (several lines, English) or as one
 * JSON object, into buffer (always terminated when size > 0).  Returns
 * the length the whole text needs, as snprintf does.
 */
RAYO_API size_t rayo_compare_format_text(const rayo_compare_report *report,
                                         char *buffer, size_t size);
RAYO_API size_t rayo_compare_format_json(const rayo_compare_report *report,
                                         char *buffer, size_t size);

/*
 * Records in report how the image's file was written when it departs
 * from the course's (a BMP not in its layout), and what a reader that
 * clamped the image's samples (rayo_read_options.clamp) counted.  With any sample out of range, an
 * image that was identical or consistent once clamped becomes
 * inconsistent with RAYO_DIAGNOSIS_OUT_OF_RANGE (the file is not a valid
 * image, whatever its picture); an inconsistent one keeps its own
 * diagnosis, and the formatters note the clamping.
 */
RAYO_API void rayo_compare_note_clamped(rayo_compare_report *report,
                                        const rayo_read_report *read);

/* The kind of image's picture (RAYO_PICTURE_UNKNOWN for an invalid
   image), and the course's exercise pictures of that kind belong to. */
RAYO_API rayo_picture_kind rayo_picture_kind_of(const rayo_image *image);
RAYO_API rayo_course_exercise rayo_picture_kind_exercise(
    rayo_picture_kind kind);

/* "bilevel", "gray", "colour"; "unknown". */
RAYO_API const char *rayo_picture_kind_name(rayo_picture_kind kind);

/*
 * 1 when a and b show the same picture: the same size and, every sample
 * taken as 8 bits (other maxvals scaled, rounded; a bilevel pixel black
 * 0 or white 255, a gray one as three equal channels), the same values.
 * Whatever their files' formats: a PBM and the PNG of the same sphere
 * are the same picture.
 */
RAYO_API int rayo_image_same_picture(const rayo_image *a,
                                     const rayo_image *b);

/*
 * Records in report the kinds of the two pictures and, when
 * reference_course is an exercise (not RAYO_COURSE_EXERCISES), that the
 * reference is the course's image of it: the caller knows (it was named
 * course:ejN, or rayo_image_same_picture with the course's image).  The
 * text report then notes a difference of kind ("your image is gray; this
 * reference is exercise 1's black and white sphere (course:ej1):
 * exercise 2? ...").  Nothing is noted for a lossy image (a JPEG is
 * never exactly bilevel, nor its gray exactly gray).
 */
RAYO_API void rayo_compare_note_kinds(rayo_compare_report *report,
                                      const rayo_image *reference,
                                      const rayo_image *image,
                                      rayo_course_exercise reference_course);

/* The diagnosis alone as one sentence (no newline), as the text report
   gives it after "diagnosis: "; "none" when there is none. */
RAYO_API size_t rayo_compare_format_diagnosis(
    const rayo_compare_report *report, char *buffer, size_t size);

#ifdef __cplusplus
}
#endif

#endif
