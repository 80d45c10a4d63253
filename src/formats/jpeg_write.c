/*
 * jpeg_write.c - writing JPEG with libjpeg(-turbo), one row at a time,
 * for `rayo convert x.pbm x.jpg` (the course's first statement asks for
 * the picture "in PNG or JPG").
 *
 * Colour is written as colour, gray and bilevel as one-channel gray
 * (bilevel 0 and 255); samples over 8 bits are scaled to 0-255, rounded.
 * The quality is rayo_write_options' (1-100; anything else is 90), with
 * libjpeg's default 4:2:0 chroma subsampling.  JPEG is lossy: a bilevel
 * image comes back with gray fringes at its edges, which is why PNG is
 * the format to hand in.  Errors (libjpeg's or the output's) end in one
 * rayo_error.  Not the reader (jpeg_read.c).  Built with RAYO_NO_JPEG
 * (no libjpeg: the page), writing JPEG is refused.
 */
#ifdef RAYO_NO_JPEG
#include "writer_impl.h"

static rayo_status refuse_open(rayo_writer *writer, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "%s: this build of rayo does not write JPEG (it "
                          "was built without libjpeg, RAYO_NO_JPEG)",
                          rayo_output_name(writer->out));
}

/* Never called: no writer opens. */
static rayo_status refuse_rows(rayo_writer *writer, const unsigned char *rows,
                               size_t stride, uint32_t count, rayo_error *err)
{
    (void)rows, (void)stride, (void)count;
    return refuse_open(writer, err);
}

static void discard_nothing(rayo_writer *writer) { (void)writer; }

const rayo_writer_ops rayo_jpeg_writer_ops = {
    refuse_open, refuse_rows, NULL, refuse_open, discard_nothing};

#else
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "writer_impl.h"

#define JPEG_BUFFER (64u * 1024u)

typedef struct jpeg_state {
    struct jpeg_error_mgr errors; /* first: libjpeg hands it back */
    struct jpeg_destination_mgr destination;
    struct jpeg_compress_struct cinfo;
    jmp_buf jump;
    rayo_output *out;
    rayo_error error;
    unsigned char buffer[JPEG_BUFFER];
    unsigned char *row; /* one converted row */
    int started;
} jpeg_state;

static jpeg_state *state_of(j_common_ptr cinfo)
{
    return (jpeg_state *)(void *)cinfo->err;
}

static void on_error(j_common_ptr cinfo)
{
    jpeg_state *s = state_of(cinfo);
    char message[JMSG_LENGTH_MAX];
    (*cinfo->err->format_message)(cinfo, message);
    if (s->error.status == RAYO_OK)
        rayo_error_set(&s->error, RAYO_ERR_IO, "%s: libjpeg: %s",
                       rayo_output_name(s->out), message);
    longjmp(s->jump, 1);
}

static void on_message(j_common_ptr cinfo, int level)
{
    (void)cinfo;
    (void)level;
}

static void destination_init(j_compress_ptr cinfo)
{
    jpeg_state *s = state_of((j_common_ptr)cinfo);
    s->destination.next_output_byte = s->buffer;
    s->destination.free_in_buffer = sizeof s->buffer;
}

static boolean destination_empty(j_compress_ptr cinfo)
{
    jpeg_state *s = state_of((j_common_ptr)cinfo);
    if (rayo_output_write(s->out, s->buffer, sizeof s->buffer, &s->error) !=
        RAYO_OK)
        longjmp(s->jump, 1);
    destination_init(cinfo);
    return TRUE;
}

static void destination_term(j_compress_ptr cinfo)
{
    jpeg_state *s = state_of((j_common_ptr)cinfo);
    size_t n = sizeof s->buffer - s->destination.free_in_buffer;
    if (rayo_output_write(s->out, s->buffer, n, &s->error) != RAYO_OK)
        longjmp(s->jump, 1);
}

