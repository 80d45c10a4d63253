/*
 * jpeg_read.c - reading JPEG with libjpeg(-turbo) into a rayo_image: the
 * course's first statement asks for the picture "in PNG or JPG", so a
 * student's JPG must be readable for compare.
 *
 * libjpeg decodes; this file feeds it from the rayo_source (the two magic
 * bytes reader.c consumed first), asks for gray or RGB (CMYK, a print
 * format, is refused by name), checks the size against limits.h before
 * any pixel memory is asked for, bounds libjpeg's own memory (a
 * progressive file keeps every coefficient, about twice the image), and
 * turns libjpeg's errors, and its warnings (a file cut short, which it
 * would pad with gray), into one rayo_error naming the file.  JPEG is
 * lossy: what is read is what the encoder kept, not what was drawn;
 * compare knows it (docs/compare.md).  Not the writer (jpeg_write.c).
 * Built with RAYO_NO_JPEG (no libjpeg: the page), a JPEG is refused.
 */
#ifdef RAYO_NO_JPEG
#include "reader_impl.h"

rayo_status rayo_jpeg_read(rayo_source *src, const unsigned char magic[2],
                           rayo_image *image, rayo_error *err)
{
    (void)magic;
    (void)image;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: a JPEG, which this build of rayo does not "
                          "read (it was built without libjpeg, "
                          "RAYO_NO_JPEG); save the image as PNG, BMP or "
                          "PBM/PGM/PPM",
                          src->name);
}

#else
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "rayo/limits.h"
#include "reader_impl.h"

#define JPEG_BUFFER (64u * 1024u)

typedef struct jpeg_reader {
    struct jpeg_error_mgr errors; /* first: libjpeg hands it back */
    struct jpeg_source_mgr source;
    jmp_buf jump;
    rayo_source *src;
    unsigned char magic[2];
    int magic_given;
    unsigned char buffer[JPEG_BUFFER];
    char message[JMSG_LENGTH_MAX];
} jpeg_reader;

static jpeg_reader *reader_of(j_common_ptr cinfo)
{
    return (jpeg_reader *)(void *)cinfo->err;
}

static void on_error(j_common_ptr cinfo)
{
    jpeg_reader *r = reader_of(cinfo);
    (*cinfo->err->format_message)(cinfo, r->message);
    longjmp(r->jump, 1);
}

/* A warning is corrupt or missing data: an error here. */
static void on_message(j_common_ptr cinfo, int level)
{
    if (level < 0)
        on_error(cinfo);
}

static void source_init(j_decompress_ptr cinfo)
{
    (void)cinfo;
}

static boolean source_fill(j_decompress_ptr cinfo)
{
    jpeg_reader *r = reader_of((j_common_ptr)cinfo);
    size_t got = 0;
    if (!r->magic_given) {
        memcpy(r->buffer, r->magic, 2);
        got = 2;
        r->magic_given = 1;
    } else {
        rayo_source_read(r->src, r->buffer, sizeof r->buffer, &got);
    }
    if (got == 0)
        longjmp(r->jump, 2);
    r->source.next_input_byte = r->buffer;
    r->source.bytes_in_buffer = got;
    return TRUE;
}

static void source_skip(j_decompress_ptr cinfo, long count)
{
    jpeg_reader *r = reader_of((j_common_ptr)cinfo);
    while (count > 0) {
        if (r->source.bytes_in_buffer == 0)
            source_fill(cinfo);
        if ((size_t)count <= r->source.bytes_in_buffer) {
            r->source.next_input_byte += count;
            r->source.bytes_in_buffer -= (size_t)count;
            return;
        }
        count -= (long)r->source.bytes_in_buffer;
        r->source.bytes_in_buffer = 0;
    }
}

static void source_term(j_decompress_ptr cinfo)
{
    (void)cinfo;
}

/* Everything that may longjmp, with cinfo and image owned by the
 * caller. */
static void decode(jpeg_reader *r, struct jpeg_decompress_struct *cinfo,
                   rayo_image *image, rayo_status *status, rayo_error *err)
{
    rayo_image_info info;
    uint64_t pixels;
    jpeg_read_header(cinfo, TRUE);
    if (cinfo->jpeg_color_space == JCS_CMYK ||
        cinfo->jpeg_color_space == JCS_YCCK) {
        *status = rayo_error_set(err, RAYO_ERR_FORMAT,
                                 "%s: found a CMYK JPEG (a print format); "
                                 "expected gray or colour",
                                 r->src->name);
        return;
    }
    cinfo->out_color_space =
        cinfo->num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    info = cinfo->num_components == 1
               ? rayo_image_info_gray8(cinfo->image_width,
                                       cinfo->image_height)
               : rayo_image_info_rgb8(cinfo->image_width,
                                      cinfo->image_height);
    if (rayo_image_info_check(&info, NULL) != RAYO_OK) {
        *status = rayo_error_set(err, RAYO_ERR_LIMIT,
                                 "%s: found a %lux%lu JPEG; expected at most "
                                 "%u pixels each way and %lu (2^30) in all",
                                 r->src->name, (unsigned long)info.width,
                                 (unsigned long)info.height,
                                 RAYO_MAX_DIMENSION, RAYO_MAX_PIXELS);
        return;
    }
    /* libjpeg's own memory: its rows and, for a progressive file, every
       coefficient (2 bytes a sample, blocks padded), and some slack. */
    pixels = (uint64_t)(info.width + 16) * (info.height + 16);
    cinfo->mem->max_memory_to_use =
        (long)(pixels * info.channels * 3 + (16u << 20));
    *status = rayo_image_create(image, &info, err);
    if (*status != RAYO_OK)
        return;
    jpeg_start_decompress(cinfo);
    while (cinfo->output_scanline < cinfo->output_height) {
        JSAMPROW row = rayo_image_row(image, cinfo->output_scanline);
        jpeg_read_scanlines(cinfo, &row, 1);
    }
    jpeg_finish_decompress(cinfo);
}

rayo_status rayo_jpeg_read(rayo_source *src, const unsigned char magic[2],
                           rayo_image *image, rayo_error *err)
{
    struct jpeg_decompress_struct cinfo;
    jpeg_reader *r = calloc(1, sizeof *r);
    rayo_status status = RAYO_OK;
    int jumped;
    if (r == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    r->src = src;
    memcpy(r->magic, magic, 2);
    cinfo.err = jpeg_std_error(&r->errors);
    r->errors.error_exit = on_error;
    r->errors.emit_message = on_message;
    jumped = setjmp(r->jump);
    if (jumped == 0) {
        jpeg_create_decompress(&cinfo);
        r->source.init_source = source_init;
        r->source.fill_input_buffer = source_fill;
        r->source.skip_input_data = source_skip;
        r->source.resync_to_restart = jpeg_resync_to_restart;
        r->source.term_source = source_term;
        cinfo.src = &r->source;
        decode(r, &cinfo, image, &status, err);
    } else if (jumped == 2 || src->read_errno != 0) {
        status = rayo_source_end_error(src, "the rest of the JPEG data", err);
    } else {
        /* Where libjpeg stands: what was read, less what it holds. */
        uint64_t at = rayo_source_offset(src) + (r->magic_given ? 0 : 2) -
                      r->source.bytes_in_buffer;
        status = rayo_error_set(err, RAYO_ERR_FORMAT,
                                "%s: byte %llu: libjpeg: %s", src->name,
                                (unsigned long long)at, r->message);
    }
    jpeg_destroy_decompress(&cinfo);
    free(r);
    return status;
}

#endif
