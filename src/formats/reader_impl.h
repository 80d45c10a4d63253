/*
 * reader_impl.h - what the format readers share behind reader.h:
 * reader.c recognises the format from the first bytes and hands the
 * source to pnm_read.c or png_read.c.  Not a public header.
 */
#ifndef RAYO_READER_IMPL_H
#define RAYO_READER_IMPL_H

#include "rayo/reader.h"
#include "read_source.h"

/*
 * Reads a Netpbm image whose magic "P<digit>" (digit '1'..'6') has been
 * consumed; fills report->format, ->plain, ->trailing_samples and
 * ->trailing_data.  For those it reads on past the raster (and, for
 * plain formats, past the whitespace that follows it) up to
 * RAYO_TRAILING_SCAN_BYTES bytes, which it counts in
 * report->trailing_bytes; the caller adds what is left after the cursor.
 */
rayo_status rayo_pnm_read(rayo_source *src, int digit, int clamp,
                          rayo_image *image, rayo_read_report *report,
                          rayo_error *err);

/*
 * Reads a PNG image whose 8-byte signature has been consumed and checked;
 * leaves the cursor after IEND.
 */
rayo_status rayo_png_read(rayo_source *src, rayo_image *image,
                          rayo_error *err);

/*
 * Reads a JPEG image whose first two bytes (FF D8, given) have been
 * consumed.
 */
rayo_status rayo_jpeg_read(rayo_source *src, const unsigned char magic[2],
                           rayo_image *image, rayo_error *err);

/*
 * Reads a BMP image whose "BM" has been consumed; fills report's bmp_
 * fields and leaves the cursor after the last row.
 */
rayo_status rayo_bmp_read(rayo_source *src, rayo_image *image,
                          rayo_read_report *report, rayo_error *err);

#endif
