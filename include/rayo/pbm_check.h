/*
 * pbm_check.h - a strict checker for the plain Netpbm a student's
 * program writes (PBM, P1, for exercise 1; PGM, P2, and PPM, P3, for
 * exercises 2 and 3), that explains every deviation in the student's
 * terms.
 *
 * The readers (reader.h) are tolerant, as Netpbm's tools are, and stop at
 * the first error; this checker is the opposite: it holds the output to
 * the letter of the format and of the exercise, keeps going after a
 * mistake, and says what each one is (below).  It is not a reader for
 * other formats: raw Netpbm, another plain format than the one asked for,
 * and PNG are named and refused, and the caller may read them with
 * rayo_image_read_memory.
 */
#ifndef RAYO_PBM_CHECK_H
#define RAYO_PBM_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/grade.h"
#include "rayo/image.h"
#include "rayo/status.h"

/*
 * The letter: the magic in capitals, width and height as two numbers
 * separated by whitespace, the exercise's size, for P2 and P3 a maximum
 * value of 255, only digits and whitespace in the raster, P2 and P3
 * samples whole numbers in 0..255, exactly as many as the header
 * promises.  Each deviation is named: "a lowercase magic 'p1'", "the
 * dimensions written '640x480'", "640 pixels more than the header
 * promises: one row too many", "1 number above 255 ... not clamped".
 * Lines over 70 characters are a note ("note: ...", not counted as a
 * warning): Netpbm's own limit, which the statements and most viewers
 * ignore.
 *
 * Outputs that are evidently the format asked for under a wrong magic (a
 * P5 header over text numbers for P2, say) are read as that format, and
 * the report says so.
 */

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Checks size bytes of output against a width x height plain PBM and
 * adds its findings to item (result pass or fail, reason lines).  When
 * the pixels can be read despite the mistakes (a P1 or p1 header with
 * usable dimensions) they are put in image, a RAYO_SAMPLE_BIT image of
 * the header's size (missing pixels white, surplus ones dropped), which
 * the caller frees; otherwise image is left zeroed.  Returns RAYO_OK
 * unless memory ran out.
 */
RAYO_API rayo_status rayo_pbm_check(const void *data, size_t size,
                                    uint32_t width, uint32_t height,
                                    rayo_grade_item *item, rayo_image *image,
                                    rayo_error *err);

/*
 * The same for the plain format magic asks for: '1' (exactly
 * rayo_pbm_check), '2' (PGM) or '3' (PPM).  For P2 and P3 the pixels are
 * put in image, 8-bit gray or RGB, maxval 255, when the header's
 * dimensions can be read (with the magic P5 or P6, or P3 for P2 and P2
 * for P3, when what follows is evidently the format asked for):
 * samples out of range clamped to 0..255, numbers with a decimal point
 * taken by their whole part, missing samples black, surplus ones
 * dropped.  Lines of the report that begin "note: " are remarks, not
 * warnings.  RAYO_ERR_INVALID for another magic, RAYO_ERR_NOMEM when
 * memory ran out; RAYO_OK otherwise, however wrong the output is.
 */
RAYO_API rayo_status rayo_pnm_check(const void *data, size_t size, char magic,
                                    uint32_t width, uint32_t height,
                                    rayo_grade_item *item, rayo_image *image,
                                    rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
