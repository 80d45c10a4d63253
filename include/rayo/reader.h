/*
 * reader.h - reading Netpbm (PBM, PGM, PPM; plain and raw), PNG and BMP
 * files into a rayo_image.
 *
 * The format comes from the content's first bytes (P1-P6, the PNG
 * signature or "BM"), never from the file's name.  Limits are checked
 * before any pixel memory is requested, and a malformed file's error is
 * one line naming the file and the byte.  Not a writer (writer.h) and
 * not a converter between layouts (image_convert.h): each format becomes
 * the layout nearest to it.  Which layout, how each format is read, and
 * the errors are said after the includes.
 */
#ifndef RAYO_READER_H
#define RAYO_READER_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/status.h"
#include "rayo/writer.h"

/*
 * What each format becomes:
 *
 *   P1, P4               RAYO_SAMPLE_BIT (1 = black)
 *   P2, P5               1 channel, U8 when maxval <= 255, else U16
 *   P3, P6               3 channels, U8 when maxval <= 255, else U16
 *   PNG gray, 1 bit      RAYO_SAMPLE_BIT (so PBM -> PNG -> PBM round-trips)
 *   PNG gray, 2/4/8 bit  1 channel U8, maxval 2^depth - 1 (3, 15, 255)
 *   PNG gray, 16 bit     1 channel U16, maxval 65535
 *   PNG palette          3 channels U8, maxval 255
 *   PNG RGB              3 channels, U8 or U16
 *   alpha (PNG gray+alpha, RGBA, tRNS)
 *                        composited over white and dropped:
 *                        v' = round((v a + M (M - a)) / M), M = maxval;
 *                        low-depth gray with tRNS becomes 8-bit first
 *   BMP 1 bit, palette of black and white
 *                        RAYO_SAMPLE_BIT
 *   BMP 1/4/8 bit, palette of grays
 *                        1 channel U8
 *   BMP other palettes, 16, 24, 32 bit
 *                        3 channels U8 (channel masks scaled to 0-255;
 *                        alpha ignored); rows top down or bottom up, and
 *                        rows without padding when the file's size says
 *                        so (the report's bmp_ fields)
 *
 * Netpbm is read as its format pages say and as tolerantly as Netpbm's
 * own tools: comments ('#' to the end of the line) anywhere in the
 * header and, in plain rasters, between samples; any whitespace; maxval 1
 * to 65535; 16-bit samples big-endian.  It is strict about the raster: a
 * sample over maxval, a character other than a digit, whitespace or a
 * comment in a plain raster, or a raster cut short is an error.  Bytes
 * after the first image (a second image, a trailing newline, garbage) are
 * accepted and counted in the report, which also says how many of them
 * are data rather than whitespace and how many samples they hold: a
 * caller can tell a file with a row more than its header promises from
 * one that ends in a newline.
 *
 * PNG is read by libpng: every colour type and bit depth, interlaced or
 * not; a CRC error in any chunk, a missing IEND or a truncated stream is
 * an error.  Ancillary chunks but tRNS (text, gamma, colour space, ICC)
 * are skipped unread, and nothing after the last row is inflated, so a
 * PNG costs the image's memory and about 2 MiB more, and time in
 * proportion to its size and the image's.
 *
 * A build of rayo without libpng's reader or without libjpeg
 * (RAYO_NO_PNG_READ, RAYO_NO_JPEG: the page, docs/architecture.md) still
 * recognises those files, and refuses them with RAYO_ERR_FORMAT: "FILE:
 * a PNG, which this build of rayo does not read (...)".
 *
 * Limits (limits.h) are checked before any pixel memory is requested:
 * width and height, total pixels, and, for a regular file or memory, that
 * there are enough bytes left for the raster the header promises.
 *
 * Errors: RAYO_ERR_FORMAT (malformed, truncated or lying input),
 * RAYO_ERR_LIMIT (over a limit), RAYO_ERR_IO (the system refused a read),
 * RAYO_ERR_NOMEM.  The message is one line: "FILE: byte N: found X;
 * expected Y" (plain text positions also give the line).
 */

