/*
 * pbm_check.h - a strict checker for the plain PBM (P1) a student's
 * program writes, that explains every deviation in the student's terms.
 *
 * The readers (reader.h) are tolerant, as Netpbm's tools are, and stop
 * at the first error; this checker is the opposite: it holds the output
 * to the letter of the format and of the exercise (the magic 'P1' in
 * capitals, width and height as two numbers separated by whitespace, the
 * exercise's size, only 0, 1 and whitespace in the raster, exactly
 * width x height pixels, lines of at most 70 characters), keeps going
 * after a mistake, and says what each one is: "a lowercase magic 'p1'",
 * "the dimensions written '640x480'", "640 pixels more than the header
 * promises: one row too many".  Lines over 70 characters are a warning:
 * Netpbm's own limit, which most viewers ignore.
 *
 * It is not a reader for other formats: raw PBM, PGM, PPM and PNG are
 * named and refused (the exercise asks for P1), and the caller may read
 * them with rayo_image_read_memory.
 */
#ifndef RAYO_PBM_CHECK_H
#define RAYO_PBM_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/grade.h"
#include "rayo/image.h"
#include "rayo/status.h"

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
rayo_status rayo_pbm_check(const void *data, size_t size, uint32_t width,
                           uint32_t height, rayo_grade_item *item,
                           rayo_image *image, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