static void jpeg_discard(rayo_writer *writer)
{
    jpeg_state *s = writer->state;
    if (s == NULL)
        return;
    jpeg_destroy_compress(&s->cinfo);
    free(s->row);
    free(s);
    writer->state = NULL;
}

/* The error kept by a callback, or libjpeg's, after a longjmp. */
static rayo_status failed(rayo_writer *writer, rayo_error *err)
{
    jpeg_state *s = writer->state;
    rayo_status status = s->error.status != RAYO_OK ? s->error.status
                                                    : RAYO_ERR_IO;
    rayo_error_set(err, status, "%s", s->error.message);
    jpeg_discard(writer);
    return status;
}

static rayo_status jpeg_open(rayo_writer *writer, rayo_error *err)
{
    const rayo_image_info *info = &writer->info;
    unsigned quality = writer->options.quality;
    jpeg_state *s = calloc(1, sizeof *s);
    if (s == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    s->out = writer->out;
    rayo_error_init(&s->error, rayo_error_lang(err));
    s->row = malloc((size_t)info->width * info->channels);
    if (s->row == NULL) {
        free(s);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    writer->state = s;
    s->cinfo.err = jpeg_std_error(&s->errors);
    s->errors.error_exit = on_error;
    s->errors.emit_message = on_message;
    if (setjmp(s->jump) != 0)
        return failed(writer, err);
    jpeg_create_compress(&s->cinfo);
    s->destination.init_destination = destination_init;
    s->destination.empty_output_buffer = destination_empty;
    s->destination.term_destination = destination_term;
    s->cinfo.dest = &s->destination;
    s->cinfo.image_width = info->width;
    s->cinfo.image_height = info->height;
    s->cinfo.input_components = (int)info->channels;
    s->cinfo.in_color_space = info->channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&s->cinfo);
    jpeg_set_quality(&s->cinfo,
                     quality >= 1 && quality <= 100 ? (int)quality : 90,
                     TRUE);
    jpeg_start_compress(&s->cinfo, TRUE);
    s->started = 1;
    return RAYO_OK;
}

/* One row of the image's layout as 8-bit samples. */
static void convert(const rayo_image_info *info, const unsigned char *from,
                    unsigned char *to)
{
    size_t i, n = (size_t)info->width * info->channels;
    if (info->sample == RAYO_SAMPLE_BIT) {
        for (i = 0; i < info->width; i++)
            to[i] = rayo_bit_get(from, (uint32_t)i) ? 0 : 255;
        return;
    }
    for (i = 0; i < n; i++) {
        unsigned v = from[i];
        if (info->sample == RAYO_SAMPLE_U16) {
            uint16_t w;
            memcpy(&w, from + 2 * i, 2);
            v = w;
        }
        to[i] = info->maxval == 255
                    ? (unsigned char)v
                    : (unsigned char)((v * 255u + info->maxval / 2u) /
                                      info->maxval);
    }
}

static rayo_status jpeg_rows(rayo_writer *writer, const unsigned char *rows,
                             size_t stride, uint32_t count, rayo_error *err)
{
    jpeg_state *s = writer->state;
    uint32_t k;
    if (setjmp(s->jump) != 0)
        return failed(writer, err);
    for (k = 0; k < count; k++) {
        JSAMPROW row = s->row;
        convert(&writer->info, rows + (size_t)k * stride, s->row);
        jpeg_write_scanlines(&s->cinfo, &row, 1);
    }
    return RAYO_OK;
}

static rayo_status jpeg_finish(rayo_writer *writer, rayo_error *err)
{
    jpeg_state *s = writer->state;
    if (setjmp(s->jump) != 0)
        return failed(writer, err);
    jpeg_finish_compress(&s->cinfo);
    jpeg_discard(writer);
    return RAYO_OK;
}

const rayo_writer_ops rayo_jpeg_writer_ops = {jpeg_open, jpeg_rows, NULL,
                                              jpeg_finish, jpeg_discard};

#endif