#ifdef __cplusplus
extern "C" {
#endif

/* How far after a Netpbm raster trailing_samples and trailing_data look
   (64 MiB); trailing_bytes counts everything. */
#define RAYO_TRAILING_SCAN_BYTES (64ull << 20)

typedef struct rayo_read_report {
    rayo_format format;      /* RAYO_FORMAT_PBM/PGM/PPM/PNG, from the
                                content's magic, not the name */
    int plain;               /* Netpbm P1-P3 */
    uint64_t trailing_bytes; /* bytes after the raster (accepted); after
                                a plain raster, the whitespace and
                                comments that end it are not counted */
    /*
     * Netpbm only (0 for PNG), within the first RAYO_TRAILING_SCAN_BYTES
     * trailing bytes:
     *
     * trailing_samples: samples beyond the raster the header promises
     * (samples, not pixels: a PPM pixel is three).  Plain: the samples
     * that follow, separated by whitespace or comments as in a raster
     * (each 0 or 1 digit of a PBM, each decimal number of a PGM or PPM,
     * whatever its value), up to the first thing that is not one (the
     * "P1" of a second image, a stray letter).  Raw: the whole samples
     * the trailing bytes hold (1 or 2 bytes each; in a PBM, a row of
     * ceil(width / 8) bytes holds width pixels, a partial row up to 8
     * per byte), or 0 when they are only whitespace or begin, after
     * whitespace, another Netpbm image ('P' and a digit 1-7).
     *
     * trailing_data: the trailing bytes that are not whitespace (nor,
     * after a plain raster, in a comment).
     *
     * A plain PBM of 640x480 whose file holds a 481st row: 640 samples,
     * 640 bytes of data (or more, with spaces between the digits).  A raw
     * raster followed by a newline: 1 trailing byte, no data, no sample.
     */
    uint64_t trailing_samples;
    uint64_t trailing_data;
    /*
     * Plain PGM and PPM read with rayo_read_options.clamp only: the
     * samples above maxval (taken as maxval) and the negative ones (taken
     * as 0), the line of the first of each (0: none), the largest and
     * the smallest number found (saturating at 65536 and -65536).
     */
    uint64_t clamped_high, clamped_low;
    uint64_t first_high_line, first_low_line;
    long largest_found, smallest_found;
    /*
     * BMP only: how the file departs from the course's layout (24 bits,
     * rows bottom up, each padded to 4 bytes): its bits a pixel, rows
     * stored top down (a negative height), rows written without their
     * padding (read as such because the file's size is exactly that).
     */
    unsigned bmp_bits;
    int bmp_top_down;
    int bmp_unpadded;
} rayo_read_report;

/* How to read (rayo_image_read_file_with, rayo_image_read_memory_with);
   zeroed: as rayo_image_read_file. */
typedef struct rayo_read_options {
    /* Plain PGM/PPM samples above maxval, or negative, are clamped into
       range and counted in the report instead of refused: a program that
       did not clamp its values can still have its picture compared. */
    int clamp;
} rayo_read_options;

/*
 * Reads the image in path ("-" = standard input) into image, which the
 * caller frees with rayo_image_free.  report may be NULL.  On failure
 * image is left zeroed.
 */
RAYO_API rayo_status rayo_image_read_file(const char *path, rayo_image *image,
                                          rayo_read_report *report,
                                          rayo_error *err);

/* rayo_image_read_file with options (NULL: none). */
RAYO_API rayo_status rayo_image_read_file_with(
    const char *path, const rayo_read_options *options, rayo_image *image,
    rayo_read_report *report, rayo_error *err);

/* The same from size bytes at data; name is used in messages. */
RAYO_API rayo_status rayo_image_read_memory(const void *data, size_t size,
                                            const char *name,
                                            rayo_image *image,
                                            rayo_read_report *report,
                                            rayo_error *err);

/* rayo_image_read_memory with options (NULL: none), for a program
   without files (the page reads what it checks with clamp). */
RAYO_API rayo_status rayo_image_read_memory_with(
    const void *data, size_t size, const char *name,
    const rayo_read_options *options, rayo_image *image,
    rayo_read_report *report, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
