/*
 * writer.h - streaming image writers: Netpbm (PBM, PGM, PPM; plain and
 * raw), PNG, BMP and JPEG.
 *
 * A writer is opened with the image's header, fed rows from top to bottom
 * (as many at a time as the caller likes) and finished; it never needs the
 * whole frame, so a 16384-pixel-wide render streams in the memory of a few
 * rows.  Writers are strict about what they emit: plain Netpbm lines are
 * at most 70 characters, as the format pages ask.
 *
 * Converting between layouts (say colour to bilevel) is not a writer's
 * job (image_convert.h).  What each format takes is said after the
 * includes.
 */
#ifndef RAYO_WRITER_H
#define RAYO_WRITER_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/output.h"
#include "rayo/status.h"

/*
 * What each format takes:
 *   PBM  RAYO_SAMPLE_BIT rows;
 *   PGM  one channel, U8 or U16 (the maxval is kept);
 *   PPM  three channels, U8 or U16 (the maxval is kept);
 *   PNG  BIT (written as 1-bit gray, black where the bit is 1), or one or
 *        three channels of U8 (8-bit) or U16 (16-bit), samples scaled to
 *        the full range when maxval is not 255 or 65535.
 *   BMP  the course's layout (bottom-up rows padded to 4 bytes): three
 *        channels as 24 bits B, G, R; one channel as 8 bits through a
 *        gray palette; BIT as 1 bit through a white, black palette;
 *        samples over 8 bits scaled to 0-255.  Rows are kept until the
 *        image is finished (the file wants the bottom row first).
 *   JPEG three channels as colour, one channel and BIT as gray (bilevel
 *        0 and 255), samples over 8 bits scaled; lossy, at the options'
 *        quality.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_format {
    RAYO_FORMAT_PBM,
    RAYO_FORMAT_PGM,
    RAYO_FORMAT_PPM,
    RAYO_FORMAT_PNG,
    RAYO_FORMAT_BMP,
    RAYO_FORMAT_JPEG
} rayo_format;

/* "pbm", "pgm", "ppm", "png", "bmp", "jpeg" (or "jpg"); RAYO_ERR_INVALID
 * for anything else. */
RAYO_API rayo_status rayo_format_parse(const char *name, rayo_format *format,
                                       rayo_error *err);

/*
 * The format named by a path's extension (".pbm", ".PNG", ...), matched
 * without regard to case.  RAYO_ERR_INVALID when there is none we know.
 */
RAYO_API rayo_status rayo_format_from_path(const char *path,
                                           rayo_format *format,
                                           rayo_error *err);

/* "pbm", "pgm", "ppm", "png", "bmp" or "jpeg". */
RAYO_API const char *rayo_format_name(rayo_format format);

/* 1 for PBM, PGM and PPM (plain or raw), 0 for PNG, BMP and JPEG. */
RAYO_API int rayo_format_is_netpbm(rayo_format format);

/* The format that holds this layout without loss (PBM, PGM or PPM). */
RAYO_API rayo_format rayo_format_netpbm_for(const rayo_image_info *info);

typedef struct rayo_write_options {
    rayo_format format;
    int plain; /* Netpbm: 1 = plain (P1-P3, ASCII), 0 = raw (P4-P6) */
    unsigned quality; /* JPEG only: 1 to 100; anything else is 90 */
} rayo_write_options;

typedef struct rayo_writer rayo_writer;

/*
 * Starts an image on out, which stays the caller's: finish or discard
 * the writer first, then commit or abort out (the writer may leave bytes
 * of its own memory pending in out until it is finished).
 * RAYO_ERR_INVALID when the format cannot hold this layout.
 */
RAYO_API rayo_status rayo_writer_open(rayo_writer **writer, rayo_output *out,
                                      const rayo_image_info *info,
                                      const rayo_write_options *options,
                                      rayo_error *err);

/* Writes count rows, each rayo_image_info_row_bytes() long, stride apart. */
RAYO_API rayo_status rayo_writer_write_rows(rayo_writer *writer,
                                            const unsigned char *rows,
                                            size_t stride, uint32_t count,
                                            rayo_error *err);

/*
 * The same as a row sink for rayo_render (render.h): context is the
 * rayo_writer, first_row is implied by the order rows arrive in.
 */
RAYO_API rayo_status rayo_writer_row_sink(void *writer,
                                          const unsigned char *rows,
                                          size_t stride, uint32_t first_row,
                                          uint32_t count, rayo_error *err);

/*
 * Ends the image (fails if rows are missing) and frees the writer, which
 * is freed whatever the outcome.
 */
RAYO_API rayo_status rayo_writer_finish(rayo_writer *writer, rayo_error *err);

/* Frees a writer without ending its image (after an error): the image
 * is incomplete, so its output's commit fails from then on (abort it). */
RAYO_API void rayo_writer_discard(rayo_writer *writer);

/* Writes a whole image: open, all rows, finish. */
RAYO_API rayo_status rayo_image_write(const rayo_image *image,
                                      rayo_output *out,
                                      const rayo_write_options *options,
                                      rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
