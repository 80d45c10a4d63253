/*
 * jpeg_stub.c - the library's JPEG reader and writer for the page, which
 * has no libjpeg: a JPEG is recognised by its first bytes and refused
 * with a sentence saying what to do; writing one is refused likewise.
 * (The command reads and writes JPEG with libjpeg-turbo: jpeg_read.c,
 * jpeg_write.c.)
 */
#include "../../src/formats/reader_impl.h"
#include "../../src/formats/writer_impl.h"

rayo_status rayo_jpeg_read(rayo_source *src, const unsigned char magic[2],
                           rayo_image *image, rayo_error *err)
{
    (void)magic;
    (void)image;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: a JPEG, which the page does not read; save "
                          "the image as PNG or PBM/PGM/PPM",
                          src->name);
}

static rayo_status refuse(rayo_writer *writer, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "%s: the page does not write JPEG",
                          rayo_output_name(writer->out));
}

static rayo_status never_rows(rayo_writer *writer, const unsigned char *rows,
                              size_t stride, uint32_t count, rayo_error *err)
{
    (void)rows;
    (void)stride;
    (void)count;
    return refuse(writer, err);
}

static void nothing(rayo_writer *writer)
{
    (void)writer;
}

const rayo_writer_ops rayo_jpeg_writer_ops = {refuse, never_rows, NULL,
                                              refuse, nothing};
