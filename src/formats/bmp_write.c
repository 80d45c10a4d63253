/*
 * bmp_write.c - writing Windows BMP in the layout the course's TP1 asks
 * for: a 14-byte file header, a 40-byte BITMAPINFOHEADER with a positive
 * height (rows stored bottom up), no compression, image size and
 * resolutions 0, and rows padded with zero bytes to a multiple of 4;
 * colour 24 bits a pixel in B, G, R order, so a right TP1 program's file
 * and rayo's are the same bytes.  Rows arrive top first and the file
 * wants the bottom one first, so a BMP costs its whole raster in memory
 * (3 bytes a pixel for colour), unlike the other writers.
 */
#include <stdlib.h>
#include <string.h>

#include "bmp_layout.h"
#include "writer_impl.h"

/*
 * Bilevel and gray images, which the course never wrote as BMP, take the
 * format's palettes: 1 bit a pixel (entry 0 white, 1 black: a PBM row's
 * bits unchanged) and 8 bits a pixel (entry i the gray i scaled from
 * maxval to 255: lossless).  Samples over 8 bits are scaled to 0-255,
 * rounded.  The rows are kept, formatted, until the image is finished.
 */

typedef struct bmp_state {
    unsigned bits;          /* 1, 8 or 24 */
    size_t stride;          /* a stored row, padded */
    unsigned char *raster;  /* height rows of stride bytes, file order */
} bmp_state;

/* A sample of maxval scaled to 0-255, rounded. */
static unsigned char to_byte(unsigned value, unsigned maxval)
{
    if (maxval == 255)
        return (unsigned char)value;
    return (unsigned char)((value * 255u + maxval / 2u) / maxval);
}

static unsigned sample_at(const rayo_image_info *info,
                          const unsigned char *row, size_t i)
{
    if (info->sample == RAYO_SAMPLE_U16) {
        uint16_t v;
        memcpy(&v, row + i * 2, 2);
        return v;
    }
    return row[i];
}

static void bmp_discard(rayo_writer *writer)
{
    bmp_state *state = writer->state;
    if (state == NULL)
        return;
    free(state->raster);
    free(state);
    writer->state = NULL;
}

static rayo_status bmp_open(rayo_writer *writer, rayo_error *err)
{
    const rayo_image_info *info = &writer->info;
    bmp_state *state;
    unsigned char header[RAYO_BMP_HEADERS + 256 * 4];
    size_t palette = 0, raster_bytes, i;
    uint64_t file_size;
    rayo_status status;
    state = calloc(1, sizeof *state);
    if (state == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    state->bits = info->sample == RAYO_SAMPLE_BIT ? 1
                  : info->channels == 1           ? 8
                                                  : 24;
    state->stride = rayo_bmp_stride(info->width, state->bits);
    if (state->bits <= 8)
        palette = (size_t)1 << state->bits;
    /* The size fields are 32 bits; RAYO_MAX_PIXELS keeps the raster
       well inside them, and the product is checked all the same. */
    file_size = (uint64_t)RAYO_BMP_HEADERS + palette * 4 +
                (uint64_t)state->stride * info->height;
    if (file_size > UINT32_MAX || (uint64_t)state->stride * info->height >
                                      (uint64_t)(size_t)-1) {
        free(state);
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%s: a BMP of %lux%lu does not fit the "
                              "format's 4 GiB",
                              rayo_output_name(writer->out),
                              (unsigned long)info->width,
                              (unsigned long)info->height);
    }
    raster_bytes = state->stride * (size_t)info->height;
    state->raster = calloc(raster_bytes > 0 ? raster_bytes : 1, 1);
    if (state->raster == NULL) {
        free(state);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    memset(header, 0, sizeof header);
    header[0] = 'B';
    header[1] = 'M';
    rayo_bmp_put32(header + 2, (uint32_t)file_size);
    rayo_bmp_put32(header + 10, (uint32_t)(RAYO_BMP_HEADERS + palette * 4));
    rayo_bmp_put32(header + 14, 40);
    rayo_bmp_put32(header + 18, info->width);
    rayo_bmp_put32(header + 22, info->height);
    rayo_bmp_put16(header + 26, 1);
    rayo_bmp_put16(header + 28, (uint16_t)state->bits);
    rayo_bmp_put32(header + 46, (uint32_t)palette);
    for (i = 0; i < palette; i++) {
        unsigned char *entry = header + RAYO_BMP_HEADERS + i * 4;
        unsigned char gray = state->bits == 1
                                 ? (unsigned char)(i == 0 ? 255 : 0)
                             : info->sample == RAYO_SAMPLE_U16
                                 ? (unsigned char)i
                             : i <= info->maxval
                                 ? to_byte((unsigned)i, info->maxval)
                                 : 0;
        entry[0] = entry[1] = entry[2] = gray;
    }
    writer->state = state;
    status = rayo_output_write(writer->out, header,
                               RAYO_BMP_HEADERS + palette * 4, err);
    if (status != RAYO_OK)
        bmp_discard(writer);
    return status;
}

/* Row y of the image (0 = top) into its place in the file's order. */
static void store_row(const rayo_writer *writer, bmp_state *state,
                      const unsigned char *row, uint32_t y)
{
    const rayo_image_info *info = &writer->info;
    unsigned char *to =
        state->raster + (size_t)(info->height - 1 - y) * state->stride;
    uint32_t x;
    if (state->bits == 1) {
        memcpy(to, row, rayo_image_info_row_bytes(info));
        return;
    }
    if (state->bits == 8) {
        /* 8-bit samples index a palette that scales their maxval;
           16-bit ones are scaled here and index plain grays. */
        for (x = 0; x < info->width; x++)
            to[x] = info->sample == RAYO_SAMPLE_U16
                        ? to_byte(sample_at(info, row, x), info->maxval)
                        : row[x];
        return;
    }
    for (x = 0; x < info->width; x++) {
        size_t i = (size_t)x * 3;
        to[i + 0] = to_byte(sample_at(info, row, i + 2), info->maxval);
        to[i + 1] = to_byte(sample_at(info, row, i + 1), info->maxval);
        to[i + 2] = to_byte(sample_at(info, row, i + 0), info->maxval);
    }
}

static rayo_status bmp_rows(rayo_writer *writer, const unsigned char *rows,
                            size_t stride, uint32_t count, rayo_error *err)
{
    bmp_state *state = writer->state;
    uint32_t first = writer->rows_written - count, k;
    (void)err;
    for (k = 0; k < count; k++)
        store_row(writer, state, rows + (size_t)k * stride, first + k);
    return RAYO_OK;
}

static rayo_status bmp_finish(rayo_writer *writer, rayo_error *err)
{
    bmp_state *state = writer->state;
    rayo_status status = rayo_output_write(
        writer->out, state->raster,
        state->stride * (size_t)writer->info.height, err);
    bmp_discard(writer);
    return status;
}

const rayo_writer_ops rayo_bmp_writer_ops = {bmp_open, bmp_rows, NULL,
                                             bmp_finish, bmp_discard};
