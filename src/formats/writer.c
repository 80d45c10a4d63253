/*
 * writer.c - the format-independent half of rayo_writer: format names,
 * extensions, row bookkeeping and dispatch to the format's table.
 */
#include "../io/output_reserve.h"
#include "writer_impl.h"
#include "writer_runs.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

static const char *const format_names[] = {"pbm", "pgm", "ppm", "png",
                                            "bmp", "jpeg"};
#define FORMAT_COUNT (sizeof format_names / sizeof format_names[0])

static int equal_ignoring_case(const char *a, const char *b)
{
    while (*a && *b) {
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
            return 0;
        a++;
        b++;
    }
    return *a == *b;
}

static int lookup(const char *name, rayo_format *format)
{
    size_t i;
    if (equal_ignoring_case(name, "jpg")) {
        *format = RAYO_FORMAT_JPEG;
        return 1;
    }
    for (i = 0; i < FORMAT_COUNT; i++) {
        if (equal_ignoring_case(name, format_names[i])) {
            *format = (rayo_format)i;
            return 1;
        }
    }
    return 0;
}

rayo_status rayo_format_parse(const char *name, rayo_format *format,
                              rayo_error *err)
{
    if (lookup(name, format))
        return RAYO_OK;
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "unknown format '%s'; expected pbm, pgm, ppm, png, "
                          "bmp or jpeg",
                          name);
}

rayo_status rayo_format_from_path(const char *path, rayo_format *format,
                                  rayo_error *err)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    if (dot != NULL && lookup(dot + 1, format))
        return RAYO_OK;
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "cannot tell the format of '%s' from its extension; "
                          "expected .pbm, .pgm, .ppm, .png, .bmp or .jpg "
                          "(or give "
                          "--format)",
                          path);
}

const char *rayo_format_name(rayo_format format)
{
    return (unsigned)format < FORMAT_COUNT ? format_names[format] : "?";
}

int rayo_format_is_netpbm(rayo_format format)
{
    return format == RAYO_FORMAT_PBM || format == RAYO_FORMAT_PGM ||
           format == RAYO_FORMAT_PPM;
}

rayo_format rayo_format_netpbm_for(const rayo_image_info *info)
{
    if (info->sample == RAYO_SAMPLE_BIT)
        return RAYO_FORMAT_PBM;
    return info->channels == 1 ? RAYO_FORMAT_PGM : RAYO_FORMAT_PPM;
}

rayo_status rayo_writer_open(rayo_writer **result, rayo_output *out,
                             const rayo_image_info *info,
                             const rayo_write_options *options,
                             rayo_error *err)
{
    rayo_writer *writer;
    rayo_status status;
    *result = NULL;
    status = rayo_image_info_check(info, err);
    if (status != RAYO_OK)
        return status;
    writer = calloc(1, sizeof *writer);
    if (writer == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    writer->ops = options->format == RAYO_FORMAT_PNG   ? &rayo_png_writer_ops
                  : options->format == RAYO_FORMAT_BMP ? &rayo_bmp_writer_ops
                  : options->format == RAYO_FORMAT_JPEG
                      ? &rayo_jpeg_writer_ops
                      : &rayo_pnm_writer_ops;
    writer->out = out;
    writer->info = *info;
    writer->options = *options;
    status = writer->ops->open(writer, err);
    if (status != RAYO_OK) {
        free(writer);
        return status;
    }
    *result = writer;
    return RAYO_OK;
}

/* Counts count more rows; RAYO_ERR_INVALID past the image's height. */
static rayo_status count_rows(rayo_writer *writer, uint32_t count,
                              rayo_error *err)
{
    if (count > writer->info.height - writer->rows_written)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "%s: more rows than the image's height %lu",
                              rayo_output_name(writer->out),
                              (unsigned long)writer->info.height);
    writer->rows_written += count;
    return RAYO_OK;
}

rayo_status rayo_writer_write_rows(rayo_writer *writer,
                                   const unsigned char *rows, size_t stride,
                                   uint32_t count, rayo_error *err)
{
    rayo_status status = count_rows(writer, count, err);
    if (status != RAYO_OK)
        return status;
    return writer->ops->rows(writer, rows, stride, count, err);
}

rayo_status rayo_writer_row_sink(void *writer, const unsigned char *rows,
                                 size_t stride, uint32_t first_row,
                                 uint32_t count, rayo_error *err)
{
    (void)first_row;
    return rayo_writer_write_rows(writer, rows, stride, count, err);
}

rayo_writer *rayo_writer_taking_runs(rayo_row_sink sink, void *context,
                                     const rayo_image_info *rows)
{
    rayo_writer *writer = context;
    if (sink != rayo_writer_row_sink || writer == NULL ||
        !writer->takes_runs || rows->sample != RAYO_SAMPLE_BIT ||
        rows->width != writer->info.width)
        return NULL;
    return writer;
}

rayo_status rayo_writer_write_runs(rayo_writer *writer,
                                   const unsigned char *rows, size_t stride,
                                   const rayo_row_runs *runs, uint32_t count,
                                   rayo_error *err)
{
    rayo_status status = count_rows(writer, count, err);
    uint32_t r;
    if (status != RAYO_OK)
        return status;
    for (r = 0; r < count; r++)
        writer->rows_as_runs += runs[r].count != RAYO_ROW_RUNS_BITS;
    return writer->ops->runs(writer, rows, stride, runs, count, err);
}

rayo_status rayo_writer_finish(rayo_writer *writer, rayo_error *err)
{
    rayo_status status;
    if (writer->rows_written != writer->info.height) {
        status = rayo_error_set(err, RAYO_ERR_INVALID,
                                "%s: %lu rows written of %lu",
                                rayo_output_name(writer->out),
                                (unsigned long)writer->rows_written,
                                (unsigned long)writer->info.height);
        rayo_writer_discard(writer);
        return status;
    }
    status = writer->ops->finish(writer, err);
    free(writer);
    return status;
}

void rayo_writer_discard(rayo_writer *writer)
{
    if (writer == NULL)
        return;
    /* What is pending is part of an incomplete image, and may point into
     * the writer's memory (output_reserve.h): dropped, and the output
     * can no longer be committed. */
    rayo_output_abandon(writer->out);
    writer->ops->discard(writer);
    free(writer);
}

rayo_status rayo_image_write(const rayo_image *image, rayo_output *out,
                             const rayo_write_options *options,
                             rayo_error *err)
{
    rayo_writer *writer;
    rayo_status status =
        rayo_writer_open(&writer, out, &image->info, options, err);
    if (status != RAYO_OK)
        return status;
    status = rayo_writer_write_rows(writer, image->pixels, image->stride,
                                    image->info.height, err);
    if (status != RAYO_OK) {
        rayo_writer_discard(writer);
        return status;
    }
    return rayo_writer_finish(writer, err);
}
