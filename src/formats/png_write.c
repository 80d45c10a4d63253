/*
 * png_write.c - writing PNG with libpng, one row at a time.
 *
 * Bilevel rows go out as 1-bit grayscale (libpng's invert_mono turns our
 * 1 = black into PNG's 0 = black); gray and RGB as 8 or 16 bits a sample,
 * scaled to the full range when the image's maxval is smaller.  Bilevel
 * rows are deflated with zlib's run-length strategy, much faster on
 * rendered frames at about the same size (docs/performance.md).  libpng
 * reports errors by longjmp; every entry point here sets a jump buffer,
 * and the message (or the output's own error) is kept in the state so the
 * caller gets one rayo_error like any other writer's.
 */
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "writer_impl.h"

typedef struct png_state {
    png_structp png;
    png_infop info;
    rayo_output *out;
    rayo_error error;       /* set by the callbacks before they jump */
    unsigned char *scratch; /* a converted row, or NULL when not needed */
} png_state;

static void on_png_error(png_structp png, png_const_charp message)
{
    png_state *state = png_get_error_ptr(png);
    if (state->error.status == RAYO_OK)
        rayo_error_set(&state->error, RAYO_ERR_IO, "%s: libpng: %s",
                       rayo_output_name(state->out), message);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

static void on_png_write(png_structp png, png_bytep data, size_t length)
{
    png_state *state = png_get_io_ptr(png);
    if (rayo_output_write(state->out, data, length, &state->error) !=
        RAYO_OK)
        png_error(png, "write failed");
}

static void on_png_flush(png_structp png)
{
    (void)png;
}

static int needs_scratch(const rayo_image_info *info)
{
    if (info->sample == RAYO_SAMPLE_BIT)
        return 0;
    if (info->sample == RAYO_SAMPLE_U8)
        return info->maxval != 255;
    return 1; /* 16-bit rows are reordered big-endian */
}

static void free_state(png_state *state)
{
    png_destroy_write_struct(&state->png, &state->info);
    free(state->scratch);
    free(state);
}

static rayo_status fail(rayo_writer *writer, png_state *state,
                        rayo_error *err)
{
    rayo_status status = state->error.status;
    if (err != NULL)
        *err = state->error;
    free_state(state);
    writer->state = NULL;
    return status;
}

static rayo_status png_open(rayo_writer *writer, rayo_error *err)
{
    const rayo_image_info *info = &writer->info;
    png_state *state = calloc(1, sizeof *state);
    int color = info->channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY;
    int depth = info->sample == RAYO_SAMPLE_BIT   ? 1
                : info->sample == RAYO_SAMPLE_U8 ? 8
                                                  : 16;
    if (state == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    rayo_error_init(&state->error, rayo_error_lang(err));
    writer->state = state;
    state->out = writer->out;
    if (needs_scratch(info)) {
        state->scratch = malloc(rayo_image_info_row_bytes(info));
        if (state->scratch == NULL) {
            rayo_error_set(&state->error, RAYO_ERR_NOMEM, "out of memory");
            return fail(writer, state, err);
        }
    }
    state->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, state,
                                         on_png_error, on_png_warning);
    if (state->png != NULL)
        state->info = png_create_info_struct(state->png);
    if (state->png == NULL || state->info == NULL) {
        rayo_error_set(&state->error, RAYO_ERR_NOMEM,
                       "out of memory starting libpng");
        return fail(writer, state, err);
    }
    if (setjmp(png_jmpbuf(state->png)))
        return fail(writer, state, err);
    png_set_write_fn(state->png, state, on_png_write, on_png_flush);
    png_set_IHDR(state->png, state->info, info->width, info->height, depth,
                 color, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (depth == 1) /* see the top of the file */
        png_set_compression_strategy(state->png, Z_RLE);
    png_write_info(state->png, state->info);
    if (depth == 1)
        png_set_invert_mono(state->png);
    return RAYO_OK;
}

/* The row as libpng wants it: full-range samples, 16-bit big-endian. */
static const unsigned char *convert_row(const rayo_image_info *info,
                                        const unsigned char *row,
                                        unsigned char *scratch)
{
    size_t i, samples = (size_t)info->width * info->channels;
    if (scratch == NULL)
        return row;
    if (info->sample == RAYO_SAMPLE_U8) {
        for (i = 0; i < samples; i++)
            scratch[i] = (unsigned char)((row[i] * 255u + info->maxval / 2) /
                                         info->maxval);
        return scratch;
    }
    for (i = 0; i < samples; i++) {
        uint16_t v;
        unsigned long full;
        memcpy(&v, row + 2 * i, 2);
        full = ((unsigned long)v * 65535u + info->maxval / 2) / info->maxval;
        scratch[2 * i] = (unsigned char)(full >> 8);
        scratch[2 * i + 1] = (unsigned char)(full & 0xFF);
    }
    return scratch;
}

static rayo_status png_rows(rayo_writer *writer, const unsigned char *rows,
                            size_t stride, uint32_t count, rayo_error *err)
{
    png_state *state = writer->state;
    uint32_t r;
    if (state == NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "PNG writer used after an error");
    if (setjmp(png_jmpbuf(state->png)))
        return fail(writer, state, err);
    for (r = 0; r < count; r++) {
        const unsigned char *row =
            convert_row(&writer->info, rows + (size_t)r * stride,
                        state->scratch);
        png_write_row(state->png, row);
    }
    return RAYO_OK;
}

static rayo_status png_finish(rayo_writer *writer, rayo_error *err)
{
    png_state *state = writer->state;
    if (state == NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "PNG writer used after an error");
    if (setjmp(png_jmpbuf(state->png)))
        return fail(writer, state, err);
    png_write_end(state->png, NULL);
    free_state(state);
    writer->state = NULL;
    return RAYO_OK;
}

static void png_discard(rayo_writer *writer)
{
    if (writer->state != NULL)
        free_state(writer->state);
    writer->state = NULL;
}

const rayo_writer_ops rayo_png_writer_ops = {
    .open = png_open,
    .rows = png_rows,
    .runs = NULL,
    .finish = png_finish,
    .discard = png_discard,
};
