/*
 * reader.c - the public face of the image readers: opens the source,
 * recognises the format from its first bytes (Netpbm magic, the PNG
 * signature, BMP's "BM" or JPEG's FF D8), hands over to pnm_read.c,
 * png_read.c, bmp_read.c or jpeg_read.c, and counts what
 * follows the image (pnm_read.c also says what a Netpbm file's tail
 * holds).
 *
 * Not where any format is parsed; see reader.h for what is accepted.
 */
#include "reader_impl.h"

#include <stdio.h>
#include <string.h>

static const unsigned char png_signature[8] = {0x89, 'P',  'N',  'G',
                                               '\r', '\n', 0x1a, '\n'};

static rayo_status bad_magic(const rayo_source *src,
                             const unsigned char *bytes, size_t count,
                             rayo_error *err)
{
    char found[40] = "";
    size_t i, used = 0;
    if (count == 0)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte 0: found an empty file; expected a "
                              "Netpbm magic number (P1-P6), a PNG "
                              "signature, a BMP's \"BM\" or a JPEG's ff d8",
                              src->name);
    for (i = 0; i < count && i < 4; i++)
        used += (size_t)snprintf(found + used, sizeof found - used,
                                 bytes[i] > ' ' && bytes[i] < 127 &&
                                         bytes[i] != '\\'
                                     ? "%c"
                                     : "\\x%02x",
                                 bytes[i]);
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte 0: found \"%s\"; expected a Netpbm magic "
                          "number (P1-P6), a PNG signature, a BMP's "
                          "\"BM\" or a JPEG's ff d8",
                          src->name, found);
}

/* Reads the magic and dispatches; the image is zeroed on failure. */
static rayo_status read_image(rayo_source *src, int clamp,
                              rayo_image *image, rayo_read_report *report,
                              rayo_error *err)
{
    unsigned char magic[8];
    size_t got;
    rayo_source_read(src, magic, 2, &got);
    if (got == 2 && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '6')
        return rayo_pnm_read(src, magic[1], clamp, image, report, err);
    if (src->read_errno != 0)
        return rayo_source_end_error(src, "a magic number", err);
    if (got == 2 && magic[0] == 0xff && magic[1] == 0xd8) {
        report->format = RAYO_FORMAT_JPEG;
        return rayo_jpeg_read(src, magic, image, err);
    }
    if (got == 2 && magic[0] == 'B' && magic[1] == 'M') {
        report->format = RAYO_FORMAT_BMP;
        return rayo_bmp_read(src, image, report, err);
    }
    if (got == 2 && magic[0] == png_signature[0] &&
        magic[1] == png_signature[1]) {
        rayo_source_read(src, magic + 2, 6, &got);
        if (got == 6 && memcmp(magic, png_signature, 8) == 0) {
            report->format = RAYO_FORMAT_PNG;
            report->plain = 0;
            return rayo_png_read(src, image, err);
        }
        if (got < 6)
            return rayo_source_end_error(src, "the rest of a PNG signature",
                                         err);
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte 0: found a damaged PNG signature; "
                              "expected 89 50 4e 47 0d 0a 1a 0a",
                              src->name);
    }
    return bad_magic(src, magic, got, err);
}

static rayo_status read_from(rayo_source *src, int clamp, rayo_image *image,
                             rayo_read_report *report, rayo_error *err)
{
    rayo_read_report local;
    rayo_status status;
    uint64_t rest = 0;
    if (report == NULL)
        report = &local;
    memset(report, 0, sizeof *report);
    memset(image, 0, sizeof *image);
    status = read_image(src, clamp, image, report, err);
    /* The Netpbm reader has counted what it looked at past the raster. */
    if (status == RAYO_OK)
        status = rayo_source_count_rest(src, &rest, err);
    if (status == RAYO_OK)
        report->trailing_bytes += rest;
    if (status != RAYO_OK) {
        rayo_image_free(image);
        memset(image, 0, sizeof *image);
    }
    return status;
}

rayo_status rayo_image_read_file_with(const char *path,
                                      const rayo_read_options *options,
                                      rayo_image *image,
                                      rayo_read_report *report,
                                      rayo_error *err)
{
    rayo_source src;
    rayo_status status;
    memset(image, 0, sizeof *image);
    status = rayo_source_open_file(&src, path, err);
    if (status != RAYO_OK)
        return status;
    status = read_from(&src, options != NULL && options->clamp, image,
                       report, err);
    rayo_source_close(&src);
    return status;
}

rayo_status rayo_image_read_file(const char *path, rayo_image *image,
                                 rayo_read_report *report, rayo_error *err)
{
    return rayo_image_read_file_with(path, NULL, image, report, err);
}

rayo_status rayo_image_read_memory_with(const void *data, size_t size,
                                        const char *name,
                                        const rayo_read_options *options,
                                        rayo_image *image,
                                        rayo_read_report *report,
                                        rayo_error *err)
{
    rayo_source src;
    rayo_source_open_memory(&src, data, size, name ? name : "memory");
    return read_from(&src, options != NULL && options->clamp, image, report,
                     err);
}

rayo_status rayo_image_read_memory(const void *data, size_t size,
                                   const char *name, rayo_image *image,
                                   rayo_read_report *report,
                                   rayo_error *err)
{
    return rayo_image_read_memory_with(data, size, name, NULL, image, report,
                                       err);
}
